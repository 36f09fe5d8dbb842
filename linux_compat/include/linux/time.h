/*
 * linux/time.h — time units and conversions.  The kernel's only clock is
 * CLOCK_MONOTONIC (time since boot; on the host the virtual clock).
 */
#ifndef _LINUX_TIME_H
#define _LINUX_TIME_H

#include <linux/types.h>
#include <linux/time64.h>

/* As Linux's __kernel_clockid_t, and as glibc's: a hosted test program may
 * include both (the C libraries' __clockid_t_defined guard). */
#ifndef __clockid_t_defined
#define __clockid_t_defined 1
typedef int clockid_t;
#endif

#define CLOCK_REALTIME		0
#define CLOCK_MONOTONIC		1
#define CLOCK_MONOTONIC_RAW	4
#define CLOCK_BOOTTIME		7

#endif /* _LINUX_TIME_H */
