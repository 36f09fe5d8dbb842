/*
 * ev3api_motor.h — motors (included by ev3api.h): EV3RT's calls and ev3lx's
 * checked forms (the naming rule is in ev3api.h).
 */
#ifndef EV3API_MOTOR_H
#define EV3API_MOTOR_H

#ifdef __cplusplus
extern "C" {
#endif

#include <stdbool.h>
#include <stdint.h>
#include "kernel.h"

typedef enum {
	EV3_PORT_A = 0, EV3_PORT_B = 1, EV3_PORT_C = 2, EV3_PORT_D = 3,
	TNUM_MOTOR_PORT = 4
} motor_port_t;

typedef enum {
	NONE_MOTOR = 0,          /* port not used */
	MEDIUM_MOTOR = 1,        /* EV3 medium motor, speed-regulated */
	LARGE_MOTOR = 2,         /* EV3 large motor, speed-regulated */
	UNREGULATED_MOTOR = 3,   /* any DC motor, power only */
	TNUM_MOTOR_TYPE = 4
} motor_type_t;

/* ---- EV3RT ---- */

/* Declares what is on an output port; resets its counts. */
ER ev3_motor_config(motor_port_t port, motor_type_t type);
/* The configured type, or E_ID. */
ER_UINT ev3_motor_get_type(motor_port_t port);
/* Cumulative tacho counts in degrees (0 and a warning on error). */
int32_t ev3_motor_get_counts(motor_port_t port);
ER ev3_motor_reset_counts(motor_port_t port);
/* power outside -100..100 is clamped (warning logged).  Large and medium
 * motors get a regulated speed (OUTPUT_SPEED), unregulated ones a power. */
ER ev3_motor_set_power(motor_port_t port, int power);
/* The driver's current speed value of the port (MOTORDATA), -100..100. */
int ev3_motor_get_power(motor_port_t port);
ER ev3_motor_stop(motor_port_t port, bool_t brake);
/* Turns by degrees (the sign gives the direction) at speed_abs, then brakes;
 * blocking waits until done. */
ER ev3_motor_rotate(motor_port_t port, int degrees, uint32_t speed_abs, bool_t blocking);
/* Drives a pair synchronised until changed: turn_ratio -100..100 (0 straight,
 * +-100 spinning on the spot), positive turns towards the right motor. */
ER ev3_motor_steer(motor_port_t left_motor, motor_port_t right_motor, int power, int turn_ratio);

/* ---- ev3lx's checked forms ---- */

/* Declares what is on an output port; resets its counts.  E_ID, E_PAR. */
ER ev3lx_motor_config(motor_port_t port, motor_type_t type);
/* The configured type.  E_ID, E_MACV. */
ER ev3lx_motor_get_type(motor_port_t port, motor_type_t *p_type);
/* Runs at a regulated speed, -100..100 (% of the motor's maximum).  E_ID, E_PAR, E_OBJ. */
ER ev3lx_motor_set_speed(motor_port_t port, int speed);
/* Runs at an unregulated power, -100..100.  E_ID, E_PAR, E_OBJ. */
ER ev3lx_motor_set_power(motor_port_t port, int power);
/* Measured speed, -100..100.  E_ID, E_OBJ, E_MACV. */
ER ev3lx_motor_get_speed(motor_port_t port, int *p_speed);
/* Stops: brake = hold the position, else coast.  E_ID, E_OBJ. */
ER ev3lx_motor_stop(motor_port_t port, bool brake);
/* Cumulative tacho counts in degrees.  E_ID, E_OBJ, E_MACV. */
ER ev3lx_motor_get_counts(motor_port_t port, int32_t *p_counts);
/* Zeroes the cumulative counts.  E_ID, E_OBJ. */
ER ev3lx_motor_reset_counts(motor_port_t port);
/* Turns by degrees (sign gives the direction) at |speed| 1..100, then holds.
 * blocking: waits until done (E_TMOUT if the motor does not finish in time,
 * e.g. stalled).  E_ID, E_PAR, E_OBJ, E_CTX. */
ER ev3lx_motor_rotate(motor_port_t port, int degrees, int speed, bool blocking);
/* Whether a rotate/limited command is still running on the port.  E_ID, E_OBJ, E_MACV. */
ER ev3lx_motor_is_busy(motor_port_t port, bool *p_busy);
/* Drives two motors synchronised until changed: speed -100..100, turn
 * -200..200 (0 straight, +-100 one wheel stopped, +-200 spinning on the
 * spot).  E_ID, E_PAR, E_OBJ. */
ER ev3lx_motor_steer(motor_port_t left, motor_port_t right, int speed, int turn);
/* The same, stopping both (braked) after the first motor has turned by degrees (> 0). */
ER ev3lx_motor_sync(motor_port_t left, motor_port_t right, int speed, int turn, int degrees);

#ifdef __cplusplus
}
#endif

#endif /* EV3API_MOTOR_H */
