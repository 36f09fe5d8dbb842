/*
 * tribot.c — the driving base on the line mat (tribot.h).
 *
 * Geometry (m): wheel radius 0.028 (LEGO's 56 mm tyre), track 0.12, colour
 * sensor 0.08 in front of the axle looking down, seeing a spot of radius
 * 0.006.  Mass 0.75 kg over both wheels; rolling resistance 0.03 of the
 * weight.  The line's centre is the set of points at EV3SIM_LINE_RADIUS_M
 * from the segment (-S/2, 0)..(S/2, 0) (S = EV3SIM_LINE_STRAIGHT_M): a
 * stadium, so the distance from any point to it is |d(point, segment) - R|.
 */
#include <math.h>
#include <stddef.h>
#include "host_sim/clock.h"
#include "host_sim/devices/ev3_brick.h"
#include "host_sim/devices/ev3_motor.h"
#include "host_sim/devices/uart_sensor.h"
#include "ev3sim/tribot.h"

#define PI 3.14159265358979323846
#define DEG (PI / 180.0)

#define WHEEL_RADIUS_M   0.028
#define TRACK_M          0.12
#define SENSOR_AHEAD_M   0.08
#define SPOT_RADIUS_M    0.006
#define MASS_KG          0.75
#define ROLLING_CRR      0.03
#define GRAVITY          9.81
/* Below this shaft speed (deg/s) rolling resistance fades out linearly. */
#define ROLL_SMOOTH_DPS  10.0
/* Where the robot starts: the lower straight, x = START_X_M, heading +x. */
#define START_X_M        (-0.30)

#define HALF_S   (EV3SIM_LINE_STRAIGHT_M / 2.0)
#define LINE_R   EV3SIM_LINE_RADIUS_M
#define PERIMETER (2.0 * EV3SIM_LINE_STRAIGHT_M + 2.0 * PI * LINE_R)

static struct tribot {
	bool running;
	struct ev3sim_tribot_cfg cfg;
	struct hs_motor *motor[2];
	hs_event_t step_ev;
	double angle_deg[2];            /* shaft angles at the last step */
	double x, y, heading;           /* m, m, rad */
	double last_s;                  /* arc position of the spot at the last step */
	struct ev3sim_placement placements[EV3SIM_MAX_PLACEMENTS];  /* by time */
	unsigned nplacements, next_placement;
	struct ev3sim_tribot_sample now;
} tb;

/* Distance from (x, y) to the line's centre, positive outside the stadium. */
static double line_error(double x, double y)
{
	double cx = x < -HALF_S ? -HALF_S : x > HALF_S ? HALF_S : x;

	return hypot(x - cx, y) - LINE_R;
}

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
	double inside = EV3SIM_LINE_WIDTH_M / 2.0 + SPOT_RADIUS_M - fabs(error_m);
	double c = inside / (2.0 * SPOT_RADIUS_M);

	return c < 0.0 ? 0.0 : c > 1.0 ? 1.0 : c;
}

/* The colour sensor sees the mat under its spot. */
static unsigned set_color_scene(double cover)
{
	struct uart_sensor *s = tb.cfg.color_port >= 0 ? ev3_input_uart_sensor((unsigned)tb.cfg.color_port)
						       : NULL;
	struct uart_sensor_scene scene;
	double white = 1.0 - cover;
	unsigned reflect = (unsigned)lround(EV3SIM_MAT_BLACK_PCT * cover + EV3SIM_MAT_WHITE_PCT * white);

	if (s == NULL)
		return reflect;     /* none, or unplugged by a fault */
	scene = *uart_sensor_scene(s);
	scene.reflect_pct = (uint8_t)reflect;
	scene.color = cover > 0.5 ? 1 : 6;      /* black or white */
	for (int i = 0; i < 3; i++)
		scene.rgb[i] = (uint16_t)lround(30.0 * cover + 420.0 * white);
	uart_sensor_set_scene(s, &scene);
	return reflect;
}

/* Rolling resistance on one wheel at shaft speed dps, N m. */
static double rolling_load(double dps)
{
	double full = ROLLING_CRR * MASS_KG / 2.0 * GRAVITY * WHEEL_RADIUS_M;
	double s = dps / ROLL_SMOOTH_DPS;

	return full * (s > 1.0 ? 1.0 : s < -1.0 ? -1.0 : s);
}

/* The hand's placements due by t: the robot moves sideways, and its
 * progress along the line starts again from where it is put down (the hand
 * carried it, it did not drive there). */
static void apply_placements(uint64_t t)
{
	while (tb.next_placement < tb.nplacements && tb.placements[tb.next_placement].t_ns <= t) {
		double left_m = tb.placements[tb.next_placement++].left_mm / 1000.0;

		tb.x -= left_m * sin(tb.heading);
		tb.y += left_m * cos(tb.heading);
		tb.last_s = arc_position(tb.x + SENSOR_AHEAD_M * cos(tb.heading),
					 tb.y + SENSOR_AHEAD_M * sin(tb.heading));
	}
}

/* Event: one physics step. */
static void tribot_step(void *arg)
{
	uint64_t t = hs_now();
	double d[2], ds, dpsi, sx, sy, err, s, dprog;

	(void)arg;
	tb.step_ev = 0;
	for (int i = 0; i < 2; i++) {
		double a = hs_motor_angle_deg(tb.motor[i]);

		d[i] = (a - tb.angle_deg[i]) * DEG * WHEEL_RADIUS_M;
		tb.angle_deg[i] = a;
		hs_motor_set_load(tb.motor[i], rolling_load(hs_motor_speed_dps(tb.motor[i])),
				   MASS_KG / 2.0 * WHEEL_RADIUS_M * WHEEL_RADIUS_M);
	}
	ds = (d[0] + d[1]) / 2.0;
	dpsi = (d[1] - d[0]) / TRACK_M;
	tb.x += ds * cos(tb.heading + dpsi / 2.0);
	tb.y += ds * sin(tb.heading + dpsi / 2.0);
	tb.heading += dpsi;
	apply_placements(t);
	sx = tb.x + SENSOR_AHEAD_M * cos(tb.heading);
	sy = tb.y + SENSOR_AHEAD_M * sin(tb.heading);
	err = line_error(sx, sy);
	s = arc_position(sx, sy);
	dprog = s - tb.last_s;
	if (dprog > PERIMETER / 2.0)
		dprog -= PERIMETER;
	else if (dprog < -PERIMETER / 2.0)
		dprog += PERIMETER;
	tb.last_s = s;

	tb.now.t_ns = t;
	tb.now.x_m = tb.x;
	tb.now.y_m = tb.y;
	tb.now.heading_deg = tb.heading / DEG;
	tb.now.sensor_x_m = sx;
	tb.now.sensor_y_m = sy;
	tb.now.line_error_m = err;
	tb.now.line_cover = cover_of(err);
	tb.now.progress_m += dprog;
	tb.now.travel_m += fabs(ds);
	tb.now.reflect_pct = set_color_scene(tb.now.line_cover);
	tb.step_ev = hs_event_at(t + EV3SIM_TRIBOT_STEP_NS, tribot_step, NULL);
}

ER ev3sim_tribot_start(const struct ev3sim_tribot_cfg *cfg)
{
	unsigned ports[2];

	if (cfg == NULL || cfg->left_port >= 4 || cfg->right_port >= 4 ||
	    cfg->left_port == cfg->right_port || cfg->color_port >= 4 ||
	    cfg->nplacements > EV3SIM_MAX_PLACEMENTS || (cfg->nplacements > 0 && cfg->placements == NULL))
		return E_PAR;
	for (unsigned i = 0; i < cfg->nplacements; i++)
		if (!(fabs(cfg->placements[i].left_mm) <= EV3SIM_MAX_PLACE_MM))
			return E_PAR;
	ev3sim_tribot_stop();
	tb = (struct tribot){ .cfg = *cfg };
	/* by time, placements at one time in their given order (insertion sort) */
	for (unsigned i = 0; i < cfg->nplacements; i++) {
		unsigned j = i;

		while (j > 0 && tb.placements[j - 1].t_ns > cfg->placements[i].t_ns) {
			tb.placements[j] = tb.placements[j - 1];
			j--;
		}
		tb.placements[j] = cfg->placements[i];
	}
	tb.nplacements = cfg->nplacements;
	tb.cfg.placements = NULL;       /* the caller's array need not outlive the call */
	ports[0] = cfg->left_port;
	ports[1] = cfg->right_port;
	for (int i = 0; i < 2; i++) {
		tb.motor[i] = ev3_output_motor(ports[i]);
		if (tb.motor[i] == NULL)
			return E_OBJ;
		tb.angle_deg[i] = hs_motor_angle_deg(tb.motor[i]);
	}
	if (cfg->color_port >= 0 && ev3_input_uart_sensor((unsigned)cfg->color_port) == NULL)
		return E_OBJ;
	tb.x = START_X_M;
	tb.y = -LINE_R;
	tb.heading = 0.0;
	tb.last_s = arc_position(tb.x + SENSOR_AHEAD_M, tb.y);
	tb.now.line_error_m = line_error(tb.x + SENSOR_AHEAD_M, tb.y);
	tb.now.line_cover = cover_of(tb.now.line_error_m);
	tb.now.reflect_pct = set_color_scene(tb.now.line_cover);
	tb.running = true;
	tb.step_ev = hs_event_at(hs_now(), tribot_step, NULL);
	return E_OK;
}

void ev3sim_tribot_stop(void)
{
	if (tb.running)
		hs_event_cancel(&tb.step_ev);
	tb.running = false;
}

const struct ev3sim_tribot_sample *ev3sim_tribot_now(void)
{
	return &tb.now;
}
