/* SPDX-License-Identifier: GPL-2.0 */
/*
 * nxt_us_uapi.h - the user interface of nxt_us: read() of /dev/nxt_usN
 * gives the distance in centimetres as text ("42\n"; 255 means no echo),
 * NXT_US_SINGLE_SHOT measures once and returns all eight echoes, and
 * NXT_US_CONTINUOUS goes back to continuous measurement.
 */
#ifndef NXT_US_UAPI_H
#define NXT_US_UAPI_H

#include <linux/ioctl.h>
#include <linux/types.h>

struct nxt_us_echoes {
	__u8 cm[8];		/* the echoes of one ping, nearest first; 0 past the last */
};

#define NXT_US_SINGLE_SHOT	_IOR('u', 1, struct nxt_us_echoes)
#define NXT_US_CONTINUOUS	_IO('u', 2)

#endif /* NXT_US_UAPI_H */
