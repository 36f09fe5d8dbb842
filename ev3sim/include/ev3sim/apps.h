/*
 * apps.h — ev3sim's small applications: a motor run and a sensor survey,
 * each booting the simulated brick with ev3api_cfg and one application task
 * that prints what it sees through the EV3 API.  Host only.
 */
#ifndef EV3SIM_APPS_H
#define EV3SIM_APPS_H

#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include "kernel.h"
#include "host_sim/devices/ev3_brick.h"

struct ev3sim_motor_opts {
	unsigned port;              /* 0..3 = A..D */
	enum hs_motor_kind kind;
	bool power_mode;            /* unregulated power instead of regulated speed */
	int value;                  /* speed or power, -100..100 */
	double seconds;             /* how long it runs, > 0 */
	unsigned every_ms;          /* sample period of the printed rows */
	uint64_t seed;
	const char *trace_path;
};

/* Runs a motor and prints rows "t_s speed counts" and a key=value summary to
 * out.  E_OK, E_PAR (message in err), E_SYS (boot or run failure). */
ER ev3sim_motor_app(const struct ev3sim_motor_opts *o, FILE *out, char *err, size_t errlen);

/* What is plugged into a port for the sensor survey. */
enum ev3sim_input_device {
	EV3SIM_IN_NONE, EV3SIM_IN_TOUCH, EV3SIM_IN_NXT_TOUCH, EV3SIM_IN_NXT_LIGHT,
	EV3SIM_IN_GYRO, EV3SIM_IN_COLOR, EV3SIM_IN_ULTRASONIC, EV3SIM_IN_IR,
	EV3SIM_IN_HT_ACCEL, EV3SIM_IN_HT_COLOR, EV3SIM_IN_NXT_TEMP,     /* NXT I2C sensors */
	EV3SIM_IN_COUNT
};
enum ev3sim_output_device {
	EV3SIM_OUT_NONE, EV3SIM_OUT_LARGE, EV3SIM_OUT_MEDIUM, EV3SIM_OUT_COUNT
};

/* Names as the command line spells them ("touch", "gyro", "large"...), and back. */
const char *ev3sim_input_device_name(enum ev3sim_input_device d);
const char *ev3sim_output_device_name(enum ev3sim_output_device d);
bool ev3sim_input_device_parse(const char *s, enum ev3sim_input_device *d);
bool ev3sim_output_device_parse(const char *s, enum ev3sim_output_device *d);
/* Plugs NXT I2C sensor device d into input port (0..3) as ev3sim shows them: an accelerometer
 * lying flat (1 g on Z, about 200 counts), a colour sensor V2 seeing white, a temperature
 * sensor at 22.5 C.  E_PAR if d is not an NXT I2C device. */
ER ev3sim_attach_nxt_iic(unsigned port, enum ev3sim_input_device d);

struct ev3sim_sensors_opts {
	enum ev3sim_input_device in[4];
	enum ev3sim_output_device out[4];
	double seconds;             /* live values for this long after detection */
	unsigned every_ms;
	uint64_t seed;
	const char *trace_path;
};

/* The default set: touch, gyro, colour, ultrasonic on 1..4; large, medium,
 * nothing, large on A..D. */
void ev3sim_sensors_defaults(struct ev3sim_sensors_opts *o);

/* Plugs the devices in, prints what d_analog detected on every port
 * (InConn/InDcm/OutConn/OutDcm through the analog hack), then live values
 * through the API, and a key=value summary.  E_OK, E_PAR, E_SYS. */
ER ev3sim_sensors_app(const struct ev3sim_sensors_opts *o, FILE *out, char *err, size_t errlen);


/* ---- shared by the applications (balance_run.c, motor_app.c, sensors_app.c) ---- */

/* ATT_INI helper: the console shows warnings and worse only, so that the
 * applications' own output stays readable (everything is still traced). */
void ev3sim_quiet_console(void);

/* Wall-clock seconds (monotonic), for sim_speed. */
double ev3sim_wall_seconds(void);

#endif /* EV3SIM_APPS_H */
