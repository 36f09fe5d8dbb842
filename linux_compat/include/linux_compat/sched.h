/*
 * linux_compat/sched.h — how linux_compat blocks and wakes RTOS tasks.
 *
 * Every Linux sleep (semaphores, mutexes, completions, wait queues, the
 * worker) is a waiter record on a list plus slp_tsk/tslp_tsk of the task;
 * a wakeup marks the record and wakes the task with wup_tsk / iwup_tsk.
 * TOPPERS queues a wakeup that arrives before the sleep, so the window
 * between "decide to sleep" and "sleep" loses nothing; a sleeper re-checks
 * its record after every return, so an extra queued wakeup is harmless.
 *
 * Wakeups requested with the CPU or interrupts locked (where HRP2 forbids
 * service calls) are recorded and delivered by the next tick (<= 200 us).
 */
#ifndef _LINUX_COMPAT_SCHED_H
#define _LINUX_COMPAT_SCHED_H

#include <stdbool.h>
#include <stddef.h>
#include <linux/types.h>

struct lx_waiter {
	struct lx_waiter *next;
	int tskid;               /* the sleeping task (a TOPPERS ID) */
	volatile bool woken;     /* set by the waker, under the interrupt lock */
	bool exclusive;          /* wake_up wakes one exclusive waiter, all others */
};

struct lx_waitlist {
	struct lx_waiter *head;
	struct lx_waiter *tail;
};

/* The calling task's ID (TSK_NONE in non-task context). */
int lx_current_tskid(void);

/* Wakes task tskid from any context (with the CPU/interrupts locked: deferred
 * until linux_compat unmasks them, or the next tick for a raw CPU lock). */
void lx_wake_task(int tskid);
/* Delivers wakeups deferred while locked (the tick ISR; the irqrestore paths). */
void lx_deferred_wakeups_run(void);
/* True while a deferred wakeup waits (cheap test before lx_deferred_wakeups_run). */
extern bool lx_deferred_wake_pending;
/* Forgets deferred wakeups and bottom-half state (boot). */
void lx_sched_reset(void);

/* Lists; the caller holds the interrupt lock (SIL_LOC_INT) for all of these. */
void lx_waitlist_add_locked(struct lx_waitlist *wl, struct lx_waiter *w);
bool lx_waitlist_remove_locked(struct lx_waitlist *wl, struct lx_waiter *w);
struct lx_waiter *lx_waitlist_pop_locked(struct lx_waitlist *wl);
static inline bool lx_waitlist_empty(const struct lx_waitlist *wl) { return wl->head == NULL; }

/* Prepares w for the calling task (not yet on a list). */
void lx_waiter_init(struct lx_waiter *w);

/*
 * Sleeps the calling task until w->woken, the deadline (ns, lx_clock_now_ns
 * scale; U64_MAX = none) or rel_wai.  Returns 0 (woken), -ETIME (deadline)
 * or -EINTR (released).  The caller re-checks w->woken under its lock.
 */
int lx_waiter_sleep(struct lx_waiter *w, uint64_t deadline_ns);

/* Bottom halves (timer_list callbacks): disabled while the count is non-zero. */
void lx_bh_disable(void);
void lx_bh_enable(void);
bool lx_bh_disabled(void);

/* The deadline `ms` milliseconds from now (U64_MAX for a negative ms). */
uint64_t lx_deadline_after_ms(long ms);

#endif /* _LINUX_COMPAT_SCHED_H */
