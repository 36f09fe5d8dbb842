/* SPDX-License-Identifier: GPL-2.0 */
/*
 * scratch_uapi.h — the interface of the scratch driver (scratch_drv.c):
 * its device name, ioctls and shared (mmap) area.
 */
#ifndef SCRATCH_UAPI_H
#define SCRATCH_UAPI_H

#include <linux/types.h>
#include <linux/ioctl.h>

#define SCRATCH_DEVICE_NAME	"scratch"

/* What mmap shows: updated by the timer and the GPIO interrupt. */
struct scratch_shared {
	__u32 ticks;            /* timer periods since the last reset */
	__u32 edges;            /* GPIO edges since the last reset */
	__u32 level;            /* pin level at the last edge */
	__u32 period_us;        /* current timer period */
};

#define SCRATCH_GET_EDGES	_IOR('S', 1, __u32)
#define SCRATCH_SET_PERIOD	_IOW('S', 2, __u32)    /* microseconds, 100..1000000 */

#endif /* SCRATCH_UAPI_H */
