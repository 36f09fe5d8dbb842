/*
 * clock.h — time for models: the one virtual clock of rtos_stub, device
 * events on it, clock-rate conversions and the TIMER64P3 counter.  Host only.
 *
 * TIMER64P3 is modelled from its registers: its input clock is the ASYNC3
 * domain, HS_PLL1_SYSCLK2_HZ = 132 MHz as LEGO configures PLL1 (24 MHz x 22
 * / 2 / 2); in dual 32-bit unchained mode TIM34 counts input / (TDDR34 + 1)
 * (LEGO: TGCR = 0x3306 → 33 MHz, so TIM34 >> 8 ticks every ~7.76 us) and
 * TIM12 counts the input clock.  Counters run while TCR.ENAMODE is
 * continuous and the half is out of reset, wrap after PRD, and are computed
 * from the virtual clock at each read — exact at any instant.
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

/* TIMER64P3 counters as a read at this virtual instant would return them. */
uint32_t hs_timer64p3_tim12(void);
uint32_t hs_timer64p3_tim34(void);
/* Frequency TIM34 counts at under the current TGCR/TCR (0 if stopped). */
uint64_t hs_timer64p3_tim34_hz(void);

#endif /* HOST_SIM_CLOCK_H */
