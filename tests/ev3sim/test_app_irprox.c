/*
 * test_app_irprox.c — the infrared sensor's proximity from the pose
 * (tests/ev3sim/apps/irprox through the whole stack): 100 with the wall
 * beyond its 70 cm, then the wall's distance as host_sim reports it
 * (mm / 7) when the app stops near it.
 */
#include <math.h>
#include <stdio.h>
#include <string.h>
#include "tap.h"
#include "ev3sim/run.h"
#include "ev3sim/world.h"

extern const struct rtos_cfg ev3rt_app_cfg;

static char lines[8][160];
static unsigned nlines;

/* Keeps the app's NOTICE lines. */
static void sink(const char *line, void *ctx)
{
	(void)ctx;
	if (strncmp(line, "NOTICE: irprox: ", 16) == 0 && nlines < 8)
		snprintf(lines[nlines++], sizeof(lines[0]), "%s", line + 16);
}

int main(void)
{
	struct ev3sim_world w = {
		.name = "irwall",
		.mat = { .kind = EV3SIM_MAT_PLAIN, .width = 1.5, .height = 0.6, .rgb = { 255, 255, 255 } },
		.obstacles = { { .kind = EV3SIM_OBST_SEGMENT, .x0 = 1.2, .y0 = 0, .x1 = 1.2, .y1 = 0.6, .height = 0.2 } },
		.nobstacles = 1,
		.robot = { .wheel_radius = 0.028, .track = 0.12, .mass = 0.75, .body_radius = 0.09, .rolling_crr = 0.03,
			   .left_port = 1, .right_port = 2, .motor = EV3SIM_OUT_LARGE,
			   .mounts = { { .port = 3, .device = EV3SIM_IN_IR, .x = 0.07, .height = 0.05,
					 .beam = EV3SIM_IR_BEAM_DEG * 3.14159265358979 / 180 } },
			   .nmounts = 1 },
		.start_x = 0.2, .start_y = 0.3,
	};
	struct ev3sim_run_opts o;
	struct ev3sim_run_result r;
	char err[256];
	int start = -1, t = 0, stop = -1;
	double expect;

	tap_plan(5);
	ev3sim_run_defaults_world(&o, &w);
	o.app_name = "irprox";
	o.seconds = 12;
	o.log_sink = sink;
	o.quiet = true;
	if (!ok(ev3sim_run(&o, &ev3rt_app_cfg, &r, err, sizeof(err)) == E_OK, "the app runs 12 s facing a wall: %s",
		r.end_status ? err : "")) {
		tap_skip(4, "no run");
		return tap_done();
	}
	for (unsigned i = 0; i < nlines; i++)
		tap_diag("%s", lines[i]);
	if (nlines > 0)
		(void)sscanf(lines[0], "start %d", &start);
	if (nlines > 1)
		(void)sscanf(lines[1], "stopped at %d ms, %d", &t, &stop);
	is_int(start, 100, "the wall 0.93 m ahead is beyond the sensor's 70 cm: proximity 100");
	ok(t > 0 && t < 15000 && stop >= 0 && stop <= 20, "it crept up until it read 20 or less (%d at %d ms)", stop, t);
	expect = (1.2 - (r.x_m + 0.07)) * 1000.0 / 7.0;
	ok(fabs(stop - expect) <= 2.0, "that is the wall's distance from the sensor in host_sim's units (%.1f)", expect);
	is_int(r.contacts, 0, "it stopped short of the wall");
	return tap_done();
}
