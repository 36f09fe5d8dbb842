/*
 * app.h — misbehave: an EV3RT app whose main task misbehaves as the
 * environment's EV3LX_MISBEHAVE asks (stall, null, divide, abort, recurse,
 * big-locals), so that tests can check ev3sim's reports and exit statuses.
 */
#include "ev3api.h"
#include "target_test.h"

#define MAIN_PRIORITY (TMIN_APP_TPRI + 1)
#ifndef STACK_SIZE
#define STACK_SIZE 4096
#endif

#ifndef TOPPERS_MACRO_ONLY
extern void main_task(intptr_t exinf);
#endif
