/*
 * app.c — usleep: an EV3RT 1.x app as tutorials write them, whose app.cfg
 * has a task and no time event, so only its waits tell that it counts in
 * microseconds (TOPPERS/HRP3).  It sleeps a quarter of a second and logs
 * how long that took by the system clock.
 */
#include "app.h"

void main_task(intptr_t unused)
{
	SYSTIM before, after;

	get_tim(&before);
	tslp_tsk(250000);       /* 0.25 s */
	get_tim(&after);
	syslog(LOG_NOTICE, "usleep: tslp_tsk(250000) took %lu ms", (unsigned long)((after - before) / 1000U));
}
