/*
 * balance_run.c — one run of the balancing experiment (balance_run.h).
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "rtos_host.h"
#include <kernel_cfg.h>
#include "host_sim/scenario.h"
#include "host_sim/devices/ev3_brick.h"
#include "host_sim/devices/ev3_ui.h"
#include "uart_hack.h"
#include "ev3sim/apps.h"
#include "ev3sim/balance_run.h"
#include "ev3sim/brick_io.h"
#include "ev3sim/serial_log.h"
#include "../../examples/gyroboy/gyroboy.h"

#define LEFT_PORT   0U      /* A */
#define RIGHT_PORT  3U      /* D */
#define GYRO_PORT   1U      /* input port 2 */
#define CHUNK_NS    50000000ULL             /* run in 50 ms slices (progress, fall check) */
#define DRAIN_NS    40000000ULL             /* after BACK: the app stops, its tasks finish their work */
#define PI 3.14159265358979323846

/* The library's copy of examples/gyroboy (ev3sim/module.mk): its configuration,
 * settings and counters under ev3sim's names. */
extern const struct rtos_cfg ev3sim_gyroboy_cfg;
extern struct gyroboy_params ev3sim_gyroboy_params;
extern struct gyroboy_stats ev3sim_gyroboy_stats;

/*
 * The harness's own kernel-domain task: once d_uart is loaded it maps the
 * driver's shared memory, so the summary can give the gyro port's link
 * counters (what the app cannot see through EV3RT's API).
 */
#define LINK_WATCH_TSKID  (TNUM_TSKID - EV3LX_LIB_NUM_TSKID)
#define LINK_WATCH_TRIES  200

static const struct lms_uart_shm *uart_link;

static void link_watch_task(intptr_t exinf)
{
	const struct lms_uart_shm *map = NULL;   /* on the task's stack */

	(void)exinf;
	for (int i = 0; i < LINK_WATCH_TRIES && uart_svc_map(&map) != E_OK; i++)
		(void)dly_tsk(10);
	uart_link = map;
}

static const struct rtos_task_cfg harness_tasks[] = {
	{ LINK_WATCH_TSKID, TA_ACT, 0, link_watch_task, TMIN_TPRI, 16 * 1024, TDOM_KERNEL, "ev3sim link watch" },
};
static const struct rtos_cfg *const harness_includes[] = { &ev3sim_gyroboy_cfg, &brick_io_cfg, NULL };
static const struct rtos_cfg harness_cfg = {
	.name = "ev3sim_balance",
	.tasks = RTOS_TABLE(harness_tasks),
	.includes = harness_includes,
};

/* The app's counters and the gyro link's, as the summary reports them. */
static struct ev3sim_balance_stats app_stats(void)
{
	const struct gyroboy_stats *a = &ev3sim_gyroboy_stats;
	struct ev3sim_balance_stats s = {
		.calibrated = a->calibrated, .gyro_offset_dps = a->gyro_offset_dps,
		.tilt_est_deg = a->tilt_est_deg, .power = a->power, .releases = a->releases, .runs = a->runs,
		.deadline_misses = a->deadline_misses, .overlaps = a->overlaps, .late_starts = a->late_starts,
		.max_start_delay_ns = (uint64_t)a->max_start_delay_us * 1000U, .api_errors = a->api_errors,
		.api_blocked = a->api_blocked, .max_api_call_us = a->max_api_call_us, .logger_lines = a->logger_lines, .logger_skipped = a->logger_skipped,
	};

	/* a call still waiting when the run ends is a blocked call too (it may never return) */
	for (unsigned t = 0; t < GYROBOY_TASKS; t++) {
		uint64_t waited = a->call_since_us[t] ? rtos_host_now() / 1000U - a->call_since_us[t] : 0;

		if (waited > GYROBOY_BLOCKED_US)
			s.api_blocked++;
		if (waited > s.max_api_call_us)
			s.max_api_call_us = waited > UINT32_MAX ? UINT32_MAX : (uint32_t)waited;
	}
	if (uart_link) {
		const struct lms_uart_port_ext *x = &uart_link->ext.port[GYRO_PORT];

		s.gyro_frames = x->frames;
		s.gyro_check_errors = x->check_errors;
		s.gyro_size_errors = x->size_errors;
		s.gyro_resyncs = x->resyncs;
		s.gyro_reconnects = x->reconnects;
	}
	return s;
}

static struct recorder {
	struct ev3sim_balance_result *res;
	FILE *out;
	double sum_sq;
	uint64_t samples;
	double wheel0;
	bool released;
} rec;

/* Observer of every physics step: statistics and the series after the release. */
static void observe(const struct ev3sim_robot_sample *s, void *ctx)
{
	struct ev3sim_balance_result *res = rec.res;
	const struct gyroboy_stats *app = &ev3sim_gyroboy_stats;
	double travel;

	(void)ctx;
	if (s->held)
		return;
	if (!rec.released) {
		rec.released = true;
		rec.wheel0 = s->wheel_deg;
	}
	if (fabs(s->tilt_deg) > res->max_tilt_deg)
		res->max_tilt_deg = fabs(s->tilt_deg);
	rec.sum_sq += s->tilt_deg * s->tilt_deg;
	rec.samples++;
	travel = fabs(s->wheel_deg - rec.wheel0) * PI / 180.0 * ev3sim_gyro_boy.wheel_radius_m * 100.0;
	if (travel > res->max_travel_cm)
		res->max_travel_cm = travel;
	if (rec.out)	/* streamed: an hour at 1 kHz is 3.6 million rows, never held in memory */
		fprintf(rec.out, "%.3f,%.4f,%.3f,%.3f,%.4f,%d,%.2f,%.2f\n",
			((double)s->t_ns - (double)EV3SIM_RELEASE_NS) * 1e-9, s->tilt_deg, s->tilt_rate_dps,
			s->wheel_deg - rec.wheel0, app->tilt_est_deg, app->power, s->duty_a * 100.0,
			s->duty_d * 100.0);
}

/* Draws the progress bar on stderr. */
static void draw_progress(double done_s, double total_s, double speed)
{
	int width = 30, filled = total_s > 0 ? (int)(width * done_s / total_s) : width;

	if (filled > width)
		filled = width;
	fprintf(stderr, "\r[%.*s%*s] %6.1f/%.1f s virtual, %.0fx ", filled,
		"##############################", width - filled, "", done_s, total_s, speed);
	fflush(stderr);
}

/* Plugs in the robot's devices and schedules the faults. */
static ER plug_in(const struct ev3sim_balance_opts *o, char *err, size_t errlen)
{
	struct uart_sensor_options gyro = { .name = "in2.gyro" };
	ER ercd;

	gyro.gyro_noise_dps = o->gyro_noise_dps;
	for (unsigned i = 0; i < o->nfaults; i++) {
		if (o->faults[i].target == EV3SIM_FAULT_GYRO_NOISE)
			gyro.gyro_noise_dps = o->faults[i].value;
		else if (o->faults[i].target == EV3SIM_FAULT_GYRO_DRIFT)
			gyro.gyro_drift_dps = o->faults[i].value;
	}
	ercd = ev3_attach_motor(LEFT_PORT, HS_MOTOR_LARGE, NULL);
	if (ercd == E_OK)
		ercd = ev3_attach_motor(RIGHT_PORT, HS_MOTOR_LARGE, NULL);
	if (ercd == E_OK)
		ercd = ev3_attach_uart_sensor(GYRO_PORT, UART_SENSOR_TYPE_GYRO, &gyro);
	if (ercd != E_OK) {
		snprintf(err, errlen, "cannot attach the robot's devices (%d)", (int)ercd);
		return E_SYS;
	}
	if (ev3sim_fault_check_wheels(o->faults, o->nfaults, LEFT_PORT, RIGHT_PORT, err, errlen) != E_OK)
		return E_PAR;
	for (unsigned i = 0; i < o->nfaults; i++) {
		if (o->faults[i].target != EV3SIM_FAULT_BRICK)
			continue;
		ercd = ev3_fault_at(EV3SIM_RELEASE_NS + o->faults[i].at_ns, &o->faults[i].fault);
		if (ercd != E_OK) {
			snprintf(err, errlen, "fault %u rejected by host_sim (%d)", i + 1, (int)ercd);
			return E_PAR;
		}
	}
	return E_OK;
}

ER ev3sim_balance_run(const struct ev3sim_balance_opts *o, struct ev3sim_balance_result *res,
		      char *err, size_t errlen)
{
	static const struct hs_board_cfg board = { .devices = ev3_board_devices };
	struct ev3sim_push pushes[EV3SIM_MAX_PUSHES];
	struct hs_scenario scn = { .rtos = &harness_cfg, .board = &board };
	struct ev3sim_robot_cfg robot = {
		.left_port = LEFT_PORT, .right_port = RIGHT_PORT, .gyro_port = GYRO_PORT,
		.release_ns = EV3SIM_RELEASE_NS, .pushes = pushes, .observer = observe,
	};
	const struct serial_log_stats *log;
	uint64_t end, fell_ns;
	double wall0, speed = 0.0;
	bool progress_shown = false, tty;
	ER ercd;

	memset(res, 0, sizeof(*res));
	if (!(o->seconds > 0 && o->seconds <= EV3SIM_MAX_SECONDS) || o->npushes > EV3SIM_MAX_PUSHES ||
	    o->nfaults > EV3SIM_MAX_FAULTS || fabs(o->start_tilt_deg) >= 45.0 || !(o->gyro_noise_dps >= 0)) {
		snprintf(err, errlen, "bad run options");
		return E_PAR;
	}
	if (o->app.logger_hz > EV3SIM_LOGGER_MAX_HZ) {
		snprintf(err, errlen, "logger rate must be 0..%u Hz", EV3SIM_LOGGER_MAX_HZ);
		return E_PAR;
	}
	ev3sim_gyroboy_params = (struct gyroboy_params){
		.balancer = o->app.balancer, .logger_hz = o->app.logger_hz, .logger_above = o->app.logger_above,
	};
	uart_link = NULL;
	if (serial_log_setup(o->log_baud ? o->log_baud : SERIAL_LOG_DEFAULT_BAUD, o->log_out) != E_OK) {
		snprintf(err, errlen, "bad serial log baud");
		return E_PAR;
	}
	for (unsigned i = 0; i < o->npushes; i++) {
		pushes[i] = o->pushes[i];
		pushes[i].t_ns += EV3SIM_RELEASE_NS;
	}
	robot.npushes = o->npushes;
	robot.start_tilt_deg = o->start_tilt_deg;
	rec = (struct recorder){ .res = res, .out = o->series_out };
	if (rec.out)
		fputs(EV3SIM_SERIES_HEADER, rec.out);
	res->seconds = o->seconds;
	scn.seed = o->seed;
	scn.vcd_path = o->trace_path;

	wall0 = ev3sim_wall_seconds();
	if (brick_io_setup(NULL, NULL, err, errlen) != E_OK)
		return E_SYS;
	brick_io_serial_to_uart();
	if (hs_sim_boot(&scn) != E_OK) {
		snprintf(err, errlen, "boot failed: %s", rtos_host_boot_error());
		return E_SYS;
	}
	ercd = plug_in(o, err, errlen);
	if (ercd == E_OK && ev3sim_robot_start(&robot) != E_OK) {
		snprintf(err, errlen, "the robot's physics could not start");
		ercd = E_SYS;
	}
	if (ercd != E_OK) {
		hs_sim_shutdown();
		brick_io_teardown();
		return ercd;
	}
	end = EV3SIM_RELEASE_NS + (uint64_t)llround(o->seconds * 1e9);
	tty = o->progress && isatty(STDERR_FILENO);
	while (rtos_host_now() < end && !ev3sim_robot_fallen(NULL) && !rtos_host_exited()) {
		uint64_t next = rtos_host_now() + CHUNK_NS;

		hs_sim_run_until(next < end ? next : end);
		if (tty) {
			double wall = ev3sim_wall_seconds() - wall0;

			speed = wall > 0 ? rtos_host_now() * 1e-9 / wall : 0.0;
			if (wall > 1.0 || progress_shown) {
				draw_progress(rtos_host_now() * 1e-9, end * 1e-9, speed);
				progress_shown = true;
			}
		}
	}
	if (progress_shown)
		fprintf(stderr, "\r%79s\r", "");
	ev3sim_robot_stop();
	res->fell = ev3sim_robot_fallen(&fell_ns);
	res->fell_at_s = res->fell ? ((double)fell_ns - (double)EV3SIM_RELEASE_NS) * 1e-9 : 0.0;
	res->rms_tilt_deg = rec.samples ? sqrt(rec.sum_sq / (double)rec.samples) : 0.0;
	res->wall_s = ev3sim_wall_seconds() - wall0;
	res->sim_virtual_s = rtos_host_now() * 1e-9;
	/* BACK ends the app: it stops its cyclic handlers and the motors, its tasks finish
	 * their work (the logger its last line) before the summary's counts are taken and
	 * the drivers unload */
	(void)ev3_ui_button_set(EV3_UI_BUTTON_BACK, true);
	hs_sim_run_for(DRAIN_NS);
	res->app = app_stats();
	log = serial_log_get_stats();
	res->log_bytes = log->bytes;
	res->log_spin_ms = log->spin_ns / 1000000U;
	res->bugs = rtos_host_bug_count();
	res->trace_failed = hs_sim_shutdown() != E_OK;
	brick_io_teardown();
	return E_OK;
}

void ev3sim_balance_summary(const struct ev3sim_balance_opts *o,
			    const struct ev3sim_balance_result *r, char *buf, size_t len)
{
	char fell_at[32] = "none";

	if (r->fell)
		snprintf(fell_at, sizeof(fell_at), "%.3f", r->fell_at_s);
	snprintf(buf, len,
		 "result=%s seconds=%g seed=%llu balancer=%s logger_hz=%u logger_prio=%s "
		 "fell_at_s=%s max_tilt_deg=%.2f rms_tilt_deg=%.3f max_travel_cm=%.1f "
		 "deadline_misses=%u balance_runs=%u max_start_delay_us=%llu "
		 "logger_lines=%u logger_skipped=%u log_bytes=%llu logger_spin_ms=%llu "
		 "gyro_frames=%u gyro_check_errors=%u gyro_size_errors=%u gyro_resyncs=%u "
		 "gyro_reconnects=%u api_errors=%u api_blocked=%u max_api_call_us=%u bugs=%u sim_speed=%.0fx",
		 r->fell ? "fell" : "upright", r->seconds, (unsigned long long)o->seed,
		 o->app.balancer ? "on" : "off", o->app.logger_hz,
		 o->app.logger_above ? "above" : "below", fell_at, r->max_tilt_deg, r->rms_tilt_deg,
		 r->max_travel_cm, r->app.deadline_misses, r->app.runs,
		 (unsigned long long)(r->app.max_start_delay_ns / 1000U), r->app.logger_lines,
		 r->app.logger_skipped, (unsigned long long)r->log_bytes,
		 (unsigned long long)r->log_spin_ms, r->app.gyro_frames, r->app.gyro_check_errors,
		 r->app.gyro_size_errors, r->app.gyro_resyncs, r->app.gyro_reconnects,
		 r->app.api_errors, r->app.api_blocked, r->app.max_api_call_us, r->bugs,
		 r->wall_s > 0 ? r->sim_virtual_s / r->wall_s : 0.0);
}
