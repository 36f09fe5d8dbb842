/*
 * test_t_stdlib.c — TOPPERS's library functions as EV3RT apps use them:
 * itron_strerror's names, t_perror's and SVC_PERROR's log line of a failed
 * service call (nothing for one that succeeded), and assert, which logs the
 * failed expression at LOG_EMERG and goes on, as EV3RT's does on the brick.
 */
#include "tap.h"
#include "kernel.h"
#include "t_stdlib.h"
#include "rtos_test.h"

static char traced[2048];

static void sink(const char *line, void *ctx)
{
	(void)ctx;
	strncat(traced, line, sizeof(traced) - strlen(traced) - 2);
	strcat(traced, "\n");
}

static const struct rtos_cfg cfg = { .name = "t_stdlib" };

int main(void)
{
	int after_assert = 0;

	tap_plan(10);
	is_str(itron_strerror(E_OK), "E_OK", "E_OK");
	is_str(itron_strerror(E_TMOUT), "E_TMOUT", "E_TMOUT");
	is_str(itron_strerror(ERCD(E_PAR, -3)), "E_PAR", "the main code of an error with a sub code");
	is_str(itron_strerror(-99), "unknown error", "a code TOPPERS does not define");

	is_int(rtos_host_boot(&cfg), E_OK, "boot");
	rtos_host_trace_set_sink(sink, NULL);
	t_perror(LOG_ERROR, "app.c", 12, "wai_sem(SEM1)", ERCD(E_TMOUT, -2));
	SVC_PERROR(E_OK);
	SVC_PERROR(tslp_tsk(-5));
	assert(after_assert == 1);
	after_assert = 1;
	ok(strstr(traced, "syslog ERROR: E_TMOUT (-2) reported by `wai_sem(SEM1)' in line 12 of `app.c'.\n") != NULL,
	   "t_perror: the error's name, sub code, expression, line and file");
	ok(strstr(traced, "reported by `E_OK'") == NULL, "SVC_PERROR logs nothing for E_OK");
	ok(strstr(traced, "syslog ERROR: E_CTX (-1) reported by `tslp_tsk(-5)'") != NULL,
	   "SVC_PERROR logs a failed call (not from a task; a plain code's sub code is -1) with its expression");
	ok(strstr(traced, "syslog EMERG: ") != NULL && strstr(traced, "Assertion `after_assert == 1' failed.") != NULL,
	   "a failed assert is logged at LOG_EMERG with its expression");
	is_int(after_assert, 1, "and the program goes on, as on EV3RT's AM1808 target");
	rtos_host_trace_set_sink(NULL, NULL);
	rtos_host_shutdown();
	return tap_done();
}
