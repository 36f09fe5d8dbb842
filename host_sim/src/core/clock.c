/*
 * clock.c — time for models: the virtual clock, device events and clock-rate
 * conversions.  Host only.
 */
#include "rtos_host.h"
#include "host_sim/clock.h"

#define NS_PER_S   1000000000ULL

uint64_t hs_now(void)
{
	return rtos_host_now();
}

hs_event_t hs_event_at(uint64_t t_ns, rtos_host_event_fn fn, void *arg)
{
	uint64_t now = rtos_host_now();

	return rtos_host_event_at(t_ns < now ? now : t_ns, fn, arg);
}

hs_event_t hs_event_after(uint64_t dt_ns, rtos_host_event_fn fn, void *arg)
{
	return rtos_host_event_at(rtos_host_now() + dt_ns, fn, arg);
}

void hs_event_cancel(hs_event_t *ev)
{
	if (ev && *ev) {
		rtos_host_event_cancel(*ev);
		*ev = 0;
	}
}

uint64_t hs_ns_to_cycles(uint64_t ns, uint64_t hz)
{
	/* Split to stay exact without 128-bit arithmetic (32-bit hosts too). */
	return (ns / NS_PER_S) * hz + ((ns % NS_PER_S) * hz) / NS_PER_S;
}

uint64_t hs_cycles_to_ns(uint64_t cycles, uint64_t hz)
{
	uint64_t whole, rem;

	if (hz == 0)
		return UINT64_MAX;
	whole = cycles / hz;
	rem = cycles % hz;
	return whole * NS_PER_S + (rem * NS_PER_S + hz - 1U) / hz;
}
