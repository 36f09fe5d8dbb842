/*
 * linux/kobject.h — the part of Linux 6.1's kobject a driver touches: the
 * kobject embedded in struct device (kobj_to_dev, sysfs_notify on it) and
 * uevents (kobject_uevent, kobject_uevent_env), implemented by
 * linux_compat/src/sysfs.c.  A kobject here is always a device's: there is no
 * kset, ktype or reference count of its own (the device's is used).
 * Uevents are recorded, not sent: linux_compat/sysfs.h reads them back as
 * udev would receive them (action, devpath, subsystem, the extra variables).
 */
#ifndef _LINUX_KOBJECT_H
#define _LINUX_KOBJECT_H

#include <linux/types.h>
#include <linux/compiler.h>

struct kobject {
	const char *name;
};

/* Linux's enum kobject_action, in its order (the action strings follow it). */
enum kobject_action {
	KOBJ_ADD,
	KOBJ_REMOVE,
	KOBJ_CHANGE,
	KOBJ_MOVE,
	KOBJ_ONLINE,
	KOBJ_OFFLINE,
	KOBJ_BIND,
	KOBJ_UNBIND,
};

/* Records a uevent of the device that embeds kobj; 0. */
int kobject_uevent(struct kobject *kobj, enum kobject_action action);
/* The same with extra "KEY=value" variables (envp, NULL-terminated, at most
 * LX_UEVENT_VARS are kept); 0, or -EINVAL for a malformed variable. */
int kobject_uevent_env(struct kobject *kobj, enum kobject_action action, char *envp[]);
/* The name of the kobject (the device's name). */
static inline const char *kobject_name(const struct kobject *kobj)
{
	return kobj->name;
}

#endif /* _LINUX_KOBJECT_H */
