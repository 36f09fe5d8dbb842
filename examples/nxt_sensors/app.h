/*
 * app.h — nxt_sensors: IDs, priorities and stack sizes (read by app.cfg and app.c).
 */
#ifdef __cplusplus
extern "C" {
#endif

#include "ev3api.h"
#include "target_test.h"

#define MAIN_PRIORITY   (TMIN_APP_TPRI + 1)

#ifndef STACK_SIZE
#define STACK_SIZE      4096
#endif

#define ACCEL_PORT      EV3_PORT_1
#define COLOR_PORT      EV3_PORT_2
#define TEMP_PORT       EV3_PORT_3
#define PERIOD_MS       100     /* between two rounds of readings */
#define ROUNDS          20

#ifndef TOPPERS_MACRO_ONLY

extern void main_task(intptr_t exinf);

#endif /* TOPPERS_MACRO_ONLY */

#ifdef __cplusplus
}
#endif
