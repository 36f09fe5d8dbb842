/*
 * completion.c — completions on the wait core.
 */
#include <linux/completion.h>
#include <linux/kernel.h>
#include <linux/errno.h>
#include <linux/jiffies.h>
#include <linux_compat/waitcore.h>
#include <linux_compat/clock.h>
#include <sil.h>

/* Not done, no waiters. */
void init_completion(struct completion *x)
{
	x->done = 0;
	x->waiters.head = x->waiters.tail = NULL;
}

/* Not done again. */
void reinit_completion(struct completion *x)
{
	x->done = 0;
}

/* Wakes the oldest waiter or records the completion. */
void complete(struct completion *x)
{
	if (x->done != UINT_MAX)
		lx_count_release(&x->done, &x->waiters);
}

/* Done for everyone from now on. */
void complete_all(struct completion *x)
{
	SIL_PRE_LOC;

	SIL_LOC_INT();
	x->done = UINT_MAX;
	SIL_UNL_INT();
	(void)lx_waitlist_wake_all(&x->waiters);
}

/* Consumes one completion (none after complete_all: it stays done). */
static void consume_extra(struct completion *x)
{
	SIL_PRE_LOC;

	/* lx_count_* took one unit; complete_all's count never runs down. */
	SIL_LOC_INT();
	if (x->done == UINT_MAX - 1)
		x->done = UINT_MAX;
	SIL_UNL_INT();
}

/* Waits with a deadline; 0, -ETIME or -EINTR. */
static int wait_common(struct completion *x, uint64_t deadline, bool interruptible,
		       const char *what, const char *file, int line)
{
	int ret = lx_count_acquire(&x->done, &x->waiters, deadline, interruptible, what, file, line);

	if (ret == 0)
		consume_extra(x);
	return ret;
}

/* The jiffies left until deadline, at least 1. */
static unsigned long jiffies_left(uint64_t deadline)
{
	uint64_t now = lx_clock_now_ns();
	unsigned long left = deadline > now ? nsecs_to_jiffies(deadline - now) : 0;

	return left > 0 ? left : 1;
}

/* Sleeps until completed. */
void lx_wait_for_completion_at(struct completion *x, const char *file, int line)
{
	(void)wait_common(x, U64_MAX, false, "wait_for_completion()", file, line);
}

/* Sleeps at most timeout jiffies; jiffies left (>= 1) or 0. */
unsigned long lx_wait_for_completion_timeout_at(struct completion *x, unsigned long timeout,
						const char *file, int line)
{
	uint64_t deadline = lx_clock_now_ns() + jiffies_to_nsecs(timeout);

	if (wait_common(x, deadline, false, "wait_for_completion_timeout()", file, line) != 0)
		return 0;
	return jiffies_left(deadline);
}

/* Sleeps until completed or released: 0 or -ERESTARTSYS. */
int lx_wait_for_completion_interruptible_at(struct completion *x, const char *file, int line)
{
	return wait_common(x, U64_MAX, true, "wait_for_completion_interruptible()", file, line)
		== 0 ? 0 : -ERESTARTSYS;
}

/* Jiffies left, 0 on timeout, -ERESTARTSYS if released. */
long lx_wait_for_completion_interruptible_timeout_at(struct completion *x, unsigned long timeout,
						     const char *file, int line)
{
	uint64_t deadline = lx_clock_now_ns() + jiffies_to_nsecs(timeout);
	int ret = wait_common(x, deadline, true, "wait_for_completion_interruptible_timeout()",
			      file, line);

	if (ret == -ETIME)
		return 0;
	if (ret != 0)
		return -ERESTARTSYS;
	return (long)jiffies_left(deadline);
}

void (wait_for_completion)(struct completion *x)
{
	lx_wait_for_completion_at(x, NULL, 0);
}

unsigned long (wait_for_completion_timeout)(struct completion *x, unsigned long timeout)
{
	return lx_wait_for_completion_timeout_at(x, timeout, NULL, 0);
}

int (wait_for_completion_interruptible)(struct completion *x)
{
	return lx_wait_for_completion_interruptible_at(x, NULL, 0);
}

long (wait_for_completion_interruptible_timeout)(struct completion *x, unsigned long timeout)
{
	return lx_wait_for_completion_interruptible_timeout_at(x, timeout, NULL, 0);
}

/* One completion if available, without sleeping. */
bool try_wait_for_completion(struct completion *x)
{
	if (!lx_count_tryacquire(&x->done))
		return false;
	consume_extra(x);
	return true;
}

/* True if a wait would return at once. */
bool completion_done(struct completion *x)
{
	return READ_ONCE(x->done) != 0;
}
