/*
 * power_module.h — what the d_power module shares between its two translation
 * units: the hack file (power_hack.c, with the driver) defines it, the service
 * calls (power_svc.c) use it.  Linux types only; hidden in the module.
 */
#ifndef EV3LX_POWER_MODULE_H
#define EV3LX_POWER_MODULE_H

#include <linux/types.h>
#include <linux/fs.h>
#include "lms_power.h"

extern struct file *power_file;		/* /dev/lms_power, NULL while d_power is not up */

#endif /* EV3LX_POWER_MODULE_H */
