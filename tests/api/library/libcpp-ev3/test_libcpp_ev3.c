/*
 * test_libcpp_ev3.c — libcpp-ev3, EV3RT's C++ API (api/library/libcpp-ev3),
 * through its unit-test app (app/: a C++ app taking the library from its
 * Makefile.inc as EV3RT apps do) on a bare brick: large motors on A and D,
 * touch on 1, gyro on 2, colour on 3, ultrasonic on 4, the touch sensor
 * pressed from 15 s to 16 s.  Each class does what EV3RT documents, and each
 * sensor read is what EV3RT's C call says of the same port.
 */
#include "../../../examples/example_test.h"

/* Parses the last line logged with prefix by fmt; false (and a failed test) if none. */
#define LOGGED(n, prefix, fmt, ...) \
	ok(ex_logged(prefix) != NULL && sscanf(ex_logged(prefix), fmt, __VA_ARGS__) == (n), \
	   "logged: %s", ex_logged(prefix) ? ex_logged(prefix) : prefix " (missing)")

int main(void)
{
	struct ev3sim_run_opts o;
	struct ev3sim_run_result r;
	int a, b, c, d, e, f;
	unsigned u1, u2, u3;

	ev3sim_run_defaults(&o, EV3SIM_ROBOT_BARE);
	o.app_name = "libcpp-ev3";
	o.out[0] = EV3SIM_OUT_LARGE;
	o.out[3] = EV3SIM_OUT_LARGE;
	o.in[0] = EV3SIM_IN_TOUCH;
	o.in[1] = EV3SIM_IN_GYRO;
	o.in[2] = EV3SIM_IN_COLOR;
	o.in[3] = EV3SIM_IN_ULTRASONIC;
	o.actions[0] = (struct ev3sim_action){ .touch = true, .t_ns = 15000000000ULL, .hold_ns = 1000000000ULL };
	o.nactions = 1;
	o.seconds = 19;
	if (!ok(ex_run(&o, &r), "the unit-test app runs"))
		return tap_done();

	/* global objects */
	if (LOGGED(2, "libcpp: global gyro", "libcpp: global gyro set %d, angle %d", &a, &b)) {
		is_int(a, 1, "main_task starts after the global constructors, even one that waits for its sensor");
		in_range(b, -1, 1, "the global GyroSensor reads its port (angle %d)", b);
	}

	/* Clock */
	if (LOGGED(3, "libcpp: clock", "libcpp: clock wait 120 -> %u, sleep 80 -> %u, reset -> %u", &u1, &u2, &u3)) {
		in_range(u1, 120, 121, "Clock::wait(120) delays 120 ms of now()");
		in_range(u2 - u1, 80, 81, "Clock::sleep(80) sleeps 80 ms");
		is_int(u3, 0, "Clock::reset() starts now() again from 0");
	}

	/* Motor */
	if (LOGGED(4, "libcpp: motor new", "libcpp: motor new count %d pwm %d brake %d port %d", &a, &b, &c, &d)) {
		is_int(a, 0, "a new Motor counts from 0");
		is_int(b, 0, "its PWM is 0");
		is_int(c, 1, "it brakes by default");
		is_int(d, 0, "PORT_A is EV3_PORT_A");
	}
	if (LOGGED(3, "libcpp: motor pwm 50", "libcpp: motor pwm %d count %d C counts %d", &a, &b, &c)) {
		ok(b > 90, "setPWM(50) turns it forwards (%d degrees in 0.5 s)", b);
		in_range(c - b, 0, 3, "getCount() is the C API's counts (no offset yet)");
	}
	if (LOGGED(1, "libcpp: motor clamp high", "libcpp: motor clamp high %d", &a))
		is_int(a, 100, "setPWM(150) is clamped to PWM_MAX");
	if (LOGGED(1, "libcpp: motor clamp low", "libcpp: motor clamp low %d", &a))
		is_int(a, -100, "setPWM(-150) is clamped to PWM_MIN");
	if (LOGGED(2, "libcpp: motor pwm 0", "libcpp: motor pwm 0 braked moved %d C power %d", &a, &b)) {
		in_range(a, -2, 2, "setPWM(0) in brake mode stops and holds it (moved %d)", a);
		is_int(b, 0, "the driver's power is 0");
	}
	if (LOGGED(2, "libcpp: motor setCount", "libcpp: motor setCount 1000 reads %d, C counts %d", &a, &b)) {
		is_int(a, 1000, "setCount(1000) makes getCount() read 1000");
		ok(b != 1000, "and leaves the driver's counter alone (%d)", b);
	}
	if (LOGGED(5, "libcpp: motor stop", "libcpp: motor stop brake %d, float %d: rolled %d then %d degrees, pwm %d",
		   &a, &b, &c, &d, &e)) {
		is_int(b, 0, "setBrake(false) is float mode");
		ok(d > c + 20, "stop() in float mode lets it coast further (%d degrees) than in brake mode (%d)", d, c);
		is_int(e, 100, "stop() keeps the PWM last set, as EV3RT's inline stop() does");
	}
	if (LOGGED(3, "libcpp: motor reset", "libcpp: motor reset reads %d C counts %d pwm %d", &a, &b, &c)) {
		in_range(a, -2, 2, "reset() brakes even in float mode and counts from 0 (%d)", a);
		is_int(a, b, "with no offset left: getCount() is the C API's counts");
		is_int(c, 60, "and reset() keeps the PWM last set, as EV3RT's inline reset() does");
	}
	if (LOGGED(2, "libcpp: motor destructor", "libcpp: motor destructor left power %d, moved %d", &a, &b)) {
		is_int(a, 0, "a Motor's destructor stops its motor");
		in_range(b, -2, 2, "braking (moved %d afterwards)", b);
	}

	/* Steering */
	if (LOGGED(2, "libcpp: steering ratio 0 ", "libcpp: steering ratio 0 left %d right %d", &a, &b)) {
		ok(a > 300, "setPower(60, 0) drives both forwards (%d degrees a second)", a);
		in_range(b, a * 0.97, a * 1.03, "at one speed (right %d)", b);
	}
	if (LOGGED(2, "libcpp: steering ratio 25 ", "libcpp: steering ratio 25 left %d right %d", &a, &b))
		in_range(b, a * 0.72, a * 0.78, "a ratio of +25 runs the right motor at 75 %% of the left (%d of %d)",
			 b, a);
	if (LOGGED(2, "libcpp: steering ratio -50 ", "libcpp: steering ratio -50 left %d right %d", &a, &b))
		in_range(a, b * 0.47, b * 0.53, "a ratio of -50 runs the left motor at 50 %% of the right (%d of %d)",
			 a, b);
	if (LOGGED(2, "libcpp: steering ratio 100 ", "libcpp: steering ratio 100 left %d right %d", &a, &b)) {
		ok(a > 300, "a ratio of +100 drives the left motor (%d)", a);
		in_range(b, -2, 2, "and holds the right one (%d): a pivot", b);
	}

	/* Sensors */
	if (LOGGED(2, "libcpp: touch before", "libcpp: touch before %d, the global object's %d", &a, &b)) {
		is_int(a, 0, "TouchSensor::isPressed() is false before the press");
		is_int(b, 0, "a global TouchSensor, constructed after boot as on EV3RT, reads its port too");
	}
	if (LOGGED(2, "libcpp: touch pressed", "libcpp: touch pressed at %u ms, C says %d", &u1, &a)) {
		in_range(u1, 15000, 15030, "and true from the press at 15 s (%u ms)", u1);
		is_int(a, 1, "as the C API says");
	}
	if (LOGGED(2, "libcpp: gyro angle", "libcpp: gyro angle %d rate %d", &a, &b)) {
		in_range(a, -1, 1, "a new GyroSensor's angle is 0 at rest (%d)", a);
		in_range(b, -1, 1, "its rate is 0 at rest (%d)", b);
	}
	if (LOGGED(2, "libcpp: gyro offset", "libcpp: gyro offset 5 rate %d C rate %d", &a, &b))
		in_range(a, b - 6, b - 4, "getAnglerVelocity() subtracts setOffset(5) (%d, the C API's rate %d)", a, b);
	if (LOGGED(1, "libcpp: gyro reset", "libcpp: gyro reset angle %d", &a))
		in_range(a, -1, 1, "reset() makes the angle 0 (%d)", a);
	if (LOGGED(2, "libcpp: color brightness", "libcpp: color brightness %d C %d", &a, &b))
		is_int(a, b, "ColorSensor::getBrightness() is the C API's reflect (%d)", a);
	if (LOGGED(2, "libcpp: color ambient", "libcpp: color ambient %d C %d", &a, &b))
		is_int(a, b, "getAmbient() is its ambient (%d)", a);
	if (LOGGED(2, "libcpp: color number", "libcpp: color number %d C %d", &a, &b))
		is_int(a, b, "getColorNumber() is its colour (%d)", a);
	if (LOGGED(6, "libcpp: color raw", "libcpp: color raw %d %d %d C %d %d %d", &a, &b, &c, &d, &e, &f))
		ok(a == d && b == e && c == f, "getRawColor() fills in its RGB (%d %d %d)", a, b, c);
	if (LOGGED(3, "libcpp: sonar", "libcpp: sonar distance %d C %d listen %d", &a, &b, &c)) {
		is_int(a, b, "SonarSensor::getDistance() is the C API's distance (%d cm)", a);
		is_int(c, 0, "listen() hears no other sensor");
	}
	ok(ex_logged("libcpp: done") != NULL, "the app ran to its end");
	is_int(r.warnings + r.errors + r.bugs, 0, "no warnings, errors or bugs");
	return tap_done();
}
