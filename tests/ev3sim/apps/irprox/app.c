/*
 * app.c — irprox: a driving base creeps towards a wall reading the infrared
 * sensor's proximity (tests/ev3sim/test_app_irprox.c builds the world).
 *
 * Large motors on B (left) and C (right), the infrared sensor on port 4
 * looking ahead.  It logs the proximity, drives slowly until it reads
 * STOP_AT or less (or TIMEOUT_MS pass), stops and logs it again.
 */
#include "ev3api.h"
#include "app.h"

#define LEFT_MOTOR   EV3_PORT_B
#define RIGHT_MOTOR  EV3_PORT_C
#define IR           EV3_PORT_4

#define STOP_AT      20
#define TIMEOUT_MS   15000

void main_task(intptr_t exinf)
{
	int t;

	ev3_motor_config(LEFT_MOTOR, LARGE_MOTOR);
	ev3_motor_config(RIGHT_MOTOR, LARGE_MOTOR);
	ev3_sensor_config(IR, INFRARED_SENSOR);
	tslp_tsk(500);
	syslog(LOG_NOTICE, "irprox: start %d", ev3_infrared_sensor_get_distance(IR));
	for (t = 0; t < TIMEOUT_MS && ev3_infrared_sensor_get_distance(IR) > STOP_AT; t += 10) {
		ev3_motor_steer(LEFT_MOTOR, RIGHT_MOTOR, 20, 0);
		tslp_tsk(10);
	}
	ev3_motor_stop(LEFT_MOTOR, true);
	ev3_motor_stop(RIGHT_MOTOR, true);
	tslp_tsk(300);
	syslog(LOG_NOTICE, "irprox: stopped at %d ms, %d", t, ev3_infrared_sensor_get_distance(IR));
}
