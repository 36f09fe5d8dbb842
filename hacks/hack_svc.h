/*
 * hack_svc.h — the one header a hack's RTOS side includes (hacks/<drv>_svc.c):
 * the Linux API its service calls use (driver_common.h, without the driver),
 * then the kernel's interface and linux_compat's RTOS-side interfaces:
 *   - the kernel's service calls and types (kernel.h) and the configuration
 *     tables (rtos_cfg.h);
 *   - Linux results as TOPPERS codes (linux_compat/er.h): lx_errno_to_er;
 *   - linux_compat's configuration fragments (linux_compat/config.h);
 *   - module parameters set from the RTOS side (linux_compat/modparam.h);
 *   - the module's interface mark and function-code base (hack_interface.h).
 * The driver's source is never in this translation unit: its macros and the
 * kernel's chip headers (EV3RT's am1808.h names SPI registers as d_analog
 * does) stay apart.
 */
#ifndef EV3LX_HACK_SVC_H
#define EV3LX_HACK_SVC_H

#include "driver_common.h"

#include <kernel.h>
#include <rtos_cfg.h>
#include <linux_compat/er.h>
#include <linux_compat/config.h>
#include <linux_compat/modparam.h>
#include "hack_interface.h"
#include "hack_routines.h"

#endif /* EV3LX_HACK_SVC_H */
