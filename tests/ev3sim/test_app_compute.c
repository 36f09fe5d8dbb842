/*
 * test_app_compute.c — an app's own computation costs virtual CPU time
 * (rtos_host.h, CPU time): tests/ev3sim/apps/compute times a loop that
 * makes no service call with get_utm, as a benchmark app does.  Each round
 * is one basic block, which costs 5 ARM926 instructions at 300 MHz (17 ns):
 * 100 000 rounds take 1.7 ms and the interrupts that preempt them, twice as
 * many about twice as long.  Without the model both read 0.
 */
#include "ev3sim_test.h"
#include "ev3sim/run.h"

extern const struct rtos_cfg ev3rt_app_cfg;

static struct et_run run;

static int compute_main(int argc, char **argv)
{
	return ev3sim_run_main(argc, argv, "compute", &ev3rt_app_cfg);
}

int main(void)
{
	static const char *const args[] = { "--seconds", "1", NULL };
	unsigned long one = 0, two = 0;
	const char *line;
	bool ran = et_run_main(&run, args, compute_main, NULL);

	ok(ran && run.status == 0, "the compute app runs (status %d)", run.status);
	if (run.status != 0)
		tap_diag("stderr:\n%s", run.err);
	line = strstr(run.out, "compute: ");
	ok(line != NULL && sscanf(line, "compute: 100000 rounds %lu us, 200000 rounds %lu us", &one, &two) == 2,
	   "it timed its two loops");
	in_range((long)one, 1500, 2500, "100 000 rounds of its own code took %lu us of virtual time", one);
	/* the clock also runs while the tick's and the drivers' interrupts preempt the loop */
	in_range((long)two, 19 * (long)one / 10, 23 * (long)one / 10, "twice the rounds, about twice the time (%lu us)",
		 two);
	return tap_done();
}
