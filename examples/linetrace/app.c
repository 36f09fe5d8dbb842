/*
 * app.c — linetrace: a driving base follows the edge of a black line.
 *
 * Large motors on B (left) and C (right), touch sensor on port 1, colour
 * sensor on port 3 looking down in front of the axle.  The main task waits
 * for the touch sensor to be pressed (busy-polling, as EV3RT apps do), then
 * starts TRACE_CYC: every 4 ms the reflected light is compared with the
 * middle between the line's and the mat's, and the pair is steered with
 * ev3_motor_steer by a PD controller on that error: more light turns right,
 * so the robot keeps to the line's left-hand edge.  The back button stops it.
 */
#include "ev3api.h"
#include "app.h"

#define LEFT_MOTOR   EV3_PORT_B
#define RIGHT_MOTOR  EV3_PORT_C
#define TOUCH        EV3_PORT_1
#define COLOR        EV3_PORT_3

#define POWER        40
#define KP           2.0f       /* turn_ratio per % of reflected light */
#define KD           6.0f       /* per % change in one period */

static int target;              /* reflect % between line and mat */
static int last_error;
static int steps;

void main_task(intptr_t exinf)
{
	int white, black;

	ev3_motor_config(LEFT_MOTOR, LARGE_MOTOR);
	ev3_motor_config(RIGHT_MOTOR, LARGE_MOTOR);
	ev3_sensor_config(TOUCH, TOUCH_SENSOR);
	ev3_sensor_config(COLOR, COLOR_SENSOR);
	ev3_led_set_color(LED_ORANGE);

	/* the robot is put down with the sensor on the line: it sees black */
	black = ev3_color_sensor_get_reflect(COLOR);
	syslog(LOG_NOTICE, "linetrace: line %d%%, press the touch sensor to start", black);
	while (!ev3_touch_sensor_is_pressed(TOUCH))
		;
	while (ev3_touch_sensor_is_pressed(TOUCH))
		;
	white = 64;
	target = (black + white) / 2;
	syslog(LOG_NOTICE, "linetrace: go, target %d%%", target);
	ev3_led_set_color(LED_GREEN);
	ev3_sta_cyc(TRACE_CYC);

	while (!ev3_button_is_pressed(BACK_BUTTON))
		tslp_tsk(100);
	ev3_stp_cyc(TRACE_CYC);
	ev3_motor_stop(LEFT_MOTOR, true);
	ev3_motor_stop(RIGHT_MOTOR, true);
	ev3_led_set_color(LED_OFF);
	syslog(LOG_NOTICE, "linetrace: stopped after %d steps", steps);
}

void trace_cyc(intptr_t exinf)
{
	int error = ev3_color_sensor_get_reflect(COLOR) - target;
	float turn = KP * error + KD * (error - last_error);

	last_error = error;
	if (turn > 100.0f)
		turn = 100.0f;
	else if (turn < -100.0f)
		turn = -100.0f;
	ev3_motor_steer(LEFT_MOTOR, RIGHT_MOTOR, POWER, (int)turn);
	steps++;
}
