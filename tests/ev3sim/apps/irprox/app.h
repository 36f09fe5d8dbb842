/*
 * app.h — irprox: IDs, priorities and stack sizes (read by app.cfg and app.c).
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

#ifndef TOPPERS_MACRO_ONLY

extern void main_task(intptr_t exinf);

#endif /* TOPPERS_MACRO_ONLY */

#ifdef __cplusplus
}
#endif
