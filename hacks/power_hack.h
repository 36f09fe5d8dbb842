/*
 * power_hack.h — d_power's interface on the RTOS: extended service calls
 * (function codes POWER_FN_FIRST.. are d_power's) and the configuration fragment that
 * defines them.  Plain TOPPERS C: applications and the api include it.
 *
 * The battery's voltage and currents need no service call: they are raw
 * counts in d_analog's shared ANALOG area (analog_hack.h).
 *
 * Every call returns a TOPPERS code:
 *   E_PAR   a test-pin level other than 0 or 1
 *   E_CTX   called from non-task context
 *   E_OBJ   the driver is not loaded (its module_init failed)
 */
#ifndef EV3LX_POWER_HACK_H
#define EV3LX_POWER_HACK_H

#include "kernel.h"
#include "rtos_cfg.h"
#include "hack_interface.h"

/* The function codes this module owns: POWER_FN_FIRST .. + POWER_FN_COUNT - 1
 * (EV3LX_FNCD_BASE moves every module's range, -DPOWER_FN_FIRST=n this one; boot rejects ranges
 * that overlap another module's). */
#ifndef POWER_FN_FIRST
#define POWER_FN_FIRST (EV3LX_FNCD_BASE + 63)
#endif
#define POWER_FN_COUNT 8
#define POWER_FN_LAST  (POWER_FN_FIRST + POWER_FN_COUNT - 1)

#define POWER_FN_RECHARGEABLE  (POWER_FN_FIRST + 0)  /* (): read() of /dev/lms_power -> 1 rechargeable pack, 0 AA cells */
#define POWER_FN_TEST_PIN      (POWER_FN_FIRST + 1)  /* (uint_t level): write() of one byte, 0 or 1 */

/* The rest needs the driver's ABI header: not for a configuration's names (cfg/ev3lx.cfg). */
#ifndef EV3LX_CFG_NAMES_ONLY
#include "lms_power.h"

/* The DEF_SVC rows (INCLUDE it in the application's configuration). */
extern HACK_INTERFACE const struct rtos_cfg power_hack_cfg;

/* 1 when a rechargeable pack is fitted, 0 for AA cells, or an error code. */
static inline ER_UINT power_svc_rechargeable(void)
{
	return cal_svc(POWER_FN_RECHARGEABLE, 0, 0, 0, 0, 0);
}

/* Drives the board's test pin to level (0 or 1). */
static inline ER power_svc_test_pin(uint_t level)
{
	return (ER)cal_svc(POWER_FN_TEST_PIN, (intptr_t)level, 0, 0, 0, 0);
}

#endif /* EV3LX_CFG_NAMES_ONLY */
#endif /* EV3LX_POWER_HACK_H */
