/*
 * ev3_motor.h — EV3 large and medium servo motors on an output port: a DC
 * motor with gearing, friction and load behind the H-bridge, its quadrature
 * tacho on the port's INT (pin 5) and DIR (pin 6) GPIOs, 360 counts per
 * output revolution, and its identification voltage on pin 5.
 * docs/host-sim-devices.md gives the parameters and their sources.  Host only.
 *
 * Physics works at the output shaft (gearing folded in), on a fixed 1 ms
 * step and at every input change, with the exact solution of the linear
 * motor equation over each step; the shaft angle is linear within a step,
 * so the time of every tacho edge is computed, not stepped.
 */
#ifndef HOST_SIM_DEVICES_EV3_MOTOR_H
#define HOST_SIM_DEVICES_EV3_MOTOR_H

#include <stdbool.h>
#include <stdint.h>
#include "host_sim/devices/ev3_ports.h"

enum hs_motor_kind {
	HS_MOTOR_LARGE = 0,        /* 45502, lms2012 type 7 (TACHO) */
	HS_MOTOR_MEDIUM = 1,       /* 45503, lms2012 type 8 (MINITACHO) */
};

/* Output-shaft parameters of a motor model. */
struct hs_motor_params {
	const char *name;
	double no_load_dps;         /* no-load speed at nominal_v, deg/s */
	double stall_nm;            /* stall torque at nominal_v, N m */
	double nominal_v;
	double mech_time_s;         /* mechanical time constant J * w0 / stall */
	double coulomb_frac;        /* dry friction as a fraction of stall torque */
	double stall_a;             /* stall current at nominal_v (for the motor-current channel) */
	uint16_t pin5_low_mv, pin5_high_mv;   /* ID voltage on pin 5 with the encoder low / high */
	uint16_t pin5_pulled_mv;    /* pin 5 with encoder high while the brick pulls 5w high */
};

/* The built-in parameters of a kind. */
const struct hs_motor_params *hs_motor_params_of(enum hs_motor_kind kind);

/* How the H-bridge spends each PWM period: fractions driving forward and
 * reverse at the battery voltage, and braking (terminals shorted); the rest
 * is coasting (terminals open). */
struct hbridge_drive {
	double fwd, rev, brake;
};

/* H-bridge input level: the GPIO drives it high or low, or the GPIO floats
 * and the PWM signal drives it (low for the period's low fraction). */
enum hbridge_input {
	HBRIDGE_LOW,
	HBRIDGE_HIGH,
	HBRIDGE_PWM,
};

/* The bridge's time split for inputs in0 (DIR0, pin 1) and in1 (DIR1, pin 2)
 * with the PWM signal low for pwm_low of each period (LEGO's d_pwm.c: forward =
 * DIR0 high + DIR1 floating, reverse = the mirror, brake = both high,
 * coast = both low). */
struct hbridge_drive hbridge_resolve(enum hbridge_input in0, enum hbridge_input in1, double pwm_low);

/* The shaft state of a motor. */
struct dc_motor_state {
	double omega;               /* rad/s at the output shaft */
	double theta;               /* rad */
};

/* Derived constants of a motor model (computed once from the params). */
struct dc_motor_model {
	const struct hs_motor_params *p;
	double k_back;              /* N m per rad/s of back-EMF braking at full drive */
	double k_volt;              /* N m per volt */
	double viscous;             /* N m per rad/s */
	double coulomb;             /* N m */
	double inertia;             /* kg m^2 */
};

/* Fills a model from parameters. */
void dc_motor_model_init(struct dc_motor_model *m, const struct hs_motor_params *p);

/* Advances st by dt seconds under drive at vbat volts with external load
 * torque load_nm (signed, opposing positive rotation when positive) and
 * extra_inertia; exact for the linear part, dry friction stops the shaft at
 * zero speed.  A locked shaft (stall fault) stays still. */
void dc_motor_advance(const struct dc_motor_model *m, struct dc_motor_state *st, double dt,
		      struct hbridge_drive drive, double vbat, double load_nm, double extra_inertia);

/* ---- the motor attached to an output port ---- */

struct hs_motor;

/* Options of an attached motor. */
struct hs_motor_options {
	double load_nm;             /* constant external torque on the output shaft */
	double extra_inertia;       /* kg m^2 added to the shaft (wheels, arms) */
	double start_deg;           /* initial shaft angle */
};

/* Creates the motor on output port (0..3 = A..D): watches the H-bridge
 * GPIOs, drives INT/DIR from the tacho.  NULL on bad arguments. */
struct hs_motor *hs_motor_create(unsigned port, enum hs_motor_kind kind,
				   const struct hs_motor_options *opt);
/* Stops its events, releases the pins (they float) and frees it. */
void hs_motor_destroy(struct hs_motor *m);

/* The motor on output port (0..3), or NULL. */
struct hs_motor *hs_motor_on_port(unsigned port);

/* The PWM duty or the bridge inputs changed: integrate to now, apply. */
void hs_motor_inputs_changed(struct hs_motor *m);

/* Shaft angle (deg, continuous) and speed (deg/s) now. */
double hs_motor_angle_deg(struct hs_motor *m);
double hs_motor_speed_dps(struct hs_motor *m);
/* Exact shaft speed now, deg/s (0 while stalled), without starting a new step:
 * what the speed_dps trace signal would show if the load were re-applied now. */
double hs_motor_speed_now_dps(struct hs_motor *m);
/* Tacho position the pins show now, in counts (each INT edge is one count). */
int64_t hs_motor_tacho_counts(const struct hs_motor *m);
/* The bridge split in effect. */
struct hbridge_drive hs_motor_drive(const struct hs_motor *m);
/* Current through the motor now, amperes (estimate, for the ADC). */
double hs_motor_current_a(struct hs_motor *m);

/* Scenario and faults. */
void hs_motor_set_load(struct hs_motor *m, double load_nm, double extra_inertia);
/* hs_motor_set_load by a caller that sets the load again at next_ns (> now; 0:
 * no promise), as a physics model stepping with the motor does: the motor's own
 * step falling due at that instant then leaves the new segment to that call
 * instead of solving one the call replaces.  The caller keeps the promise or
 * withdraws it with hs_motor_end_load_promise before next_ns. */
void hs_motor_set_load_until(struct hs_motor *m, double load_nm, double extra_inertia,
			     uint64_t next_ns);
/* Withdraws the promise of hs_motor_set_load_until: the motor steps on its own again. */
void hs_motor_end_load_promise(struct hs_motor *m);
/* Locks the shaft (true) or frees it. */
void hs_motor_set_stalled(struct hs_motor *m, bool stalled);
/* Freezes the tacho outputs (true); on release they jump to the true position. */
void hs_motor_set_encoder_stuck(struct hs_motor *m, bool stuck);
/* Spurious INT glitches (2 us pulses) at a mean rate per second; 0 stops. */
void hs_motor_set_encoder_noise(struct hs_motor *m, double glitches_per_s);
/* Counts of spurious glitches emitted so far. */
uint64_t hs_motor_glitches(const struct hs_motor *m);

/* Pin 5 voltage in mV as the ADC sees it, given whether the brick drives
 * the 5w detection pull high. */
uint16_t hs_motor_pin5_mv(const struct hs_motor *m, bool pull5w_high);
/* Kind of the attached motor. */
enum hs_motor_kind hs_motor_kind_of(const struct hs_motor *m);

#endif /* HOST_SIM_DEVICES_EV3_MOTOR_H */
