/*
 * run.c — an EV3RT-style application in a robot and its world (run.h).
 */
#define _POSIX_C_SOURCE 200809L
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "rtos_host.h"
#include <kernel_cfg.h>
#include "host_sim/scenario.h"
#include "host_sim/devices/ev3_brick.h"
#include "host_sim/devices/ev3_lcd.h"
#include "host_sim/devices/ev3_ui.h"
#include "host_sim/devices/uart_sensor.h"
#include "ev3sim/brick_io.h"
#include "ev3sim/balance_run.h"
#include "ev3sim/live.h"
#include "ev3sim/run.h"
#include "ev3sim/tribot.h"
#include "ev3sim/world.h"
#include "ev3sim/world_plot.h"
#include "ev3sim/wav_out.h"

ER (*ev3sim_lcd_png_writer)(const char *path);
const struct ev3sim_lcd_video *ev3sim_lcd_video;

#define CHUNK_NS        10000000ULL     /* run in 10 ms slices: the CSV's row period */
#define DRAIN_NS        20000000ULL
#define TOUCH_PRESS_NS  3000000000ULL
#define TOUCH_HOLD_NS   300000000ULL

static const char *const robot_names[] = { "bare", "gyroboy", "tribot" };

/* LEGO's button numbering in host_sim of each EV3RT button_t. */
static const enum ev3_ui_button ui_button_of[] = {
	EV3_UI_BUTTON_LEFT, EV3_UI_BUTTON_RIGHT, EV3_UI_BUTTON_UP,
	EV3_UI_BUTTON_DOWN, EV3_UI_BUTTON_ENTER, EV3_UI_BUTTON_BACK,
};

/*
 * The app's writable memory as loaded (the regions of its ATT_MOD modules):
 * copied before its first boot and put back before every later one, as a
 * power-on loads the app afresh — so runs in one process do not share the
 * app's statics.
 */
static struct {
	const struct rtos_cfg *app;
	unsigned n;
	struct image_region { void *base, *copy; SIZE size; } *region;   /* one per writable region */
} image;

/*
 * Before the brick powers down, the app ends as EV3RT's loader ends one: its
 * cyclic handlers stop and its tasks are terminated (ter_tsk), by a task of
 * the highest priority in the kernel domain.  Only then do the drivers unload
 * (ATT_TER), so no app task still polls their shared memory.  Its ID is the
 * first below those the library takes at the top of the range (cfg/ev3lx.cfg).
 */
#define POWER_OFF_TSKID  (TNUM_TSKID - EV3LX_LIB_NUM_TSKID)
#define POWER_OFF_STACK  (16 * 1024)

static void power_off_task(intptr_t exinf);

static const struct rtos_task_cfg power_off_tasks[] = {
	{ POWER_OFF_TSKID, TA_NULL, 0, power_off_task, TMIN_TPRI, POWER_OFF_STACK, TDOM_KERNEL,
	  "ev3sim power-off" },
};
/* The run's configuration: the power-off task, the app and the SD card and
 * serial port (brick_io.h). */
static const struct rtos_cfg *run_includes[3] = { NULL, &brick_io_cfg, NULL };
static const struct rtos_cfg run_cfg = {
	.name = "ev3sim_run",
	.tasks = RTOS_TABLE(power_off_tasks),
	.includes = run_includes,
};

static struct {
	const struct ev3sim_run_opts *o;
	struct ev3sim_run_result *r;
	double sum_sq_error;
	uint64_t samples, on_line;
} run;

const char *ev3sim_robot_name(enum ev3sim_robot_kind k)
{
	return (unsigned)k < sizeof(robot_names) / sizeof(robot_names[0]) ? robot_names[k] : "?";
}

bool ev3sim_robot_parse(const char *s, enum ev3sim_robot_kind *k)
{
	for (unsigned i = 0; i < sizeof(robot_names) / sizeof(robot_names[0]); i++)
		if (strcmp(s, robot_names[i]) == 0) {
			*k = (enum ev3sim_robot_kind)i;
			return true;
		}
	return false;
}

void ev3sim_run_defaults(struct ev3sim_run_opts *o, enum ev3sim_robot_kind robot)
{
	memset(o, 0, sizeof(*o));
	o->robot = robot;
	o->seconds = 10.0;
	o->seed = 1;
	/* the hand lets go when the app starts driving the wheels: a balancer
	 * that calibrates first (EV3RT's gyroboy sample) is let go when ready */
	o->release_ns = 0;
	o->release_on_drive = true;
	o->pace = 1.0;
	switch (robot) {
	case EV3SIM_ROBOT_GYROBOY:
		o->out[0] = EV3SIM_OUT_LARGE;
		o->out[3] = EV3SIM_OUT_LARGE;
		o->in[1] = EV3SIM_IN_GYRO;
		o->start_tilt_deg = 0.5;
		o->gyro_noise_dps = UART_SENSOR_GYRO_NOISE_AT_REST_DPS;
		break;
	case EV3SIM_ROBOT_TRIBOT:
		o->out[1] = EV3SIM_OUT_LARGE;
		o->out[2] = EV3SIM_OUT_LARGE;
		o->in[0] = EV3SIM_IN_TOUCH;
		o->in[2] = EV3SIM_IN_COLOR;
		o->in[3] = EV3SIM_IN_ULTRASONIC;
		o->actions[0] = (struct ev3sim_action){ .touch = true, .t_ns = TOUCH_PRESS_NS,
							.hold_ns = TOUCH_HOLD_NS };
		o->nactions = 1;
		break;
	default:
		break;
	}
}

void ev3sim_run_defaults_world(struct ev3sim_run_opts *o, const struct ev3sim_world *w)
{
	ev3sim_run_defaults(o, EV3SIM_ROBOT_BARE);
	o->world = w;
	o->out[w->robot.left_port] = w->robot.motor;
	o->out[w->robot.right_port] = w->robot.motor;
	for (unsigned k = 0; k < w->robot.nmounts; k++) {
		o->in[w->robot.mounts[k].port] = w->robot.mounts[k].device;
		if (w->robot.mounts[k].device == EV3SIM_IN_GYRO)
			o->gyro_noise_dps = UART_SENSOR_GYRO_NOISE_AT_REST_DPS;
	}
}

/*
 * Copies n bytes of an app region.  A region is the app's whole data or bss
 * section, so under ASan it holds the redzones between the app's objects too:
 * copied byte by byte outside ASan's checks (memcpy would be intercepted).
 */
__attribute__((no_sanitize_address))
static void copy_region(void *dst, const void *src, size_t n)
{
	volatile uint8_t *d = dst;
	const volatile uint8_t *s = src;

	while (n--)
		*d++ = *s++;
}

/* Copies the app's writable regions at its first run, restores them at later ones. */
static ER load_image(const struct rtos_cfg *app)
{
	if (image.app == app) {
		for (unsigned i = 0; i < image.n; i++)
			copy_region(image.region[i].base, image.region[i].copy, image.region[i].size);
		return E_OK;
	}
	for (unsigned i = 0; i < image.n; i++)
		free(image.region[i].copy);
	free(image.region);
	memset(&image, 0, sizeof(image));
	/* at most one region per memory object: an app attaches as many modules as it likes */
	if (app->nmems > 0 && (image.region = calloc(app->nmems, sizeof(*image.region))) == NULL)
		return E_NOMEM;
	for (uint_t i = 0; i < app->nmems; i++) {
		const struct rtos_mem_cfg *m = &app->mems[i];

		if (!(m->access & TPM_WRITE) || m->size == 0)
			continue;
		image.region[image.n].base = (void *)(uintptr_t)m->base;
		image.region[image.n].size = m->size;
		image.region[image.n].copy = malloc(m->size);
		if (image.region[image.n].copy == NULL)
			return E_NOMEM;
		copy_region(image.region[image.n].copy, m->base, m->size);
		image.n++;
	}
	image.app = app;
	return E_OK;
}

/* Stops the app's cyclic handlers and terminates its tasks. */
static void power_off_task(intptr_t exinf)
{
	const struct rtos_cfg *app = run_includes[0];

	(void)exinf;
	for (uint_t i = 0; i < app->ncycs; i++)
		(void)stp_cyc(app->cycs[i].cycid);
	for (uint_t i = 0; i < app->ntasks; i++)
		(void)ter_tsk(app->tasks[i].tskid);     /* E_OBJ for a dormant one */
}

/* Syslog lines of the run: counted and handed to the sink. */
static void trace_sink(const char *line, void *ctx)
{
	const char *text = strstr(line, " syslog ");

	(void)ctx;
	if (text == NULL)
		return;
	text += strlen(" syslog ");
	run.r->log_lines++;
	if (strncmp(text, "WARNING:", 8) == 0)
		run.r->warnings++;
	else if (strncmp(text, "ERROR:", 6) == 0 || strncmp(text, "CRIT:", 5) == 0 ||
		 strncmp(text, "ALERT:", 6) == 0 || strncmp(text, "EMERG:", 6) == 0)
		run.r->errors++;
	if (run.o->log_sink)
		run.o->log_sink(text, run.o->log_ctx);
}

/* The gyro's noise and drift from the faults. */
static void gyro_options(const struct ev3sim_run_opts *o, struct uart_sensor_options *gyro)
{
	gyro->gyro_noise_dps = o->gyro_noise_dps;
	for (unsigned i = 0; i < o->nfaults; i++) {
		if (o->faults[i].target == EV3SIM_FAULT_GYRO_NOISE)
			gyro->gyro_noise_dps = o->faults[i].value;
		else if (o->faults[i].target == EV3SIM_FAULT_GYRO_DRIFT)
			gyro->gyro_drift_dps = o->faults[i].value;
	}
}

/* Plugs in the devices with a neutral scene (the world sets what it drives). */
static ER plug_in(const struct ev3sim_run_opts *o)
{
	static const struct uart_sensor_scene scene = {
		.reflect_pct = EV3SIM_MAT_WHITE_PCT, .ambient_pct = 10, .color = 6,
		.rgb = { 420, 420, 420 }, .distance_mm = 1000,
		.beacon_distance = { -128, -128, -128, -128 },
	};
	static const uint8_t uart_type[EV3SIM_IN_COUNT] = {
		[EV3SIM_IN_GYRO] = UART_SENSOR_TYPE_GYRO, [EV3SIM_IN_COLOR] = UART_SENSOR_TYPE_COLOR,
		[EV3SIM_IN_ULTRASONIC] = UART_SENSOR_TYPE_ULTRASONIC, [EV3SIM_IN_IR] = UART_SENSOR_TYPE_IR,
	};
	ER ercd = E_OK;

	for (unsigned p = 0; p < 4 && ercd == E_OK; p++) {
		struct uart_sensor_options uopt = { .name = NULL };

		switch (o->in[p]) {
		case EV3SIM_IN_NONE:
			break;
		case EV3SIM_IN_TOUCH:
			ercd = ev3_attach_analog(p, EV3_INPUT_EV3_TOUCH, NULL);
			break;
		case EV3SIM_IN_NXT_TOUCH:
			ercd = ev3_attach_analog(p, EV3_INPUT_NXT_TOUCH, NULL);
			break;
		case EV3SIM_IN_NXT_LIGHT:
			ercd = ev3_attach_analog(p, EV3_INPUT_NXT_LIGHT, NULL);
			if (ercd == E_OK)
				ercd = ev3_set_light(p, 40);
			break;
		case EV3SIM_IN_HT_ACCEL:
		case EV3SIM_IN_HT_COLOR:
		case EV3SIM_IN_NXT_TEMP:
			ercd = ev3sim_attach_nxt_iic(p, o->in[p]);
			break;
		default:
			if (o->in[p] == EV3SIM_IN_GYRO)
				gyro_options(o, &uopt);
			ercd = ev3_attach_uart_sensor(p, uart_type[o->in[p]], &uopt);
			if (ercd == E_OK)
				ercd = ev3_set_scene(p, &scene);
			break;
		}
		if (ercd == E_OK && o->out[p] != EV3SIM_OUT_NONE)
			ercd = ev3_attach_motor(p, o->out[p] == EV3SIM_OUT_MEDIUM ? HS_MOTOR_MEDIUM :
						HS_MOTOR_LARGE, NULL);
	}
	return ercd;
}

/* Event: the touch sensors on every port with one change to (bool)arg. */
static void touch_event(void *arg)
{
	for (unsigned p = 0; p < 4; p++)
		if (run.o->in[p] == EV3SIM_IN_TOUCH || run.o->in[p] == EV3SIM_IN_NXT_TOUCH)
			ev3_set_touch(p, arg != NULL);
}

/* The output ports of the robot's wheel motors (A = 0); false for a robot without wheels. */
static bool wheel_ports(const struct ev3sim_run_opts *o, unsigned *left, unsigned *right)
{
	if (o->world != NULL) {
		*left = o->world->robot.left_port;
		*right = o->world->robot.right_port;
		return true;
	}
	switch (o->robot) {
	case EV3SIM_ROBOT_GYROBOY: *left = 0; *right = 3; return true;
	case EV3SIM_ROBOT_TRIBOT:  *left = 1; *right = 2; return true;
	default:                   return false;
	}
}

/* Schedules the user's actions and the faults. */
static ER schedule(const struct ev3sim_run_opts *o, char *err, size_t errlen)
{
	static const char press = 1;
	unsigned left, right;

	if (wheel_ports(o, &left, &right) &&
	    ev3sim_fault_check_wheels(o->faults, o->nfaults, left, right, err, errlen) != E_OK)
		return E_PAR;
	for (unsigned i = 0; i < o->nactions; i++) {
		const struct ev3sim_action *a = &o->actions[i];

		if (a->touch) {
			hs_sim_at(a->t_ns, touch_event, (void *)&press);
			hs_sim_at(a->t_ns + a->hold_ns, touch_event, NULL);
		} else if (a->button >= sizeof(ui_button_of) / sizeof(ui_button_of[0]) ||
			   ev3_ui_click_at(a->t_ns, ui_button_of[a->button], a->hold_ns) != E_OK) {
			snprintf(err, errlen, "action %u: bad button click", i + 1);
			return E_PAR;
		}
	}
	for (unsigned i = 0; i < o->nfaults; i++) {
		if (o->faults[i].target != EV3SIM_FAULT_BRICK)
			continue;
		if (ev3_fault_at(o->faults[i].at_ns, &o->faults[i].fault) != E_OK) {
			snprintf(err, errlen, "fault %u rejected by host_sim", i + 1);
			return E_PAR;
		}
	}
	return E_OK;
}

/* Starts the robot's physics. */
static ER start_world(const struct ev3sim_run_opts *o)
{
	unsigned left, right;

	if (!wheel_ports(o, &left, &right))
		return E_OK;
	if (o->world != NULL) {
		struct ev3sim_world_placement pl[EV3SIM_MAX_PLACEMENTS];
		struct ev3sim_world_run wr = { .world = o->world, .placements = pl, .nplacements = o->nplacements };

		for (unsigned i = 0; i < o->nplacements; i++) {
			pl[i].t_ns = o->placements[i].t_ns;
			pl[i].left_m = o->placements[i].left_mm / 1000.0;
		}
		for (unsigned p = 0; p < 4; p++)
			wr.in[p] = o->in[p];
		return ev3sim_world_start(&wr);
	}
	if (o->robot == EV3SIM_ROBOT_GYROBOY) {
		struct ev3sim_robot_cfg cfg = {
			.left_port = left, .right_port = right, .gyro_port = 1, .release_ns = o->release_ns,
			.release_on_drive = o->release_on_drive, .start_tilt_deg = o->start_tilt_deg, .pushes = o->pushes, .npushes = o->npushes,
		};

		return ev3sim_robot_start(&cfg);
	}
	if (o->robot == EV3SIM_ROBOT_TRIBOT) {
		struct ev3sim_tribot_cfg cfg = {
			.left_port = left, .right_port = right,
			.placements = o->placements, .nplacements = o->nplacements,
		};

		for (unsigned p = 0; p < 4; p++)
			cfg.in[p] = o->in[p];
		return ev3sim_tribot_start(&cfg);
	}
	return E_OK;
}

/* The world's state every CHUNK_NS: statistics and a CSV row. */
static void observe(const struct ev3sim_run_opts *o, struct ev3sim_run_result *r)
{
	double t = rtos_host_now() * 1e-9;

	if (o->plot_path)
		ev3sim_world_series_add();
	if (o->world != NULL) {
		const struct ev3sim_world_state *s = ev3sim_world_now();

		r->travel_m = s->travel_m;
		if (o->csv)
			fprintf(o->csv, "%.2f,%.4f,%.4f,%.2f,%.4f,%g,%g,%g,%g,%u\n", t, s->x, s->y, s->heading_deg,
				s->travel_m, s->port_value[0], s->port_value[1], s->port_value[2], s->port_value[3],
				s->contacts);
		return;
	}
	if (o->robot == EV3SIM_ROBOT_GYROBOY) {
		const struct ev3sim_robot_sample *s = ev3sim_robot_now();

		if (!s->held && fabs(s->tilt_deg) > r->max_tilt_deg)
			r->max_tilt_deg = fabs(s->tilt_deg);
		if (o->csv)
			fprintf(o->csv, "%.2f,%.3f,%.3f,%.2f,%d\n", t, s->tilt_deg, s->tilt_rate_dps,
				s->wheel_deg, s->held ? 1 : 0);
	} else if (o->robot == EV3SIM_ROBOT_TRIBOT) {
		const struct ev3sim_tribot_sample *s = ev3sim_tribot_now();
		double e = fabs(s->line_error_m) * 1000.0;

		if (e > r->max_line_error_mm)
			r->max_line_error_mm = e;
		run.sum_sq_error += e * e;
		run.samples++;
		run.on_line += s->line_cover > 0.0;
		r->progress_m = s->progress_m;
		r->travel_m = s->travel_m;
		if (o->csv)
			fprintf(o->csv, "%.2f,%.4f,%.4f,%.2f,%.2f,%u,%.3f\n", t, s->x_m, s->y_m,
				s->heading_deg, s->line_error_m * 1000.0, s->reflect_pct, s->progress_m);
	}
}

static void csv_header(const struct ev3sim_run_opts *o)
{
	if (o->csv == NULL)
		return;
	if (o->world != NULL)
		fprintf(o->csv, "t_s,x_m,y_m,heading_deg,travel_m,in1,in2,in3,in4,contacts\n");
	else if (o->robot == EV3SIM_ROBOT_GYROBOY)
		fprintf(o->csv, "t_s,tilt_deg,tilt_rate_dps,wheel_deg,held\n");
	else if (o->robot == EV3SIM_ROBOT_TRIBOT)
		fprintf(o->csv, "t_s,x_m,y_m,heading_deg,line_error_mm,reflect_pct,progress_m\n");
	else
		fprintf(o->csv, "t_s\n");
}

ER ev3sim_run(const struct ev3sim_run_opts *o, const struct rtos_cfg *app,
	      struct ev3sim_run_result *r, char *err, size_t errlen)
{
	static const struct hs_board_cfg board = { .devices = ev3_board_devices };
	struct hs_scenario scn = { .rtos = &run_cfg, .board = &board, .seed = o->seed,
				   .vcd_path = o->trace_path };
	uint64_t end;
	double wall0;
	ER ercd, shutdown;
	bool lcd_failed = false;    /* the video */
	bool png_failed = false;
	char audio_err[256];

	memset(r, 0, sizeof(*r));
	if (app == NULL || !(o->seconds > 0 && o->seconds <= EV3SIM_MAX_SECONDS) ||
	    o->nfaults > EV3SIM_RUN_MAX_FAULTS || o->nactions > EV3SIM_RUN_MAX_ACTIONS ||
	    o->npushes > EV3SIM_MAX_PUSHES || o->nplacements > EV3SIM_MAX_PLACEMENTS ||
	    (unsigned)o->robot > EV3SIM_ROBOT_TRIBOT ||
	    (o->world != NULL && o->robot != EV3SIM_ROBOT_BARE) ||
	    (o->plot_path != NULL && o->world == NULL && o->robot != EV3SIM_ROBOT_TRIBOT) ||
	    fabs(o->start_tilt_deg) >= 30.0 || !(o->gyro_noise_dps >= 0)) {
		snprintf(err, errlen, "bad run options");
		return E_PAR;
	}
	if (o->world != NULL && ev3sim_world_check(o->world) != NULL) {
		snprintf(err, errlen, "world %s: %s", o->world->name, ev3sim_world_check(o->world));
		return E_PAR;
	}
	for (unsigned p = 0; p < 4; p++)
		if ((unsigned)o->in[p] >= EV3SIM_IN_COUNT || (unsigned)o->out[p] >= EV3SIM_OUT_COUNT) {
			snprintf(err, errlen, "bad device on port %u", p + 1);
			return E_PAR;
		}
	if (load_image(app) != E_OK) {
		snprintf(err, errlen, "out of memory for the app's image");
		return E_SYS;
	}
	run_includes[0] = app;
	if (brick_io_setup(o->sd_dir, o->serial_path, err, errlen) != E_OK)
		return E_PAR;
	if ((o->bt_path != NULL && brick_io_bt_listen(o->bt_path, err, errlen) != E_OK) ||
	    (o->usb_path != NULL && brick_io_usb_listen(o->usb_path, err, errlen) != E_OK) ||
	    (o->bt_master_path != NULL && brick_io_bt_master(o->bt_master_path, err, errlen) != E_OK)) {
		brick_io_teardown();
		return E_PAR;
	}
	memset(&run, 0, sizeof(run));
	run.o = o;
	run.r = r;
	if (o->live && ev3sim_live_begin(o, err, errlen) != E_OK) {
		brick_io_teardown();
		return E_SYS;
	}
	wall0 = ev3sim_wall_seconds();
	if (hs_sim_boot(&scn) != E_OK) {
		snprintf(err, errlen, "boot failed: %s", rtos_host_boot_error());
		if (o->live)
			ev3sim_live_end(NULL);
		brick_io_teardown();
		return E_SYS;
	}
	rtos_host_trace_set_source_sink("syslog", trace_sink, NULL);
	if (o->quiet)
		ev3sim_quiet_console();
	ercd = o->audio_path ? ev3sim_wav_begin(o->audio_path, err, errlen) : E_OK;
	if (ercd == E_OK && (ercd = plug_in(o)) != E_OK)
		snprintf(err, errlen, "cannot plug the devices in (%d)", (int)ercd);
	if (ercd == E_OK)
		ercd = schedule(o, err, errlen);
	if (ercd == E_OK && (ercd = start_world(o)) != E_OK)
		snprintf(err, errlen, "the %s's devices are not all plugged in (%d)",
			 o->world ? "world's robot" : ev3sim_robot_name(o->robot), (int)ercd);
	if (ercd == E_OK && o->plot_path)
		ev3sim_world_series_begin();
	if (ercd != E_OK) {
		(void)ev3sim_wav_end(audio_err, sizeof(audio_err));
		(void)iact_tsk(POWER_OFF_TSKID);
		hs_sim_run_for(DRAIN_NS);
		rtos_host_trace_set_sink(NULL, NULL);
		hs_sim_shutdown();
		if (o->live)
			ev3sim_live_end(NULL);
		brick_io_teardown();
		return ercd == E_PAR ? E_PAR : E_SYS;
	}
	csv_header(o);
	end = (uint64_t)llround(o->seconds * 1e9);
	if (o->lcd_video_path && (!ev3sim_lcd_video || ev3sim_lcd_video->begin(o->lcd_video_path) != E_OK))
		lcd_failed = true;
	/* a stalled task or a stack overrun ends the system: time then stands still; the
	 * live view takes the page's inputs and paces after each step, and may stop the run */
	while (rtos_host_now() < end && !rtos_host_exited()) {
		uint64_t next = rtos_host_now() + CHUNK_NS;

		hs_sim_run_until(next < end ? next : end);
		observe(o, r);
		if (o->lcd_video_path && !lcd_failed)
			ev3sim_lcd_video->frame(rtos_host_now());
		if (o->live && rtos_host_now() < end && !ev3sim_live_step()) {
			r->stopped = true;
			break;
		}
	}
	if (o->live)
		ev3sim_live_record();
	if (o->lcd_video_path && !lcd_failed && ev3sim_lcd_video->end(rtos_host_now()) != E_OK)
		lcd_failed = true;
	if (o->world != NULL) {
		const struct ev3sim_world_state *s = ev3sim_world_now();

		ev3sim_world_stop();
		r->x_m = s->x;
		r->y_m = s->y;
		r->heading_deg = s->heading_deg;
		r->travel_m = s->travel_m;
		r->contacts = s->contacts;
		r->min_clearance_mm = s->min_clearance_m < 1e29 ? s->min_clearance_m * 1000.0 : -1.0;
		r->goal_reached = s->goal_reached;
		r->goal_at_s = s->goal_at_s;
	} else if (o->robot == EV3SIM_ROBOT_GYROBOY) {
		uint64_t fell_ns;

		r->fell = ev3sim_robot_fallen(&fell_ns);
		r->fell_at_s = r->fell ? fell_ns * 1e-9 : 0.0;
		ev3sim_robot_stop();
	} else if (o->robot == EV3SIM_ROBOT_TRIBOT) {
		ev3sim_tribot_stop();
		r->rms_line_error_mm = run.samples ? sqrt(run.sum_sq_error / (double)run.samples) : 0.0;
		r->on_line_pct = run.samples ? 100.0 * (double)run.on_line / (double)run.samples : 0.0;
	}
	r->seconds = rtos_host_now() * 1e-9;
	r->bugs = rtos_host_bug_count();
	r->end_status = rtos_host_end_status();
	if (r->end_status != 0)
		snprintf(r->end_report, sizeof(r->end_report), "%s", rtos_host_last_bug());
	r->wall_s = ev3sim_wall_seconds() - wall0;
	if (ev3sim_wav_end(audio_err, sizeof(audio_err)) != E_OK)
		ercd = E_SYS;
	if (o->lcd_path) {
		static uint8_t px[EV3_LCD_PANEL_HEIGHT][EV3_LCD_PANEL_WIDTH];

		ev3_lcd_pixels(px);
		r->lcd_dark = 0;
		for (unsigned y = 0; y < EV3_LCD_PANEL_HEIGHT; y++)
			for (unsigned x = 0; x < EV3_LCD_PANEL_WIDTH; x++)
				r->lcd_dark += px[y][x];
		if (!ev3sim_lcd_png_writer || ev3sim_lcd_png_writer(o->lcd_path) != E_OK)
			png_failed = true;
	}
	(void)iact_tsk(POWER_OFF_TSKID);
	hs_sim_run_for(DRAIN_NS);
	rtos_host_trace_set_sink(NULL, NULL);
	shutdown = hs_sim_shutdown();
	brick_io_teardown();
	if (o->live) {
		char line[1024];

		ev3sim_run_summary(o, r, line, sizeof(line));
		ev3sim_live_end(line);
	}
	if (r->end_status != 0) {
		snprintf(err, errlen, "the app %s at %.3f s: %s",
			 r->end_status == RTOS_HOST_EXIT_STALL ? "stalled" : "overran a task's stack", r->seconds,
			 r->end_report);
		return E_SYS;
	}
	if (shutdown != E_OK) {
		snprintf(err, errlen, "cannot write %s completely", o->trace_path);
		return E_SYS;
	}
	if (ercd != E_OK) {
		snprintf(err, errlen, "%s", audio_err);
		return E_SYS;
	}
	if (o->plot_path && ev3sim_world_plot(o->plot_path, o->plot_signals, o->app_name, err, errlen) != 0)
		return E_SYS;
	if (png_failed || lcd_failed) {
		snprintf(err, errlen, "cannot write %s", png_failed ? o->lcd_path : o->lcd_video_path);
		return E_SYS;
	}
	return E_OK;
}

void ev3sim_run_summary(const struct ev3sim_run_opts *o, const struct ev3sim_run_result *r,
			char *buf, size_t len)
{
	char world[256] = "";

	if (o->world != NULL) {
		char goal[32] = "none", clearance[32] = "none";

		if (r->goal_reached)
			snprintf(goal, sizeof(goal), "%.2f", r->goal_at_s);
		if (r->min_clearance_mm >= 0)
			snprintf(clearance, sizeof(clearance), "%.0f", r->min_clearance_mm);
		snprintf(world, sizeof(world),
			 "world=%s x_m=%.3f y_m=%.3f heading_deg=%.1f travel_m=%.3f contacts=%u "
			 "min_clearance_mm=%s goal_at_s=%s ", o->world->name, r->x_m, r->y_m, r->heading_deg,
			 r->travel_m, r->contacts, clearance, goal);
	} else if (o->robot == EV3SIM_ROBOT_GYROBOY) {
		char fell_at[32] = "none";

		if (r->fell)
			snprintf(fell_at, sizeof(fell_at), "%.3f", r->fell_at_s);
		snprintf(world, sizeof(world), "result=%s fell_at_s=%s max_tilt_deg=%.2f ",
			 r->fell ? "fell" : "upright", fell_at, r->max_tilt_deg);
	} else if (o->robot == EV3SIM_ROBOT_TRIBOT) {
		snprintf(world, sizeof(world),
			 "line_progress_m=%.3f travel_m=%.3f max_line_error_mm=%.1f rms_line_error_mm=%.1f "
			 "on_line_pct=%.1f ", r->progress_m, r->travel_m, r->max_line_error_mm,
			 r->rms_line_error_mm, r->on_line_pct);
	}
	if (o->lcd_path) {
		size_t n = strlen(world);

		snprintf(world + n, sizeof(world) - n, "lcd_dark_pixels=%u ", r->lcd_dark);
	}
	if (r->stopped) {
		size_t n = strlen(world);

		snprintf(world + n, sizeof(world) - n, "stopped_at_s=%.2f ", r->seconds);
	}
	snprintf(buf, len, "app=%s robot=%s seconds=%g seed=%llu %slog_lines=%u warnings=%u errors=%u "
		 "bugs=%u sim_speed=%.0fx",
		 o->app_name ? o->app_name : "?", o->world ? "world" : ev3sim_robot_name(o->robot), o->seconds,
		 (unsigned long long)o->seed, world, r->log_lines, r->warnings, r->errors, r->bugs,
		 r->wall_s > 0 ? r->seconds / r->wall_s : 0.0);
}
