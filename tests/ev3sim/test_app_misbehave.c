/*
 * test_app_misbehave.c — an app that misbehaves (tests/ev3sim/apps/misbehave)
 * run as `ev3sim run` runs it (ev3sim_run_main), once per mistake in a
 * child process: a stalled task (and a busy one, which is no stall: its CPU
 * time lets virtual time pass), a NULL store, a division by zero, abort(),
 * runaway recursion and 64 KiB of locals in a 4 KiB task each end the run
 * with a report on stderr naming the task (and the source line where the
 * kind has one) and the exit status docs/ev3sim.md gives the kind — never
 * a hang, never a bare signal.
 */
#define _POSIX_C_SOURCE 200809L
#include <signal.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include <unistd.h>
#include <sys/wait.h>
#include "tap.h"
#include "rtos_host.h"
#include "ev3sim/cli.h"
#include "ev3sim/run.h"

extern const struct rtos_cfg ev3rt_app_cfg;

#define TIMEOUT_S 300   /* qemu-arm under a loaded machine: far beyond a run's few seconds */

struct outcome {
	int status;           /* exit status; -1 killed by a signal; -2 still running at the timeout */
	int signal;
	char out[16384];
	char err[16384];
};

/* Reads what a temporary file holds. */
static void slurp(FILE *f, char *buf, size_t len)
{
	size_t n;

	rewind(f);
	n = fread(buf, 1, len - 1, f);
	buf[n] = '\0';
	fclose(f);
}

/* Runs the app with EV3LX_MISBEHAVE=what for at most a few virtual seconds, in a child. */
static void run_misbehave(const char *what, struct outcome *o)
{
	char *argv[] = { "run_misbehave", "--seconds", "3", NULL };
	FILE *out = tmpfile(), *err = tmpfile();
	struct timespec tick = { 0, 20 * 1000 * 1000 };
	int wstatus = 0;
	pid_t pid;

	memset(o, 0, sizeof(*o));
	o->status = -2;
	if (out == NULL || err == NULL)
		tap_bail_out("tmpfile");
	fflush(NULL);
	pid = fork();
	if (pid < 0)
		tap_bail_out("fork");
	if (pid == 0) {
		dup2(fileno(out), STDOUT_FILENO);
		dup2(fileno(err), STDERR_FILENO);
		setenv("EV3LX_MISBEHAVE", what, 1);
		setenv("EV3LX_STALL_MS", "500", 1);
		/* exit, not _exit: the status must survive the atexit hooks, as the runner's does */
		exit(ev3sim_run_main(3, argv, "misbehave", &ev3rt_app_cfg));
	}
	for (long waited = 0; waited < TIMEOUT_S * 50L; waited++) {
		pid_t done = waitpid(pid, &wstatus, WNOHANG);

		if (done == pid) {
			if (WIFEXITED(wstatus)) {
				o->status = WEXITSTATUS(wstatus);
			} else {
				o->status = -1;
				o->signal = WIFSIGNALED(wstatus) ? WTERMSIG(wstatus) : 0;
			}
			break;
		}
		nanosleep(&tick, NULL);
	}
	if (o->status == -2) {
		kill(pid, SIGKILL);
		waitpid(pid, &wstatus, 0);
	}
	slurp(out, o->out, sizeof(o->out));
	slurp(err, o->err, sizeof(o->err));
	if (o->status < 0)
		tap_diag("%s: %s", what, o->status == -2 ? "still running at the timeout: killed" : "killed by a signal");
}

/* The run ended with status, stderr holding each of the NULL-terminated texts. */
static void expect(const char *what, const struct outcome *o, int status, const char *const *texts)
{
	bool all = true;

	is_int(o->status, status, "%s: exit status %d", what, status);
	for (const char *const *t = texts; *t != NULL; t++) {
		bool found = strstr(o->err, *t) != NULL;

		ok(found, "%s: the report says '%s'", what, *t);
		all = all && found;
	}
	if (o->status != status || !all)
		tap_diag("stderr:\n%s", o->err);
}

static void test_clean_run(void)
{
	struct outcome o;

	run_misbehave("", &o);
	is_int(o.status, 0, "a well-behaved run: status 0");
	ok(strstr(o.out, "misbehave: done") != NULL && strstr(o.out, "app=misbehave ") != NULL,
	   "it logs its line and the summary");
}

static void test_stall(void)
{
	struct outcome o;

	run_misbehave("stall", &o);
	expect("a stalled task", &o, EV3SIM_EXIT_STALL,
	       (const char *[]){ "ev3sim run: the app stalled at 0.100 s", "in task MAIN_TASK",
				 "without advancing virtual time", "spin_unseen at ", "app.c:", NULL });
	ok(strstr(o.out, "app=misbehave ") == NULL, "a stalled run prints no summary");
}

/* A loop in the app's own code costs the CPU time of its basic blocks: no
 * stall, the run ends at its time with a summary, as on the brick. */
static void test_busy(void)
{
	struct outcome o;

	run_misbehave("busy", &o);
	is_int(o.status, 0, "a task busy in its own code: status 0 (its CPU time lets time pass)");
	ok(strstr(o.out, "app=misbehave robot=bare seconds=3 ") != NULL, "the run reached its 3 s and summed up");
}

static void test_null(void)
{
	struct outcome o;

	run_misbehave("null", &o);
	expect("a NULL store", &o, EV3SIM_EXIT_CRASH,
#if defined(__SANITIZE_ADDRESS__)
	       /* the app stores 16 bytes past NULL: UBSan stops a store through NULL before it faults */
	       (const char *[]){ "FATAL: crash: SIGSEGV (address not mapped) at address 0x10 in task MAIN_TASK",
#else
	       (const char *[]){ "FATAL: crash: SIGSEGV (address not mapped) at address 0x0 in task MAIN_TASK",
#endif
				 "at t=100", "main_task at ", "app.c:", NULL });
}

static void test_divide(void)
{
	struct outcome o;

#if defined(__SANITIZE_ADDRESS__)
	/* -fsanitize=integer-divide-by-zero reports the division before the CPU
	 * faults and exits with the sanitizer's status: no signal to report */
	tap_skip(5, "UBSan reports a division by zero before it faults");
	(void)o;
	return;
#endif
	run_misbehave("divide", &o);
#if defined(__arm__)
	/* ARMv5 has no divide instruction: libgcc's division routine raises SIGFPE
	 * itself, so the PC is in the C library, which has no line to give */
	expect("a division by zero", &o, EV3SIM_EXIT_CRASH,
	       (const char *[]){ "FATAL: crash: SIGFPE", "in task MAIN_TASK", NULL });
#else
	expect("a division by zero", &o, EV3SIM_EXIT_CRASH,
	       (const char *[]){ "FATAL: crash: SIGFPE (integer division by zero)", "in task MAIN_TASK",
				 "main_task at ", "app.c:", NULL });
#endif
}

static void test_abort(void)
{
	struct outcome o;

	run_misbehave("abort", &o);
	expect("abort()", &o, EV3SIM_EXIT_CRASH,
	       (const char *[]){ "FATAL: crash: SIGABRT (abort() called) in task MAIN_TASK", NULL });
}

static void test_recurse(void)
{
	struct outcome o;

	rtos_host_crash_install();   /* in this process too: does its alternate stack disarm itself? */
	if (!rtos_host_signal_stack_disarms()) {
		/* without SS_AUTODISARM host_sim's pointer trap has to run on the faulting
		 * stack, and a fault at a stack's end leaves no room there for it */
		tap_skip(3, "the alternate signal stack cannot disarm itself here (qemu-arm 7.2 has no "
		     "SS_AUTODISARM): a fault at a stack's end cannot be reported while host_sim's "
		     "pointer trap is installed");
		return;
	}
	run_misbehave("recurse", &o);
	expect("runaway recursion", &o, EV3SIM_EXIT_STACK,
	       (const char *[]){ "FATAL: stack overflow: task MAIN_TASK ran off the end of its host stack",
				 "recurse at ", NULL });
}

static void test_big_locals(void)
{
	struct outcome o;

	run_misbehave("big-locals", &o);
	expect("64 KiB of locals in a 4 KiB task", &o, EV3SIM_EXIT_STACK,
	       (const char *[]){ "ev3sim run: the app overran a task's stack at 0.100 s",
				 "stack: task MAIN_TASK used ", "more than the 4096 bytes its configuration gives it",
				 NULL });
}

int main(void)
{
	test_clean_run();
	test_stall();
	test_busy();
	test_null();
	test_divide();
	test_abort();
	test_recurse();
	test_big_locals();
	return tap_done();
}
