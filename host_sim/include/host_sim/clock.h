/*
 * clock.h — time for models: the one virtual clock of rtos_stub, device
 * events on it and clock-rate conversions.  Host only.
 */
#ifndef HOST_SIM_CLOCK_H
#define HOST_SIM_CLOCK_H

#include <stdint.h>
#include "rtos_host.h"

/* The time and event helpers are inline: models call them on every tacho edge
 * and register access, and each is a line over rtos_host's own call. */

/* Virtual time now, in ns since boot. */
static inline uint64_t hs_now(void)
{
	return rtos_host_now();
}

typedef rtos_host_event_t hs_event_t;
/* Schedules fn(arg) at absolute virtual time t_ns (clamped to now). */
static inline hs_event_t hs_event_at(uint64_t t_ns, rtos_host_event_fn fn, void *arg)
{
	uint64_t now = rtos_host_now();

	return rtos_host_event_at(t_ns < now ? now : t_ns, fn, arg);
}

/* Schedules fn(arg) dt_ns from now. */
static inline hs_event_t hs_event_after(uint64_t dt_ns, rtos_host_event_fn fn, void *arg)
{
	return rtos_host_event_at(rtos_host_now() + dt_ns, fn, arg);
}

/* Cancels *ev if set and zeroes it. */
static inline void hs_event_cancel(hs_event_t *ev)
{
	if (ev && *ev) {
		rtos_host_event_cancel(*ev);
		*ev = 0;
	}
}

/* Whole cycles of a clock of hz elapsed in ns (floor), and the ns at which
 * cycle number cycles begins (ceil): counters never run early. */
uint64_t hs_ns_to_cycles(uint64_t ns, uint64_t hz);
uint64_t hs_cycles_to_ns(uint64_t cycles, uint64_t hz);

#endif /* HOST_SIM_CLOCK_H */
