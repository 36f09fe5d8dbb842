/*
 * wait.c — wait queues.
 */
#include <linux/wait.h>
#include <linux/kernel.h>
#include <linux/errno.h>
#include <linux_compat/clock.h>
#include <linux_compat/context.h>
#include <rtos_cfg.h>
#include <sil.h>

/* An empty queue. */
void lx_init_waitqueue_head(struct wait_queue_head *wq_head, const char *name)
{
	lx_spin_lock_init(&wq_head->lock, name);
	wq_head->waiters.head = wq_head->waiters.tail = NULL;
}

/* Wakes the non-exclusive waiters and up to nr_exclusive exclusive ones (0: all). */
void __wake_up(struct wait_queue_head *wq_head, unsigned int mode, int nr_exclusive, void *key)
{
	ID woken[TNUM_TSKID];
	unsigned int n = 0, i;
	struct lx_waiter *w, *next;
	SIL_PRE_LOC;

	int exclusive_left = nr_exclusive;    /* <= 0: every exclusive waiter */

	(void)mode;
	(void)key;
	SIL_LOC_INT();
	for (w = wq_head->waiters.head; w != NULL; w = next) {
		next = w->next;
		if (w->exclusive && nr_exclusive > 0) {
			if (exclusive_left == 0)
				continue;
			exclusive_left--;
		}
		/* Off the queue, so that a waiter that re-arms is not woken twice by this call. */
		lx_waitlist_remove_locked(&wq_head->waiters, w);
		w->woken = true;
		if (n < TNUM_TSKID)
			woken[n++] = w->tskid;
	}
	SIL_UNL_INT();
	for (i = 0; i < n; i++)
		lx_wake_task(woken[i]);
}

/* True if any task waits. */
bool waitqueue_active(struct wait_queue_head *wq_head)
{
	return READ_ONCE(wq_head->waiters.head) != NULL;
}

/* Puts the calling task's waiter on the queue. */
void lx_wait_prepare(struct wait_queue_head *wq_head, struct lx_waiter *w, bool exclusive)
{
	SIL_PRE_LOC;

	lx_waiter_init(w);
	w->exclusive = exclusive;
	SIL_LOC_INT();
	lx_waitlist_add_locked(&wq_head->waiters, w);
	SIL_UNL_INT();
}

/* Sleeps until woken; re-arms w on the queue for the next condition test. */
int lx_wait_block(struct wait_queue_head *wq_head, struct lx_waiter *w, uint64_t deadline_ns,
		  bool interruptible)
{
	int ret;
	SIL_PRE_LOC;

	for (;;) {
		ret = lx_waiter_sleep(w, deadline_ns);
		if (ret != -EINTR || interruptible)
			break;
	}
	SIL_LOC_INT();
	if (w->woken) {
		ret = 0;
		w->woken = false;
		lx_waitlist_add_locked(&wq_head->waiters, w);
	}
	SIL_UNL_INT();
	return ret == -EINTR ? -ERESTARTSYS : ret;
}

/* Takes w off the queue (if a wake_up has not already). */
void lx_wait_finish(struct wait_queue_head *wq_head, struct lx_waiter *w)
{
	SIL_PRE_LOC;

	SIL_LOC_INT();
	(void)lx_waitlist_remove_locked(&wq_head->waiters, w);
	SIL_UNL_INT();
}

/* might_sleep for the wait_event macros. */
bool lx_wait_may_sleep(const char *what, const char *file, int line)
{
	return lx_might_sleep_check(what, file, line);
}

/* Deadline timeout jiffies from now. */
uint64_t lx_wait_deadline(long timeout)
{
	return lx_clock_now_ns() + jiffies_to_nsecs(timeout < 0 ? 0 : (unsigned long)timeout);
}

/* Jiffies left until deadline, at least 1. */
long lx_wait_jiffies_left(uint64_t deadline_ns)
{
	uint64_t now = lx_clock_now_ns();
	long left = deadline_ns > now ? (long)nsecs_to_jiffies(deadline_ns - now) : 0;

	return left > 0 ? left : 1;
}
