/*
 * linux_compat/clock.h — linux_compat's monotonic clock and its tick ISR.
 */
#ifndef _LINUX_COMPAT_CLOCK_H
#define _LINUX_COMPAT_CLOCK_H

#include <linux/types.h>
#include <t_stddef.h>
#include <kernel.h>

/* The RTOS tick in nanoseconds, from the TOPPERS tick constants (kernel.h:
 * TIC_NUME/TIC_DENO ms per tick); the resolution of hrtimers and delays. */
#define LX_TICK_NS	((uint64_t)(TIC_NUME) * 1000000U / (TIC_DENO))

/* Nanoseconds since boot; any context.  Host: the virtual clock; AM1808:
 * get_utm extended to 64 bits (needs a call at least every 71 minutes,
 * which the tick ISR guarantees). */
uint64_t lx_clock_now_ns(void);
/* Forgets the clock's history (at boot). */
void lx_clock_reset(void);

/* The ISR linux_compat attaches to the RTOS tick (INTNO_TICK): jiffies,
 * deferred wakeups, due hrtimers, then due timer_list timers. */
void lx_tick_isr(intptr_t exinf);

/* Engine entry points the tick ISR calls (now = the tick's time). */
void lx_hrtimer_run_due(uint64_t now);
void lx_timers_run_due(void);
void lx_jiffies_update(uint64_t now);
/* Resets the engines (at boot: no timer is queued in a fresh system). */
void lx_hrtimer_reset(void);
void lx_timers_reset(void);

#endif /* _LINUX_COMPAT_CLOCK_H */
