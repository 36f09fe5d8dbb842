/*
 * app.c — live: shows "Press ENTER" with the LEDs orange, waits for the
 * ENTER button, then shows "Driving", turns the LEDs green and drives the
 * tribot's wheels (B and C) forward at 40 % power.
 */
#include "ev3api.h"
#include "app.h"

void main_task(intptr_t exinf)
{
	ev3_motor_config(EV3_PORT_B, LARGE_MOTOR);
	ev3_motor_config(EV3_PORT_C, LARGE_MOTOR);
	ev3_lcd_set_font(EV3_FONT_MEDIUM);
	ev3_lcd_draw_string("Press ENTER", 10, 40);
	ev3_led_set_color(LED_ORANGE);
	syslog(LOG_NOTICE, "live: waiting for ENTER");
	while (!ev3_button_is_pressed(ENTER_BUTTON))
		tslp_tsk(10);
	syslog(LOG_NOTICE, "live: ENTER");
	ev3_lcd_fill_rect(0, 0, EV3_LCD_WIDTH, EV3_LCD_HEIGHT, EV3_LCD_WHITE);
	ev3_lcd_draw_string("Driving", 10, 40);
	ev3_led_set_color(LED_GREEN);
	ev3_motor_set_power(EV3_PORT_B, 40);
	ev3_motor_set_power(EV3_PORT_C, 40);
}
