/*
 * Steering.cpp — libcpp-ev3's steering: two Motor objects' setPWM.
 */
#include "Steering.h"

namespace ev3api {

/* Keeps the two motors; nothing is driven yet. */
Steering::Steering(Motor& leftMotor, Motor& rightMotor)
	: mLeftMotor(leftMotor), mRightMotor(rightMotor)
{
}

/* Clamps v to -100..100. */
static int clamp100(int v)
{
	return v > 100 ? 100 : v < -100 ? -100 : v;
}

/* The outer motor runs at power, the inner one at (100 - |turnRatio|) % of
 * it: at a ratio of +-100 the inner motor stops and the robot pivots on
 * that wheel. */
void Steering::setPower(int power, int turnRatio)
{
	int inner;

	power = clamp100(power);
	turnRatio = clamp100(turnRatio);
	inner = power * (100 - (turnRatio < 0 ? -turnRatio : turnRatio)) / 100;
	mLeftMotor.setPWM(turnRatio >= 0 ? power : inner);
	mRightMotor.setPWM(turnRatio >= 0 ? inner : power);
}

} /* namespace ev3api */
