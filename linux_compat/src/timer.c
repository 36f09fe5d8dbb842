/*
 * timer.c — jiffies and timer_list timers, served by the tick ISR.
 *
 * Pending timers are in a pairing heap (linux_compat/timerheap.h) ordered by
 * expiry (wrap-safe, as time_before) and queueing sequence: O(1) to add,
 * O(log n) amortized to take the first or delete any, where Linux uses its
 * timer wheel.  A timer queued at a time already due while the tick runs the
 * due ones waits for the next tick.
 */
#include <linux/timer.h>
#include <linux/jiffies.h>
#include <linux/kernel.h>
#include <linux_compat/clock.h>
#include <linux_compat/context.h>
#include <linux_compat/report.h>
#include <linux_compat/sched.h>
#include <linux_compat/timerheap.h>
#include <kernel.h>
#include <sil.h>

#define TIMER_MAGIC	LX_TIMER_MAGIC

volatile unsigned long jiffies = INITIAL_JIFFIES;
u64 jiffies_64 = INITIAL_JIFFIES;

/* Clock time at which jiffies next advance: jiffies follow the clock by
 * counting, because a 64-bit division per tick costs ~170 instructions on
 * the ARM926, which has no divide instruction. */
static u64 next_jiffy_ns = TICK_NSEC;

/* Pending timers in expiry order, FIFO among equal expiries. */
static struct {
	struct lx_heap heap;
	/* The timer whose callback runs (the timer is not touched after its
	 * callback: the callback may free it). */
	const struct timer_list *running;
} tq;

/* The first pending timer, or NULL. */
static inline struct timer_list *queue_first(void)
{
	struct lx_heap_node *first = lx_heap_first(&tq.heap);

	return first != NULL ? container_of(first, struct timer_list, lx_node) : NULL;
}

/* Empties the queue and restarts jiffies (boot). */
void lx_timers_reset(void)
{
	lx_heap_init(&tq.heap);
	tq.running = NULL;
	jiffies_64 = INITIAL_JIFFIES;
	jiffies = (unsigned long)jiffies_64;
	next_jiffy_ns = TICK_NSEC;
}

/* Sets jiffies from the clock (tick ISR). */
void lx_jiffies_update(uint64_t now)
{
	u64 j = jiffies_64;
	SIL_PRE_LOC;

	if (now < next_jiffy_ns)
		return;
	do {			/* = INITIAL_JIFFIES + now / TICK_NSEC */
		j++;
		next_jiffy_ns += TICK_NSEC;
	} while (now >= next_jiffy_ns);
	SIL_LOC_INT();
	jiffies_64 = j;
	jiffies = (unsigned long)j;
	SIL_UNL_INT();
}

/* jiffies_64 without tearing. */
u64 get_jiffies_64(void)
{
	u64 j;
	SIL_PRE_LOC;

	SIL_LOC_INT();
	j = jiffies_64;
	SIL_UNL_INT();
	return j;
}

/* Queues timer after every timer expiring no later (FIFO among equals); during
 * the tick's pass a due one waits for the pass to end.  The heap's key is the
 * expiry on the 64-bit jiffies count (expires is jiffies' wrapping value, and
 * its distance from now fits a long, as time_before assumes).  Locked by the
 * caller. */
static void enqueue_locked(struct timer_list *timer)
{
	timer->lx_node.key = jiffies_64 + (u64)(s64)(long)(timer->expires - (unsigned long)jiffies_64);
	timer->lx_pending = 1;
	lx_heap_insert(&tq.heap, &timer->lx_node);
}

/* Unlinks a pending timer; locked by the caller. */
static void dequeue_locked(struct timer_list *timer)
{
	lx_heap_remove(&tq.heap, &timer->lx_node);
	timer->lx_pending = 0;
}

/* Prepares timer with callback fn. */
void timer_setup(struct timer_list *timer, void (*fn)(struct timer_list *), unsigned int flags)
{
	if (timer == NULL) {
		lx_report("timer_setup", NULL, 0, "NULL timer");
		return;
	}
	if (timer->lx_magic == TIMER_MAGIC && timer->lx_pending) {
		lx_report("timer_setup on a pending timer", NULL, 0, "the timer is dequeued first");
		del_timer(timer);
	}
	timer->expires = 0;
	timer->function = fn;
	timer->flags = flags;
	timer->lx_node.child = timer->lx_node.next = timer->lx_node.prev = NULL;
	timer->lx_pending = 0;
	timer->lx_magic = TIMER_MAGIC;
}

/* Checks that timer is usable; reports if not. */
static bool usable(struct timer_list *timer, const char *what)
{
	if (timer == NULL) {
		lx_report(what, NULL, 0, "NULL timer");
		return false;
	}
	if (timer->lx_magic != TIMER_MAGIC) {
		lx_report(what, NULL, 0, "the timer was never set up (timer_setup)");
		return false;
	}
	if (timer->function == NULL) {
		lx_report(what, NULL, 0, "the timer has no callback");
		return false;
	}
	return true;
}

/* (Re)queues timer at expires; 1 if it was pending. */
int mod_timer(struct timer_list *timer, unsigned long expires)
{
	int was_pending;
	SIL_PRE_LOC;

	if (!usable(timer, "mod_timer"))
		return 0;
	SIL_LOC_INT();
	was_pending = timer->lx_pending;
	if (was_pending)
		dequeue_locked(timer);
	timer->expires = expires;
	enqueue_locked(timer);
	SIL_UNL_INT();
	return was_pending;
}

/* Moves a pending timer earlier (never later), or queues an idle one. */
int timer_reduce(struct timer_list *timer, unsigned long expires)
{
	if (timer != NULL && timer->lx_pending && !time_before(expires, timer->expires))
		return 1;
	return mod_timer(timer, expires);
}

/* Queues an idle timer at timer->expires. */
void add_timer(struct timer_list *timer)
{
	if (timer != NULL && timer->lx_pending) {
		lx_report("add_timer on a pending timer", NULL, 0, "use mod_timer to re-arm");
		return;
	}
	if (timer != NULL)
		(void)mod_timer(timer, timer->expires);
}

/* Dequeues timer; 1 if it was pending. */
int del_timer(struct timer_list *timer)
{
	int was_pending;
	SIL_PRE_LOC;

	if (timer == NULL || timer->lx_magic != TIMER_MAGIC)
		return 0;
	SIL_LOC_INT();
	was_pending = timer->lx_pending;
	if (was_pending)
		dequeue_locked(timer);
	SIL_UNL_INT();
	return was_pending;
}

/* del_timer; waiting for a running callback would deadlock from it, so that is reported. */
int lx_del_timer_sync_at(struct timer_list *timer, const char *file, int line)
{
	if (timer != NULL && tq.running == timer)
		lx_report("del_timer_sync would deadlock", file, line,
			  "the timer's callback is running (called from it or from what it interrupted)");
	else if (timer != NULL && lx_in_hardirq() && !(timer->flags & TIMER_IRQSAFE))
		lx_report("del_timer_sync in hard-IRQ context", file, line,
			  "Linux forbids this for timers without TIMER_IRQSAFE");
	return del_timer(timer);
}

/* del_timer_sync without a call site. */
int (del_timer_sync)(struct timer_list *timer)
{
	return lx_del_timer_sync_at(timer, NULL, 0);
}

/* Takes the first due timer off the queue (marked running), or NULL; (timers
 * queued due during the pass wait on the deferred FIFO); interrupts locked by
 * the caller. */
static struct timer_list *take_due_locked(u64 now)
{
	struct timer_list *t = queue_first();

	if (t == NULL || t->lx_node.key > now)
		return NULL;
	dequeue_locked(t);
	tq.running = t;
	return t;
}

/* Runs the due timer_list callbacks (tick ISR), unless bottom halves are disabled. */
void lx_timers_run_due(void)
{
	struct timer_list *t;
	const struct timer_list *first = queue_first();
	u64 now = jiffies_64;
	SIL_PRE_LOC;

	if (first == NULL || first->lx_node.key > now || lx_bh_disabled())
		return;
	SIL_LOC_INT();
	lx_heap_pass_begin(&tq.heap, now);
	while ((t = take_due_locked(now)) != NULL) {
		SIL_UNL_INT();
		lx_timer_callback_enter(false, t);
		t->function(t);
		lx_timer_callback_exit();
		SIL_LOC_INT();
		tq.running = NULL;
	}
	lx_heap_pass_end(&tq.heap);
	SIL_UNL_INT();
}
