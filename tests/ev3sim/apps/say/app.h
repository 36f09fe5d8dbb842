/*
 * app.h — say: an EV3RT app that logs one line, SAY_WHAT; make
 * ev3sim-app-path-check copies it under awkward paths and edits this line.
 */
#include "ev3api.h"
#include "target_test.h"

#define SAY_WHAT "original"

#define MAIN_PRIORITY (TMIN_APP_TPRI + 1)
#define STACK_SIZE 4096

#ifndef TOPPERS_MACRO_ONLY
extern void main_task(intptr_t exinf);
#endif
