/*
 * app_common.c — helpers the ev3sim applications share (apps.h).
 */
#define _POSIX_C_SOURCE 200809L
#include <time.h>
#include "syssvc/syslog.h"
#include "ev3sim/apps.h"

void ev3sim_quiet_console(void)
{
	(void)syslog_msk_log(LOG_UPTO(LOG_DEBUG), LOG_UPTO(LOG_WARNING));
}

double ev3sim_wall_seconds(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (double)ts.tv_sec + (double)ts.tv_nsec * 1e-9;
}
