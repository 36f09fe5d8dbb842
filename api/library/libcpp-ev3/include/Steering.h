/*
 * Steering.h — libcpp-ev3's steering: a pair of motors driven together at a
 * power, the inner one slowed by a turn ratio.  Interface and documented
 * behaviour: EV3RT's SDK, common/library/libcpp-ev3/include/Steering.h (a
 * turn ratio of +25 runs the left motor at the power and the right one at
 * 75 % of it, turning right).
 */
#ifndef EV3LX_LIBCPP_EV3_STEERING_H
#define EV3LX_LIBCPP_EV3_STEERING_H

#include "Motor.h"

namespace ev3api {

class Steering {
public:
	/* Steers with leftMotor and rightMotor (kept by reference). */
	explicit Steering(Motor& leftMotor, Motor& rightMotor);

	/* Drives at power (-100..100, negative backwards): turnRatio 0 runs
	 * both motors at power, a positive one slows the right motor to
	 * (100 - turnRatio) % of it (turning right), a negative one the left;
	 * both are clamped to -100..100. */
	void setPower(int power, int turnRatio);

private:
	Motor& mLeftMotor;
	Motor& mRightMotor;
};

} /* namespace ev3api */

#endif /* EV3LX_LIBCPP_EV3_STEERING_H */
