/*
 * Pid.cpp — cpptracer's PID controller.
 */
#include "Pid.h"

/* Gains and period as given; starts reset. */
Pid::Pid(float kp, float ki, float kd, float dt, float iLimit)
	: mKp(kp), mKi(ki), mKd(kd), mDt(dt), mILimit(iLimit), mIntegral(0.0f), mLastError(0.0f),
	  mFirst(true)
{
}

/* The next update starts without history. */
void Pid::reset()
{
	mIntegral = 0.0f;
	mLastError = 0.0f;
	mFirst = true;
}

/* The first update after a reset has no derivative: there is no previous
 * error to differentiate, and the step from 0 would kick the output.  The
 * integral stops growing where its term reaches +-iLimit. */
float Pid::update(float error)
{
	float derivative = mFirst ? 0.0f : (error - mLastError) / mDt;
	float iTerm;

	mIntegral += error * mDt;
	iTerm = mKi * mIntegral;
	if (mKi != 0.0f && iTerm > mILimit)
		mIntegral = mILimit / mKi;
	else if (mKi != 0.0f && iTerm < -mILimit)
		mIntegral = -mILimit / mKi;
	mLastError = error;
	mFirst = false;
	return mKp * error + mKi * mIntegral + mKd * derivative;
}
