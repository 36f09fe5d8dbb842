/*
 * report.c — reports of kernel-API misuse: BUG, WARN, panic, context bugs.
 *
 * Where a report goes and how the system stops is the target's business
 * (lx_platform_report, lx_platform_halt: src/host/report.c, src/am1808/report.c).
 */
#include <linux/kernel.h>
#include <linux_compat/platform.h>
#include <linux_compat/report.h>

#define LX_REPORT_MAX	256

/* Reports a misuse at file:line with a formatted detail and returns. */
void lx_report(const char *what, const char *file, int line, const char *fmt, ...)
{
	char detail[LX_REPORT_MAX];
	va_list args;

	va_start(args, fmt);
	vscnprintf(detail, sizeof(detail), fmt, args);
	va_end(args);
	lx_platform_report(what, file, line, detail);
}

/* BUG(): reports the location and stops the system. */
void lx_bug(const char *file, int line)
{
	char context[64];

	lx_context_forbids_sleep(context, sizeof(context));
	lx_report("kernel BUG", file, line, "BUG() in %s", context);
	lx_platform_halt();
}

/* WARN(): reports a warning with a message and returns. */
void lx_warn(const char *file, int line, const char *fmt, ...)
{
	char detail[LX_REPORT_MAX];
	va_list args;

	va_start(args, fmt);
	vscnprintf(detail, sizeof(detail), fmt, args);
	va_end(args);
	lx_platform_report("WARNING", file, line, detail);
}

/* panic(): reports the message and stops the system. */
void panic(const char *fmt, ...)
{
	char detail[LX_REPORT_MAX];
	va_list args;

	va_start(args, fmt);
	vscnprintf(detail, sizeof(detail), fmt, args);
	va_end(args);
	lx_platform_report("Kernel panic", NULL, 0, detail);
	lx_platform_halt();
}
