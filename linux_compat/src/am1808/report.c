/*
 * report.c (AM1808) — reports are syslog lines at LOG_EMERG; a fatal one
 * stops the CPU with interrupts masked.
 */
#include <linux/kernel.h>
#include <linux_compat/platform.h>
#include <kernel.h>
#include <sil.h>
#include <t_syslog.h>

/* One syslog line at LOG_EMERG. */
void lx_platform_report(const char *what, const char *file, int line, const char *detail)
{
	if (file != NULL)
		syslog(LOG_EMERG, "BUG: %s at %s:%d: %s", what, file, line, detail);
	else
		syslog(LOG_EMERG, "BUG: %s: %s", what, detail);
}

/* Masks interrupts and spins forever. */
void lx_platform_halt(void)
{
	SIL_PRE_LOC;

	SIL_LOC_INT();
	for (;;)
		;
}

/* The AM1808 kernel does not name its interrupt contexts. */
void lx_platform_describe_interrupt(char *buf, size_t len)
{
	snprintf(buf, len, "interrupt context");
}
