/*
 * report.c — reports of kernel-API misuse: BUG, WARN, panic, context bugs.
 *
 * Host: through rtos_host_bug, so a test fails unless it expects the bug.
 * AM1808: one syslog line at LOG_EMERG.
 */
#include <linux/kernel.h>
#include <linux_compat/report.h>
#include <stdio.h>
#include <t_syslog.h>
#include <kernel.h>
#include <sil.h>
#if defined(EV3LX_HOST)
#include <stdlib.h>
#include <rtos_host.h>
#endif

#define LX_REPORT_MAX	256

/* Emits one report line: "<what> at <file>:<line>: <detail>". */
static void emit_report(const char *what, const char *file, int line, const char *detail)
{
#if defined(EV3LX_HOST)
	if (file != NULL)
		rtos_host_bug(what, "at %s:%d: %s", file, line, detail);
	else
		rtos_host_bug(what, "%s", detail);
#else
	if (file != NULL)
		syslog(LOG_EMERG, "BUG: %s at %s:%d: %s", what, file, line, detail);
	else
		syslog(LOG_EMERG, "BUG: %s: %s", what, detail);
#endif
}

/* Reports a misuse at file:line with a formatted detail and returns. */
void lx_report(const char *what, const char *file, int line, const char *fmt, ...)
{
	char detail[LX_REPORT_MAX];
	va_list args;

	va_start(args, fmt);
	vscnprintf(detail, sizeof(detail), fmt, args);
	va_end(args);
	emit_report(what, file, line, detail);
}

/* Stops the system after a fatal report; never returns. */
static void __attribute__((__noreturn__)) halt_system(void)
{
#if defined(EV3LX_HOST)
	fflush(stdout);
	fflush(stderr);
	abort();
#else
	SIL_PRE_LOC;

	SIL_LOC_INT();
	for (;;)
		;
#endif
}

/* BUG(): reports the location and stops the system. */
void lx_bug(const char *file, int line)
{
	char context[64];

	lx_context_forbids_sleep(context, sizeof(context));
	lx_report("kernel BUG", file, line, "BUG() in %s", context);
	halt_system();
}

/* WARN(): reports a warning with a message and returns. */
void lx_warn(const char *file, int line, const char *fmt, ...)
{
	char detail[LX_REPORT_MAX];
	va_list args;

	va_start(args, fmt);
	vscnprintf(detail, sizeof(detail), fmt, args);
	va_end(args);
	emit_report("WARNING", file, line, detail);
}

/* panic(): reports the message and stops the system. */
void panic(const char *fmt, ...)
{
	char detail[LX_REPORT_MAX];
	va_list args;

	va_start(args, fmt);
	vscnprintf(detail, sizeof(detail), fmt, args);
	va_end(args);
	emit_report("Kernel panic", NULL, 0, detail);
	halt_system();
}
