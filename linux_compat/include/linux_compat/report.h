/*
 * linux_compat/report.h — how linux_compat reports misuse of the kernel API.
 *
 * Every report is one line "BUG: <what> at <file>:<line>: <details> [<context>]".
 * Host: it goes to rtos_host_bug, so the test run fails unless the test
 * declared it expects bugs (rtos_host_expect_bugs).  AM1808: it is logged
 * with syslog at LOG_EMERG.
 */
#ifndef _LINUX_COMPAT_REPORT_H
#define _LINUX_COMPAT_REPORT_H

#include <stdbool.h>

/* Reports a misuse ("what") at file:line with a formatted detail; returns. */
void lx_report(const char *what, const char *file, int line, const char *fmt, ...)
	__attribute__((__format__(printf, 4, 5)));

/* BUG(): reports and stops the system; never returns. */
void lx_bug(const char *file, int line) __attribute__((__noreturn__, __cold__));

/* WARN(): reports a warning with a formatted message and returns. */
void lx_warn(const char *file, int line, const char *fmt, ...)
	__attribute__((__format__(printf, 3, 4), __cold__));

#endif /* _LINUX_COMPAT_REPORT_H */
