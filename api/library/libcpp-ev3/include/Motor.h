/*
 * Motor.h — libcpp-ev3's motor: one of the brick's output ports, driven by
 * PWM (power) with a brake or float stop, and its rotation counted in
 * degrees from a zero the app may move.  Interface and documented behaviour:
 * EV3RT's SDK, common/library/libcpp-ev3/include/Motor.h.
 */
#ifndef EV3LX_LIBCPP_EV3_MOTOR_H
#define EV3LX_LIBCPP_EV3_MOTOR_H

#include "Port.h"
#include "ev3api.h"

namespace ev3api {

class Motor {
public:
	friend class Steering;

	static const int PWM_MAX = 100;
	static const int PWM_MIN = -100;

	/* Configures port for a motor of type; brake: whether a PWM of 0 and
	 * stop() brake (true) or let it coast (false). */
	explicit Motor(ePortM port, bool brake = true, motor_type_t type = LARGE_MOTOR);

	/* Stops the motor (brake or float, as set). */
	~Motor(void);

	/* Stops the motor at once (braking, whatever the mode, so that it is
	 * still when its counter is cleared) and makes its current position
	 * the count 0.  Inline, as in EV3RT's header: apps that ship a copy of
	 * that header must not meet a second definition in the library. */
	void reset(void)
	{
		ev3_motor_stop(mPort, true);
		ev3_motor_reset_counts(mPort);
		mOffset = 0;
	}

	/* Degrees turned since the count's zero (reset(), setCount()). */
	int32_t getCount(void) const { return ev3_motor_get_counts(mPort) - mOffset; }

	/* Makes the current position read count: later getCount()s go on from
	 * it.  The driver's own counter is left alone. */
	void setCount(int32_t count) { mOffset = ev3_motor_get_counts(mPort) - count; }

	/* Drives at pwm, clamped to PWM_MIN..PWM_MAX; 0 in brake mode stops
	 * the motor braking, 0 in float mode lets it coast. */
	void setPWM(int pwm);

	/* Sets the brake mode used by the next setPWM(0) and stop(). */
	void setBrake(bool brake);

	/* Stops the motor, braking or coasting as the brake mode says (inline,
	 * as in EV3RT's header). */
	void stop(void) { (void)ev3_motor_stop(mPort, mBrake); }

protected:
	/* The port as EV3RT's C API numbers it. */
	motor_port_t getPort(void) const { return mPort; }

	/* The brake mode: true brakes, false floats. */
	bool getBrake(void) const { return mBrake; }

	/* The PWM last set by setPWM() (stop() and reset() keep it, as EV3RT's do). */
	int getPWM(void) const { return mPWM; }

private:
	motor_port_t mPort;
	bool mBrake;
	motor_type_t mType;
	int mPWM;
	int32_t mOffset;
};

} /* namespace ev3api */

#endif /* EV3LX_LIBCPP_EV3_MOTOR_H */
