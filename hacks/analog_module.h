/*
 * analog_module.h — what the d_analog module shares between its two translation
 * units: the hack file (analog_hack.c, with the driver) defines it, the service
 * calls (analog_svc.c) use it.  Linux types only; hidden in the module.
 */
#ifndef EV3LX_ANALOG_MODULE_H
#define EV3LX_ANALOG_MODULE_H

#include <linux/types.h>
#include <linux/fs.h>
#include "lms_analog.h"

extern struct file *analog_file;		/* /dev/lms_analog, NULL while d_analog is not up */
extern struct file *dcm_file;			/* /dev/lms_dcm */
extern const struct lms_analog *analog_map_addr;	/* ANALOG, mapped */

#endif /* EV3LX_ANALOG_MODULE_H */
