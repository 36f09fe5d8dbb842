/*
 * linux/wait.h — wait queues and the wait_event family.
 *
 * A waiter puts itself on the queue before it tests the condition, then
 * sleeps; wake_up marks it and wakes its task (TOPPERS keeps a wakeup that
 * arrives before the sleep), so no wakeup between test and sleep is lost.
 * wake_up* are legal from any context, interrupt handlers included.  The
 * wait_event forms are macros evaluating the condition in the caller, as
 * Linux's; they may be used only where sleeping is legal (reported
 * otherwise, and they then return at once: timeout forms as timed out,
 * interruptible forms with -ERESTARTSYS).
 */
#ifndef _LINUX_WAIT_H
#define _LINUX_WAIT_H

#include <linux/types.h>
#include <linux/compiler.h>
#include <linux/errno.h>     /* the interruptible waits expand to -ERESTARTSYS */
#include <linux/list.h>
#include <linux/spinlock.h>
#include <linux/jiffies.h>
#include <linux/sched.h>
#include <linux_compat/sched.h>

struct wait_queue_head {
	spinlock_t lock;               /* for callers using Linux's wq_head->lock idioms */
	struct lx_waitlist waiters;
};
typedef struct wait_queue_head wait_queue_head_t;

#define __WAIT_QUEUE_HEAD_INITIALIZER(name) \
	{ .lock = __SPIN_LOCK_UNLOCKED(name.lock), .waiters = { NULL, NULL } }
#define DECLARE_WAIT_QUEUE_HEAD(name)	struct wait_queue_head name = __WAIT_QUEUE_HEAD_INITIALIZER(name)
#define DECLARE_WAIT_QUEUE_HEAD_ONSTACK(name) DECLARE_WAIT_QUEUE_HEAD(name)

/* Initialises an empty queue. */
void lx_init_waitqueue_head(struct wait_queue_head *wq_head, const char *name);
#define init_waitqueue_head(wq)	lx_init_waitqueue_head((wq), #wq)

/* Wakes every non-exclusive waiter and the first exclusive one; any context. */
void __wake_up(struct wait_queue_head *wq_head, unsigned int mode, int nr_exclusive, void *key);
#define wake_up(x)			__wake_up((x), TASK_NORMAL, 1, NULL)
#define wake_up_nr(x, nr)		__wake_up((x), TASK_NORMAL, (nr), NULL)
#define wake_up_all(x)			__wake_up((x), TASK_NORMAL, 0, NULL)
#define wake_up_interruptible(x)	__wake_up((x), TASK_INTERRUPTIBLE, 1, NULL)
#define wake_up_interruptible_nr(x, nr)	__wake_up((x), TASK_INTERRUPTIBLE, (nr), NULL)
#define wake_up_interruptible_all(x)	__wake_up((x), TASK_INTERRUPTIBLE, 0, NULL)
#define wake_up_interruptible_sync(x)	__wake_up((x), TASK_INTERRUPTIBLE, 1, NULL)
#define wake_up_locked(x)		__wake_up((x), TASK_NORMAL, 1, NULL)
#define wake_up_poll(x, m)		__wake_up((x), TASK_NORMAL, 1, NULL)
#define wake_up_interruptible_poll(x, m) __wake_up((x), TASK_INTERRUPTIBLE, 1, NULL)

/* True if some task waits on the queue. */
bool waitqueue_active(struct wait_queue_head *wq_head);
#define wq_has_sleeper(wq)	waitqueue_active(wq)

/*
 * The steps behind wait_event (also usable directly):
 * lx_wait_prepare puts w (the calling task) on the queue, unmarked;
 * lx_wait_block sleeps until w is woken, the deadline (ns; U64_MAX none)
 * or, if interruptible, rel_wai - 0, -ETIME or -ERESTARTSYS - and leaves w
 * re-armed on the queue; lx_wait_finish takes w off the queue.
 */
void lx_wait_prepare(struct wait_queue_head *wq_head, struct lx_waiter *w, bool exclusive);
int lx_wait_block(struct wait_queue_head *wq_head, struct lx_waiter *w, uint64_t deadline_ns,
		  bool interruptible);
void lx_wait_finish(struct wait_queue_head *wq_head, struct lx_waiter *w);
/* The might_sleep check for wait_event: true if the caller may sleep. */
bool lx_wait_may_sleep(const char *what, const char *file, int line);
/* Deadline timeout jiffies from now / jiffies left until it (at least 1). */
uint64_t lx_wait_deadline(long timeout);
long lx_wait_jiffies_left(uint64_t deadline_ns);

/* The loop every wait_event form shares: 0, -ETIME or -ERESTARTSYS. */
#define __lx_wait_event(wq_head, condition, deadline, interruptible, exclusive) ({	\
	struct lx_waiter __lx_w;						\
	int __lx_ret = 0;							\
	lx_wait_prepare(&(wq_head), &__lx_w, (exclusive));			\
	for (;;) {								\
		if (condition)							\
			break;							\
		__lx_ret = lx_wait_block(&(wq_head), &__lx_w, (deadline),	\
					 (interruptible));			\
		if (__lx_ret != 0)						\
			break;							\
	}									\
	lx_wait_finish(&(wq_head), &__lx_w);					\
	__lx_ret; })

/* Sleeps until condition is true. */
#define wait_event(wq_head, condition) do {					\
	if (!lx_wait_may_sleep("wait_event()", __FILE__, __LINE__) || (condition)) \
		break;								\
	(void)__lx_wait_event(wq_head, condition, U64_MAX, false, false);	\
} while (0)

/* Sleeps until condition is true or rel_wai: 0 or -ERESTARTSYS. */
#define wait_event_interruptible(wq_head, condition) ({				\
	int __lx_wei = 0;							\
	if (!lx_wait_may_sleep("wait_event_interruptible()", __FILE__, __LINE__)) \
		__lx_wei = (condition) ? 0 : -ERESTARTSYS;			\
	else if (!(condition))							\
		__lx_wei = __lx_wait_event(wq_head, condition, U64_MAX, true, false); \
	__lx_wei; })
#define wait_event_killable(wq_head, condition)	wait_event_interruptible(wq_head, condition)
#define wait_event_interruptible_exclusive(wq_head, condition) ({		\
	int __lx_wei = 0;							\
	if (!lx_wait_may_sleep("wait_event_interruptible_exclusive()", __FILE__, __LINE__)) \
		__lx_wei = (condition) ? 0 : -ERESTARTSYS;			\
	else if (!(condition))							\
		__lx_wei = __lx_wait_event(wq_head, condition, U64_MAX, true, true); \
	__lx_wei; })

/* Sleeps at most timeout jiffies: 0 if condition is still false at the end,
 * else the jiffies left (at least 1). */
#define wait_event_timeout(wq_head, condition, timeout) ({			\
	long __lx_wet;								\
	uint64_t __lx_dl = lx_wait_deadline(timeout);				\
	if (condition)								\
		__lx_wet = lx_wait_jiffies_left(__lx_dl);			\
	else if (!lx_wait_may_sleep("wait_event_timeout()", __FILE__, __LINE__)) \
		__lx_wet = 0;							\
	else {									\
		(void)__lx_wait_event(wq_head, condition, __lx_dl, false, false); \
		__lx_wet = (condition) ? lx_wait_jiffies_left(__lx_dl) : 0;	\
	}									\
	__lx_wet; })

/* As wait_event_timeout, or -ERESTARTSYS if released by rel_wai. */
#define wait_event_interruptible_timeout(wq_head, condition, timeout) ({	\
	long __lx_weit;								\
	uint64_t __lx_dl = lx_wait_deadline(timeout);				\
	if (condition)								\
		__lx_weit = lx_wait_jiffies_left(__lx_dl);			\
	else if (!lx_wait_may_sleep("wait_event_interruptible_timeout()", __FILE__, __LINE__)) \
		__lx_weit = 0;							\
	else {									\
		int __lx_r = __lx_wait_event(wq_head, condition, __lx_dl, true, false); \
		if (__lx_r == -ERESTARTSYS)					\
			__lx_weit = -ERESTARTSYS;				\
		else								\
			__lx_weit = (condition) ? lx_wait_jiffies_left(__lx_dl) : 0; \
	}									\
	__lx_weit; })

#endif /* _LINUX_WAIT_H */
