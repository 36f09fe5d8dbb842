/*
 * ColorSensor.h — libcpp-ev3's EV3 colour sensor.  Interface and documented
 * behaviour: EV3RT's SDK, common/library/libcpp-ev3/include/ColorSensor.h.
 * Each read selects the sensor's mode for it, as EV3RT's C calls do.
 */
#ifndef EV3LX_LIBCPP_EV3_COLORSENSOR_H
#define EV3LX_LIBCPP_EV3_COLORSENSOR_H

#include "Sensor.h"

namespace ev3api {

class ColorSensor : public Sensor {
public:
	/* Configures port for the colour sensor. */
	explicit ColorSensor(ePortS port);

	virtual ~ColorSensor(void);

	/* Ambient light, 0..100 %. */
	uint8_t getAmbient(void) const;

	/* Reflected light of its own red lamp, 0..100 %. */
	int8_t getBrightness(void) const;

	/* The colour it recognises (COLOR_NONE when none). */
	colorid_t getColorNumber(void) const;

	/* The raw red, green and blue readings, into rgb. */
	void getRawColor(rgb_raw_t& rgb) const;
};

} /* namespace ev3api */

#endif /* EV3LX_LIBCPP_EV3_COLORSENSOR_H */
