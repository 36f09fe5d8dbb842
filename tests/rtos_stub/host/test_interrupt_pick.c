/*
 * test_interrupt_pick.c — which pending line is delivered next: the most
 * urgent enabled one, the lowest number among equal priorities; pending
 * disabled lines are passed over until enabled; a level line asserted
 * through its own ISR is not taken again inside it but after it, and a more
 * urgent line raised meanwhile still nests; lines raised under a CPU lock
 * come out in priority order at unl_cpu.
 */
#include "tap.h"
#include "kernel.h"
#include "rtos_test.h"

#define IRQ_A     80U   /* priority -2 */
#define IRQ_B     81U   /* priority -2 */
#define IRQ_C     82U   /* priority -4, configured disabled */
#define IRQ_LVL   83U   /* priority -3, level */
#define IRQ_URG   84U   /* priority -6 */
#define IRQ_LOW2  20U   /* priority -1, a low number with a low priority */

static int lvl_left;

static void isr_log(intptr_t x)
{
	rt_log("%c", (char)x);
}

static void isr_lvl(intptr_t x)
{
	rt_log("V%d", lvl_left);
	if (lvl_left == 2)
		rtos_host_irq_raise(IRQ_URG);   /* more urgent: nests at once */
	rtos_host_irq_raise(IRQ_A);             /* less urgent: waits for V to return */
	if (--lvl_left == 0)
		rtos_host_irq_set_level(IRQ_LVL, false);
	rt_log(")");
}

static void main_task(intptr_t x)
{
	rt_log_reset();

	/* 1. under a CPU lock: raised in reverse order, delivered by priority, then number */
	loc_cpu();
	rtos_host_irq_raise(IRQ_LOW2);
	rtos_host_irq_raise(IRQ_B);
	rtos_host_irq_raise(IRQ_A);
	rtos_host_irq_raise(IRQ_URG);
	rtos_host_irq_raise(IRQ_C);      /* disabled: stays pending */
	unl_cpu();
	rt_log("|");

	/* 2. the pending disabled line is taken when enabled, and not again after */
	ena_int(IRQ_C);
	rtos_host_irq_raise(IRQ_B);
	dis_int(IRQ_C);
	rtos_host_irq_raise(IRQ_C);
	rt_log("|");

	/* 3. raised under a lock in rising urgency: the more urgent first */
	loc_cpu();
	rtos_host_irq_raise(IRQ_A);
	rtos_host_irq_raise(IRQ_URG);
	unl_cpu();
	rt_log("|");

	/* 4. a level line through its ISR */
	lvl_left = 3;
	rtos_host_irq_set_level(IRQ_LVL, true);
	rt_log("|");
}

static const struct rtos_task_cfg tasks[] = {
	{ 1, TA_ACT, 0, main_task, 5, 1024, TDOM_KERNEL, "main" },
};
static const struct rtos_int_cfg ints[] = {
	{ IRQ_A, TA_ENAINT, -2 },
	{ IRQ_B, TA_ENAINT, -2 },
	{ IRQ_C, TA_NULL, -4 },
	{ IRQ_LVL, TA_ENAINT, -3 },
	{ IRQ_URG, TA_ENAINT, -6 },
	{ IRQ_LOW2, TA_ENAINT, -1 },
};
static const struct rtos_isr_cfg isrs[] = {
	{ TA_NULL, 'A', IRQ_A, isr_log, 1 },
	{ TA_NULL, 'B', IRQ_B, isr_log, 1 },
	{ TA_NULL, 'C', IRQ_C, isr_log, 1 },
	{ TA_NULL, 0, IRQ_LVL, isr_lvl, 1 },
	{ TA_NULL, 'U', IRQ_URG, isr_log, 1 },
	{ TA_NULL, 'L', IRQ_LOW2, isr_log, 1 },
};
static const struct rtos_cfg cfg = {
	.name = "interrupt_pick", .tasks = RTOS_TABLE(tasks), .ints = RTOS_TABLE(ints), .isrs = RTOS_TABLE(isrs),
};

int main(void)
{
	const char *log;

	tap_plan(6);
	is_int(rtos_host_boot(&cfg), E_OK, "boot");
	rtos_host_run_for(1000000);
	log = rt_log_text();
	tap_diag("log: %s", log);
	ok(strncmp(log, "U A B L |", 9) == 0,
	   "after unl_cpu: most urgent first, the lower number among equals, the disabled line held");
	ok(strstr(log, "| C B |") != NULL, "the pending disabled line is taken at ena_int, once");
	ok(strstr(log, "| U A |") != NULL, "raised under a lock: the more urgent line first");
	ok(strstr(log, "| V3 ) V2 U ) V1 ) A |") != NULL,
	   "a level line is taken again after its ISR, not inside; a more urgent one nests, a less urgent one waits");
	ok(rtos_host_irq_pending(IRQ_C) && !rtos_host_irq_enabled(IRQ_C), "the line raised while disabled stays pending");
	rtos_host_shutdown();
	return tap_done();
}
