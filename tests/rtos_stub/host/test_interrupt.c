/*
 * test_interrupt.c — interrupt delivery: CPU lock masks interrupts and holds
 * off dispatch; nesting of higher over lower priority (lower pends); several
 * ISRs on a line in isrpri order; dis_int/ena_int; level lines re-delivered
 * while asserted; a level storm is reported; SIL lock masks; ISRs on the tick.
 */
#include "tap.h"
#include "kernel.h"
#include "sil.h"
#include "rtos_test.h"

#define IRQ_LOW   70U   /* priority -1 */
#define IRQ_MID   71U   /* priority -3 */
#define IRQ_HIGH  72U   /* priority -5 */
#define IRQ_LEVEL 73U
#define IRQ_OFF   74U   /* configured disabled */
#define IRQ_STORM 75U

static int level_left;
static uint_t tick_isr_count;
static uint_t depth_in_high;
static bool_t loc_in_isr;

static int low_runs;

static void isr_low(intptr_t x)
{
	rt_log("L(");
	if (low_runs++ == 0) {
		rtos_host_irq_raise(IRQ_HIGH);   /* nests at once; MID, raised by H, nests after H */
		rtos_host_irq_raise(IRQ_LOW);    /* same line again: pends until we return */
	}
	rt_log(")L");
}

static void isr_mid(intptr_t x)
{
	rt_log("M%d", (int)x);
}

static void isr_high(intptr_t x)
{
	depth_in_high = rtos_host_irq_depth();
	rt_log("H");
	rtos_host_irq_raise(IRQ_MID);    /* lower: pends until H returns */
}

static void isr_level(intptr_t x)
{
	rt_log("V%d", level_left);
	if (--level_left == 0)
		rtos_host_irq_set_level(IRQ_LEVEL, false);
}

static void isr_off(intptr_t x)
{
	rt_log("O");
}

static void isr_storm(intptr_t x)
{
	/* never clears its level */
}

static void isr_tick(intptr_t x)
{
	tick_isr_count++;
}

static void isr_wake(intptr_t x)
{
	loc_in_isr = sns_loc();
	rt_log("W");
	iwup_tsk(2);
}

static void high_task(intptr_t x)
{
	for (;;) {
		slp_tsk();
		rt_log("T");
	}
}

static void main_task(intptr_t x)
{
	/* 1. nesting */
	rt_log_reset();
	rtos_host_irq_raise(IRQ_LOW);
	rt_log("|");

	/* 2. CPU lock masks interrupts and holds off dispatch */
	loc_cpu();
	rtos_host_irq_raise(IRQ_OFF + 10);  /* wake line (84) */
	rt_log("locked");
	unl_cpu();                          /* ISR, then high_task preempts */
	rt_log("unlocked");
	rt_log("|");

	/* 3. dis_dsp: the ISR runs, the dispatch waits for ena_dsp */
	dis_dsp();
	rtos_host_irq_raise(IRQ_OFF + 10);
	rt_log("dsp-off");
	ena_dsp();
	rt_log("|");

	/* 4. a disabled line pends until ena_int */
	rtos_host_irq_raise(IRQ_OFF);
	rt_log("off");
	ena_int(IRQ_OFF);
	dis_int(IRQ_OFF);
	rt_log("|");

	/* 5. level: delivered again while asserted */
	level_left = 3;
	rtos_host_irq_set_level(IRQ_LEVEL, true);
	rt_log("|");

	/* 6. SIL lock masks interrupts (nesting-safe) */
	{
		SIL_PRE_LOC;
		SIL_LOC_INT();
		{
			uint_t inner = sil_host_loc_int();
			rtos_host_irq_raise(IRQ_OFF + 10);
			sil_host_unl_int(inner);
			rt_log("inner-unl");
		}
		SIL_UNL_INT();
	}
	rt_log("sil-unl");
}

static const struct rtos_task_cfg tasks[] = {
	{ 1, TA_ACT, 0, main_task, 5, 1024, TDOM_KERNEL, "main" },
	{ 2, TA_ACT, 0, high_task, 2, 1024, TDOM_KERNEL, "high" },
};
static const struct rtos_int_cfg ints[] = {
	{ IRQ_LOW, TA_ENAINT, -1 },
	{ IRQ_MID, TA_ENAINT, -3 },
	{ IRQ_HIGH, TA_ENAINT, -5 },
	{ IRQ_LEVEL, TA_ENAINT, -2 },
	{ IRQ_OFF, TA_NULL, -2 },
	{ IRQ_STORM, TA_ENAINT, -2 },
	{ IRQ_OFF + 10, TA_ENAINT, -4 },
};
static const struct rtos_isr_cfg isrs[] = {
	{ TA_NULL, 0, IRQ_LOW, isr_low, 1 },
	{ TA_NULL, 2, IRQ_MID, isr_mid, 9 },
	{ TA_NULL, 1, IRQ_MID, isr_mid, 3 },    /* isrpri 3 runs before 9 */
	{ TA_NULL, 0, IRQ_HIGH, isr_high, 1 },
	{ TA_NULL, 0, IRQ_LEVEL, isr_level, 1 },
	{ TA_NULL, 0, IRQ_OFF, isr_off, 1 },
	{ TA_NULL, 0, IRQ_STORM, isr_storm, 1 },
	{ TA_NULL, 0, IRQ_OFF + 10, isr_wake, 1 },
	{ TA_NULL, 0, INTNO_TICK, isr_tick, 1 },
};
static const struct rtos_cfg cfg = {
	.name = "interrupt", .tasks = RTOS_TABLE(tasks), .ints = RTOS_TABLE(ints), .isrs = RTOS_TABLE(isrs),
};

int main(void)
{
	const char *log;

	tap_plan(12);
	is_int(rtos_host_boot(&cfg), E_OK, "boot");
	rtos_host_run_for(1000000);
	log = rt_log_text();
	ok(strncmp(log, "L( H M1 M2 )L L( )L |", 21) == 0,
	   "higher priority nests, lower pends until the higher returns, same line pends; ISRs in isrpri order");
	tap_diag("log: %s", log);
	ok(strstr(log, "| locked W T unlocked |") != NULL,
	   "CPU lock masks the interrupt; on unl_cpu the ISR runs, then the woken task preempts");
	ok(strstr(log, "| W dsp-off T |") != NULL, "dis_dsp: the ISR runs at once, the dispatch waits for ena_dsp");
	ok(strstr(log, "| off O |") != NULL, "a disabled line pends and is taken on ena_int");
	ok(strstr(log, "| V3 V2 V1 |") != NULL, "a level line is re-delivered until the ISR deasserts it");
	ok(strstr(log, "| inner-unl W T sil-unl") != NULL,
	   "SIL lock masks interrupts and nests: delivery at the outermost SIL_UNL_INT");
	is_int(depth_in_high, 2, "nesting depth 2 in the nested ISR");
	is_int(tick_isr_count, 5, "an ISR on INTNO_TICK runs on every tick (5 in 1 ms)");
	is_int(rtos_host_irq_priority(INTNO_TICK), INTPRI_TICK, "the kernel configured the tick line");

	rtos_host_expect_bugs(true);
	rtos_host_irq_set_level(IRQ_STORM, true);
	ok(rtos_host_bug_count() == 1 && strstr(rtos_host_last_bug(), "irq storm") != NULL &&
	   !rtos_host_irq_enabled(IRQ_STORM), "a level line that never clears is reported and disabled");
	tap_diag("bug: %s", rtos_host_last_bug());
	rtos_host_expect_bugs(false);
	ok(!loc_in_isr, "sns_loc is FALSE in an ISR taken after unl_cpu");
	rtos_host_shutdown();
	return tap_done();
}
