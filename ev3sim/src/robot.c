/*
 * robot.c — the two-wheeled inverted pendulum coupled to host_sim's motors.
 *
 * Coordinates: psi = body pitch (positive forward), phi = motor shaft angle
 * relative to the body (the average of both motors), theta = phi + psi = the
 * wheels' rotation over the ground (no slip: the axle travels R theta).  With
 *   a = (m_w + M) R^2 + J_w,  b = M R L cos psi,  c = M L^2 + J_b,
 *   F = M g L sin psi + M R L sin psi psi'^2 - tau_roll(theta') + tau_push
 * Lagrange's equations in (phi, psi) are
 *   a phi'' + (a + b) psi''         = tau_shaft - tau_roll + h
 *   (a + b) phi'' + (a + 2b + c) psi'' = F
 * (h = M R L sin psi psi'^2; the rotor inertia and the motor's own torque
 * live in host_sim's motor model).  Eliminating psi'' gives what the shafts
 * see: an effective inertia (a c - b^2) / (a + 2b + c) and a load torque
 * (a + b) F / (a + 2b + c) + tau_roll - h, which is handed to the motors for
 * the next step; after it, the measured change of the shaft speed gives psi''.
 */
#include <math.h>
#include <stddef.h>
#include "host_sim/clock.h"
#include "host_sim/devices/ev3_brick.h"
#include "ev3sim/robot.h"

#define PI 3.14159265358979323846
#define DEG (PI / 180.0)
/* Below this wheel speed (rad/s) rolling resistance fades out linearly, so a
 * robot at rest is not pushed back and forth by a sign function. */
#define ROLL_SMOOTH_RAD_S 0.2

const struct ev3sim_robot_params ev3sim_gyro_boy = {
	.wheel_radius_m = 0.028,
	.wheel_mass_kg = 0.044,
	.wheel_inertia = 2.4e-5,
	.body_mass_kg = 0.62,
	.com_height_m = 0.085,
	.body_inertia = 1.3e-3,
	.rolling_crr = 0.02,
	.gravity = 9.81,
	.fall_deg = 45.0,
};

static struct robot {
	bool running;
	bool driven;                /* a wheel motor has had a non-zero duty */
	struct ev3sim_robot_cfg cfg;
	const struct ev3sim_robot_params *p;
	struct hs_motor *motor[2];
	hs_event_t step_ev;
	double psi, psi_dot;            /* rad, rad/s */
	double omega;                   /* shaft speed at the last step, rad/s */
	double theta_dot;
	double load, inertia;           /* what the shafts see during the current step */
	double force_psi;               /* F of the last step */
	double coupling, m_psi;         /* a + b and a + 2b + c of the last step */
	struct ev3sim_robot_sample now;
	uint64_t fell_at;
} rb;

/* Rolling resistance torque opposing the wheels' rotation over the ground. */
static double rolling_torque(const struct ev3sim_robot_params *p, double theta_dot)
{
	double full = p->rolling_crr * (p->body_mass_kg + p->wheel_mass_kg) * p->gravity *
		      p->wheel_radius_m;
	double s = theta_dot / ROLL_SMOOTH_RAD_S;

	return full * (s > 1.0 ? 1.0 : s < -1.0 ? -1.0 : s);
}

/* Pitch torque of the pushes active at t. */
static double push_torque(uint64_t t)
{
	double sum = 0.0;

	for (unsigned i = 0; i < rb.cfg.npushes; i++)
		if (t >= rb.cfg.pushes[i].t_ns && t < rb.cfg.pushes[i].t_ns + EV3SIM_PUSH_NS)
			sum += rb.cfg.pushes[i].torque_nm;
	return sum;
}

/* True once the app runs a motor: its bridge drives or brakes (a motor the
 * app has not started, or has floated, coasts). */
static bool bridge_engaged(struct hs_motor *m)
{
	struct hbridge_drive d = hs_motor_drive(m);

	return d.fwd != 0.0 || d.rev != 0.0 || d.brake != 0.0;
}

/* Bridge drive of a motor as a signed fraction. */
static double duty_of(struct hs_motor *m)
{
	struct hbridge_drive d = hs_motor_drive(m);

	return d.fwd - d.rev;
}

/* Hands each motor half of the shafts' load and effective inertia until the
 * next physics step at next_ns (0: none comes). */
static void set_loads(double load, double inertia, uint64_t next_ns)
{
	for (int i = 0; i < 2; i++)
		hs_motor_set_load_until(rb.motor[i], load / 2.0, inertia / 2.0, next_ns);
}

/* The gyro measures the body's pitch rate. */
static void set_gyro(double rate_dps)
{
	struct uart_sensor *s = ev3_input_uart_sensor(rb.cfg.gyro_port);
	struct uart_sensor_scene scene;

	if (s == NULL)
		return;     /* unplugged by a fault: nothing measures */
	scene = *uart_sensor_scene(s);
	scene.rate_dps = rate_dps;
	uart_sensor_set_scene(s, &scene);
}

/* The shafts' speed (rad/s) and angle (rad) now, averaged over both motors.
 * The exact speed is read without starting a motor segment: the step's new
 * loads start the one segment each motor needs. */
static void read_shafts(double *omega, double *phi)
{
	*omega = 0.0;
	*phi = 0.0;
	for (int i = 0; i < 2; i++) {
		*omega += hs_motor_speed_now_dps(rb.motor[i]) * DEG / 2.0;
		*phi += hs_motor_angle_deg(rb.motor[i]) * DEG / 2.0;
	}
}

/* Records the state of this step and tells the observer. */
static void publish(uint64_t t, double phi, double theta, bool held)
{
	rb.now.t_ns = t;
	rb.now.tilt_deg = rb.psi / DEG;
	rb.now.tilt_rate_dps = rb.psi_dot / DEG;
	rb.now.wheel_deg = theta / DEG;
	rb.now.motor_deg = phi / DEG;
	rb.now.duty_a = duty_of(rb.motor[0]);
	rb.now.duty_d = duty_of(rb.motor[1]);
	rb.now.held = held;
	rb.now.fallen = rb.fell_at != 0;
	if (rb.cfg.observer)
		rb.cfg.observer(&rb.now, rb.cfg.observer_ctx);
}

/* Event: one physics step at the current virtual time. */
static void robot_step(void *arg)
{
	const struct ev3sim_robot_params *p = rb.p;
	const double dt = EV3SIM_ROBOT_STEP_NS * 1e-9;
	uint64_t t = hs_now();
	bool held;
	double omega, phi, theta, a, b, c, h, roll;

	/* the hand waits for the app to drive the wheels, where asked to */
	if (!rb.driven && (bridge_engaged(rb.motor[0]) || bridge_engaged(rb.motor[1])))
		rb.driven = true;
	held = t < rb.cfg.release_ns || (rb.cfg.release_on_drive && !rb.driven);

	(void)arg;
	rb.step_ev = 0;
	read_shafts(&omega, &phi);

	/* The body over the last step: psi'' from F and the shafts' acceleration. */
	if (held) {
		rb.psi = rb.cfg.start_tilt_deg * DEG;
		rb.psi_dot = 0.0;
	} else {
		double old_rate = rb.psi_dot;

		rb.psi_dot += (rb.force_psi * dt - rb.coupling * (omega - rb.omega)) / rb.m_psi;
		rb.psi += 0.5 * (old_rate + rb.psi_dot) * dt;
	}
	rb.omega = omega;
	rb.theta_dot = omega + rb.psi_dot;
	theta = phi + rb.psi;
	if (fabs(rb.psi) >= p->fall_deg * DEG) {
		/* on the ground: the body stops, the wheels spin free */
		rb.fell_at = t;
		rb.psi = copysign(p->fall_deg * DEG, rb.psi);
		rb.psi_dot = 0.0;
		rb.load = 0.0;
		rb.inertia = p->wheel_inertia;
		set_loads(rb.load, rb.inertia, 0);
		set_gyro(0.0);
		publish(t, phi, theta, false);
		return;
	}

	/* What the shafts see during the next step. */
	a = (p->wheel_mass_kg + p->body_mass_kg) * p->wheel_radius_m * p->wheel_radius_m +
	    p->wheel_inertia;
	b = p->body_mass_kg * p->wheel_radius_m * p->com_height_m * cos(rb.psi);
	c = p->body_mass_kg * p->com_height_m * p->com_height_m + p->body_inertia;
	h = p->body_mass_kg * p->wheel_radius_m * p->com_height_m * sin(rb.psi) *
	    rb.psi_dot * rb.psi_dot;
	roll = rolling_torque(p, rb.theta_dot);
	rb.force_psi = p->body_mass_kg * p->gravity * p->com_height_m * sin(rb.psi) + h - roll +
		       push_torque(t);
	rb.coupling = a + b;
	rb.m_psi = a + 2.0 * b + c;
	if (held) {
		/* a hand holds the body: the wheels roll the robot along */
		rb.load = roll;
		rb.inertia = a;
	} else {
		rb.load = rb.coupling * rb.force_psi / rb.m_psi + roll - h;
		rb.inertia = (a * c - b * b) / rb.m_psi;
	}
	set_loads(rb.load, rb.inertia, t + EV3SIM_ROBOT_STEP_NS);
	set_gyro(rb.psi_dot / DEG);
	publish(t, phi, theta, held);
	rb.step_ev = hs_event_at(t + EV3SIM_ROBOT_STEP_NS, robot_step, NULL);
}

/* Starts the physics on the attached motors and gyro. */
ER ev3sim_robot_start(const struct ev3sim_robot_cfg *cfg)
{
	unsigned ports[2];

	if (cfg == NULL || cfg->left_port >= 4 || cfg->right_port >= 4 ||
	    cfg->left_port == cfg->right_port || cfg->gyro_port >= 4 ||
	    (cfg->npushes > 0 && cfg->pushes == NULL) || cfg->npushes > EV3SIM_MAX_PUSHES)
		return E_PAR;
	ports[0] = cfg->left_port;
	ports[1] = cfg->right_port;
	ev3sim_robot_stop();
	rb = (struct robot){ .cfg = *cfg, .p = cfg->params ? cfg->params : &ev3sim_gyro_boy };
	for (int i = 0; i < 2; i++) {
		rb.motor[i] = ev3_output_motor(ports[i]);
		if (rb.motor[i] == NULL)
			return E_OBJ;
	}
	if (ev3_input_uart_sensor(cfg->gyro_port) == NULL)
		return E_OBJ;
	rb.psi = cfg->start_tilt_deg * DEG;
	rb.running = true;
	rb.step_ev = hs_event_at(hs_now(), robot_step, NULL);
	return E_OK;
}

/* Stops the physics events. */
void ev3sim_robot_stop(void)
{
	unsigned ports[2] = { rb.cfg.left_port, rb.cfg.right_port };

	if (rb.running) {
		hs_event_cancel(&rb.step_ev);
		/* the motors step on their own again (one unplugged by a fault is gone) */
		for (int i = 0; i < 2; i++)
			if (ev3_output_motor(ports[i]) == rb.motor[i])
				hs_motor_end_load_promise(rb.motor[i]);
	}
	rb.running = false;
}

const struct ev3sim_robot_sample *ev3sim_robot_now(void)
{
	return &rb.now;
}

bool ev3sim_robot_fallen(uint64_t *t_ns)
{
	if (t_ns)
		*t_ns = rb.fell_at;
	return rb.fell_at != 0;
}
