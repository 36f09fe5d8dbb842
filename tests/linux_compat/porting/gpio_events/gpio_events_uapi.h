/* SPDX-License-Identifier: GPL-2.0 */
/*
 * gpio_events_uapi.h - the user interface of gpio_events: each read() of
 * /dev/gpio_eventsN returns whole records, one per rising edge of the
 * watched input, oldest first; GPIO_EVENTS_STATS counts them.
 */
#ifndef GPIO_EVENTS_UAPI_H
#define GPIO_EVENTS_UAPI_H

#include <linux/ioctl.h>
#include <linux/types.h>

struct gpio_event {
	__u64 timestamp_ns;	/* CLOCK_MONOTONIC time of the edge, taken in the hard IRQ */
	__u32 seq;		/* edge number, from 0 */
	__u32 level;		/* the input's logical level when the thread ran */
};

struct gpio_events_stats {
	__u32 edges;		/* edges the hard handler saw */
	__u32 handled;		/* thread runs */
	__u32 dropped;		/* edges lost to a full queue */
};

#define GPIO_EVENTS_STATS	_IOR('g', 1, struct gpio_events_stats)

#endif /* GPIO_EVENTS_UAPI_H */
