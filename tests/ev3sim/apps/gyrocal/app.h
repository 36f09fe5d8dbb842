/*
 * app.h — gyrocal: the gyro calibration of LEGO's Gyro Boy as EV3RT apps
 * write it (read by app.cfg and app.c).
 */
#ifdef __cplusplus
extern "C" {
#endif

#include "ev3api.h"
#include "target_test.h"

#define MAIN_PRIORITY (TMIN_APP_TPRI + 1)

#ifndef STACK_SIZE
#define STACK_SIZE 4096
#endif

#define CALIBRATIONS  5
#define SAMPLES       200   /* per calibration, 4 ms apart */

#ifndef TOPPERS_MACRO_ONLY

extern void main_task(intptr_t exinf);

#endif /* TOPPERS_MACRO_ONLY */

#ifdef __cplusplus
}
#endif
