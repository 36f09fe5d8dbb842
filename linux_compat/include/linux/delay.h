/*
 * linux/delay.h — busy delays and sleeps.
 *
 * udelay/ndelay/mdelay busy-wait (sil_dly_nse: virtual CPU time on the host,
 * a calibrated loop on the AM1808) and are legal in any context.
 * msleep/ssleep sleep the task (dly_tsk, whole ms, never shorter),
 * usleep_range sleeps on an hrtimer (at least min us, late by less than a
 * tick); sleeping where it is illegal is reported, and the call then
 * busy-waits instead.
 */
#ifndef _LINUX_DELAY_H
#define _LINUX_DELAY_H

#include <linux/types.h>
#include <linux/kernel.h>

#define MAX_UDELAY_MS	5

/* Busy-waits usecs microseconds. */
void udelay(unsigned long usecs);
/* Busy-waits nsecs nanoseconds. */
void ndelay(unsigned long nsecs);
/* Busy-waits msecs milliseconds. */
void mdelay(unsigned long msecs);

/* Sleeps at least msecs ms (file/line: call site for a context report). */
void lx_msleep_at(unsigned int msecs, const char *file, int line);
/* msleep ended early by rel_wai: returns the ms left. */
unsigned long lx_msleep_interruptible_at(unsigned int msecs, const char *file, int line);
/* Sleeps between min and max us (served at min, rounded up to the tick). */
void lx_usleep_range_at(unsigned long min, unsigned long max, const char *file, int line);

void msleep(unsigned int msecs);
unsigned long msleep_interruptible(unsigned int msecs);
void usleep_range(unsigned long min, unsigned long max);
void ssleep(unsigned int seconds);
void fsleep(unsigned long usecs);

#define msleep(ms)			lx_msleep_at((ms), __FILE__, __LINE__)
#define msleep_interruptible(ms)	lx_msleep_interruptible_at((ms), __FILE__, __LINE__)
#define usleep_range(min, max)		lx_usleep_range_at((min), (max), __FILE__, __LINE__)
#define usleep_range_state(min, max, s)	lx_usleep_range_at((min), (max), __FILE__, __LINE__)
#define ssleep(s)			lx_msleep_at((s) * 1000U, __FILE__, __LINE__)
#define usleep_idle_range(min, max)	lx_usleep_range_at((min), (max), __FILE__, __LINE__)

#endif /* _LINUX_DELAY_H */
