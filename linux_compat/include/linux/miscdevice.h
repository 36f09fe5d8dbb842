/*
 * linux/miscdevice.h — misc character devices (major 10).
 *
 * misc_register (linux_compat/src/devfs.c, process context) adds the device
 * to ev3lx's registry as /dev/<name>: 0, -EINVAL (no name or fops),
 * -EBUSY (minor or name taken, or no dynamic minor left), -ENOMEM (registry
 * full).  MISC_DYNAMIC_MINOR picks a free minor (63 downwards, as 2.6.33)
 * and misc_deregister hands it back.  Opening the device sets
 * file->private_data to the struct miscdevice before the driver's .open, as
 * Linux's misc_open does.  The first three members keep Linux's order, so
 * LEGO's positional initialisers { minor, name, fops } work.
 */
#ifndef _LINUX_MISCDEVICE_H
#define _LINUX_MISCDEVICE_H

#include <linux/types.h>
#include <linux/fs.h>
#include <linux/kdev_t.h>

#define MISC_MAJOR		10
#define MISC_DYNAMIC_MINOR	255
#define MISC_DYNAMIC_MINORS	64

struct device;
struct attribute_group;

struct miscdevice {
	int minor;
	const char *name;
	const struct file_operations *fops;
	struct list_head list;
	struct device *parent;
	struct device *this_device;
	const struct attribute_group **groups;
	const char *nodename;
	umode_t mode;
};

/* Registers misc as /dev/<misc->name> (see above).  Process context. */
int misc_register(struct miscdevice *misc);
/* Removes misc from the registry (void since Linux 4.3; files already open keep working). */
void misc_deregister(struct miscdevice *misc);

#endif /* _LINUX_MISCDEVICE_H */
