/*
 * test_blink.c — examples/blink: EV3 cyclic handlers in task context,
 * paused and resumed by ENTER clicks, ended by BACK.
 */
#include <stdlib.h>
#include "ev3api.h"
#include "example_test.h"

static struct ev3sim_action click(unsigned button, uint64_t t_ms)
{
	return (struct ev3sim_action){ .button = button, .t_ns = t_ms * 1000000ULL,
				       .hold_ns = 100000000ULL };
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
	return tap_done();
}
