/*
 * test_tick_delivery.c — the tick line with ISRs attached: it is raised on
 * every boundary, across the ends of runs; at each, the kernel's time events
 * due then are processed first, then the line's ISRs in isrpri order, in ISR
 * context at depth 1, and a task a time event released runs after them.  A
 * tick while the CPU is locked waits, latched, for unl_cpu.
 */
#include "tap.h"
#include "kernel.h"
#include "rtos_test.h"

#define US 1000ULL

static bool all_in_isr_context = true;

/* Logs the ISR's name and the time in microseconds, after checking its context. */
static void isr_log(intptr_t name)
{
	if (!sns_ctx() || rtos_host_irq_depth() != 1)
		all_in_isr_context = false;
	rt_log("%c%llu", (char)name, (unsigned long long)(rtos_host_now() / US));
}

/* Sleeps 1 ms from time 0 (the tick at 1000 us releases it) and logs; then
 * spends 300 us with the CPU locked, over the tick at 1200 us, and sleeps for good. */
static void sleeper(intptr_t x)
{
	(void)x;
	dly_tsk(1);
	rt_log("W%llu", (unsigned long long)(rtos_host_now() / US));
	loc_cpu();
	rtos_host_consume(300 * US);
	rt_log("U");
	unl_cpu();
	slp_tsk();
}

static const struct rtos_task_cfg tasks[] = { RT_TASK(1, sleeper, 5, true) };
static const struct rtos_isr_cfg tick_isrs[] = {
	{ TA_NULL, 'b', INTNO_TICK, isr_log, 2 },
	{ TA_NULL, 'a', INTNO_TICK, isr_log, 1 },   /* isrpri 1 runs before 2 */
};
static const struct rtos_cfg cfg = {
	.name = "tick_delivery", .tasks = RTOS_TABLE(tasks), .isrs = RTOS_TABLE(tick_isrs),
};

int main(void)
{
	/* no CPU time for service calls: the sleep starts at time 0 exactly */
	static const struct rtos_host_cpu_cost free_calls = { 0, 0, false };

	tap_plan(5);
	rtos_host_set_cpu_cost(&free_calls);
	is_int(rtos_host_boot(&cfg), E_OK, "boot with two ISRs on the tick line and a sleeping task");
	rtos_host_run_for(1000 * US);
	is_str(rt_log_text(), "a200 b200 a400 b400 a600 b600 a800 b800 a1000 b1000 W1000",
	       "every boundary runs the ISRs in isrpri order; the task released at 1000 us runs after them");
	ok(all_in_isr_context, "the tick's ISRs run in ISR context, not nested");

	rt_log_reset();
	rtos_host_run_for(150 * US);
	rtos_host_run_for(150 * US);
	rtos_host_run_for(300 * US);
	is_str(rt_log_text(), "U a1300 b1300 a1400 b1400 a1600 b1600",
	       "the tick at 1200 us, the CPU locked, is taken at unl_cpu; runs ending between "
	       "boundaries keep the tick on the boundaries");
	is_u64(rtos_host_now(), 1600 * US, "the runs end at their deadline");
	rtos_host_shutdown();
	return tap_done();
}
