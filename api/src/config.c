/*
 * config.c — ev3api_cfg: what an application using the API INCLUDEs.
 */
#include "ev3api_brick.h"
#include "ev3api_routines.h"
#include "ev3_drivers_cfg.h"
#include "api_internal.h"

/* ATT_INI: the API's state starts empty at every boot. */
void api_boot(intptr_t exinf)
{
	(void)exinf;
	api_motor_boot();
	api_sensor_boot();
	api_brick_boot();
	api_battery_boot();
	api_speaker_boot();
	api_lcd_boot();
	api_serial_boot();
	api_app_heap_boot();
}

static const struct rtos_ini_cfg api_inis[] = { { api_boot, 0 } };

/* The button task runs click handlers (ev3lx_button_set_on_clicked) in task
 * context; the LCD task starts the panel at boot; the app-init task runs the
 * app's C++ global constructors. */
static const struct rtos_task_cfg api_tasks[] = {
	{ EV3_BUTTON_TSKID, TA_ACT, 0, api_button_task, EV3_BUTTON_TASK_PRIORITY,
	  EV3_BUTTON_TASK_STACK, EV3_BUTTON_TASK_DOMAIN, "ev3api buttons" },
	{ EV3_LCD_TSKID, TA_ACT, 0, api_lcd_task, EV3_BUTTON_TASK_PRIORITY,
	  EV3_LCD_TASK_STACK, EV3_BUTTON_TASK_DOMAIN, "ev3api LCD start" },
	{ EV3_APP_INIT_TSKID, TA_ACT, 0, api_app_init_task, EV3_BUTTON_TASK_PRIORITY,
	  EV3_APP_INIT_TASK_STACK, EV3_BUTTON_TASK_DOMAIN, "ev3api app init" },
};

/* Guards the click-handler table (handler and exinf change together). */
static const struct rtos_sem_cfg api_sems[] = {
	{ EV3_BUTTON_SEMID, TA_TPRI, 1, 1, "ev3api click handlers" },
};

/* The frame of the LCD calls: an application task of any user domain draws into it. */
#define LCD_FRAME_ROW(dom) \
	{ (dom), api_lcd_frame, sizeof(api_lcd_frame), TPM_READ | TPM_WRITE, "ev3api LCD frame" }

/* The apps' heap: every user domain's, as EV3RT's app heap is the app's. */
#define APP_HEAP_ROW(dom) \
	{ (dom), api_app_heap, sizeof(api_app_heap), TPM_READ | TPM_WRITE, "ev3api app heap" }

static const struct rtos_mem_cfg api_mems[] = {
	LCD_FRAME_ROW(1), APP_HEAP_ROW(1),
#if TNUM_DOMID >= 2
	LCD_FRAME_ROW(2), APP_HEAP_ROW(2),
#endif
#if TNUM_DOMID >= 3
	LCD_FRAME_ROW(3), APP_HEAP_ROW(3),
#endif
#if TNUM_DOMID >= 4
	LCD_FRAME_ROW(4), APP_HEAP_ROW(4),
#endif
};
_Static_assert(TNUM_DOMID >= 1 && TNUM_DOMID <= 4, "one LCD frame row and one heap row per user domain (1..4)");

static const struct rtos_cfg *const api_includes[] = { &ev3_drivers_cfg, NULL };

const struct rtos_cfg ev3api_cfg = {
	.name = "ev3api_cfg",
	.tasks = RTOS_TABLE(api_tasks),
	.sems = RTOS_TABLE(api_sems),
	.mems = RTOS_TABLE(api_mems),
	.inis = RTOS_TABLE(api_inis),
	.includes = api_includes,
};
