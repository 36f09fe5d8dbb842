/*
 * test_sensor_api.c — the sensor API end to end with host_sim's sensors: a
 * colour sensor on port 1, a gyro on 2, an ultrasonic on 3, an IR on 4;
 * values flow from the models' scenes through d_uart /
 * d_analog to the application.  Unplugging never blocks a call for good.
 */
#include "api_test.h"

static const struct uart_sensor_scene color_scene = {
	.reflect_pct = 37, .ambient_pct = 12, .color = 5, .rgb = { 300, 200, 100 },
};
static const struct uart_sensor_scene gyro_scene = { .rate_dps = 90.0 };
static const struct uart_sensor_scene us_scene = { .distance_mm = 500 };
static const struct uart_sensor_scene ir_scene = { .distance_mm = 350 };
static uint8_t global_byte;     /* outside the application's domain */

static void attach_uart_sensors(void)
{
	ev3_attach_uart_sensor(0, 29, NULL);
	ev3_attach_uart_sensor(1, 32, NULL);
	ev3_attach_uart_sensor(2, 30, NULL);
	ev3_attach_uart_sensor(3, 33, NULL);
	ev3_set_scene(0, &color_scene);
	ev3_set_scene(1, &gyro_scene);
	ev3_set_scene(2, &us_scene);
	ev3_set_scene(3, &ir_scene);
}

static void uart_body(void)
{
	uint8_t pct = 0;
	colorid_t color = COLOR_NONE;
	rgb_raw_t rgb = { 0, 0, 0 };
	int16_t rate = 0, angle = 0, cm = 0;
	int8_t prox = 0;
	int8_t raw[4] = { 0 };
	sensor_type_t type = NONE_SENSOR;
	uint64_t t0;

	is_int(ev3lx_sensor_config(EV3_PORT_1, COLOR_SENSOR), E_OK, "config colour on port 1");
	is_int(ev3lx_sensor_config(EV3_PORT_2, GYRO_SENSOR), E_OK, "config gyro on port 2");
	is_int(ev3lx_sensor_config(EV3_PORT_3, ULTRASONIC_SENSOR), E_OK, "config ultrasonic on port 3");
	is_int(ev3lx_sensor_config(EV3_PORT_4, INFRARED_SENSOR), E_OK, "config IR on port 4");
	is_int(ev3lx_sensor_config(TNUM_SENSOR_PORT, GYRO_SENSOR), E_ID, "config bad port: E_ID");
	is_int(ev3lx_sensor_config(EV3_PORT_1, (sensor_type_t)42), E_PAR, "config bad type: E_PAR");
	is_int(ev3lx_sensor_get_type(EV3_PORT_2, &type), E_OK, "get_type");
	is_int(type, GYRO_SENSOR, "port 2 is a gyro");

	/* first reads wait for the handshakes, then values flow */
	t0 = at_now_ms();
	is_int(ev3lx_color_sensor_get_reflect(EV3_PORT_1, &pct), E_OK, "reflect (waits for the handshake)");
	ok(at_now_ms() - t0 < 4000, "first value within the start timeout (%llu ms)",
	   (unsigned long long)(at_now_ms() - t0));
	is_int(pct, 37, "reflected light from the surface");
	is_int(ev3lx_color_sensor_get_color(EV3_PORT_1, &color), E_OK, "color");
	is_int(color, COLOR_RED, "the surface is red");
	is_int(ev3lx_color_sensor_get_ambient(EV3_PORT_1, &pct), E_OK, "ambient");
	is_int(pct, 12, "ambient light");
	is_int(ev3lx_color_sensor_get_rgb_raw(EV3_PORT_1, &rgb), E_OK, "rgb_raw");
	ok(rgb.r == 300 && rgb.g == 200 && rgb.b == 100, "raw RGB %u/%u/%u", rgb.r, rgb.g, rgb.b);

	is_int(ev3lx_gyro_sensor_get_rate(EV3_PORT_2, &rate), E_OK, "gyro rate");
	in_range(rate, 88, 92, "rate follows the body's rotation");
	is_int(ev3lx_gyro_sensor_reset(EV3_PORT_2), E_OK, "gyro reset");
	is_int(ev3lx_gyro_sensor_get_angle(EV3_PORT_2, &angle), E_OK, "gyro angle");
	in_range(angle, -2, 10, "angle restarts near 0 after reset (%d)", angle);
	dly_tsk(1000);
	ev3lx_gyro_sensor_get_angle(EV3_PORT_2, &angle);
	in_range(angle, 80, 100, "a second at 90 deg/s later the angle is about 90 (%d)", angle);

	is_int(ev3lx_ultrasonic_sensor_get_distance(EV3_PORT_3, &cm), E_OK, "ultrasonic distance");
	is_int(cm, 50, "500 mm is 50 cm");
	is_int(ev3lx_infrared_sensor_get_distance(EV3_PORT_4, &prox), E_OK, "IR proximity");
	ok(prox > 0 && prox < 100, "IR proximity in range (%d)", prox);

	is_int(ev3lx_uart_sensor_get_raw(EV3_PORT_3, raw, 2), E_OK, "get_raw of the ultrasonic");
	is_int((uint8_t)raw[0] | (uint8_t)raw[1] << 8, 500, "raw is the distance in tenths of a cm (US-DIST-CM)");
	is_int(ev3lx_uart_sensor_get_raw(EV3_PORT_3, raw, 0), E_PAR, "get_raw of 0 bytes: E_PAR");
	is_int(ev3lx_uart_sensor_get_raw(EV3_PORT_3, raw, 33), E_PAR, "get_raw of 33 bytes: E_PAR");
	is_int(ev3lx_uart_sensor_get_raw(EV3_PORT_3, NULL, 2), E_MACV, "get_raw into NULL: E_MACV");
	is_int(ev3lx_color_sensor_get_reflect(EV3_PORT_1, &global_byte), E_MACV,
	       "reflect into memory outside the domain: E_MACV");
	is_int(ev3lx_gyro_sensor_get_rate(EV3_PORT_1, &rate), E_OBJ, "gyro read on the colour port: E_OBJ");
	is_int(ev3lx_touch_sensor_is_pressed(EV3_PORT_1, NULL), E_OBJ, "touch read on a UART port: E_OBJ");

	/* a sensor of another type answers: E_OBJ, not a wrong value */
	is_int(ev3lx_sensor_config(EV3_PORT_3, GYRO_SENSOR), E_OK, "port 3 declared a gyro (it is not)");
	is_int(ev3lx_gyro_sensor_get_rate(EV3_PORT_3, &rate), E_OBJ, "the ultrasonic's data is refused: E_OBJ");

	/* unplugged: bounded wait, then E_TMOUT */
	ev3_detach_input(1);
	dly_tsk(300);
	t0 = at_now_ms();
	ER ercd = E_OK;
	for (int i = 0; i < 50 && ercd == E_OK; i++) {
		ercd = ev3lx_gyro_sensor_get_rate(EV3_PORT_2, &rate);
		dly_tsk(20);
	}
	is_int(ercd, E_TMOUT, "an unplugged gyro times out");
	ok(at_now_ms() - t0 < 6000, "without blocking for long (%llu ms)",
	   (unsigned long long)(at_now_ms() - t0));
}

int main(void)
{
	tap_plan(40);
	ok(at_run(attach_uart_sensors, uart_body, 3, 60), "the UART sensor application finished");
	return tap_done();
}
