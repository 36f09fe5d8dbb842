/*
 * Sensor.h — libcpp-ev3's sensor base class: a sensor object configures its
 * port for its type when it is constructed (ev3_sensor_config) and reads it
 * through EV3RT's C API.  Interface: EV3RT's SDK,
 * common/library/libcpp-ev3/include/Sensor.h.
 */
#ifndef EV3LX_LIBCPP_EV3_SENSOR_H
#define EV3LX_LIBCPP_EV3_SENSOR_H

#include "Port.h"
#include "ev3api.h"

namespace ev3api {

class Sensor {
protected:
	/* Configures port for a sensor of type (its mode is chosen by the reads). */
	explicit Sensor(ePortS port, sensor_type_t type)
		: mPort(static_cast<sensor_port_t>(port)), mType(type)
	{
		ev3_sensor_config(mPort, mType);
	}

	/* Nothing to release: the port stays configured. */
	virtual ~Sensor(void) {}

	/* The port as EV3RT's C API numbers it. */
	sensor_port_t getPort(void) const { return mPort; }

private:
	sensor_port_t mPort;
	sensor_type_t mType;
};

} /* namespace ev3api */

#endif /* EV3LX_LIBCPP_EV3_SENSOR_H */
