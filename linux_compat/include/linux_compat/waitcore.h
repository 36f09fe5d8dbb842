/*
 * linux_compat/waitcore.h — the sleeping acquisition shared by semaphores,
 * mutexes and completions: a counter and a FIFO of waiters, where a release
 * either grants the oldest waiter directly or counts up.
 */
#ifndef _LINUX_COMPAT_WAITCORE_H
#define _LINUX_COMPAT_WAITCORE_H

#include <stdbool.h>
#include <linux/types.h>
#include <linux_compat/sched.h>

/*
 * Takes one unit of *count, sleeping on wl until granted one.  deadline_ns as
 * lx_waiter_sleep (U64_MAX: none); interruptible: rel_wai ends the wait.
 * what/file/line name the call for a context report: where sleeping is
 * illegal, only a free unit is taken.  Returns 0, -ETIME or -EINTR.
 */
int lx_count_acquire(unsigned int *count, struct lx_waitlist *wl, uint64_t deadline_ns,
		     bool interruptible, const char *what, const char *file, int line);

/* Takes a unit without sleeping: true if taken.  Any context. */
bool lx_count_tryacquire(unsigned int *count);

/* Grants the oldest waiter of wl, or adds one unit to *count.  Any context. */
void lx_count_release(unsigned int *count, struct lx_waitlist *wl);

/* Grants every waiter of wl; returns how many. Any context. */
unsigned int lx_waitlist_wake_all(struct lx_waitlist *wl);

#endif /* _LINUX_COMPAT_WAITCORE_H */
