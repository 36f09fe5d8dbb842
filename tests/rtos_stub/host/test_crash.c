/*
 * test_crash.c — the host kernel's fatal faults (crash.c): a code address's
 * source line by addr2line; each task's stack use measured at its service
 * calls, a use beyond its stksz and the slack reported with the sizes and
 * the system ended with RTOS_HOST_EXIT_STACK (kept through shutdown, cleared
 * by the next boot); a fatal signal outside a task (a cyclic handler, the
 * harness) reported in a child process naming that context, with status 4.
 */
#define _POSIX_C_SOURCE 200809L
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include <sys/wait.h>
#include "tap.h"
#include "kernel.h"
#include "rtos_test.h"

#define MS 1000000ULL
#define HOG_LOCALS (40 * 1024)

/* NULL; under the sanitizers 16 bytes past it, since UBSan stops a store through NULL itself */
#if defined(__SANITIZE_ADDRESS__)
static volatile uintptr_t nowhere_address = 16;
#define NOWHERE ((int *)nowhere_address)
#define NOWHERE_TEXT "0x10"
#else
static int *volatile nowhere;
#define NOWHERE nowhere
#define NOWHERE_TEXT "0x0"
#endif
static volatile char sink;

/* Sleeps with a small frame: a modest, measurable use. */
static void frugal(intptr_t x)
{
	volatile char few[256];

	(void)x;
	few[0] = 1;
	dly_tsk(1);
	sink = few[0];
}

/* Sleeps with 40 KiB of locals in a 4 KiB task. */
static void hog(intptr_t x)
{
	volatile char lots[HOG_LOCALS];

	(void)x;
	for (size_t i = 0; i < sizeof(lots); i += 1024)
		lots[i] = (char)i;
	dly_tsk(1);
	sink = lots[1024];
}

/* A cyclic handler that stores through NULL. */
static void bad_cyclic(intptr_t x)
{
	(void)x;
	*NOWHERE = 1;
}

static const struct rtos_task_cfg frugal_tasks[] = {
	{ 1, TA_ACT, 0, frugal, 8, 4096, TDOM_KERNEL, "frugal" },
};
static const struct rtos_cfg frugal_cfg = { .name = "frugal", .tasks = RTOS_TABLE(frugal_tasks) };

static const struct rtos_task_cfg hog_tasks[] = {
	{ 1, TA_ACT, 0, hog, 8, 4096, TDOM_KERNEL, "hog" },
};
static const struct rtos_cfg hog_cfg = { .name = "hog", .tasks = RTOS_TABLE(hog_tasks) };

static const struct rtos_cyc_cfg bad_cycs[] = {
	{ 1, TA_STA, 0, bad_cyclic, 5, 0, "bad" },
};
static const struct rtos_cfg cyclic_cfg = { .name = "bad cyclic", .cycs = RTOS_TABLE(bad_cycs) };

static void test_source_line(void)
{
	char line[512];

	ok(rtos_host_source_line((uintptr_t)&hog, line, sizeof(line)) && strstr(line, "hog at ") != NULL &&
	   strstr(line, "test_crash.c:") != NULL, "a function's address: its name and line (%s)", line);
	ok(!rtos_host_source_line(0, line, sizeof(line)) && line[0] == '\0', "address 0: none");
}

static void test_stack_use(void)
{
	size_t used;

	is_int(rtos_host_boot(&frugal_cfg), E_OK, "boot a task with a small frame");
	rtos_host_run_for(5 * MS);
	used = rtos_host_task_stack_used(1);
	ok(used >= 256 && used < 4096, "its use is measured: %zu bytes", used);
	is_int(rtos_host_end_status(), 0, "the system did not end on a fault");
	is_int(rtos_host_bug_count(), 0, "no report");
	rtos_host_shutdown();

	rtos_host_expect_bugs(true);
	is_int(rtos_host_boot(&hog_cfg), E_OK, "boot a 4 KiB task with 40 KiB of locals");
	rtos_host_run_for(5 * MS);
	used = rtos_host_task_stack_used(1);
	ok(used >= HOG_LOCALS, "its use is measured: %zu bytes", used);
	is_int(rtos_host_end_status(), RTOS_HOST_EXIT_STACK, "the system ended on a stack overrun");
	ok(rtos_host_exited(), "as after ext_ker");
	ok(strstr(rtos_host_last_bug(), "stack: task hog used ") != NULL &&
	   strstr(rtos_host_last_bug(), "more than the 4096 bytes its configuration gives it") != NULL,
	   "the report names the task, its use and its size: %s", rtos_host_last_bug());
	rtos_host_shutdown();
	is_int(rtos_host_end_status(), RTOS_HOST_EXIT_STACK, "the status outlives the shutdown");
	rtos_host_expect_bugs(false);
	is_int(rtos_host_boot(&frugal_cfg), E_OK, "boot again");
	is_int(rtos_host_end_status(), 0, "the next boot clears it");
	rtos_host_shutdown();
}

/* Runs cfg (NULL: none) in a child that then stores through NULL from the harness;
 * its exit status and stderr. */
static int crash_child(const struct rtos_cfg *cfg, char *err, size_t len)
{
	FILE *f = tmpfile();
	int wstatus = 0;
	size_t n;
	pid_t pid;

	if (f == NULL)
		tap_bail_out("tmpfile");
	fflush(NULL);
	pid = fork();
	if (pid < 0)
		tap_bail_out("fork");
	if (pid == 0) {
		dup2(fileno(f), STDERR_FILENO);
		if (cfg != NULL) {
			(void)rtos_host_boot(cfg);
			rtos_host_run_for(20 * MS);
		}
		rtos_host_crash_install();
		*NOWHERE = 2;
		_exit(0);
	}
	waitpid(pid, &wstatus, 0);
	rewind(f);
	n = fread(err, 1, len - 1, f);
	err[n] = '\0';
	fclose(f);
	return WIFEXITED(wstatus) ? WEXITSTATUS(wstatus) : -1;
}

static void test_fatal_outside_tasks(void)
{
	char err[4096];
	int status;

	status = crash_child(&cyclic_cfg, err, sizeof(err));
	is_int(status, RTOS_HOST_EXIT_CRASH, "a NULL store in a cyclic handler: status 4");
	ok(strstr(err, "FATAL: crash: SIGSEGV (address not mapped) at address " NOWHERE_TEXT
		   " in cyclic 1 at t=") &&
	   strstr(err, "bad_cyclic at ") && strstr(err, "test_crash.c:"),
	   "the report names the handler, the time and the line");
	if (status != RTOS_HOST_EXIT_CRASH || strstr(err, "test_crash.c:") == NULL || strstr(err, "cyclic 1 at t=") == NULL)
		tap_diag("stderr:\n%s", err);
	status = crash_child(NULL, err, sizeof(err));
	is_int(status, RTOS_HOST_EXIT_CRASH, "a NULL store in the harness: status 4");
	ok(strstr(err, "in the harness (idle)") && strstr(err, "crash_child at "),
	   "the report names the harness and the line");
	if (status != RTOS_HOST_EXIT_CRASH || strstr(err, "harness") == NULL)
		tap_diag("stderr:\n%s", err);
}

int main(void)
{
	test_source_line();
	test_stack_use();
	test_fatal_outside_tasks();
	return tap_done();
}
