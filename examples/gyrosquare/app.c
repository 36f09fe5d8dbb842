/*
 * app.c — gyrosquare: a driving base drives a square, turning its corners
 * by the gyro.
 *
 * Large motors on B (left) and C (right), the gyro on port 2 lying flat.  The
 * robot stands still for a second while the gyro is reset, then drives four
 * sides of SIDE_MM, each held straight by the gyro (a proportional steer
 * towards the side's heading) and measured by the wheels' counts, and turns
 * 90 degrees to the left on the spot at each corner, slowing down as the gyro
 * nears the corner's angle.  The EV3 gyro counts clockwise positive, so a
 * left turn takes its angle down by 90.  Each corner and the end are logged
 * with the gyro's angle.
 */
#include "ev3api.h"
#include "app.h"

#define LEFT_MOTOR   EV3_PORT_B
#define RIGHT_MOTOR  EV3_PORT_C
#define GYRO         EV3_PORT_2

#define SIDE_MM      500
#define WHEEL_MM     56         /* LEGO's 56 x 28 tyre */
#define POWER        40
#define KP_STRAIGHT  3          /* steer per degree off the side's heading */
#define PERIOD_MS    4

static const float pi = 3.14159265f;

/* The mean of both wheels' counts, degrees. */
static int wheel_deg(void)
{
	return (ev3_motor_get_counts(LEFT_MOTOR) + ev3_motor_get_counts(RIGHT_MOTOR)) / 2;
}

/* Drives SIDE_MM forward holding the gyro at heading (deg). */
static void drive_side(int heading)
{
	int start = wheel_deg();
	int target = (int)(SIDE_MM * 360.0f / (pi * WHEEL_MM));

	while (wheel_deg() - start < target) {
		int turn = KP_STRAIGHT * (ev3_gyro_sensor_get_angle(GYRO) - heading);

		if (turn > 100)
			turn = 100;
		else if (turn < -100)
			turn = -100;
		/* steering with a positive ratio turns right: off to the right
		 * (the angle above the heading) steers left */
		ev3_motor_steer(LEFT_MOTOR, RIGHT_MOTOR, POWER, -turn);
		tslp_tsk(PERIOD_MS);
	}
	ev3_motor_stop(LEFT_MOTOR, true);
	ev3_motor_stop(RIGHT_MOTOR, true);
	tslp_tsk(300);
}

/* Turns left on the spot until the gyro reads heading (deg). */
static void turn_to(int heading)
{
	int err;

	while ((err = ev3_gyro_sensor_get_angle(GYRO) - heading) > 0) {
		int power = err * 2;

		if (power > 30)
			power = 30;
		else if (power < 8)
			power = 8;
		ev3_motor_set_power(LEFT_MOTOR, -power);
		ev3_motor_set_power(RIGHT_MOTOR, power);
		tslp_tsk(PERIOD_MS);
	}
	ev3_motor_stop(LEFT_MOTOR, true);
	ev3_motor_stop(RIGHT_MOTOR, true);
	tslp_tsk(300);
}

void main_task(intptr_t exinf)
{
	int heading = 0;

	ev3_motor_config(LEFT_MOTOR, LARGE_MOTOR);
	ev3_motor_config(RIGHT_MOTOR, LARGE_MOTOR);
	ev3_sensor_config(GYRO, GYRO_SENSOR);
	tslp_tsk(1000);         /* stand still: the gyro settles */
	ev3_gyro_sensor_reset(GYRO);
	ev3_motor_reset_counts(LEFT_MOTOR);
	ev3_motor_reset_counts(RIGHT_MOTOR);
	syslog(LOG_NOTICE, "gyrosquare: go");
	for (int corner = 1; corner <= 4; corner++) {
		drive_side(heading);
		heading -= 90;
		turn_to(heading);
		syslog(LOG_NOTICE, "gyrosquare: corner %d, gyro %d deg", corner, ev3_gyro_sensor_get_angle(GYRO));
	}
	syslog(LOG_NOTICE, "gyrosquare: done, gyro %d deg, wheels %d deg", ev3_gyro_sensor_get_angle(GYRO),
	       wheel_deg());
}
