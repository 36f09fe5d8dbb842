/*
 * test_touch_api.c — the touch sensor through the API: the EV3 touch sensor
 * model's pin 6 -> d_analog's 1 ms sampling -> ANALOG shared memory -> ev3api;
 * another device on the port is E_OBJ, an empty port reads as not pressed.
 */
#include "api_test.h"

static bool global_flag;       /* outside the application's domain */

static void attach_touch(void)
{
	ev3_attach_analog(0, EV3_INPUT_EV3_TOUCH, NULL);
	ev3_attach_uart_sensor(2, UART_SENSOR_TYPE_GYRO, NULL);
}

static void touch_body(void)
{
	bool pressed = true;

	is_int(ev3lx_sensor_config(EV3_PORT_1, TOUCH_SENSOR), E_OK, "config touch on port 1");
	dly_tsk(10);
	is_int(ev3lx_touch_sensor_is_pressed(EV3_PORT_1, &pressed), E_OK, "is_pressed");
	ok(!pressed, "released");
	ev3_set_touch(0, true);
	dly_tsk(10);
	ev3lx_touch_sensor_is_pressed(EV3_PORT_1, &pressed);
	ok(pressed, "pressed");
	ev3_set_touch(0, false);
	dly_tsk(10);
	ev3lx_touch_sensor_is_pressed(EV3_PORT_1, &pressed);
	ok(!pressed, "released again");
	is_int(ev3lx_touch_sensor_is_pressed(EV3_PORT_2, &pressed), E_OBJ, "unconfigured port: E_OBJ");
	is_int(ev3lx_touch_sensor_is_pressed(EV3_PORT_1, &global_flag), E_MACV,
	       "outside the domain: E_MACV");

	dly_tsk(2500);		/* d_analog's detection starts 2 s after loading */
	is_int(ev3lx_sensor_config(EV3_PORT_3, TOUCH_SENSOR), E_OK, "touch configured on port 3 ...");
	is_int(ev3lx_touch_sensor_is_pressed(EV3_PORT_3, &pressed), E_OBJ, "... where a gyro answers: E_OBJ");
	is_int(ev3lx_sensor_config(EV3_PORT_4, TOUCH_SENSOR), E_OK, "touch configured on empty port 4");
	pressed = true;
	ok(ev3lx_touch_sensor_is_pressed(EV3_PORT_4, &pressed) == E_OK && !pressed,
	   "nothing plugged in: not pressed (an open switch)");

	ev3_set_touch(0, true);
	dly_tsk(10);
	ok(ev3lx_touch_sensor_is_pressed(EV3_PORT_1, &pressed) == E_OK && pressed, "held pressed ...");
	ev3_detach_input(0);
	dly_tsk(1000);
	ok(ev3lx_touch_sensor_is_pressed(EV3_PORT_1, &pressed) == E_OK && !pressed,
	   "... and unplugged: not pressed, no frozen value");
}

int main(void)
{
	tap_plan(14);
	ok(at_run(attach_touch, touch_body, 4, 10), "the touch application finished");
	return tap_done();
}
