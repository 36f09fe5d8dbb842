/* SPDX-License-Identifier: GPL-2.0 */
/*
 * edge_watch_uapi.h - the user interface of edge_watch: /dev/edge_watch
 * reads give one line per event ("edges=N timeouts=M\n"), poll reports a new
 * event, and EDGE_WATCH_GET counts both.
 */
#ifndef EDGE_WATCH_UAPI_H
#define EDGE_WATCH_UAPI_H

#include <linux/ioctl.h>
#include <linux/types.h>

struct edge_watch_counts {
	__u32 edges;		/* edges seen on the pin */
	__u32 timeouts;		/* watchdog periods that ended without an edge */
};

#define EDGE_WATCH_GET		_IOR('e', 1, struct edge_watch_counts)
#define EDGE_WATCH_RESET	_IO('e', 2)

#endif /* EDGE_WATCH_UAPI_H */
