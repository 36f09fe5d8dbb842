/*
 * ui_hack.h — d_ui's interface on the RTOS: extended service calls
 * (function codes UI_FN_FIRST.. are d_ui's) and the configuration fragment that
 * defines them.  Plain TOPPERS C: applications and the api include it.
 *
 * Reading a button needs no service call: ui_svc_map() gives d_ui's shared
 * page, whose pressed[] bytes (lms_ui.h, LEGO's button order) follow the
 * debounced buttons.
 *
 * Every call checks its arguments and returns a TOPPERS code:
 *   E_PAR   a pattern outside '0'..'9', or a timeout below TMO_FEVR
 *   E_MACV  a buffer the calling task may not write
 *   E_CTX   called from non-task context
 *   E_OBJ   the driver is not loaded (its module_init failed)
 *   E_TMOUT no click within the timeout (TMO_POL: none queued)
 *   E_RLWAI the wait was ended by rel_wai (how a task waiting for clicks is stopped)
 */
#ifndef EV3LX_UI_HACK_H
#define EV3LX_UI_HACK_H

#include "kernel.h"
#include "rtos_cfg.h"
#include "hack_interface.h"

/* The function codes this module owns: UI_FN_FIRST .. + UI_FN_COUNT - 1
 * (EV3LX_FNCD_BASE moves every module's range, -DUI_FN_FIRST=n this one; boot rejects ranges
 * that overlap another module's). */
#ifndef UI_FN_FIRST
#define UI_FN_FIRST (EV3LX_FNCD_BASE + 47)
#endif
#define UI_FN_COUNT 16
#define UI_FN_LAST  (UI_FN_FIRST + UI_FN_COUNT - 1)

#define UI_FN_LED         (UI_FN_FIRST + 0)  /* (uint_t pattern): write() of LMS_UI_LED_* ('0'..'9') */
#define UI_FN_MAP         (UI_FN_FIRST + 1)  /* (const struct lms_ui **out): address of the shared page */
#define UI_FN_WAIT_CLICK  (UI_FN_FIRST + 2)  /* (struct lms_ui_click *out, TMO tmout): the oldest click */

/* The rest needs the driver's ABI header: not for a configuration's names (cfg/ev3lx.cfg). */
#ifndef EV3LX_CFG_NAMES_ONLY
#include "lms_ui.h"

/* The DEF_SVC rows (INCLUDE it in the application's configuration). */
extern HACK_INTERFACE const struct rtos_cfg ui_hack_cfg;

/* Shows LED pattern LMS_UI_LED_OFF..LMS_UI_LED_ORANGE_PULSE on both LEDs. */
static inline ER ui_svc_led(uint_t pattern)
{
	return (ER)cal_svc(UI_FN_LED, (intptr_t)pattern, 0, 0, 0, 0);
}

/* The driver's shared page (pressed[], counters), read-only for callers. */
static inline ER ui_svc_map(const struct lms_ui **out)
{
	return (ER)cal_svc(UI_FN_MAP, (intptr_t)out, 0, 0, 0, 0);
}

/*
 * Takes the oldest click off d_ui's queue into *out, waiting at most tmout ms
 * for one (TMO_POL: no wait, TMO_FEVR: no limit).  Clicks go to one caller
 * each: tasks waiting at the same time share the clicks.
 */
static inline ER ui_svc_wait_click(struct lms_ui_click *out, TMO tmout)
{
	return (ER)cal_svc(UI_FN_WAIT_CLICK, (intptr_t)out, (intptr_t)tmout, 0, 0, 0);
}

#endif /* EV3LX_CFG_NAMES_ONLY */
#endif /* EV3LX_UI_HACK_H */
