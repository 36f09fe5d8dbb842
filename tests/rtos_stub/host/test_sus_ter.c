/*
 * test_sus_ter.c — sus_tsk/rsm_tsk (a ready task stops until resumed; a
 * waiting one keeps waiting, and once released stays suspended; suspending
 * oneself; E_QOVR, E_OBJ, E_CTX), ter_tsk (a sleeping task ends and restarts
 * from its entry when activated again; a queued activation restarts it at
 * once; E_ILUSE for oneself, E_OBJ for a dormant task) and ext_ker (nothing
 * runs after it, the run functions return, shutdown still runs ATT_TER).
 */
#include "tap.h"
#include "kernel.h"
#include "rtos_test.h"

#define MS 1000000ULL

enum { T_MAIN = 1, T_SPIN, T_SLEEPER, T_SELF, T_VICTIM, T_ENDER, T_LATE };

static ER r_sus[4], r_rsm[2], r_ter[4], r_ctx[2], r_dsp;
static int spins, victim_starts, victim_after_sleep, late_runs, ter_runs;
static bool_t ended_ctx;

/* Counts while it runs (1 ms of CPU per round). */
static void spin(intptr_t x)
{
	for (;;) {
		spins++;
		dly_tsk(1);
	}
}

static void sleeper(intptr_t x)
{
	slp_tsk();
	rt_log("sleeper-woke");
}

static void self_suspender(intptr_t x)
{
	rt_log("self-sus");
	sus_tsk(TSK_SELF);
	rt_log("self-resumed");
}

static void victim(intptr_t x)
{
	victim_starts++;
	dly_tsk(50);
	victim_after_sleep++;
}

static void cyc(intptr_t x)
{
	r_ctx[0] = sus_tsk(T_SPIN);
	r_ctx[1] = ter_tsk(T_VICTIM);
}

static void main_task(intptr_t x)
{
	int before;

	act_tsk(T_SPIN);
	dly_tsk(5);
	r_sus[0] = sus_tsk(T_SPIN);
	r_sus[1] = sus_tsk(T_SPIN);            /* already: E_QOVR */
	before = spins;
	dly_tsk(10);
	rt_log("spins-while-suspended=%d", spins - before);
	r_rsm[0] = rsm_tsk(T_SPIN);
	r_rsm[1] = rsm_tsk(T_SPIN);            /* not suspended: E_OBJ */
	dly_tsk(5);
	ter_tsk(T_SPIN);

	/* a waiting task suspended, then woken: it runs only once resumed */
	act_tsk(T_SLEEPER);
	dly_tsk(1);
	sus_tsk(T_SLEEPER);
	wup_tsk(T_SLEEPER);
	dly_tsk(1);
	rt_log("resume");
	rsm_tsk(T_SLEEPER);
	dly_tsk(1);

	act_tsk(T_SELF);
	dly_tsk(1);
	rt_log("main-resumes-self");
	rsm_tsk(T_SELF);
	dly_tsk(1);

	r_sus[2] = sus_tsk(T_SLEEPER);         /* dormant: E_OBJ */
	dis_dsp();
	r_dsp = sus_tsk(TSK_SELF);             /* dispatching disabled: E_CTX */
	ena_dsp();

	/* ter_tsk */
	act_tsk(T_VICTIM);
	dly_tsk(1);
	r_ter[0] = ter_tsk(T_VICTIM);
	dly_tsk(60);
	r_ter[1] = ter_tsk(T_VICTIM);          /* dormant: E_OBJ */
	r_ter[2] = ter_tsk(TSK_SELF);          /* oneself: E_ILUSE */
	act_tsk(T_VICTIM);
	dly_tsk(1);
	act_tsk(T_VICTIM);                     /* queued activation */
	r_ter[3] = ter_tsk(T_VICTIM);          /* ends, restarts at once */
	dly_tsk(1);
	sta_cyc(1);
	dly_tsk(2);
	stp_cyc(1);
	dly_tsk(60);
	rt_log("main-done");
}

/* Ends the kernel; nothing after it runs. */
static void ender(intptr_t x)
{
	act_tsk(T_LATE);
	ext_ker();
	rt_log("after-ext_ker");
}

static void late(intptr_t x)
{
	late_runs++;
}

/* A task that keeps making service calls while a handler ends the kernel. */
static int busy_after;
static ER handler_ext_ker = E_SYS;

static void busy(intptr_t x)
{
	for (;;) {
		if (rtos_host_exited())
			busy_after++;
		dly_tsk(1);
	}
}

static void ender_cyc(intptr_t x)
{
	handler_ext_ker = ext_ker();
}

static void ter_routine(intptr_t x)
{
	ter_runs++;
	ended_ctx = rtos_host_exited();
}

static const struct rtos_task_cfg tasks[] = {
	{ T_MAIN, TA_ACT, 0, main_task, 5, 1024, TDOM_KERNEL, "main" },
	{ T_SPIN, TA_NULL, 0, spin, 6, 1024, TDOM_KERNEL, "spin" },
	{ T_SLEEPER, TA_NULL, 0, sleeper, 4, 1024, TDOM_KERNEL, "sleeper" },
	{ T_SELF, TA_NULL, 0, self_suspender, 4, 1024, TDOM_KERNEL, "self" },
	{ T_VICTIM, TA_NULL, 0, victim, 4, 1024, TDOM_KERNEL, "victim" },
};
static const struct rtos_cyc_cfg cycs[] = { { 1, TA_NULL, 0, cyc, 1, 0, "cyc" } };
static const struct rtos_cfg cfg = {
	.name = "sus_ter", .tasks = RTOS_TABLE(tasks), .cycs = RTOS_TABLE(cycs),
};

static const struct rtos_task_cfg end_tasks[] = {
	{ 1, TA_ACT, 0, ender, 5, 1024, TDOM_KERNEL, "ender" },
	{ 2, TA_NULL, 0, late, 6, 1024, TDOM_KERNEL, "late" },
};
static const struct rtos_ter_cfg end_ters[] = { { ter_routine, 0 } };
static const struct rtos_cfg end_cfg = {
	.name = "ext_ker", .tasks = RTOS_TABLE(end_tasks), .ters = RTOS_TABLE(end_ters),
};

static const struct rtos_task_cfg busy_tasks[] = { { 1, TA_ACT, 0, busy, 5, 1024, TDOM_KERNEL, "busy" } };
static const struct rtos_cyc_cfg end_cycs[] = { { 1, TA_STA | TA_PHS, 0, ender_cyc, 5, 5, "ender" } };
static const struct rtos_cfg cyc_end_cfg = {
	.name = "ext_ker-cyc", .tasks = RTOS_TABLE(busy_tasks), .cycs = RTOS_TABLE(end_cycs),
};

int main(void)
{
	uint64_t t;

	tap_plan(19);
	rt_log_reset();
	is_int(rtos_host_boot(&cfg), E_OK, "boot");
	rtos_host_run_for(300 * MS);
	ok(r_sus[0] == E_OK && strstr(rt_log_text(), "spins-while-suspended=0") != NULL,
	   "a suspended task does not run (%s)", rt_log_text());
	is_int(r_sus[1], E_QOVR, "suspending a suspended task: E_QOVR");
	ok(r_rsm[0] == E_OK && r_rsm[1] == E_OBJ, "rsm_tsk resumes; again: E_OBJ");
	ok(strstr(rt_log_text(), "resume sleeper-woke") != NULL, "a waiting task released while suspended runs only once resumed");
	ok(strstr(rt_log_text(), "self-sus main-resumes-self self-resumed") != NULL, "sus_tsk(TSK_SELF) switches away until resumed");
	is_int(r_sus[2], E_OBJ, "suspending a dormant task: E_OBJ");
	is_int(r_dsp, E_CTX, "sus_tsk(TSK_SELF) with dispatching disabled: E_CTX");
	is_int(r_ter[0], E_OK, "ter_tsk of a sleeping task");
	is_int(r_ter[1], E_OBJ, "ter_tsk of a dormant task: E_OBJ");
	is_int(r_ter[2], E_ILUSE, "ter_tsk(TSK_SELF): E_ILUSE");
	ok(r_ter[3] == E_OK && victim_starts == 3 && victim_after_sleep == 1,
	   "a terminated task restarts from its entry; a queued activation restarts it at once (%d starts, %d finished)",
	   victim_starts, victim_after_sleep);
	ok(r_ctx[0] == E_CTX && r_ctx[1] == E_CTX, "sus_tsk and ter_tsk from a handler: E_CTX");
	is_int(rtos_host_bug_count(), 0, "no bug reports");
	rtos_host_shutdown();

	rt_log_reset();
	is_int(rtos_host_boot(&end_cfg), E_OK, "boot the ext_ker case");
	rtos_host_run_for(10 * MS);
	t = rtos_host_now();
	rtos_host_run_for(10 * MS);
	ok(rtos_host_exited() && late_runs == 0 && strstr(rt_log_text(), "after-ext_ker") == NULL && rtos_host_now() == t,
	   "after ext_ker nothing runs and time stands still");
	rtos_host_shutdown();
	ok(ter_runs == 1 && ended_ctx, "shutdown still runs the ATT_TER routines");

	rtos_host_boot(&cyc_end_cfg);
	rtos_host_run_for(20 * MS);
	is_int(handler_ext_ker, E_OK, "ext_ker from a cyclic handler returns E_OK");
	ok(rtos_host_exited() && busy_after == 0 && rtos_host_now() <= 6 * MS,
	   "and the system stops there: no task runs after it (t=%llu ns)", (unsigned long long)rtos_host_now());
	rtos_host_shutdown();
	return tap_done();
}
