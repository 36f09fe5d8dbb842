/*
 * world.c — a driving robot in a world (world.h): differential drive over
 * the mat, obstacles that stop it, and the sensors' physical inputs set from
 * its pose in host_sim's device models.
 */
#include <math.h>
#include <stdlib.h>
#include <string.h>
#include "host_sim/clock.h"
#include "host_sim/rng.h"
#include "host_sim/devices/ev3_brick.h"
#include "host_sim/devices/ev3_motor.h"
#include "host_sim/devices/uart_sensor.h"
#include "ev3sim/world.h"

#define PI 3.14159265358979323846
#define DEG (PI / 180.0)
#define GRAVITY 9.81
/* Below this shaft speed (deg/s) a wheel's rolling or slipping resistance
 * fades out linearly: no sign chatter at rest. */
#define SMOOTH_DPS 10.0
/* Rubber tyre on a hard floor: what a wheel can push before it spins
 * (a typical friction coefficient; an estimate). */
#define TYRE_MU 0.8
/* A touch sensor's tip: a small sphere; pressed within a millimetre of an obstacle. */
#define TOUCH_TIP_M 0.004
#define TOUCH_REACH_M 0.001
/* The colour sensor's spot is its footprint at this height and grows above
 * it; what comes back falls with the square of the height beyond twice it
 * (an estimate: LEGO gives no optics). */
#define COLOR_REF_HEIGHT_M 0.008
#define RAYS_PER_BEAM 7
/* The ultrasonic and infrared sensors' distances are cast every 5 steps
 * (5 ms, in which the robot moves a few millimetres at most): the ray
 * casting is the step's dearest part, and the sensors themselves measure
 * no faster (host_sim sends a sample every 10 ms or more). */
#define RANGE_EVERY_STEPS 5U
#define STEP_S (EV3SIM_WORLD_STEP_NS * 1e-9)

static struct world {
	bool running, active;
	struct ev3sim_world w;
	struct ev3sim_world_run run;
	struct ev3sim_world_placement placements[EV3SIM_WORLD_MAX_PLACEMENTS];
	unsigned nplacements, next_placement;
	struct hs_motor *motor[2];
	hs_event_t step_ev;
	double angle_deg[2];
	double x, y, heading;
	bool blocked;
	uint64_t steps;
	bool touch_pressed[4];
	struct hs_rng slip_rng;
	struct ev3sim_world_point *trail;
	size_t ntrail, trail_cap;
	struct ev3sim_world_state now;
} wd;

/* ---- geometry ---- */

/* Distance from (px, py) to the segment (ax, ay)-(bx, by). */
static double segment_distance(double ax, double ay, double bx, double by, double px, double py)
{
	double dx = bx - ax, dy = by - ay, len2 = dx * dx + dy * dy;
	double t = len2 > 0 ? ((px - ax) * dx + (py - ay) * dy) / len2 : 0.0;

	t = t < 0 ? 0 : t > 1 ? 1 : t;
	return hypot(px - (ax + t * dx), py - (ay + t * dy));
}

double ev3sim_obstacle_distance(const struct ev3sim_obstacle *o, double x, double y)
{
	switch (o->kind) {
	case EV3SIM_OBST_SEGMENT:
		return segment_distance(o->x0, o->y0, o->x1, o->y1, x, y);
	case EV3SIM_OBST_BOX: {
		double lx = fmin(o->x0, o->x1), hx = fmax(o->x0, o->x1);
		double ly = fmin(o->y0, o->y1), hy = fmax(o->y0, o->y1);
		double dx = x < lx ? lx - x : x > hx ? x - hx : 0.0;
		double dy = y < ly ? ly - y : y > hy ? y - hy : 0.0;

		return hypot(dx, dy);
	}
	default: {
		double d = hypot(x - o->x0, y - o->y0) - o->r;

		return d > 0 ? d : 0.0;
	}
	}
}

/* Distance along the ray (x, y) + t (cx, cy) to the segment, or -1. */
static double ray_segment(double x, double y, double cx, double cy,
			  double ax, double ay, double bx, double by)
{
	double ex = bx - ax, ey = by - ay;
	double den = cx * ey - cy * ex;
	double t, s;

	if (fabs(den) < 1e-15)
		return -1.0;    /* parallel: a wall seen edge-on returns no echo */
	t = ((ax - x) * ey - (ay - y) * ex) / den;
	s = ((ax - x) * cy - (ay - y) * cx) / den;
	return t >= 0 && s >= 0 && s <= 1 ? t : -1.0;
}

/* The nearer of two ray distances (negative: a miss). */
static double nearer(double a, double b)
{
	return a < 0 ? b : b < 0 ? a : fmin(a, b);
}

double ev3sim_obstacle_ray(const struct ev3sim_obstacle *o, double x, double y, double a)
{
	double cx = cos(a), cy = sin(a);

	switch (o->kind) {
	case EV3SIM_OBST_SEGMENT:
		return ray_segment(x, y, cx, cy, o->x0, o->y0, o->x1, o->y1);
	case EV3SIM_OBST_BOX: {
		double d = -1.0;

		d = nearer(d, ray_segment(x, y, cx, cy, o->x0, o->y0, o->x1, o->y0));
		d = nearer(d, ray_segment(x, y, cx, cy, o->x1, o->y0, o->x1, o->y1));
		d = nearer(d, ray_segment(x, y, cx, cy, o->x1, o->y1, o->x0, o->y1));
		d = nearer(d, ray_segment(x, y, cx, cy, o->x0, o->y1, o->x0, o->y0));
		return d;
	}
	default: {
		/* |p + t c - o|^2 = r^2, |c| = 1 */
		double px = x - o->x0, py = y - o->y0;
		double b = px * cx + py * cy, c = px * px + py * py - o->r * o->r;
		double disc = b * b - c, t;

		if (disc < 0)
			return -1.0;
		t = -b - sqrt(disc);
		return t >= 0 ? t : (c <= 0 ? 0.0 : -1.0);
	}
	}
}

/* ---- the mat ---- */

double ev3sim_stadium_error(const struct ev3sim_world_mat *m, double x, double y)
{
	double half = m->straight / 2.0;
	double px = x - m->cx, py = y - m->cy;
	double cx = px < -half ? -half : px > half ? half : px;

	return hypot(px - cx, py) - m->radius;
}

void ev3sim_world_mat_rgb(const struct ev3sim_world_mat *m, double x, double y, uint8_t rgb[3])
{
	memset(rgb, 255, 3);
	if (x < m->x0 || y < m->y0 || x >= m->x0 + m->width || y >= m->y0 + m->height)
		return;
	switch (m->kind) {
	case EV3SIM_MAT_PLAIN:
		memcpy(rgb, m->rgb, 3);
		break;
	case EV3SIM_MAT_STADIUM:
		if (fabs(ev3sim_stadium_error(m, x, y)) <= m->line_width / 2.0)
			memset(rgb, 0, 3);
		break;
	default: {
		unsigned col = (unsigned)((x - m->x0) / m->width * m->px_w);
		unsigned row = (unsigned)((m->y0 + m->height - y) / m->height * m->px_h);

		if (col >= m->px_w)
			col = m->px_w - 1;
		if (row >= m->px_h)
			row = m->px_h - 1;
		memcpy(rgb, m->pixels + ((size_t)row * m->px_w + col) * 3, 3);
		break;
	}
	}
}

/* EV3 colour codes (COL-COLOR: 2 blue .. 7 brown) and surfaces of those colours. */
static const struct { uint8_t code, rgb[3]; } palette[] = {
	{ 2, { 0, 0, 255 } }, { 3, { 0, 160, 0 } }, { 4, { 255, 255, 0 } }, { 5, { 255, 0, 0 } },
	{ 7, { 128, 64, 0 } },
};

/* The EV3 colour code of an RGB surface: a grey one is white (6) or black
 * (1) by its lightness, as the sensor tells no greys apart; a coloured one
 * the nearest of the others. */
static uint8_t colour_code(const double rgb[3])
{
	double hi = fmax(rgb[0], fmax(rgb[1], rgb[2])), lo = fmin(rgb[0], fmin(rgb[1], rgb[2]));
	double best = 1e30;
	uint8_t code = 0;

	if (hi - lo < 80.0)
		return (rgb[0] + rgb[1] + rgb[2]) / 3.0 >= 100.0 ? 6 : 1;
	for (unsigned i = 0; i < sizeof(palette) / sizeof(palette[0]); i++) {
		double d = 0;

		for (int c = 0; c < 3; c++)
			d += (rgb[c] - palette[i].rgb[c]) * (rgb[c] - palette[i].rgb[c]);
		if (d < best) {
			best = d;
			code = palette[i].code;
		}
	}
	return code;
}

/* Fraction of a spot of radius r over the stadium's line (a linear ramp across its edge). */
static double stadium_cover(const struct ev3sim_world_mat *m, double error_m, double r)
{
	double inside = m->line_width / 2.0 + r - fabs(error_m);
	double c = inside / (2.0 * r);

	return c < 0.0 ? 0.0 : c > 1.0 ? 1.0 : c;
}

/* What a colour sensor at (sx, sy) sees: its scene's light fields; returns reflected %. */
static unsigned colour_scene(const struct ev3sim_world_mount *mt, double sx, double sy,
			     struct uart_sensor_scene *scene)
{
	const struct ev3sim_world_mat *m = &wd.w.mat;
	double r = mt->footprint / 2.0 * fmax(1.0, mt->height / COLOR_REF_HEIGHT_M);
	double att = mt->height > 2.0 * COLOR_REF_HEIGHT_M ?
		     (2.0 * COLOR_REF_HEIGHT_M / mt->height) * (2.0 * COLOR_REF_HEIGHT_M / mt->height) : 1.0;
	double avg[3] = { 0, 0, 0 };
	unsigned reflect;

	if (m->kind == EV3SIM_MAT_STADIUM) {
		double cover = stadium_cover(m, ev3sim_stadium_error(m, sx, sy), r);
		double white = 1.0 - cover;

		reflect = (unsigned)lround((EV3SIM_BLACK_PCT * cover + EV3SIM_WHITE_PCT * white) * att);
		scene->reflect_pct = (uint8_t)reflect;
		scene->color = att < 0.1 ? 0 : cover > 0.5 ? 1 : 6;
		for (int i = 0; i < 3; i++)
			scene->rgb[i] = (uint16_t)lround((30.0 * cover + 420.0 * white) * att);
		return reflect;
	}
	/* the mean colour over the spot: a 5 x 5 grid, the points inside the
	 * circle (a plain mat is one colour: its centre) */
	unsigned n = 0;
	int reach = m->kind == EV3SIM_MAT_PLAIN ? 0 : 2;

	for (int i = -reach; i <= reach; i++)
		for (int j = -reach; j <= reach; j++) {
			uint8_t px[3];

			if (i * i + j * j > 5)
				continue;
			ev3sim_world_mat_rgb(m, sx + r * i / 2.0, sy + r * j / 2.0, px);
			for (int c = 0; c < 3; c++)
				avg[c] += px[c];
			n++;
		}
	for (int c = 0; c < 3; c++)
		avg[c] /= n;
	/* reflected light is measured in the sensor's red light: a red surface
	 * reads as bright as white, a blue one as dark as black */
	reflect = (unsigned)lround((EV3SIM_BLACK_PCT + (EV3SIM_WHITE_PCT - EV3SIM_BLACK_PCT) * avg[0] / 255.0) * att);
	scene->reflect_pct = (uint8_t)reflect;
	scene->color = att < 0.1 ? 0 : colour_code(avg);
	for (int c = 0; c < 3; c++)
		scene->rgb[c] = (uint16_t)lround((30.0 + 390.0 * avg[c] / 255.0) * att);
	return reflect;
}

/* ---- the robot ---- */

/* A point of the robot frame (fx forward, fy left) on the mat, at pose (x, y, h). */
static void to_mat(double x, double y, double h, double fx, double fy, double *mx, double *my)
{
	*mx = x + fx * cos(h) - fy * sin(h);
	*my = y + fx * sin(h) + fy * cos(h);
}

/* The body's distance to the nearest obstacle, and whether a touch tip
 * would be inside one, at pose (x, y, h). */
static double clearance_at(double x, double y, double h, bool *tip_inside)
{
	double best = 1e30, tip[EV3SIM_WORLD_MAX_MOUNTS][2];
	unsigned ntips = 0;

	*tip_inside = false;
	for (unsigned k = 0; k < wd.w.robot.nmounts; k++) {
		const struct ev3sim_world_mount *mt = &wd.w.robot.mounts[k];

		if (mt->device == EV3SIM_IN_TOUCH) {
			to_mat(x, y, h, mt->x, mt->y, &tip[ntips][0], &tip[ntips][1]);
			ntips++;
		}
	}
	for (unsigned i = 0; i < wd.w.nobstacles; i++) {
		const struct ev3sim_obstacle *o = &wd.w.obstacles[i];
		double d = ev3sim_obstacle_distance(o, x, y) - wd.w.robot.body_radius;

		if (d < best)
			best = d;
		for (unsigned k = 0; k < ntips; k++)
			if (ev3sim_obstacle_distance(o, tip[k][0], tip[k][1]) < TOUCH_TIP_M)
				*tip_inside = true;
	}
	return best;
}

/* Whether a touch tip at pose (x, y, h) is within reach of an obstacle. */
static bool tip_touches(const struct ev3sim_world_mount *mt, double x, double y, double h)
{
	double tx, ty;

	to_mat(x, y, h, mt->x, mt->y, &tx, &ty);
	for (unsigned i = 0; i < wd.w.nobstacles; i++)
		if (ev3sim_obstacle_distance(&wd.w.obstacles[i], tx, ty) <= TOUCH_TIP_M + TOUCH_REACH_M)
			return true;
	return false;
}

/* The nearest obstacle within a beam from (sx, sy) facing a, seen from height
 * h (obstacles lower than the sensor are not seen): distance, or range when none. */
static double beam_distance(double sx, double sy, double a, double beam, double h, double range)
{
	double best = range;

	for (int k = 0; k < RAYS_PER_BEAM; k++) {
		double ray = a + beam * ((double)k / (RAYS_PER_BEAM - 1) - 0.5);

		for (unsigned i = 0; i < wd.w.nobstacles; i++) {
			const struct ev3sim_obstacle *o = &wd.w.obstacles[i];
			double d;

			if (o->height < h)
				continue;
			d = ev3sim_obstacle_ray(o, sx, sy, ray);
			if (d >= 0 && d < best)
				best = d;
		}
	}
	return best;
}

/* Rolling resistance (or, against an obstacle, the tyre's grip) on one wheel at shaft speed dps, N m. */
static double wheel_load(double dps, double coeff)
{
	double full = coeff * wd.w.robot.mass / 2.0 * GRAVITY * wd.w.robot.wheel_radius;
	double s = dps / SMOOTH_DPS;

	return full * (s > 1.0 ? 1.0 : s < -1.0 ? -1.0 : s);
}

/* Sets every mounted sensor's physical input from the pose; yaw_dps: the
 * body's rate; ranges: cast the ultrasonic and infrared beams too. */
static void sense(double yaw_dps, bool ranges)
{
	bool spot_set = false;

	for (unsigned k = 0; k < wd.w.robot.nmounts; k++) {
		const struct ev3sim_world_mount *mt = &wd.w.robot.mounts[k];
		struct uart_sensor *s;
		struct uart_sensor_scene scene;
		double sx, sy;

		if (wd.run.in[mt->port] != mt->device)
			continue;
		to_mat(wd.x, wd.y, wd.heading, mt->x, mt->y, &sx, &sy);
		if (mt->device == EV3SIM_IN_TOUCH) {
			bool pressed = tip_touches(mt, wd.x, wd.y, wd.heading);

			wd.now.port_value[mt->port] = pressed;
			if (pressed != wd.touch_pressed[mt->port]) {
				wd.touch_pressed[mt->port] = pressed;
				(void)ev3_set_touch(mt->port, pressed);
			}
			continue;
		}
		s = ev3_input_uart_sensor(mt->port);     /* NULL: unplugged by a fault */
		if (s != NULL)
			scene = *uart_sensor_scene(s);
		else
			memset(&scene, 0, sizeof(scene));
		switch (mt->device) {
		case EV3SIM_IN_COLOR:
			wd.now.port_value[mt->port] = colour_scene(mt, sx, sy, &scene);
			if (!spot_set) {
				wd.now.spot_x = sx;
				wd.now.spot_y = sy;
				spot_set = true;
			}
			break;
		case EV3SIM_IN_ULTRASONIC: {
			double d;

			if (!ranges)
				continue;
			d = beam_distance(sx, sy, wd.heading + mt->direction, mt->beam, mt->height,
						 EV3SIM_US_NOTHING_M);

			d = d < EV3SIM_US_MIN_M ? EV3SIM_US_MIN_M : d;
			scene.distance_mm = (uint32_t)lround(d * 1000.0);
			wd.now.port_value[mt->port] = scene.distance_mm;
			break;
		}
		case EV3SIM_IN_IR: {
			double d;

			if (!ranges)
				continue;
			d = beam_distance(sx, sy, wd.heading + mt->direction, mt->beam, mt->height,
					  EV3SIM_IR_RANGE_M);
			scene.distance_mm = (uint32_t)lround(d * 1000.0);
			wd.now.port_value[mt->port] = scene.distance_mm;
			break;
		}
		case EV3SIM_IN_GYRO:
			/* the EV3 gyro counts clockwise positive seen from its top
			 * (MathWorks, LEGO MINDSTORMS EV3 Support: "Gyro Sensors"):
			 * the mat's counter-clockwise heading with its sign turned */
			if (!mt->pitch_axis)
				scene.rate_dps = mt->inverted ? yaw_dps : -yaw_dps;
			wd.now.port_value[mt->port] = mt->inverted ? wd.now.heading_deg : -wd.now.heading_deg;
			break;
		default:
			continue;
		}
		if (s != NULL)
			uart_sensor_set_scene(s, &scene);
	}
}

/* The hand's placements due by t; whether one moved the robot. */
static bool apply_placements(uint64_t t)
{
	bool placed = false;

	while (wd.next_placement < wd.nplacements && wd.placements[wd.next_placement].t_ns <= t) {
		double left_m = wd.placements[wd.next_placement++].left_m;

		wd.x -= left_m * sin(wd.heading);
		wd.y += left_m * cos(wd.heading);
		placed = true;
	}
	return placed;
}

/* Appends the pose to the trail (a failed growth keeps the trail as it is). */
static void trail_add(uint64_t t)
{
	if (wd.ntrail == wd.trail_cap) {
		size_t cap = wd.trail_cap ? wd.trail_cap * 2 : 4096;
		struct ev3sim_world_point *p = realloc(wd.trail, cap * sizeof(*p));

		if (p == NULL)
			return;
		wd.trail = p;
		wd.trail_cap = cap;
	}
	wd.trail[wd.ntrail++] = (struct ev3sim_world_point){ t * 1e-9, wd.x, wd.y, wd.heading / DEG };
	wd.now.trail = wd.trail;
	wd.now.ntrail = wd.ntrail;
}

/* The state's pose fields, clearance and goal, from the robot now; clearance:
 * the body's at this pose, or NAN when it is not known yet. */
static void observe_pose(uint64_t t, double clearance)
{
	bool tip_inside;

	wd.now.t_ns = t;
	wd.now.x = wd.x;
	wd.now.y = wd.y;
	wd.now.heading_deg = wd.heading / DEG;
	if (wd.w.nobstacles > 0) {
		wd.now.clearance_m = isnan(clearance) ? clearance_at(wd.x, wd.y, wd.heading, &tip_inside) : clearance;
		if (wd.now.clearance_m < wd.now.min_clearance_m)
			wd.now.min_clearance_m = wd.now.clearance_m;
	}
	if (wd.w.has_goal && !wd.now.goal_reached && hypot(wd.x - wd.w.goal_x, wd.y - wd.w.goal_y) <= wd.w.goal_r) {
		wd.now.goal_reached = true;
		wd.now.goal_at_s = t * 1e-9;
	}
}

/* Event: one physics step. */
static void world_step(void *arg)
{
	const struct ev3sim_world_robot *rb = &wd.w.robot;
	uint64_t t = hs_now();
	double d[2], ds, dpsi, nx, ny, nh, yaw_dps = 0.0, clear = NAN;
	bool placed, moved;

	(void)arg;
	wd.step_ev = 0;
	for (int i = 0; i < 2; i++) {
		double a = hs_motor_angle_deg(wd.motor[i]);
		double dps = hs_motor_speed_dps(wd.motor[i]);

		d[i] = (a - wd.angle_deg[i]) * DEG * rb->wheel_radius;
		wd.angle_deg[i] = a;
		/* against an obstacle the robot stands: the wheels spin on the floor
		 * once the motors beat the tyres' grip */
		if (wd.blocked)
			hs_motor_set_load(wd.motor[i], wheel_load(dps, TYRE_MU), 0.0);
		else
			hs_motor_set_load(wd.motor[i], wheel_load(dps, rb->rolling_crr),
					  rb->mass / 2.0 * rb->wheel_radius * rb->wheel_radius);
		if (rb->slip > 0) {
			double f = rb->slip * (1.0 + 0.5 * hs_rng_gauss(&wd.slip_rng));

			d[i] *= 1.0 - (f < 0 ? 0 : f > 1 ? 1 : f);
		}
	}
	ds = (d[0] + d[1]) / 2.0;
	dpsi = (d[1] - d[0]) / rb->track;
	nx = wd.x + ds * cos(wd.heading + dpsi / 2.0);
	ny = wd.y + ds * sin(wd.heading + dpsi / 2.0);
	nh = wd.heading + dpsi;
	moved = ds != 0 || dpsi != 0;
	clear = wd.now.clearance_m;     /* the pose's, while it stays */
	if (wd.w.nobstacles > 0 && moved) {
		bool tip_inside;
		double c = clearance_at(nx, ny, nh, &tip_inside);

		if (c < 0 || tip_inside) {
			if (!wd.blocked)
				wd.now.contacts++;
			wd.blocked = true;
			moved = false;
		} else {
			clear = c;
		}
	}
	if (moved) {
		wd.blocked = false;
		wd.x = nx;
		wd.y = ny;
		wd.heading = nh;
		yaw_dps = dpsi / DEG / STEP_S;
		wd.now.travel_m += fabs(ds);
	}
	wd.now.touching = wd.blocked;
	placed = apply_placements(t);
	observe_pose(t, placed ? NAN : clear);
	sense(yaw_dps, placed || wd.steps % RANGE_EVERY_STEPS == 0);
	if (++wd.steps % (EV3SIM_WORLD_TRAIL_NS / EV3SIM_WORLD_STEP_NS) == 0)
		trail_add(t);
	if (wd.run.on_step)
		wd.run.on_step(&wd.now, placed, wd.run.ctx);
	wd.step_ev = hs_event_at(t + EV3SIM_WORLD_STEP_NS, world_step, NULL);
}

/* ---- checks and life cycle ---- */

const char *ev3sim_world_check(const struct ev3sim_world *w)
{
	const struct ev3sim_world_robot *r = &w->robot;
	const struct ev3sim_world_mat *m = &w->mat;
	bool port_used[4] = { false };

	if (!(m->width > 0 && m->height > 0 && m->width <= 100 && m->height <= 100))
		return "the mat's size must be 0 < size <= 100 m";
	if (m->kind == EV3SIM_MAT_IMAGE && (m->pixels == NULL || m->px_w == 0 || m->px_h == 0))
		return "the mat's image has no pixels";
	if (m->kind == EV3SIM_MAT_STADIUM && !(m->radius > 0 && m->straight >= 0 && m->line_width > 0))
		return "the stadium line needs radius > 0, straight >= 0, line width > 0";
	if (!(r->wheel_radius >= 0.005 && r->wheel_radius <= 0.2))
		return "the wheel radius must be 5..200 mm";
	if (!(r->track >= 0.02 && r->track <= 1.0))
		return "the track must be 20..1000 mm";
	if (!(r->mass >= 0.1 && r->mass <= 20))
		return "the mass must be 0.1..20 kg";
	if (!(r->body_radius >= 0.01 && r->body_radius <= 1.0))
		return "the body radius must be 10..1000 mm";
	if (!(r->rolling_crr >= 0 && r->rolling_crr <= 0.5))
		return "rolling resistance must be 0..0.5";
	if (!(r->slip >= 0 && r->slip <= 0.5))
		return "slip must be 0..0.5";
	if (r->left_port >= 4 || r->right_port >= 4 || r->left_port == r->right_port)
		return "the wheel motors need two different output ports A..D";
	if (r->motor != EV3SIM_OUT_LARGE && r->motor != EV3SIM_OUT_MEDIUM)
		return "the wheel motors must be large or medium";
	if (r->nmounts > EV3SIM_WORLD_MAX_MOUNTS)
		return "at most 4 sensors";
	for (unsigned k = 0; k < r->nmounts; k++) {
		const struct ev3sim_world_mount *mt = &r->mounts[k];

		if (mt->port >= 4)
			return "a sensor's port must be 1..4";
		if (port_used[mt->port])
			return "two sensors on one port";
		port_used[mt->port] = true;
		if (mt->device != EV3SIM_IN_TOUCH && mt->device != EV3SIM_IN_GYRO && mt->device != EV3SIM_IN_COLOR &&
		    mt->device != EV3SIM_IN_ULTRASONIC && mt->device != EV3SIM_IN_IR)
			return "a sensor must be touch, gyro, color, ultrasonic or ir";
		if (!(fabs(mt->x) <= 1.0 && fabs(mt->y) <= 1.0 && mt->height >= 0 && mt->height <= 1.0))
			return "a sensor must sit within 1 m of the axle, 0..1000 mm high";
		if (mt->device == EV3SIM_IN_COLOR && !(mt->footprint >= 0.001 && mt->footprint <= 0.1 &&
						      mt->height >= 0.001))
			return "a colour sensor needs a footprint of 1..100 mm and a height of at least 1 mm";
		if ((mt->device == EV3SIM_IN_ULTRASONIC || mt->device == EV3SIM_IN_IR) &&
		    !(mt->beam >= 0 && mt->beam <= PI))
			return "a beam must be 0..180 degrees";
	}
	if (w->nobstacles > EV3SIM_WORLD_MAX_OBSTACLES)
		return "at most 256 walls and obstacles";
	for (unsigned i = 0; i < w->nobstacles; i++) {
		const struct ev3sim_obstacle *o = &w->obstacles[i];

		if (!isfinite(o->x0) || !isfinite(o->y0) || !isfinite(o->x1) || !isfinite(o->y1) || !(o->height > 0))
			return "an obstacle needs finite coordinates and a height > 0";
		if (o->kind == EV3SIM_OBST_CIRCLE && !(o->r > 0))
			return "a circle needs a radius > 0";
	}
	if (!isfinite(w->start_x) || !isfinite(w->start_y) || !isfinite(w->start_heading))
		return "the start pose must be finite";
	for (unsigned i = 0; i < w->nobstacles; i++)
		if (ev3sim_obstacle_distance(&w->obstacles[i], w->start_x, w->start_y) < r->body_radius)
			return "the robot starts inside an obstacle (its body radius reaches one)";
	if (w->has_goal && !(w->goal_r > 0))
		return "the goal needs a radius > 0";
	return NULL;
}

ER ev3sim_world_start(const struct ev3sim_world_run *run)
{
	const struct ev3sim_world *w = run ? run->world : NULL;

	if (w == NULL || ev3sim_world_check(w) != NULL || run->nplacements > EV3SIM_WORLD_MAX_PLACEMENTS ||
	    (run->nplacements > 0 && run->placements == NULL))
		return E_PAR;
	for (unsigned i = 0; i < run->nplacements; i++)
		if (!(fabs(run->placements[i].left_m) <= 2.0))
			return E_PAR;
	ev3sim_world_stop();
	free(wd.trail);
	memset(&wd, 0, sizeof(wd));
	wd.w = *w;
	wd.run = *run;
	wd.run.world = &wd.w;
	/* by time, placements at one time in their given order (insertion sort) */
	for (unsigned i = 0; i < run->nplacements; i++) {
		unsigned j = i;

		while (j > 0 && wd.placements[j - 1].t_ns > run->placements[i].t_ns) {
			wd.placements[j] = wd.placements[j - 1];
			j--;
		}
		wd.placements[j] = run->placements[i];
	}
	wd.nplacements = run->nplacements;
	wd.run.placements = NULL;   /* the caller's array need not outlive the call */
	wd.motor[0] = ev3_output_motor(w->robot.left_port);
	wd.motor[1] = ev3_output_motor(w->robot.right_port);
	for (int i = 0; i < 2; i++) {
		if (wd.motor[i] == NULL)
			return E_OBJ;
		wd.angle_deg[i] = hs_motor_angle_deg(wd.motor[i]);
	}
	if (w->robot.slip > 0)
		hs_rng_stream(&wd.slip_rng, "world.slip");
	wd.x = w->start_x;
	wd.y = w->start_y;
	wd.heading = w->start_heading;
	for (unsigned k = 0; k < w->robot.nmounts; k++)
		if (run->in[w->robot.mounts[k].port] == w->robot.mounts[k].device)
			wd.now.port_device[w->robot.mounts[k].port] = w->robot.mounts[k].device;
	wd.now.min_clearance_m = 1e30;
	wd.now.clearance_m = 1e30;
	observe_pose(hs_now(), NAN);
	sense(0.0, true);
	trail_add(hs_now());
	wd.running = wd.active = true;
	wd.step_ev = hs_event_at(hs_now(), world_step, NULL);
	return E_OK;
}

void ev3sim_world_stop(void)
{
	if (wd.running)
		hs_event_cancel(&wd.step_ev);
	wd.running = false;
}

bool ev3sim_world_active(void)
{
	return wd.active;
}

const struct ev3sim_world_state *ev3sim_world_now(void)
{
	return &wd.now;
}

const struct ev3sim_world *ev3sim_world_current(void)
{
	return &wd.w;
}

struct ev3sim_world *(*ev3sim_world_file_reader)(const char *path, char *err, size_t errlen);

void ev3sim_world_free(struct ev3sim_world *w)
{
	if (w == NULL)
		return;
	free((void *)w->mat.pixels);
	free(w);
}
