/*
 * test_nxt_sensor_api.c — EV3RT's NXT I2C sensor calls through the whole
 * stack (api, iic_hack, d_iic, the bit-banged bus, host_sim's slaves), from
 * an application task in user domain 1: a HiTechnic accelerometer, colour
 * sensors v1 and V2 and the NXT temperature sensor configured and read,
 * values following the scene, the first reading waiting for the probe, a
 * sensor of another kind refused (E_OBJ / false), argument errors with
 * TOPPERS codes, and the port given back when configured to another type.
 */
#include "api_test.h"
#include "host_sim/devices/nxt_iic.h"
#include "iic_hack.h"

static void attach(void)
{
	ev3_attach_nxt_iic(0, NXT_IIC_HT_ACCEL, &(struct nxt_iic_scene){ .accel = { 200, -3, -512 } });
	ev3_attach_nxt_iic(1, NXT_IIC_HT_COLOR_V2, &(struct nxt_iic_scene){ .color_number = 6, .rgb = { 250, 200, 10 } });
	ev3_attach_nxt_iic(2, NXT_IIC_TEMP, &(struct nxt_iic_scene){ .temp_c = 36.6 });
	ev3_attach_nxt_iic(3, NXT_IIC_HT_COLOR, &(struct nxt_iic_scene){ .color_number = 2, .rgb = { 5, 6, 7 } });
}

static void body(void)
{
	int16_t axes[3] = { 0, 0, 0 };
	uint8_t color = 0;
	rgb_raw_t rgb = { 0, 0, 0 };
	float temp = 0;
	uint64_t t0;

	is_int(ev3_sensor_config(EV3_PORT_1, HT_NXT_ACCEL_SENSOR), E_OK, "config HT accelerometer on 1");
	is_int(ev3_sensor_config(EV3_PORT_2, HT_NXT_COLOR_SENSOR), E_OK, "config HT colour (V2) on 2");
	is_int(ev3_sensor_config(EV3_PORT_3, NXT_TEMP_SENSOR), E_OK, "config NXT temperature on 3");
	is_int(ev3_sensor_config(EV3_PORT_4, HT_NXT_COLOR_SENSOR), E_OK, "config HT colour (v1) on 4");
	is_int(ev3_sensor_get_type(EV3_PORT_3), NXT_TEMP_SENSOR, "get_type");

	t0 = at_now_ms();
	ok(ht_nxt_accel_sensor_measure(EV3_PORT_1, axes), "accelerometer measured");
	in_range(at_now_ms() - t0, 10, 200, "the first reading waited for the probe and a poll");
	ok(axes[0] == 200 && axes[1] == -3 && axes[2] == -512, "axes 200, -3, -512 (%d %d %d)",
	   axes[0], axes[1], axes[2]);
	ok(ht_nxt_color_sensor_measure_color(EV3_PORT_2, &color) && color == 6, "colour number 6 (V2)");
	ok(ht_nxt_color_sensor_measure_rgb(EV3_PORT_2, &rgb) && rgb.r == 250 && rgb.g == 200 && rgb.b == 10,
	   "RGB 250, 200, 10 (V2)");
	ok(ht_nxt_color_sensor_measure_color(EV3_PORT_4, &color) && color == 2, "colour number 2 (v1)");
	ok(ht_nxt_color_sensor_measure_rgb(EV3_PORT_4, &rgb) && rgb.r == 5 && rgb.g == 6 && rgb.b == 7,
	   "RGB 5, 6, 7 (v1)");
	ok(nxt_temp_sensor_measure(EV3_PORT_3, &temp), "temperature measured");
	ok(temp > 36.55f && temp < 36.65f, "36.5625 C at 12 bits (%.4f)", (double)temp);

	t0 = at_now_ms();
	ok(ht_nxt_accel_sensor_measure(EV3_PORT_1, axes), "a second reading");
	is_int(at_now_ms() - t0, 0, "from the shared memory, without waiting");

	ev3_set_nxt_iic_scene(0, &(struct nxt_iic_scene){ .accel = { -1, 1, 100 } });
	dly_tsk(50);
	ok(ht_nxt_accel_sensor_measure(EV3_PORT_1, axes) && axes[0] == -1 && axes[1] == 1 && axes[2] == 100,
	   "new acceleration within 50 ms");
	ev3_set_nxt_iic_scene(2, &(struct nxt_iic_scene){ .temp_c = -20.0 });
	dly_tsk(300);
	ok(nxt_temp_sensor_measure(EV3_PORT_3, &temp) && temp == -20.0f, "-20 C within 300 ms");

	/* unplugged: the driver withdraws the data, the reading times out; plugged in again: values */
	ev3_detach_input(2);
	dly_tsk(150);
	is_int(ev3lx_nxt_temp_sensor_measure(EV3_PORT_3, &temp), E_TMOUT, "unplugged: E_TMOUT, no stale value");
	ev3_attach_nxt_iic(2, NXT_IIC_TEMP, &(struct nxt_iic_scene){ .temp_c = 30.0625 });
	ok(nxt_temp_sensor_measure(EV3_PORT_3, &temp), "plugged in again: measured");
	dly_tsk(250);
	ok(nxt_temp_sensor_measure(EV3_PORT_3, &temp) && temp == 30.0625f,
	   "30.0625 C: the driver sent the 12-bit setup again (%.4f)", (double)temp);

	/* errors */
	is_int(ev3lx_ht_nxt_accel_sensor_measure(EV3_PORT_2, axes), E_OBJ, "accelerometer read on a colour port: E_OBJ");
	ok(!ht_nxt_accel_sensor_measure(EV3_PORT_2, axes), "EV3RT form: false");
	is_int(ev3lx_nxt_temp_sensor_measure((sensor_port_t)4, &temp), E_ID, "port 5: E_ID");
	is_int(ev3lx_ht_nxt_color_sensor_measure_rgb(EV3_PORT_2, NULL), E_MACV, "NULL: E_MACV");
	is_int(ev3lx_ht_nxt_accel_sensor_measure(EV3_PORT_1, (int16_t *)((uintptr_t)axes | 1U)), E_PAR,
	       "misaligned axes: E_PAR");
	is_int(ev3_sensor_config(EV3_PORT_1, NXT_TEMP_SENSOR), E_OK, "port 1 reconfigured as a temperature sensor");
	is_int(ev3lx_nxt_temp_sensor_measure(EV3_PORT_1, &temp), E_OBJ,
	       "the accelerometer does not answer as one: E_OBJ");
	is_int(ev3_sensor_config(EV3_PORT_1, TOUCH_SENSOR), E_OK, "port 1 as a touch sensor");
	dly_tsk(5);
	is_int(iic_svc_state(0), LMS_IIC_STATE_IDLE, "d_iic gave the port back");
	is_int(ev3lx_ht_nxt_accel_sensor_measure(EV3_PORT_1, axes), E_OBJ, "not an accelerometer any more: E_OBJ");

	/* a UART sensor's port becomes an I2C port and back: the TX buffer changes hands */
	ev3_attach_uart_sensor(0, UART_SENSOR_TYPE_GYRO, NULL);
	is_int(ev3_sensor_config(EV3_PORT_1, GYRO_SENSOR), E_OK, "port 1: a gyro");
	ok(ev3lx_gyro_sensor_get_angle(EV3_PORT_1, &axes[0]) == E_OK, "gyro read (handshake done)");
	ev3_attach_nxt_iic(0, NXT_IIC_HT_ACCEL, &(struct nxt_iic_scene){ .accel = { 1, 2, 3 } });
	is_int(ev3_sensor_config(EV3_PORT_1, HT_NXT_ACCEL_SENSOR), E_OK, "replaced by an accelerometer");
	ok(ht_nxt_accel_sensor_measure(EV3_PORT_1, axes) && axes[0] == 1 && axes[1] == 2 && axes[2] == 3,
	   "read through the TX buffer d_uart gave up");
	ev3_attach_uart_sensor(0, UART_SENSOR_TYPE_GYRO, NULL);
	is_int(ev3_sensor_config(EV3_PORT_1, GYRO_SENSOR), E_OK, "a gyro again");
	ok(ev3lx_gyro_sensor_get_angle(EV3_PORT_1, &axes[0]) == E_OK, "gyro read: d_iic left the buffer alone");
}

int main(void)
{
	tap_plan(38);
	ok(at_run(attach, body, 5, 20), "app finished");
	return tap_done();
}
