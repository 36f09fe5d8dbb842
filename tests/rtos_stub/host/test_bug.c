/*
 * test_bug.c — bug reports: the message format (what, message, virtual
 * time, context), counting, expected bugs, kernel-detected misuse
 * (ext_tsk from an ISR, the harness re-entered from a task, events in the
 * past), and that an unexpected bug makes the process exit non-zero even
 * when every TAP line passed (checked in a child process).
 */
#define _POSIX_C_SOURCE 200809L
#include <sys/wait.h>
#include <unistd.h>

#include "tap.h"
#include "kernel.h"
#include "rtos_test.h"

#define IRQ_DEV 110U

static char ctx_in_isr[64];

static void isr_dev(intptr_t x)
{
	snprintf(ctx_in_isr, sizeof(ctx_in_isr), "%s", rtos_host_context_name());
	ext_tsk();                         /* misuse: reported, returns */
}

static void noop(void *arg)
{
}

static void main_task(intptr_t x)
{
	rtos_host_consume(1500);
	rtos_host_irq_raise(IRQ_DEV);
	rtos_host_run_for(10);             /* misuse: the harness from a task */
}

static const struct rtos_task_cfg tasks[] = { { 1, TA_ACT, 0, main_task, 5, 1024, TDOM_KERNEL, "main" } };
static const struct rtos_int_cfg ints[] = { { IRQ_DEV, TA_ENAINT, -2 } };
static const struct rtos_isr_cfg isrs[] = { { TA_NULL, 0, IRQ_DEV, isr_dev, 1 } };
static const struct rtos_cfg cfg = {
	.name = "bug", .tasks = RTOS_TABLE(tasks), .ints = RTOS_TABLE(ints), .isrs = RTOS_TABLE(isrs),
};

/* Runs a child that reports one bug (expected or not) and returns 0; returns its exit status. */
static int child_status(bool expected)
{
	pid_t pid;
	int status = -1;

	fflush(stdout);
	pid = fork();
	if (pid == 0) {
		if (!freopen("/dev/null", "w", stdout) || !freopen("/dev/null", "w", stderr))
			_exit(99);	/* neither the expected 0 nor the bug exit: the test fails */
		rtos_host_boot(&cfg);
		rtos_host_expect_bugs(expected);
		rtos_host_bug("test", "a deliberate bug");
		exit(0);
	}
	waitpid(pid, &status, 0);
	return WIFEXITED(status) ? WEXITSTATUS(status) : 128;
}

int main(void)
{
	tap_plan(9);
	is_int(rtos_host_boot(&cfg), E_OK, "boot");
	rtos_host_expect_bugs(true);
	is_int(rtos_host_bug_count(), 0, "no bugs after boot");
	rtos_host_run_for(1000000);
	is_int(rtos_host_bug_count(), 2, "ext_tsk from an ISR and run_for from a task are both reported");
	is_str(ctx_in_isr, "isr 110", "context name of an ISR");
	is_str(rtos_host_last_bug(),
	       "harness: rtos_host_run_for called from inside the kernel (task main) at t=1500 ns in task main",
	       "report: what, message, virtual time, context");
	rtos_host_event_at(5, noop, NULL);
	ok(rtos_host_bug_count() == 3 && strstr(rtos_host_last_bug(), "in the past") != NULL,
	   "an event scheduled in the past is reported");
	rtos_host_bug("driver", "sleeping in atomic context (%d)", 7);
	is_str(rtos_host_last_bug(), "driver: sleeping in atomic context (7) at t=1000000 ns in idle",
	       "layers above report through rtos_host_bug");
	rtos_host_expect_bugs(false);
	is_int(child_status(false), 1, "an unexpected bug makes the process exit non-zero");
	is_int(child_status(true), 0, "an expected bug does not");
	rtos_host_shutdown();
	return tap_done();
}
