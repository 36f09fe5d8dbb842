/*
 * live.c — the simulation's half of `ev3sim run --live` (live.h): the
 * page's inputs applied at step boundaries, the state it shows, the pace.
 *
 * The simulation runs on the program's main thread; the server's thread
 * only reads the snapshot and the plot's rows and queues commands, under
 * one mutex.  The snapshot is refreshed at most every LIVE_SNAPSHOT_NS of
 * wall-clock time (a fast run steps tens of thousands of times a second),
 * and at every step while the run is paused or stepped.  Everything is read
 * from host_sim with calls that change nothing (the display's pixels, the
 * LEDs' pins, the buttons, the tachos' counts, the sensors' scenes), so
 * watching a run leaves it as it is.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <pthread.h>
#include <stdarg.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <time.h>
#include "rtos_host.h"
#include "host_sim/devices/ev3_brick.h"
#include "host_sim/devices/ev3_lcd.h"
#include "host_sim/devices/ev3_motor.h"
#include "host_sim/devices/ev3_ui.h"
#include "host_sim/devices/uart_sensor.h"
#include "ev3sim/live.h"
#include "ev3sim/robot.h"
#include "ev3sim/run.h"
#include "ev3sim/tribot.h"

const struct ev3sim_live_server *ev3sim_live_server;

#define LIVE_ROWS        8192U          /* the plot's rows kept (82 s at a row per 10 ms step) */
#define LIVE_ROWS_SENT   1000U          /* rows in one answer; the page asks again for more */
#define LIVE_INPUTS      64U            /* button changes queued between two steps */
#define LIVE_SNAPSHOT_NS 20000000ULL    /* the snapshot's refresh, wall-clock time */
#define GYROBOY_WHEEL_RADIUS_MM 28.0    /* robot.c's wheel: the gyro boy's travel */
#define PI 3.14159265358979323846

/* The plot's signals: one row per step. */
enum {
	COL_T, COL_X, COL_Y, COL_HEADING, COL_TILT, COL_OUT_A, COL_IN_1 = COL_OUT_A + 4, COLS = COL_IN_1 + 4
};
static const char *const col_names[COLS] = {
	"t_s", "x_mm", "y_mm", "heading_deg", "tilt_deg", "A_deg", "B_deg", "C_deg", "D_deg",
	"in1", "in2", "in3", "in4",
};

/* The buttons as the page names them, in EV3RT's button_t order, and host_sim's. */
static const char *const button_names[] = { "left", "right", "up", "down", "enter", "back" };
static const enum ev3_ui_button ui_buttons[] = {
	EV3_UI_BUTTON_LEFT, EV3_UI_BUTTON_RIGHT, EV3_UI_BUTTON_UP,
	EV3_UI_BUTTON_DOWN, EV3_UI_BUTTON_ENTER, EV3_UI_BUTTON_BACK,
};
#define NBUTTONS (sizeof(button_names) / sizeof(button_names[0]))

/* Where the robot is: position on the mat, heading from +x, pitch. */
struct live_pose {
	bool valid;
	double x_mm, y_mm, heading_deg, tilt_deg;
};

/* One input port as the page shows it. */
struct port_view {
	const char *device;         /* the device's name, "none" */
	const char *what;           /* what value holds ("COL-REFLECT %", "pressed"...), "" */
	double value;
};

/* A button the page pressed or released. */
struct live_input {
	unsigned button;            /* index in button_names */
	bool pressed;
};

struct snapshot {
	uint64_t t_ns;
	struct live_pose pose;
	bool lcd_on;
	uint8_t lcd[EV3_LCD_PANEL_HEIGHT][EV3_LCD_PANEL_WIDTH];
	unsigned lcd_dark;
	enum ev3_ui_color led[EV3_UI_LEDS];
	bool held[NBUTTONS];
	struct port_view in[4];
	const char *out_device[4];
	double out_deg[4];
};

static struct {
	pthread_mutex_t mu;
	pthread_cond_t cv;
	bool active;                /* between begin and end */
	const struct ev3sim_run_opts *o;
	/* what the page asked for, taken at the next step */
	struct live_input inputs[LIVE_INPUTS];
	unsigned ninputs;
	double pace;                /* times real time, 0: as fast as possible */
	bool paused, stop;
	unsigned steps;             /* single steps asked for while paused */
	bool repace;                /* the pace's reference is to be taken again */
	/* what the page shows */
	struct snapshot snap;
	uint64_t snap_wall_ns;
	bool finished;
	char summary[1024];
	double rows[LIVE_ROWS][COLS];
	uint64_t nrows;             /* rows recorded; row n is rows[n % LIVE_ROWS] */
	/* the pace's reference: virtual time ref_virt_ns was at wall time ref_wall_ns */
	uint64_t ref_wall_ns, ref_virt_ns;
} lv = { .mu = PTHREAD_MUTEX_INITIALIZER };

/* Monotonic wall-clock time, ns. */
static uint64_t wall_ns(void)
{
	struct timespec ts;

	clock_gettime(CLOCK_MONOTONIC, &ts);
	return (uint64_t)ts.tv_sec * 1000000000ULL + (uint64_t)ts.tv_nsec;
}

/*
 * The robot's pose now: the one place the live view asks where the robot
 * is.  The driving base's from its physics; the gyro boy rolls along +x
 * (its wheels' travel) and leans (its pitch); a bare brick has none.
 */
static struct live_pose live_pose(void)
{
	struct live_pose p = { .valid = false };

	if (lv.o->world != NULL) {
		const struct ev3sim_world_state *w = ev3sim_world_now();

		p = (struct live_pose){ true, w->x * 1000.0, w->y * 1000.0, w->heading_deg, w->pitch_deg };
	} else if (lv.o->robot == EV3SIM_ROBOT_TRIBOT) {
		const struct ev3sim_tribot_sample *s = ev3sim_tribot_now();

		p = (struct live_pose){ true, s->x_m * 1000.0, s->y_m * 1000.0, s->heading_deg, 0.0 };
	} else if (lv.o->robot == EV3SIM_ROBOT_GYROBOY) {
		const struct ev3sim_robot_sample *s = ev3sim_robot_now();

		p = (struct live_pose){ true, s->wheel_deg * PI / 180.0 * GYROBOY_WHEEL_RADIUS_MM, 0.0, 0.0,
					s->tilt_deg };
	}
	return p;
}

/* A world's mat and obstacles as the page draws them: {"kind":"world",...}, in mm. */
static void world_json(const struct ev3sim_world *w, char *buf, size_t len)
{
	const struct ev3sim_world_mat *m = &w->mat;
	size_t at;

	at = (size_t)snprintf(buf, len, "{\"kind\":\"world\",\"mat_kind\":\"%s\",\"x0_mm\":%.0f,\"y0_mm\":%.0f,"
			      "\"width_mm\":%.0f,\"height_mm\":%.0f,\"rgb\":[%u,%u,%u],\"obstacles\":[",
			      m->kind == EV3SIM_MAT_STADIUM ? "stadium" : m->kind == EV3SIM_MAT_IMAGE ? "image" : "plain",
			      m->x0 * 1000.0, m->y0 * 1000.0, m->width * 1000.0, m->height * 1000.0,
			      m->rgb[0], m->rgb[1], m->rgb[2]);
	for (unsigned i = 0; i < w->nobstacles && at < len; i++) {
		const struct ev3sim_obstacle *o = &w->obstacles[i];

		at += (size_t)snprintf(buf + at, len - at, "%s{\"kind\":\"%s\",\"x0\":%.0f,\"y0\":%.0f,"
				       "\"x1\":%.0f,\"y1\":%.0f,\"r\":%.0f}", i ? "," : "",
				       o->kind == EV3SIM_OBST_SEGMENT ? "segment" : o->kind == EV3SIM_OBST_BOX ? "box" : "circle",
				       o->x0 * 1000.0, o->y0 * 1000.0, o->x1 * 1000.0, o->y1 * 1000.0, o->r * 1000.0);
	}
	if (at < len)
		at += (size_t)snprintf(buf + at, len - at, "]");
	if (at < len && w->has_goal)
		at += (size_t)snprintf(buf + at, len - at, ",\"goal\":[%.0f,%.0f,%.0f]", w->goal_x * 1000.0,
				       w->goal_y * 1000.0, w->goal_r * 1000.0);
	if (at < len)
		snprintf(buf + at, len - at, "}");
}

/* The mat the robot is on, as the page draws it (JSON object), beside live_pose. */
static void live_mat_json(char *buf, size_t len)
{
	if (lv.o->world != NULL && lv.o->world->mat.kind != EV3SIM_MAT_STADIUM)
		world_json(lv.o->world, buf, len);
	else if (lv.o->robot == EV3SIM_ROBOT_TRIBOT || lv.o->world != NULL)
		snprintf(buf, len, "{\"kind\":\"stadium\",\"straight_mm\":%.0f,\"radius_mm\":%.0f,"
			 "\"line_mm\":%.0f,\"white_pct\":%d,\"black_pct\":%d}",
			 EV3SIM_LINE_STRAIGHT_M * 1000.0, EV3SIM_LINE_RADIUS_M * 1000.0,
			 EV3SIM_LINE_WIDTH_M * 1000.0, EV3SIM_MAT_WHITE_PCT, EV3SIM_MAT_BLACK_PCT);
	else if (lv.o->robot == EV3SIM_ROBOT_GYROBOY)
		snprintf(buf, len, "{\"kind\":\"floor\"}");
	else
		snprintf(buf, len, "null");
}

/* What input port p's device shows now. */
static struct port_view input_view(unsigned p)
{
	enum ev3sim_input_device d = lv.o->in[p];
	struct port_view v = { ev3sim_input_device_name(d), "", 0.0 };
	const struct uart_sensor *s;
	const struct uart_sensor_scene *sc;
	unsigned mode;

	switch (d) {
	case EV3SIM_IN_TOUCH:
		v.what = "pressed";
		v.value = ev3_input_pin_mv(p, 6) > 2500U;
		return v;
	case EV3SIM_IN_NXT_TOUCH:
	case EV3SIM_IN_NXT_LIGHT:
		v.what = "pin 1 mV";
		v.value = ev3_input_pin_mv(p, 1);
		return v;
	case EV3SIM_IN_GYRO:
	case EV3SIM_IN_COLOR:
	case EV3SIM_IN_ULTRASONIC:
	case EV3SIM_IN_IR:
		break;
	default:
		return v;
	}
	s = ev3_input_uart_sensor(p);
	if (s == NULL)
		return v;
	sc = uart_sensor_scene(s);
	mode = uart_sensor_mode(s);
	v.what = mode < uart_sensor_get_def(s)->modes ? uart_sensor_get_def(s)->mode[mode].name : "";
	switch (d) {
	case EV3SIM_IN_GYRO:       v.value = sc->rate_dps; break;
	case EV3SIM_IN_COLOR:      v.value = mode == 1 ? sc->ambient_pct : mode == 2 ? sc->color : sc->reflect_pct; break;
	case EV3SIM_IN_ULTRASONIC: v.value = sc->distance_mm; break;
	default:                   v.value = sc->distance_mm; break;
	}
	return v;
}

/* The angle output port p's motor's tacho shows (deg: one count a degree), 0 without one. */
static double output_deg(unsigned p)
{
	struct hs_motor *m = lv.o->out[p] != EV3SIM_OUT_NONE ? ev3_output_motor(p) : NULL;

	return m != NULL ? (double)hs_motor_tacho_counts(m) : 0.0;
}

/* Records the plot's row of this step (the lock held). */
static void record_row(const struct live_pose *pose)
{
	double *row = lv.rows[lv.nrows % LIVE_ROWS];

	row[COL_T] = (double)rtos_host_now() * 1e-9;
	row[COL_X] = pose->x_mm;
	row[COL_Y] = pose->y_mm;
	row[COL_HEADING] = pose->heading_deg;
	row[COL_TILT] = pose->tilt_deg;
	for (unsigned p = 0; p < 4; p++) {
		row[COL_OUT_A + p] = output_deg(p);
		row[COL_IN_1 + p] = input_view(p).value;
	}
	lv.nrows++;
}

/* Refreshes the snapshot (the lock held). */
static void take_snapshot(const struct live_pose *pose)
{
	struct snapshot *s = &lv.snap;

	s->t_ns = rtos_host_now();
	s->pose = *pose;
	s->lcd_on = ev3_lcd_display_on();
	ev3_lcd_pixels(s->lcd);
	s->lcd_dark = 0;
	for (unsigned y = 0; y < EV3_LCD_PANEL_HEIGHT; y++)
		for (unsigned x = 0; x < EV3_LCD_PANEL_WIDTH; x++)
			s->lcd_dark += s->lcd[y][x];
	for (unsigned i = 0; i < EV3_UI_LEDS; i++)
		s->led[i] = ev3_ui_led_color((enum ev3_ui_led)i);
	for (unsigned b = 0; b < NBUTTONS; b++)
		s->held[b] = ev3_ui_button_held(ui_buttons[b]);
	for (unsigned p = 0; p < 4; p++) {
		s->in[p] = input_view(p);
		s->out_device[p] = ev3sim_output_device_name(lv.o->out[p]);
		s->out_deg[p] = output_deg(p);
	}
	lv.snap_wall_ns = wall_ns();
}

ER ev3sim_live_begin(const struct ev3sim_run_opts *o, char *err, size_t errlen)
{
	pthread_condattr_t attr;
	unsigned bound = 0;
	char why[256];

	if (ev3sim_live_server == NULL) {
		snprintf(err, errlen, "--live: this program has no HTTP server (build/host/ev3sim has one: "
			 "Debian's libmicrohttpd is a 64-bit host library)");
		return E_SYS;
	}
	pthread_mutex_lock(&lv.mu);
	lv.o = o;
	lv.ninputs = 0;
	lv.pace = o->pace;
	lv.paused = lv.stop = lv.finished = false;
	lv.steps = 0;
	lv.repace = true;
	lv.nrows = 0;
	lv.summary[0] = '\0';
	memset(&lv.snap, 0, sizeof(lv.snap));
	lv.active = true;
	pthread_mutex_unlock(&lv.mu);
	/* the pace's waits are timed on the monotonic clock */
	pthread_condattr_init(&attr);
	pthread_condattr_setclock(&attr, CLOCK_MONOTONIC);
	pthread_cond_init(&lv.cv, &attr);
	pthread_condattr_destroy(&attr);
	if (ev3sim_live_server->start(o->live_port, &bound, why, sizeof(why)) != E_OK) {
		snprintf(err, errlen, "--live: %s", why);
		lv.active = false;
		pthread_cond_destroy(&lv.cv);
		return E_SYS;
	}
	fprintf(stderr, "ev3sim run: live view at http://127.0.0.1:%u/\n", bound);
	fflush(stderr);
	return E_OK;
}

/* Waits on the condition until wall time until_ns (0: until signalled); the lock held. */
static void wait_until(uint64_t until_ns)
{
	struct timespec ts;

	if (until_ns == 0) {
		pthread_cond_wait(&lv.cv, &lv.mu);
		return;
	}
	ts.tv_sec = (time_t)(until_ns / 1000000000ULL);
	ts.tv_nsec = (long)(until_ns % 1000000000ULL);
	(void)pthread_cond_timedwait(&lv.cv, &lv.mu, &ts);
}

bool ev3sim_live_step(void)
{
	struct live_pose pose = live_pose();
	bool go;

	pthread_mutex_lock(&lv.mu);
	for (unsigned i = 0; i < lv.ninputs; i++)
		(void)ev3_ui_button_set(ui_buttons[lv.inputs[i].button], lv.inputs[i].pressed);
	lv.ninputs = 0;
	record_row(&pose);
	if (lv.paused || wall_ns() - lv.snap_wall_ns >= LIVE_SNAPSHOT_NS)
		take_snapshot(&pose);
	for (;;) {
		uint64_t now = wall_ns(), due;

		if (lv.stop)
			break;
		if (lv.paused) {
			if (lv.steps > 0) {
				lv.steps--;
				break;
			}
			/* paused, the page shows the state it is paused at */
			if (lv.snap.t_ns != rtos_host_now())
				take_snapshot(&pose);
			wait_until(0);
			lv.repace = true;
			continue;
		}
		if (lv.repace) {
			lv.ref_wall_ns = now;
			lv.ref_virt_ns = rtos_host_now();
			lv.repace = false;
		}
		if (lv.pace <= 0.0)
			break;
		due = lv.ref_wall_ns + (uint64_t)((double)(rtos_host_now() - lv.ref_virt_ns) / lv.pace);
		if (now >= due)
			break;
		wait_until(due);
	}
	go = !lv.stop;
	pthread_mutex_unlock(&lv.mu);
	return go;
}

void ev3sim_live_record(void)
{
	struct live_pose pose = live_pose();

	pthread_mutex_lock(&lv.mu);
	record_row(&pose);
	take_snapshot(&pose);
	pthread_mutex_unlock(&lv.mu);
}

void ev3sim_live_end(const char *summary)
{
	if (!lv.active)
		return;
	pthread_mutex_lock(&lv.mu);
	lv.finished = true;
	snprintf(lv.summary, sizeof(lv.summary), "%s", summary != NULL ? summary : "");
	pthread_mutex_unlock(&lv.mu);
	ev3sim_live_server->stop();
	pthread_mutex_lock(&lv.mu);
	lv.active = false;
	pthread_mutex_unlock(&lv.mu);
	pthread_cond_destroy(&lv.cv);
}

/* ---- the server's half ---- */

/* Appends to buf[*n..len) as printf does; *n stops at len - 1. */
__attribute__((format(printf, 4, 5)))
static void put(char *buf, size_t len, size_t *n, const char *fmt, ...)
{
	va_list ap;
	int k;

	if (*n + 1 >= len)
		return;
	va_start(ap, fmt);
	k = vsnprintf(buf + *n, len - *n, fmt, ap);
	va_end(ap);
	if (k > 0)
		*n = *n + (size_t)k < len ? *n + (size_t)k : len - 1;
}

/* A number as JSON has it (finite; NaN and infinities as null). */
static void put_num(char *buf, size_t len, size_t *n, double v)
{
	if (isfinite(v))
		put(buf, len, n, "%.6g", v);
	else
		put(buf, len, n, "null");
}

/* The display's pixels as hex, row by row, each row's 178 bits MSB first in 23 bytes. */
static void put_lcd(char *buf, size_t len, size_t *n, const struct snapshot *s)
{
	static const char hex[] = "0123456789abcdef";

	for (unsigned y = 0; y < EV3_LCD_PANEL_HEIGHT; y++)
		for (unsigned x = 0; x < EV3_LCD_PANEL_WIDTH; x += 8) {
			unsigned byte = 0;

			for (unsigned b = 0; b < 8; b++)
				byte = byte << 1 | (x + b < EV3_LCD_PANEL_WIDTH && s->lcd[y][x + b]);
			if (*n + 3 < len) {
				buf[(*n)++] = hex[byte >> 4];
				buf[(*n)++] = hex[byte & 15];
				buf[*n] = '\0';
			}
		}
}

/* The name of an LED colour. */
static const char *led_name(enum ev3_ui_color c)
{
	switch (c) {
	case EV3_UI_LED_RED:    return "red";
	case EV3_UI_LED_GREEN:  return "green";
	case EV3_UI_LED_ORANGE: return "orange";
	default:                return "off";
	}
}

size_t ev3sim_live_status_json(uint64_t since, char *buf, size_t len)
{
	const struct snapshot *s = &lv.snap;
	uint64_t first, last;
	size_t n = 0;

	if (len == 0)
		return 0;
	buf[0] = '\0';
	pthread_mutex_lock(&lv.mu);
	put(buf, len, &n, "{\"t_s\":%.3f,\"pace\":", (double)s->t_ns * 1e-9);
	put_num(buf, len, &n, lv.pace);
	put(buf, len, &n, ",\"paused\":%s,\"finished\":%s,\"summary\":\"", lv.paused ? "true" : "false",
	    lv.finished ? "true" : "false");
	for (const char *c = lv.summary; *c != '\0'; c++)
		put(buf, len, &n, *c == '"' || *c == '\\' ? "\\%c" : "%c", *c);
	put(buf, len, &n, "\",\"pose\":");
	if (s->pose.valid) {
		put(buf, len, &n, "{\"x_mm\":");
		put_num(buf, len, &n, s->pose.x_mm);
		put(buf, len, &n, ",\"y_mm\":");
		put_num(buf, len, &n, s->pose.y_mm);
		put(buf, len, &n, ",\"heading_deg\":");
		put_num(buf, len, &n, s->pose.heading_deg);
		put(buf, len, &n, ",\"tilt_deg\":");
		put_num(buf, len, &n, s->pose.tilt_deg);
		put(buf, len, &n, "}");
	} else {
		put(buf, len, &n, "null");
	}
	put(buf, len, &n, ",\"leds\":[\"%s\",\"%s\"],\"buttons\":{", led_name(s->led[0]), led_name(s->led[1]));
	for (unsigned b = 0; b < NBUTTONS; b++)
		put(buf, len, &n, "%s\"%s\":%s", b ? "," : "", button_names[b], s->held[b] ? "true" : "false");
	put(buf, len, &n, "},\"ports\":[");
	for (unsigned p = 0; p < 4; p++) {
		put(buf, len, &n, "%s{\"port\":\"%u\",\"device\":\"%s\",\"what\":\"%s\",\"value\":", p ? "," : "",
		    p + 1, s->in[p].device ? s->in[p].device : "none", s->in[p].what ? s->in[p].what : "");
		put_num(buf, len, &n, s->in[p].value);
		put(buf, len, &n, "}");
	}
	for (unsigned p = 0; p < 4; p++) {
		put(buf, len, &n, ",{\"port\":\"%c\",\"device\":\"%s\",\"what\":\"%s\",\"value\":", 'A' + p,
		    s->out_device[p] ? s->out_device[p] : "none", s->out_device[p] && lv.o->out[p] ? "deg" : "");
		put_num(buf, len, &n, s->out_deg[p]);
		put(buf, len, &n, "}");
	}
	put(buf, len, &n, "],\"lcd\":{\"on\":%s,\"width\":%u,\"height\":%u,\"dark\":%u,\"hex\":\"",
	    s->lcd_on ? "true" : "false", EV3_LCD_PANEL_WIDTH, EV3_LCD_PANEL_HEIGHT, s->lcd_dark);
	put_lcd(buf, len, &n, s);
	put(buf, len, &n, "\"},\"signals\":[");
	for (unsigned c = 0; c < COLS; c++)
		put(buf, len, &n, "%s\"%s\"", c ? "," : "", col_names[c]);
	/* the rows after since that are still kept, at most LIVE_ROWS_SENT */
	last = lv.nrows;
	first = since > last ? last : since;
	if (last - first > LIVE_ROWS)
		first = last - LIVE_ROWS;
	if (last - first > LIVE_ROWS_SENT)
		last = first + LIVE_ROWS_SENT;
	put(buf, len, &n, "],\"rows_from\":%llu,\"rows\":[", (unsigned long long)first);
	for (uint64_t r = first; r < last; r++) {
		put(buf, len, &n, "%s[", r > first ? "," : "");
		for (unsigned c = 0; c < COLS; c++) {
			if (c)
				put(buf, len, &n, ",");
			put_num(buf, len, &n, lv.rows[r % LIVE_ROWS][c]);
		}
		put(buf, len, &n, "]");
	}
	put(buf, len, &n, "],\"next\":%llu}", (unsigned long long)last);
	pthread_mutex_unlock(&lv.mu);
	return n;
}

size_t ev3sim_live_world_json(char *buf, size_t len)
{
	static char mat[EV3SIM_WORLD_MAX_OBSTACLES * 96 + 512];    /* under lv.mu */
	size_t n = 0;

	if (len == 0)
		return 0;
	buf[0] = '\0';
	pthread_mutex_lock(&lv.mu);
	live_mat_json(mat, sizeof(mat));
	put(buf, len, &n, "{\"app\":\"%s\",\"robot\":\"%s\",\"seconds\":%g,\"mat\":%s}",
	    lv.o->app_name ? lv.o->app_name : "?",
	    lv.o->world != NULL ? lv.o->world->name : ev3sim_robot_name(lv.o->robot), lv.o->seconds, mat);
	pthread_mutex_unlock(&lv.mu);
	return n;
}

ER ev3sim_live_command(const char *cmd, const char *arg)
{
	ER ercd = E_OK;

	pthread_mutex_lock(&lv.mu);
	if (!lv.active || cmd == NULL) {
		ercd = E_OBJ;
	} else if (strcmp(cmd, "press") == 0 || strcmp(cmd, "release") == 0) {
		unsigned b = 0;

		while (b < NBUTTONS && (arg == NULL || strcmp(arg, button_names[b]) != 0))
			b++;
		if (b == NBUTTONS || lv.ninputs == LIVE_INPUTS)
			ercd = E_PAR;
		else
			lv.inputs[lv.ninputs++] = (struct live_input){ b, cmd[0] == 'p' };
	} else if (strcmp(cmd, "pace") == 0) {
		char *end = NULL;
		double pace = arg != NULL ? strtod(arg, &end) : -1.0;

		if (end == arg || end == NULL || *end != '\0' || !(pace >= 0.0 && pace <= EV3SIM_LIVE_MAX_PACE)) {
			ercd = E_PAR;
		} else {
			lv.pace = pace;
			lv.repace = true;
		}
	} else if (strcmp(cmd, "pause") == 0) {
		lv.paused = true;
	} else if (strcmp(cmd, "resume") == 0) {
		lv.paused = false;
		lv.repace = true;
	} else if (strcmp(cmd, "step") == 0) {
		lv.paused = true;
		lv.steps++;
	} else if (strcmp(cmd, "stop") == 0) {
		lv.stop = true;
	} else {
		ercd = E_PAR;
	}
	if (ercd == E_OK)
		pthread_cond_broadcast(&lv.cv);
	pthread_mutex_unlock(&lv.mu);
	return ercd;
}
