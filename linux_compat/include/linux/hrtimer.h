/*
 * linux/hrtimer.h — high-resolution timers over the RTOS tick.
 *
 * Engine (linux_compat/src/hrtimer.c): one queue sorted by expiry (FIFO for
 * equal expiries), served by an ISR on the RTOS tick interrupt (INTNO_TICK).
 * Callbacks run in that interrupt context (hard-IRQ, as Linux's), one after
 * another, never nested.  The queue is checked every tick (200 us): a timer
 * fires at the first tick at or after its expiry - never early, late by less
 * than one tick.  A callback returning HRTIMER_RESTART is re-queued at its
 * expiry as the callback left it (hrtimer_forward* advances it from the
 * previous expiry, so periods never drift).  A RESTART whose expiry is
 * still due is served at the next tick, not in a loop.
 *
 * Difference from Linux: expiry resolution is the tick (hrtimer_resolution),
 * and the SOFT modes also run in hard-IRQ context.  As in Linux,
 * hrtimer_forward clamps an interval below hrtimer_resolution to it: a
 * periodic timer asking for less than a tick is called once per tick.
 */
#ifndef _LINUX_HRTIMER_H
#define _LINUX_HRTIMER_H

#include <linux/types.h>
#include <linux/list.h>
#include <linux/ktime.h>
#include <linux/time.h>
#include <linux/init.h>
#include <linux/kernel.h>
#include <linux_compat/timerheap.h>

enum hrtimer_mode {
	HRTIMER_MODE_ABS	= 0x00,
	HRTIMER_MODE_REL	= 0x01,
	HRTIMER_MODE_PINNED	= 0x02,
	HRTIMER_MODE_SOFT	= 0x04,
	HRTIMER_MODE_HARD	= 0x08,

	HRTIMER_MODE_ABS_PINNED	= HRTIMER_MODE_ABS | HRTIMER_MODE_PINNED,
	HRTIMER_MODE_REL_PINNED	= HRTIMER_MODE_REL | HRTIMER_MODE_PINNED,
	HRTIMER_MODE_ABS_SOFT	= HRTIMER_MODE_ABS | HRTIMER_MODE_SOFT,
	HRTIMER_MODE_REL_SOFT	= HRTIMER_MODE_REL | HRTIMER_MODE_SOFT,
	HRTIMER_MODE_ABS_PINNED_SOFT = HRTIMER_MODE_ABS_PINNED | HRTIMER_MODE_SOFT,
	HRTIMER_MODE_REL_PINNED_SOFT = HRTIMER_MODE_REL_PINNED | HRTIMER_MODE_SOFT,
	HRTIMER_MODE_ABS_HARD	= HRTIMER_MODE_ABS | HRTIMER_MODE_HARD,
	HRTIMER_MODE_REL_HARD	= HRTIMER_MODE_REL | HRTIMER_MODE_HARD,
	HRTIMER_MODE_ABS_PINNED_HARD = HRTIMER_MODE_ABS_PINNED | HRTIMER_MODE_HARD,
	HRTIMER_MODE_REL_PINNED_HARD = HRTIMER_MODE_REL_PINNED | HRTIMER_MODE_HARD,
};

enum hrtimer_restart {
	HRTIMER_NORESTART,
	HRTIMER_RESTART,
};

struct hrtimer {
	/* Public, as in Linux: the callback. */
	enum hrtimer_restart (*function)(struct hrtimer *);
	/* Private to the engine. */
	struct lx_heap_node lx_node;         /* in the queue (while lx_queued) */
	ktime_t lx_expires;                  /* expiry, absolute ns */
	clockid_t lx_clockid;
	u32 lx_magic;                        /* set by hrtimer_init/setup */
	u8 lx_queued;                        /* in the queue */
	u8 lx_cancelled;                     /* cancelled from its own callback: ignore RESTART */
};

/* The expiry granularity: one RTOS tick. */
extern const unsigned int hrtimer_resolution;

/* Prepares timer for clock_id and mode (function must be set before start); not on an active timer. */
void hrtimer_init(struct hrtimer *timer, clockid_t clock_id, enum hrtimer_mode mode);
/* hrtimer_init and set the callback (Linux 6.13). */
void hrtimer_setup(struct hrtimer *timer, enum hrtimer_restart (*function)(struct hrtimer *),
		   clockid_t clock_id, enum hrtimer_mode mode);
/* (Re)queues timer to expire at tim (ABS) or now + tim (REL); any context. */
void hrtimer_start(struct hrtimer *timer, ktime_t tim, const enum hrtimer_mode mode);
/* hrtimer_start; may fire as late as tim + delta_ns (here: served at tim). */
void hrtimer_start_range_ns(struct hrtimer *timer, ktime_t tim, u64 delta_ns,
			    const enum hrtimer_mode mode);
/* Requeues timer at its current (forwarded) expiry. */
void hrtimer_restart(struct hrtimer *timer);
/*
 * Stops timer: 1 if it was active (queued or running), 0 if not.  From the
 * timer's own callback this would deadlock in Linux: it is reported, the
 * timer is dequeued and the callback's RESTART ignored.
 */
int hrtimer_cancel(struct hrtimer *timer);
int lx_hrtimer_cancel_at(struct hrtimer *timer, const char *file, int line);
#define hrtimer_cancel(timer)	lx_hrtimer_cancel_at((timer), __FILE__, __LINE__)
/* Dequeues timer: 1 if it was queued, 0 if inactive, -1 if its callback is running. */
int hrtimer_try_to_cancel(struct hrtimer *timer);
/*
 * Moves the expiry forward from the previous expiry in whole intervals
 * until it is after now; returns the number of intervals (0 if the expiry
 * is already after now).  Not on a queued timer.
 */
u64 hrtimer_forward(struct hrtimer *timer, ktime_t now, ktime_t interval);
/* hrtimer_forward relative to the current time. */
u64 hrtimer_forward_now(struct hrtimer *timer, ktime_t interval);
/* True if timer is queued or its callback is running. */
bool hrtimer_active(const struct hrtimer *timer);
/* True if timer is queued. */
bool hrtimer_is_queued(struct hrtimer *timer);
/* True while timer's callback runs. */
bool hrtimer_callback_running(struct hrtimer *timer);
/* Time left until timer expires (negative if due). */
ktime_t hrtimer_get_remaining(const struct hrtimer *timer);

/* The timer's expiry. */
static inline ktime_t hrtimer_get_expires(const struct hrtimer *timer)	{ return timer->lx_expires; }
static inline ktime_t hrtimer_get_softexpires(const struct hrtimer *timer) { return timer->lx_expires; }
static inline s64 hrtimer_get_expires_ns(const struct hrtimer *timer)	{ return timer->lx_expires; }
/* Sets the expiry of a timer that is not queued (e.g. in its callback). */
static inline void hrtimer_set_expires(struct hrtimer *timer, ktime_t time) { timer->lx_expires = time; }
static inline void hrtimer_set_expires_range_ns(struct hrtimer *timer, ktime_t time, u64 delta)
{
	(void)delta;
	timer->lx_expires = time;
}
static inline void hrtimer_add_expires(struct hrtimer *timer, ktime_t time) { timer->lx_expires += time; }
static inline void hrtimer_add_expires_ns(struct hrtimer *timer, u64 ns) { timer->lx_expires += (s64)ns; }
/* The current time of the timer's clock. */
static inline ktime_t hrtimer_cb_get_time(const struct hrtimer *timer)
{
	(void)timer;
	return ktime_get();
}
/* Starts timer with expiry already set by hrtimer_set_expires. */
static inline void hrtimer_start_expires(struct hrtimer *timer, enum hrtimer_mode mode)
{
	hrtimer_start(timer, timer->lx_expires, mode & ~HRTIMER_MODE_REL);
}

#endif /* _LINUX_HRTIMER_H */
