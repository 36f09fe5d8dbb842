/*
 * clock.h — time for models: the one virtual clock of rtos_stub, device
 * events on it and clock-rate conversions.  Host only.
 */
#ifndef HOST_SIM_CLOCK_H
#define HOST_SIM_CLOCK_H

#include <stdint.h>
#include "rtos_host.h"

/* Virtual time now, in ns since boot. */
uint64_t hs_now(void);

typedef rtos_host_event_t hs_event_t;
/* Schedules fn(arg) at absolute virtual time t_ns (clamped to now). */
hs_event_t hs_event_at(uint64_t t_ns, rtos_host_event_fn fn, void *arg);
/* Schedules fn(arg) dt_ns from now. */
hs_event_t hs_event_after(uint64_t dt_ns, rtos_host_event_fn fn, void *arg);
/* Cancels *ev if set and zeroes it. */
void hs_event_cancel(hs_event_t *ev);

/* Whole cycles of a clock of hz elapsed in ns (floor), and the ns at which
 * cycle number cycles begins (ceil): counters never run early. */
uint64_t hs_ns_to_cycles(uint64_t ns, uint64_t hz);
uint64_t hs_cycles_to_ns(uint64_t cycles, uint64_t hz);

#endif /* HOST_SIM_CLOCK_H */
