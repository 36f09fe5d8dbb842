/*
 * test_balance.c — the paper's experiment end to end (ev3sim balance): the
 * robot stays upright with the 1 kHz logger and no deadline miss, recovers
 * from pushes, falls without its balancer (the negative control) and with
 * the logger above the balancer (the ablation), keeps balancing through
 * gyro drift, and the same seed gives the same summary in two processes.
 */
#include "ev3sim_test.h"

static struct et_run run, run2;

/* Summary without its last field (sim_speed depends on the host). */
static void strip_speed(char *line)
{
	char *p = strstr(line, " sim_speed=");

	if (p)
		*p = '\0';
}

static void test_upright(void)
{
	const char *secs = et_seconds("60", "60", "6");
	const char *args[] = { "balance", "--seconds", secs, "--logger-hz", "1000", NULL };
	char line[1024];

	ok(et_run(&run, args), "ev3sim balance --seconds %s --logger-hz 1000 ran", secs);
	is_int(run.status, 0, "exit status 0");
	et_last_line(&run, line, sizeof(line));
	tap_diag("%s", line);
	ok(strncmp(line, "result=upright ", 15) == 0, "upright after %s virtual seconds with the logger", secs);
	ok(et_number(line, "seconds") == atof(secs), "the summary says seconds=%s", secs);
	is_int(et_number(line, "deadline_misses"), 0, "zero deadline misses of the balance task");
	/* one activation per 4 ms, from the end of calibration (~2.1 s) to the end */
	ok(et_number(line, "balance_runs") >= atof(secs) * 250 &&
	   et_number(line, "balance_runs") <= (atof(secs) + 1.0) * 250,
	   "the balance task ran every 4 ms (%g runs)", et_number(line, "balance_runs"));
	ok(et_number(line, "max_start_delay_us") < 1000, "it started within 1 ms of each release (max %g us)",
	   et_number(line, "max_start_delay_us"));
	ok(et_number(line, "logger_lines") > atof(secs) * 600,
	   "the logger wrote lines all along (%g)", et_number(line, "logger_lines"));
	ok(et_number(line, "log_bytes") > atof(secs) * 9000,
	   "the serial log carried most of 115200 baud (%g bytes)", et_number(line, "log_bytes"));
	ok(et_number(line, "logger_spin_ms") > atof(secs) * 500,
	   "the logger spent most of the CPU waiting for the port (%g ms)", et_number(line, "logger_spin_ms"));
	ok(et_number(line, "max_tilt_deg") < 3.0, "it stays near vertical (max %g deg)",
	   et_number(line, "max_tilt_deg"));
	is_int(et_number(line, "api_errors"), 0, "no API call failed");
	is_int(et_number(line, "api_blocked"), 0, "no API call blocked while balancing");
	ok(et_number(line, "max_api_call_us") >= 0 && et_number(line, "max_api_call_us") < 200,
	   "the longest took %g us", et_number(line, "max_api_call_us"));
	is_int(et_number(line, "bugs"), 0, "no bug reports from the stack");
	ok(strstr(line, " sim_speed=") != NULL && line[strlen(line) - 1] == 'x', "sim_speed comes last");
}

static void test_push(void)
{
	const char *args[] = { "balance", "--seconds", et_seconds("10", "10", "6"), "--push", "1:0.2",
			       "--push", "3500ms:-0.2", NULL };
	char line[1024];

	ok(et_run(&run, args), "balance with two pushes ran");
	et_last_line(&run, line, sizeof(line));
	tap_diag("%s", line);
	ok(strncmp(line, "result=upright ", 15) == 0, "it recovers from a push each way");
	ok(et_number(line, "max_tilt_deg") > 4.0, "the pushes tipped it (max %g deg)",
	   et_number(line, "max_tilt_deg"));
	is_int(et_number(line, "deadline_misses"), 0, "no deadline miss meanwhile");

	{
		const char *hard[] = { "balance", "--seconds", "5", "--push", "1:2.0", NULL };

		ok(et_run(&run, hard), "balance with a push far too hard ran");
		et_last_line(&run, line, sizeof(line));
		ok(strncmp(line, "result=fell ", 12) == 0, "a 2 N m push topples it (%s)", line);
		ok(et_number(line, "fell_at_s") > 1.0 && et_number(line, "fell_at_s") < 2.0,
		   "it falls just after the push (at %g s)", et_number(line, "fell_at_s"));
	}
}

static void test_negative_control(void)
{
	const char *args[] = { "balance", "--seconds", "10", "--no-balancer", NULL };
	char line[1024];

	ok(et_run(&run, args), "balance --no-balancer ran");
	is_int(run.status, 0, "exit status 0 (a fall is a result, not an error)");
	et_last_line(&run, line, sizeof(line));
	tap_diag("%s", line);
	ok(strncmp(line, "result=fell ", 12) == 0, "without the balancer it falls: result=fell");
	ok(et_number(line, "fell_at_s") > 0 && et_number(line, "fell_at_s") < 3.0,
	   "within seconds of the release (%g s)", et_number(line, "fell_at_s"));
	is_int(et_number(line, "balance_runs"), 0, "the balance task never ran");
	ok(et_number(line, "max_tilt_deg") >= 45.0, "tilt reached the ground (%g deg)",
	   et_number(line, "max_tilt_deg"));
}

static void test_ablation(void)
{
	const char *args[] = { "balance", "--seconds", "10", "--logger-prio-above", NULL };
	char line[1024];

	ok(et_run(&run, args), "balance --logger-prio-above ran");
	et_last_line(&run, line, sizeof(line));
	tap_diag("%s", line);
	ok(strncmp(line, "result=fell ", 12) == 0, "a logger above the balancer topples the robot");
	ok(et_number(line, "deadline_misses") > 10, "the balance task missed its deadlines (%g)",
	   et_number(line, "deadline_misses"));
	/* Starved by the logger, it is held up before it starts or inside a call, as the timing falls. */
	ok(et_number(line, "max_start_delay_us") > 1000 || et_number(line, "max_api_call_us") > 1000,
	   "it was held up: started late (max %g us) or waited in a call (longest %g us)",
	   et_number(line, "max_start_delay_us"), et_number(line, "max_api_call_us"));
}

static void test_drift_and_faults(void)
{
	const char *args[] = { "balance", "--seconds", et_seconds("30", "30", "5"), "--fault", "gyro-drift:3",
			       "--fault", "uart-bit-errors:1e-4", "--fault", "encoder-noise:A:20", NULL };
	char line[1024];

	ok(et_run(&run, args), "balance with gyro drift, bit errors and encoder glitches ran");
	et_last_line(&run, line, sizeof(line));
	tap_diag("%s", line);
	ok(strncmp(line, "result=upright ", 15) == 0, "the offset tracking keeps it upright");
	is_int(et_number(line, "deadline_misses"), 0, "no deadline miss");
}

static void test_determinism(void)
{
	const char *secs = et_seconds("20", "20", "2");
	const char *a7[] = { "balance", "--seconds", secs, "--seed", "7", "--push", "1:0.15", NULL };
	const char *a8[] = { "balance", "--seconds", secs, "--seed", "8", "--push", "1:0.15", NULL };
	char l1[1024], l2[1024];

	ok(et_run(&run, a7) && et_run(&run2, a7), "two runs with seed 7 in separate processes");
	et_last_line(&run, l1, sizeof(l1));
	et_last_line(&run2, l2, sizeof(l2));
	strip_speed(l1);
	strip_speed(l2);
	ok(strcmp(l1, l2) == 0, "identical summaries but for sim_speed");
	tap_diag("%s", l1);
	ok(et_run(&run2, a8), "a run with seed 8");
	et_last_line(&run2, l2, sizeof(l2));
	strip_speed(l2);
	ok(strcmp(l1, l2) != 0, "another seed gives another run (gyro noise)");
}

/* A wheel's motor cannot be unplugged (the robot keeps no pointer to a freed
 * motor): a clear error and no run; another port's motor can. */
static void test_wheel_unplug(void)
{
	const char *wheel[] = { "balance", "--seconds", "1", "--fault", "unplug:D:0.5", NULL };
	const char *other[] = { "balance", "--seconds", "1", "--fault", "unplug:B:0.5", NULL };
	char line[1024];

	ok(et_run(&run, wheel), "balance --fault unplug:D ran");
	ok(run.status != 0 && strstr(run.err, "unplug:D would take a wheel off the robot") != NULL,
	   "unplugging a wheel motor is refused with its reason (status %d)", run.status);
	ok(strstr(run.out, "result=") == NULL, "and nothing is reported as a result");
	ok(et_run(&run, other), "balance --fault unplug:B ran");
	et_last_line(&run, line, sizeof(line));
	ok(run.status == 0 && strncmp(line, "result=upright ", 15) == 0,
	   "an empty output port may be unplugged: %s", line);
}

/* The gyro unplugged for 100 ms while balancing: its reads wait for the reconnection (the
 * 2.4 s handshake at 2400 baud) in the balance and logger tasks, and the summary says so. */
static void test_blocked_sensor(void)
{
	const char *args[] = { "balance", "--seconds", "5", "--fault", "unplug:2:1s:100ms", "--no-progress", NULL };
	char line[1024];

	ok(et_run(&run, args) && run.status == 0, "balance with the gyro unplugged for 100 ms");
	et_last_line(&run, line, sizeof(line));
	tap_diag("%s", line);
	ok(et_number(line, "api_blocked") >= 1, "the blocked gyro reads are counted (api_blocked=%g)",
	   et_number(line, "api_blocked"));
	ok(et_number(line, "max_api_call_us") > 100000, "the longest wait (still waiting when the robot fell) is in the summary (%g us)",
	   et_number(line, "max_api_call_us"));
}

int main(void)
{
	tap_plan(44 + 1 + 3);
	test_upright();
	test_push();
	test_negative_control();
	test_ablation();
	test_drift_and_faults();
	test_determinism();
	test_blocked_sensor();
	test_wheel_unplug();
	return tap_done();
}
