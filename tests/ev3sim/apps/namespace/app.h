/*
 * app.h — namespace: an EV3RT app whose global names are ones ev3lx's kernel,
 * drivers and simulator use inside (and a main of its own, which EV3RT apps
 * may have): an app's names are its own.
 */
#ifdef __cplusplus
extern "C" {
#endif

#include "ev3api.h"
#include "target_test.h"

#define MAIN_PRIORITY  (TMIN_APP_TPRI + 1)

#ifndef TOPPERS_MACRO_ONLY
extern void main_task(intptr_t exinf);
#endif

#ifdef __cplusplus
}
#endif
