/*
 * ev3rt_brick.c — EV3RT's button, LED and EV3 cyclic handler calls
 * (ev3api_brick.h, ev3api_cyc.h) as thin wrappers over the checked forms.
 */
#include "ev3api_brick.h"
#include "ev3api_cyc.h"
#include "api_internal.h"

ER ev3_led_set_color(ledcolor_t color)
{
	return ev3lx_led_set_color(color);
}

bool_t ev3_button_is_pressed(button_t button)
{
	bool pressed = false;
	ER ercd = ev3lx_button_is_pressed(button, &pressed);

	if (ercd != E_OK) {
		api_warn(__func__, (int)button, ercd);
		return false;
	}
	return pressed;
}

ER ev3_button_set_on_clicked(button_t button, ISR handler, intptr_t exinf)
{
	return ev3lx_button_set_on_clicked(button, handler, exinf);
}

ER ev3_sta_cyc(ID ev3cycid)
{
	return sta_cyc(ev3cycid);
}

ER ev3_stp_cyc(ID ev3cycid)
{
	return stp_cyc(ev3cycid);
}
