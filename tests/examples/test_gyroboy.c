/*
 * test_gyroboy.c — examples/gyroboy in the gyro boy robot: it calibrates
 * while held, balances with EV3RT's regulated set_power through pushes and
 * a drifting gyro, and falls when let go too early to have calibrated.
 */
#include "example_test.h"

int main(void)
{
	struct ev3sim_run_opts o;
	struct ev3sim_run_result r;
	const char *line;

	ev3sim_run_defaults(&o, EV3SIM_ROBOT_GYROBOY);
	o.app_name = "gyroboy";
	o.seconds = 20;
	o.pushes[0] = (struct ev3sim_push){ 8000000000ULL, 0.2 };
	o.pushes[1] = (struct ev3sim_push){ 14000000000ULL, -0.2 };
	o.npushes = 2;
	if (!ok(ex_run(&o, &r), "gyroboy runs 20 s with two pushes"))
		return tap_done();
	ok(!r.fell, "it stays upright");
	in_range(r.max_tilt_deg, 0.1, 15, "tilting under the pushes (max %.2f deg)", r.max_tilt_deg);
	line = ex_logged("gyroboy: gyro offset");
	ok(line != NULL, "it calibrated before the release (%s)", line ? line : "no line");
	ok(ex_logged("gyroboy: fell") == NULL, "and never logged a fall");
	is_int(r.warnings + r.errors + r.bugs, 0, "no warnings, errors or bugs");

	ev3sim_run_defaults(&o, EV3SIM_ROBOT_GYROBOY);
	o.app_name = "gyroboy";
	o.seconds = 15;
	o.faults[0] = (struct ev3sim_fault_spec){ .target = EV3SIM_FAULT_GYRO_DRIFT, .value = 2.0 };
	o.nfaults = 1;
	if (ex_run(&o, &r))
		ok(!r.fell, "upright with a gyro drifting 2 deg/s (offset tracking)");

	ev3sim_run_defaults(&o, EV3SIM_ROBOT_GYROBOY);
	o.app_name = "gyroboy";
	o.seconds = 8;
	o.release_ns = 1000000000ULL;   /* before the gyro has answered */
	if (ex_run(&o, &r))
		ok(r.fell, "let go before it could balance: it falls (at %.2f s)", r.fell_at_s);
	ok(ex_logged("gyroboy: fell over") != NULL, "and the app noticed");
	return tap_done();
}
