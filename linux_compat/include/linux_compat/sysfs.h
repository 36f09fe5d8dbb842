/*
 * linux_compat/sysfs.h — sysfs from the API side: what user space on Linux
 * reads and writes under /sys, for hacks, tests and ev3sim.
 *
 * Paths name a device's file as Linux lays them out:
 *   /sys/class/<class>/<device>/<attribute>
 *   /sys/bus/<bus>/devices/<device>/<attribute>
 * with a named attribute group as a subdirectory (<device>/<group>/<attribute>).
 * A device's files are its class's dev_groups, its own groups, those
 * device_create_file added, its bound driver's dev_groups, and "dev"
 * ("major:minor\n") when it has a device number.
 *
 * The caller is treated as the files' owner without CAP_DAC_OVERRIDE: a read
 * needs the mode's owner read bit, a write its owner write bit (-EACCES
 * otherwise, as open(2) gives).  Errors: -EINVAL (NULL path or buffer, a
 * path outside /sys), -ENOENT (no such device or file), -EISDIR (a
 * directory), -EACCES, -E2BIG (a write longer than PAGE_SIZE, as sysfs's
 * atomic writes), -EIO (no show/store behind a permitted mode, as Linux's
 * dev_attr_show/store), -ENOMEM, or show/store's own error.  Both run show
 * or store in process context (they may sleep) and are reported elsewhere.
 */
#ifndef _LINUX_COMPAT_SYSFS_H
#define _LINUX_COMPAT_SYSFS_H

#include <linux/types.h>
#include <linux/kobject.h>

/* Reads the file at path from its start: show() fills a page, the first
 * len bytes of it are copied to buf; returns the bytes copied (no NUL is
 * added) or a negative errno. */
ssize_t lx_sysfs_read(const char *path, char *buf, size_t len);
/* Writes len bytes of buf to the file at path (store() gets them
 * NUL-terminated); returns store's result or a negative errno. */
ssize_t lx_sysfs_write(const char *path, const char *buf, size_t len);
/* How many times sysfs_notify named the file at path (0 if never, or no such file). */
unsigned int lx_sysfs_notify_count(const char *path);
/* Calls fn(path, ctx) for every readable file of every class device, in
 * registration order (for dumps, e.g. ev3sim's); returns how many. */
unsigned int lx_sysfs_for_each_class_file(void (*fn)(const char *path, void *ctx), void *ctx);

/* Uevents recorded (kobject_uevent, device add/remove, driver bind/unbind). */
#define LX_UEVENT_LOG	32      /* the newest ones kept */
#define LX_UEVENT_VARS	4       /* extra variables kept per event */
struct lx_uevent {
	enum kobject_action action;
	char devpath[96];       /* "/devices/platform/ev3-ports/lego-port/port0" */
	char subsystem[24];     /* the class or bus name, "" if none */
	char vars[LX_UEVENT_VARS][40];
	unsigned int nvars;
};
/* The number of uevents since boot. */
unsigned int lx_uevent_count(void);
/* Uevent number i (0 = first since boot), or NULL if no longer kept. */
const struct lx_uevent *lx_uevent_get(unsigned int i);
/* Linux's name of an action ("add", "change", ...). */
const char *lx_uevent_action_name(enum kobject_action action);

/* Forgets classes, uevents and notifications (lx_io_boot). */
void lx_sysfs_boot(void);

/* Registers a class of linux_compat's own at boot (lx_io_boot), before any
 * task runs: no lock. */
struct class;
void lx_class_register_boot(struct class *cls);
/* Resets the input core: no devices, the input class registered (lx_io_boot). */
void lx_input_boot(void);

/* The driver core's side (src/driver_core.c calls them, core locked). */
struct device;
/* Checks dev's class (registered, its name free there) and the modes of its
 * files, and adds dev to its class: 0, -EINVAL or -EEXIST. */
int lx_sysfs_device_add(struct device *dev);
/* Removes dev from its class and forgets its files and notifications. */
void lx_sysfs_device_del(struct device *dev);
/* The device called name on the bus called bus_name (added), or NULL. */
struct device *lx_bus_find_device_by_name(const char *bus_name, const char *name);

#endif /* _LINUX_COMPAT_SYSFS_H */
