/*
 * app.c — avoid: a driving base wanders without touching anything, seeing
 * obstacles with the ultrasonic sensor.
 *
 * Large motors on B (left) and C (right), a touch sensor as a bumper on port
 * 1, the ultrasonic sensor on port 4 looking ahead.  Every 10 ms it reads the
 * distance ahead: with more than NEAR_CM free it drives straight on; closer,
 * it backs off a little and turns on the spot until it sees more than CLEAR_CM free and a little
 * further (its body is wider than the sensor's beam near it), the way it
 * turned last time unless that took over two seconds (then the other way).
 * The bumper should never be pressed; if it is, the robot backs off before
 * it turns.  It logs every turn, and at the end how far the wheels rolled.
 */
#include "ev3api.h"
#include "app.h"

#define LEFT_MOTOR   EV3_PORT_B
#define RIGHT_MOTOR  EV3_PORT_C
#define BUMPER       EV3_PORT_1
#define SONAR        EV3_PORT_4

#define POWER        45
#define TURN_POWER   25
#define NEAR_CM      35
#define CLEAR_CM     60
#define BACK_MS      300        /* backing off before a turn */
#define EXTRA_MS     300        /* turn on past the clear view: the body is wider than the beam */
#define PERIOD_MS    10
#define RUN_MS       60000

void main_task(intptr_t exinf)
{
	int turns = 0, bumps = 0, dir = 1;
	SYSTIM start, now;

	ev3_motor_config(LEFT_MOTOR, LARGE_MOTOR);
	ev3_motor_config(RIGHT_MOTOR, LARGE_MOTOR);
	ev3_sensor_config(BUMPER, TOUCH_SENSOR);
	ev3_sensor_config(SONAR, ULTRASONIC_SENSOR);
	tslp_tsk(500);
	syslog(LOG_NOTICE, "avoid: go, %d cm free ahead", ev3_ultrasonic_sensor_get_distance(SONAR));
	get_tim(&start);
	for (get_tim(&now); now - start < RUN_MS; get_tim(&now)) {
		int cm = ev3_ultrasonic_sensor_get_distance(SONAR);

		if (ev3_touch_sensor_is_pressed(BUMPER)) {
			bumps++;
			ev3_motor_steer(LEFT_MOTOR, RIGHT_MOTOR, -POWER, 0);
			tslp_tsk(400);
			cm = 0;
		}
		if (cm >= NEAR_CM) {
			ev3_motor_steer(LEFT_MOTOR, RIGHT_MOTOR, POWER, 0);
			tslp_tsk(PERIOD_MS);
			continue;
		}
		/* too close: back off a little, then turn on the spot until the
		 * way ahead is clear */
		int spent = BACK_MS;

		turns++;
		ev3_motor_steer(LEFT_MOTOR, RIGHT_MOTOR, -POWER, 0);
		tslp_tsk(BACK_MS);
		while (ev3_ultrasonic_sensor_get_distance(SONAR) < CLEAR_CM && spent < 4000) {
			ev3_motor_set_power(LEFT_MOTOR, dir * TURN_POWER);
			ev3_motor_set_power(RIGHT_MOTOR, -dir * TURN_POWER);
			tslp_tsk(PERIOD_MS);
			spent += PERIOD_MS;
		}
		tslp_tsk(EXTRA_MS);
		syslog(LOG_NOTICE, "avoid: turn %d %s at %d cm, %d ms", turns, dir > 0 ? "right" : "left", cm, spent);
		if (spent > 2000)
			dir = -dir;
	}
	ev3_motor_stop(LEFT_MOTOR, true);
	ev3_motor_stop(RIGHT_MOTOR, true);
	syslog(LOG_NOTICE, "avoid: done, %d turns, %d bumps, wheels %d deg", turns, bumps,
	       (ev3_motor_get_counts(LEFT_MOTOR) + ev3_motor_get_counts(RIGHT_MOTOR)) / 2);
}
