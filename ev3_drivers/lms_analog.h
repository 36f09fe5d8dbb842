/* SPDX-License-Identifier: GPL-2.0 */
/*
 * lms_analog.h - user-visible ABI of the EV3 analog driver (d_analog).
 *
 * /dev/lms_analog: mmap gives struct lms_analog (LEGO's ANALOG, 5172 bytes, same offsets on
 *                  every target); read gives a text dump; write is accepted and ignored.
 * /dev/lms_dcm:    read gives the detected types, write sets the input-port pin levels.
 *
 * Layout and codes are those of LEGO's lms2012 so that its user space works unchanged.
 */
#ifndef LMS_ANALOG_H
#define LMS_ANALOG_H

#ifdef __KERNEL__
#include <linux/types.h>
#else
#include <stdint.h>
#endif

#define LMS_ANALOG_DEVICE_NAME	"lms_analog"
#define LMS_DCM_DEVICE_NAME	"lms_dcm"

#define LMS_ANALOG_INPUTS	4	/* input ports 1..4 are indexes 0..3 */
#define LMS_ANALOG_OUTPUTS	4	/* output ports A..D are indexes 0..3 */
#define LMS_ANALOG_LOG_SIZE	300	/* samples in each pin 1 / pin 6 ring */
#define LMS_ANALOG_NXTCOL_SIZE	72	/* bytes of NXT colour-sensor data per port */

/* ADC scale: a 12-bit raw count, 4095 = 5000 mV. */
#define LMS_ADC_MAX		4095
#define LMS_ADC_FULL_SCALE_MV	5000

/* Device types (InDcm, OutDcm). */
#define LMS_TYPE_NXT_TOUCH	1
#define LMS_TYPE_NXT_LIGHT	2
#define LMS_TYPE_NXT_SOUND	3
#define LMS_TYPE_NXT_COLOR	4
#define LMS_TYPE_TACHO		7	/* EV3 large motor */
#define LMS_TYPE_MINITACHO	8	/* EV3 medium motor */
#define LMS_TYPE_NEWTACHO	9
#define LMS_TYPE_NXT_TEST	101
#define LMS_TYPE_NXT_IIC	123
#define LMS_TYPE_TERMINAL	124
#define LMS_TYPE_UNKNOWN	125	/* connected; the connection code says how */
#define LMS_TYPE_NONE		126
#define LMS_TYPE_ERROR		127

/* Connection types (InConn, OutConn). */
#define LMS_CONN_UNKNOWN		111
#define LMS_CONN_DAISYCHAIN		117
#define LMS_CONN_NXT_COLOR		118
#define LMS_CONN_NXT_DUMB		119
#define LMS_CONN_NXT_IIC		120
#define LMS_CONN_INPUT_DUMB		121	/* EV3 analog device; its ID resistor sets InPin1 */
#define LMS_CONN_INPUT_UART		122	/* EV3 UART sensor: hand the port to d_uart */
#define LMS_CONN_OUTPUT_DUMB		123
#define LMS_CONN_OUTPUT_INTELLIGENT	124
#define LMS_CONN_OUTPUT_TACHO		125	/* a motor; OutDcm says which */
#define LMS_CONN_NONE			126
#define LMS_CONN_ERROR			127

/*
 * The shared memory of /dev/lms_analog.  Voltages are raw ADC counts (see LMS_ADC_*).
 * The driver samples pin 1 and pin 6 of every input port each millisecond and the other
 * channels every 8 ms; user space reads without locking (every field is written whole).
 */
struct lms_analog {
	uint16_t in_pin1[LMS_ANALOG_INPUTS];	/* InPin1: latest pin 1 (ID/analog) */
	uint16_t in_pin6[LMS_ANALOG_INPUTS];	/* InPin6: latest pin 6 */
	uint16_t out_pin5[LMS_ANALOG_OUTPUTS];	/* OutPin5: latest output-port pin 5 */
	uint16_t battery_temp;			/* BatteryTemp */
	uint16_t motor_current;			/* MotorCurrent */
	uint16_t battery_current;		/* BatteryCurrent */
	uint16_t cell123456;			/* Cell123456: battery voltage */
	uint16_t pin1[LMS_ANALOG_INPUTS][LMS_ANALOG_LOG_SIZE];	/* Pin1: pin 1 sample rings */
	uint16_t pin6[LMS_ANALOG_INPUTS][LMS_ANALOG_LOG_SIZE];	/* Pin6: pin 6 sample rings */
	uint16_t actual[LMS_ANALOG_INPUTS];	/* Actual: ring index of the newest sample */
	uint16_t log_in[LMS_ANALOG_INPUTS];	/* LogIn: ring index the next sample goes to */
	uint16_t log_out[LMS_ANALOG_INPUTS];	/* LogOut: ring index of the oldest sample kept */
	/* NxtCol: LEGO's NXT colour-sensor area; this driver keeps it zero (see d_analog.c). */
	uint8_t nxt_col[LMS_ANALOG_INPUTS][LMS_ANALOG_NXTCOL_SIZE];
	uint16_t out_pin5_low[LMS_ANALOG_OUTPUTS];	/* OutPin5Low: pin 5 with pin 6 pulled low */
	int8_t updated[LMS_ANALOG_INPUTS];	/* Updated: set to 1 on each new sample */
	int8_t in_dcm[LMS_ANALOG_INPUTS];	/* InDcm: LMS_TYPE_* per input port */
	int8_t in_conn[LMS_ANALOG_INPUTS];	/* InConn: LMS_CONN_* per input port */
	int8_t out_dcm[LMS_ANALOG_OUTPUTS];	/* OutDcm: LMS_TYPE_* per output port */
	int8_t out_conn[LMS_ANALOG_OUTPUTS];	/* OutConn: LMS_CONN_* per output port */
};

#define LMS_ANALOG_SIZE		5172	/* sizeof(struct lms_analog) on every target */

/*
 * /dev/lms_dcm read: at least LMS_DCM_READ_SIZE bytes; returns in_dcm[0..3], out_dcm[0..3],
 * '\r' and a terminating 0.
 */
#define LMS_DCM_READ_SIZE	10

/*
 * /dev/lms_dcm write: LMS_DCM_WRITE_SIZE characters, one per input port, each one of
 *   LMS_DCM_KEEP            leave the port as it is;
 *   LMS_DCM_FLOAT           float pins 5 and 6 and switch the 9 V supply off;
 *   LMS_DCM_PINS(bits)      drive the pins: LMS_DCM_PIN5_HIGH, LMS_DCM_PIN6_HIGH (each low
 *                           when absent) and LMS_DCM_PIN1_9V (9 V supply on pin 1).
 * Levels apply to a port that has a device connected; detection refloats a port when its
 * device is unplugged.  LEGO's NXT colour commands (0x0D..0x11) are refused: -EOPNOTSUPP.
 */
#define LMS_DCM_WRITE_SIZE	4
#define LMS_DCM_KEEP		'-'
#define LMS_DCM_FLOAT		'f'
#define LMS_DCM_PIN5_HIGH	0x01
#define LMS_DCM_PIN6_HIGH	0x02
#define LMS_DCM_PIN1_9V		0x04
#define LMS_DCM_PINS(bits)	('0' + ((bits) & 0x07))

/* Converts a raw ADC count to millivolts. */
static inline unsigned int lms_analog_raw_to_mv(uint16_t raw)
{
	return (unsigned int)raw * LMS_ADC_FULL_SCALE_MV / LMS_ADC_MAX;
}

#endif /* LMS_ANALOG_H */
