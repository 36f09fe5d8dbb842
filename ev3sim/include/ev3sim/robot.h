/*
 * robot.h — the self-balancing robot's body: a two-wheeled inverted pendulum
 * sized like LEGO's gyro boy, whose wheels are the output shafts of
 * host_sim's large motors on ports A and D and whose pitch rate is what
 * host_sim's gyro on the robot's gyro port measures.  Host only.
 *
 * Each physics step (a host event every EV3SIM_ROBOT_STEP_NS) reads the
 * motors' shaft speeds and angles, advances the body, hands the motors the
 * body's reaction (hs_motor_set_load: load torque and effective inertia for
 * the coming step) and sets the gyro's scene.  docs/ev3sim.md derives the
 * equations and lists the parameters.
 */
#ifndef EV3SIM_ROBOT_H
#define EV3SIM_ROBOT_H

#include <stdbool.h>
#include <stdint.h>
#include "kernel.h"

#define EV3SIM_ROBOT_STEP_NS   1000000ULL     /* physics step: 1 ms */
#define EV3SIM_PUSH_NS         100000000ULL   /* a push lasts 100 ms */
#define EV3SIM_MAX_PUSHES      16U

/* Mechanical parameters (SI units; masses and inertias of both wheels together). */
struct ev3sim_robot_params {
	double wheel_radius_m;
	double wheel_mass_kg;       /* both wheels with tyres */
	double wheel_inertia;       /* both wheels about the axle, kg m^2 */
	double body_mass_kg;        /* everything but the wheels */
	double com_height_m;        /* body centre of mass above the axle */
	double body_inertia;        /* body pitch inertia about its centre of mass, kg m^2 */
	double rolling_crr;         /* rolling resistance coefficient (force / weight) */
	double gravity;
	double fall_deg;            /* tilt at which the robot has fallen */
};

/* The gyro boy estimate (docs/ev3sim.md gives the sources). */
extern const struct ev3sim_robot_params ev3sim_gyro_boy;

/* A push: a pitch torque on the body for EV3SIM_PUSH_NS from t_ns (absolute). */
struct ev3sim_push {
	uint64_t t_ns;
	double torque_nm;           /* positive tips the robot forward */
};

/* One physics step's state, as recorded for the CSV and the plot. */
struct ev3sim_robot_sample {
	uint64_t t_ns;
	double tilt_deg;            /* body pitch from vertical, positive forward */
	double tilt_rate_dps;
	double wheel_deg;           /* wheel rotation over the ground (average of both) */
	double motor_deg;           /* shaft angle relative to the body (average of A and D) */
	double duty_a, duty_d;      /* H-bridge drive, -1..1 (forward minus reverse fraction) */
	bool held, fallen;
};

typedef void (*ev3sim_robot_observer)(const struct ev3sim_robot_sample *s, void *ctx);

/* What the robot is made of and when things happen to it. */
struct ev3sim_robot_cfg {
	const struct ev3sim_robot_params *params;   /* NULL: ev3sim_gyro_boy */
	unsigned left_port, right_port;             /* output ports 0..3 of the wheel motors */
	unsigned gyro_port;                         /* input port 0..3 of the gyro */
	uint64_t release_ns;                        /* held upright until then (absolute) */
	bool release_on_drive;                      /* and until a wheel motor is driven */
	double start_tilt_deg;                      /* tilt while held and at release */
	const struct ev3sim_push *pushes;
	unsigned npushes;
	ev3sim_robot_observer observer;             /* called after every step, may be NULL */
	void *observer_ctx;
};

/* Starts the physics on a booted board whose motors and gyro are attached:
 * E_OBJ if a motor or the gyro is missing, E_PAR for bad ports or pushes. */
ER ev3sim_robot_start(const struct ev3sim_robot_cfg *cfg);
/* Stops the physics events (before hs_sim_shutdown). */
void ev3sim_robot_stop(void);

/* The latest step's state. */
const struct ev3sim_robot_sample *ev3sim_robot_now(void);
/* Whether the body has fallen, and when (absolute ns). */
bool ev3sim_robot_fallen(uint64_t *t_ns);

#endif /* EV3SIM_ROBOT_H */
