/*
 * Motor.cpp — libcpp-ev3's motor over EV3RT's C motor calls.
 */
#include "Motor.h"

namespace ev3api {

/* The port configured for type, which clears the driver's counter: the
 * count starts at 0 with no offset. */
Motor::Motor(ePortM port, bool brake, motor_type_t type)
	: mPort(static_cast<motor_port_t>(port)), mBrake(brake), mType(type), mPWM(0), mOffset(0)
{
	ev3_motor_config(mPort, mType);
}

/* Leaves the motor stopped, as its brake mode says. */
Motor::~Motor(void)
{
	stop();
}

/* Clamps, keeps the value for getPWM(), and stops on 0 in brake mode
 * (setting power 0 would let the motor coast). */
void Motor::setPWM(int pwm)
{
	if (pwm > PWM_MAX)
		pwm = PWM_MAX;
	else if (pwm < PWM_MIN)
		pwm = PWM_MIN;
	mPWM = pwm;
	if (pwm == 0 && mBrake)
		ev3_motor_stop(mPort, true);
	else
		ev3_motor_set_power(mPort, pwm);
}

/* Only remembered: it applies from the next setPWM(0) or stop(). */
void Motor::setBrake(bool brake)
{
	mBrake = brake;
}

} /* namespace ev3api */
