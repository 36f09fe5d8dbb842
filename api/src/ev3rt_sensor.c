/*
 * ev3rt_sensor.c — EV3RT's sensor calls (ev3api_sensor.h) as thin wrappers
 * over ev3lx's checked forms: values are returned; on a bad port or a sensor
 * of another type a warning is logged and 0 / false returned.
 */
#include <string.h>
#include "ev3api_motor.h"
#include "ev3api_sensor.h"
#include "api_internal.h"

ER ev3_sensor_config(sensor_port_t port, sensor_type_t type)
{
	return ev3lx_sensor_config(port, type);
}

ER_UINT ev3_sensor_get_type(sensor_port_t port)
{
	sensor_type_t type = NONE_SENSOR;
	ER ercd = ev3lx_sensor_get_type(port, &type);

	return ercd == E_OK ? (ER_UINT)type : ercd;
}

/* value when the checked read succeeded, else 0 after a warning naming the call. */
static int value_or_zero(const char *call, sensor_port_t port, ER ercd, int value)
{
	if (ercd != E_OK) {
		api_warn(call, (int)port, ercd);
		return 0;
	}
	return value;
}

colorid_t ev3_color_sensor_get_color(sensor_port_t port)
{
	colorid_t color = COLOR_NONE;
	ER ercd = ev3lx_color_sensor_get_color(port, &color);

	return (colorid_t)value_or_zero(__func__, port, ercd, (int)color);
}

uint8_t ev3_color_sensor_get_reflect(sensor_port_t port)
{
	uint8_t value = 0;
	ER ercd = ev3lx_color_sensor_get_reflect(port, &value);

	return (uint8_t)value_or_zero(__func__, port, ercd, value);
}

uint8_t ev3_color_sensor_get_ambient(sensor_port_t port)
{
	uint8_t value = 0;
	ER ercd = ev3lx_color_sensor_get_ambient(port, &value);

	return (uint8_t)value_or_zero(__func__, port, ercd, value);
}

void ev3_color_sensor_get_rgb_raw(sensor_port_t port, rgb_raw_t *val)
{
	ER ercd = ev3lx_color_sensor_get_rgb_raw(port, val);

	if (ercd != E_OK)
		api_warn(__func__, (int)port, ercd);
}

int16_t ev3_gyro_sensor_get_angle(sensor_port_t port)
{
	int16_t value = 0;
	ER ercd = ev3lx_gyro_sensor_get_angle(port, &value);

	return (int16_t)value_or_zero(__func__, port, ercd, value);
}

int16_t ev3_gyro_sensor_get_rate(sensor_port_t port)
{
	int16_t value = 0;
	ER ercd = ev3lx_gyro_sensor_get_rate(port, &value);

	return (int16_t)value_or_zero(__func__, port, ercd, value);
}

ER ev3_gyro_sensor_reset(sensor_port_t port)
{
	return ev3lx_gyro_sensor_reset(port);
}

int16_t ev3_ultrasonic_sensor_get_distance(sensor_port_t port)
{
	int16_t value = 0;
	ER ercd = ev3lx_ultrasonic_sensor_get_distance(port, &value);

	return (int16_t)value_or_zero(__func__, port, ercd, value);
}

bool_t ev3_ultrasonic_sensor_listen(sensor_port_t port)
{
	bool value = false;
	ER ercd = ev3lx_ultrasonic_sensor_listen(port, &value);

	return (bool_t)value_or_zero(__func__, port, ercd, value);
}

int8_t ev3_infrared_sensor_get_distance(sensor_port_t port)
{
	int8_t value = 0;
	ER ercd = ev3lx_infrared_sensor_get_distance(port, &value);

	return (int8_t)value_or_zero(__func__, port, ercd, value);
}

ir_seek_t ev3_infrared_sensor_seek(sensor_port_t port)
{
	ir_seek_t seek;
	ER ercd = ev3lx_infrared_sensor_seek(port, &seek);

	if (ercd != E_OK) {
		api_warn(__func__, (int)port, ercd);
		memset(&seek, 0, sizeof(seek));
	}
	return seek;
}

ir_remote_t ev3_infrared_sensor_get_remote(sensor_port_t port)
{
	ir_remote_t remote;
	ER ercd = ev3lx_infrared_sensor_get_remote(port, &remote);

	if (ercd != E_OK) {
		api_warn(__func__, (int)port, ercd);
		memset(&remote, 0, sizeof(remote));
	}
	return remote;
}

bool_t ev3_touch_sensor_is_pressed(sensor_port_t port)
{
	bool value = false;
	ER ercd = ev3lx_touch_sensor_is_pressed(port, &value);

	return (bool_t)value_or_zero(__func__, port, ercd, value);
}
