/*
 * clock.c — clock-rate conversions for models (the clock and events are
 * inline in clock.h).  Host only.
 */
#include "rtos_host.h"
#include "host_sim/clock.h"

#define NS_PER_S   1000000000ULL

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
