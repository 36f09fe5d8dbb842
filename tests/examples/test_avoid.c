/*
 * test_avoid.c — examples/avoid in the built-in world "maze": for a minute
 * it wanders, turning away from what its ultrasonic sensor sees ahead, and
 * never touches a wall, a box or a can (the world counts every move an
 * obstacle stops, and the body's least clearance), nor presses its bumper;
 * it covers several metres.  With the ultrasonic sensor mounted higher than
 * every wall (it sees over them: 255 cm) the same app drives into one.
 */
#include "example_test.h"
#include <math.h>
#include "ev3sim/world.h"

int main(void)
{
	const struct ev3sim_world *maze = ev3sim_world_builtin("maze");
	static struct ev3sim_world high;
	struct ev3sim_run_opts o;
	struct ev3sim_run_result r;
	int turns = 0, bumps = -1, wheels = 0;
	const char *line;

	ev3sim_run_defaults_world(&o, maze);
	o.app_name = "avoid";
	o.seconds = 64;
	if (!ok(ex_run(&o, &r), "avoid runs 64 s in the maze"))
		return tap_done();
	line = ex_logged("avoid: done");
	ok(line && sscanf(line, "avoid: done, %d turns, %d bumps, wheels %d deg", &turns, &bumps, &wheels) == 3,
	   "it ran its minute: %s", line ? line : "(nothing)");
	is_int(r.contacts, 0, "it never touched a wall or an obstacle");
	ok(r.min_clearance_mm > 0, "its body kept clear of everything (least %.0f mm)", r.min_clearance_mm);
	is_int(bumps, 0, "its bumper was never pressed");
	ok(turns >= 5, "it turned away from what it saw %d times", turns);
	ok(r.travel_m > 5.0, "it covered %.1f m", r.travel_m);
	is_int(r.warnings + r.errors + r.bugs, 0, "no warnings, errors or bugs");

	high = *maze;
	high.robot.mounts[3].height = 0.3;
	ev3sim_run_defaults_world(&o, &high);
	o.app_name = "avoid";
	o.seconds = 20;
	if (ok(ex_run(&o, &r), "with the ultrasonic sensor 300 mm up, over the 200 mm walls"))
		ok(r.contacts > 0, "it drives into a wall (%u contacts, least clearance %.0f mm)", r.contacts,
		   r.min_clearance_mm);
	else
		tap_skip(1, "no run");
	return tap_done();
}
