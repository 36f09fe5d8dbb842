/*
 * test_task.c — task scheduling: priority order, FIFO within a priority,
 * preemption by sig_sem and by an ISR, the preempted task staying at the
 * head of its queue, rot_rdq, activation queueing and task exit.
 */
#include "tap.h"
#include "kernel.h"
#include "rtos_test.h"

#define INTNO_DEV 50U

static void t_low(intptr_t x);
static void t_mid_a(intptr_t x);
static void t_mid_b(intptr_t x);
static void t_high(intptr_t x);

/* ---- 1: activation order by priority, FIFO within a priority ---- */
static void order_task(intptr_t x)
{
	rt_log("%c", (char)x);
}

static const struct rtos_task_cfg order_tasks[] = {
	{ 1, TA_ACT, 'a', order_task, 8, 1024, TDOM_KERNEL, "a8" },
	{ 2, TA_ACT, 'b', order_task, 3, 1024, TDOM_KERNEL, "b3" },
	{ 3, TA_ACT, 'c', order_task, 8, 1024, TDOM_KERNEL, "c8" },
	{ 4, TA_ACT, 'd', order_task, 1, 1024, TDOM_KERNEL, "d1" },
	{ 5, TA_ACT, 'e', order_task, 3, 1024, TDOM_KERNEL, "e3" },
};
static const struct rtos_cfg order_cfg = { .name = "order", .tasks = RTOS_TABLE(order_tasks) };

/* ---- 2: preemption by sig_sem and by an ISR ---- */
static void t_high(intptr_t x)
{
	rt_log("H-wait");
	wai_sem(1);
	rt_log("H-got");
	slp_tsk();
	rt_log("H-woken");
}

static void t_low(intptr_t x)
{
	rt_log("L-sig");
	sig_sem(1);          /* H preempts here */
	rt_log("L-after-sig");
	rtos_host_irq_raise(INTNO_DEV);   /* the ISR wakes H: preempted on ISR return */
	rt_log("L-after-irq");
}

static void dev_isr(intptr_t x)
{
	rt_log("ISR");
	iwup_tsk(2);
	rt_log("ISR-end");
}

static const struct rtos_task_cfg pre_tasks[] = {
	{ 1, TA_ACT, 0, t_low, 10, 1024, TDOM_KERNEL, "low" },
	{ 2, TA_ACT, 0, t_high, 2, 1024, TDOM_KERNEL, "high" },
};
static const struct rtos_sem_cfg pre_sems[] = { { 1, TA_NULL, 0, 1, "s" } };
static const struct rtos_int_cfg pre_ints[] = { { INTNO_DEV, TA_ENAINT, -2 } };
static const struct rtos_isr_cfg pre_isrs[] = { { TA_NULL, 0, INTNO_DEV, dev_isr, 1 } };
static const struct rtos_cfg pre_cfg = {
	.name = "preempt", .tasks = RTOS_TABLE(pre_tasks), .sems = RTOS_TABLE(pre_sems),
	.ints = RTOS_TABLE(pre_ints), .isrs = RTOS_TABLE(pre_isrs),
};

/* ---- 3: a preempted task stays at the head of its priority ---- */
static void t_mid_a(intptr_t x)
{
	rt_log("A1");
	act_tsk(4);           /* high preempts A; A stays ahead of B */
	rt_log("A2");
}

static void t_mid_b(intptr_t x)
{
	rt_log("B");
}

static void t_top(intptr_t x)
{
	rt_log("T");
}

static const struct rtos_task_cfg head_tasks[] = {
	{ 1, TA_ACT, 0, t_mid_a, 5, 1024, TDOM_KERNEL, "A" },
	{ 2, TA_ACT, 0, t_mid_b, 5, 1024, TDOM_KERNEL, "B" },
	{ 4, TA_NULL, 0, t_top, 1, 1024, TDOM_KERNEL, "T" },
};
static const struct rtos_cfg head_cfg = { .name = "head", .tasks = RTOS_TABLE(head_tasks) };

/* ---- 4: rot_rdq, activation queueing, chg_pri ---- */
static int rot_count;

static void t_rot(intptr_t x)
{
	for (int i = 0; i < 2; i++) {
		rt_log("%c%d", (char)x, i);
		rot_rdq(TPRI_SELF);
	}
}

static const struct rtos_task_cfg rot_tasks[] = {
	{ 1, TA_ACT, 'x', t_rot, 6, 1024, TDOM_KERNEL, "x" },
	{ 2, TA_ACT, 'y', t_rot, 6, 1024, TDOM_KERNEL, "y" },
};
static const struct rtos_cfg rot_cfg = { .name = "rot", .tasks = RTOS_TABLE(rot_tasks) };

static ER act_results[4];
static ER_UINT can_act_result;

static void t_counter(intptr_t x)
{
	rot_count++;
}

static void t_activator(intptr_t x)
{
	PRI p = 0;

	act_results[0] = act_tsk(2);       /* dormant -> ready (lower priority, no switch) */
	act_results[1] = act_tsk(2);       /* queued */
	act_results[2] = act_tsk(2);       /* E_QOVR */
	can_act_result = can_act(2);       /* 1 queued activation cancelled */
	act_results[3] = act_tsk(2);       /* queued again */
	get_pri(TSK_SELF, &p);
	rt_log("pri%d", (int)p);
	chg_pri(TSK_SELF, 12);             /* below the counter task: it runs twice now */
	rt_log("after-chg count=%d", rot_count);
}

static const struct rtos_task_cfg act_tasks[] = {
	{ 1, TA_ACT, 0, t_activator, 4, 1024, TDOM_KERNEL, "activator" },
	{ 2, TA_NULL, 0, t_counter, 8, 1024, TDOM_KERNEL, "counter" },
};
static const struct rtos_cfg act_cfg = { .name = "act", .tasks = RTOS_TABLE(act_tasks) };

int main(void)
{
	tap_plan(13);

	rt_log_reset();
	is_int(rtos_host_boot(&order_cfg), E_OK, "boot order config");
	rtos_host_run_for(1000000);
	is_str(rt_log_text(), "d b e a c", "tasks run by priority, FIFO (activation order) within a priority");

	rt_log_reset();
	is_int(rtos_host_boot(&pre_cfg), E_OK, "boot preemption config");
	rtos_host_run_for(1000000);
	is_str(rt_log_text(),
	       "H-wait L-sig H-got L-after-sig ISR ISR-end H-woken L-after-irq",
	       "sig_sem preempts at once; an ISR's wakeup preempts on the ISR's return");
	is_u64(rtos_host_now(), 1000000, "run_for ends at the requested virtual time");

	rt_log_reset();
	is_int(rtos_host_boot(&head_cfg), E_OK, "boot head-of-queue config");
	rtos_host_run_for(1000);
	is_str(rt_log_text(), "A1 T A2 B", "a preempted task resumes before its peers");

	rt_log_reset();
	rtos_host_boot(&rot_cfg);
	rtos_host_run_for(1000);
	is_str(rt_log_text(), "x0 y0 x1 y1", "rot_rdq(TPRI_SELF) hands over within the priority");

	rt_log_reset();
	rot_count = 0;
	rtos_host_boot(&act_cfg);
	rtos_host_run_for(1000);
	ok(act_results[0] == E_OK && act_results[1] == E_OK && act_results[2] == E_QOVR,
	   "act_tsk: activate, queue one, then E_QOVR");
	is_int(can_act_result, 1, "can_act returns the queued count");
	is_int(act_results[3], E_OK, "act_tsk queues again after can_act");
	is_str(rt_log_text(), "pri4 after-chg count=2",
	       "chg_pri below a ready task dispatches it; the queued activation reruns it");
	is_int(rot_count, 2, "task ran twice (activation + queued activation)");
	rtos_host_shutdown();
	return tap_done();
}
