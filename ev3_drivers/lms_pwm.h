/* SPDX-License-Identifier: GPL-2.0 */
/*
 * lms_pwm.h — user interface of d_pwm: the command protocol written to
 * /dev/lms_pwm, the busy report read from it, and the MOTORDATA array
 * /dev/lms_motor maps.  Interface-compatible with LEGO's lms2012 d_pwm.
 *
 * A command is one write(): byte 0 is the opcode, byte 1 (where present)
 * a port mask (bit 0 = port A .. bit 3 = port D).  Multi-byte fields are
 * little-endian and sit at the offsets below; a write must be at least the
 * opcode's minimum length and at most its full length, else -EINVAL.
 */
#ifndef LMS_PWM_H
#define LMS_PWM_H

#ifdef __KERNEL__
#include <linux/types.h>
#else
#include <stdint.h>
#endif

#define LMS_PWM_DEVICE_NAME    "lms_pwm"
#define LMS_MOTOR_DEVICE_NAME  "lms_motor"

#define LMS_PWM_PORTS          4
#define LMS_PWM_PORT_MASK      0x0F   /* valid bits of a port mask */
#define LMS_PWM_CMD_MAX        20     /* the longest command, in bytes */

/* Opcodes (lms2012 bytecodes). */
#define LMS_PWM_PROGRAM_STOP     0x02  /* [0]; brake 100 ms where braked, coast; then PROGRAM_START */
#define LMS_PWM_PROGRAM_START    0x03  /* [0]; polarity +1, sync pairs dissolved */
#define LMS_PWM_OUTPUT_GET_TYPE  0xA0  /* accepted, ignored */
#define LMS_PWM_OUTPUT_SET_TYPE  0xA1  /* [1..4] = type of port A..D */
#define LMS_PWM_OUTPUT_RESET     0xA2  /* [1] Nos */
#define LMS_PWM_OUTPUT_STOP      0xA3  /* [1] Nos, [2] brake (0 coast, 1 hold) */
#define LMS_PWM_OUTPUT_POWER     0xA4  /* [1] Nos, [2] s8 power -100..100 */
#define LMS_PWM_OUTPUT_SPEED     0xA5  /* [1] Nos, [2] s8 speed -100..100 */
#define LMS_PWM_OUTPUT_START     0xA6  /* [1] Nos */
#define LMS_PWM_OUTPUT_POLARITY  0xA7  /* [1] Nos, [2] s8 -1, 0 (toggle), 1 */
#define LMS_PWM_OUTPUT_READ      0xA8  /* accepted, ignored */
#define LMS_PWM_OUTPUT_TEST      0xA9  /* accepted, ignored */
#define LMS_PWM_OUTPUT_READY     0xAA  /* accepted, ignored */
#define LMS_PWM_OUTPUT_POSITION  0xAB  /* accepted, does nothing */
#define LMS_PWM_OUTPUT_STEP_POWER 0xAC /* step layout below */
#define LMS_PWM_OUTPUT_TIME_POWER 0xAD
#define LMS_PWM_OUTPUT_STEP_SPEED 0xAE
#define LMS_PWM_OUTPUT_TIME_SPEED 0xAF
#define LMS_PWM_OUTPUT_STEP_SYNC 0xB0  /* sync layout below */
#define LMS_PWM_OUTPUT_TIME_SYNC 0xB1
#define LMS_PWM_OUTPUT_CLR_COUNT 0xB2  /* [1] Nos */
#define LMS_PWM_OUTPUT_PRG_STOP  0xB3  /* accepted, ignored */
#define LMS_PWM_OUTPUT_GET_COUNT 0xB4  /* accepted, ignored */

/* STEP_/TIME_POWER and STEP_/TIME_SPEED: 20 bytes (17 used). */
#define LMS_PWM_STEP_OFF_NOS     1
#define LMS_PWM_STEP_OFF_VALUE   2     /* s8 power or speed, -100..100 */
#define LMS_PWM_STEP_OFF_STEP1   4     /* s32 ramp-up length, tacho counts or ms */
#define LMS_PWM_STEP_OFF_STEP2   8     /* s32 constant phase */
#define LMS_PWM_STEP_OFF_STEP3   12    /* s32 ramp-down length */
#define LMS_PWM_STEP_OFF_BRAKE   16    /* u8 0 coast / 1 hold at the end */
#define LMS_PWM_STEP_LEN_MIN     17
#define LMS_PWM_STEP_LEN         20

/* STEP_SYNC and TIME_SYNC: 16 bytes (13 used). */
#define LMS_PWM_SYNC_OFF_NOS     1     /* exactly two ports */
#define LMS_PWM_SYNC_OFF_SPEED   2     /* s8 -100..100 */
#define LMS_PWM_SYNC_OFF_TURN    4     /* s16 -200..200 */
#define LMS_PWM_SYNC_OFF_STEP    8     /* s32 counts of the master or ms; 0 = forever */
#define LMS_PWM_SYNC_OFF_BRAKE   12    /* u8 0 coast / 1 hold at the end */
#define LMS_PWM_SYNC_LEN_MIN     13
#define LMS_PWM_SYNC_LEN         16

/* Device types for OUTPUT_SET_TYPE: these two are driven as tacho motors. */
#define LMS_PWM_TYPE_TACHO       7     /* EV3 large motor */
#define LMS_PWM_TYPE_MINITACHO   8     /* EV3 medium motor */
#define LMS_PWM_TYPE_NONE        126

/* read() of /dev/lms_pwm: "R T " — ReadyStatus and TestStatus busy masks as hex digits. */
#define LMS_PWM_STATUS_LEN       4

/* mmap of /dev/lms_motor: MOTORDATA[4], 12 bytes each, refreshed every 2 ms. */
struct lms_motor_data {
	int32_t tacho_counts;   /* counts since the current limited command began (0 when unlimited) */
	int8_t  speed;          /* measured speed, -100..100 */
	int8_t  pad[3];
	int32_t tacho_sensor;   /* cumulative counts, zeroed by OUTPUT_CLR_COUNT */
};

#define LMS_MOTOR_DATA_SIZE      (LMS_PWM_PORTS * 12)

#endif /* LMS_PWM_H */
