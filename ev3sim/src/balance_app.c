/*
 * balance_app.c — the self-balancing robot's application (balance_app.h).
 *
 * Controller: full state feedback on the body angle psi, its rate, the wheel
 * angle theta = phi + psi (phi: the motors' count, relative to the body) and
 * its rate, in degrees and degrees per second, giving the power in percent.
 * The gains are a discrete LQR design for the ev3sim robot model at the 4 ms
 * period (docs/ev3sim.md); the loop keeps its margin with several periods of
 * extra delay.  The gyro offset is estimated while the robot is held and
 * then tracked slowly (LEGO's gyro boy does the same): over seconds the body
 * rate of a balancing robot averages zero, so a drifting sensor bias is
 * followed instead of being integrated into the angle.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "ev3api.h"
#include "uart_hack.h"
#include "rtos_host.h"
#include "ev3sim/apps.h"
#include "ev3sim/balance_app.h"
#include "ev3sim/serial_log.h"

#define MAIN_TSKID     1
#define BALANCE_TSKID  2
#define LOGGER_TSKID   3
#define BALANCE_CYCID  1
#define LOGGER_CYCID   2
#define APP_DOMAIN     1
#define APP_STACK      (16 * 1024)

#define LEFT_MOTOR     EV3_PORT_A
#define RIGHT_MOTOR    EV3_PORT_D
#define GYRO_PORT      EV3_PORT_2

/* State feedback gains: power % per degree and per degree/s. */
#define K_TILT         9.8
#define K_TILT_RATE    1.08
#define K_WHEEL        0.076
#define K_WHEEL_RATE   0.21

#define CALIBRATION_SAMPLES  100
#define CALIBRATION_GAP_MS   5
#define OFFSET_TRACKING      0.0005      /* per period: a time constant of 8 s */
#define WHEEL_RATE_WINDOW    5           /* periods the wheel rate is averaged over */

/* Virtual CPU time of the application's own computation on the 300 MHz
 * ARM926 (no FPU: soft-float): a control step and formatting a log line. */
#define BALANCE_COMPUTE_NS   30000ULL
/* An API call of the balance task that takes longer than this waited somewhere (a fast call
 * costs a few microseconds of CPU time). */
#define BLOCKED_NS           200000ULL
#define LOG_FORMAT_NS        20000ULL

static struct ev3sim_balance_cfg app_cfg = { true, 1000, false };
static struct ev3sim_balance_stats stats;
static const struct lms_uart_shm *uart_link;   /* d_uart's shared memory, for its counters */

/* Balance task state (only the balance task and the main task before the
 * cyclic starts touch it). */
static struct {
	double offset;              /* gyro offset, deg/s */
	double tilt;                /* body angle estimate, deg */
	double tilt_rate;
	double phi_history[WHEEL_RATE_WINDOW];
	unsigned history_len, history_pos;
	bool running;               /* an activation is in progress */
	bool pending;               /* released, not started yet */
	uint64_t release_ns;
	unsigned logger_phase;      /* logger rate accumulator, in Hz-milliseconds */
	bool stopping;              /* ev3sim_balance_stop: release nothing more */
} bal;

/* Charges the application's computation as CPU time of the calling task. */
static void spend_cpu(uint64_t ns)
{
	rtos_host_consume(ns);
}

static ER check(ER ercd)
{
	if (ercd != E_OK)
		stats.api_errors++;
	return ercd;
}

/* check() for a call of the balance task started at virtual time t0: a call that took longer
 * than BLOCKED_NS waited (in a driver, or for the sensor) and is counted as blocked. */
static ER check_since(ER ercd, uint64_t t0)
{
	if (rtos_host_now() - t0 > BLOCKED_NS)
		stats.api_blocked++;
	return check(ercd);
}

/* Cyclic handler: releases the balance task, counting overlaps. */
static void balance_cyclic(intptr_t exinf)
{
	(void)exinf;
	if (bal.stopping)
		return;
	stats.releases++;
	if (bal.running || bal.pending) {
		stats.overlaps++;
		stats.deadline_misses++;
	}
	bal.release_ns = rtos_host_now();
	bal.pending = true;
	(void)iact_tsk(BALANCE_TSKID);
}

/* Cyclic handler (1 ms): wakes the logger logger_hz times per second. */
static void logger_cyclic(intptr_t exinf)
{
	(void)exinf;
	if (bal.stopping)
		return;
	bal.logger_phase += app_cfg.logger_hz;
	if (bal.logger_phase < 1000U)
		return;
	bal.logger_phase -= 1000U;
	if (iwup_tsk(LOGGER_TSKID) == E_QOVR)
		stats.logger_skipped++;
}

/* One control step. */
static void balance_task(intptr_t exinf)
{
	const double dt = EV3SIM_BALANCE_PERIOD_MS / 1000.0;
	uint64_t delay = rtos_host_now() - bal.release_ns;
	int16_t rate = 0;
	int32_t count_l = 0, count_r = 0;
	uint64_t t0;
	double phi, phi_rate, u;
	int power;

	(void)exinf;
	bal.pending = false;
	bal.running = true;
	if (delay > stats.max_start_delay_ns)
		stats.max_start_delay_ns = delay;
	if (delay > EV3SIM_START_BOUND_NS) {
		stats.late_starts++;
		stats.deadline_misses++;
	}
	t0 = rtos_host_now();
	check_since(ev3lx_gyro_sensor_get_rate(GYRO_PORT, &rate), t0);
	t0 = rtos_host_now();
	check_since(ev3lx_motor_get_counts(LEFT_MOTOR, &count_l), t0);
	t0 = rtos_host_now();
	check_since(ev3lx_motor_get_counts(RIGHT_MOTOR, &count_r), t0);

	bal.offset += OFFSET_TRACKING * (rate - bal.offset);
	bal.tilt_rate = rate - bal.offset;
	bal.tilt += bal.tilt_rate * dt;
	phi = (count_l + count_r) / 2.0;
	if (bal.history_len < WHEEL_RATE_WINDOW) {
		phi_rate = bal.history_len ? (phi - bal.phi_history[0]) / (bal.history_len * dt) : 0.0;
		bal.phi_history[bal.history_len++] = phi;
	} else {
		phi_rate = (phi - bal.phi_history[bal.history_pos]) / (WHEEL_RATE_WINDOW * dt);
		bal.phi_history[bal.history_pos] = phi;
		bal.history_pos = (bal.history_pos + 1) % WHEEL_RATE_WINDOW;
	}
	u = K_TILT * bal.tilt + K_TILT_RATE * bal.tilt_rate +
	    K_WHEEL * (phi + bal.tilt) + K_WHEEL_RATE * (phi_rate + bal.tilt_rate);
	power = (int)lround(u > 100.0 ? 100.0 : u < -100.0 ? -100.0 : u);
	spend_cpu(BALANCE_COMPUTE_NS);
	t0 = rtos_host_now();
	check_since(ev3lx_motor_set_power(LEFT_MOTOR, power), t0);
	t0 = rtos_host_now();
	check_since(ev3lx_motor_set_power(RIGHT_MOTOR, power), t0);

	stats.power = power;
	stats.tilt_est_deg = bal.tilt;
	stats.gyro_offset_dps = bal.offset;
	stats.runs++;
	bal.running = false;
}

/* Logger: one line per wakeup, "<ms>,<rate deg/s>,<tilt estimate cdeg>\r\n". */
static void logger_task(intptr_t exinf)
{
	(void)exinf;
	for (;;) {
		char line[48];
		int16_t rate = 0;
		int len;

		if (slp_tsk() != E_OK)
			continue;
		(void)ev3lx_gyro_sensor_get_rate(GYRO_PORT, &rate);
		len = snprintf(line, sizeof(line), "%lu,%d,%ld\r\n",
			       (unsigned long)(rtos_host_now() / 1000000U), rate,
			       lround(stats.tilt_est_deg * 100.0));
		spend_cpu(LOG_FORMAT_NS);
		if (serial_log_write(line, (uint_t)len) == len)
			stats.logger_lines++;
	}
}

/* Main task: set up, calibrate while held, start the loops. */
static void main_task(intptr_t exinf)
{
	const struct lms_uart_shm *map = NULL;   /* on the task's stack: the domain's memory */
	int16_t rate = 0;
	double sum = 0.0;

	(void)exinf;
	check(ev3lx_motor_config(LEFT_MOTOR, LARGE_MOTOR));
	check(ev3lx_motor_config(RIGHT_MOTOR, LARGE_MOTOR));
	check(ev3lx_sensor_config(GYRO_PORT, GYRO_SENSOR));
	if (check(uart_svc_map(&map)) == E_OK)
		uart_link = map;
	/* the first read waits for the gyro's handshake */
	if (check(ev3lx_gyro_sensor_get_rate(GYRO_PORT, &rate)) != E_OK)
		return;
	for (int i = 0; i < CALIBRATION_SAMPLES; i++) {
		dly_tsk(CALIBRATION_GAP_MS);
		check(ev3lx_gyro_sensor_get_rate(GYRO_PORT, &rate));
		sum += rate;
	}
	bal.offset = sum / CALIBRATION_SAMPLES;
	stats.gyro_offset_dps = bal.offset;
	check(ev3lx_motor_reset_counts(LEFT_MOTOR));
	check(ev3lx_motor_reset_counts(RIGHT_MOTOR));
	stats.calibrated = true;
	stats.calibrated_ns = rtos_host_now();
	if (app_cfg.logger_hz > 0) {
		check(act_tsk(LOGGER_TSKID));
		check(sta_cyc(LOGGER_CYCID));
	}
	if (app_cfg.balancer)
		check(sta_cyc(BALANCE_CYCID));
}

static struct rtos_task_cfg app_tasks[] = {
	{ MAIN_TSKID, TA_ACT, 0, main_task, EV3SIM_MAIN_PRIORITY, APP_STACK, APP_DOMAIN, "main" },
	{ BALANCE_TSKID, TA_NULL, 0, balance_task, EV3SIM_BALANCE_PRIORITY, APP_STACK, APP_DOMAIN,
	  "balance" },
	{ LOGGER_TSKID, TA_NULL, 0, logger_task, EV3SIM_LOGGER_PRIORITY, APP_STACK, APP_DOMAIN,
	  "logger" },
};

static const struct rtos_cyc_cfg app_cycs[] = {
	{ BALANCE_CYCID, TA_NULL, 0, balance_cyclic, EV3SIM_BALANCE_PERIOD_MS, 0, "balance" },
	{ LOGGER_CYCID, TA_NULL, 0, logger_cyclic, 1, 0, "logger" },
};

/* ATT_INI: the application's state starts empty at every boot. */
static void app_boot(intptr_t exinf)
{
	(void)exinf;
	ev3sim_quiet_console();
	memset(&stats, 0, sizeof(stats));
	memset(&bal, 0, sizeof(bal));
	uart_link = NULL;
}

static const struct rtos_ini_cfg app_inis[] = { { app_boot, 0 } };

static const struct rtos_cfg *const app_includes[] = { &ev3api_cfg, &serial_log_cfg, NULL };

const struct rtos_cfg ev3sim_balance_app_cfg = {
	.name = "ev3sim_balance",
	.tasks = RTOS_TABLE(app_tasks),
	.cycs = RTOS_TABLE(app_cycs),
	.inis = RTOS_TABLE(app_inis),
	.includes = app_includes,
};

ER ev3sim_balance_setup(const struct ev3sim_balance_cfg *cfg)
{
	if (cfg == NULL || cfg->logger_hz > EV3SIM_LOGGER_MAX_HZ)
		return E_PAR;
	app_cfg = *cfg;
	app_tasks[2].itskpri = cfg->logger_above ? EV3SIM_LOGGER_ABOVE_PRIORITY : EV3SIM_LOGGER_PRIORITY;
	return E_OK;
}

void ev3sim_balance_stop(void)
{
	bal.stopping = true;
}

const struct ev3sim_balance_stats *ev3sim_balance_stats(void)
{
	if (uart_link) {
		const struct lms_uart_port_ext *x = &uart_link->ext.port[GYRO_PORT];

		stats.gyro_frames = x->frames;
		stats.gyro_check_errors = x->check_errors;
		stats.gyro_size_errors = x->size_errors;
		stats.gyro_resyncs = x->resyncs;
		stats.gyro_reconnects = x->reconnects;
	}
	return &stats;
}
