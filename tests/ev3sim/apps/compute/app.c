/*
 * app.c — compute: integer work with no service call between two readings
 * of the clock (get_utm), n and then 2n rounds, as a benchmark app times
 * its computation; logs the microseconds each took.
 */
#include "app.h"

static volatile unsigned sink;

/* n rounds of a few integer operations, in the app's own code. */
static __attribute__((noinline)) void work(int n)
{
	unsigned s = 0;

	for (unsigned i = 0; i < (unsigned)n; i++)
		s += (i * 3U) ^ (i >> 2);
	sink = s;
}

/* The microseconds n rounds take. */
static unsigned long timed(int n)
{
	SYSUTM t0, t1;

	get_utm(&t0);
	work(n);
	get_utm(&t1);
	return (unsigned long)(t1 - t0);
}

void main_task(intptr_t exinf)
{
	unsigned long one = timed(100000), two = timed(200000);

	syslog(LOG_NOTICE, "compute: 100000 rounds %lu us, 200000 rounds %lu us", one, two);
}
