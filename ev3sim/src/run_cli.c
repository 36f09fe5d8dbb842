/*
 * run_cli.c — `ev3sim run APP [options]` (run.h): builds the app directory
 * with make into an application runner and executes it with the options;
 * the runner parses them (ev3sim_run_main) and runs the app.
 */
#define _XOPEN_SOURCE 700
#include <errno.h>
#include <limits.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <sys/stat.h>
#include <unistd.h>
#include "t_syslog.h"
#include "ev3sim/brick_io.h"
#include "ev3sim/cli.h"
#include "ev3sim/output.h"
#include "ev3sim/parse.h"
#include "ev3sim/balance_run.h"
#include "ev3sim/plot.h"
#include "ev3sim/live.h"
#include "ev3sim/run.h"
#include "ev3sim/app_build.h"
#include "ev3sim/world_plot.h"

#define MAX_PUSH_NM 5.0

extern char **environ;

/* The world a --world file gave, for the whole run (the process ends with it). */
static struct ev3sim_world *loaded;

static const char run_usage[] =
	"usage: ev3sim run APP_DIR [options]\n"
	"\n"
	"Builds the EV3RT application in APP_DIR (app.c or app.cpp, app.h, app.cfg and\n"
	"an optional Makefile.inc, read as EV3RT's build reads it) against ev3lx and\n"
	"runs it on the simulated brick in a robot, then prints one key=value summary.\n"
	"Times count from power-on.\n"
	"\n"
	"  --lib-dir DIR        EV3RT SDK libraries the app's Makefile.inc includes from\n"
	"                       $(EV3RT_SDK_LIB_DIR)/<lib>/Makefile (e.g. the SDK's\n"
	"                       common/library), beside ev3lx's own (libcpp-ev3), whose\n"
	"                       library of the same name they replace; before the others\n"
	"  --debug              build the app at -O0 (under a build of its own) and show\n"
	"                       the command that runs it under gdb (docs/ev3sim.md)\n"
	"  --kernel K           the kernel profile the app is written for: hrp2 (EV3RT 0.x,\n"
	"                       time in ms), hrp3 (EV3RT 1.x, time in us) or auto (default:\n"
	"                       hrp3 when app.cfg has a CRE_CYC or CRE_ALM in HRP3's\n"
	"                       notification form, or has no time event and the app's\n"
	"                       source waits 100000 or more, as in tslp_tsk(1000000));\n"
	"                       before the others\n"
	"  --robot R            bare, gyroboy or tribot (default bare):\n"
	"                         gyroboy: large motors A (left), D (right), gyro on 2; held\n"
	"                                  upright until --release (when the app drives\n"
	"                                  the wheels), then falls unless balanced\n"
	"                         tribot:  large motors B (left), C (right), touch on 1, colour on 3\n"
	"                                  looking down at a line-following mat, ultrasonic on 4;\n"
	"                                  the touch sensor is pressed at 3 s (unless --touch)\n"
	"  --world W            the robot in a world instead: a built-in one (line: the\n"
	"                       tribot's mat; arena: an open walled floor; maze: walls,\n"
	"                       boxes and cans) or a world file (JSON: the mat image, walls\n"
	"                       and obstacles, the robot's build and start; docs/ev3sim.md);\n"
	"                       its build gives the devices on the ports\n"
	"  --in1 .. --in4 DEV   none, touch, nxt-touch, nxt-light, gyro, color, ultrasonic, ir\n"
	"  --outA .. --outD DEV none, large, medium (override the robot's)\n"
	"  --seconds N          virtual seconds to run (default 10, max 3600)\n"
	"  --seed S             seed of every random stream (default 1)\n"
	"  --touch T[:HOLD]     press the touch sensor at T for HOLD (default 300ms); may repeat\n"
	"  --click BUTTON:T     click left|right|up|down|enter|back at T (held 100 ms); may repeat\n"
	"  --release WHEN       gyroboy: when the hand lets go: drive (default: when the app\n"
	"                       first drives a wheel motor, so a balancer calibrates first)\n"
	"                       or a time T (let go at T, driven or not)\n"
	"  --tilt DEG           gyroboy: tilt when let go (default 0.5)\n"
	"  --gyro-noise SIGMA   white noise on every gyro sample, deg/s (default 0.15, an EV3\n"
	"                       gyro at rest, for the gyro boy's gyro; 0 for one --in names)\n"
	"  --push T:NM          gyroboy: pitch torque NM (N m) for 100 ms at T; may repeat\n"
	"  --place T:MM         tribot: the hand puts the robot down MM mm to its left\n"
	"                       (negative: right) at T, same heading (e.g. to show a\n"
	"                       calibrating app white, then black); may repeat\n"
	"  --fault SPEC         inject a fault (as ev3sim balance --help lists; uart faults go to\n"
	"                       the first UART sensor, times from power-on); may repeat\n"
	"  --sd DIR             the SD card: ev3_memfile_load and ev3_sdcard_* see DIR (and\n"
	"                       nothing outside it)\n"
	"  --serial PATH        the serial port (EV3_SERIAL_DEFAULT, EV3_SERIAL_UART): a file\n"
	"                       receives what the app writes; a pseudo-terminal or FIFO\n"
	"                       carries both directions\n"
	"  --bt PATH            Bluetooth SPP: a Unix socket at PATH; a program connected to it\n"
	"                       is the paired PC or brick (EV3_SERIAL_BT, SIO_PORT_BT,\n"
	"                       ev3_bluetooth_is_connected)\n"
	"  --bt-master PATH     the remote slave the brick connects to as SPP master\n"
	"                       (SIO_PORT_SPP_MASTER_TEST): a program listening on a Unix\n"
	"                       socket at PATH, e.g. another ev3sim run's --bt\n"
	"  --usb PATH           USB CDC: a Unix socket at PATH; a program connected to it is\n"
	"                       the PC the brick is plugged into (EV3_SERIAL_USB_CDC,\n"
	"                       SIO_PORT_USB_CDC, ev3_usb_cdc_is_connected)\n"
	"  --trace FILE.vcd     host_sim's signal trace\n"
	"  --audio FILE.wav     what the speaker played (32 kHz, 16-bit mono)\n"
	"  --lcd FILE.png       the display's last frame (178 x 128, grey)\n"
	"  --lcd-video FILE.gif the display over time: a frame per change, sampled every 10 ms\n"
	"  --csv FILE           the robot's state every 10 ms\n"
	"  --plot FILE.png      with a world (or the tribot): the path on the mat and signals\n"
	"                       against time (gnuplot)\n"
	"  --plot-signals LIST  the plot's signals: heading, in1..in4, left, right,\n"
	"                       clearance (default: heading and the robot's sensors)\n"
	"  --quiet              the console shows warnings and worse only\n"
	"  --live[=PORT]        watch and steer the run in a browser: a page on\n"
	"                       http://127.0.0.1:PORT/ (default 8033; 0: any free port,\n"
	"                       the address is printed on stderr) with the mat and the\n"
	"                       robot, the display, LEDs, buttons to click, the ports and\n"
	"                       a plot; pause, single steps, pace\n"
	"  --pace N|fast        with --live: at most N times real time (default 1), or as\n"
	"                       fast as it goes\n"
	"\n"
	"Summary: app, robot, seconds, seed, the world's figures (gyroboy: result, fell_at_s,\n"
	"max_tilt_deg; tribot: line_progress_m, travel_m, max/rms_line_error_mm, on_line_pct;\n"
	"a world: world, x_m, y_m, heading_deg, travel_m, contacts, min_clearance_mm, goal_at_s),\n"
	"syslog line counts, bugs, sim_speed.\n";

static const char *const button_names[] = { "left", "right", "up", "down", "enter", "back" };

static int usage(const char *fmt, const char *what)
{
	fprintf(stderr, "ev3sim run: ");
	fprintf(stderr, fmt, what);
	fprintf(stderr, "\n(ev3sim run --help lists the options)\n");
	return EV3SIM_EXIT_USAGE;
}

/* Splits "A:B" at the first ':' into a (copied) and b; false if too long. */
static bool split_colon(const char *v, char *a, size_t alen, const char **b)
{
	const char *colon = strchr(v, ':');
	size_t n = colon ? (size_t)(colon - v) : strlen(v);

	if (n >= alen)
		return false;
	memcpy(a, v, n);
	a[n] = '\0';
	*b = colon ? colon + 1 : NULL;
	return true;
}

/* The first port with a UART sensor (where uart-* faults go), else 0. */
static unsigned first_uart_port(const struct ev3sim_run_opts *o)
{
	for (unsigned p = 0; p < 4; p++)
		if (o->in[p] == EV3SIM_IN_GYRO || o->in[p] == EV3SIM_IN_COLOR ||
		    o->in[p] == EV3SIM_IN_ULTRASONIC || o->in[p] == EV3SIM_IN_IR)
			return p;
	return 0;
}

/* One option with its value v; EV3SIM_EXIT_OK or a usage error. */
static int run_option(struct ev3sim_run_opts *o, const char *name, const char *v, bool *touch_given,
		      const char **csv_path)
{
	char head[64], err[256];
	const char *tail;

	if (strcmp(name, "--robot") == 0) {
		enum ev3sim_robot_kind k;

		if (!ev3sim_robot_parse(v, &k))
			return usage("--robot: bad value '%s' (bare, gyroboy or tribot)", v);
	} else if (strncmp(name, "--in", 4) == 0 && name[4] >= '1' && name[4] <= '4' && name[5] == '\0') {
		if (!ev3sim_input_device_parse(v, &o->in[name[4] - '1']))
			return usage("bad input device '%s' (none, touch, nxt-touch, nxt-light, gyro, "
				     "color, ultrasonic, ir, ht-accel, ht-color, nxt-temp)", v);
	} else if (strncmp(name, "--out", 5) == 0 && name[5] >= 'A' && name[5] <= 'D' && name[6] == '\0') {
		if (!ev3sim_output_device_parse(v, &o->out[name[5] - 'A']))
			return usage("bad output device '%s' (none, large, medium)", v);
	} else if (strcmp(name, "--seconds") == 0) {
		if (!ev3sim_parse_double(v, &o->seconds) || !(o->seconds > 0) ||
		    o->seconds > EV3SIM_MAX_SECONDS)
			return usage("--seconds: bad value '%s' (0 < N <= 3600)", v);
	} else if (strcmp(name, "--seed") == 0) {
		if (!ev3sim_parse_uint(v, UINT64_MAX, &o->seed))
			return usage("--seed: bad value '%s' (an unsigned integer)", v);
	} else if (strcmp(name, "--touch") == 0) {
		struct ev3sim_action a = { .touch = true, .hold_ns = 300000000ULL };

		if (!*touch_given)
			o->nactions = 0;    /* the first --touch replaces the robot's default press */
		*touch_given = true;
		if (o->nactions == EV3SIM_RUN_MAX_ACTIONS)
			return usage("%s: too many actions (16)", "--touch");
		if (!split_colon(v, head, sizeof(head), &tail) || !ev3sim_parse_time(head, &a.t_ns) ||
		    (tail && (!ev3sim_parse_time(tail, &a.hold_ns) || a.hold_ns == 0)))
			return usage("--touch: bad value '%s' (T[:HOLD], e.g. 2s:500ms)", v);
		o->actions[o->nactions++] = a;
	} else if (strcmp(name, "--click") == 0) {
		struct ev3sim_action a = { .touch = false, .hold_ns = 100000000ULL, .button = 99 };

		if (o->nactions == EV3SIM_RUN_MAX_ACTIONS)
			return usage("%s: too many actions (16)", "--click");
		if (split_colon(v, head, sizeof(head), &tail))
			for (unsigned b = 0; b < sizeof(button_names) / sizeof(button_names[0]); b++)
				if (strcmp(head, button_names[b]) == 0)
					a.button = b;
		if (a.button == 99 || tail == NULL || !ev3sim_parse_time(tail, &a.t_ns))
			return usage("--click: bad value '%s' (BUTTON:T, e.g. enter:2s)", v);
		o->actions[o->nactions++] = a;
	} else if (strcmp(name, "--release") == 0) {
		if (strcmp(v, "drive") == 0) {
			o->release_ns = 0;
			o->release_on_drive = true;
		} else if (ev3sim_parse_time(v, &o->release_ns)) {
			o->release_on_drive = false;
		} else {
			return usage("--release: bad value '%s' (drive, or a time, e.g. 4s)", v);
		}
	} else if (strcmp(name, "--tilt") == 0) {
		if (!ev3sim_parse_double(v, &o->start_tilt_deg) || fabs(o->start_tilt_deg) >= 30.0)
			return usage("--tilt: bad value '%s' (|DEG| < 30)", v);
	} else if (strcmp(name, "--gyro-noise") == 0) {
		if (!ev3sim_parse_double(v, &o->gyro_noise_dps) || !(o->gyro_noise_dps >= 0) ||
		    o->gyro_noise_dps > EV3SIM_MAX_GYRO_NOISE_DPS)
			return usage("--gyro-noise: bad value '%s' (0..1000 deg/s)", v);
	} else if (strcmp(name, "--push") == 0) {
		double nm;

		if (o->npushes == EV3SIM_MAX_PUSHES)
			return usage("%s: too many pushes (16)", "--push");
		if (!split_colon(v, head, sizeof(head), &tail) || tail == NULL ||
		    !ev3sim_parse_time(head, &o->pushes[o->npushes].t_ns) ||
		    !ev3sim_parse_double(tail, &nm) || fabs(nm) > MAX_PUSH_NM)
			return usage("--push: bad value '%s' (T:NM, |NM| <= 5 N m)", v);
		o->pushes[o->npushes++].torque_nm = nm;
	} else if (strcmp(name, "--place") == 0) {
		double mm;

		if (o->nplacements == EV3SIM_MAX_PLACEMENTS)
			return usage("%s: too many placements (16)", "--place");
		if (!split_colon(v, head, sizeof(head), &tail) || tail == NULL ||
		    !ev3sim_parse_time(head, &o->placements[o->nplacements].t_ns) ||
		    !ev3sim_parse_double(tail, &mm) || !(fabs(mm) <= EV3SIM_MAX_PLACE_MM))
			return usage("--place: bad value '%s' (T:MM, |MM| <= 2000)", v);
		o->placements[o->nplacements++].left_mm = mm;
	} else if (strcmp(name, "--fault") == 0) {
		if (o->nfaults == EV3SIM_RUN_MAX_FAULTS)
			return usage("%s: too many faults (16)", "--fault");
		if (!ev3sim_fault_parse(v, first_uart_port(o), &o->faults[o->nfaults], err, sizeof(err)))
			return usage("--fault: %s", err);
		o->nfaults++;
	} else if (strcmp(name, "--trace") == 0) {
		if (!ev3sim_can_create("run", v))	/* checked before the run, not after it */
			return EV3SIM_EXIT_FAIL;
		o->trace_path = v;
	} else if (strcmp(name, "--audio") == 0) {
		o->audio_path = v;     /* streamed: opened at the boot (wav_out.h) */
	} else if (strcmp(name, "--lcd") == 0) {
		if (!ev3sim_lcd_png_writer)
			return usage("%s: this program has no PNG writer (the 32-bit ev3sim links no libpng: build/host/ev3sim has it)", "--lcd");
		if (!ev3sim_can_create("run", v))
			return EV3SIM_EXIT_FAIL;
		o->lcd_path = v;
	} else if (strcmp(name, "--lcd-video") == 0) {
		if (!ev3sim_lcd_video)
			return usage("%s: this program has no GIF writer (the 32-bit ev3sim links no giflib: build/host/ev3sim has it)", "--lcd-video");
		if (!ev3sim_can_create("run", v))
			return EV3SIM_EXIT_FAIL;
		o->lcd_video_path = v;
	} else if (strcmp(name, "--sd") == 0) {
		struct stat st;

		if (stat(v, &st) != 0 || !S_ISDIR(st.st_mode))
			return usage("--sd: '%s' is not a directory", v);
		o->sd_dir = v;
	} else if (strcmp(name, "--serial") == 0) {
		o->serial_path = v;
	} else if (strcmp(name, "--bt") == 0) {
		o->bt_path = v;
	} else if (strcmp(name, "--bt-master") == 0) {
		o->bt_master_path = v;
	} else if (strcmp(name, "--usb") == 0) {
		o->usb_path = v;
	} else if (strcmp(name, "--csv") == 0) {
		*csv_path = v;
	} else if (strcmp(name, "--world") == 0) {
		/* read before the others (ev3sim_run_main) */
	} else if (strcmp(name, "--plot") == 0) {
		if (o->world == NULL && o->robot != EV3SIM_ROBOT_TRIBOT)
			return usage("%s: needs a world (--world, or --robot tribot)", "--plot");
		if (!ev3sim_have_gnuplot()) {
			fprintf(stderr, "ev3sim run: --plot: gnuplot not found on PATH (install gnuplot-nox: make deps)\n");
			return EV3SIM_EXIT_FAIL;
		}
		if (!ev3sim_can_create("run", v))
			return EV3SIM_EXIT_FAIL;
		o->plot_path = v;
	} else if (strcmp(name, "--plot-signals") == 0) {
		if (!ev3sim_plot_signals_parse(v, &o->plot_signals, err, sizeof(err)))
			return usage("--plot-signals: %s", err);
	} else if (strcmp(name, "--live") == 0) {
		uint64_t port;

		if (!ev3sim_parse_uint(v, 65535, &port))
			return usage("--live: bad port '%s' (0..65535; 0: any free port)", v);
		o->live = true;
		o->live_port = (unsigned)port;
	} else if (strcmp(name, "--pace") == 0) {
		if (strcmp(v, "fast") == 0)
			o->pace = 0.0;
		else if (!ev3sim_parse_double(v, &o->pace) || !(o->pace > 0.0 && o->pace <= EV3SIM_LIVE_MAX_PACE))
			return usage("--pace: bad value '%s' (0 < N <= 1000 times real time, or fast)", v);
	} else {
		return usage("unknown option %s", name);
	}
	return EV3SIM_EXIT_OK;
}

int ev3sim_run_main(int argc, char **argv, const char *app_name, const struct rtos_cfg *app)
{
	enum ev3sim_robot_kind robot = EV3SIM_ROBOT_BARE;
	const struct ev3sim_world *world = NULL;
	struct ev3sim_run_opts o;
	struct ev3sim_run_result r;
	const char *csv_path = NULL;
	bool touch_given = false, quiet = false, pace_given = false;
	char err[1536], line[1024];
	int status = EV3SIM_EXIT_OK;

	/* the robot first: its devices are the defaults the other options change */
	for (int i = 1; i < argc; i++) {
		if (strcmp(argv[i], "--help") == 0 || strcmp(argv[i], "-h") == 0) {
			fputs(run_usage, stdout);
			return ev3sim_finish_stdout("run", EV3SIM_EXIT_OK);
		}
		if (strcmp(argv[i], "--robot") == 0 && i + 1 < argc && !ev3sim_robot_parse(argv[i + 1], &robot))
			return usage("--robot: bad value '%s' (bare, gyroboy or tribot)", argv[i + 1]);
		if (strncmp(argv[i], "--robot=", 8) == 0 && !ev3sim_robot_parse(argv[i] + 8, &robot))
			return usage("--robot: bad value '%s' (bare, gyroboy or tribot)", argv[i] + 8);
	}
	for (int i = 1; i < argc; i++) {
		const char *v = NULL;

		if (strcmp(argv[i], "--world") == 0 && i + 1 < argc)
			v = argv[i + 1];
		else if (strncmp(argv[i], "--world=", 8) == 0)
			v = argv[i] + 8;
		if (v == NULL)
			continue;
		if (robot != EV3SIM_ROBOT_BARE)
			return usage("--world: the world gives the robot (not with --robot %s)", ev3sim_robot_name(robot));
		world = ev3sim_world_builtin(v);
		if (world != NULL)
			continue;
		if (strchr(v, '/') == NULL && strchr(v, '.') == NULL) {
			fprintf(stderr, "ev3sim run: --world: '%s' is neither a built-in world (%s) nor a file\n"
				"(ev3sim run --help lists the options)\n", v, ev3sim_world_builtin_names);
			return EV3SIM_EXIT_USAGE;
		}
		if (!ev3sim_world_file_reader)
			return usage("--world: this program has no world file reader (the 32-bit ev3sim links no "
				     "json-c or libpng: build/host/ev3sim has it); '%s'", v);
		world = loaded = ev3sim_world_file_reader(v, err, sizeof(err));
		if (world == NULL) {
			fprintf(stderr, "ev3sim run: --world: %s\n", err);
			return EV3SIM_EXIT_USAGE;
		}
	}
	if (world != NULL)
		ev3sim_run_defaults_world(&o, world);
	else
		ev3sim_run_defaults(&o, robot);
	o.app_name = app_name;
	for (int i = 1; i < argc; i++) {
		char name[64];
		const char *eq = strchr(argv[i], '='), *v;
		int st;

		if (strcmp(argv[i], "--quiet") == 0) {
			quiet = true;
			continue;
		}
		if (strcmp(argv[i], "--live") == 0) {     /* its port is optional: --live=PORT */
			o.live = true;
			o.live_port = EV3SIM_LIVE_DEFAULT_PORT;
			continue;
		}
		if (strncmp(argv[i], "--", 2) != 0)
			return usage("unexpected argument '%s'", argv[i]);
		if (eq != NULL && (size_t)(eq - argv[i]) < sizeof(name)) {
			memcpy(name, argv[i], (size_t)(eq - argv[i]));
			name[eq - argv[i]] = '\0';
			v = eq + 1;
		} else if (strlen(argv[i]) < sizeof(name) && i + 1 < argc) {
			strcpy(name, argv[i]);
			v = argv[++i];
		} else {
			return usage("%s needs a value (or is unknown)", argv[i]);
		}
		pace_given |= strcmp(name, "--pace") == 0;
		st = run_option(&o, name, v, &touch_given, &csv_path);
		if (st != EV3SIM_EXIT_OK)
			return st;
	}
	if (pace_given && !o.live)
		return usage("%s: only with --live (a run without it goes as fast as it can)", "--pace");
	if (csv_path && (o.csv = ev3sim_open_output("run", csv_path)) == NULL)
		return EV3SIM_EXIT_FAIL;
	o.quiet = quiet;
	if (ev3sim_run(&o, app, &r, err, sizeof(err)) != E_OK) {
		fprintf(stderr, "ev3sim run: %s\n", err);
		status = r.end_status != 0 ? r.end_status : EV3SIM_EXIT_FAIL;
	} else {
		ev3sim_run_summary(&o, &r, line, sizeof(line));
		printf("%s\n", line);
	}
	if (o.serial_path && brick_io_serial_write_errno() != 0) {
		fprintf(stderr, "ev3sim run: cannot write --serial %s: %s\n", o.serial_path,
			strerror(brick_io_serial_write_errno()));
		status = EV3SIM_EXIT_FAIL;
	}
	if (o.csv && !ev3sim_close_output("run", o.csv, csv_path))
		status = EV3SIM_EXIT_FAIL;
	return ev3sim_finish_stdout("run", status);
}

/* The source tree, and the configuration an app is built for: ev3sim is
 * build/CONFIG/ev3sim in the tree; host32's builds apps for host32 (the
 * target's 32-bit types), every other one (host, host-pgo) for host. */
static bool source_root(char *root, size_t len, const char **config)
{
	char exe[PATH_MAX];
	ssize_t n = readlink("/proc/self/exe", exe, sizeof(exe) - 1);

	if (n <= 0)
		return false;
	exe[n] = '\0';
	*config = "host";
	for (int up = 0; up < 3; up++) {
		char *slash = strrchr(exe, '/');

		if (slash == NULL)
			return false;
		if (up == 1 && strcmp(slash + 1, "host32") == 0)
			*config = "host32";
		*slash = '\0';
	}
	if (strlen(exe) >= len)
		return false;
	strcpy(root, exe);
	return true;
}

/* Removes every flag (an option without a value) from argv[1..*argc) where it
 * stands as an option, not as another option's value; true if there was one. */
static bool take_flag(int *argc, char **argv, const char *flag)
{
	bool found = false;
	int out = 1;

	for (int i = 1; i < *argc; i++) {
		const char *prev = out > 1 ? argv[out - 1] : "";
		bool is_value = strncmp(prev, "--", 2) == 0 && strchr(prev, '=') == NULL &&
				strcmp(prev, "--quiet") != 0 && strcmp(prev, "--live") != 0;

		if (!is_value && strcmp(argv[i], flag) == 0) {
			found = true;
			continue;
		}
		argv[out++] = argv[i];
	}
	*argc = out;
	return found;
}

int ev3sim_run_command(int argc, char **argv)
{
	char root[PATH_MAX], app[PATH_MAX], runner[2 * PATH_MAX + 64], err[2 * PATH_MAX + 128];
	char cfg_path[PATH_MAX + 16], lib_dir[PATH_MAX];
	const char *config;
	const char *kernel = NULL;
	bool have_lib_dir = false, debug;
	struct stat st;
	char **args;
	int runner_fd;

	if (argc < 1 || strcmp(argv[0], "--help") == 0 || strcmp(argv[0], "-h") == 0) {
		fputs(run_usage, argc < 1 ? stderr : stdout);
		return argc < 1 ? EV3SIM_EXIT_USAGE : ev3sim_finish_stdout("run", EV3SIM_EXIT_OK);
	}
	if (realpath(argv[0], app) == NULL || stat(app, &st) != 0 || !S_ISDIR(st.st_mode))
		return usage("'%s' is not an application directory", argv[0]);
	snprintf(cfg_path, sizeof(cfg_path), "%s/app.cfg", app);
	if (access(cfg_path, R_OK) != 0)
		return usage("'%s' has no app.cfg", argv[0]);
	if (!source_root(root, sizeof(root), &config)) {
		fprintf(stderr, "ev3sim run: cannot find the ev3lx source tree\n");
		return EV3SIM_EXIT_FAIL;
	}
	/* the build's options; the runner gets the others */
	debug = take_flag(&argc, argv, "--debug");
	while (argc >= 2 && (strcmp(argv[1], "--lib-dir") == 0 || strcmp(argv[1], "--kernel") == 0)) {
		if (argc < 3)
			return usage("%s needs a value", argv[1]);
		if (strcmp(argv[1], "--lib-dir") == 0) {
			if (realpath(argv[2], lib_dir) == NULL || stat(lib_dir, &st) != 0 || !S_ISDIR(st.st_mode))
				return usage("--lib-dir '%s' is not a directory", argv[2]);
			have_lib_dir = true;
		} else if (strcmp(argv[2], "auto") == 0 || strcmp(argv[2], "hrp2") == 0 || strcmp(argv[2], "hrp3") == 0) {
			kernel = argv[2];
		} else {
			return usage("--kernel '%s': expected hrp2, hrp3 or auto", argv[2]);
		}
		argv[2] = argv[0];
		argv += 2;
		argc -= 2;
	}
	runner_fd = ev3sim_app_build(root, config, app, have_lib_dir ? lib_dir : NULL, kernel, debug, runner,
				     sizeof(runner), err, sizeof(err));
	if (runner_fd < 0) {
		fprintf(stderr, "ev3sim run: %s\n", err);
		return EV3SIM_EXIT_FAIL;
	}
	args = calloc((size_t)argc + 1, sizeof(*args));
	if (args == NULL) {
		close(runner_fd);
		return EV3SIM_EXIT_FAIL;
	}
	args[0] = runner;
	for (int i = 1; i < argc; i++)
		args[i] = argv[i];
	if (debug) {
		/* the command that runs the same under gdb, with the project's task list */
		fprintf(stderr, "ev3sim run: built at -O0 for gdb: gdb -x %s/tools/gdb/ev3lx-tasks.py --args %s",
			root, runner);
		for (int i = 1; i < argc; i++)
			fprintf(stderr, " %s", argv[i]);
		fputc('\n', stderr);
	}
	fflush(stdout);
	fexecve(runner_fd, args, environ);
	fprintf(stderr, "ev3sim run: cannot execute %s: %s\n", runner, strerror(errno));
	close(runner_fd);
	free(args);
	return EV3SIM_EXIT_FAIL;
}
