/*
 * world_builtin.c — the built-in worlds (world.h): the tribot's line mat,
 * an open walled arena and a maze with obstacles, each with the same driving
 * base (LEGO's educator vehicle layout: large motors on B and C, 56 mm tyres).
 */
#include <string.h>
#include "ev3sim/tribot.h"
#include "ev3sim/world.h"

#define PI 3.14159265358979323846
#define DEG (PI / 180.0)
#define WALL_H 0.20         /* m: walls and boxes stand higher than any sensor */
#define CAN_H  0.12         /* m: a drinks can */

const char ev3sim_world_builtin_names[] = "line, arena, maze";

/* The driving base: 56 mm tyres (LEGO's 56 x 28 wheel), 120 mm track, 0.75 kg,
 * a body 90 mm round from the axle's centre. */
#define BASE_ROBOT(...) { \
	.wheel_radius = 0.028, .track = 0.12, .mass = 0.75, .body_radius = 0.09, .rolling_crr = 0.03, \
	.left_port = 1, .right_port = 2, .motor = EV3SIM_OUT_LARGE, __VA_ARGS__ }

/* The colour sensor 80 mm ahead of the axle, 8 mm over the mat, seeing a
 * spot 12 mm across. */
#define COLOR_DOWN(p) { .port = (p), .device = EV3SIM_IN_COLOR, .x = 0.08, .height = 0.008, .footprint = 0.012 }
#define US_AHEAD(p) { .port = (p), .device = EV3SIM_IN_ULTRASONIC, .x = 0.06, .height = 0.08, \
		      .beam = EV3SIM_US_BEAM_DEG * DEG }
#define GYRO_YAW(p) { .port = (p), .device = EV3SIM_IN_GYRO, .height = 0.06 }
/* A bumper: the touch sensor's tip 105 mm ahead, 15 mm beyond the body. */
#define BUMPER(p) { .port = (p), .device = EV3SIM_IN_TOUCH, .x = 0.105, .height = 0.03 }

#define SEG(ax, ay, bx, by) { .kind = EV3SIM_OBST_SEGMENT, .x0 = (ax), .y0 = (ay), .x1 = (bx), .y1 = (by), \
			      .height = WALL_H }
#define BOX(ax, ay, bx, by) { .kind = EV3SIM_OBST_BOX, .x0 = (ax), .y0 = (ay), .x1 = (bx), .y1 = (by), \
			      .height = WALL_H }
#define CAN(cx, cy) { .kind = EV3SIM_OBST_CIRCLE, .x0 = (cx), .y0 = (cy), .x1 = (cx), .y1 = (cy), \
		      .r = 0.033, .height = CAN_H }
/* The walls round a w x h floor from the origin. */
#define BORDER(w, h) SEG(0, 0, w, 0), SEG(w, 0, w, h), SEG(w, h, 0, h), SEG(0, h, 0, 0)

/* The tribot's line mat: the stadium of tribot.h centred on the origin, the
 * robot on its lower straight heading along it, touch on port 1 (a button
 * the hand presses), colour on 3 looking down, ultrasonic on 4 (nothing to
 * see: it reads 255 cm), a gyro on 2 when one is plugged in.  The colour
 * sensor is the first mount (tribot.c measures the line under it). */
static const struct ev3sim_world line_world = {
	.name = "line",
	.mat = { .kind = EV3SIM_MAT_STADIUM, .x0 = -1.2, .y0 = -0.7, .width = 2.4, .height = 1.4,
		 .straight = EV3SIM_LINE_STRAIGHT_M, .radius = EV3SIM_LINE_RADIUS_M,
		 .line_width = EV3SIM_LINE_WIDTH_M },
	.robot = BASE_ROBOT(.mounts = { COLOR_DOWN(2), US_AHEAD(3), GYRO_YAW(1) }, .nmounts = 3),
	.start_x = -0.30, .start_y = -EV3SIM_LINE_RADIUS_M, .start_heading = 0.0,
};

/* An open white floor of 2 x 2 m with walls round it: room to drive shapes.
 * Bumper on 1, gyro on 2, colour on 3, ultrasonic on 4. */
static const struct ev3sim_world arena_world = {
	.name = "arena",
	.mat = { .kind = EV3SIM_MAT_PLAIN, .width = 2.0, .height = 2.0, .rgb = { 255, 255, 255 } },
	.obstacles = { BORDER(2.0, 2.0) },
	.nobstacles = 4,
	.robot = BASE_ROBOT(.mounts = { BUMPER(0), GYRO_YAW(1), COLOR_DOWN(2), US_AHEAD(3) }, .nmounts = 4),
	.start_x = 0.6, .start_y = 0.6, .start_heading = 0.0,
};

/* A 2.4 x 1.8 m walled floor with two long walls across it, boxes and cans;
 * the goal is the far corner.  The same robot as the arena's. */
static const struct ev3sim_world maze_world = {
	.name = "maze",
	.mat = { .kind = EV3SIM_MAT_PLAIN, .width = 2.4, .height = 1.8, .rgb = { 255, 255, 255 } },
	.obstacles = {
		BORDER(2.4, 1.8),
		BOX(0.78, 0.0, 0.82, 1.1),      /* a wall from the near side */
		BOX(1.58, 0.7, 1.62, 1.8),      /* one from the far side */
		BOX(1.1, 1.25, 1.3, 1.45),
		BOX(1.95, 0.25, 2.1, 0.4),
		CAN(0.4, 1.35), CAN(1.2, 0.35), CAN(2.05, 1.2),
	},
	.nobstacles = 11,
	.robot = BASE_ROBOT(.mounts = { BUMPER(0), GYRO_YAW(1), COLOR_DOWN(2), US_AHEAD(3) }, .nmounts = 4),
	.start_x = 0.35, .start_y = 0.35, .start_heading = 90.0 * DEG,
	.has_goal = true, .goal_x = 2.1, .goal_y = 1.5, .goal_r = 0.2,
};

const struct ev3sim_world *ev3sim_world_builtin(const char *name)
{
	static const struct ev3sim_world *const all[] = { &line_world, &arena_world, &maze_world };

	for (unsigned i = 0; i < sizeof(all) / sizeof(all[0]); i++)
		if (strcmp(name, all[i]->name) == 0)
			return all[i];
	return NULL;
}
