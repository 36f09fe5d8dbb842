/*
 * test_context.c — every E_CTX case: task-only calls from non-task contexts
 * (ISR, cyclic, alarm, ATT_INI, the harness), i-calls from a task, blocking
 * calls with the CPU locked or dispatching disabled, and calls that need
 * the CPU unlocked.
 */
#include "tap.h"
#include "kernel.h"
#include "rtos_test.h"

#define IRQ_DEV 90U

static char bad_names[1024];

static void expect_ctx(const char *name, ER ercd)
{
	if (MERCD(ercd) != E_CTX) {
		size_t len = strlen(bad_names);

		snprintf(bad_names + len, sizeof(bad_names) - len, " %s=%d", name, (int)ercd);
	}
}

#define X(call) expect_ctx(#call, (ER)(call))

/* Task-context calls (they need a task and an unlocked CPU). */
static void task_calls_fail(void)
{
	ID id;
	PRI pri;
	FLGPTN ptn;
	SYSTIM tim;

	X(act_tsk(2));
	X(can_act(2));
	X(chg_pri(2, 3));
	X(get_pri(2, &pri));
	X(wup_tsk(2));
	X(can_wup(2));
	X(rel_wai(2));
	X(sig_sem(1));
	X(pol_sem(1));
	X(set_flg(1, 1));
	X(clr_flg(1, 0));
	X(pol_flg(1, 1, TWF_ORW, &ptn));
	X(sta_cyc(1));
	X(stp_cyc(1));
	X(sta_alm(1, 10));
	X(stp_alm(1));
	X(rot_rdq(3));
	X(dis_dsp());
	X(ena_dsp());
	X(get_tim(&tim));
	X(slp_tsk());
	X(tslp_tsk(10));
	X(dly_tsk(10));
	X(wai_sem(1));
	X(twai_sem(1, 10));
	X(wai_flg(1, 1, TWF_ORW, &ptn));
	X(twai_flg(1, 1, TWF_ORW, &ptn, 10));
	(void)id;
}

/* Calls that only exist for a task, whatever the lock state. */
static void task_only_any_lock(void)
{
	ID id;

	X(get_tid(&id));
	X(loc_cpu());
	X(unl_cpu());
}

/* i-calls (non-task context, CPU unlocked). */
static void icalls_fail(void)
{
	ID id;

	X(iact_tsk(2));
	X(iwup_tsk(2));
	X(irel_wai(2));
	X(isig_sem(1));
	X(iset_flg(1, 1));
	X(ista_alm(1, 10));
	X(istp_alm(1));
	X(irot_rdq(3));
	(void)id;
}

static char ctx_report[8][1100];
static int nreport;

static void record(const char *where)
{
	snprintf(ctx_report[nreport++], sizeof(ctx_report[0]), "%s:%s", where, bad_names);
	bad_names[0] = '\0';
}

static void isr_dev(intptr_t x)
{
	task_calls_fail();
	task_only_any_lock();
	record("isr");
	iloc_cpu();
	icalls_fail();            /* with the CPU locked, i-calls are E_CTX too */
	X(dis_int(IRQ_DEV));
	X(ena_int(IRQ_DEV));
	iunl_cpu();
	record("isr-locked");
}

static void cyc_handler(intptr_t x)
{
	task_calls_fail();
	task_only_any_lock();
	record("cyclic");
}

static void alm_handler(intptr_t x)
{
	task_calls_fail();
	task_only_any_lock();
	record("alarm");
}

static void ini_routine(intptr_t x)
{
	task_calls_fail();
	task_only_any_lock();
	icalls_fail();            /* ATT_INI runs with the CPU locked */
	record("init");
}

static void other_task(intptr_t x)
{
}

static void main_task(intptr_t x)
{
	ID id;
	FLGPTN ptn;

	/* i-calls from a task */
	icalls_fail();
	X(iloc_cpu());
	X(iunl_cpu());
	X(iget_tid(&id));
	record("task");

	/* CPU locked */
	loc_cpu();
	task_calls_fail();
	X(dis_int(IRQ_DEV));
	X(ena_int(IRQ_DEV));
	unl_cpu();
	record("task-locked");

	/* Dispatching disabled: blocking calls fail, others work */
	dis_dsp();
	X(slp_tsk());
	X(tslp_tsk(10));
	X(dly_tsk(10));
	X(wai_sem(1));
	X(twai_sem(1, 10));
	X(wai_flg(1, 1, TWF_ORW, &ptn));
	X(twai_flg(1, 1, TWF_ORW, &ptn, 10));
	if (sig_sem(1) != E_OK || pol_sem(1) != E_OK)
		strcat(bad_names, " non-blocking-calls-failed");
	ena_dsp();
	record("task-dsp-disabled");

	sta_alm(1, 1);
	rtos_host_irq_raise(IRQ_DEV);
	dly_tsk(5);
}

static const struct rtos_task_cfg tasks[] = {
	{ 1, TA_ACT, 0, main_task, 5, 1024, TDOM_KERNEL, "main" },
	{ 2, TA_NULL, 0, other_task, 9, 1024, TDOM_KERNEL, "other" },
};
static const struct rtos_sem_cfg sems[] = { { 1, TA_NULL, 0, 1, "s" } };
static const struct rtos_flg_cfg flgs[] = { { 1, TA_NULL, 0, "f" } };
static const struct rtos_cyc_cfg cycs[] = { { 1, TA_STA, 0, cyc_handler, 100, 2, "c" } };
static const struct rtos_alm_cfg alms[] = { { 1, TA_NULL, 0, alm_handler, "a" } };
static const struct rtos_int_cfg ints[] = { { IRQ_DEV, TA_ENAINT, -2 } };
static const struct rtos_isr_cfg isrs[] = { { TA_NULL, 0, IRQ_DEV, isr_dev, 1 } };
static const struct rtos_ini_cfg inis[] = { { ini_routine, 0 } };
static const struct rtos_cfg cfg = {
	.name = "context", .tasks = RTOS_TABLE(tasks), .sems = RTOS_TABLE(sems), .flgs = RTOS_TABLE(flgs),
	.cycs = RTOS_TABLE(cycs), .alms = RTOS_TABLE(alms), .ints = RTOS_TABLE(ints),
	.isrs = RTOS_TABLE(isrs), .inis = RTOS_TABLE(inis),
};

static const char *report_of(const char *where)
{
	size_t n = strlen(where);

	for (int i = 0; i < nreport; i++)
		if (strncmp(ctx_report[i], where, n) == 0 && ctx_report[i][n] == ':')
			return ctx_report[i] + n + 1;
	return "(not run)";
}

int main(void)
{
	static const char *const wheres[] = {
		"init", "task", "task-locked", "task-dsp-disabled", "isr", "isr-locked", "alarm", "cyclic",
	};

	tap_plan(11);
	is_int(rtos_host_boot(&cfg), E_OK, "boot");
	rtos_host_run_for(10000000);
	for (size_t i = 0; i < sizeof(wheres) / sizeof(wheres[0]); i++)
		is_str(report_of(wheres[i]), "", "every call that is not allowed in %s returns E_CTX", wheres[i]);

	/* The harness is non-task context too. */
	task_calls_fail();
	task_only_any_lock();
	is_str(bad_names, "", "task calls from the harness (idle) return E_CTX");
	ok(sns_ctx() == TRUE && sns_dpn() == TRUE, "the harness is non-task context");
	rtos_host_shutdown();
	return tap_done();
}
