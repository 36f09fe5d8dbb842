/*
 * Pid.h — cpptracer: a discrete PID controller of its own (position form,
 * the derivative on the error, the integral bounded against wind-up).
 */
#ifndef CPPTRACER_PID_H
#define CPPTRACER_PID_H

class Pid {
public:
	/* Gains per unit of error, per unit-second and per unit/second; dt
	 * the period in seconds; the integral's contribution is kept within
	 * +-iLimit. */
	Pid(float kp, float ki, float kd, float dt, float iLimit);

	/* Forgets the integral and the last error. */
	void reset();

	/* The control for error, one period after the previous call. */
	float update(float error);

private:
	float mKp, mKi, mKd, mDt, mILimit;
	float mIntegral;
	float mLastError;
	bool mFirst;
};

#endif /* CPPTRACER_PID_H */
