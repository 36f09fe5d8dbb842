/*
 * test_dtq.c — examples/dtq: a producer in an EV3 cyclic handler and a
 * bursty consumer task coupled by a data queue: every item arrives once,
 * in order, and none is lost.
 */
#include "example_test.h"

int main(void)
{
	struct ev3sim_run_opts o;
	struct ev3sim_run_result r;
	const char *line;
	int received = -1, produced = -1, out_of_order = -1, lost = -1, depth = -1;
	long sum = -1;

	ev3sim_run_defaults(&o, EV3SIM_ROBOT_BARE);
	o.app_name = "dtq";
	o.seconds = 5;
	if (!ok(ex_run(&o, &r), "dtq runs 5 s"))
		return tap_done();
	line = ex_logged("dtq: received");
	ok(line != NULL, "the consumer reported (%s)", line ? line : "no line");
	if (line)
		sscanf(line, "dtq: received %d of %d, sum %ld, out of order %d, lost %d, max depth %d",
		       &received, &produced, &sum, &out_of_order, &lost, &depth);
	is_int(produced, 300, "300 items produced");
	is_int(received, 300, "300 received");
	is_int(sum, 300L * 301L / 2L, "each once (their sum)");
	is_int(out_of_order, 0, "in order");
	is_int(lost, 0, "none lost");
	in_range(depth, 2, 8, "the bursts let the queue fill (max depth %d)", depth);
	is_int(r.warnings + r.errors + r.bugs, 0, "no warnings, errors or bugs");
	return tap_done();
}
