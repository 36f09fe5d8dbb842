/*
 * app.c — gyroboy: a two-wheeled robot balanced by EV3RT's API, with a gyro
 * logger beside it (the experiment `ev3sim balance` runs).
 *
 * Large motors on A (left) and D (right), gyro on port 2.  The main task
 * waits for the gyro, estimates its offset while the robot is held still,
 * then starts BALANCE_CYC: every 4 ms it releases the balance task, whose
 * control step reads the gyro rate and the wheel counts and sets the same
 * power on both motors with ev3_motor_set_power (a regulated speed on large
 * motors).  With gyroboy_params.logger_hz set, LOGGER_CYC wakes the logger
 * task that often to write "<ms>,<rate>,<tilt cdeg>" lines to the default
 * serial port; the app counts its deadline misses itself (get_utm).
 *
 * Control: state feedback on the body angle (the integrated, offset-corrected
 * rate), its rate, the wheel angle and the wheel rate.  The offset keeps being
 * tracked slowly: a balancing robot's mean body rate is zero, so a drifting
 * gyro bias is followed instead of being integrated into the angle.
 *
 * It stops when it falls over or when BACK is pressed.
 */
#include <stdio.h>
#include <string.h>
#include "ev3api.h"
#include "app.h"

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

struct gyroboy_params gyroboy_params = { true, 0, false };
struct gyroboy_stats gyroboy_stats;

static float gyro_offset;           /* deg/s */
static float tilt;                  /* body angle, deg */
static float wheel_history[WHEEL_RATE_WINDOW];
static int history_len, history_pos;
static bool_t fallen, stepping, released;
static SYSUTM first_release_us;
static uint32_t step_release;       /* the release the pending step answers (0 = the first) */
static uint32_t logger_phase;       /* logger rate accumulator, in Hz-milliseconds */
static FILE *serial;

/*
 * The timing of every API call while balancing, in every task: a call
 * longer than GYROBOY_BLOCKED_US (a sensor waiting for its data, a driver's lock)
 * can make the 4 ms control step late.  A call's start is kept in the
 * counters until it returns, so a launcher can see one that never does.
 */
static SYSUTM call_begin(unsigned task)
{
	SYSUTM t0;

	get_utm(&t0);
	gyroboy_stats.call_since_us[task] = t0;
	return t0;
}

/* The end of task's call begun at since: counts a failure (ercd) and a block. */
static void call_end(unsigned task, ER ercd, SYSUTM since)
{
	SYSUTM now;

	get_utm(&now);
	gyroboy_stats.call_since_us[task] = 0;
	if (ercd != E_OK)
		gyroboy_stats.api_errors++;
	if (now - since > GYROBOY_BLOCKED_US)
		gyroboy_stats.api_blocked++;
	if (now - since > gyroboy_stats.max_api_call_us)
		gyroboy_stats.max_api_call_us = (uint32_t)(now - since);
}

/* The gyro's rate, read by task. */
static int16_t gyro_rate(unsigned task)
{
	SYSUTM t0 = call_begin(task);
	int16_t rate = ev3_gyro_sensor_get_rate(GYRO);

	call_end(task, E_OK, t0);
	return rate;
}

/* A motor's counts, read by the balance task. */
static int32_t motor_counts(motor_port_t port)
{
	SYSUTM t0 = call_begin(GYROBOY_IN_BALANCE);
	int32_t counts = ev3_motor_get_counts(port);

	call_end(GYROBOY_IN_BALANCE, E_OK, t0);
	return counts;
}

/* A power for a motor, set by the balance task. */
static void set_power(motor_port_t port, int power)
{
	SYSUTM t0 = call_begin(GYROBOY_IN_BALANCE);
	ER ercd = ev3_motor_set_power(port, power);

	call_end(GYROBOY_IN_BALANCE, ercd, t0);
}

/* Whether BACK is pressed, asked by the main task. */
static bool_t back_pressed(void)
{
	SYSUTM t0 = call_begin(GYROBOY_IN_MAIN);
	bool_t pressed = ev3_button_is_pressed(BACK_BUTTON);

	call_end(GYROBOY_IN_MAIN, E_OK, t0);
	return pressed;
}

void main_task(intptr_t exinf)
{
	float sum = 0.0f;
	int i;

	/* a fresh start (a launcher may run the app again without reloading it) */
	memset(&gyroboy_stats, 0, sizeof(gyroboy_stats));
	fallen = stepping = released = false;
	tilt = 0.0f;
	history_len = history_pos = 0;
	logger_phase = 0;
	serial = NULL;
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
	gyroboy_stats.gyro_offset_dps = gyro_offset;
	ev3_motor_reset_counts(LEFT_MOTOR);
	ev3_motor_reset_counts(RIGHT_MOTOR);
	gyroboy_stats.calibrated = true;
	syslog(LOG_NOTICE, "gyroboy: gyro offset %d mdeg/s, balancing", (int)(gyro_offset * 1000.0f));

	if (gyroboy_params.logger_hz > 0 && gyroboy_params.logger_hz <= LOGGER_MAX_HZ &&
	    (serial = ev3_serial_open_file(EV3_SERIAL_DEFAULT)) != NULL) {
		act_tsk(LOGGER_TASK);
		/* after act_tsk: a dormant task's priority cannot be changed (E_OBJ) */
		if (gyroboy_params.logger_above)
			chg_pri(LOGGER_TASK, LOGGER_ABOVE_PRIORITY);
		ev3_sta_cyc(LOGGER_CYC);
	}
	ev3_led_set_color(LED_GREEN);
	if (gyroboy_params.balancer)
		ev3_sta_cyc(BALANCE_CYC);

	while (!fallen && !back_pressed())
		tslp_tsk(10);
	ev3_stp_cyc(BALANCE_CYC);
	ev3_stp_cyc(LOGGER_CYC);
	ev3_motor_stop(LEFT_MOTOR, false);
	ev3_motor_stop(RIGHT_MOTOR, false);
	ev3_led_set_color(LED_RED);
	if (fallen)
		syslog(LOG_NOTICE, "gyroboy: fell over");
}

/* Every 4 ms: releases the control step, counting a release while the last one is unfinished. */
void balance_cyc(intptr_t exinf)
{
	if (fallen)
		return;
	if (!released) {
		get_utm(&first_release_us);
		released = true;
	}
	gyroboy_stats.releases++;
	if (stepping) {
		gyroboy_stats.overlaps++;
		gyroboy_stats.deadline_misses++;
		return;
	}
	stepping = true;
	step_release = gyroboy_stats.releases - 1;
	act_tsk(BALANCE_TASK);
}

/* One control step. */
void balance_task(intptr_t exinf)
{
	const float dt = BALANCE_PERIOD_MS / 1000.0f;
	/* the nominal release of this step: the cyclic's period from the first one */
	SYSUTM release = first_release_us + step_release * BALANCE_PERIOD_MS * 1000U;
	SYSUTM start;
	float rate, wheel, wheel_rate, u;
	int power;

	get_utm(&start);
	if (start - release > gyroboy_stats.max_start_delay_us)
		gyroboy_stats.max_start_delay_us = start - release;
	if (start - release > START_BOUND_US) {
		gyroboy_stats.late_starts++;
		gyroboy_stats.deadline_misses++;
	}
	rate = gyro_rate(GYROBOY_IN_BALANCE);
	wheel = (motor_counts(LEFT_MOTOR) + motor_counts(RIGHT_MOTOR)) / 2.0f;

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
	set_power(LEFT_MOTOR, power);
	set_power(RIGHT_MOTOR, power);
	if (tilt > FALLEN_DEG || tilt < -FALLEN_DEG)
		fallen = true;
	gyroboy_stats.power = power;
	gyroboy_stats.tilt_est_deg = tilt;
	gyroboy_stats.gyro_offset_dps = gyro_offset;
	gyroboy_stats.runs++;
	stepping = false;
}

/* Every 1 ms: wakes the logger logger_hz times a second. */
void logger_cyc(intptr_t exinf)
{
	logger_phase += gyroboy_params.logger_hz;
	if (logger_phase < 1000U)
		return;
	logger_phase -= 1000U;
	if (wup_tsk(LOGGER_TASK) == E_QOVR)
		gyroboy_stats.logger_skipped++;
}

/* One line per wakeup: "<ms>,<rate deg/s>,<tilt estimate cdeg>\r\n". */
void logger_task(intptr_t exinf)
{
	SYSTIM now;
	int16_t rate;

	for (;;) {
		if (slp_tsk() != E_OK)
			continue;
		get_tim(&now);
		rate = gyro_rate(GYROBOY_IN_LOGGER);
		/* the serial port's own wait (a polled UART, ~1 ms a line) is the logger's CPU time, not a block */
		if (fprintf(serial, "%lu,%d,%ld\r\n", (unsigned long)now, rate,
			    (long)(gyroboy_stats.tilt_est_deg * 100.0f)) > 0 && fflush(serial) == 0)
			gyroboy_stats.logger_lines++;
	}
}
