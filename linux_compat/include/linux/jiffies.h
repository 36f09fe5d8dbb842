/*
 * linux/jiffies.h — jiffies and HZ.
 *
 * HZ is 1000: one jiffy is 1 ms (5 RTOS ticks of 200 us).  jiffies counts
 * from INITIAL_JIFFIES (5 minutes before wrap on 32 bits, as Linux does, so
 * wrap bugs show early) and advances in the tick ISR: jiffies_64 =
 * INITIAL_JIFFIES + ktime_get() / 1 ms.  Compare jiffies only with
 * time_after/time_before.
 */
#ifndef _LINUX_JIFFIES_H
#define _LINUX_JIFFIES_H

#include <linux/types.h>
#include <linux/time64.h>

#define HZ		1000
#define USER_HZ		100
#define TICK_NSEC	(NSEC_PER_SEC / HZ)
#define TICK_USEC	(USEC_PER_SEC / HZ)

#define INITIAL_JIFFIES	((unsigned long)(unsigned int)(-300 * HZ))

extern volatile unsigned long jiffies;
extern u64 jiffies_64;

/* jiffies_64, read consistently on 32-bit CPUs. */
u64 get_jiffies_64(void);

#define time_after(a, b)	((long)((b) - (a)) < 0)
#define time_before(a, b)	time_after(b, a)
#define time_after_eq(a, b)	((long)((a) - (b)) >= 0)
#define time_before_eq(a, b)	time_after_eq(b, a)
#define time_in_range(a, b, c)	(time_after_eq(a, b) && time_before_eq(a, c))
#define time_in_range_open(a, b, c) (time_after_eq(a, b) && time_before(a, c))
#define time_after64(a, b)	((s64)((b) - (a)) < 0)
#define time_before64(a, b)	time_after64(b, a)
#define time_after_eq64(a, b)	((s64)((a) - (b)) >= 0)
#define time_before_eq64(a, b)	time_after_eq64(b, a)
#define time_is_before_jiffies(a)	time_after(jiffies, a)
#define time_is_after_jiffies(a)	time_before(jiffies, a)
#define time_is_before_eq_jiffies(a)	time_after_eq(jiffies, a)
#define time_is_after_eq_jiffies(a)	time_before_eq(jiffies, a)

#define MAX_JIFFY_OFFSET	((long)(~0UL >> 1) - 1)

/* HZ = 1000: a jiffy is a millisecond; conversions round up, as Linux's. */
static inline unsigned long msecs_to_jiffies(const unsigned int m)
{
	if ((int)m < 0)
		return MAX_JIFFY_OFFSET;
	return (unsigned long)m * HZ / MSEC_PER_SEC;
}
static inline unsigned long usecs_to_jiffies(const unsigned int u)
{
	return (unsigned long)(((u64)u * HZ + USEC_PER_SEC - 1) / USEC_PER_SEC);
}
static inline unsigned long nsecs_to_jiffies(u64 n)
{
	return (unsigned long)((n + TICK_NSEC - 1) / TICK_NSEC);
}
static inline u64 nsecs_to_jiffies64(u64 n)		{ return (n + TICK_NSEC - 1) / TICK_NSEC; }
static inline unsigned int jiffies_to_msecs(const unsigned long j) { return (unsigned int)(j * (MSEC_PER_SEC / HZ)); }
static inline unsigned int jiffies_to_usecs(const unsigned long j) { return (unsigned int)(j * (USEC_PER_SEC / HZ)); }
static inline u64 jiffies_to_nsecs(const unsigned long j)	{ return (u64)j * TICK_NSEC; }
static inline u64 jiffies64_to_nsecs(u64 j)			{ return j * TICK_NSEC; }
static inline u64 jiffies64_to_msecs(u64 j)			{ return j * (MSEC_PER_SEC / HZ); }
static inline unsigned long secs_to_jiffies(unsigned int s)	{ return (unsigned long)s * HZ; }

/* j rounded to a whole second (here: unchanged beyond HZ granularity). */
static inline unsigned long round_jiffies(unsigned long j)		{ return j; }
static inline unsigned long round_jiffies_relative(unsigned long j)	{ return j; }
static inline unsigned long round_jiffies_up(unsigned long j)		{ return j; }

#endif /* _LINUX_JIFFIES_H */
