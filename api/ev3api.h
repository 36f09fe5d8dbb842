/*
 * ev3api.h — the EV3 C API for application tasks: EV3RT's application
 * interface, so that an EV3RT app builds unchanged, and ev3lx's checked forms
 * of the same calls.
 *
 * One naming rule:
 *   ev3_*, ht_nxt_*, nxt_*  EV3RT's names, signatures, types and behaviour:
 *                           getters return the value; on a bad port or a
 *                           sensor of another type they log a warning through
 *                           syslog and return 0 / false; set_power clamps.
 *   ev3lx_*                 ev3lx's checked form of a call: returns a TOPPERS
 *                           error code, values come back through pointers,
 *                           nothing is clamped or logged.
 * Every EV3RT call is a thin wrapper over its checked form.
 *
 * Errors of the checked forms:
 *   E_OK    done
 *   E_ID    bad port
 *   E_PAR   bad value or type
 *   E_OBJ   the port is not configured, or configured as another type
 *   E_MACV  a pointer the calling task may not access
 *   E_TMOUT a sensor did not deliver in time (no call waits without bound)
 *   E_CTX   called from non-task context (handlers, ISRs)
 *   E_NOSPT a device class ev3lx has no driver for yet
 *
 * Like EV3RT's, this header includes one header per group.  A group ev3lx
 * does not provide yet is declared with EV3RT's signatures but marked
 * EV3API_NOT_YET (ev3api_not_yet.h): an app using it compiles, and its link fails naming the
 * missing call (never a stub that silently does nothing).
 *
 * As EV3RT's ev3api.h does (public source: ev3rt-git/ev3rt-hrp2-sdk,
 * common/ev3api/include/ev3api.h), it gives an app the kernel's, the system
 * log's and the TOPPERS library's headers and <stdio.h>, declares the API
 * with C linkage for C++ apps, and brings in the configuration's object IDs
 * (kernel_cfg.h, or module_cfg.h for a loadable module, BUILD_MODULE) —
 * except in the configurator's own pass over app.cfg (TOPPERS_CFG1_OUT),
 * when they do not exist yet.  Apps never include kernel_cfg.h themselves.
 * ev3lx's own code (the API's sources, ev3sim, tests) includes the group
 * headers it uses instead, and no app configuration.
 *
 * docs/api.md has every function and its errors; docs/ev3rt-apps.md how an
 * EV3RT app is built and what differs.
 */
#ifndef EV3API_H
#define EV3API_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include "kernel.h"
#include "t_syslog.h"
#include "t_stdlib.h"

#include "ev3api_motor.h"
#include "ev3api_sensor.h"
#include "ev3api_brick.h"
#include "ev3api_cyc.h"
#include "ev3api_fs.h"
#include "ev3api_lcd.h"
#include "ev3api_speaker.h"
#include "ev3api_battery.h"

#if !defined(TOPPERS_CFG1_OUT)
#include "ev3api_cfg.h"
#if defined(BUILD_MODULE)
#include "module_cfg.h"
#else
#include "kernel_cfg.h"
#endif
#endif

#endif /* EV3API_H */
