/*
 * pwm_module.h — what d_pwm's module shares between its two translation
 * units: the hack file (pwm_hack.c, with the driver) defines it, the service
 * calls (pwm_svc.c) use it.  Linux types only; hidden in the module.
 */
#ifndef EV3LX_PWM_MODULE_H
#define EV3LX_PWM_MODULE_H

#include <linux/types.h>
#include <linux/fs.h>
#include "lms_pwm.h"

extern struct file *pwm_file;			/* /dev/lms_pwm, NULL while d_pwm is not up */
extern struct file *motor_file;			/* /dev/lms_motor */
extern const struct lms_motor_data *motor_map;	/* MOTORDATA[4], mapped */

/* set (OUTPUT_SPEED or OUTPUT_POWER, mask, value), then start (OUTPUT_START,
 * mask) through d_pwm's handlers; 0 or the driver's -errno. */
int pwm_module_run(const u8 *set, const u8 *start);
/* The ReadyStatus mask. */
u8 pwm_module_ready_status(void);

#endif /* EV3LX_PWM_MODULE_H */
