/*
 * bench_brick.h — the simulated brick the benchmarks run on: host_sim's EV3
 * with four motors (A, B large; C, D medium) and four UART sensors (1 colour,
 * 2 gyro, 3 ultrasonic, 4 infrared), booted with ev3api_cfg (linux_compat
 * and the drivers through their hacks) and one application task in user
 * domain 1, as a real application runs.  Used by the host bench
 * (bench_host.c) and the ARMv5 bench (bench_arm.c).  Host backend only.
 */
#ifndef EV3LX_BENCH_BRICK_H
#define EV3LX_BENCH_BRICK_H

#include <stdbool.h>
#include <stdint.h>
#include "ev3api_motor.h"
#include "ev3api_sensor.h"

/* The motor and the sensor whose calls are measured. */
#define BENCH_MOTOR_PORT   EV3_PORT_A
#define BENCH_SENSOR_PORT  EV3_PORT_2     /* the gyro, streaming its angle (mode 0) */
#define BENCH_RAW_BYTES    2U             /* GYRO-ANG is one 16-bit value */

/* The full brick, or (light) only the measured motor and sensor: the quick
 * bench's ARMv5 run uses the light brick to keep QEMU's log short. */
enum bench_brick_kind { BENCH_BRICK_FULL, BENCH_BRICK_LIGHT };

/* Boots the brick, runs body in the application task, shuts down; false if
 * boot failed or body did not return within max_virtual_s virtual seconds. */
bool bench_brick_run(enum bench_brick_kind kind, void (*body)(void), uint64_t seed,
		     unsigned max_virtual_s);

/* From the application task: configures the brick's motors and sensors,
 * starts the motors turning, and waits (bounded) until every sensor streams
 * DATA, so the measured calls take their fast paths.  E_OK or the first error. */
ER bench_brick_prepare(void);

/* The speed for the i-th measured ev3lx_motor_set_speed: it alternates
 * between two forward speeds, so every call changes the regulator's target
 * without reversing the motor. */
int bench_speed_for(unsigned i);

/* The bytes ev3lx_motor_set_speed hands the driver for a speed (d_pwm's
 * OUTPUT_SPEED command: opcode, port mask, value); *len gets their count. */
void bench_speed_command(int speed, uint8_t *cmd, unsigned *len);

#endif /* EV3LX_BENCH_BRICK_H */
