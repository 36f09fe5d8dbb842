/*
 * test_linetrace.c — examples/linetrace on the tribot's line mat: it waits,
 * busy-polling, for the touch sensor, then follows the line with
 * ev3_motor_steer; without the press it never starts.  While it waits the
 * hand puts the robot down elsewhere (--place): the sensor sees the white
 * mat, then the line again, and the hand's moves are no progress.
 */
#include "example_test.h"
#include <math.h>
#include "ev3sim/tribot.h"

int main(void)
{
	struct ev3sim_run_opts o;
	struct ev3sim_run_result r;

	ev3sim_run_defaults(&o, EV3SIM_ROBOT_TRIBOT);
	o.app_name = "linetrace";
	o.seconds = 45;
	if (!ok(ex_run(&o, &r), "linetrace runs 45 s on the tribot"))
		return tap_done();
	ok(ex_logged("linetrace: go") != NULL, "the touch press started it");
	ok(r.progress_m > 4.6, "it went round the whole 4.51 m track along the line (%.2f m)", r.progress_m);
	in_range(r.progress_m, r.travel_m * 0.9, r.travel_m * 1.1,
		 "all its travel (%.2f m) was progress along the line", r.travel_m);
	ok(r.max_line_error_mm < 25.0, "the sensor stayed within 25 mm of the line (max %.1f mm)",
	   r.max_line_error_mm);
	is_int(r.on_line_pct, 100, "it saw the line all the time");
	is_int(r.warnings + r.errors + r.bugs, 0, "no warnings, errors or bugs");

	ev3sim_run_defaults(&o, EV3SIM_ROBOT_TRIBOT);
	o.app_name = "linetrace";
	o.seconds = 8;
	o.nactions = 0;     /* nobody presses the touch sensor */
	if (ex_run(&o, &r))
		ok(r.travel_m < 0.001, "without the press it waits (travel %.4f m)", r.travel_m);
	ok(ex_logged("linetrace: go") == NULL, "and never starts");

	ev3sim_run_defaults(&o, EV3SIM_ROBOT_TRIBOT);
	o.app_name = "linetrace";
	o.seconds = 2;
	o.nactions = 0;
	o.placements[0] = (struct ev3sim_placement){ .t_ns = 1500000000ULL, .left_mm = -20.0 };
	o.placements[1] = (struct ev3sim_placement){ .t_ns = 1000000000ULL, .left_mm = 60.0 };
	o.nplacements = 2;
	if (ex_run(&o, &r)) {
		const struct ev3sim_tribot_sample *s = ev3sim_tribot_now();

		in_range(s->y_m, -EV3SIM_LINE_RADIUS_M + 0.0399, -EV3SIM_LINE_RADIUS_M + 0.0401,
			 "the hand's moves, in time order, put it 60 mm left and then 20 mm right (y %.4f m)", s->y_m);
		is_int(s->reflect_pct, EV3SIM_MAT_WHITE_PCT, "its sensor sees the white mat there");
		ok(fabs(r.progress_m) < 0.0001 && r.travel_m < 0.001, "being carried is neither progress nor travel (%.6f m, %.6f m)",
		   r.progress_m, r.travel_m);
	}
	return tap_done();
}
