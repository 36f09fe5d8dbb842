/*
 * bug.c — bug reports: context violations and other misuse found by the
 * kernel or the layers above.  An unexpected report makes the process exit
 * non-zero, so a test with a hidden bug fails under prove even if every TAP
 * line passed.
 */
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "kernel_impl.h"

static uint_t bugs_since_boot;
static uint_t bugs_unexpected;
static bool bugs_expected;
static bool exit_hook_installed;
static char last_bug[1024];

/* At exit: an unexpected bug turns a passing run into a failing one; a system
 * that ended on a stalled task or a stack overrun exits with that kind's status. */
static void bug_exit_hook(void)
{
	int status = rtos_host_end_status();

	if (bugs_unexpected == 0)
		return;
	fprintf(stderr, "rtos_host: %u unexpected bug report(s): failing the run\n", bugs_unexpected);
	printf("# rtos_host: %u unexpected bug report(s): failing the run\n", bugs_unexpected);
	fflush(NULL);
	_exit(status != 0 ? status : 1);
}

/* Reports a bug on stderr (unless expected) and as a TAP diagnostic, with virtual time and context. */
void rtos_host_bug(const char *what, const char *fmt, ...)
{
	char msg[768];
	va_list ap;

	va_start(ap, fmt);
	vsnprintf(msg, sizeof(msg), fmt, ap);
	va_end(ap);
	snprintf(last_bug, sizeof(last_bug), "%s: %s at t=%llu ns in %s", what, msg,
		 (unsigned long long)now_ns, rtos_host_context_name());
	fflush(stdout);
	/* Expected bugs (tests of the checks) stay off stderr so that prove's output stays clean. */
	if (!bugs_expected)
		fprintf(stderr, "BUG: %s\n", last_bug);
	printf("# BUG %s%s\n", last_bug, bugs_expected ? " (expected)" : "");
	fflush(NULL);
	rtos_host_trace("bug", "%s", last_bug);
	bugs_since_boot++;
	if (!bugs_expected) {
		bugs_unexpected++;
		if (!exit_hook_installed) {
			exit_hook_installed = true;
			atexit(bug_exit_hook);
		}
	}
}

/* While expecting, bugs are counted but do not fail the run. */
void rtos_host_expect_bugs(bool expect)
{
	bugs_expected = expect;
}

/* Number of bugs reported since boot. */
uint_t rtos_host_bug_count(void)
{
	return bugs_since_boot;
}

/* Text of the last bug report since boot (empty if none). */
const char *rtos_host_last_bug(void)
{
	return last_bug;
}

/* Forgets the reports of the previous boot (the exit status keeps them). */
void bug_reset(void)
{
	bugs_since_boot = 0;
	last_bug[0] = '\0';
}

/* A name for the current context. */
const char *rtos_host_context_name(void)
{
	static char name[96];

	switch (cpu.kind) {
	case EXEC_TASK:
		if (runtsk != NULL && runtsk->cfg->name != NULL)
			snprintf(name, sizeof(name), "task %s", runtsk->cfg->name);
		else
			snprintf(name, sizeof(name), "task %d", runtsk != NULL ? (int)runtsk->id : 0);
		break;
	case EXEC_ISR:
		snprintf(name, sizeof(name), "isr %d", (int)cpu.exec_id);
		break;
	case EXEC_CYC:
		snprintf(name, sizeof(name), "cyclic %d", (int)cpu.exec_id);
		break;
	case EXEC_ALM:
		snprintf(name, sizeof(name), "alarm %d", (int)cpu.exec_id);
		break;
	case EXEC_INIT:
		snprintf(name, sizeof(name), "init");
		break;
	case EXEC_EVENT:
		snprintf(name, sizeof(name), "event");
		break;
	default:
		snprintf(name, sizeof(name), terminating ? "ter" : "idle");
		break;
	}
	return name;
}
