/*
 * linux/time.h — time units and conversions.  The kernel's only clock is
 * CLOCK_MONOTONIC (time since boot; on the host the virtual clock).
 */
#ifndef _LINUX_TIME_H
#define _LINUX_TIME_H

#include <sys/types.h>      /* clockid_t, whose type the C library fixes (int / unsigned long) */
#include <linux/types.h>
#include <linux/time64.h>

#define CLOCK_REALTIME		0
#define CLOCK_MONOTONIC		1
#define CLOCK_MONOTONIC_RAW	4
#define CLOCK_BOOTTIME		7

#endif /* _LINUX_TIME_H */
