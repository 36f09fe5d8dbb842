/*
 * app.c — drive: a driving base reports what its sensors read as it drives
 * across a world (tests/ev3sim/test_app_drive.c builds the worlds).
 *
 * Large motors on B (left) and C (right); touch on port 1 (a bumper), gyro
 * on 2, colour on 3 looking down, ultrasonic on 4 looking ahead.  It logs
 * the distance ahead, drives straight on at DRIVE_POWER logging every change
 * of the colour under it, until the bumper is pressed or DRIVE_MS pass, logs
 * the distance then, backs off, spins left on the spot for SPIN_MS and logs
 * the gyro's angle and the wheels' counts.
 */
#include "ev3api.h"
#include "app.h"

#define LEFT_MOTOR   EV3_PORT_B
#define RIGHT_MOTOR  EV3_PORT_C
#define BUMPER       EV3_PORT_1
#define GYRO         EV3_PORT_2
#define COLOR        EV3_PORT_3
#define SONAR        EV3_PORT_4

#define DRIVE_POWER  40
#define DRIVE_MS     8000
#define SPIN_MS      2000

void main_task(intptr_t exinf)
{
	int t, last_color = -1;

	ev3_motor_config(LEFT_MOTOR, LARGE_MOTOR);
	ev3_motor_config(RIGHT_MOTOR, LARGE_MOTOR);
	ev3_sensor_config(BUMPER, TOUCH_SENSOR);
	ev3_sensor_config(GYRO, GYRO_SENSOR);
	ev3_sensor_config(COLOR, COLOR_SENSOR);
	ev3_sensor_config(SONAR, ULTRASONIC_SENSOR);
	tslp_tsk(500);
	ev3_gyro_sensor_reset(GYRO);
	syslog(LOG_NOTICE, "drive: ahead %d cm", ev3_ultrasonic_sensor_get_distance(SONAR));
	for (t = 0; t < DRIVE_MS && !ev3_touch_sensor_is_pressed(BUMPER); t += 10) {
		int color = ev3_color_sensor_get_color(COLOR);

		if (color != last_color) {
			syslog(LOG_NOTICE, "drive: color %d at %d ms", color, t);
			last_color = color;
		}
		ev3_motor_steer(LEFT_MOTOR, RIGHT_MOTOR, DRIVE_POWER, 0);
		tslp_tsk(10);
	}
	syslog(LOG_NOTICE, "drive: stopped at %d ms, bumper %d, ahead %d cm, wheels %d deg", t,
	       ev3_touch_sensor_is_pressed(BUMPER), ev3_ultrasonic_sensor_get_distance(SONAR),
	       (ev3_motor_get_counts(LEFT_MOTOR) + ev3_motor_get_counts(RIGHT_MOTOR)) / 2);
	ev3_motor_steer(LEFT_MOTOR, RIGHT_MOTOR, -DRIVE_POWER, 0);
	tslp_tsk(300);
	ev3_motor_stop(LEFT_MOTOR, true);
	ev3_motor_stop(RIGHT_MOTOR, true);
	tslp_tsk(200);
	syslog(LOG_NOTICE, "drive: backed off, bumper %d", ev3_touch_sensor_is_pressed(BUMPER));
	ev3_motor_set_power(LEFT_MOTOR, -20);
	ev3_motor_set_power(RIGHT_MOTOR, 20);
	tslp_tsk(SPIN_MS);
	ev3_motor_stop(LEFT_MOTOR, true);
	ev3_motor_stop(RIGHT_MOTOR, true);
	tslp_tsk(300);
	syslog(LOG_NOTICE, "drive: spun, gyro %d deg, reflect %d", ev3_gyro_sensor_get_angle(GYRO),
	       ev3_color_sensor_get_reflect(COLOR));
}
