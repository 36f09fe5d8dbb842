/*
 * test_params.c — d_ui's module parameters, set before the module loads:
 * debounce_ms (a longer window filters longer glitches), the button pins
 * (UP and DOWN swapped) and leds_active_low (every LED pin inverted).
 */
#include <linux/moduleparam.h>
#include "ui_test.h"
#include <linux_compat/modparam.h>

static ER param_ercd[4];

/* Before any task runs, as a module's command line would. */
static void set_params(void)
{
	param_ercd[0] = lx_module_param_set("d_ui", "debounce_ms", "50");
	param_ercd[1] = lx_module_param_set("d_ui", "up_gpio", "126");		/* GP7_14 */
	param_ercd[2] = lx_module_param_set("d_ui", "down_gpio", "127");	/* GP7_15 */
	param_ercd[3] = lx_module_param_set("d_ui", "leds_active_low", "1");
}

static void body(void)
{
	struct lms_ui_click c;

	ok(param_ercd[0] == E_OK && param_ercd[1] == E_OK && param_ercd[2] == E_OK &&
	   param_ercd[3] == E_OK, "parameters accepted before the load");
	ok(ev3_ui_led_color(EV3_UI_LED_LEFT) == EV3_UI_LED_ORANGE &&
	   ev3_ui_led_color(EV3_UI_LED_RIGHT) == EV3_UI_LED_ORANGE,
	   "leds_active_low: 'off' drives every LED pin high");
	ui_svc_led(LMS_UI_LED_GREEN);
	ok(ev3_ui_led_color(EV3_UI_LED_LEFT) == EV3_UI_LED_RED, "and 'green' drives only green low");

	ev3_ui_click_at(rtos_host_now() + UIT_MS, EV3_UI_BUTTON_ENTER, 40 * UIT_MS);
	dly_tsk(150);
	ok(ui_svc_wait_click(&c, TMO_POL) == E_TMOUT && uit_shm->presses[LMS_UI_BUTTON_ENTER] == 0,
	   "debounce_ms 50: a 40 ms press is filtered");
	ev3_ui_click_at(rtos_host_now() + UIT_MS, EV3_UI_BUTTON_ENTER, 60 * UIT_MS);
	dly_tsk(150);
	ok(ui_svc_wait_click(&c, TMO_POL) == E_OK && c.button == LMS_UI_BUTTON_ENTER,
	   "a 60 ms press is a click");

	ev3_ui_click_at(rtos_host_now() + UIT_MS, EV3_UI_BUTTON_UP, 80 * UIT_MS);
	dly_tsk(150);
	ok(ui_svc_wait_click(&c, TMO_POL) == E_OK && c.button == LMS_UI_BUTTON_DOWN,
	   "pins swapped: the UP contact (GP7_15) is d_ui's DOWN");
}

int main(void)
{
	tap_plan(7);
	uit_at_power_on = set_params;
	ok(uit_run(body, 6), "scenario ran to its end");
	return tap_done();
}
