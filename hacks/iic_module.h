/*
 * iic_module.h — what the d_iic module shares between its two translation
 * units: the hack file (iic_hack.c, with the driver) defines it, the service
 * calls (iic_svc.c) use it.  Linux types only; hidden in the module.
 */
#ifndef EV3LX_IIC_MODULE_H
#define EV3LX_IIC_MODULE_H

#include <linux/types.h>
#include <linux/fs.h>
#include "lms_iic.h"

extern struct file *iic_file;			/* /dev/lms_iic, opened at the first call */
extern const struct lms_iic *iic_hack_map;	/* its shared memory, mapped */

/* The open device, opening it (and mapping its memory) on first use; NULL if d_iic is not up. */
struct file *iic_hack_file(void);
/* Port @port's state (LMS_IIC_STATE_*) in the driver's table. */
u8 iic_module_port_state(unsigned int port);
/* Port @port's mode in the driver's table. */
s8 iic_module_port_mode(unsigned int port);

#endif /* EV3LX_IIC_MODULE_H */
