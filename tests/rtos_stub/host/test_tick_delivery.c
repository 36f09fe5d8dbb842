/*
 * test_tick_delivery.c — the tick line with ISRs attached: it is raised on
 * every boundary, across the ends of runs; at each, the kernel's time events
 * due then are processed first, then the line's ISRs in isrpri order, in ISR
 * context at depth 1, and a task a time event released runs after them.  A
 * tick while the CPU is locked waits, latched, for unl_cpu.  Lines a tick's ISR
 * raises below the tick's priority are delivered after its ISRs, best first,
 * every one of them, then the task one of them woke.
 */
#include "tap.h"
#include "kernel.h"
#include "rtos_test.h"

#define US 1000ULL
#define IRQ_MID 40U    /* below the tick */
#define IRQ_LOW 41U    /* below IRQ_MID */

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

/* A tick ISR: on the tick at 2000 us, raises the low line, then the middle one. */
static void isr_raise(intptr_t x)
{
	(void)x;
	if (rtos_host_now() == 2000 * US) {
		rtos_host_irq_raise(IRQ_LOW);
		rtos_host_irq_raise(IRQ_MID);
	}
}

/* The low line's ISR: logs and wakes the waiter. */
static void isr_low(intptr_t name)
{
	isr_log(name);
	iwup_tsk(2);
}

/* Waits for the low line's ISR, logs when it runs. */
static void waiter(intptr_t x)
{
	(void)x;
	slp_tsk();
	rt_log("T%llu", (unsigned long long)(rtos_host_now() / US));
	slp_tsk();
}

static const struct rtos_task_cfg tasks[] = { RT_TASK(1, sleeper, 5, true), RT_TASK(2, waiter, 3, true) };
static const struct rtos_int_cfg ints[] = { { IRQ_MID, TA_ENAINT, -4 }, { IRQ_LOW, TA_ENAINT, -2 } };
static const struct rtos_isr_cfg tick_isrs[] = {
	{ TA_NULL, 'b', INTNO_TICK, isr_log, 2 },
	{ TA_NULL, 'a', INTNO_TICK, isr_log, 1 },   /* isrpri 1 runs before 2 */
	{ TA_NULL, 0, INTNO_TICK, isr_raise, 3 },
	{ TA_NULL, 'm', IRQ_MID, isr_log, 1 },
	{ TA_NULL, 'l', IRQ_LOW, isr_low, 1 },
};
static const struct rtos_cfg cfg = {
	.name = "tick_delivery", .tasks = RTOS_TABLE(tasks), .ints = RTOS_TABLE(ints),
	.isrs = RTOS_TABLE(tick_isrs),
};

int main(void)
{
	/* no CPU time for service calls: the sleep starts at time 0 exactly */
	static const struct rtos_host_cpu_cost free_calls = { 0, 0, false, 0 };

	tap_plan(6);
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

	rt_log_reset();
	rtos_host_run_for(400 * US);
	is_str(rt_log_text(), "a1800 b1800 a2000 b2000 m2000 l2000 T2000",
	       "lines a tick's ISR raised run after its ISRs, best first, then the task one woke");
	rtos_host_shutdown();
	return tap_done();
}
