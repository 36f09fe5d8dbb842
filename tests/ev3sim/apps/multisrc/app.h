/*
 * app.h — multisrc: an EV3RT app whose Makefile.inc adds a source from
 * another directory (make ev3sim-run-check builds and runs it).
 */
#include "ev3api.h"

#define MAIN_PRIORITY (TMIN_APP_TPRI + 1)
#ifndef STACK_SIZE
#define STACK_SIZE 4096
#endif

#ifndef TOPPERS_MACRO_ONLY
extern void main_task(intptr_t exinf);
#endif
