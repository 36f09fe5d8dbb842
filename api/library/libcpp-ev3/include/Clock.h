/*
 * Clock.h — libcpp-ev3's clock: time since the object's start, and the
 * calling task's delay and sleep.  Interface and documented behaviour:
 * EV3RT's SDK, common/library/libcpp-ev3/include/Clock.h.  Its unit is the
 * kernel's time unit, as EV3RT's: milliseconds on EV3RT's TOPPERS/HRP2
 * kernel (the SDK documents msec), microseconds on TOPPERS/HRP3.
 */
#ifndef EV3LX_LIBCPP_EV3_CLOCK_H
#define EV3LX_LIBCPP_EV3_CLOCK_H

#include "ev3api.h"

namespace ev3api {

class Clock {
public:
	/* Starts counting now. */
	Clock(void);

	/* Starts counting again from now. */
	void reset(void);

	/* Time since the start (modulo 2^32). */
	uint32_t now(void) const;

	/* Delays the calling task for duration (dly_tsk: a wake-up does not
	 * end it). */
	void wait(uint32_t duration) { dly_tsk(duration); }

	/* Sleeps the calling task for duration at most (tslp_tsk: wup_tsk
	 * ends it early). */
	void sleep(uint32_t duration) { tslp_tsk(duration); }

protected:
	/* The kernel's system time, truncated to 32 bits. */
	static uint32_t getTim();

private:
	uint32_t mStartClock;
};

} /* namespace ev3api */

#endif /* EV3LX_LIBCPP_EV3_CLOCK_H */
