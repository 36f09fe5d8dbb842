/* The bad configurations' header, in EV3RT's idiom. */
#include "kernel.h"
#include "rtos_cfg.h"

#define MAIN_PRIORITY (TMIN_APP_TPRI + 1)

#ifndef TOPPERS_MACRO_ONLY
extern void main_task(intptr_t exinf);
extern void handler(intptr_t exinf);
#endif
