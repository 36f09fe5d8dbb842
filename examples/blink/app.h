/*
 * app.h — blink: IDs, priorities and stack sizes (read by app.cfg and app.c).
 */
#ifdef __cplusplus
extern "C" {
#endif

#include "ev3api.h"
#include "target_test.h"

#define MAIN_PRIORITY     (TMIN_APP_TPRI + 1)

#ifndef STACK_SIZE
#define STACK_SIZE        4096
#endif

#define BLINK_PERIOD_MS   250
#define REPORT_PERIOD_MS  1000

#ifndef TOPPERS_MACRO_ONLY

extern void main_task(intptr_t exinf);
extern void blink_cyc(intptr_t exinf);
extern void report_cyc(intptr_t exinf);

#endif /* TOPPERS_MACRO_ONLY */

#ifdef __cplusplus
}
#endif
