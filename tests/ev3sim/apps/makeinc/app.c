/*
 * app.c — makeinc: reports what its Makefile.inc gave the build.
 */
#include <math.h>
#include <zlib.h>
#include "app.h"

void main_task(intptr_t exinf)
{
#ifdef __OPTIMIZE__
	const char *optimized = "optimized";
#else
	const char *optimized = "not optimized";
#endif
#if defined(MAKE_EV3) && defined(APPL_CFLAGS_SEEN)
	const char *defs = "CDEFS and APPL_CFLAGS";
#else
	const char *defs = "no CDEFS or APPL_CFLAGS";
#endif

	float32_t root = (float32_t)sqrt(49.0);
	SYSTIM before, after;

	get_tim(&before);
	dly_tsk(250U * 1000U);
	get_tim(&after);
	syslog(LOG_NOTICE, "makeinc: gain %d, %s, %s, zlib %s, sqrt %d, dly_tsk(250000) %d ms", gain_apply(100), defs,
	       optimized, zlibVersion(), (int)root, (int)((after - before) / 1000U));
}
