/*
 * app.h — gyroboy: IDs, priorities and stack sizes (read by app.cfg and
 * app.c), and the app's settings and counters.
 */
#ifdef __cplusplus
extern "C" {
#endif

#include "ev3api.h"
#include "target_test.h"

/*
 * Priorities, all in the app's range (TMIN_APP_TPRI and below; the drivers'
 * work runs above it, as on EV3RT): the control step first, then the main
 * task, then the logger.  The EV3_CRE_CYC handlers, which only wake the
 * tasks, run at TMIN_APP_TPRI.  The logger-above-balancer experiment raises
 * the logger to LOGGER_ABOVE_PRIORITY.
 */
#define BALANCE_PRIORITY      (TMIN_APP_TPRI + 1)
#define MAIN_PRIORITY         (TMIN_APP_TPRI + 2)
#define LOGGER_PRIORITY       (TMIN_APP_TPRI + 4)
#define LOGGER_ABOVE_PRIORITY TMIN_APP_TPRI

#ifndef STACK_SIZE
#define STACK_SIZE        4096
#endif

#include "gyroboy.h"

#ifndef TOPPERS_MACRO_ONLY

extern void main_task(intptr_t exinf);
extern void balance_task(intptr_t exinf);
extern void logger_task(intptr_t exinf);
extern void balance_cyc(intptr_t exinf);
extern void logger_cyc(intptr_t exinf);

#endif /* TOPPERS_MACRO_ONLY */

#ifdef __cplusplus
}
#endif
