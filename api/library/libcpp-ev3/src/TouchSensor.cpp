/*
 * TouchSensor.cpp — libcpp-ev3's touch sensor over EV3RT's C touch call.
 */
#include "TouchSensor.h"

namespace ev3api {

/* The port configured as a touch sensor (Sensor). */
TouchSensor::TouchSensor(ePortS port)
	: Sensor(port, TOUCH_SENSOR)
{
}

/* ev3_touch_sensor_is_pressed. */
bool TouchSensor::isPressed(void) const
{
	return ev3_touch_sensor_is_pressed(getPort());
}

} /* namespace ev3api */
