/*
 * linux/kdev_t.h — device numbers: MAJOR, MINOR, MKDEV.
 *
 * Device numbers are __kernel_dev_t (u32, Linux's 12-bit major / 20-bit
 * minor encoding): MKDEV returns one, struct inode's i_rdev and the chrdev
 * region calls take one, and dev_t is one, as in Linux.  A hosted test
 * program whose C library defined its own (wider) dev_t first keeps that one
 * (the C libraries' __dev_t_defined guard), and must use __kernel_dev_t with
 * the chrdev calls.
 */
#ifndef _LINUX_KDEV_T_H
#define _LINUX_KDEV_T_H

#include <linux/types.h>

typedef u32 __kernel_dev_t;
#ifndef __dev_t_defined
#define __dev_t_defined
typedef __kernel_dev_t dev_t;
#endif

#define MINORBITS	20
#define MINORMASK	((1U << MINORBITS) - 1)

#define MAJOR(dev)	((unsigned int)((dev) >> MINORBITS))
#define MINOR(dev)	((unsigned int)((dev) & MINORMASK))
#define MKDEV(ma, mi)	((__kernel_dev_t)(((__kernel_dev_t)(ma) << MINORBITS) | (mi)))

#endif /* _LINUX_KDEV_T_H */
