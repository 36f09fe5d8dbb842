/*
 * test_stall.c — a task that keeps the CPU without virtual time advancing
 * (a loop making no service call) is reported after the wall-clock bound
 * with its name and PC (and source line); the run returns, nothing runs any more, and the
 * system can be shut down and booted again.
 */
#include "tap.h"
#include "kernel.h"
#include "rtos_test.h"

#define MS 1000000ULL

static volatile unsigned long spins;
static int other_runs;

static void spinner(intptr_t x)
{
	dly_tsk(2);
	for (;;)
		spins++;
}

static void other(intptr_t x)
{
	for (;;) {
		other_runs++;
		dly_tsk(1);
	}
}

static const struct rtos_task_cfg tasks[] = {
	{ 1, TA_ACT, 0, spinner, 8, 4096, TDOM_KERNEL, "spinner" },
	{ 2, TA_ACT, 0, other, 10, 4096, TDOM_KERNEL, "other" },
};
static const struct rtos_cfg cfg = { .name = "stall", .tasks = RTOS_TABLE(tasks) };

int main(void)
{
	uint64_t t;
	int runs;

	tap_plan(10);
	rtos_host_set_stall_bound(1000);   /* wall ms: generous, a loaded machine under qemu-arm is slow */
	rtos_host_expect_bugs(true);
	is_int(rtos_host_boot(&cfg), E_OK, "boot");
	rtos_host_run_for(100 * MS);
	ok(rtos_host_stalled(), "the run returned with the task reported as stalled");
	is_int(rtos_host_end_status(), RTOS_HOST_EXIT_STALL, "the end status says a stall");
	is_int(rtos_host_bug_count(), 1, "one bug report");
	ok(strstr(rtos_host_last_bug(), "stall") != NULL && strstr(rtos_host_last_bug(), "task spinner") != NULL &&
	   strstr(rtos_host_last_bug(), "PC 0x") != NULL, "it names the task and its PC: %s", rtos_host_last_bug());
	t = rtos_host_now();
	runs = other_runs;
	rtos_host_run_for(10 * MS);
	ok(rtos_host_now() == t && other_runs == runs, "nothing runs after the stall (t=%llu ns)", (unsigned long long)t);
	rtos_host_shutdown();
	is_int(rtos_host_end_status(), RTOS_HOST_EXIT_STALL, "and still does after the shutdown");
	rtos_host_set_stall_bound(0);
	other_runs = 0;
	is_int(rtos_host_boot(&cfg), E_OK, "boot again");
	ok(!rtos_host_stalled() && rtos_host_end_status() == 0, "no longer stalled");
	rtos_host_run_for(1 * MS);
	ok(other_runs >= 1, "the system runs again");
	rtos_host_shutdown();
	return tap_done();
}
