/*
 * app.cpp — etstyle: nine unit objects, each attached as a module of its
 * own, each with a counter in its own writable data, all registered with
 * one singleton; the app defines __dso_handle, as ET Robocon's C++ apps do
 * for EV3RT's toolchain.  Its app.cfg attaches app.o twice and an object
 * the app no longer builds, as teams' apps do: EV3RT ignores both.
 */
#include "ev3api.h"
#include "app.h"
#include "units.h"

void *__dso_handle = 0;

static Unit *const units[] = { &u1, &u2, &u3, &u4, &u5, &u6, &u7, &u8, &u9 };

void main_task(intptr_t unused)
{
	int sum = 0;

	for (Unit *u : units)
		sum += u->step();
	syslog(LOG_NOTICE, "etstyle: %u units stepped, sum %d, %d registered", (unsigned)(sizeof(units) / sizeof(units[0])),
	       sum, Registry::instance().units);
}
