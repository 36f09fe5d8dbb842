/*
 * app.c — gyroboy: a two-wheeled robot balanced by EV3RT's API.
 *
 * Large motors on A (left) and D (right), gyro on port 2.  The main task
 * waits for the gyro, estimates its offset while the robot is held still,
 * then starts BALANCE_CYC: every 4 ms, in task context, one control step
 * reads the gyro rate and the wheel counts and sets the same power on both
 * motors with ev3_motor_set_power (a regulated speed on large motors).
 *
 * Control: state feedback on the body angle (the integrated, offset-corrected
 * rate), its rate, the wheel angle and the wheel rate.  The offset keeps being
 * tracked slowly: a balancing robot's mean body rate is zero, so a drifting
 * gyro bias is followed instead of being integrated into the angle.
 */
#include "ev3api.h"
#include "app.h"
#include "kernel_cfg.h"

#define LEFT_MOTOR   EV3_PORT_A
#define RIGHT_MOTOR  EV3_PORT_D
#define GYRO         EV3_PORT_2

/* Feedback gains: power per degree and per degree/s. */
#define K_TILT       9.8f
#define K_TILT_RATE  1.08f
#define K_WHEEL      0.076f
#define K_WHEEL_RATE 0.21f

#define CALIBRATION_SAMPLES 200
#define CALIBRATION_GAP_MS  5
#define OFFSET_TRACKING     0.0005f   /* per period: a time constant of 8 s */
#define WHEEL_RATE_WINDOW   5         /* periods the wheel rate is averaged over */
#define FALLEN_DEG          40.0f

static float gyro_offset;           /* deg/s */
static float tilt;                  /* body angle, deg */
static float wheel_history[WHEEL_RATE_WINDOW];
static int history_len, history_pos;
static bool_t fallen;

void main_task(intptr_t exinf)
{
	float sum = 0.0f;
	int i;

	ev3_motor_config(LEFT_MOTOR, LARGE_MOTOR);
	ev3_motor_config(RIGHT_MOTOR, LARGE_MOTOR);
	ev3_sensor_config(GYRO, GYRO_SENSOR);
	ev3_led_set_color(LED_ORANGE);

	/* hold the robot still: the gyro's offset */
	ev3_gyro_sensor_reset(GYRO);
	for (i = 0; i < CALIBRATION_SAMPLES; i++) {
		sum += ev3_gyro_sensor_get_rate(GYRO);
		tslp_tsk(CALIBRATION_GAP_MS);
	}
	gyro_offset = sum / CALIBRATION_SAMPLES;
	ev3_motor_reset_counts(LEFT_MOTOR);
	ev3_motor_reset_counts(RIGHT_MOTOR);
	syslog(LOG_NOTICE, "gyroboy: gyro offset %d mdeg/s, balancing", (int)(gyro_offset * 1000.0f));
	ev3_led_set_color(LED_GREEN);
	ev3_sta_cyc(BALANCE_CYC);

	while (!fallen)
		tslp_tsk(100);
	ev3_stp_cyc(BALANCE_CYC);
	ev3_motor_stop(LEFT_MOTOR, false);
	ev3_motor_stop(RIGHT_MOTOR, false);
	ev3_led_set_color(LED_RED);
	syslog(LOG_NOTICE, "gyroboy: fell over");
}

void balance_cyc(intptr_t exinf)
{
	const float dt = BALANCE_PERIOD_MS / 1000.0f;
	float rate, wheel, wheel_rate, u;
	int power;

	if (fallen)
		return;
	rate = ev3_gyro_sensor_get_rate(GYRO);
	wheel = (ev3_motor_get_counts(LEFT_MOTOR) + ev3_motor_get_counts(RIGHT_MOTOR)) / 2.0f;

	gyro_offset += OFFSET_TRACKING * (rate - gyro_offset);
	rate -= gyro_offset;
	tilt += rate * dt;
	if (history_len < WHEEL_RATE_WINDOW) {
		wheel_rate = history_len ? (wheel - wheel_history[0]) / (history_len * dt) : 0.0f;
		wheel_history[history_len++] = wheel;
	} else {
		wheel_rate = (wheel - wheel_history[history_pos]) / (WHEEL_RATE_WINDOW * dt);
		wheel_history[history_pos] = wheel;
		history_pos = (history_pos + 1) % WHEEL_RATE_WINDOW;
	}
	/* wheel angle and rate over the ground: the motors turn relative to the body */
	u = K_TILT * tilt + K_TILT_RATE * rate + K_WHEEL * (wheel + tilt) +
	    K_WHEEL_RATE * (wheel_rate + rate);
	if (u > 100.0f)
		u = 100.0f;
	else if (u < -100.0f)
		u = -100.0f;
	power = (int)(u + (u < 0 ? -0.5f : 0.5f));
	ev3_motor_set_power(LEFT_MOTOR, power);
	ev3_motor_set_power(RIGHT_MOTOR, power);
	if (tilt > FALLEN_DEG || tilt < -FALLEN_DEG)
		fallen = true;
}
