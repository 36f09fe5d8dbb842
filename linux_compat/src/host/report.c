/*
 * report.c (host) — reports go to the host kernel's bug channel, so a test
 * fails unless it declared that it expects them; a fatal one aborts.
 */
#include <stdio.h>
#include <stdlib.h>
#include <linux_compat/platform.h>
#include <rtos_host.h>

/* One bug report through rtos_host_bug. */
void lx_platform_report(const char *what, const char *file, int line, const char *detail)
{
	if (file != NULL)
		rtos_host_bug(what, "at %s:%d: %s", file, line, detail);
	else
		rtos_host_bug(what, "%s", detail);
}

/* Flushes the output and aborts the process. */
void lx_platform_halt(void)
{
	fflush(stdout);
	fflush(stderr);
	abort();
}

/* "interrupt context (<the host kernel's name of it>)". */
void lx_platform_describe_interrupt(char *buf, size_t len)
{
	snprintf(buf, len, "interrupt context (%s)", rtos_host_context_name());
}
