/*
 * fault_spec.h — ev3sim's --fault syntax, mapped onto host_sim's seeded
 * fault injection (ev3_brick.h) and the gyro's noise/drift options.
 *
 *   KIND[:FIELD...]; times take a unit (s default, ms, us, ns) and count
 *   from the robot's release; a duration of 0 or none lasts to the end.
 *
 *   gyro-noise:SIGMA                 white noise on every gyro sample, deg/s
 *   gyro-drift:DPS                   constant gyro bias, deg/s
 *   uart-bit-errors:P[:T[:D]]        gyro bytes with one bit flipped, probability per byte
 *   uart-drop:P[:T[:D]]              gyro bytes lost
 *   uart-dup:P[:T[:D]]               gyro bytes duplicated
 *   adc-noise:MV[:T[:D]]             noise on every ADC sample, mV
 *   encoder-noise:PORT:RATE[:T[:D]]  tacho glitches per second on an output port A..D
 *   encoder-stuck:PORT[:T[:D]]       tacho frozen
 *   motor-stall:PORT[:T[:D]]         shaft locked
 *   unplug:PORT[:T[:D]]              unplug input port 1..4 or output port A..D
 */
#ifndef EV3SIM_FAULT_SPEC_H
#define EV3SIM_FAULT_SPEC_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include "kernel.h"
#include "host_sim/devices/ev3_brick.h"

enum ev3sim_fault_target {
	EV3SIM_FAULT_BRICK,         /* a host_sim fault (fault.kind etc.) */
	EV3SIM_FAULT_GYRO_NOISE,    /* the gyro's noise option (value) */
	EV3SIM_FAULT_GYRO_DRIFT,    /* the gyro's drift option (value) */
};

struct ev3sim_fault_spec {
	enum ev3sim_fault_target target;
	struct ev3_fault fault;     /* port, value, duration for EV3SIM_FAULT_BRICK */
	double value;               /* gyro options */
	uint64_t at_ns;             /* from release */
};

/* Parses one --fault value; gyro_port (0..3) is where uart-* faults go.
 * false with a message in err for a bad spec. */
bool ev3sim_fault_parse(const char *spec, unsigned gyro_port, struct ev3sim_fault_spec *out,
			char *err, size_t errlen);

/* E_OK, or E_PAR with a message in err if a fault of faults[0..n) would unplug the motor of output port left or right:
 * a robot's wheels are its motors' shafts, so the motor cannot leave. */
ER ev3sim_fault_check_wheels(const struct ev3sim_fault_spec *faults, unsigned n, unsigned left,
			     unsigned right, char *err, size_t errlen);

#endif /* EV3SIM_FAULT_SPEC_H */
