/*
 * test_ter.c — ATT_TER termination routines at rtos_host_shutdown: reverse
 * order of registration across includes, non-task context "ter" with the
 * CPU unlocked and the system intact (a routine hands work to a task with
 * iwup_tsk and runs the system until the task has done it), a NULL routine
 * is a boot error, none run after a failed boot or twice, and boot/shutdown
 * from inside a routine are reported.
 */
#define _POSIX_C_SOURCE 200809L
#include "tap.h"
#include "kernel.h"
#include "rtos_test.h"
#include "boot_refusal_test.h"

#define MS 1000000ULL

static bool work_requested, work_done;
static uint64_t work_done_at;
static bool_t ter_ctx, ter_loc;
static char ter_ctx_name[32];

/* A task that sleeps until asked, then takes 5 ms of sleeping to finish. */
static void cleanup_task(intptr_t exinf)
{
	(void)exinf;
	while (!work_requested)
		slp_tsk();
	dly_tsk(5);
	work_done = true;
	work_done_at = rtos_host_now();
}

static void lib_ter(intptr_t exinf)
{
	rt_log("lib%d", (int)exinf);
}

/* The library's termination: wake the task and run the system until it has finished. */
static void lib_ter_work(intptr_t exinf)
{
	rt_log("lib%d", (int)exinf);
	ter_ctx = sns_ctx();
	ter_loc = sns_loc();
	snprintf(ter_ctx_name, sizeof(ter_ctx_name), "%s", rtos_host_context_name());
	work_requested = true;
	is_int(iwup_tsk(2), E_OK, "iwup_tsk works in a termination routine");
	for (int i = 0; i < 100 && !work_done; i++)
		rtos_host_run_for(MS);
}

static void app_ter(intptr_t exinf)
{
	rt_log("app%d", (int)exinf);
}

static void ini_fn(intptr_t exinf)
{
	rt_log("ini%d", (int)exinf);
}

static const struct rtos_task_cfg lib_tasks[] = { RT_TASK(2, cleanup_task, 3, true) };
static const struct rtos_ter_cfg lib_ters[] = { { lib_ter, 1 }, { lib_ter_work, 2 } };
static const struct rtos_ini_cfg lib_inis[] = { { ini_fn, 1 } };
static const struct rtos_cfg lib_cfg = {
	.name = "lib", .tasks = RTOS_TABLE(lib_tasks), .inis = RTOS_TABLE(lib_inis),
	.ters = RTOS_TABLE(lib_ters),
};
static const struct rtos_cfg *const app_includes[] = { &lib_cfg, NULL };
static const struct rtos_ter_cfg app_ters[] = { { app_ter, 1 }, { app_ter, 2 } };
static const struct rtos_ini_cfg app_inis[] = { { ini_fn, 0 } };
static const struct rtos_cfg app_cfg = {
	.name = "app", .inis = RTOS_TABLE(app_inis), .ters = RTOS_TABLE(app_ters),
	.includes = app_includes,
};

static const struct rtos_ter_cfg null_ters[] = { { NULL, 0 } };
static const struct rtos_cfg null_cfg = { .name = "nullter", .ters = RTOS_TABLE(null_ters) };

/* A termination routine that misuses the harness. */
static void bad_ter(intptr_t exinf)
{
	(void)exinf;
	rtos_host_shutdown();
	is_int(rtos_host_boot(&app_cfg), E_CTX, "rtos_host_boot from a termination routine: E_CTX");
}
static const struct rtos_ter_cfg bad_ters[] = { { bad_ter, 0 } };
static const struct rtos_cfg bad_cfg = { .name = "bad", .ters = RTOS_TABLE(bad_ters) };

int main(void)
{
	bool said_so = true;

	tap_plan(20);

	rt_log_reset();
	is_int(rtos_host_boot(&app_cfg), E_OK, "boot with termination routines");
	is_str(rt_log_text(), "ini0 ini1", "ATT_INI in registration order");
	rtos_host_run_for(3 * MS);
	ok(!work_done, "the task waits for the request");
	rt_log_reset();
	rtos_host_shutdown();
	is_str(rt_log_text(), "lib2 lib1 app2 app1",
	       "ATT_TER in reverse registration order (the included library before the application)");
	ok(ter_ctx, "termination routines run in non-task context");
	ok(!ter_loc, "with the CPU unlocked (the system can still run)");
	is_str(ter_ctx_name, "ter", "context name 'ter'");
	ok(work_done, "a task finished the work the termination routine handed it");
	is_u64(work_done_at, 3 * MS + 5 * MS, "after its 5 ms sleep, in virtual time");

	rt_log_reset();
	rtos_host_shutdown();
	is_str(rt_log_text(), "", "a second shutdown runs no termination routine");

	is_int(rt_boot_refused(&null_cfg, &said_so), E_PAR, "a NULL termination routine is a boot error");
	ok(said_so, "...printed on stderr");
	ok(strstr(rtos_host_boot_error(), "ATT_TER[0]") != NULL, "naming the row: %s",
	   rtos_host_boot_error());
	rt_log_reset();
	rtos_host_shutdown();
	is_str(rt_log_text(), "", "no termination routine runs after a failed boot");

	rtos_host_expect_bugs(true);
	is_int(rtos_host_boot(&bad_cfg), E_OK, "boot a configuration whose termination misbehaves");
	rtos_host_shutdown();
	ok(rtos_host_bug_count() == 2, "shutdown and boot from a termination routine are reported (%u)",
	   rtos_host_bug_count());
	rtos_host_expect_bugs(false);

	work_requested = work_done = false;
	is_int(rtos_host_boot(&app_cfg), E_OK, "boots again after all that");
	rtos_host_shutdown();
	return tap_done();
}
