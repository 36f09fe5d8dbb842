/*
 * test_syslog.c — syslog: console lines "# [<ns>] LEVEL: msg" for the
 * console mask, trace lines for the log mask, masks set by syslog_msk_log
 * and reset at boot; the trace line format "<ns> <source> <text>".
 */
#define _POSIX_C_SOURCE 200809L
#include <unistd.h>

#include "tap.h"
#include "kernel.h"
#include "syssvc/syslog.h"
#include "rtos_test.h"

static char traced[2048];

static void sink(const char *line, void *ctx)
{
	strncat(traced, line, sizeof(traced) - strlen(traced) - 2);
	strcat(traced, "\n");
}

static const struct rtos_cfg cfg = { .name = "syslog" };

/* Runs fn with stdout captured into buf. */
static void capture(void (*fn)(void), char *buf, size_t size)
{
	FILE *tmp = tmpfile();
	int saved;
	size_t n;

	fflush(stdout);
	saved = dup(1);
	dup2(fileno(tmp), 1);
	fn();
	fflush(stdout);
	dup2(saved, 1);
	close(saved);
	rewind(tmp);
	n = fread(buf, 1, size - 1, tmp);
	buf[n] = '\0';
	fclose(tmp);
}

static void log_some(void)
{
	syslog(LOG_NOTICE, "motor %d ready", 3);
	syslog(LOG_INFO, "info line");
	syslog(LOG_ERROR, "bad %s", "thing");
}

int main(void)
{
	char out[1024];

	tap_plan(6);
	is_int(rtos_host_boot(&cfg), E_OK, "boot");
	rtos_host_run_for(1500);
	rtos_host_trace_set_sink(sink, NULL);
	capture(log_some, out, sizeof(out));
	is_str(out, "# [1500] NOTICE: motor 3 ready\n# [1500] ERROR: bad thing\n",
	       "console gets LOG_UPTO(LOG_NOTICE) by default, as TAP comments with virtual time");
	is_str(traced, "1500 syslog NOTICE: motor 3 ready\n1500 syslog INFO: info line\n1500 syslog ERROR: bad thing\n",
	       "the trace gets every priority by default, as \"<ns> syslog ...\" lines");
	traced[0] = '\0';
	is_int(syslog_msk_log(LOG_MASK(LOG_ERROR), LOG_UPTO(LOG_INFO)), E_OK, "syslog_msk_log");
	capture(log_some, out, sizeof(out));
	ok(strstr(out, "INFO: info line") != NULL && strcmp(traced, "1500 syslog ERROR: bad thing\n") == 0,
	   "masks select console and trace lines");
	rtos_host_boot(&cfg);
	traced[0] = '\0';
	capture(log_some, out, sizeof(out));
	ok(strstr(out, "INFO") == NULL && strstr(traced, "0 kernel boot syslog") == NULL &&
	   strstr(traced, "0 syslog INFO: info line") != NULL, "masks return to the defaults at boot");
	rtos_host_trace_set_sink(NULL, NULL);
	rtos_host_shutdown();
	return tap_done();
}
