/*
 * test_gyroboy.c — examples/gyroboy in the gyro boy robot: it calibrates
 * while held, balances with EV3RT's regulated set_power through pushes and
 * a drifting gyro, and falls when let go too early to have calibrated.  The
 * hand lets go when the app first runs the wheels (--release drive, the
 * default: a motor's bridge drives or brakes, power 0 included), so a
 * balancer that calibrates first is let go when ready, however still its
 * gyro reads; or at a time given, driven or not.
 */
#include "example_test.h"
#include "host_sim/devices/uart_sensor.h"

/* The time of the first CSV row (every 10 ms) in which the robot is not held, or -1. */
static double first_unheld_s(bool on_drive, uint64_t release_ns, double gyro_noise_dps)
{
	struct ev3sim_run_opts o;
	struct ev3sim_run_result r;
	char line[128];
	double t = -1.0, tilt, rate, wheel;
	int held;

	ev3sim_run_defaults(&o, EV3SIM_ROBOT_GYROBOY);
	o.app_name = "gyroboy";
	o.seconds = 5;
	o.release_on_drive = on_drive;
	o.release_ns = release_ns;
	o.gyro_noise_dps = gyro_noise_dps;
	o.csv = tmpfile();
	if (o.csv == NULL || !ex_run(&o, &r))
		return -1.0;
	rewind(o.csv);
	while (t < 0.0 && fgets(line, sizeof(line), o.csv) != NULL)
		if (sscanf(line, "%lf,%lf,%lf,%lf,%d", &t, &tilt, &rate, &wheel, &held) != 5 || held)
			t = -1.0;
	fclose(o.csv);
	return t;
}

int main(void)
{
	struct ev3sim_run_opts o;
	struct ev3sim_run_result r;
	const char *line;
	double on_drive_s, at_4s_s, still_s;

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
	o.release_on_drive = false;
	if (ex_run(&o, &r))
		ok(r.fell, "let go at 1 s, before it could balance: it falls (at %.2f s)", r.fell_at_s);
	ok(ex_logged("gyroboy: fell over") != NULL, "and the app noticed");

	/* when the hand lets go: the first row of the robot's state with held = 0 */
	on_drive_s = first_unheld_s(true, 0, UART_SENSOR_GYRO_NOISE_AT_REST_DPS);
	at_4s_s = first_unheld_s(false, 4000000000ULL, UART_SENSOR_GYRO_NOISE_AT_REST_DPS);
	still_s = first_unheld_s(true, 0, 0.0);
	in_range(on_drive_s, 2.55, 2.75,
		 "--release drive: let go when the balancer first drives the wheels, after calibrating (%.2f s)",
		 on_drive_s);
	in_range(at_4s_s, 3.99, 4.01, "--release 4s: let go at 4 s (%.2f s)", at_4s_s);
	/* a balancer held still computes power 0 until the gyro moves: running
	 * the wheels at 0 (the bridge braking) is driving them too */
	in_range(still_s, 2.55, 2.75, "with a noiseless gyro too, when the balancer starts (%.2f s)", still_s);
	return tap_done();
}
