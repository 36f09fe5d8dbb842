/*
 * syslog.c — the TOPPERS system log on the host: lines in the console mask
 * go to stdout as TAP comments "# [<ns>] <level>: <msg>", lines in the log
 * mask go to the trace.  Never blocks, callable from any context.
 */
#include <stdarg.h>
#include <stdio.h>

#include "kernel_impl.h"
#include "syssvc/syslog.h"

#define DEFAULT_LOGMASK LOG_UPTO(LOG_DEBUG)
#define DEFAULT_LOWMASK LOG_UPTO(LOG_NOTICE)

static uint_t log_mask = DEFAULT_LOGMASK;
static uint_t low_mask = DEFAULT_LOWMASK;

static const char *const level_names[] = {
	"EMERG", "ALERT", "CRIT", "ERROR", "WARNING", "NOTICE", "INFO", "DEBUG",
};

/* Writes one formatted log line at prio (console and/or trace per the masks). */
void syslog(uint_t prio, const char *format, ...)
{
	char msg[400];
	va_list ap;

	svc_charge();
	if (prio > LOG_DEBUG)
		prio = LOG_DEBUG;
	if (!(low_mask & LOG_MASK(prio)) && !((log_mask & LOG_MASK(prio)) && trace_on()))
		return;
	va_start(ap, format);
	vsnprintf(msg, sizeof(msg), format, ap);
	va_end(ap);
	if (low_mask & LOG_MASK(prio)) {
		printf("# [%llu] %s: %s\n", (unsigned long long)now_ns, level_names[prio], msg);
		fflush(stdout);
	}
	if (log_mask & LOG_MASK(prio))
		rtos_host_trace("syslog", "%s: %s", level_names[prio], msg);
}

/* Sets which priorities reach the trace (logmask) and the console (lowmask); any domain may. */
ER _syslog_msk_log(uint_t logmask, uint_t lowmask, ID cdmid)
{
	(void)cdmid;
	svc_charge();
	log_mask = logmask;
	low_mask = lowmask;
	return E_OK;
}

/* Restores the default masks (boot). */
void syslog_reset(void)
{
	log_mask = DEFAULT_LOGMASK;
	low_mask = DEFAULT_LOWMASK;
}
