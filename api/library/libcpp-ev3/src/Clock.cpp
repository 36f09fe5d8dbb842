/*
 * Clock.cpp — libcpp-ev3's clock over the kernel's get_tim.
 */
#include "Clock.h"

namespace ev3api {

/* Starts at the system time now. */
Clock::Clock(void)
	: mStartClock(getTim())
{
}

/* Restarts at the system time now. */
void Clock::reset(void)
{
	mStartClock = getTim();
}

/* Unsigned subtraction: right across the 32-bit wrap as well. */
uint32_t Clock::now(void) const
{
	return getTim() - mStartClock;
}

/* get_tim's SYSTIM in the kernel's unit, its low 32 bits. */
uint32_t Clock::getTim()
{
	SYSTIM t = 0;

	get_tim(&t);
	return static_cast<uint32_t>(t);
}

} /* namespace ev3api */
