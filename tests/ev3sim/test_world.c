/*
 * test_world.c — the world's geometry and checks (world.h): distances to and
 * rays against segments, boxes and circles; the mat's colour under a point
 * (plain, the stadium line, an image, off the mat); the built-in worlds; and
 * a world's bad numbers named by ev3sim_world_check.
 */
#include <math.h>
#include <string.h>
#include "tap.h"
#include "ev3sim/world.h"

#define PI 3.14159265358979323846

int main(void)
{
	const struct ev3sim_obstacle seg = { .kind = EV3SIM_OBST_SEGMENT, .x0 = 1, .y0 = -1, .x1 = 1, .y1 = 1, .height = 0.2 };
	const struct ev3sim_obstacle box = { .kind = EV3SIM_OBST_BOX, .x0 = 2, .y0 = 1, .x1 = 1, .y1 = -1, .height = 0.2 };
	const struct ev3sim_obstacle can = { .kind = EV3SIM_OBST_CIRCLE, .x0 = 2, .y0 = 0, .r = 0.5, .height = 0.1 };
	static const uint8_t px[2][2][3] = { { { 255, 0, 0 }, { 0, 255, 0 } }, { { 0, 0, 255 }, { 10, 20, 30 } } };
	struct ev3sim_world_mat img = { .kind = EV3SIM_MAT_IMAGE, .x0 = 0, .y0 = 0, .width = 2, .height = 2,
					.px_w = 2, .px_h = 2, .pixels = &px[0][0][0] };
	const struct ev3sim_world *line = ev3sim_world_builtin("line");
	struct ev3sim_world w;
	uint8_t rgb[3];

	tap_plan(27);
	in_range(ev3sim_obstacle_distance(&seg, 0, 0), 0.9999, 1.0001, "a point 1 m from a wall");
	in_range(ev3sim_obstacle_distance(&seg, 1, 3), 1.9999, 2.0001, "beyond its end: to the end");
	is_int(ev3sim_obstacle_distance(&box, 1.5, 0) == 0.0, 1, "inside a box: 0");
	in_range(ev3sim_obstacle_distance(&box, 3, 2), sqrt(2) - 1e-9, sqrt(2) + 1e-9, "off a box's corner: to the corner");
	in_range(ev3sim_obstacle_distance(&can, 0, 0), 1.4999, 1.5001, "to a can's side");
	in_range(ev3sim_obstacle_ray(&seg, 0, 0, 0), 0.9999, 1.0001, "a ray straight at the wall");
	in_range(ev3sim_obstacle_ray(&seg, 0, 0, PI / 4), 1.414, 1.415, "a ray at 45 degrees: sqrt 2");
	ok(ev3sim_obstacle_ray(&seg, 0, 0, PI) < 0, "a ray away from it misses");
	ok(ev3sim_obstacle_ray(&seg, 0, 0, PI / 2) < 0, "a ray along it misses");
	in_range(ev3sim_obstacle_ray(&box, 0, 0, 0), 0.9999, 1.0001, "a ray at a box hits its near side");
	in_range(ev3sim_obstacle_ray(&can, 0, 0, 0), 1.4999, 1.5001, "a ray at a can hits its near side");
	ok(ev3sim_obstacle_ray(&can, 0, 0.6, 0) < 0, "a ray passing a can misses");

	ev3sim_world_mat_rgb(&img, 0.5, 1.5, rgb);
	ok(rgb[0] == 255 && rgb[1] == 0 && rgb[2] == 0, "an image's top-left pixel is the far left corner");
	ev3sim_world_mat_rgb(&img, 1.5, 0.5, rgb);
	ok(rgb[0] == 10 && rgb[1] == 20 && rgb[2] == 30, "its bottom-right the near right corner");
	ev3sim_world_mat_rgb(&img, 2.5, 0.5, rgb);
	ok(rgb[0] == 255 && rgb[1] == 255 && rgb[2] == 255, "off the mat: white");
	ok(line != NULL && line->mat.kind == EV3SIM_MAT_STADIUM, "the built-in \"line\" is the stadium mat");
	ev3sim_world_mat_rgb(&line->mat, line->start_x + 0.08, line->start_y, rgb);
	ok(rgb[0] == 0, "the tribot's colour sensor starts over the black line");
	in_range(ev3sim_stadium_error(&line->mat, 0, 0), -0.4001, -0.3999, "the stadium's centre is 0.4 m inside its line");
	ok(ev3sim_world_builtin("arena") != NULL && ev3sim_world_builtin("maze") != NULL &&
	   ev3sim_world_builtin("nowhere") == NULL, "arena and maze are built in, nothing else (%s)",
	   ev3sim_world_builtin_names);
	ok(ev3sim_world_check(line) == NULL && ev3sim_world_check(ev3sim_world_builtin("maze")) == NULL,
	   "the built-in worlds pass the checks");

	w = *ev3sim_world_builtin("maze");
	w.start_x = 0.8;
	w.start_y = 0.5;
	is_str(ev3sim_world_check(&w), "the robot starts inside an obstacle (its body radius reaches one)",
	       "a start inside a wall is refused");
	w = *ev3sim_world_builtin("maze");
	w.robot.mounts[1].port = 0;
	is_str(ev3sim_world_check(&w), "two sensors on one port", "two sensors on a port");
	w = *ev3sim_world_builtin("maze");
	w.robot.right_port = w.robot.left_port;
	is_str(ev3sim_world_check(&w), "the wheel motors need two different output ports A..D", "one motor port for both wheels");
	w = *ev3sim_world_builtin("maze");
	w.robot.wheel_radius = 0;
	is_str(ev3sim_world_check(&w), "the wheel radius must be 5..200 mm", "no wheels");
	w = *ev3sim_world_builtin("maze");
	w.obstacles[4].height = NAN;
	is_str(ev3sim_world_check(&w), "an obstacle needs finite coordinates and a height > 0", "a NaN height");
	w = *ev3sim_world_builtin("maze");
	w.mat.width = -1;
	is_str(ev3sim_world_check(&w), "the mat's size must be 0 < size <= 100 m", "a negative mat");
	w = *ev3sim_world_builtin("maze");
	w.robot.mounts[3].beam = 4;
	is_str(ev3sim_world_check(&w), "a beam must be 0..180 degrees", "a beam over 180 degrees");
	return tap_done();
}
