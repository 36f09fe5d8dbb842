/*
 * linux/version.h — the kernel version a driver is built against.  ev3lx
 * implements the API of current Linux for drivers written since 2.6.33; it
 * reports the release whose API it follows (6.1, Debian 12's kernel), so
 * version tests in drivers take their modern branch.
 */
#ifndef _LINUX_VERSION_H
#define _LINUX_VERSION_H

#define KERNEL_VERSION(a, b, c)	(((a) << 16) + ((b) << 8) + ((c) > 255 ? 255 : (c)))
#define LINUX_VERSION_MAJOR	6
#define LINUX_VERSION_PATCHLEVEL	1
#define LINUX_VERSION_SUBLEVEL	0
#define LINUX_VERSION_CODE	KERNEL_VERSION(LINUX_VERSION_MAJOR, LINUX_VERSION_PATCHLEVEL, \
					       LINUX_VERSION_SUBLEVEL)

#endif /* _LINUX_VERSION_H */
