/*
 * SonarSensor.cpp — libcpp-ev3's ultrasonic sensor over EV3RT's C calls.
 */
#include "SonarSensor.h"

namespace ev3api {

/* The port configured as an ultrasonic sensor (Sensor). */
SonarSensor::SonarSensor(ePortS port)
	: Sensor(port, ULTRASONIC_SENSOR)
{
}

/* Nothing of its own to release. */
SonarSensor::~SonarSensor(void)
{
}

/* ev3_ultrasonic_sensor_get_distance: US-DIST-CM. */
int16_t SonarSensor::getDistance(void) const
{
	return ev3_ultrasonic_sensor_get_distance(getPort());
}

/* ev3_ultrasonic_sensor_listen: US-LISTEN. */
bool SonarSensor::listen(void) const
{
	return ev3_ultrasonic_sensor_listen(getPort());
}

} /* namespace ev3api */
