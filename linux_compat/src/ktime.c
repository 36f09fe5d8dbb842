/*
 * ktime.c — the monotonic clock as Linux reads it.
 */
#include <linux/ktime.h>
#include <linux_compat/clock.h>

/* ns since boot (the clock linux_compat/clock.h describes); any context. */
ktime_t ktime_get(void)
{
	return (ktime_t)lx_clock_now_ns();
}
