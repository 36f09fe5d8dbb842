/*
 * syssvc/syslog.h — TOPPERS's system log service, as apps include it
 * (public source: ev3rt-git/ev3rt-hrp2, syssvc/syslog.h): syslog itself and
 * the priorities are t_syslog.h's; the service adds syslog_msk_log.
 *
 * As HRP2 has it, the service's entry takes the caller's domain
 * (_syslog_msk_log); kernel-domain code (TOPPERS_SVC_CALL) calls it as the
 * kernel domain, a user domain through extended service call
 * TFN_SYSLOG_MSK_LOG (4, include/extsvc_fncode.h), which the system log's
 * configuration defines.  The host serves a user domain's call directly.
 */
#ifndef TOPPERS_SYSLOG_H
#define TOPPERS_SYSLOG_H

#include "kernel.h"
#include "t_syslog.h"

#ifdef __cplusplus
extern "C" {
#endif

#define TFN_SYSLOG_MSK_LOG  (4)

/* Sets which priorities reach the log (logmask) and the console (lowmask), for domain cdmid. */
ER _syslog_msk_log(uint_t logmask, uint_t lowmask, ID cdmid);

#if defined(TOPPERS_SVC_CALL)
#define syslog_msk_log(logmask, lowmask) _syslog_msk_log(logmask, lowmask, TDOM_KERNEL)
#elif defined(EV3LX_AM1808)
/* syslog_msk_log from a user domain: the system log's extended service call. */
Inline ER syslog_msk_log(uint_t logmask, uint_t lowmask)
{
	return (ER)cal_svc(TFN_SYSLOG_MSK_LOG, (intptr_t)logmask, (intptr_t)lowmask, 0, 0, 0);
}
#else
/* syslog_msk_log from a user domain: the host serves it directly. */
Inline ER syslog_msk_log(uint_t logmask, uint_t lowmask)
{
	return _syslog_msk_log(logmask, lowmask, TDOM_SELF);
}
#endif

#ifdef __cplusplus
}
#endif

#endif /* TOPPERS_SYSLOG_H */
