/*
 * tribot.c — the driving base on the line mat (tribot.h): the built-in world
 * "line" (world_builtin.c) with the wheel motors and sensors on the run's
 * ports, and the line's own measures — the spot's distance from the line and
 * the progress along it — taken after every step of the world.
 *
 * The line's centre is the set of points at EV3SIM_LINE_RADIUS_M from the
 * segment (-S/2, 0)..(S/2, 0) (S = EV3SIM_LINE_STRAIGHT_M): a stadium, so the
 * distance from any point to it is |d(point, segment) - R|.
 */
#include <math.h>
#include <stddef.h>
#include "ev3sim/tribot.h"
#include "ev3sim/world.h"

#define PI 3.14159265358979323846

#define HALF_S   (EV3SIM_LINE_STRAIGHT_M / 2.0)
#define LINE_R   EV3SIM_LINE_RADIUS_M
#define PERIMETER (2.0 * EV3SIM_LINE_STRAIGHT_M + 2.0 * PI * LINE_R)

static struct tribot {
	struct ev3sim_world world;
	double last_s;                  /* arc position of the spot at the last step */
	double spot_r;                  /* the colour sensor's spot radius */
	struct ev3sim_tribot_sample now;
} tb;

/* Arc position (m) of the point of the line nearest to (x, y), counter-clockwise
 * from the lower straight's left end. */
static double arc_position(double x, double y)
{
	if (x >= -HALF_S && x <= HALF_S)
		return y < 0 ? x + HALF_S : EV3SIM_LINE_STRAIGHT_M + PI * LINE_R + (HALF_S - x);
	if (x > HALF_S)
		return EV3SIM_LINE_STRAIGHT_M + (atan2(y, x - HALF_S) + PI / 2.0) * LINE_R;
	/* left half circle: angle from +pi/2 (top) round to 3pi/2 (bottom) */
	double a = atan2(y, x + HALF_S);

	if (a < 0)
		a += 2.0 * PI;
	return 2.0 * EV3SIM_LINE_STRAIGHT_M + PI * LINE_R + (a - PI / 2.0) * LINE_R;
}

/* Fraction of the sensor's spot over the line (a linear ramp across its edge). */
static double cover_of(double error_m)
{
	double inside = EV3SIM_LINE_WIDTH_M / 2.0 + tb.spot_r - fabs(error_m);
	double c = inside / (2.0 * tb.spot_r);

	return c < 0.0 ? 0.0 : c > 1.0 ? 1.0 : c;
}

/* The line's measures after a step of the world; a placement (the hand
 * carried the robot) starts the progress again from where it is put down. */
static void line_step(const struct ev3sim_world_state *s, bool placed, void *ctx)
{
	const struct ev3sim_world_robot *rb = &tb.world.robot;
	double h = s->heading_deg * (PI / 180.0);
	double ahead = rb->nmounts > 0 ? rb->mounts[0].x : 0.08;
	double sx = s->x + ahead * cos(h), sy = s->y + ahead * sin(h);
	double arc = arc_position(sx, sy), dprog;

	(void)ctx;
	if (placed)
		tb.last_s = arc;
	dprog = arc - tb.last_s;
	if (dprog > PERIMETER / 2.0)
		dprog -= PERIMETER;
	else if (dprog < -PERIMETER / 2.0)
		dprog += PERIMETER;
	tb.last_s = arc;
	tb.now.t_ns = s->t_ns;
	tb.now.x_m = s->x;
	tb.now.y_m = s->y;
	tb.now.heading_deg = s->heading_deg;
	tb.now.sensor_x_m = sx;
	tb.now.sensor_y_m = sy;
	tb.now.line_error_m = ev3sim_stadium_error(&tb.world.mat, sx, sy);
	tb.now.line_cover = cover_of(tb.now.line_error_m);
	tb.now.progress_m += dprog;
	tb.now.travel_m = s->travel_m;
	tb.now.reflect_pct = (unsigned)lround(EV3SIM_MAT_BLACK_PCT * tb.now.line_cover +
					      EV3SIM_MAT_WHITE_PCT * (1.0 - tb.now.line_cover));
}

ER ev3sim_tribot_start(const struct ev3sim_tribot_cfg *cfg)
{
	struct ev3sim_world_placement pl[EV3SIM_MAX_PLACEMENTS];
	struct ev3sim_world_run run = { .world = &tb.world, .on_step = line_step };
	ER ercd;

	if (cfg == NULL || cfg->left_port >= 4 || cfg->right_port >= 4 ||
	    cfg->left_port == cfg->right_port ||
	    cfg->nplacements > EV3SIM_MAX_PLACEMENTS || (cfg->nplacements > 0 && cfg->placements == NULL))
		return E_PAR;
	for (unsigned i = 0; i < cfg->nplacements; i++) {
		if (!(fabs(cfg->placements[i].left_mm) <= EV3SIM_MAX_PLACE_MM))
			return E_PAR;
		pl[i].t_ns = cfg->placements[i].t_ns;
		pl[i].left_m = cfg->placements[i].left_mm / 1000.0;
	}
	ev3sim_tribot_stop();
	tb = (struct tribot){ .world = *ev3sim_world_builtin("line") };
	tb.world.robot.left_port = cfg->left_port;
	tb.world.robot.right_port = cfg->right_port;
	tb.spot_r = tb.world.robot.mounts[0].footprint / 2.0;
	for (unsigned p = 0; p < 4; p++)
		run.in[p] = cfg->in[p];
	run.placements = pl;
	run.nplacements = cfg->nplacements;
	ercd = ev3sim_world_start(&run);
	if (ercd != E_OK)
		return ercd;
	tb.now.x_m = tb.world.start_x;
	tb.now.y_m = tb.world.start_y;
	tb.now.sensor_x_m = tb.world.start_x + tb.world.robot.mounts[0].x;
	tb.now.sensor_y_m = tb.world.start_y;
	tb.last_s = arc_position(tb.now.sensor_x_m, tb.now.sensor_y_m);
	tb.now.line_error_m = ev3sim_stadium_error(&tb.world.mat, tb.now.sensor_x_m, tb.now.sensor_y_m);
	tb.now.line_cover = cover_of(tb.now.line_error_m);
	tb.now.reflect_pct = (unsigned)lround(EV3SIM_MAT_BLACK_PCT * tb.now.line_cover +
					      EV3SIM_MAT_WHITE_PCT * (1.0 - tb.now.line_cover));
	return E_OK;
}

void ev3sim_tribot_stop(void)
{
	ev3sim_world_stop();
}

const struct ev3sim_tribot_sample *ev3sim_tribot_now(void)
{
	return &tb.now;
}
