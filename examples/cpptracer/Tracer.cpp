/*
 * Tracer.cpp — cpptracer's line tracer.
 */
#include "Tracer.h"
#include "app.h"

/* The mat's reflected light, %: the white of the course. */
static const int WHITE = 64;
/* Forward PWM of both wheels before steering. */
static const int POWER = 40;
/* The wheels' diameter, mm (LEGO's 56 mm tyre). */
static const int WHEEL_DIAMETER_MM = 56;

/* PID gains per % of light: proportional, integral (per %.s), derivative
 * (per %/s); the period is the cyclic handler's. */
Tracer::Tracer()
	: mLeftWheel(PORT_B), mRightWheel(PORT_C), mColorSensor(PORT_3),
	  mPid(0.9f, 0.3f, 0.012f, TRACER_PERIOD_MS / 1000.0f, 20.0f), mTarget(0), mSteps(0)
{
}

/* The robot is put down with its sensor on the line: it sees the black. */
void Tracer::init()
{
	int black = mColorSensor.getBrightness();

	mTarget = (black + WHITE) / 2;
	mPid.reset();
	mLeftWheel.reset();
	mRightWheel.reset();
	mSteps = 0;
}

/* More light than the target means the sensor is over the mat, right of
 * the edge: turn left, the right wheel faster. */
void Tracer::run()
{
	int turn = static_cast<int>(mPid.update(static_cast<float>(mColorSensor.getBrightness() - mTarget)));

	mLeftWheel.setPWM(POWER - turn);
	mRightWheel.setPWM(POWER + turn);
	mSteps++;
}

/* Braking: the Motor objects brake by default. */
void Tracer::terminate()
{
	mLeftWheel.stop();
	mRightWheel.stop();
}

/* The mean of the wheels' counts, in degrees, times the wheel's
 * circumference per degree. */
int Tracer::travelMm() const
{
	long degrees = (static_cast<long>(mLeftWheel.getCount()) + mRightWheel.getCount()) / 2;

	return static_cast<int>(degrees * 314L * WHEEL_DIAMETER_MM / 36000L);
}
