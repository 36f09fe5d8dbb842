/*
 * app.h — live: an EV3RT app that waits for ENTER, then says so on the
 * display and drives the driving base forward (tests/ev3sim/test_app_live.c
 * clicks ENTER in a browser on `ev3sim run --live`'s page).
 */
#include "ev3api.h"
#include "target_test.h"

#define MAIN_PRIORITY (TMIN_APP_TPRI + 1)
#define STACK_SIZE 4096

#ifndef TOPPERS_MACRO_ONLY
extern void main_task(intptr_t exinf);
#endif
