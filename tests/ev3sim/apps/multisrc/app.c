/*
 * app.c — multisrc: runs motor A at a speed computed in lib/speed.c for a
 * second and logs how far it turned.
 */
#include "ev3api.h"
#include "app.h"
#include "speed.h"

void main_task(intptr_t exinf)
{
	ev3_motor_config(EV3_PORT_A, LARGE_MOTOR);
	ev3_motor_set_power(EV3_PORT_A, speed_for(EV3_PORT_A));
	tslp_tsk(1000);
	syslog(LOG_NOTICE, "multisrc: A turned %ld degrees, %d speed lookups",
	       (long)ev3_motor_get_counts(EV3_PORT_A), speed_lookups);
	ev3_motor_stop(EV3_PORT_A, true);
}
