/*
 * app.cpp — cpptracer: a line tracer in ET Robocon's style, written against
 * EV3RT's C++ API (libcpp-ev3: ev3api::Motor, ColorSensor, TouchSensor,
 * Clock) with a PID class of its own.
 *
 * The main task makes the tracer (its motors and sensor configured) as a
 * local object, which lives as long as the task runs and which the tracer
 * task reaches through a pointer; no heap, so nothing is left behind when
 * the brick boots again.  It waits for the touch sensor, then starts
 * TRACER_CYC, whose handler activates the tracer task every
 * TRACER_PERIOD_MS; it reports the run every 5 s and stops the robot when
 * the back button is pressed.
 */
#include "app.h"
#include "Tracer.h"
#include "TouchSensor.h"
#include "Clock.h"

using namespace ev3api;

/* main_task's tracer, while it runs */
static Tracer *tracer;

/* Activates the tracer for one period (EV3RT's cyclic handlers run in a
 * task of their own; the tracer task does the work). */
void tracer_cyc(intptr_t exinf)
{
	act_tsk(TRACER_TASK);
}

/* One period of tracing; an activation that finds one still running is
 * queued by the kernel, none is lost. */
void tracer_task(intptr_t exinf)
{
	tracer->run();
	ext_tsk();
}

void main_task(intptr_t unused)
{
	Tracer mainTracer;
	TouchSensor touchSensor(PORT_1);
	Clock clock;
	uint32_t next_report = 5000;

	tracer = &mainTracer;
	tracer->init();
	syslog(LOG_NOTICE, "cpptracer: target %d%%, press the touch sensor to start", tracer->target());
	while (!touchSensor.isPressed())
		clock.sleep(10);
	syslog(LOG_NOTICE, "cpptracer: go after %u ms", (unsigned)clock.now());
	clock.reset();
	ev3_sta_cyc(TRACER_CYC);

	while (!ev3_button_is_pressed(BACK_BUTTON)) {
		clock.sleep(100);
		if (clock.now() >= next_report) {
			syslog(LOG_NOTICE, "cpptracer: %u ms, %u periods, the wheels rolled %d mm",
			       (unsigned)clock.now(), tracer->steps(), tracer->travelMm());
			next_report += 5000;
		}
	}
	ev3_stp_cyc(TRACER_CYC);
	tracer->terminate();
	syslog(LOG_NOTICE, "cpptracer: stopped after %u periods", tracer->steps());
}
