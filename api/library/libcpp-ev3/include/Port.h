/*
 * Port.h — libcpp-ev3's port numbers: the names EV3RT's C++ API gives the
 * brick's sensor ports (1..4) and motor ports (A..D), with the values of
 * EV3RT's C API (sensor_port_t, motor_port_t) they are converted to.
 * Public source of the names and values: EV3RT's SDK,
 * common/library/libcpp-ev3/include/Port.h.  They are at global scope, as
 * there: apps write PORT_1 and PORT_A without a namespace.
 */
#ifndef EV3LX_LIBCPP_EV3_PORT_H
#define EV3LX_LIBCPP_EV3_PORT_H

/* A sensor port: PORT_1 is EV3_PORT_1. */
enum ePortS {
	PORT_1 = 0,
	PORT_2,
	PORT_3,
	PORT_4
};

/* A motor port: PORT_A is EV3_PORT_A. */
enum ePortM {
	PORT_A = 0,
	PORT_B,
	PORT_C,
	PORT_D
};

/* The power a sensor port supplies (NXT-era sensors); no class uses it. */
enum ePower {
	POWER_OFF = 0,
	POWER_LOWSPEED_9V = 1,
	POWER_LOWSPEED = 2
};

#define NUM_PORT_S (4)
#define NUM_PORT_M (4)

#endif /* EV3LX_LIBCPP_EV3_PORT_H */
