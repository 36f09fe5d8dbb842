/*
 * app.h — usleep: an EV3RT 1.x app whose app.cfg names no time event.
 */
#ifdef __cplusplus
extern "C" {
#endif

#include "ev3api.h"
#include "target_test.h"

#define MAIN_PRIORITY (TMIN_APP_TPRI + 1)

#ifndef TOPPERS_MACRO_ONLY
extern void main_task(intptr_t exinf);
#endif

#ifdef __cplusplus
}
#endif
