/*
 * linux/platform_data/i2c-davinci.h — the board's settings of a DaVinci I2C
 * controller (Linux's layout), given to da8xx_register_i2c (mach/da8xx.h).
 */
#ifndef __LINUX_PLATFORM_DATA_I2C_DAVINCI_H
#define __LINUX_PLATFORM_DATA_I2C_DAVINCI_H

#include <linux/types.h>

struct davinci_i2c_platform_data {
	unsigned int bus_freq;          /* SCL, kHz (0: 100) */
	unsigned int bus_delay;         /* wait after each message, us */
	bool gpio_recovery;             /* not supported here */
	bool has_pfunc;                 /* ICPFUNC exists: set to I2C function at init */
};

#endif /* __LINUX_PLATFORM_DATA_I2C_DAVINCI_H */
