/*
 * GyroSensor.cpp — libcpp-ev3's gyro over EV3RT's C gyro calls.
 */
#include "GyroSensor.h"

namespace ev3api {

/* The port configured as a gyro, its angle made 0, no offset. */
GyroSensor::GyroSensor(ePortS port)
	: Sensor(port, GYRO_SENSOR), mOffset(DEFAULT_OFFSET)
{
	ev3_gyro_sensor_reset(getPort());
}

/* Kept for getAnglerVelocity(). */
void GyroSensor::setOffset(int16_t offset)
{
	mOffset = offset;
}

/* ev3_gyro_sensor_reset. */
void GyroSensor::reset(void)
{
	ev3_gyro_sensor_reset(getPort());
}

/* ev3_gyro_sensor_get_rate less the offset. */
int16_t GyroSensor::getAnglerVelocity(void) const
{
	return static_cast<int16_t>(ev3_gyro_sensor_get_rate(getPort()) - mOffset);
}

/* ev3_gyro_sensor_get_angle. */
int16_t GyroSensor::getAngle(void) const
{
	return ev3_gyro_sensor_get_angle(getPort());
}

} /* namespace ev3api */
