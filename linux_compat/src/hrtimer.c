/*
 * hrtimer.c — hrtimers on the RTOS tick.
 *
 * One priority queue ordered by (expiry, queueing sequence): a pairing heap
 * (linux_compat/timerheap.h), O(1) to insert and O(log n) amortized to take
 * the first or cancel any, as Linux's rbtree timerqueue.  The tick ISR
 * compares the first timer's expiry with the tick's time - the whole cost of
 * a tick with nothing due - and runs due callbacks one after another in its
 * own interrupt context.  A timer queued during that pass at a time already
 * due waits on a FIFO for the pass to end and runs at the next tick, so a
 * callback that re-arms itself in the past cannot hold the ISR.  Queue
 * updates are made under SIL_LOC_INT, so timers may be started and cancelled
 * from any context.
 */
#include <linux/hrtimer.h>
#include <linux/kernel.h>
#include <linux_compat/clock.h>
#include <linux_compat/context.h>
#include <linux_compat/report.h>
#include <kernel.h>
#include <sil.h>

#define HRTIMER_MAGIC	0x68727469U    /* "hrti": set by hrtimer_init */

const unsigned int hrtimer_resolution = (unsigned int)LX_TICK_NS;

static struct {
	struct lx_heap heap;
	/* The timer whose callback runs; the timer itself is not touched after a
	 * callback returning HRTIMER_NORESTART (it may have freed it). */
	struct hrtimer *running;
} queue;

/* Empties the queue (boot). */
void lx_hrtimer_reset(void)
{
	lx_heap_init(&queue.heap);
	queue.running = NULL;
}

/* The first queued timer, or NULL. */
static inline struct hrtimer *queue_first(void)
{
	struct lx_heap_node *first = lx_heap_first(&queue.heap);

	return first != NULL ? container_of(first, struct hrtimer, lx_node) : NULL;
}

/* Queues timer after every timer expiring no later (its sequence is the
 * largest); during the tick's pass a due one waits for the pass to end.
 * Interrupts locked by the caller. */
static void enqueue_locked(struct hrtimer *timer)
{
	timer->lx_node.key = (u64)timer->lx_expires;
	timer->lx_queued = 1;
	lx_heap_insert(&queue.heap, &timer->lx_node);
}

/* Unlinks a queued timer; interrupts locked by the caller. */
static void dequeue_locked(struct hrtimer *timer)
{
	timer->lx_queued = 0;
	lx_heap_remove(&queue.heap, &timer->lx_node);
}

/* Prepares timer; reports re-initialisation of a queued timer (which is dequeued first). */
void hrtimer_init(struct hrtimer *timer, clockid_t clock_id, enum hrtimer_mode mode)
{
	SIL_PRE_LOC;

	(void)mode;
	if (timer == NULL) {
		lx_report("hrtimer_init", NULL, 0, "NULL timer");
		return;
	}
	SIL_LOC_INT();
	if (timer->lx_magic == HRTIMER_MAGIC && timer->lx_queued) {
		dequeue_locked(timer);
		SIL_UNL_INT();
		lx_report("hrtimer_init on an active timer", NULL, 0,
			  "the timer was queued; it is dequeued");
		SIL_LOC_INT();
	}
	timer->function = NULL;
	timer->lx_node.child = timer->lx_node.next = timer->lx_node.prev = NULL;
	timer->lx_expires = 0;
	timer->lx_clockid = clock_id;
	timer->lx_queued = 0;
	timer->lx_cancelled = 0;
	timer->lx_magic = HRTIMER_MAGIC;
	SIL_UNL_INT();
}

/* hrtimer_init plus the callback (Linux 6.13's form). */
void hrtimer_setup(struct hrtimer *timer, enum hrtimer_restart (*function)(struct hrtimer *),
		   clockid_t clock_id, enum hrtimer_mode mode)
{
	hrtimer_init(timer, clock_id, mode);
	if (timer != NULL)
		timer->function = function;
}

/* Checks that timer can be queued; reports and returns false if not. */
static bool startable(struct hrtimer *timer, const char *what)
{
	if (timer == NULL) {
		lx_report(what, NULL, 0, "NULL timer");
		return false;
	}
	if (timer->lx_magic != HRTIMER_MAGIC) {
		lx_report(what, NULL, 0, "the timer was never initialised (hrtimer_init/hrtimer_setup)");
		return false;
	}
	if (timer->function == NULL) {
		lx_report(what, NULL, 0, "the timer has no callback (function is NULL)");
		return false;
	}
	return true;
}

/* Queues timer at its absolute expiry (dequeuing it first if queued). */
static void requeue_at(struct hrtimer *timer, ktime_t expires)
{
	SIL_PRE_LOC;

	SIL_LOC_INT();
	if (timer->lx_queued)
		dequeue_locked(timer);
	timer->lx_expires = expires;
	timer->lx_cancelled = 0;
	enqueue_locked(timer);
	SIL_UNL_INT();
}

/* (Re)queues timer at tim (ABS) or now + tim (REL). */
void hrtimer_start(struct hrtimer *timer, ktime_t tim, const enum hrtimer_mode mode)
{
	if (!startable(timer, "hrtimer_start"))
		return;
	if (mode & HRTIMER_MODE_REL)
		tim = ktime_add_safe(ktime_get(), tim < 0 ? 0 : tim);
	requeue_at(timer, tim);
}

/* hrtimer_start; the slack is not used (expiry is served at tim). */
void hrtimer_start_range_ns(struct hrtimer *timer, ktime_t tim, u64 delta_ns,
			    const enum hrtimer_mode mode)
{
	(void)delta_ns;
	hrtimer_start(timer, tim, mode);
}

/* Requeues timer at its current expiry. */
void hrtimer_restart(struct hrtimer *timer)
{
	if (startable(timer, "hrtimer_restart"))
		requeue_at(timer, timer->lx_expires);
}

/*
 * False (after a report) if timer was never initialised: Linux's cancel reads
 * timer->base, which hrtimer_init sets — NULL in a timer never initialised, an
 * oops on 6.1 and an endless loop in 2.6's lock_hrtimer_base.  LEGO's exit
 * code cancels its timer even when its init's misc_register failed and the
 * timer was never set up.
 */
static bool cancellable(const struct hrtimer *timer, const char *what)
{
	if (timer == NULL)
		return false;
	if (timer->lx_magic != HRTIMER_MAGIC) {
		lx_report(what, NULL, 0, "the timer was never initialised (hrtimer_init/hrtimer_setup): "
			  "Linux dereferences its NULL base here and crashes (6.1) or spins for ever (2.6)");
		return false;
	}
	return true;
}

/* Dequeues timer: 1 if it was queued, 0 if inactive, -1 while its callback runs. */
int hrtimer_try_to_cancel(struct hrtimer *timer)
{
	int ret;
	SIL_PRE_LOC;

	if (!cancellable(timer, "hrtimer_try_to_cancel"))
		return 0;
	SIL_LOC_INT();
	if (queue.running == timer) {
		ret = -1;
	} else if (timer->lx_queued) {
		dequeue_locked(timer);
		ret = 1;
	} else {
		ret = 0;
	}
	SIL_UNL_INT();
	return ret;
}

/* Stops timer; 1 if it was active.  Self-cancellation is reported (at file:line), never waited for. */
int lx_hrtimer_cancel_at(struct hrtimer *timer, const char *file, int line)
{
	int ret;
	SIL_PRE_LOC;

	if (!cancellable(timer, "hrtimer_cancel"))
		return 0;
	SIL_LOC_INT();
	if (queue.running != timer) {
		ret = timer->lx_queued ? 1 : 0;
		if (timer->lx_queued)
			dequeue_locked(timer);
		SIL_UNL_INT();
		return ret;
	}
	/* Linux would wait for the callback to finish: from the callback itself
	 * (or anything it interrupted) that never happens. */
	if (timer->lx_queued)
		dequeue_locked(timer);
	timer->lx_cancelled = 1;
	SIL_UNL_INT();
	lx_report("hrtimer_cancel would deadlock", file, line,
		  "the timer is cancelled while its callback runs (%s); use hrtimer_try_to_cancel "
		  "or return HRTIMER_NORESTART",
		  lx_running_hrtimer() == timer ? "from its own callback" : "from a context it interrupted");
	return 1;
}

/* hrtimer_cancel without a call site. */
int (hrtimer_cancel)(struct hrtimer *timer)
{
	return lx_hrtimer_cancel_at(timer, NULL, 0);
}

/* Advances the expiry from the previous expiry past now in whole intervals; their count. */
u64 hrtimer_forward(struct hrtimer *timer, ktime_t now, ktime_t interval)
{
	u64 overruns;

	if (timer == NULL)
		return 0;
	if (timer->lx_queued) {
		lx_report("hrtimer_forward on a queued timer", NULL, 0,
			  "the timer is queued; forward it only from its callback or when stopped");
		return 0;
	}
	if (now < timer->lx_expires)
		return 0;
	if (interval <= 0) {
		lx_report("hrtimer_forward", NULL, 0, "interval %lld ns is not positive",
			  (long long)interval);
		interval = 1;
	}
	/* As Linux: no interval is shorter than the clock's resolution (here the
	 * tick), so a sub-tick period is delivered once per tick, without overrun. */
	if (interval < (ktime_t)hrtimer_resolution)
		interval = (ktime_t)hrtimer_resolution;
	/* One period is the usual case: no 64-bit division (a library call on the
	 * ARM926); only an overrun of several periods needs it, as in Linux. */
	if (now - timer->lx_expires < interval) {
		timer->lx_expires = ktime_add_safe(timer->lx_expires, interval);
		return 1;
	}
	overruns = (u64)(now - timer->lx_expires) / (u64)interval + 1U;
	timer->lx_expires = ktime_add_safe(timer->lx_expires, (ktime_t)(overruns * (u64)interval));
	return overruns;
}

/* hrtimer_forward from the current time. */
u64 hrtimer_forward_now(struct hrtimer *timer, ktime_t interval)
{
	return hrtimer_forward(timer, ktime_get(), interval);
}

/* Queued or running. */
bool hrtimer_active(const struct hrtimer *timer)
{
	return timer != NULL && timer->lx_magic == HRTIMER_MAGIC &&
	       (timer->lx_queued || queue.running == timer);
}

/* Queued. */
bool hrtimer_is_queued(struct hrtimer *timer)
{
	return timer != NULL && timer->lx_magic == HRTIMER_MAGIC && timer->lx_queued;
}

/* Callback running. */
bool hrtimer_callback_running(struct hrtimer *timer)
{
	return timer != NULL && queue.running == timer;
}

/* Expiry minus now. */
ktime_t hrtimer_get_remaining(const struct hrtimer *timer)
{
	return timer->lx_expires - ktime_get();
}

/*
 * Takes the first due timer off the queue and marks it running; NULL if none.
 * (Timers queued due during the pass wait on the deferred FIFO, not here.)
 * Interrupts locked by the caller.
 */
static struct hrtimer *take_due_locked(u64 now)
{
	struct hrtimer *t = queue_first();

	if (t == NULL || t->lx_expires > (ktime_t)now)
		return NULL;
	dequeue_locked(t);
	t->lx_cancelled = 0;
	queue.running = t;
	return t;
}

/*
 * Runs every timer due at now, in expiry order, in the calling (tick ISR)
 * context.  Interrupts are locked around the queue work only: one locked
 * section between two callbacks (the previous one's re-queueing, the next
 * one's removal), none around a callback.
 */
void lx_hrtimer_run_due(uint64_t now)
{
	struct hrtimer *t;
	enum hrtimer_restart ret;
	SIL_PRE_LOC;

	/* The per-tick fast path: nothing due. */
	t = queue_first();
	if (t == NULL || t->lx_expires > (ktime_t)now)
		return;
	SIL_LOC_INT();
	lx_heap_pass_begin(&queue.heap, now);
	while ((t = take_due_locked(now)) != NULL) {
		SIL_UNL_INT();
		lx_timer_callback_enter(true, t);
		ret = t->function(t);
		lx_timer_callback_exit();
		if (ret == HRTIMER_RESTART && t->function == NULL) {
			/* Re-initialised in its own callback and never given a function. */
			lx_report("hrtimer callback returned HRTIMER_RESTART", NULL, 0,
				  "the timer has no callback any more; it is not restarted");
			ret = HRTIMER_NORESTART;
		}
		SIL_LOC_INT();
		queue.running = NULL;
		/* A timer the callback started again stays where it was put. */
		if (ret == HRTIMER_RESTART && !t->lx_queued && !t->lx_cancelled)
			enqueue_locked(t);
		if (ret == HRTIMER_RESTART)
			t->lx_cancelled = 0;
	}
	lx_heap_pass_end(&queue.heap);
	SIL_UNL_INT();
}
