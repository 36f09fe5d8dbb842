/*
 * SonarSensor.h — libcpp-ev3's EV3 ultrasonic sensor.  Interface and
 * documented behaviour: EV3RT's SDK,
 * common/library/libcpp-ev3/include/SonarSensor.h.
 */
#ifndef EV3LX_LIBCPP_EV3_SONARSENSOR_H
#define EV3LX_LIBCPP_EV3_SONARSENSOR_H

#include "Sensor.h"

namespace ev3api {

class SonarSensor : public Sensor {
public:
	/* Configures port for the ultrasonic sensor. */
	explicit SonarSensor(ePortS port);

	virtual ~SonarSensor(void);

	/* Distance to what is in front of it, in cm. */
	int16_t getDistance(void) const;

	/* Whether it hears another ultrasonic sensor's signal. */
	bool listen(void) const;
};

} /* namespace ev3api */

#endif /* EV3LX_LIBCPP_EV3_SONARSENSOR_H */
