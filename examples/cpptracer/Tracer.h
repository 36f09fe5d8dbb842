/*
 * Tracer.h — cpptracer's line tracer: two wheels and a colour sensor
 * looking down, steered by a PID controller on the reflected light so that
 * the sensor keeps to the line's left-hand edge.
 */
#ifndef CPPTRACER_TRACER_H
#define CPPTRACER_TRACER_H

#include "Motor.h"
#include "ColorSensor.h"
#include "Pid.h"

using namespace ev3api;

class Tracer {
public:
	/* The wheels on B (left) and C (right), the colour sensor on 3. */
	Tracer();

	/* Takes the light seen now as the line's and aims between it and
	 * the mat's. */
	void init();

	/* One period: reads the light, steers. */
	void run();

	/* Stops both wheels. */
	void terminate();

	/* How far the wheels have rolled, on average, in mm. */
	int travelMm() const;

	/* Periods run since init(). */
	unsigned steps() const { return mSteps; }

	/* The reflected light aimed at, %. */
	int target() const { return mTarget; }

private:
	Motor mLeftWheel;
	Motor mRightWheel;
	ColorSensor mColorSensor;
	Pid mPid;
	int mTarget;
	unsigned mSteps;
};

#endif /* CPPTRACER_TRACER_H */
