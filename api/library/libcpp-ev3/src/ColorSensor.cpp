/*
 * ColorSensor.cpp — libcpp-ev3's colour sensor over EV3RT's C colour calls.
 */
#include "ColorSensor.h"

namespace ev3api {

/* The port configured as a colour sensor (Sensor). */
ColorSensor::ColorSensor(ePortS port)
	: Sensor(port, COLOR_SENSOR)
{
}

/* Nothing of its own to release. */
ColorSensor::~ColorSensor(void)
{
}

/* ev3_color_sensor_get_ambient: COL-AMBIENT. */
uint8_t ColorSensor::getAmbient(void) const
{
	return ev3_color_sensor_get_ambient(getPort());
}

/* ev3_color_sensor_get_reflect: COL-REFLECT, 0..100 fits int8_t. */
int8_t ColorSensor::getBrightness(void) const
{
	return static_cast<int8_t>(ev3_color_sensor_get_reflect(getPort()));
}

/* ev3_color_sensor_get_color: COL-COLOR. */
colorid_t ColorSensor::getColorNumber(void) const
{
	return ev3_color_sensor_get_color(getPort());
}

/* ev3_color_sensor_get_rgb_raw: RGB-RAW. */
void ColorSensor::getRawColor(rgb_raw_t& rgb) const
{
	ev3_color_sensor_get_rgb_raw(getPort(), &rgb);
}

} /* namespace ev3api */
