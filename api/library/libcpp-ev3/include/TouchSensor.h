/*
 * TouchSensor.h — libcpp-ev3's EV3 touch sensor.  Interface: EV3RT's SDK,
 * common/library/libcpp-ev3/include/TouchSensor.h.
 */
#ifndef EV3LX_LIBCPP_EV3_TOUCHSENSOR_H
#define EV3LX_LIBCPP_EV3_TOUCHSENSOR_H

#include "Sensor.h"

namespace ev3api {

class TouchSensor : public Sensor {
public:
	/* Configures port for the touch sensor. */
	explicit TouchSensor(ePortS port);

	/* Whether it is pressed now. */
	bool isPressed(void) const;
};

} /* namespace ev3api */

#endif /* EV3LX_LIBCPP_EV3_TOUCHSENSOR_H */
