/*
 * clock.c (AM1808) — the monotonic clock from the RTOS performance counter.
 *
 * get_utm gives 32-bit microseconds, which wrap every 71.6 minutes; the
 * clock extends it to 64 bits by counting wraps.  Reads happen at least
 * every tick (lx_tick_isr), so no wrap is ever missed.
 */
#include <linux_compat/clock.h>
#include <kernel.h>
#include <sil.h>

static uint32_t last_utm;
static uint64_t wrap_base_us;

/* ns since boot, 64 bits. */
uint64_t lx_clock_now_ns(void)
{
	SYSUTM utm = 0;
	uint64_t us;
	SIL_PRE_LOC;

	SIL_LOC_INT();
	(void)get_utm(&utm);
	if (utm < last_utm)
		wrap_base_us += (uint64_t)1 << 32;
	last_utm = utm;
	us = wrap_base_us + utm;
	SIL_UNL_INT();
	return us * 1000U;
}

/* Starts the wrap count afresh. */
void lx_clock_reset(void)
{
	last_utm = 0;
	wrap_base_us = 0;
}
