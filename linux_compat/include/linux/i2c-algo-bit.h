/*
 * linux/i2c-algo-bit.h — I2C bit-banged over two lines through the
 * callbacks a board or bus driver gives (Linux 6.1's
 * drivers/i2c/algos/i2c-algo-bit.c): START, repeated START and STOP, bytes
 * MSB first with the ninth clock for the ACK, udelay timing.
 *
 * Errors as Linux's: an address nobody ACKs is -ENXIO, a byte written and
 * NACKed -EREMOTEIO, SCL held low by a slave longer than timeout
 * -ETIMEDOUT (only with getscl: without it SCL is output-only and never
 * stretched).  Added here, as a hardware controller reports it: a 1 sent
 * while getsda reads 0 is a lost arbitration, -EAGAIN (the core resends it
 * adap->retries times).  The whole transfer busy-waits (udelay): it never
 * sleeps, so master_xfer_atomic is offered when can_do_atomic is set.
 */
#ifndef _LINUX_I2C_ALGO_BIT_H
#define _LINUX_I2C_ALGO_BIT_H

#include <linux/i2c.h>

struct i2c_algo_bit_data {
	void *data;                         /* the callbacks' own data */
	void (*setsda)(void *data, int state);
	void (*setscl)(void *data, int state);
	int (*getsda)(void *data);
	int (*getscl)(void *data);          /* NULL: SCL is output-only */
	int (*pre_xfer)(struct i2c_adapter *adap);
	void (*post_xfer)(struct i2c_adapter *adap);
	int udelay;                         /* half an SCL period, us */
	int timeout;                        /* jiffies SCL may be stretched */
	bool can_do_atomic;                 /* the callbacks never sleep */
};

/* The algorithm, for adapters that set it themselves. */
extern const struct i2c_algorithm i2c_bit_algo;

/* Gives adap the bit-banging algorithm over adap->algo_data (a struct
 * i2c_algo_bit_data), leaves the lines idle high and registers it:
 * i2c_add_adapter's result. */
int i2c_bit_add_bus(struct i2c_adapter *adap);
/* The same with adap->nr as the bus number (i2c_add_numbered_adapter). */
int i2c_bit_add_numbered_bus(struct i2c_adapter *adap);

#endif /* _LINUX_I2C_ALGO_BIT_H */
