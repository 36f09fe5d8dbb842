/*
 * test_app_cfg.c — an app in EV3RT's idiom (tests/cfg/app_kernel: app.c,
 * app.h, app.cfg) configured by ev3cfg through mk/ev3rt_app.mk and booted:
 * kernel_cfg.h's IDs, ATT_INI, TA_ACT, a data queue between two tasks, an
 * alarm, a kernel cyclic handler in non-task context, an EV3_CRE_CYC handler
 * in task context (it may block), and ATT_MOD: the app's own statics pass
 * the memory checks of its domain, memory outside app.o does not.
 */
#include "tap.h"
#include "kernel.h"
#include "rtos_host.h"
#include "rtos_cfg.h"
#include "kernel_cfg.h"
#include "app.h"

#define MS 1000000ULL

/* Not part of app.o: outside the app's domain. */
static SYSTIM foreign_time;
SYSTIM *app_foreign_static = &foreign_time;

int main(void)
{
	const struct app_result *r = &app_result;

	tap_plan(18);
	ok(MAIN_TASK == 1 && WORKER_TASK == 2 && EV3_CYC_TASK_EV3_CYC1 == 3 && TDOM_APP == 1,
	   "kernel_cfg.h: tasks numbered in order, the EV3 cyclic handler's task after them");
	ok(CYC1 == 1 && EV3_CYC1 == 2 && DTQ1 == 1 && MTX1 == 1, "kernel_cfg.h: cyclic handlers and other objects from 1");
	ok(EXTRA_SEM == 1 && SEM1 == 2, "an INCLUDEd file's objects are numbered where it is included");
	if (rtos_host_boot(&ev3rt_app_cfg) != E_OK) {
		tap_diag("boot: %s", rtos_host_boot_error());
		return tap_done();
	}
	is_int(r->inits, 1, "ATT_INI ran once at boot");
	rtos_host_run_for(100 * MS);
	is_int(r->main_runs, 1, "the TA_ACT task ran");
	is_int(r->get_tim_static, E_OK, "get_tim(&a static of app.o) from the user task: E_OK (ATT_MOD)");
	is_int(r->get_tim_foreign, E_MACV, "get_tim(&a static outside app.o): E_MACV");
	is_int(r->nreceived, 3, "the worker received three elements through the 2-element data queue");
	ok(r->received[0] == 10 && r->received[1] == 20 && r->received[2] == 30, "in the order they were sent");
	is_int(r->alarm_runs, 1, "the alarm fired once");
	ok(r->cyclic_runs >= 9 && r->cyclic_runs <= 11, "CRE_CYC handler every 10 ms (%d runs in 100 ms)", r->cyclic_runs);
	ok(!r->cyclic_in_task, "CRE_CYC handler in non-task context");
	ok(r->ev3_cyclic_runs >= 4 && r->ev3_cyclic_runs <= 5, "EV3_CRE_CYC handler every 20 ms from 5 ms (%d runs)",
	   r->ev3_cyclic_runs);
	is_int(r->ev3_cyclic_ctx, FALSE, "EV3_CRE_CYC handler in task context");
	is_int(r->ev3_cyclic_dly, E_OK, "and it may block (dly_tsk)");
	{
		PRI pri = 0;

		is_int(get_pri(EV3_CYC_TASK_EV3_CYC1, &pri), E_CTX, "get_pri from the harness is E_CTX (non-task)");
	}
	is_int(ev3rt_app_cfg.nsems, 2, "the INCLUDEd semaphore is in the tables");
	rtos_host_shutdown();
	ok(rtos_host_bug_count() == 0, "no bug reports");
	return tap_done();
}
