/*
 * mach/legoev3-i2c.h — the board's bit-banged I2C buses on the EV3's input
 * ports (mach-davinci/legoev3-i2c.c), for the NXT I2C sensors: what a board
 * file registers for them before the sensor drivers load.
 *
 * Each input port's bus is i2c-algo-bit over the port's pins (EV3 EP2
 * board, as LEGO's lms2012 d_iic drives them): SCL is connector pin 5,
 * output-only (push-pull from the SCL pad through the port's TX buffer,
 * which the bus enables by driving its GPIO low); SDA is connector pin 6,
 * open-drain (driven low, or released to the sensor's pull-up).  SCL runs
 * at 10 kHz (udelay 50), the rate of LEGO's firmware (lms2012 d_iic: a
 * 50 us half period).  Input port N (1..4) is bus 2 + N, as ev3dev's board
 * file numbers them (i2c-3 .. i2c-6).
 *
 *   port   buffer enable (low = on)   SCL      SDA
 *   1      GP8_11                     GP1_0    GP0_15
 *   2      GP8_14                     GP8_3    GP0_13
 *   3      GP7_9                      GP1_12   GP1_14
 *   4      GP7_10                     GP1_11   GP1_15
 *
 * The SCL pads of ports 1 and 2 are UART1's and UART0's TX pads: adding the
 * bus muxes them as GPIO (PINMUX4[31:28] = 8, PINMUX3[23:20] = 4); ports 3
 * and 4 are GPIO as the boot loader leaves them.
 */
#ifndef _MACH_LEGOEV3_I2C_H
#define _MACH_LEGOEV3_I2C_H

#include <linux/i2c.h>

#define LEGOEV3_NUM_IN_PORTS		4
/* The bus number of input port index (0 = port 1). */
#define LEGOEV3_IN_PORT_I2C_BUS(index)	(3 + (index))

/* Claims the port's three GPIOs, enables its TX buffer and registers its
 * bus, creating the clients i2c_register_board_info gave for that bus:
 * 0, -EINVAL for a bad index, -EBUSY if a line or the bus is taken (the
 * GPIO's current owner is logged).  Process context. */
int legoev3_in_port_i2c_add(unsigned int index);
/* Unregisters the port's bus and its clients, disables its TX buffer and
 * frees its lines.  Process context. */
void legoev3_in_port_i2c_del(unsigned int index);
/* The port's adapter while it is registered, else NULL. */
struct i2c_adapter *legoev3_in_port_i2c_adapter(unsigned int index);

#endif /* _MACH_LEGOEV3_I2C_H */
