/*
 * test_gyrosquare.c — examples/gyrosquare in the built-in world "arena": it
 * drives a 0.5 m square turning its corners by the gyro, and ends where it
 * started, heading as it started, one turn further; the gyro's angle at each
 * corner and at the end is the robot's heading (clockwise positive).  With a
 * gyro drift fault the same app turns its corners short: the square does not
 * close.  --plot draws the path on the mat.
 */
#define _POSIX_C_SOURCE 200809L
#include "example_test.h"
#include <math.h>
#include <stdlib.h>
#include <unistd.h>
#include "ev3sim/plot.h"
#include "ev3sim/world.h"

int main(void)
{
	const struct ev3sim_world *arena = ev3sim_world_builtin("arena");
	struct ev3sim_run_opts o;
	struct ev3sim_run_result r;
	char png[] = "/tmp/ev3lx-gyrosquare-XXXXXX";
	int gyro = 0, wheels = 0, corners = 0;
	const char *line;
	FILE *f;
	unsigned char sig[8] = { 0 };
	long size = 0;
	int fd = mkstemp(png);

	if (fd >= 0)
		close(fd);
	ev3sim_run_defaults_world(&o, arena);
	o.app_name = "gyrosquare";
	o.seconds = 20;
	if (ev3sim_have_gnuplot() && fd >= 0)
		o.plot_path = png;
	if (!ok(ex_run(&o, &r), "gyrosquare runs 20 s in the arena"))
		return tap_done();
	ok(ex_logged("gyrosquare: go") != NULL, "it started");
	for (int c = 1; c <= 4; c++) {
		char prefix[48];
		int n = 0, g;

		snprintf(prefix, sizeof(prefix), "gyrosquare: corner %d, gyro ", c);
		line = ex_logged(prefix);
		if (line && sscanf(line + strlen(prefix), "%d", &g) == 1 && abs(g + 90 * c) <= 2)
			n = 1;
		corners += n;
	}
	is_int(corners, 4, "each corner's turn ends with the gyro 90 degrees further (within 2)");
	line = ex_logged("gyrosquare: done");
	ok(line && sscanf(line, "gyrosquare: done, gyro %d deg, wheels %d deg", &gyro, &wheels) == 2, "it finished: %s",
	   line ? line : "(nothing)");
	in_range(hypot(r.x_m - arena->start_x, r.y_m - arena->start_y) * 1000.0, 0.0, 30.0,
		 "the path closes: it ends within 30 mm of its start (%.3f, %.3f)", r.x_m, r.y_m);
	in_range(r.heading_deg, 355.0, 365.0, "it turned once round, counter-clockwise (%.1f deg)", r.heading_deg);
	ok(fabs(gyro + r.heading_deg) <= 2.0, "the gyro's angle is the heading, clockwise (%d for %.1f)", gyro,
	   r.heading_deg);
	in_range(r.travel_m, 1.95, 2.15, "it drove the square's 2 m (%.2f m)", r.travel_m);
	is_int(r.contacts, 0, "it touched nothing");
	is_int(r.warnings + r.errors + r.bugs, 0, "no warnings, errors or bugs");
	if (o.plot_path) {
		f = fopen(png, "rb");
		if (f) {
			if (fread(sig, 1, 8, f) != 8)
				sig[0] = 0;
			fseek(f, 0, SEEK_END);
			size = ftell(f);
			fclose(f);
		}
		ok(memcmp(sig, "\x89PNG\r\n\x1a\n", 8) == 0 && size > 20000, "--plot drew a PNG of %ld bytes", size);
	} else {
		tap_skip(1, "gnuplot is not installed");
	}
	unlink(png);

	ev3sim_run_defaults_world(&o, arena);
	o.app_name = "gyrosquare";
	o.seconds = 20;
	o.faults[0].target = EV3SIM_FAULT_GYRO_DRIFT;
	o.faults[0].value = 3.0;
	o.nfaults = 1;
	if (ok(ex_run(&o, &r), "with a gyro drift of 3 deg/s"))
		ok(fabs(r.heading_deg - 360.0) > 20.0 &&
		   hypot(r.x_m - arena->start_x, r.y_m - arena->start_y) > 0.1,
		   "the drifting gyro turns it wrong: heading %.1f deg, %.0f mm from the start", r.heading_deg,
		   hypot(r.x_m - arena->start_x, r.y_m - arena->start_y) * 1000.0);
	else
		tap_skip(1, "no run");
	return tap_done();
}
