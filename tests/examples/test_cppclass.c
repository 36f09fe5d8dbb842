/*
 * test_cppclass.c — examples/cppclass: a C++ app with an SDK library, built
 * as EV3RT builds it (SRCLANG := c++, the library from its Makefile.inc):
 * its static constructor ran before the first task, the library's class and
 * C function work from the app's domain, and the LCD shows the result.
 */
#include "example_test.h"

int main(void)
{
	struct ev3sim_run_opts o;
	struct ev3sim_run_result r;

	ev3sim_run_defaults(&o, EV3SIM_ROBOT_BARE);
	o.app_name = "cppclass";
	o.seconds = 2;
	if (!ok(ex_run(&o, &r), "cppclass runs"))
		return tap_done();
	ok(ex_logged("cppclass: 1 object(s) constructed before the first task, probe 1") != NULL,
	   "the global object was constructed once, before main_task");
	ok(ex_logged("cppclass: average of the last 4 of 10..80 is 65, the library's C call says 65") != NULL,
	   "the library's C++ class and C function give 65");
	ok(ex_logged("cppclass: done, the LCD says so (0)") != NULL,
	   "the task ran to its end and drew from a line it allocated with new (E_OK)");
	is_int(r.warnings + r.errors + r.bugs, 0, "no warnings, errors or bugs");
	return tap_done();
}
