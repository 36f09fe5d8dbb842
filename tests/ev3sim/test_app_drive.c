/*
 * test_app_drive.c — the sensors of a robot in a world read what its pose
 * gives them, through the whole stack (tests/ev3sim/apps/drive, an EV3RT
 * app): on a mat image of stripes the colour sensor sees white, black, red
 * and blue in turn; the ultrasonic sensor sees the wall ahead by ray casting
 * (255 cm when there is none); the robot stops at the wall and its bumper is
 * pressed until it backs off; the gyro follows its spin (clockwise
 * positive), and a gyro drift fault takes it off; wheel slip shortens the
 * way the same wheel turns make.  The command line's --world, --plot and
 * --plot-signals refuse what they cannot do, naming it.
 */
#include "ev3sim_test.h"
#include <math.h>
#include "ev3sim/run.h"
#include "ev3sim/world.h"

extern const struct rtos_cfg ev3rt_app_cfg;

#define MAT_W_PX 200            /* 1 cm a pixel */
#define MAT_H_PX 60
#define MAX_LINES 32

static uint8_t stripes[MAT_H_PX][MAT_W_PX][3];
static char lines[MAX_LINES][160];
static unsigned nlines;

/* Keeps the app's NOTICE lines. */
static void sink(const char *line, void *ctx)
{
	(void)ctx;
	if (strncmp(line, "NOTICE: drive: ", 15) == 0 && nlines < MAX_LINES)
		snprintf(lines[nlines++], sizeof(lines[0]), "%s", line + 15);
}

/* The first logged line starting with prefix, or NULL. */
static const char *logged(const char *prefix)
{
	for (unsigned i = 0; i < nlines; i++)
		if (strncmp(lines[i], prefix, strlen(prefix)) == 0)
			return lines[i];
	return NULL;
}

/* A 2 x 0.6 m mat: white, with stripes across the way from x = 0.5 m:
 * black, red and blue, 0.2 m each. */
static void paint(void)
{
	static const uint8_t colours[3][3] = { { 0, 0, 0 }, { 255, 0, 0 }, { 0, 0, 255 } };

	for (int y = 0; y < MAT_H_PX; y++)
		for (int x = 0; x < MAT_W_PX; x++) {
			int stripe = x < 50 ? -1 : (x - 50) / 20;

			memcpy(stripes[y][x], stripe >= 0 && stripe < 3 ? colours[stripe] : (const uint8_t[3]){ 255, 255, 255 }, 3);
		}
}

/* The test's world: the stripes, a wall across at x = 1.5 m (or none), the
 * robot at (0.2, 0.3) heading +x with a bumper, gyro, colour and ultrasonic. */
static void make_world(struct ev3sim_world *w, bool wall, double slip)
{
	memset(w, 0, sizeof(*w));
	snprintf(w->name, sizeof(w->name), "stripes");
	w->mat = (struct ev3sim_world_mat){ .kind = EV3SIM_MAT_IMAGE, .width = 2.0, .height = 0.6,
					    .px_w = MAT_W_PX, .px_h = MAT_H_PX, .pixels = &stripes[0][0][0] };
	if (wall)
		w->obstacles[w->nobstacles++] = (struct ev3sim_obstacle){ .kind = EV3SIM_OBST_SEGMENT, .x0 = 1.5,
									 .y0 = 0, .x1 = 1.5, .y1 = 0.6, .height = 0.2 };
	w->robot = (struct ev3sim_world_robot){
		.wheel_radius = 0.028, .track = 0.12, .mass = 0.75, .body_radius = 0.09, .rolling_crr = 0.03,
		.left_port = 1, .right_port = 2, .motor = EV3SIM_OUT_LARGE, .slip = slip,
		.mounts = {
			{ .port = 0, .device = EV3SIM_IN_TOUCH, .x = 0.105, .height = 0.03 },
			{ .port = 1, .device = EV3SIM_IN_GYRO, .height = 0.06 },
			{ .port = 2, .device = EV3SIM_IN_COLOR, .x = 0.08, .height = 0.008, .footprint = 0.012 },
			{ .port = 3, .device = EV3SIM_IN_ULTRASONIC, .x = 0.06, .height = 0.08,
			  .beam = EV3SIM_US_BEAM_DEG * 3.14159265358979 / 180 },
		},
		.nmounts = 4,
	};
	w->start_x = 0.2;
	w->start_y = 0.3;
}

/* Runs the app in w for 15 s (with fault, a --fault spec, or NULL); false if it could not run. */
static bool drive(const struct ev3sim_world *w, const char *fault, struct ev3sim_run_result *r)
{
	struct ev3sim_run_opts o;
	char err[256];

	ev3sim_run_defaults_world(&o, w);
	o.app_name = "drive";
	o.seconds = 15;
	o.log_sink = sink;
	o.quiet = true;
	if (fault != NULL && !ev3sim_fault_parse(fault, 1, &o.faults[o.nfaults++], err, sizeof(err))) {
		tap_diag("fault %s: %s", fault, err);
		return false;
	}
	nlines = 0;
	if (ev3sim_run(&o, &ev3rt_app_cfg, r, err, sizeof(err)) != E_OK) {
		tap_diag("run failed: %s", err);
		return false;
	}
	for (unsigned i = 0; i < nlines; i++)
		tap_diag("%s", lines[i]);
	return true;
}

static struct et_run cli;

static int drive_main(int argc, char **argv)
{
	return ev3sim_run_main(argc, argv, "drive", &ev3rt_app_cfg);
}

/* Runs the command line with args; whether it exited with status and said text on stderr (or stdout). */
static bool cli_says(const char *const *args, int status, const char *text)
{
	if (!et_run_main(&cli, args, drive_main, NULL))
		return false;
	if (cli.status != status || (strstr(cli.err, text) == NULL && strstr(cli.out, text) == NULL)) {
		tap_diag("status %d, stderr: %s", cli.status, cli.err);
		return false;
	}
	return true;
}

/* The command line's refusals, and a run in a built-in world. */
static void command_line(void)
{
	static const char *const nowhere[] = { "--world", "nowhere", NULL };
	static const char *const both[] = { "--robot", "tribot", "--world", "maze", NULL };
	static const char *const plot[] = { "--plot", "x.png", NULL };
	static const char *const signals[] = { "--world", "maze", "--plot-signals", "heading,speed", NULL };
	static const char *const file[] = { "--world", "/nonexistent/w.json", NULL };
	static const char *const arena[] = { "--world", "arena", "--seconds", "3", "--quiet", NULL };

	ok(cli_says(nowhere, EV3SIM_EXIT_USAGE, "--world: 'nowhere' is neither a built-in world (line, arena, maze) nor a file"),
	   "--world nowhere: not built in, and no file");
	ok(cli_says(both, EV3SIM_EXIT_USAGE, "--world: the world gives the robot (not with --robot tribot)"),
	   "--world with --robot tribot is refused");
	ok(cli_says(plot, EV3SIM_EXIT_USAGE, "--plot: needs a world (--world, or --robot tribot)"),
	   "--plot without a world is refused");
	ok(cli_says(signals, EV3SIM_EXIT_USAGE, "--plot-signals: unknown signal 'speed'"), "an unknown signal is named");
	ok(cli_says(file, EV3SIM_EXIT_USAGE, ev3sim_world_file_reader ? "/nonexistent/w.json: cannot open: No such file"
				  : "this program has no world file reader"),
	   "a world file that is not there is named (or refused where no reader is linked)");
	ok(cli_says(arena, 0, "robot=world seconds=3 seed=1 world=arena x_m="),
	   "a run in the arena says so in its summary");
}

int main(void)
{
	struct ev3sim_world w;
	struct ev3sim_run_result r;
	const struct ev3sim_world_state *s;
	const char *line;
	int cm, t, bumper, wheels, gyro, reflect, colors[8], ncolors = 0;
	double plain_travel, heading;

	paint();
	make_world(&w, true, 0.0);
	if (!ok(drive(&w, NULL, &r), "the app drives 15 s in a world with a wall"))
		return tap_done();
	s = ev3sim_world_now();
	line = logged("ahead ");
	cm = 0;
	if (line)
		(void)sscanf(line, "ahead %d cm", &cm);
	ok(cm == 124,
	   "the ultrasonic sensor 60 mm ahead of the axle at x = 0.2 m sees the wall at 1.5 m: 124 cm (%s)",
	   line ? line : "nothing logged");
	/* the colours it saw for 50 ms or more: straddling an edge the spot
	 * sees a mix for a moment (brown here), as a real sensor does */
	for (unsigned i = 0; i < nlines; i++) {
		int c, next_t = 1 << 30, c2, t2;

		if (sscanf(lines[i], "color %d at %d ms", &c, &t) != 2)
			continue;
		if (i + 1 < nlines && sscanf(lines[i + 1], "color %d at %d ms", &c2, &t2) == 2)
			next_t = t2;
		if (next_t - t >= 50 && ncolors < 8)
			colors[ncolors++] = c;
	}
	ok(ncolors == 5 && colors[0] == 6 && colors[1] == 1 && colors[2] == 5 && colors[3] == 2 && colors[4] == 6,
	   "the colour sensor sees white, black, red, blue and white again as it crosses the stripes (%d colours)",
	   ncolors);
	line = logged("stopped ");
	t = bumper = cm = wheels = 0;
	ok(line && sscanf(line, "stopped at %d ms, bumper %d, ahead %d cm, wheels %d deg", &t, &bumper, &cm, &wheels) == 4,
	   "it stopped: %s", line ? line : "nothing logged");
	ok(line && bumper == 1 && t < 8000, "the bumper was pressed at the wall, before the time ran out (%d ms)", t);
	ok(line && cm >= 3 && cm <= 6, "the wall is 3..6 cm ahead of the ultrasonic sensor then (%d cm)", cm);
	ok(s->contacts >= 1, "the world counted the contact (%u)", s->contacts);
	ok(s->min_clearance_m >= 0, "the body never went into the wall (least clearance %.4f m)", s->min_clearance_m);
	line = logged("backed off");
	ok(line && strcmp(line, "backed off, bumper 0") == 0, "backing off releases the bumper (%s)", line ? line : "-");
	line = logged("spun");
	gyro = reflect = 0;
	ok(line && sscanf(line, "spun, gyro %d deg, reflect %d", &gyro, &reflect) == 2, "it spun: %s",
	   line ? line : "nothing logged");
	heading = s->heading_deg;
	ok(line && heading > 60 && fabs(gyro + heading) <= 2.0,
	   "the gyro follows the spin: %d deg clockwise for %.1f deg counter-clockwise", gyro, heading);
	ok(line && reflect == EV3SIM_WHITE_PCT, "the colour sensor sees white there: %d%%", reflect);
	is_int(r.warnings + r.errors + r.bugs, 0, "no warnings, errors or bugs");

	if (ok(drive(&w, "gyro-drift:2", &r), "with a gyro drift of 2 deg/s")) {
		line = logged("spun");
		gyro = 0;
		if (line)
			(void)sscanf(line, "spun, gyro %d deg", &gyro);
		ok(line && fabs(gyro + ev3sim_world_now()->heading_deg) > 10.0,
		   "the gyro drifts off the heading: %d deg for %.1f deg", gyro, ev3sim_world_now()->heading_deg);
	} else {
		tap_skip(1, "no run");
	}

	make_world(&w, false, 0.0);
	if (ok(drive(&w, NULL, &r), "without the wall")) {
		line = logged("ahead ");
		ok(line && strcmp(line, "ahead 255 cm") == 0, "the ultrasonic sensor reads 255 cm: nothing in range (%s)",
		   line ? line : "-");
		line = logged("stopped ");
		t = bumper = 0;
		if (line)
			(void)sscanf(line, "stopped at %d ms, bumper %d", &t, &bumper);
		ok(t == 8000 && bumper == 0,
		   "it drives the whole 8 s, the bumper never pressed (%s)", line ? line : "-");
		is_int(ev3sim_world_now()->contacts, 0, "no contact");
	} else {
		tap_skip(3, "no run");
	}
	plain_travel = r.travel_m;

	make_world(&w, false, 0.3);
	if (ok(drive(&w, NULL, &r), "with 30 %% wheel slip")) {
		ok(r.travel_m < 0.85 * plain_travel && r.travel_m > 0.5 * plain_travel,
		   "the same drive takes it %.2f m instead of %.2f m", r.travel_m, plain_travel);
	} else {
		tap_skip(1, "no run");
	}
	command_line();
	return tap_done();
}
