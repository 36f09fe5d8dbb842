/*
 * linux/cdev.h — char devices as Linux 2.6+ registers them: a device number
 * region (register_chrdev_region / alloc_chrdev_region, linux/fs.h), then a
 * struct cdev added for some of its numbers.
 *
 * There is no mknod or udev: cdev_add puts each number into ev3lx's device
 * registry (linux_compat/devfs.h) under the region's name - /dev/<name> for a
 * one-number region, /dev/<name><n> (n counted from the region's first minor)
 * for a larger one - the names a driver's device_create would typically give.
 * Device numbers are __kernel_dev_t (linux/kdev_t.h explains why not dev_t).
 */
#ifndef _LINUX_CDEV_H
#define _LINUX_CDEV_H

#include <linux/types.h>
#include <linux/kdev_t.h>
#include <linux/list.h>
#include <linux/fs.h>

struct module;

struct cdev {
	struct module *owner;
	const struct file_operations *ops;
	__kernel_dev_t dev;
	unsigned int count;
	bool lx_added;
	bool lx_allocated;     /* from cdev_alloc: cdev_del frees it */
};

/* Initialises cdev with fops (zeroing it first). */
void cdev_init(struct cdev *cdev, const struct file_operations *fops);
/* A zeroed, kmalloc'd cdev (freed by cdev_del), or NULL. */
struct cdev *cdev_alloc(void);
/* Makes the count numbers from dev live: 0, -EINVAL (no region holds them),
 * -EBUSY or -ENOMEM (registry full).  Process context. */
int cdev_add(struct cdev *cdev, __kernel_dev_t dev, unsigned int count);
/* Removes the numbers cdev_add made live (open files keep working). */
void cdev_del(struct cdev *cdev);

#endif /* _LINUX_CDEV_H */
