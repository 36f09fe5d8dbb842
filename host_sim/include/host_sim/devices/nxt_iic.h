/*
 * nxt_iic.h — NXT I2C sensors on the EV3's input ports: the bus on the
 * port pins and the sensors as I2C slaves.  Host only.
 *
 * The bus (per input port, EP2 wiring): SCL is connector pin 5, driven
 * through the port's TX buffer (enabled while its GPIO is driven low) from
 * the SCL pad (port 1 GP1_0, 2 GP8_3, 3 GP1_12, 4 GP1_11); d_analog's pin-5
 * GPIO reads the connector.  SDA is connector pin 6, the port's pin-6 GPIO.
 * Both lines are open-drain with the sensor's pull-ups: a line is low while
 * anyone pulls it low (the SoC driving low, or the slave pulling SDA), high
 * otherwise; the SoC driving a line high while the slave pulls it low is
 * counted as contention.  The slave reacts to every edge of the resolved
 * lines, in virtual time, exactly as an I2C slave state machine:
 *   SDA falling while SCL is high       START (a repeated START inside a
 *                                       transaction), address bits follow;
 *   SDA rising while SCL is high        STOP: the slave lets go of the bus;
 *   SCL rising                          the slave samples the master's bit;
 *   SCL falling                         the slave puts its next bit (or its
 *                                       ACK) on SDA, or releases it.
 * It never holds SCL (no clock stretching).  An address that is not the
 * slave's, a register pointer outside its register file, or a START/STOP in
 * the middle of a byte are protocol events the slave answers by NACKing (or
 * dropping the transaction) and counts (struct nxt_iic_stats).
 *
 * Sensors (registers from HiTechnic's and the temperature sensor's data
 * sheets; the NXT convention: version at 0x00, manufacturer at 0x08 and
 * sensor type at 0x10, 8 characters each, data from 0x42):
 *   NXT_IIC_HT_ACCEL     HiTechnic accelerometer, address 0x01: "HITECHNC",
 *                        "Accel."; 0x42..0x44 the upper 8 bits of X, Y, Z,
 *                        0x45..0x47 their lower 2 bits (10-bit signed,
 *                        about 200 counts per g).
 *   NXT_IIC_HT_COLOR     HiTechnic colour sensor (v1), address 0x01:
 *                        "HiTechnc", "Color"; 0x42 colour number (0..17),
 *                        0x43..0x45 red, green, blue (8 bits), 0x46..0x4B
 *                        raw red, green, blue (16 bits, MSB first), 0x4C
 *                        colour index, 0x4D..0x4F normalised RGB.
 *   NXT_IIC_HT_COLOR_V2  HiTechnic colour sensor V2, address 0x01:
 *                        "HiTechnc", "ColorPD"; 0x41 mode (0 active),
 *                        0x42 colour number, 0x43..0x46 red, green, blue,
 *                        white, 0x47 colour index, 0x48..0x4A normalised RGB.
 *   NXT_IIC_TEMP         LEGO NXT temperature sensor (an LM75/TMP275-class
 *                        part), address 0x4C: pointer register; 0 the
 *                        temperature (16 bits, MSB first: signed degrees in
 *                        the high byte, 1/16 degree steps in the high nibble
 *                        of the low byte), 1 configuration (bits 6:5 the
 *                        resolution, 9..12 bits; 0 at power-up), 2 and 3
 *                        T_LOW and T_HIGH.
 *   NXT_IIC_US           LEGO NXT ultrasonic sensor 9846, address 0x01 (0x02
 *                        as the 8-bit write address; register map from LEGO's
 *                        NXT Hardware Developer Kit, the ultrasonic sensor's
 *                        I2C appendix): "V1.0", "LEGO", "Sonar" at 0x00,
 *                        0x08, 0x10 (the kit's factory and units registers
 *                        at 0x11..0x14 are not modelled: the register file
 *                        here is linear, there they are not); 0x40 the
 *                        continuous measurement interval; 0x41 the command
 *                        (0x00 off, 0x01 single shot, 0x02 continuous — the
 *                        power-up state, 0x03 event capture, 0x04 warm reset);
 *                        0x42..0x49 measurement bytes 0..7 in cm (255: no
 *                        echo).  Continuous: byte 0 is the distance now,
 *                        1..7 are 0; a single shot measures once at the
 *                        command (byte 0, the rest 0) and then holds; off
 *                        holds the last bytes; warm reset returns to
 *                        continuous.
 */
#ifndef HOST_SIM_DEVICES_NXT_IIC_H
#define HOST_SIM_DEVICES_NXT_IIC_H

#include <stdbool.h>
#include <stdint.h>
#include "kernel.h"

enum nxt_iic_kind {
	NXT_IIC_HT_ACCEL = 1,
	NXT_IIC_HT_COLOR,
	NXT_IIC_HT_COLOR_V2,
	NXT_IIC_TEMP,
	NXT_IIC_US,
};

#define NXT_IIC_HT_ADDRESS   0x01U
#define NXT_IIC_US_ADDRESS   0x01U
#define NXT_IIC_TEMP_ADDRESS 0x4CU

/* What a sensor measures. */
struct nxt_iic_scene {
	int16_t accel[3];           /* HT_ACCEL: X, Y, Z in counts, -512..511 */
	uint8_t color_number;       /* HT_COLOR*: 0..17 */
	uint8_t rgb[3];             /* HT_COLOR*: red, green, blue 0..255 */
	uint8_t white;              /* HT_COLOR_V2 */
	double temp_c;              /* TEMP: degrees Celsius, -55..128 */
	uint8_t distance_cm;        /* US: the nearest echo, cm (255: none) */
};

/* Protocol counters of one port's slave (what it saw on the bus). */
struct nxt_iic_stats {
	uint32_t starts;            /* START conditions, repeated ones included */
	uint32_t repeated_starts;   /* START inside a transaction (no STOP before) */
	uint32_t stops;
	uint32_t address_acks;      /* its address, ACKed */
	uint32_t address_nacks;     /* an address that is not its own */
	uint32_t bytes_written;     /* data bytes the master wrote, ACKed */
	uint32_t write_nacks;       /* data bytes refused (register pointer outside the file) */
	uint32_t bytes_read;        /* bytes the slave sent */
	uint32_t aborted_bytes;     /* a START or STOP in the middle of a byte */
	uint32_t contention;        /* the SoC drove SDA high while the slave pulled it low */
};

/* Plugs an NXT I2C sensor into input port (0..3): pin 2 grounded, pull-ups on pins 5 and 6
 * (what d_analog reports as an NXT I2C device).  E_ID bad port, E_PAR bad kind, E_OBJ no board. */
ER ev3_attach_nxt_iic(unsigned port, enum nxt_iic_kind kind, const struct nxt_iic_scene *scene);
/* What the sensor on the port measures.  E_OBJ if the port has no NXT I2C sensor. */
ER ev3_set_nxt_iic_scene(unsigned port, const struct nxt_iic_scene *scene);
/* The slave's protocol counters.  E_OBJ if the port has no NXT I2C sensor. */
ER ev3_nxt_iic_stats(unsigned port, struct nxt_iic_stats *out);
/* The slave's register file as the master last left it (reg 0..255; -1 if none). */
int ev3_nxt_iic_register(unsigned port, unsigned reg);

#endif /* HOST_SIM_DEVICES_NXT_IIC_H */
