/*
 * app.cpp — cpptracer: a line tracer in ET Robocon's style, written against
 * EV3RT's C++ API (libcpp-ev3: ev3api::Motor, ColorSensor, TouchSensor,
 * Clock) with a PID class of its own.
 *
 * The tracer is a global object, as in ET Robocon's sample apps: its
 * constructor configures its motors and sensor when EV3RT runs the app's
 * global constructors, once the platform is up and before the first task.
 * The main task waits for the touch sensor, then starts TRACER_CYC, whose
 * handler activates the tracer task every TRACER_PERIOD_MS; it reports the
 * run every 5 s and stops the robot when the back button is pressed.
 */
#include "app.h"
#include "Tracer.h"
#include "TouchSensor.h"
#include "Clock.h"

using namespace ev3api;

static Tracer tracer;

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
	tracer.run();
	ext_tsk();
}

void main_task(intptr_t unused)
{
	TouchSensor touchSensor(PORT_1);
	Clock clock;
	uint32_t next_report = 5000;

	tracer.init();
	syslog(LOG_NOTICE, "cpptracer: target %d%%, press the touch sensor to start", tracer.target());
	while (!touchSensor.isPressed())
		clock.sleep(10);
	syslog(LOG_NOTICE, "cpptracer: go after %u ms", (unsigned)clock.now());
	clock.reset();
	ev3_sta_cyc(TRACER_CYC);

	while (!ev3_button_is_pressed(BACK_BUTTON)) {
		clock.sleep(100);
		if (clock.now() >= next_report) {
			syslog(LOG_NOTICE, "cpptracer: %u ms, %u periods, the wheels rolled %d mm",
			       (unsigned)clock.now(), tracer.steps(), tracer.travelMm());
			next_report += 5000;
		}
	}
	ev3_stp_cyc(TRACER_CYC);
	tracer.terminate();
	syslog(LOG_NOTICE, "cpptracer: stopped after %u periods", tracer.steps());
}
