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

/* A uevent's variables as a bus, class or device type adds them
 * (Linux 6.1's struct kobj_uevent_env, its sizes). */
#define UEVENT_NUM_ENVP		64
#define UEVENT_BUFFER_SIZE	2048
struct kobj_uevent_env {
	char *argv[3];
	char *envp[UEVENT_NUM_ENVP];
	int envp_idx;
	char buf[UEVENT_BUFFER_SIZE];
	int buflen;
};

/* Appends one "KEY=value" variable, printf-style: 0, or -ENOMEM when env is full. */
__printf(2, 3) int add_uevent_var(struct kobj_uevent_env *env, const char *format, ...);

/* Records a uevent of the device that embeds kobj (with its class's and
 * device type's variables, as Linux's dev_uevent adds them); 0. */
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
