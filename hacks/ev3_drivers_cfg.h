/*
 * ev3_drivers_cfg.h — the EV3's drivers on the RTOS as one configuration
 * fragment: linux_compat (worker task, tick ISR, Linux interrupt lines) plus
 * the service calls of pwm_hack, analog_hack, uart_hack and ui_hack, and read access
 * for every user domain to the drivers' shared memory (their mmap areas live
 * in linux_compat's kmalloc pool).  Plain TOPPERS C: applications INCLUDE it.
 */
#ifndef EV3LX_EV3_DRIVERS_CFG_H
#define EV3LX_EV3_DRIVERS_CFG_H

#include "rtos_cfg.h"

extern const struct rtos_cfg ev3_drivers_cfg;

#endif /* EV3LX_EV3_DRIVERS_CFG_H */
