/*
 * clock.c (host) — the monotonic clock is the host kernel's virtual clock.
 */
#include <linux_compat/clock.h>
#include <rtos_host.h>

/* Virtual ns since boot. */
uint64_t lx_clock_now_ns(void)
{
	return rtos_host_now();
}

/* Nothing to forget: the virtual clock restarts at each boot. */
void lx_clock_reset(void)
{
}
