/*
 * app.cpp — cppclass: a C++ app as EV3RT builds one.  A global object is
 * constructed before the kernel starts the first task; the main task
 * smooths a series with a class of an SDK library (running_average), asks
 * the library's C function too, and shows the result on the LCD from a
 * line it allocated with new (the app's heap, in its domain).
 */
#include "ev3api.h"
#include "app.h"
#include "running_average.h"

/* Counts its constructions: a static constructor runs before main_task. */
class StartupProbe {
public:
	StartupProbe() : order_(++constructed) {}
	int order() const { return order_; }
	static int constructed;
private:
	int order_;
};

int StartupProbe::constructed = 0;
static StartupProbe probe;

void main_task(intptr_t unused)
{
	RunningAverage average(4);
	char *line = new char[32];

	for (int i = 1; i <= 8; i++)
		average.add(i * 10);
	syslog(LOG_NOTICE, "cppclass: %d object(s) constructed before the first task, probe %d",
	       StartupProbe::constructed, probe.order());
	syslog(LOG_NOTICE, "cppclass: average of the last 4 of 10..80 is %d, the library's C call says %d",
	       average.value(), running_average_of_last(4, 10, 80, 10));
	sprintf(line, "average %d", average.value());
	syslog(LOG_NOTICE, "cppclass: done, the LCD says so (%d)", (int)ev3_lcd_draw_string(line, 0, 0));
	delete[] line;
}
