/*
 * test_blink.c — examples/blink: EV3 cyclic handlers in task context,
 * paused and resumed by ENTER clicks, ended by BACK; the runner's command
 * line and its errors.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdlib.h>
#include "ev3api_brick.h"
#include "example_test.h"
#include "stderr_capture.h"

static struct ev3sim_action click(unsigned button, uint64_t t_ms)
{
	return (struct ev3sim_action){ .button = button, .t_ns = t_ms * 1000000ULL,
				       .hold_ns = 100000000ULL };
}

/* The runner refuses command line argv (argc words) with status 2 and a message containing why. */
static void bad_command_line(int argc, char **argv, const char *why, const char *what)
{
	struct stderr_capture cap;
	const char *msg;
	int status;

	stderr_capture_begin(&cap);
	status = ev3sim_run_main(argc, argv, "blink", &ev3rt_app_cfg);
	msg = stderr_capture_end(&cap);
	is_int(status, 2, "%s: status 2", what);
	if (!ok(strstr(msg, why) != NULL, "%s: the message says so", what))
		tap_diag("  stderr: %s", msg);
}

int main(void)
{
	struct ev3sim_run_opts o;
	struct ev3sim_run_result r;
	const char *done;
	int ticks = -1, clicks = -1;

	ev3sim_run_defaults(&o, EV3SIM_ROBOT_BARE);
	o.app_name = "blink";
	o.seconds = 8;
	o.actions[0] = click(ENTER_BUTTON, 2000);   /* pause */
	o.actions[1] = click(ENTER_BUTTON, 4000);   /* resume */
	o.actions[2] = click(BACK_BUTTON, 6000);    /* end */
	o.nactions = 3;
	if (!ok(ex_run(&o, &r), "blink runs with three clicks"))
		return tap_done();
	done = ex_logged("blink: done");
	ok(done != NULL, "BACK ended it (%s)", done ? done : "no line");
	if (done)
		sscanf(done, "blink: done, %d ticks, %d enter clicks", &ticks, &clicks);
	is_int(clicks, 2, "two ENTER clicks handled");
	/* 250 ms ticks from 0.25 s to the pause (~2.1 s), and from the resume (~4.1 s) to the end (~6.1 s) */
	in_range(ticks, 15, 18, "blinking paused for 2 s: %d ticks", ticks);
	ok(done && strstr(done, "handlers in task context") != NULL, "every handler ran in task context");
	is_int(ex_count("blink: ", "ticks"), 8, "REPORT_CYC reported when started and every second (7), then the end");
	is_int(ex_count("blink: ", "(paused)"), 2, "twice while paused (3 s and 4 s)");
	is_int(r.warnings + r.errors + r.bugs, 0, "no warnings, errors or bugs");

	/* the runner's command line (what `ev3sim run APP_DIR` executes) */
	{
		char *good[] = { "run_blink", "--seconds", "3", "--click", "back:1500ms", "--quiet", NULL };
		char *bad_robot[] = { "run_blink", "--robot", "segway", NULL };
		char *bad_click[] = { "run_blink", "--click", "middle:1s", NULL };
		char *bad_port[] = { "run_blink", "--in5", "gyro", NULL };
		char *no_value[] = { "run_blink", "--seconds", NULL };
		char *bad_fault[] = { "run_blink", "--fault", "gyro-noise", NULL };

		is_int(ev3sim_run_main(6, good, "blink", &ev3rt_app_cfg), 0, "a run from the command line: status 0");
		bad_command_line(3, bad_robot, "--robot: bad value 'segway'", "--robot segway");
		bad_command_line(3, bad_click, "--click: bad value 'middle:1s'", "--click middle:1s");
		bad_command_line(3, bad_port, "unknown option --in5", "--in5");
		bad_command_line(2, no_value, "--seconds needs a value", "--seconds without a value");
		bad_command_line(3, bad_fault, "--fault: 'gyro-noise': missing or bad value", "--fault gyro-noise (no value)");
	}
	return tap_done();
}
