/*
 * ev3api_brick.h — the brick's buttons and LEDs (included by ev3api.h):
 * EV3RT's calls and ev3lx's checked forms (the naming rule is in ev3api.h).
 */
#ifndef EV3API_BRICK_H
#define EV3API_BRICK_H

#ifdef __cplusplus
extern "C" {
#endif

#include <stdbool.h>
#include <stdint.h>
#include "kernel.h"

typedef enum {
	LED_OFF = 0, LED_RED = 1, LED_GREEN = 2, LED_ORANGE = 3,
	TNUM_LED_COLOR = 4
} ledcolor_t;

typedef enum {
	LEFT_BUTTON = 0, RIGHT_BUTTON = 1, UP_BUTTON = 2, DOWN_BUTTON = 3,
	ENTER_BUTTON = 4, BACK_BUTTON = 5,
	TNUM_BUTTON = 6
} button_t;

/* ---- EV3RT ---- */

ER ev3_led_set_color(ledcolor_t color);
/* Whether the button is held down now (false and a warning on a bad button). */
bool_t ev3_button_is_pressed(button_t button);
/* handler(exinf) runs in task context each time the button is clicked
 * (released after a press); NULL removes it. */
ER ev3_button_set_on_clicked(button_t button, ISR handler, intptr_t exinf);

/* ---- ev3lx's checked forms ---- */

/* Both brick LEDs.  E_PAR, E_CTX. */
ER ev3lx_led_set_color(ledcolor_t color);
/* Whether the button is held down now (debounced).  E_ID, E_MACV. */
ER ev3lx_button_is_pressed(button_t button, bool *p_pressed);
/* Calls handler(exinf) in the button task (not in the GPIO interrupt) each
 * time the button is released after a press; NULL removes it.  E_ID, E_CTX. */
ER ev3lx_button_set_on_clicked(button_t button, ISR handler, intptr_t exinf);

/*
 * The button task that runs click handlers, and the semaphore guarding the
 * handler table (EV3_BUTTON_TSKID, EV3_BUTTON_SEMID: their IDs are the
 * configurator's, declared in cfg/ev3lx.cfg, see ev3api_cfg.h).  The task
 * runs in user domain EV3_BUTTON_TASK_DOMAIN (the application's by
 * convention), so handlers have that domain's rights.
 * rel_wai(EV3_BUTTON_TSKID) stops it cleanly; act_tsk starts it again.
 * The settings may be overridden at build time (-D).
 */
#ifndef EV3_BUTTON_TASK_PRIORITY
#define EV3_BUTTON_TASK_PRIORITY  5
#endif
#ifndef EV3_BUTTON_TASK_DOMAIN
#define EV3_BUTTON_TASK_DOMAIN    1
#endif
#ifndef EV3_BUTTON_TASK_STACK
#define EV3_BUTTON_TASK_STACK     (16 * 1024)
#endif

/*
 * The LCD task (EV3_LCD_TSKID), which starts the panel at boot (as EV3RT's
 * platform does before the app runs) and ends: at the button task's priority
 * and domain.
 */
#ifndef EV3_LCD_TASK_STACK
#define EV3_LCD_TASK_STACK        (8 * 1024)
#endif

/*
 * The app-init task (EV3_APP_INIT_TSKID), which runs the app's C++ global constructors at boot
 * once the platform is up, as EV3RT's app-init task does, holding the app's
 * tasks (priorities TMIN_APP_TPRI and lower) until they return: at the
 * button task's priority and domain.
 */
#ifndef EV3_APP_INIT_TASK_STACK
#define EV3_APP_INIT_TASK_STACK   (16 * 1024)
#endif

#ifdef __cplusplus
}
#endif

#endif /* EV3API_BRICK_H */
