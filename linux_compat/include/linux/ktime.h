/*
 * linux/ktime.h — ktime_t: signed 64-bit nanoseconds (Linux >= 4.10), and
 * ktime_get(): the monotonic clock in ns since boot (host: the virtual clock;
 * AM1808: the RTOS performance counter, get_utm, extended to 64 bits).
 */
#ifndef _LINUX_KTIME_H
#define _LINUX_KTIME_H

#include <linux/types.h>
#include <linux/time.h>
#include <linux/jiffies.h>

typedef s64 ktime_t;

/* secs seconds plus nsecs nanoseconds. */
static inline ktime_t ktime_set(const s64 secs, const unsigned long nsecs)
{
	if (secs >= KTIME_SEC_MAX)
		return KTIME_MAX;
	return secs * NSEC_PER_SEC + (s64)nsecs;
}

#define ktime_add(lhs, rhs)	((lhs) + (rhs))
#define ktime_sub(lhs, rhs)	((lhs) - (rhs))
#define ktime_add_ns(kt, nsval)	((kt) + (s64)(nsval))
#define ktime_sub_ns(kt, nsval)	((kt) - (s64)(nsval))
#define ktime_add_us(kt, usec)	ktime_add_ns(kt, (u64)(usec) * NSEC_PER_USEC)
#define ktime_add_ms(kt, msec)	ktime_add_ns(kt, (u64)(msec) * NSEC_PER_MSEC)
#define ktime_sub_us(kt, usec)	ktime_sub_ns(kt, (u64)(usec) * NSEC_PER_USEC)

/* lhs + rhs, saturating at KTIME_MAX instead of overflowing. */
static inline ktime_t ktime_add_safe(const ktime_t lhs, const ktime_t rhs)
{
	ktime_t res = (ktime_t)((u64)lhs + (u64)rhs);

	if (res < 0 || res < lhs || res < rhs)
		res = KTIME_MAX;
	return res;
}

static inline ktime_t ns_to_ktime(u64 ns)		{ return (ktime_t)ns; }
static inline ktime_t us_to_ktime(u64 us)		{ return (ktime_t)(us * NSEC_PER_USEC); }
static inline ktime_t ms_to_ktime(u64 ms)		{ return (ktime_t)(ms * NSEC_PER_MSEC); }
static inline s64 ktime_to_ns(const ktime_t kt)		{ return kt; }
static inline s64 ktime_to_us(const ktime_t kt)		{ return kt / NSEC_PER_USEC; }
static inline s64 ktime_to_ms(const ktime_t kt)		{ return kt / NSEC_PER_MSEC; }
static inline ktime_t timespec64_to_ktime(struct timespec64 ts) { return ktime_set(ts.tv_sec, ts.tv_nsec); }
static inline struct timespec64 ktime_to_timespec64(ktime_t kt) { return ns_to_timespec64(kt); }

/* -1, 0 or 1 as cmp1 is before, equal to or after cmp2. */
static inline int ktime_compare(const ktime_t cmp1, const ktime_t cmp2)
{
	if (cmp1 < cmp2)
		return -1;
	return cmp1 > cmp2 ? 1 : 0;
}
static inline bool ktime_after(const ktime_t cmp1, const ktime_t cmp2)	{ return cmp1 > cmp2; }
static inline bool ktime_before(const ktime_t cmp1, const ktime_t cmp2)	{ return cmp1 < cmp2; }
static inline s64 ktime_us_delta(const ktime_t later, const ktime_t earlier) { return ktime_to_us(later - earlier); }
static inline s64 ktime_ms_delta(const ktime_t later, const ktime_t earlier) { return ktime_to_ms(later - earlier); }
static inline s64 ktime_divns(const ktime_t kt, s64 div)		{ return kt / div; }

/* Monotonic time since boot in ns; any context. */
ktime_t ktime_get(void);
/* The same clock (all clocks are the monotonic clock here). */
static inline ktime_t ktime_get_raw(void)		{ return ktime_get(); }
static inline ktime_t ktime_get_boottime(void)		{ return ktime_get(); }
static inline ktime_t ktime_get_real(void)		{ return ktime_get(); }
static inline u64 ktime_get_ns(void)			{ return (u64)ktime_get(); }
static inline u64 ktime_get_raw_ns(void)		{ return (u64)ktime_get(); }
static inline u64 ktime_get_boottime_ns(void)		{ return (u64)ktime_get(); }
static inline u64 ktime_get_mono_fast_ns(void)		{ return (u64)ktime_get(); }
/* Monotonic time as a timespec64. */
static inline void ktime_get_ts64(struct timespec64 *ts) { *ts = ns_to_timespec64(ktime_get()); }
/* Seconds since boot. */
static inline time64_t ktime_get_seconds(void)		{ return ktime_get() / NSEC_PER_SEC; }

#endif /* _LINUX_KTIME_H */
