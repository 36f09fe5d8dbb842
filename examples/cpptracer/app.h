/*
 * app.h — cpptracer: its tasks' priorities, the tracing period and the
 * entry points app.cfg names (C linkage, as EV3RT's configurator's tables
 * call them).
 */
#ifdef __cplusplus
extern "C" {
#endif

#include "ev3api.h"
#include "target_test.h"

#define MAIN_PRIORITY    (TMIN_APP_TPRI + 1)
#define TRACER_PRIORITY  TMIN_APP_TPRI

#ifndef STACK_SIZE
#define STACK_SIZE       4096
#endif

/* The tracer's period, ms (EV3RT's HRP2 kernel: the tick is 1 ms). */
#define TRACER_PERIOD_MS 4

#ifndef TOPPERS_MACRO_ONLY

extern void main_task(intptr_t exinf);
extern void tracer_task(intptr_t exinf);
extern void tracer_cyc(intptr_t exinf);

#endif /* TOPPERS_MACRO_ONLY */

#ifdef __cplusplus
}
#endif
