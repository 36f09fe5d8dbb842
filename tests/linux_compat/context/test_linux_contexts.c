/*
 * test_linux_contexts.c — the context predicates and rules as Linux has them:
 * irqs_disabled() is true in a hard-IRQ handler and an hrtimer callback;
 * a timer_list callback runs in softirq context (in_softirq, in_interrupt,
 * not in_irq, interrupts enabled) and may del_timer_sync another timer;
 * a complete() under spin_lock_irqsave makes the waiter run at the unlock,
 * not at the next tick.
 */
#include "tap.h"
#include "lx_core_test.h"
#include <linux/kernel.h>
#include <linux/hrtimer.h>
#include <linux/timer.h>
#include <linux/interrupt.h>
#include <linux/spinlock.h>
#include <linux/completion.h>
#include <linux/preempt.h>
#include <linux/irqflags.h>
#include <linux/delay.h>
#include <linux/ktime.h>
#include <kernel.h>

#define WAITER_TSKID	2

static struct hrtimer probe_hrtimer;
static struct timer_list probe_timer, other_timer;
static bool hr_irqs_disabled, hr_in_irq, hr_not_softirq;
static bool tl_in_softirq, tl_in_interrupt, tl_not_in_irq, tl_irqs_enabled, tl_not_task;
static bool isr_irqs_disabled, isr_in_irq;
static bool handler_irqs_disabled, handler_in_irq;
static int tl_del_ret = -1;
static uint_t tl_bugs = 1;
static DEFINE_SPINLOCK(wake_lock);
static DECLARE_COMPLETION(wake_done);
static bool waiter_ran, waiter_ran_at_unlock;
static s64 completed_at, waiter_woke_at;

static enum hrtimer_restart probe_hr_cb(struct hrtimer *t)
{
	(void)t;
	hr_irqs_disabled = irqs_disabled();
	hr_in_irq = in_irq() && in_hardirq() && in_interrupt();
	hr_not_softirq = !in_softirq() && !in_serving_softirq();
	return HRTIMER_NORESTART;
}

static void other_fn(struct timer_list *t)
{
	(void)t;
}

static void probe_timer_fn(struct timer_list *t)
{
	uint_t before = rtos_host_bug_count();

	(void)t;
	tl_in_softirq = in_softirq() && in_serving_softirq();
	tl_in_interrupt = in_interrupt();
	tl_not_in_irq = !in_irq() && !in_hardirq();
	tl_irqs_enabled = !irqs_disabled();
	tl_not_task = !in_task();
	/* Legal in Linux from softirq context: only hard-IRQ context is refused. */
	tl_del_ret = del_timer_sync(&other_timer);
	tl_bugs = rtos_host_bug_count() - before;
}

static irqreturn_t probe_handler(int irq, void *dev)
{
	(void)irq;
	(void)dev;
	handler_irqs_disabled = irqs_disabled();
	handler_in_irq = in_irq() && !in_softirq();
	return IRQ_HANDLED;
}

static void probe_isr(intptr_t exinf)
{
	(void)exinf;
	isr_irqs_disabled = irqs_disabled();
	isr_in_irq = in_irq() && !in_softirq();
}

static void waiter_task(intptr_t exinf)
{
	(void)exinf;
	wait_for_completion(&wake_done);
	waiter_woke_at = ktime_get_ns();
	waiter_ran = true;
}

static void main_task(intptr_t exinf)
{
	unsigned long flags;
	static int dev;

	(void)exinf;
	hrtimer_setup(&probe_hrtimer, probe_hr_cb, CLOCK_MONOTONIC, HRTIMER_MODE_REL);
	hrtimer_start(&probe_hrtimer, us_to_ktime(300), HRTIMER_MODE_REL);
	msleep(2);

	timer_setup(&probe_timer, probe_timer_fn, 0);
	timer_setup(&other_timer, other_fn, 0);
	mod_timer(&other_timer, jiffies + 100);
	mod_timer(&probe_timer, jiffies + 1);
	msleep(5);

	rtos_host_irq_raise(91);
	if (request_irq(IRQ_DA8XX_EVTOUT1, probe_handler, 0, "probe", &dev) == 0) {
		rtos_host_irq_raise(IRQ_DA8XX_EVTOUT1);
		(void)free_irq(IRQ_DA8XX_EVTOUT1, &dev);
	}

	/* The waiter has the higher priority: Linux runs it at the unlock. */
	(void)act_tsk(WAITER_TSKID);
	msleep(1);
	spin_lock_irqsave(&wake_lock, flags);
	completed_at = ktime_get_ns();
	complete(&wake_done);
	spin_unlock_irqrestore(&wake_lock, flags);
	waiter_ran_at_unlock = waiter_ran;
}

int main(void)
{
	static const struct rtos_task_cfg tasks[] = {
		LXC_TASK(1, main_task, 8, true),
		LXC_TASK(WAITER_TSKID, waiter_task, 4, false),
	};
	static const struct rtos_int_cfg ints[] = { { 91, TA_ENAINT | TA_EDGE, -3 } };
	static const struct rtos_isr_cfg isrs[] = { { TA_NULL, 0, 91, probe_isr, 1 } };

	tap_plan(12);
	if (!lxc_boot(tasks, 2, ints, 1, isrs, 1))
		return tap_done();
	rtos_host_run_for(20 * NSEC_PER_MSEC);
	rtos_host_shutdown();

	ok(hr_irqs_disabled, "hrtimer callback: irqs_disabled()");
	ok(hr_in_irq && hr_not_softirq, "hrtimer callback: hard-IRQ context, not softirq");
	ok(handler_irqs_disabled, "Linux IRQ handler: irqs_disabled()");
	ok(handler_in_irq, "Linux IRQ handler: in_irq, not in_softirq");
	ok(isr_irqs_disabled && isr_in_irq, "RTOS ISR: irqs_disabled and in_irq");
	ok(tl_in_softirq && tl_in_interrupt, "timer_list callback: in_softirq and in_interrupt");
	ok(tl_not_in_irq, "timer_list callback: not in_irq/in_hardirq");
	ok(tl_irqs_enabled && tl_not_task, "timer_list callback: interrupts enabled, not in_task");
	is_int(tl_del_ret, 1, "del_timer_sync of another (pending) timer from a timer callback dequeues it");
	is_int((int)tl_bugs, 0, "...and is not reported");
	ok(waiter_ran_at_unlock, "complete() under spin_lock_irqsave: the waiter ran at the unlock");
	ok(waiter_ran && waiter_woke_at - completed_at < (s64)hrtimer_resolution,
	   "...within the same tick (woke %lld ns after complete)", (long long)(waiter_woke_at - completed_at));
	return tap_done();
}
