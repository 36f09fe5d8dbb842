/*
 * test_sync.c — task-dependent synchronisation and task state calls:
 * wakeup queueing (E_QOVR), can_wup, rel_wai/irel_wai (E_RLWAI, E_OBJ),
 * chg_pri re-sorting a TA_TPRI wait queue, get_tid/iget_tid, E_OBJ on
 * dormant tasks, and the sns_* state queries.
 */
#include "tap.h"
#include "kernel.h"
#include "rtos_test.h"

#define IRQ_DEV 115U

static ER r_wup[3], r_rel[3], r_slp, r_dly, r_dormant[3];
static ER_UINT r_canwup;
static ID tid_isr_task, tid_isr_idle, tid_self;
static bool_t sns[4];

static void isr_dev(intptr_t x)
{
	ID id = 99;

	iget_tid(&id);
	if (x == 0)
		tid_isr_task = id;
	else
		tid_isr_idle = id;
	irel_wai(4);
}

static void waiter(intptr_t x)
{
	if (wai_sem(1) == E_OK)
		rt_log("%c", (char)x);
}

static void sleeper(intptr_t x)
{
	r_slp = slp_tsk();               /* released by rel_wai */
	r_dly = dly_tsk(100);            /* released by irel_wai from the ISR */
}

static void main_task(intptr_t x)
{
	PRI p;

	get_tid(&tid_self);
	r_wup[0] = wup_tsk(TSK_SELF);    /* queued */
	r_wup[1] = wup_tsk(TSK_SELF);    /* E_QOVR */
	r_canwup = can_wup(TSK_SELF);
	r_wup[2] = tslp_tsk(TMO_POL);   /* nothing queued any more: E_TMOUT */

	act_tsk(4);
	dly_tsk(1);
	r_rel[0] = rel_wai(4);
	r_rel[1] = rel_wai(TSK_SELF);    /* E_ID: no TSK_SELF for rel_wai */
	r_rel[2] = rel_wai(5);           /* not waiting (dormant): E_OBJ */
	dly_tsk(1);
	rtos_host_irq_raise(IRQ_DEV);    /* ISR irel_wai(4) out of dly_tsk */

	r_dormant[0] = chg_pri(5, 3);
	r_dormant[1] = get_pri(5, &p);
	r_dormant[2] = wup_tsk(5);

	/* chg_pri re-sorts a TA_TPRI wait queue: waiters a(6) b(7) c(8); raise c above a */
	act_tsk(6);
	act_tsk(7);
	act_tsk(8);
	dly_tsk(1);
	chg_pri(8, 2);
	sig_sem(1);
	sig_sem(1);
	sig_sem(1);
	dly_tsk(1);

	sns[0] = sns_ctx();
	loc_cpu();
	sns[1] = sns_loc() && sns_dpn();
	unl_cpu();
	dis_dsp();
	sns[2] = sns_dsp() && sns_dpn();
	ena_dsp();
	sns[3] = sns_dpn();
}

static const struct rtos_task_cfg tasks[] = {
	{ 1, TA_ACT, 0, main_task, 1, 1024, TDOM_KERNEL, "main" },
	{ 4, TA_NULL, 0, sleeper, 3, 1024, TDOM_KERNEL, "sleeper" },
	{ 5, TA_NULL, 0, sleeper, 3, 1024, TDOM_KERNEL, "dormant" },
	{ 6, TA_NULL, 'a', waiter, 5, 1024, TDOM_KERNEL, "a" },
	{ 7, TA_NULL, 'b', waiter, 6, 1024, TDOM_KERNEL, "b" },
	{ 8, TA_NULL, 'c', waiter, 7, 1024, TDOM_KERNEL, "c" },
};
static const struct rtos_sem_cfg sems[] = { { 1, TA_TPRI, 0, 3, "s" } };
static const struct rtos_int_cfg ints[] = { { IRQ_DEV, TA_ENAINT, -2 } };
static const struct rtos_isr_cfg isrs[] = { { TA_NULL, 0, IRQ_DEV, isr_dev, 1 } };
static const struct rtos_cfg cfg = {
	.name = "sync", .tasks = RTOS_TABLE(tasks), .sems = RTOS_TABLE(sems), .ints = RTOS_TABLE(ints),
	.isrs = RTOS_TABLE(isrs),
};

static const struct rtos_isr_cfg idle_isrs[] = { { TA_NULL, 1, IRQ_DEV, isr_dev, 1 } };
static const struct rtos_cfg idle_cfg = { .name = "idle", .ints = RTOS_TABLE(ints), .isrs = RTOS_TABLE(idle_isrs) };

int main(void)
{
	tap_plan(12);
	rt_log_reset();
	is_int(rtos_host_boot(&cfg), E_OK, "boot");
	rtos_host_run_for(20000000);
	ok(r_wup[0] == E_OK && r_wup[1] == E_QOVR, "wup_tsk queues one wakeup, then E_QOVR");
	is_int(r_canwup, 1, "can_wup returns and clears the queued count");
	is_int(r_wup[2], E_TMOUT, "after can_wup nothing is queued: tslp_tsk(TMO_POL) is E_TMOUT");
	is_int(r_slp, E_RLWAI, "rel_wai ends a wait with E_RLWAI");
	is_int(r_dly, E_RLWAI, "irel_wai from an ISR ends dly_tsk with E_RLWAI");
	ok(r_rel[0] == E_OK && r_rel[1] == E_ID && r_rel[2] == E_OBJ, "rel_wai: E_OK, E_ID for TSK_SELF, E_OBJ if not waiting");
	ok(r_dormant[0] == E_OBJ && r_dormant[1] == E_OBJ && r_dormant[2] == E_OBJ,
	   "chg_pri, get_pri, wup_tsk on a dormant task: E_OBJ");
	is_str(rt_log_text(), "c a b", "chg_pri moves a waiter up a TA_TPRI wait queue");
	ok(tid_self == 1 && tid_isr_task == 1, "get_tid in the task, iget_tid in an ISR over it");
	ok(!sns[0] && sns[1] && sns[2] && !sns[3], "sns_ctx, sns_loc, sns_dsp, sns_dpn follow the state");
	rtos_host_boot(&idle_cfg);
	rtos_host_irq_raise(IRQ_DEV);
	is_int(tid_isr_idle, TSK_NONE, "iget_tid in an ISR over idle: TSK_NONE");
	rtos_host_shutdown();
	return tap_done();
}
