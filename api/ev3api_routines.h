/*
 * ev3api_routines.h — what the library's static-API fragment (cfg/ev3lx.cfg) names
 * from the EV3 API: its tasks' settings and bodies and its initialisation
 * routine; and, outside a configurator's pass, the IDs the configurator gave
 * the API's objects (kernel_cfg.h: a firmware's, or on the host the library's
 * own, written by ev3cfg --library from the fragment).
 */
#ifndef EV3API_ROUTINES_H
#define EV3API_ROUTINES_H

#include "kernel.h"
#include "ev3api_brick.h"

#ifndef TOPPERS_CFG1_OUT
#include <kernel_cfg.h>
#endif

#ifndef TOPPERS_MACRO_ONLY
/* ATT_INI: the API's state starts empty at every boot. */
void api_boot(intptr_t exinf);
/* The button task's body: runs click handlers. */
void api_button_task(intptr_t exinf);
/* The LCD task's body: starts the panel at boot. */
void api_lcd_task(intptr_t exinf);
/* The app-init task's body: runs the app's C++ global constructors. */
void api_app_init_task(intptr_t exinf);
#endif

#endif /* EV3API_ROUTINES_H */
