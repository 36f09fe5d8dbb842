/*
 * motor.c — EV3 large/medium motor: DC motor physics at the output
 * shaft, H-bridge, quadrature tacho edges computed analytically, pin-5 ID.
 *
 * Parameters (docs/host-sim-devices.md has the discussion):
 *   no-load speed: ev3dev's maximum speeds, 1050 deg/s large and 1560 deg/s
 *     medium (ev3dev's ev3_motor_defs.c), taken as the no-load speed at 9 V;
 *   stall torque: 0.40 N m large, 0.12 N m medium (Philo Hurbain's motor
 *     comparison, philohome.com, measured at 9 V; rounded);
 *   mechanical time constants 40 ms / 20 ms and dry friction 4 % / 12 % of
 *     stall torque: estimates, consistent with LEGO's minimum duty offsets
 *     (0.95|p| + 500 large, 0.8|p| + 2000 medium, LEGO's d_pwm.c);
 *   pin 5 ID: pybricks' 10-bit readings (device.c): large 0.16 / 4.48 V,
 *     medium 0.36 / 4.21 V with the encoder low / high.
 */
#include <math.h>
#include <stdlib.h>
#include "host_sim/clock.h"
#include "host_sim/gpio.h"
#include "host_sim/rng.h"
#include "host_sim/trace.h"
#include "host_sim/devices/ev3_brick.h"
#include "host_sim/devices/ev3_motor.h"
#include "host_sim/devices/ev3_ports.h"
#include "host_sim/devices/pwm.h"

#define STEP_NS 1000000ULL          /* physics step: 1 ms */
#define STEADY_STEP_NS 10000000ULL  /* step once the speed has settled: 10 ms */
#define STEADY_RAD_S 1e-4           /* "settled": speed changes less than this per 1 ms step */
#define GLITCH_NS 2000ULL           /* width of an encoder glitch */
#define RAD_PER_DEG (3.14159265358979323846 / 180.0)

static const struct hs_motor_params motor_params[] = {
	[HS_MOTOR_LARGE] = { "large", 1050.0, 0.40, 9.0, 0.040, 0.04, 1.8, 160, 4480, 3000 },
	[HS_MOTOR_MEDIUM] = { "medium", 1560.0, 0.12, 9.0, 0.020, 0.12, 0.8, 360, 4210, 1800 },
};

/* Built-in parameters. */
const struct hs_motor_params *hs_motor_params_of(enum hs_motor_kind kind)
{
	return (unsigned)kind <= HS_MOTOR_MEDIUM ? &motor_params[kind] : NULL;
}

/* Where one phase of a PWM period sends the bridge: the hbridge_drive field
 * its fraction adds to, or none (coasting). */
enum bridge_way { WAY_FWD, WAY_REV, WAY_BRAKE, WAY_COAST };

/* The ways of the two phases of a PWM period (signal low, then high) for a
 * pair of bridge inputs: they change with the inputs only, not with the duty. */
struct bridge_split {
	uint8_t way[2];
};

/* The bridge's split for inputs in0 and in1. */
static struct bridge_split bridge_split_of(enum hbridge_input in0, enum hbridge_input in1)
{
	struct bridge_split sp;

	for (int ph = 0; ph < 2; ph++) {
		bool a = in0 == HBRIDGE_HIGH || (in0 == HBRIDGE_PWM && ph == 1);
		bool b = in1 == HBRIDGE_HIGH || (in1 == HBRIDGE_PWM && ph == 1);

		sp.way[ph] = a && b ? WAY_BRAKE : a ? WAY_FWD : b ? WAY_REV : WAY_COAST;
	}
	return sp;
}

/* The drive of split sp with the PWM signal low for pwm_low of each period: each
 * field the sum, from 0, of its phases' fractions in phase order. */
static inline struct hbridge_drive bridge_split_drive(struct bridge_split sp, double pwm_low)
{
	double lo = pwm_low < 0 ? 0 : pwm_low > 1 ? 1 : pwm_low;
	double sum[4] = { 0, 0, 0, 0 };

	sum[sp.way[0]] += lo;
	sum[sp.way[1]] += 1.0 - lo;
	return (struct hbridge_drive){ .fwd = sum[WAY_FWD], .rev = sum[WAY_REV], .brake = sum[WAY_BRAKE] };
}

/* Time split of the bridge for its two inputs. */
struct hbridge_drive hbridge_resolve(enum hbridge_input in0, enum hbridge_input in1, double pwm_low)
{
	return bridge_split_drive(bridge_split_of(in0, in1), pwm_low);
}

/* Derived constants: the ideal no-load speed is chosen so that, with the
 * friction included, the unloaded motor at nominal voltage reaches the
 * published speed. */
void dc_motor_model_init(struct dc_motor_model *m, const struct hs_motor_params *p)
{
	double w_pub = p->no_load_dps * RAD_PER_DEG;

	m->p = p;
	m->coulomb = p->coulomb_frac * p->stall_nm;
	m->viscous = 0.01 * p->stall_nm / w_pub;
	m->k_back = (p->stall_nm - m->coulomb - m->viscous * w_pub) / w_pub;
	m->k_volt = p->stall_nm / p->nominal_v;
	m->inertia = p->mech_time_s * p->stall_nm / w_pub;
}

/* exp(x) of the last decay exponent a motor's physics step used: the step event
 * and a load re-applied at the same instant repeat it while the drive, the inertia
 * and the step length stay, and exp is most of a step's cost. */
struct exp_memo {
	bool valid;
	double x, e;
};

/* exp(x), from memo if it holds x (memo may be NULL). */
static double exp_memoized(struct exp_memo *memo, double x)
{
	if (memo == NULL)
		return exp(x);
	if (!memo->valid || memo->x != x) {
		memo->valid = true;
		memo->x = x;
		memo->e = exp(x);
	}
	return memo->e;
}

/* dc_motor_advance with the step's exp taken from memo (NULL: computed). */
static void motor_advance(const struct dc_motor_model *m, struct dc_motor_state *st, double dt,
			  const struct hbridge_drive *drive, double vbat, double load_nm,
			  double extra_inertia, struct exp_memo *memo)
{
	double J = m->inertia + (extra_inertia > 0 ? extra_inertia : 0);
	double k = m->k_back * (drive->fwd + drive->rev + drive->brake) + m->viscous;
	double td = m->k_volt * (drive->fwd - drive->rev) * vbat - load_nm;
	double w0 = st->omega, s, tn, wss, T, e, w1;

	if (dt <= 0)
		return;
	if (w0 == 0.0) {
		if (fabs(td) <= m->coulomb)
			return;     /* static friction holds */
		s = td > 0 ? 1.0 : -1.0;
	} else {
		s = w0 > 0 ? 1.0 : -1.0;
	}
	tn = td - s * m->coulomb;
	wss = tn / k;
	T = J / k;
	e = exp_memoized(memo, -dt / T);
	w1 = wss + (w0 - wss) * e;
	if (w1 * s < 0) {
		/* speed crosses zero inside the step: friction stops the shaft there */
		double tc = -T * log(-wss / (w0 - wss));

		st->theta += wss * tc + (w0 - wss) * T * (1.0 - exp(-tc / T));
		st->omega = 0.0;
		return;
	}
	st->theta += wss * dt + (w0 - wss) * T * (1.0 - e);
	st->omega = w1;
}

/* Exact step of J w' = Td - k w - c sign(w) with dry friction stopping at 0. */
void dc_motor_advance(const struct dc_motor_model *m, struct dc_motor_state *st, double dt,
		      struct hbridge_drive drive, double vbat, double load_nm, double extra_inertia)
{
	motor_advance(m, st, dt, &drive, vbat, load_nm, extra_inertia, NULL);
}

/* ---- the attached motor ---- */

/* The speed omega_now last computed inside a segment, and for which instant. */
struct omega_memo {
	bool valid;
	uint64_t t, seg_t0;
	double vbat, omega;
};

struct hs_motor {
	unsigned port;
	enum hs_motor_kind kind;
	struct dc_motor_model model;
	const struct ev3_output_pins *pins;
	enum hs_pwm_output pwm;
	uint64_t seg_t0, seg_t1;    /* current physics segment */
	double seg_omega0, seg_omega1;  /* exact speed at its start and end (rad/s) */
	double seg_theta0, seg_rate;/* linear angle within it (rad, rad/s) */
	struct hbridge_drive drive;
	double load_nm, extra_inertia;
	bool stalled, stuck;
	double noise_rate;
	uint64_t glitches;
	int64_t shown;              /* quadrature half-count index the pins show */
	bool int_level, dir_level;
	hs_event_t step_ev, edge_ev, glitch_ev, glitch_end_ev;
	int watch0, watch1;
	struct hs_rng rng;
	struct hs_signal *sig_angle, *sig_speed;
	struct exp_memo step_exp;   /* of the segments' physics steps */
	struct omega_memo mid_memo; /* of omega_now inside a segment */
	double seg_vbat;            /* battery voltage the segment is solved with */
	bool seg_unsolved;          /* begun by step_due, left to the load's owner */
	uint64_t owner_next;        /* when the load's owner re-applies it (0: no promise) */
	struct bridge_split split;  /* of the bridge GPIOs, as hs_motor_inputs_changed last read them */
};

static struct hs_motor *port_motor[EV3_OUTPUT_PORTS];

static void motor_schedule_edge(struct hs_motor *m);

/* Angle (rad) on the current linear segment at time t. */
static double seg_theta(const struct hs_motor *m, uint64_t t)
{
	return m->seg_theta0 + m->seg_rate * (double)(t - m->seg_t0) * 1e-9;
}

/* Quadrature (INT, DIR) for half-count index h: 00, 10, 11, 01 going forward
 * (LEGO's d_pwm.c: forward when INT equals the inverted DIR just after an INT edge). */
static void quad_levels(int64_t h, bool *int_lvl, bool *dir_lvl)
{
	unsigned q = (unsigned)(h & 3);

	*int_lvl = q == 1 || q == 2;
	*dir_lvl = q == 2 || q == 3;
}

/* floor(x) as an integer, for |x| < 2^63, without libm's call (a step sets it, an edge reads it). */
static int64_t floor_i64(double x)
{
	int64_t i = (int64_t)x;

	return (double)i > x ? i - 1 : i;
}

/* ceil(x) as an integer, for 0 <= x < 2^63, without libm's call; the signed
 * conversions are single instructions (the unsigned ones branch around them)
 * and give the same values in that range. */
static uint64_t ceil_u63(double x)
{
	int64_t c = (int64_t)x;

	return (uint64_t)((double)c < x ? c + 1 : c);
}

/* Half-count index of an angle in rad: 720 half-counts per revolution. */
static int64_t index_of(double theta)
{
	return floor_i64(theta / RAD_PER_DEG * 2.0);
}

/* Shows quadrature index m->shown + dir (dir +1 or -1) on the INT and DIR
 * pins, which show m->shown (int_level and dir_level follow it; a glitch
 * drives INT without changing them).  The quadrature is a Gray code: one pin
 * changes per step, INT on a step from an even index up or to one down (00-10
 * and 11-01 going forward), DIR on the others. */
static void show_step(struct hs_motor *m, int64_t dir)
{
	int64_t lower = dir > 0 ? m->shown : m->shown - 1;

	m->shown += dir;
	if ((lower & 1) == 0) {
		m->int_level = !m->int_level;
		hs_gpio_drive(m->pins->tacho_int, m->int_level ? HS_EXT_HIGH : HS_EXT_LOW);
	} else {
		m->dir_level = !m->dir_level;
		hs_gpio_drive(m->pins->tacho_dir, m->dir_level ? HS_EXT_HIGH : HS_EXT_LOW);
	}
}

/* Brings the pins to angle theta (emitting any missed edges in order). */
static void catch_up(struct hs_motor *m, double theta)
{
	int64_t target = index_of(theta);

	if (m->stuck)
		return;
	while (m->shown != target)
		show_step(m, target > m->shown ? 1 : -1);
}

/* Event: the next tacho edge. */
static void edge_due(void *arg)
{
	struct hs_motor *m = arg;

	m->edge_ev = 0;
	if (!m->stuck)
		show_step(m, m->seg_rate > 0 ? 1 : -1);
	motor_schedule_edge(m);
}

/* Schedules the next edge inside the current segment, if any. */
static void motor_schedule_edge(struct hs_motor *m)
{
	double boundary_deg, dt;
	uint64_t t;

	hs_event_cancel(&m->edge_ev);
	if (m->stuck || m->seg_rate == 0.0)
		return;
	boundary_deg = (double)(m->seg_rate > 0 ? m->shown + 1 : m->shown) * 0.5;
	dt = (boundary_deg * RAD_PER_DEG - m->seg_theta0) / m->seg_rate;
	if (dt < 0)
		dt = 0;
	/* Compare in double first: at a near-zero rate dt is astronomically large,
	 * and converting it to uint64_t ns would overflow into an edge "now". */
	if (dt * 1e9 > (double)(int64_t)(m->seg_t1 - m->seg_t0))   /* a segment lasts far less than 2^63 ns */
		return;
	t = m->seg_t0 + ceil_u63(dt * 1e9);
	if (t > m->seg_t1)
		return;
	m->edge_ev = hs_event_at(t, edge_due, m);   /* an edge already passed is due now */
}

/* Battery voltage in volts. */
static double battery_v(void)
{
	return ev3_battery_mv() / 1000.0;
}

static void motor_new_segment(struct hs_motor *m);
static void segment_solve_late(struct hs_motor *m);

static void segment_leave_to_owner(struct hs_motor *m);

/* Event: physics step boundary.  When the load's owner promised to re-apply it
 * at this instant, only the segment's start is taken here (pins, trace): the
 * owner's call, due next at this instant, solves and schedules the segment. */
static void step_due(void *arg)
{
	struct hs_motor *m = arg;

	m->step_ev = 0;
	/* the step falls due at the segment's end (a new segment cancels it) */
	if (m->seg_t1 == m->owner_next)
		segment_leave_to_owner(m);
	else
		motor_new_segment(m);
}

/* omega_now strictly inside a segment: the segment's solution re-run from its
 * start up to now (remembered for a second look at the same instant: the robot
 * reads the speed, then sets the load).  Out of line: most looks fall on a
 * segment's start or end. */
static __attribute__((noinline)) double omega_between(struct hs_motor *m, uint64_t now)
{
	struct dc_motor_state st = { m->seg_omega0, 0 };
	double v = battery_v();

	/* a segment starts at now whenever its inputs change, so within one the
	 * solution depends on the time and the battery only */
	if (m->mid_memo.valid && m->mid_memo.t == now && m->mid_memo.seg_t0 == m->seg_t0 &&
	    m->mid_memo.vbat == v)
		return m->mid_memo.omega;
	dc_motor_advance(&m->model, &st, (double)(now - m->seg_t0) * 1e-9, m->drive, v,
			 m->load_nm, m->extra_inertia);
	m->mid_memo = (struct omega_memo){ true, now, m->seg_t0, v, st.omega };
	return st.omega;
}

/* Exact speed now: the end speed at a step boundary, the start speed at its
 * start, else omega_between. */
static inline double omega_now(struct hs_motor *m)
{
	uint64_t now = hs_now();

	if (m->seg_unsolved && now != m->seg_t0)
		segment_solve_late(m);
	if (now >= m->seg_t1 || m->stalled)
		return m->stalled ? 0.0 : m->seg_omega1;
	if (now == m->seg_t0)
		return m->seg_omega0;
	return omega_between(m, now);
}

/* Starts a segment at now from the angle shown by the old one and speed
 * seg_omega1 (set by the caller to the speed now): the pins caught up, the
 * start published on the trace; its end is left to segment_solve. */
static inline __attribute__((always_inline)) void segment_begin(struct hs_motor *m, uint64_t now)
{
	double theta = seg_theta(m, now);

	m->seg_vbat = battery_v();
	catch_up(m, theta);
	m->seg_theta0 = theta;
	m->seg_omega0 = m->stalled ? 0.0 : m->seg_omega1;
	m->seg_t0 = now;
	m->seg_t1 = now + STEP_NS;
	if (m->sig_angle)
		hs_trace_set_real_pair(m->sig_angle, m->seg_theta0 / RAD_PER_DEG,
				       m->sig_speed, m->seg_omega0 / RAD_PER_DEG);
}

/* The begun segment's physics step: its end speed, length and linear rate. */
static inline __attribute__((always_inline)) void segment_solve(struct hs_motor *m)
{
	struct dc_motor_state st = { .omega = m->seg_omega0, .theta = m->seg_theta0 };

	m->seg_unsolved = false;
	if (!m->stalled) {
		motor_advance(&m->model, &st, STEP_NS * 1e-9, &m->drive, m->seg_vbat, m->load_nm,
			      m->extra_inertia, &m->step_exp);
		if (fabs(st.omega - m->seg_omega0) < STEADY_RAD_S && st.omega != 0.0) {
			/* settled: a longer step loses nothing (inputs changes still cut it) */
			st.theta = m->seg_theta0;
			st.omega = m->seg_omega0;
			dc_motor_advance(&m->model, &st, STEADY_STEP_NS * 1e-9, m->drive, m->seg_vbat,
					 m->load_nm, m->extra_inertia);
			m->seg_t1 = m->seg_t0 + STEADY_STEP_NS;
		}
	}
	m->seg_rate = (st.theta - m->seg_theta0) / ((double)(m->seg_t1 - m->seg_t0) * 1e-9);
	m->seg_omega1 = st.omega;
}

/* Whether the load's owner promised its next call inside the current segment,
 * before its end: that call cuts the segment and schedules the next step. */
static inline bool owner_cuts_segment(const struct hs_motor *m)
{
	return m->owner_next > m->seg_t0 && m->owner_next < m->seg_t1;
}

/* Queues the solved segment's next tacho edge and its end.  The end is not
 * queued when the owner's call cuts the segment first (an input change between
 * the owner's calls, or a settled segment's long step): the event would only
 * be cancelled again. */
static inline __attribute__((always_inline)) void segment_schedule(struct hs_motor *m)
{
	motor_schedule_edge(m);
	hs_event_cancel(&m->step_ev);
	/* at rest and held there (friction, stall or no drive): sleep until an input changes */
	if (m->seg_rate == 0.0 && m->seg_omega1 == 0.0)
		return;
	if (owner_cuts_segment(m))
		return;
	m->step_ev = hs_event_at(m->seg_t1, step_due, m);
}

/* step_due at the instant the load's owner re-applies it: the segment is begun,
 * its solving and scheduling left to the owner's call (or a look before it). */
static __attribute__((noinline)) void segment_leave_to_owner(struct hs_motor *m)
{
	segment_begin(m, m->seg_t1);
	hs_event_cancel(&m->edge_ev);
	m->seg_unsolved = true;
}

/* segment_solve out of line, for the rare look at a segment left to the owner. */
static __attribute__((noinline, cold)) void segment_solve_late(struct hs_motor *m)
{
	segment_solve(m);
}

/* Solves a segment left to the load's owner, for a look at it before the owner's call. */
static inline void segment_settle(struct hs_motor *m)
{
	if (m->seg_unsolved)
		segment_solve_late(m);
}

/* Starts, solves and schedules a segment at now (see segment_begin). */
static void motor_new_segment(struct hs_motor *m)
{
	segment_begin(m, hs_now());
	segment_solve(m);
	segment_schedule(m);
}

/* The bridge input of one GPIO. */
static enum hbridge_input bridge_input(unsigned pin)
{
	bool level;

	if (!hs_gpio_soc_output(pin, &level))
		return HBRIDGE_PWM;
	return level ? HBRIDGE_HIGH : HBRIDGE_LOW;
}

/* Drive d from now on: the segment finished up to now and restarted with it,
 * unless it is the drive in effect. */
static void drive_apply(struct hs_motor *m, struct hbridge_drive d)
{
	if (d.fwd == m->drive.fwd && d.rev == m->drive.rev && d.brake == m->drive.brake)
		return;
	m->seg_omega1 = omega_now(m);
	m->drive = d;
	motor_new_segment(m);
}

/* Inputs changed: the bridge GPIOs read again (their watch calls this on every
 * change of their direction or output bit), the drive applied. */
void hs_motor_inputs_changed(struct hs_motor *m)
{
	m->split = bridge_split_of(bridge_input(m->pins->dir0), bridge_input(m->pins->dir1));
	drive_apply(m, bridge_split_drive(m->split, hs_pwm_low_fraction(m->pwm)));
}

/* Watcher: a bridge GPIO changed. */
static void bridge_pin_changed(void *ctx, unsigned pin, const struct hs_pin_state *st)
{
	(void)pin;
	(void)st;
	hs_motor_inputs_changed(ctx);
}

/* ---- glitches (noisy encoder fault) ---- */

static void glitch_end(void *arg)
{
	struct hs_motor *m = arg;

	m->glitch_end_ev = 0;
	hs_gpio_drive(m->pins->tacho_int, m->int_level ? HS_EXT_HIGH : HS_EXT_LOW);
}

static void glitch_schedule(struct hs_motor *m);

/* Event: an encoder glitch starts (a 2 us pulse on INT). */
static void glitch_due(void *arg)
{
	struct hs_motor *m = arg;

	m->glitch_ev = 0;
	if (!m->glitch_end_ev) {
		m->glitches++;
		hs_gpio_drive(m->pins->tacho_int, m->int_level ? HS_EXT_LOW : HS_EXT_HIGH);
		m->glitch_end_ev = hs_event_at(hs_now() + GLITCH_NS, glitch_end, m);
	}
	glitch_schedule(m);
}

/* Draws the time of the next glitch (Poisson). */
static void glitch_schedule(struct hs_motor *m)
{
	double u;

	hs_event_cancel(&m->glitch_ev);
	if (m->noise_rate <= 0)
		return;
	u = hs_rng_unit(&m->rng);
	m->glitch_ev = hs_event_at(hs_now() + GLITCH_NS +
				   (uint64_t)(-log(1.0 - u) / m->noise_rate * 1e9), glitch_due, m);
}

/* ---- public ---- */

/* The motor's PWM peer (hs_pwm_connect): the duty of its H-bridge changed. */
static void pwm_changed(void *ctx, enum hs_pwm_output out)
{
	struct hs_motor *m = ctx;

	/* only the duty moved: the bridge GPIOs are as last read */
	drive_apply(m, bridge_split_drive(m->split, hs_pwm_low_fraction(out)));
}

/* Creates the motor on a port and starts driving its tacho pins. */
struct hs_motor *hs_motor_create(unsigned port, enum hs_motor_kind kind,
				   const struct hs_motor_options *opt)
{
	struct hs_motor *m;
	char scope[16] = "motorA";

	if (port >= EV3_OUTPUT_PORTS || !hs_motor_params_of(kind) || port_motor[port])
		return NULL;
	m = calloc(1, sizeof(*m));
	if (!m)
		return NULL;
	m->port = port;
	m->kind = kind;
	m->pins = &ev3_output_pins[port];
	m->pwm = ev3_output_pwm[port];
	dc_motor_model_init(&m->model, hs_motor_params_of(kind));
	if (opt) {
		m->load_nm = opt->load_nm;
		m->extra_inertia = opt->extra_inertia;
		m->seg_theta0 = opt->start_deg * RAD_PER_DEG;
	}
	scope[5] = (char)('A' + port);
	hs_rng_stream(&m->rng, scope);
	m->sig_angle = hs_trace_signal_real(scope, "angle_deg");
	m->sig_speed = hs_trace_signal_real(scope, "speed_dps");
	m->seg_t0 = m->seg_t1 = hs_now();
	m->shown = index_of(m->seg_theta0);
	quad_levels(m->shown, &m->int_level, &m->dir_level);
	hs_gpio_drive(m->pins->tacho_int, m->int_level ? HS_EXT_HIGH : HS_EXT_LOW);
	hs_gpio_drive(m->pins->tacho_dir, m->dir_level ? HS_EXT_HIGH : HS_EXT_LOW);
	m->watch0 = hs_gpio_watch(m->pins->dir0, bridge_pin_changed, m);
	m->watch1 = hs_gpio_watch(m->pins->dir1, bridge_pin_changed, m);
	hs_pwm_connect(m->pwm, &(struct hs_pwm_peer){ pwm_changed, m });
	port_motor[port] = m;
	m->drive.fwd = -1;  /* force the first evaluation */
	hs_motor_inputs_changed(m);
	return m;
}

/* Removes the motor: events cancelled, pins released. */
void hs_motor_destroy(struct hs_motor *m)
{
	if (!m)
		return;
	hs_event_cancel(&m->step_ev);
	hs_event_cancel(&m->edge_ev);
	hs_event_cancel(&m->glitch_ev);
	hs_event_cancel(&m->glitch_end_ev);
	hs_pwm_connect(m->pwm, NULL);
	hs_gpio_unwatch(m->watch0);
	hs_gpio_unwatch(m->watch1);
	hs_gpio_drive(m->pins->tacho_int, HS_EXT_FLOAT);
	hs_gpio_drive(m->pins->tacho_dir, HS_EXT_FLOAT);
	if (port_motor[m->port] == m)
		port_motor[m->port] = NULL;
	free(m);
}

/* The motor on an output port, or NULL. */
struct hs_motor *hs_motor_on_port(unsigned port)
{
	return port < EV3_OUTPUT_PORTS ? port_motor[port] : NULL;
}


/* Shaft angle now, degrees. */
double hs_motor_angle_deg(struct hs_motor *m)
{
	uint64_t now = hs_now();

	/* at an unsolved segment's start the angle is its start angle whatever the
	 * rate (which decides only the sign of a zero) */
	if (m->seg_unsolved && (now != m->seg_t0 || m->seg_theta0 == 0.0))
		segment_solve_late(m);
	return seg_theta(m, now) / RAD_PER_DEG;
}

/* Exact shaft speed now, deg/s: the speed a segment started now begins with
 * (the value its speed_dps signal would show). */
double hs_motor_speed_now_dps(struct hs_motor *m)
{
	return omega_now(m) / RAD_PER_DEG;
}

/* Shaft speed on the current step, deg/s. */
double hs_motor_speed_dps(struct hs_motor *m)
{
	segment_settle(m);
	return m->seg_rate / RAD_PER_DEG;
}

/* Counts the pins show (INT edges from 0). */
int64_t hs_motor_tacho_counts(const struct hs_motor *m)
{
	/* INT edges sit at odd half-count indices: count = round(index / 2) */
	return m->shown >= 0 ? (m->shown + 1) / 2 : -((-m->shown) / 2);
}

/* Bridge split in effect. */
struct hbridge_drive hs_motor_drive(const struct hs_motor *m)
{
	return m->drive;
}

/* Estimated motor current now, amperes. */
double hs_motor_current_a(struct hs_motor *m)
{
	const struct dc_motor_model *md = &m->model;
	double w, torque;

	segment_settle(m);
	w = m->seg_rate;
	torque = md->k_volt * (m->drive.fwd - m->drive.rev) * battery_v() -
		 md->k_back * (m->drive.fwd + m->drive.rev + m->drive.brake) * w;

	return fabs(torque) / md->p->stall_nm * md->p->stall_a;
}

/* Sets the external load from now on. */
void hs_motor_set_load(struct hs_motor *m, double load_nm, double extra_inertia)
{
	hs_motor_set_load_until(m, load_nm, extra_inertia, 0);
}

/* Sets the external load from now on and notes when the caller sets it next. */
void hs_motor_set_load_until(struct hs_motor *m, double load_nm, double extra_inertia,
			     uint64_t next_ns)
{
	m->seg_omega1 = omega_now(m);
	m->load_nm = load_nm;
	m->extra_inertia = extra_inertia;
	m->owner_next = next_ns;
	motor_new_segment(m);
}

/* Withdraws the promise of hs_motor_set_load_until: the motor steps on its own. */
void hs_motor_end_load_promise(struct hs_motor *m)
{
	bool end_unqueued = !m->seg_unsolved && m->step_ev == 0 && owner_cuts_segment(m) &&
			    !(m->seg_rate == 0.0 && m->seg_omega1 == 0.0);

	m->owner_next = 0;
	if (m->seg_unsolved) {
		segment_solve(m);
		segment_schedule(m);
	} else if (end_unqueued) {
		/* the segment's end, left to the owner's call (segment_schedule), is
		 * queued now: it runs after any event queued meanwhile for the same instant */
		m->step_ev = hs_event_at(m->seg_t1, step_due, m);
	}
}

/* Locks or frees the shaft from now on. */
void hs_motor_set_stalled(struct hs_motor *m, bool stalled)
{
	m->seg_omega1 = omega_now(m);
	m->stalled = stalled;
	motor_new_segment(m);
}

/* Freezes or releases the tacho outputs. */
void hs_motor_set_encoder_stuck(struct hs_motor *m, bool stuck)
{
	segment_settle(m);
	m->stuck = stuck;
	if (!stuck)
		catch_up(m, seg_theta(m, hs_now()));
	motor_schedule_edge(m);
}

/* Sets the glitch rate of the encoder. */
void hs_motor_set_encoder_noise(struct hs_motor *m, double glitches_per_s)
{
	m->noise_rate = glitches_per_s;
	glitch_schedule(m);
}

/* Glitches emitted so far. */
uint64_t hs_motor_glitches(const struct hs_motor *m)
{
	return m->glitches;
}

/* Pin 5 ID voltage for the encoder level and the 5w pull. */
uint16_t hs_motor_pin5_mv(const struct hs_motor *m, bool pull5w_high)
{
	const struct hs_motor_params *p = m->model.p;

	if (!m->int_level)
		return p->pin5_low_mv;
	return pull5w_high ? p->pin5_pulled_mv : p->pin5_high_mv;
}

/* Kind of the motor. */
enum hs_motor_kind hs_motor_kind_of(const struct hs_motor *m)
{
	return m->kind;
}
