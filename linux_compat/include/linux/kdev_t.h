/*
 * linux/kdev_t.h — device numbers: dev_t, MAJOR, MINOR, MKDEV.
 *
 * dev_t: with glibc (host builds) it is the C library's own type, so a test
 * may include <sys/types.h> and Linux headers in either order; otherwise
 * (newlib, AM1808) it is Linux's u32.  Either way it holds Linux's 12-bit
 * major / 20-bit minor encoding.
 */
#ifndef _LINUX_KDEV_T_H
#define _LINUX_KDEV_T_H

#include <linux/types.h>

#if defined(__GLIBC__)
#include <sys/types.h>
#else
typedef u32 dev_t;
#endif

#define MINORBITS	20
#define MINORMASK	((1U << MINORBITS) - 1)

#define MAJOR(dev)	((unsigned int)((dev) >> MINORBITS))
#define MINOR(dev)	((unsigned int)((dev) & MINORMASK))
#define MKDEV(ma, mi)	((dev_t)(((dev_t)(ma) << MINORBITS) | (mi)))

#endif /* _LINUX_KDEV_T_H */
