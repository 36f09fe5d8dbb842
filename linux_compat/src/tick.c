/*
 * tick.c — linux_compat's ISR on the RTOS tick, and its boot-time reset.
 */
#include <linux/kernel.h>
#include <linux/module.h>
#include <linux_compat/clock.h>
#include <linux_compat/config.h>
#include <linux_compat/context.h>
#include <linux_compat/heap.h>
#include <linux_compat/sched.h>
#include <linux_compat/workqueue.h>

/* Every tick: jiffies, wakeups deferred while locked, due hrtimers, due timer_list timers. */
void lx_tick_isr(intptr_t exinf)
{
	uint64_t now = lx_clock_now_ns();

	(void)exinf;
	lx_jiffies_update(now);
	lx_deferred_wakeups_run();
	lx_hrtimer_run_due(now);
	lx_timers_run_due();
}

/* ATT_INI: a fresh system has no timers, locks, waiters or work, and no module is loaded. */
void lx_compat_boot(intptr_t exinf)
{
	(void)exinf;
	lx_modules_reset();
	lx_heap_reset();
	lx_clock_reset();
	lx_context_reset();
	lx_sched_reset();
	lx_hrtimer_reset();
	lx_timers_reset();
	lx_workqueue_reset();
}
