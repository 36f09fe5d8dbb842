/*
 * GyroSensor.h — libcpp-ev3's EV3 gyro sensor.  Interface and documented
 * behaviour: EV3RT's SDK, common/library/libcpp-ev3/include/GyroSensor.h
 * (getAnglerVelocity is EV3RT's spelling).
 */
#ifndef EV3LX_LIBCPP_EV3_GYROSENSOR_H
#define EV3LX_LIBCPP_EV3_GYROSENSOR_H

#include "Sensor.h"

namespace ev3api {

class GyroSensor : public Sensor {
public:
	/* The offset a new object starts with. */
	static const int16_t DEFAULT_OFFSET = 0;

	/* Configures port for the gyro and makes its angle 0. */
	explicit GyroSensor(ePortS port);

	/* Sets the rate the sensor reads at rest, which getAnglerVelocity()
	 * subtracts. */
	void setOffset(int16_t offset);

	/* Makes the current angle 0. */
	void reset(void);

	/* Angular velocity in degrees/s, less the offset. */
	int16_t getAnglerVelocity(void) const;

	/* Angle in degrees since the last reset. */
	int16_t getAngle(void) const;

private:
	int16_t mOffset;
};

} /* namespace ev3api */

#endif /* EV3LX_LIBCPP_EV3_GYROSENSOR_H */
