/*
 * test_cpptracer.c — examples/cpptracer on the tribot's line mat: an ET
 * Robocon-style C++ app on EV3RT's C++ API (libcpp-ev3, taken from its
 * Makefile.inc) waits for the touch sensor, then follows the line with its
 * own PID class; its Clock and Motor counts agree with the simulated robot.
 */
#include "example_test.h"

int main(void)
{
	struct ev3sim_run_opts o;
	struct ev3sim_run_result r;
	const char *line;
	unsigned ms = 0, periods = 0;
	int mm = 0;

	ev3sim_run_defaults(&o, EV3SIM_ROBOT_TRIBOT);
	o.app_name = "cpptracer";
	o.seconds = 30;
	if (!ok(ex_run(&o, &r), "cpptracer runs 30 s on the tribot"))
		return tap_done();
	line = ex_logged("cpptracer: go after ");
	ok(line != NULL, "the touch press (at 3 s) started it: %s", line ? line : "(none)");
	ok(r.progress_m > 4.6, "it went round the whole 4.51 m track along the line (%.2f m)", r.progress_m);
	in_range(r.progress_m, r.travel_m * 0.9, r.travel_m * 1.1,
		 "all its travel (%.2f m) was progress along the line", r.travel_m);
	ok(r.max_line_error_mm < 25.0, "the sensor stayed within 25 mm of the line (max %.1f mm)",
	   r.max_line_error_mm);
	is_int(r.on_line_pct, 100, "it saw the line all the time");

	line = ex_logged("cpptracer: 25");
	ok(line != NULL && sscanf(line, "cpptracer: %u ms, %u periods, the wheels rolled %d mm",
				  &ms, &periods, &mm) == 3, "it reported at 25 s: %s", line ? line : "(none)");
	in_range(ms, 25000, 25100, "Clock::now() counts ms from its reset (%u)", ms);
	in_range(periods, ms / 4 - 2, ms / 4 + 2, "the tracer ran every 4 ms of that Clock (%u periods)", periods);
	in_range(mm, r.travel_m * 1000.0 * 0.8, r.travel_m * 1000.0,
		 "Motor::getCount() of both wheels says %d mm by then, of %.0f mm in all", mm,
		 r.travel_m * 1000.0);
	is_int(r.warnings + r.errors + r.bugs, 0, "no warnings, errors or bugs");

	ev3sim_run_defaults(&o, EV3SIM_ROBOT_TRIBOT);
	o.app_name = "cpptracer";
	o.seconds = 6;
	o.nactions = 0;     /* nobody presses the touch sensor */
	if (ex_run(&o, &r))
		ok(r.travel_m < 0.001, "without the press it waits (travel %.4f m)", r.travel_m);
	ok(ex_logged("cpptracer: go") == NULL, "and never starts");
	return tap_done();
}
