/*
 * tribot.h — a two-wheeled driving base (LEGO's educator vehicle layout: large
 * motors on B (left) and C (right), a caster behind) on a line-following mat.
 * Host only.
 *
 * It is the built-in world "line" (world.h): each physics step (a host event
 * every EV3SIM_TRIBOT_STEP_NS) turns the wheels' shaft angle changes into the
 * robot's motion over the mat (differential drive, no slip), hands the
 * motors their share of the robot's mass and rolling resistance
 * (hs_motor_set_load) and sets the scene of the colour sensor looking down in
 * front of the axle: reflected light, colour and raw RGB of the spot it sees;
 * the ultrasonic sensor sees nothing (255 cm), a gyro on a port follows the
 * turns.  This header adds the line's measures: the spot's distance from the
 * line and the progress along it.
 *
 * The mat is white with a black line of width EV3SIM_LINE_WIDTH_M laid as a
 * stadium: two straights of EV3SIM_LINE_STRAIGHT_M joined by half circles of
 * radius EV3SIM_LINE_RADIUS_M.  The robot starts on the lower straight,
 * heading along it (counter-clockwise round the track), with the sensor's
 * spot on the line.
 */
#ifndef EV3SIM_TRIBOT_H
#define EV3SIM_TRIBOT_H

#include <stdbool.h>
#include <stdint.h>
#include "kernel.h"
#include "ev3sim/apps.h"

#define EV3SIM_TRIBOT_STEP_NS   1000000ULL    /* physics step: 1 ms */

#define EV3SIM_LINE_WIDTH_M     0.020
#define EV3SIM_LINE_STRAIGHT_M  1.0
#define EV3SIM_LINE_RADIUS_M    0.40
/* Reflected light (COL-REFLECT, %) of the white mat and of the black line. */
#define EV3SIM_MAT_WHITE_PCT    64
#define EV3SIM_MAT_BLACK_PCT    5

/* The hand lifts the robot and puts it down again, as a user does to show
 * an app's calibration white and black: at t_ns (from boot) the robot moves
 * left_mm to its left (negative: right), keeping its heading. */
struct ev3sim_placement {
	uint64_t t_ns;
	double left_mm;
};

#define EV3SIM_MAX_PLACEMENTS   16U
#define EV3SIM_MAX_PLACE_MM     2000.0      /* how far the hand moves the robot at most */

struct ev3sim_tribot_cfg {
	unsigned left_port, right_port;     /* output ports 0..3 of the wheel motors */
	enum ev3sim_input_device in[4];     /* the devices plugged in: the colour sensor on 3 looks
					     * down, the ultrasonic on 4 ahead (when they are there) */
	const struct ev3sim_placement *placements;  /* any order */
	unsigned nplacements;               /* at most EV3SIM_MAX_PLACEMENTS */
};

/* One physics step's state. */
struct ev3sim_tribot_sample {
	uint64_t t_ns;
	double x_m, y_m, heading_deg;       /* axle centre on the mat, heading from +x */
	double sensor_x_m, sensor_y_m;      /* the colour sensor's spot */
	double line_error_m;                /* spot centre to the line's centre, signed: + outside */
	double line_cover;                  /* fraction of the spot on the line, 0..1 */
	double progress_m;                  /* distance along the line since the start (unwrapped) */
	double travel_m;                    /* distance the axle travelled */
	unsigned reflect_pct;               /* what the sensor sees */
};

/* Starts the physics on a booted board whose wheel motors (and colour sensor)
 * are attached: E_OBJ if one is missing, E_PAR for bad ports or placements. */
ER ev3sim_tribot_start(const struct ev3sim_tribot_cfg *cfg);
/* Stops the physics events (before hs_sim_shutdown). */
void ev3sim_tribot_stop(void);
/* The latest step's state. */
const struct ev3sim_tribot_sample *ev3sim_tribot_now(void);

#endif /* EV3SIM_TRIBOT_H */
