/*
 * cli.c — ev3sim's command line (cli.h): `balance`, `motor`, `sensors`.
 *
 * Options take their value as the next argument or after '=' (--seconds 30,
 * --seconds=30).  Every bad option or value is named in a message on stderr
 * and exits with status 2; --help prints the command's usage and exits 0.
 */
#define _POSIX_C_SOURCE 200809L
#include <errno.h>
#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>
#include "ev3sim/apps.h"
#include "ev3sim/balance_run.h"
#include "ev3sim/cli.h"
#include "ev3sim/output.h"
#include "ev3sim/parse.h"
#include "ev3sim/plot.h"
#include "ev3sim/run.h"
#include "ev3sim/serial_log.h"
#include "host_sim/devices/uart_sensor.h"

#define MAX_PUSH_NM		5.0       /* largest push torque, N m */
#define MAX_START_TILT_DEG	30.0      /* tilt when let go, exclusive */
#define MIN_LOG_BAUD		300U
#define MAX_LOG_BAUD		4000000U

static const char main_usage[] =
	"usage: ev3sim COMMAND [options]      (ev3sim COMMAND --help for its options)\n"
	"\n"
	"Runs an application on the simulated EV3 in virtual time: the EV3 API, the\n"
	"extended service calls, the reused Linux drivers, linux_compat, the RTOS and\n"
	"the simulated registers and devices.\n"
	"\n"
	"commands:\n"
	"  balance   the self-balancing robot (gyro boy) with a gyro logger\n"
	"  motor     run one motor and print its speed and counts\n"
	"  sensors   plug in sensors and motors, print what the drivers detect and live values\n"
	"  run       build an EV3RT application directory and run it in a robot\n";

static const char balance_usage[] =
	"usage: ev3sim balance [options]\n"
	"\n"
	"The paper's experiment: a two-wheeled robot balanced by a 4 ms task while a\n"
	"lower-priority task logs the gyro to a serial port.  The robot is held for\n"
	"the first 3 s (the application calibrates its gyro), then let go; times below\n"
	"count from that release.  Prints one key=value summary line.\n"
	"\n"
	"  --seconds N          virtual seconds after the release (default 10, max 3600)\n"
	"  --seed S             seed of every random stream (default 1)\n"
	"  --logger-hz F        gyro logger rate, 0..1000 Hz, 0 = no logger (default 1000)\n"
	"  --logger-prio-above  ablation: run the logger above the balancer (it falls)\n"
	"  --log-baud B         serial log baud (default 115200)\n"
	"  --log FILE           write what the serial log carries to FILE\n"
	"  --no-balancer        calibrate but never drive the motors (negative control)\n"
	"  --push T:NM          pitch torque NM (N m, |NM| <= 5) on the body for 100 ms at\n"
	"                       time T (e.g. 5s:0.2); may repeat (up to 16)\n"
	"  --tilt DEG           tilt when let go (default 0.5)\n"
	"  --gyro-noise SIGMA   gyro sample noise, deg/s (default 0.15: an EV3 gyro at rest)\n"
	"  --fault SPEC         inject a fault; may repeat (up to 16):\n"
	"                         gyro-noise:SIGMA  gyro-drift:DPS\n"
	"                         uart-bit-errors:P[:T[:D]]  uart-drop:P[:T[:D]]  uart-dup:P[:T[:D]]\n"
	"                         adc-noise:MV[:T[:D]]  encoder-noise:PORT:RATE[:T[:D]]\n"
	"                         encoder-stuck:PORT[:T[:D]]  motor-stall:PORT[:T[:D]]\n"
	"                         unplug:PORT[:T[:D]]   (PORT 1..4 or A..D; T start, D duration,\n"
	"                         with units s/ms/us, default s; no D: to the end)\n"
	"  --trace FILE.vcd     host_sim's signal trace (pins, interrupts, motors)\n"
	"  --csv FILE           the series: one row per 1 ms physics step\n"
	"  --plot FILE.png      tilt, wheel angle and motor power against time (gnuplot)\n"
	"  --no-progress        no progress bar (it shows on a terminal for runs over 1 s)\n"
	"\n"
	"Summary: result (upright|fell), the options, fell_at_s, max/rms tilt, travel,\n"
	"deadline misses of the balance task, logger counters, sim_speed (virtual seconds\n"
	"per wall second, the only field that differs between identical runs).\n";

static const char motor_usage[] =
	"usage: ev3sim motor [options]\n"
	"\n"
	"Runs a motor through the EV3 API (ev3lx_motor_set_speed or _set_power), prints\n"
	"time, measured speed and counts every --every ms, then a key=value summary.\n"
	"\n"
	"  --port P         output port A..D (default A)\n"
	"  --kind K         large or medium (default large)\n"
	"  --speed V        regulated speed -100..100 (default 50)\n"
	"  --power V        unregulated power -100..100 instead of a speed\n"
	"  --seconds N      how long it runs (default 2, max 3600)\n"
	"  --every MS       row period in ms (default 100)\n"
	"  --seed S         random seed (default 1)\n"
	"  --trace FILE.vcd host_sim's signal trace\n";

static const char sensors_usage[] =
	"usage: ev3sim sensors [options]\n"
	"\n"
	"Plugs devices into the brick, prints what d_analog detected on every port\n"
	"(InConn/InDcm, OutConn/OutDcm through the analog hack), then live values\n"
	"through the EV3 API every --every ms.  The scene: the gyro turns at 15 deg/s,\n"
	"the touch sensor is pressed every other second, the colour sensor sees a red\n"
	"surface (reflect 40 %), obstacles are 50 cm away.\n"
	"\n"
	"  --in1 .. --in4 DEV   none, touch, nxt-touch, nxt-light, gyro, color, ultrasonic, ir,\n"
	"                       ht-accel, ht-color, nxt-temp\n"
	"                       (default: touch, gyro, color, ultrasonic)\n"
	"  --outA .. --outD DEV none, large, medium (default: large, medium, none, large)\n"
	"  --seconds N          live values for this long (default 3, max 3600)\n"
	"  --every MS           row period in ms (default 500)\n"
	"  --seed S             random seed (default 1)\n"
	"  --trace FILE.vcd     host_sim's signal trace\n";

/* Argument cursor over one command's options. */
struct args {
	const char *cmd;
	int argc, i;
	char **argv;
	const char *name;           /* current option */
	const char *inline_value;   /* after '=' */
	char name_buf[64];
};

static int usage_error(const struct args *a, const char *fmt, const char *what)
{
	fprintf(stderr, "ev3sim %s: ", a->cmd);
	fprintf(stderr, fmt, what);
	fprintf(stderr, "\n(ev3sim %s --help lists the options)\n", a->cmd);
	return EV3SIM_EXIT_USAGE;
}

/* Next option: false at the end.  Splits "--name=value". */
static bool next_option(struct args *a)
{
	const char *arg, *eq;

	if (a->i >= a->argc)
		return false;
	arg = a->argv[a->i++];
	eq = strchr(arg, '=');
	a->inline_value = NULL;
	if (strncmp(arg, "--", 2) == 0 && eq != NULL && (size_t)(eq - arg) < sizeof(a->name_buf)) {
		memcpy(a->name_buf, arg, (size_t)(eq - arg));
		a->name_buf[eq - arg] = '\0';
		a->name = a->name_buf;
		a->inline_value = eq + 1;
	} else {
		a->name = arg;
	}
	return true;
}

/* The current option's value, or NULL if missing. */
static const char *value(struct args *a)
{
	if (a->inline_value)
		return a->inline_value;
	if (a->i < a->argc)
		return a->argv[a->i++];
	return NULL;
}

static bool is(const struct args *a, const char *name)
{
	return strcmp(a->name, name) == 0;
}

/* --help or -h; a value given to it (--help=1) is a usage error (*status). */
static bool is_help(const struct args *a, int *status)
{
	if (!is(a, "--help") && !is(a, "-h"))
		return false;
	*status = a->inline_value ? usage_error(a, "%s takes no value", a->name) : EV3SIM_EXIT_OK;
	return true;
}

/* Parses a seconds value in (0, max]. */
static bool parse_seconds(const char *s, double *out)
{
	double v;

	if (!ev3sim_parse_double(s, &v) || !(v > 0) || v > EV3SIM_MAX_SECONDS)
		return false;
	*out = v;
	return true;
}

/*
 * The options every app takes: --seconds, --seed, --trace, and --every where
 * every_ms is given.  -1 if the current option is none of them; else
 * EV3SIM_EXIT_OK, or the status of its usage error.
 */
static int shared_option(struct args *a, const char *v, double *seconds, uint64_t *seed,
			 const char **trace_path, unsigned *every_ms)
{
	if (is(a, "--seconds")) {
		if (!parse_seconds(v, seconds))
			return usage_error(a, "--seconds: bad value '%s' (0 < N <= 3600)", v);
	} else if (is(a, "--seed")) {
		if (!ev3sim_parse_uint(v, UINT64_MAX, seed))
			return usage_error(a, "--seed: bad value '%s' (an unsigned integer)", v);
	} else if (is(a, "--trace")) {
		if (!ev3sim_can_create(a->cmd, v))	/* checked before the run, not after it */
			return EV3SIM_EXIT_FAIL;
		*trace_path = v;
	} else if (every_ms != NULL && is(a, "--every")) {
		uint64_t ms;

		if (!ev3sim_parse_uint(v, 60000, &ms) || ms == 0)
			return usage_error(a, "--every: bad value '%s' (1..60000 ms)", v);
		*every_ms = (unsigned)ms;
	} else {
		return -1;
	}
	return EV3SIM_EXIT_OK;
}

/* A path gnuplot can take inside single quotes. */
static bool plain_path(const char *s)
{
	return s && *s && strchr(s, '\'') == NULL && strchr(s, '\n') == NULL;
}

/* What `balance`'s options set: the run's options and the outputs asked for. */
struct balance_cli {
	struct ev3sim_balance_opts o;
	const char *csv, *plot, *log_path;
};

/* One option of `balance`: its name, whether it takes a value, and what it
 * does with it (v is NULL for a flag); EV3SIM_EXIT_OK or a usage error's status. */
struct balance_option {
	const char *name;
	bool takes_value;
	int (*apply)(struct args *a, const char *v, struct balance_cli *c);
};

static int opt_no_balancer(struct args *a, const char *v, struct balance_cli *c)
{
	c->o.app.balancer = false;
	return EV3SIM_EXIT_OK;
}

static int opt_logger_prio_above(struct args *a, const char *v, struct balance_cli *c)
{
	c->o.app.logger_above = true;
	return EV3SIM_EXIT_OK;
}

static int opt_no_progress(struct args *a, const char *v, struct balance_cli *c)
{
	c->o.progress = false;
	return EV3SIM_EXIT_OK;
}

static int opt_shared(struct args *a, const char *v, struct balance_cli *c)
{
	return shared_option(a, v, &c->o.seconds, &c->o.seed, &c->o.trace_path, NULL);
}

static int opt_logger_hz(struct args *a, const char *v, struct balance_cli *c)
{
	uint64_t hz;

	if (!ev3sim_parse_uint(v, EV3SIM_LOGGER_MAX_HZ, &hz))
		return usage_error(a, "--logger-hz: bad value '%s' (0..1000)", v);
	c->o.app.logger_hz = (unsigned)hz;
	return EV3SIM_EXIT_OK;
}

static int opt_log_baud(struct args *a, const char *v, struct balance_cli *c)
{
	uint64_t baud;

	if (!ev3sim_parse_uint(v, MAX_LOG_BAUD, &baud) || baud < MIN_LOG_BAUD)
		return usage_error(a, "--log-baud: bad value '%s' (300..4000000)", v);
	c->o.log_baud = (uint32_t)baud;
	return EV3SIM_EXIT_OK;
}

static int opt_log(struct args *a, const char *v, struct balance_cli *c)
{
	c->log_path = v;
	return EV3SIM_EXIT_OK;
}

static int opt_push(struct args *a, const char *v, struct balance_cli *c)
{
	const char *colon = strchr(v, ':');
	char t[64];
	double nm;

	if (c->o.npushes == EV3SIM_MAX_PUSHES)
		return usage_error(a, "--push: more than %s pushes", "16");
	if (colon == NULL || (size_t)(colon - v) >= sizeof(t))
		return usage_error(a, "--push: bad value '%s' (T:NM, e.g. 5s:0.2)", v);
	memcpy(t, v, (size_t)(colon - v));
	t[colon - v] = '\0';
	if (!ev3sim_parse_time(t, &c->o.pushes[c->o.npushes].t_ns) ||
	    !ev3sim_parse_double(colon + 1, &nm) || fabs(nm) > MAX_PUSH_NM)
		return usage_error(a, "--push: bad value '%s' (T:NM, |NM| <= 5 N m)", v);
	c->o.pushes[c->o.npushes++].torque_nm = nm;
	return EV3SIM_EXIT_OK;
}

static int opt_tilt(struct args *a, const char *v, struct balance_cli *c)
{
	if (!ev3sim_parse_double(v, &c->o.start_tilt_deg) || fabs(c->o.start_tilt_deg) >= MAX_START_TILT_DEG)
		return usage_error(a, "--tilt: bad value '%s' (|DEG| < 30)", v);
	return EV3SIM_EXIT_OK;
}

static int opt_gyro_noise(struct args *a, const char *v, struct balance_cli *c)
{
	if (!ev3sim_parse_double(v, &c->o.gyro_noise_dps) || c->o.gyro_noise_dps < 0 ||
	    c->o.gyro_noise_dps > EV3SIM_MAX_GYRO_NOISE_DPS)
		return usage_error(a, "--gyro-noise: bad value '%s' (0..1000 deg/s)", v);
	return EV3SIM_EXIT_OK;
}

static int opt_fault(struct args *a, const char *v, struct balance_cli *c)
{
	char err[256];

	if (c->o.nfaults == EV3SIM_MAX_FAULTS)
		return usage_error(a, "--fault: more than %s faults", "16");
	if (!ev3sim_fault_parse(v, 1, &c->o.faults[c->o.nfaults], err, sizeof(err)))
		return usage_error(a, "--fault: %s", err);
	c->o.nfaults++;
	return EV3SIM_EXIT_OK;
}

static int opt_csv(struct args *a, const char *v, struct balance_cli *c)
{
	c->csv = v;
	return EV3SIM_EXIT_OK;
}

static int opt_plot(struct args *a, const char *v, struct balance_cli *c)
{
	if (!plain_path(v))
		return usage_error(a, "--plot: bad path '%s'", v);
	c->plot = v;
	return EV3SIM_EXIT_OK;
}

static const struct balance_option balance_options[] = {
	{ "--no-balancer",       false, opt_no_balancer },
	{ "--logger-prio-above", false, opt_logger_prio_above },
	{ "--no-progress",       false, opt_no_progress },
	{ "--seconds",           true,  opt_shared },
	{ "--seed",              true,  opt_shared },
	{ "--trace",             true,  opt_shared },
	{ "--logger-hz",         true,  opt_logger_hz },
	{ "--log-baud",          true,  opt_log_baud },
	{ "--log",               true,  opt_log },
	{ "--push",              true,  opt_push },
	{ "--tilt",              true,  opt_tilt },
	{ "--gyro-noise",        true,  opt_gyro_noise },
	{ "--fault",             true,  opt_fault },
	{ "--csv",               true,  opt_csv },
	{ "--plot",              true,  opt_plot },
};

/* The table row of the current option, or NULL. */
static const struct balance_option *balance_option_of(const struct args *a)
{
	for (size_t i = 0; i < sizeof(balance_options) / sizeof(balance_options[0]); i++)
		if (is(a, balance_options[i].name))
			return &balance_options[i];
	return NULL;
}

static int cmd_balance(struct args *a)
{
	struct balance_cli c = {
		.o = { .seconds = 10.0, .seed = 1, .app = { .balancer = true, .logger_hz = 1000 },
		       .start_tilt_deg = 0.5, .gyro_noise_dps = UART_SENSOR_GYRO_NOISE_AT_REST_DPS,
		       .progress = true },
	};
	struct ev3sim_balance_opts o;
	struct ev3sim_balance_result r;
	const struct balance_option *opt;
	const char *csv, *plot, *log_path, *series_path, *v = NULL;
	char err[256], line[1024], series_tmp[] = "/tmp/ev3sim-series-XXXXXX";
	int status = EV3SIM_EXIT_OK, st, fd;

	while (next_option(a)) {
		if (is_help(a, &st)) {
			if (st == EV3SIM_EXIT_OK)
				fputs(balance_usage, stdout);
			return st;
		}
		if (strncmp(a->name, "--", 2) != 0)
			return usage_error(a, "unexpected argument '%s'", a->name);
		opt = balance_option_of(a);
		if (opt == NULL)
			return usage_error(a, "unknown option %s", a->name);
		if (!opt->takes_value && a->inline_value != NULL)
			return usage_error(a, "%s takes no value", opt->name);
		if (opt->takes_value && (v = value(a)) == NULL)
			return usage_error(a, "%s needs a value", a->name);
		st = opt->apply(a, opt->takes_value ? v : NULL, &c);
		if (st != EV3SIM_EXIT_OK)
			return st;
	}
	o = c.o;
	csv = c.csv;
	plot = c.plot;
	log_path = c.log_path;
	if (plot && !ev3sim_have_gnuplot()) {
		fprintf(stderr, "ev3sim balance: --plot needs gnuplot, which is not installed "
			"(install gnuplot-nox: make deps)\n");
		return EV3SIM_EXIT_FAIL;
	}
	/* every output is opened or created before the run: a path that cannot be written is
	 * refused now; the series streams to the CSV (or, for a plot alone, a temporary file) */
	if (plot && !ev3sim_can_create(a->cmd, plot))
		return EV3SIM_EXIT_FAIL;
	series_path = csv;
	if (csv && (o.series_out = ev3sim_open_output(a->cmd, csv)) == NULL)
		return EV3SIM_EXIT_FAIL;
	if (!csv && plot) {
		fd = mkstemp(series_tmp);
		if (fd < 0 || (o.series_out = fdopen(fd, "w")) == NULL) {
			fprintf(stderr, "ev3sim balance: cannot create a temporary file: %s\n", strerror(errno));
			if (fd >= 0)
				close(fd);
			return EV3SIM_EXIT_FAIL;
		}
		series_path = series_tmp;
	}
	if (log_path && (o.log_out = ev3sim_open_output(a->cmd, log_path)) == NULL) {
		if (o.series_out)
			fclose(o.series_out);
		return EV3SIM_EXIT_FAIL;
	}
	if (ev3sim_balance_run(&o, &r, err, sizeof(err)) != E_OK) {
		fprintf(stderr, "ev3sim balance: %s\n", err);
		if (o.log_out)
			fclose(o.log_out);
		if (o.series_out)
			fclose(o.series_out);
		if (series_path == series_tmp)
			unlink(series_tmp);
		return EV3SIM_EXIT_FAIL;
	}
	if (o.log_out && !ev3sim_close_output(a->cmd, o.log_out, log_path))
		status = EV3SIM_EXIT_FAIL;
	if (o.series_out && !ev3sim_close_output(a->cmd, o.series_out, series_path))
		status = EV3SIM_EXIT_FAIL;
	if (r.trace_failed) {
		fprintf(stderr, "ev3sim balance: cannot write %s completely\n", o.trace_path);
		status = EV3SIM_EXIT_FAIL;
	}
	if (plot && status == EV3SIM_EXIT_OK) {
		char title[160];

		snprintf(title, sizeof(title), "ev3sim balance: %s, seed %llu, logger %u Hz (%s the balancer)%s",
			 r.fell ? "fell" : "upright", (unsigned long long)o.seed, o.app.logger_hz,
			 o.app.logger_above ? "above" : "below", o.app.balancer ? "" : ", no balancer");
		if (ev3sim_plot(series_path, title, plot, err, sizeof(err)) != 0) {
			fprintf(stderr, "ev3sim balance: %s\n", err);
			status = EV3SIM_EXIT_FAIL;
		}
	}
	if (series_path == series_tmp)
		unlink(series_tmp);
	ev3sim_balance_summary(&o, &r, line, sizeof(line));
	printf("%s\n", line);
	return status;
}

static int cmd_motor(struct args *a)
{
	struct ev3sim_motor_opts o = {
		.port = 0, .kind = HS_MOTOR_LARGE, .value = 50, .seconds = 2.0, .every_ms = 100, .seed = 1,
	};
	bool speed_given = false, power_given = false;
	const char *v;
	char err[256];
	int st;

	while (next_option(a)) {
		if (is_help(a, &st)) {
			if (st == EV3SIM_EXIT_OK)
				fputs(motor_usage, stdout);
			return st;
		} else if (strncmp(a->name, "--", 2) != 0) {
			return usage_error(a, "unexpected argument '%s'", a->name);
		} else if ((v = value(a)) == NULL) {
			return usage_error(a, "%s needs a value (or is unknown)", a->name);
		} else if (is(a, "--port")) {
			if (!ev3sim_parse_output_port(v, &o.port))
				return usage_error(a, "--port: bad value '%s' (A..D)", v);
		} else if (is(a, "--kind")) {
			if (strcmp(v, "large") == 0)
				o.kind = HS_MOTOR_LARGE;
			else if (strcmp(v, "medium") == 0)
				o.kind = HS_MOTOR_MEDIUM;
			else
				return usage_error(a, "--kind: bad value '%s' (large or medium)", v);
		} else if (is(a, "--speed") || is(a, "--power")) {
			double d;

			if (!ev3sim_parse_double(v, &d) || d != floor(d) || d < -100 || d > 100)
				return usage_error(a, "bad value '%s' (an integer -100..100)", v);
			o.value = (int)d;
			o.power_mode = is(a, "--power");
			speed_given |= !o.power_mode;
			power_given |= o.power_mode;
		} else if ((st = shared_option(a, v, &o.seconds, &o.seed, &o.trace_path,
					       &o.every_ms)) >= 0) {
			if (st != EV3SIM_EXIT_OK)
				return st;
		} else {
			return usage_error(a, "unknown option %s", a->name);
		}
	}
	if (speed_given && power_given)
		return usage_error(a, "%s", "--speed and --power exclude each other");
	if (ev3sim_motor_app(&o, stdout, err, sizeof(err)) != E_OK) {
		fprintf(stderr, "ev3sim motor: %s\n", err);
		return EV3SIM_EXIT_FAIL;
	}
	return EV3SIM_EXIT_OK;
}

static int cmd_sensors(struct args *a)
{
	struct ev3sim_sensors_opts o;
	const char *v;
	char err[256];
	int st;

	ev3sim_sensors_defaults(&o);
	while (next_option(a)) {
		if (is_help(a, &st)) {
			if (st == EV3SIM_EXIT_OK)
				fputs(sensors_usage, stdout);
			return st;
		} else if (strncmp(a->name, "--", 2) != 0) {
			return usage_error(a, "unexpected argument '%s'", a->name);
		} else if ((v = value(a)) == NULL) {
			return usage_error(a, "%s needs a value (or is unknown)", a->name);
		} else if (strncmp(a->name, "--in", 4) == 0 && a->name[4] >= '1' && a->name[4] <= '4' &&
			   a->name[5] == '\0') {
			if (!ev3sim_input_device_parse(v, &o.in[a->name[4] - '1']))
				return usage_error(a, "bad input device '%s' (none, touch, nxt-touch, "
						   "nxt-light, gyro, color, ultrasonic, ir, ht-accel, ht-color, nxt-temp)", v);
		} else if (strncmp(a->name, "--out", 5) == 0 && a->name[5] >= 'A' && a->name[5] <= 'D' &&
			   a->name[6] == '\0') {
			if (!ev3sim_output_device_parse(v, &o.out[a->name[5] - 'A']))
				return usage_error(a, "bad output device '%s' (none, large, medium)", v);
		} else if ((st = shared_option(a, v, &o.seconds, &o.seed, &o.trace_path,
					       &o.every_ms)) >= 0) {
			if (st != EV3SIM_EXIT_OK)
				return st;
		} else {
			return usage_error(a, "unknown option %s", a->name);
		}
	}
	if (ev3sim_sensors_app(&o, stdout, err, sizeof(err)) != E_OK) {
		fprintf(stderr, "ev3sim sensors: %s\n", err);
		return EV3SIM_EXIT_FAIL;
	}
	return EV3SIM_EXIT_OK;
}

static int cmd_run(struct args *a)
{
	return ev3sim_run_command(a->argc - a->i, a->argv + a->i);
}

int ev3sim_main(int argc, char **argv)
{
	static const struct { const char *name; int (*run)(struct args *); } cmds[] = {
		{ "balance", cmd_balance }, { "motor", cmd_motor }, { "sensors", cmd_sensors },
		{ "run", cmd_run },
	};
	struct args a = { .argc = argc, .argv = argv, .i = 2 };

	if (argc < 2) {
		fputs(main_usage, stderr);
		return EV3SIM_EXIT_USAGE;
	}
	if (strcmp(argv[1], "--help") == 0 || strcmp(argv[1], "-h") == 0 || strcmp(argv[1], "help") == 0) {
		fputs(main_usage, stdout);
		return ev3sim_finish_stdout(NULL, EV3SIM_EXIT_OK);
	}
	for (size_t i = 0; i < sizeof(cmds) / sizeof(cmds[0]); i++) {
		if (strcmp(argv[1], cmds[i].name) == 0) {
			a.cmd = cmds[i].name;
			return ev3sim_finish_stdout(a.cmd, cmds[i].run(&a));
		}
	}
	fprintf(stderr, "ev3sim: unknown command '%s'\n\n%s", argv[1], main_usage);
	return EV3SIM_EXIT_USAGE;
}
