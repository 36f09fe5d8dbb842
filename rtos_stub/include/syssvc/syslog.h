/*
 * syssvc/syslog.h — TOPPERS's system log service, as apps include it
 * (public source: ev3rt-git/ev3rt-hrp2, syssvc/syslog.h): the log calls
 * apps use (syslog, syslog_msk_log) are t_syslog.h's.
 */
#ifndef TOPPERS_SYSLOG_H
#define TOPPERS_SYSLOG_H

#include "t_syslog.h"

#endif /* TOPPERS_SYSLOG_H */
