/*
 * linux/kdev_t.h — device numbers: MAJOR, MINOR, MKDEV.
 *
 * dev_t is the C library's own type (<sys/types.h>), so Linux headers and
 * C library headers may meet in one translation unit; on newlib (AM1808)
 * that type is only 16 bits wide.  ev3lx therefore keeps device numbers in
 * __kernel_dev_t (u32, Linux's 12-bit major / 20-bit minor encoding): MKDEV
 * returns one and struct inode's i_rdev is one.
 */
#ifndef _LINUX_KDEV_T_H
#define _LINUX_KDEV_T_H

#include <sys/types.h>
#include <linux/types.h>

typedef u32 __kernel_dev_t;

#define MINORBITS	20
#define MINORMASK	((1U << MINORBITS) - 1)

#define MAJOR(dev)	((unsigned int)((dev) >> MINORBITS))
#define MINOR(dev)	((unsigned int)((dev) & MINORMASK))
#define MKDEV(ma, mi)	((__kernel_dev_t)(((__kernel_dev_t)(ma) << MINORBITS) | (mi)))

#endif /* _LINUX_KDEV_T_H */
