/*
 * test_nxt_sensors.c — examples/nxt_sensors, an EV3RT app reading the NXT
 * I2C sensors with EV3RT's calls, in ev3sim with a HiTechnic accelerometer,
 * a HiTechnic colour sensor and an NXT temperature sensor plugged in: every
 * reading succeeds and gives ev3sim's scene (lying flat: 1 g, about 200
 * counts, on Z; white: colour 17, RGB 255; 22.5 C).
 */
#include "example_test.h"

int main(void)
{
	struct ev3sim_run_opts o;
	struct ev3sim_run_result r;
	const char *line;
	int ax = -1, ay = -1, az = -1, color = -1, red = -1, green = -1, blue = -1, temp = -1, failures = -1;

	ev3sim_run_defaults(&o, EV3SIM_ROBOT_BARE);
	o.app_name = "nxt_sensors";
	o.in[0] = EV3SIM_IN_HT_ACCEL;
	o.in[1] = EV3SIM_IN_HT_COLOR;
	o.in[2] = EV3SIM_IN_NXT_TEMP;
	o.seconds = 4;
	if (!ok(ex_run(&o, &r), "nxt_sensors runs 4 s"))
		return tap_done();
	line = ex_logged("nxt_sensors: accel");
	ok(line != NULL, "the app reported (%s)", line ? line : "no line");
	if (line)
		sscanf(line, "nxt_sensors: accel %d %d %d color %d rgb %d %d %d temp %d failures %d",
		       &ax, &ay, &az, &color, &red, &green, &blue, &temp, &failures);
	ok(ax == 0 && ay == 0 && az == 200, "acceleration 0, 0, 200 counts");
	is_int(color, 17, "colour number 17 (white)");
	ok(red == 255 && green == 255 && blue == 255, "RGB 255, 255, 255");
	is_int(temp, 2250, "22.50 C");
	is_int(failures, 0, "every reading succeeded");
	is_int(r.warnings + r.errors + r.bugs, 0, "no warnings, errors or bugs");
	return tap_done();
}
