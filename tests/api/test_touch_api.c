/*
 * test_touch_api.c — the touch sensor through the API: the EV3 touch sensor
 * model's pin 6 -> d_analog's 1 ms sampling -> ANALOG shared memory -> ev3api.
 */
#include "api_test.h"

static bool global_flag;       /* outside the application's domain */

static void attach_touch(void)
{
	ev3_attach_analog(0, EV3_INPUT_EV3_TOUCH, NULL);
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
}

int main(void)
{
	tap_plan(8);
	ok(at_run(attach_touch, touch_body, 4, 10), "the touch application finished");
	return tap_done();
}
