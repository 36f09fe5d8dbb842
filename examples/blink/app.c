/*
 * app.c — blink: periodic work in EV3 cyclic handlers, driven by buttons.
 *
 * BLINK_CYC (started at boot, TA_STA) toggles the LEDs every 250 ms; it runs
 * in task context, so it may call ev3_led_set_color and even sleep.
 * REPORT_CYC, started by the main task, logs the count every second.  Click
 * ENTER to pause or resume the blinking, BACK to end: the main task stops
 * both handlers and logs the totals.
 */
#include "ev3api.h"
#include "app.h"

static volatile int ticks;          /* blink periods run */
static volatile int enter_clicks;
static volatile bool_t paused;
static volatile bool_t in_task_context = true;

void blink_cyc(intptr_t exinf)
{
	if (sns_ctx())
		in_task_context = false;
	ev3_led_set_color(ticks % 2 ? LED_OFF : LED_GREEN);
	ticks++;
	tslp_tsk(1);    /* only a task may wait */
}

void report_cyc(intptr_t exinf)
{
	syslog(LOG_NOTICE, "blink: %d ticks%s", ticks, paused ? " (paused)" : "");
}

static void on_enter(intptr_t exinf)
{
	enter_clicks++;
	paused = !paused;
	if (paused)
		ev3_stp_cyc(BLINK_CYC);
	else
		ev3_sta_cyc(BLINK_CYC);
}

static void on_back(intptr_t exinf)
{
	wup_tsk((ID)exinf);
}

void main_task(intptr_t exinf)
{
	ev3_button_set_on_clicked(ENTER_BUTTON, on_enter, 0);
	ev3_button_set_on_clicked(BACK_BUTTON, on_back, MAIN_TASK);
	ev3_sta_cyc(REPORT_CYC);

	slp_tsk();
	ev3_stp_cyc(BLINK_CYC);
	ev3_stp_cyc(REPORT_CYC);
	ev3_led_set_color(LED_OFF);
	syslog(LOG_NOTICE, "blink: done, %d ticks, %d enter clicks, %s", ticks, enter_clicks,
	       in_task_context ? "handlers in task context" : "a handler ran in interrupt context");
}
