/*
 * t_syslog.h — TOPPERS system log: priorities and the syslog service.
 */
#ifndef TOPPERS_T_SYSLOG_H
#define TOPPERS_T_SYSLOG_H

#ifdef __cplusplus
extern "C" {
#endif

#include "t_stddef.h"

#define LOG_EMERG    0U
#define LOG_ALERT    1U
#define LOG_CRIT     2U
#define LOG_ERROR    3U
#define LOG_WARNING  4U
#define LOG_NOTICE   5U
#define LOG_INFO     6U
#define LOG_DEBUG    7U

#define LOG_MASK(prio)   (1U << (prio))
#define LOG_UPTO(prio)   ((1U << ((prio) + 1)) - 1)

/* Writes one formatted log line at the given priority; never blocks. */
void syslog(uint_t prio, const char *format, ...)
	__attribute__((format(printf, 2, 3)));

/* The log line of a failed assert (t_stddef.h): at LOG_EMERG, as TOPPERS's. */
#ifndef TOPPERS_assert_fail
#define TOPPERS_assert_fail(exp, file, line) \
	syslog(LOG_EMERG, "%s:%d: Assertion `%s' failed.", (file), (int)(line), (exp))
#endif

#ifdef __cplusplus
}
#endif

#endif /* TOPPERS_T_SYSLOG_H */
