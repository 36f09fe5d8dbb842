/*
 * linux/device.h — the driver core (Linux 6.1's include/linux/device.h,
 * device/bus.h, device/driver.h), implemented by linux_compat/src/driver_core.c
 * (drivers/base/core.c, bus.c, dd.c) and src/devres.c (drivers/base/devres.c).
 *
 * struct device has a name, parent, bus, bound driver, platform and driver
 * data, an of_node and release, a class and attribute groups, whose files
 * src/sysfs.c serves (linux_compat/sysfs.h reads and writes them by path,
 * /sys/class/<class>/<device>/<attribute>, /sys/bus/<bus>/devices/...).  A bus
 * (bus_register) keeps its devices and drivers; device_add and
 * driver_register bind every matching pair through the bus's match and
 * probe (else the driver's probe), in process context; a failing probe
 * releases the device's devres and clears its driver and drvdata; -ENODEV
 * and -ENXIO fail silently, -EPROBE_DEFER puts the device on the deferred
 * list, retried whenever another device binds (synchronously, at the end
 * of the registration that bound it, where Linux queues a work item).
 * Unbinding (device_del, driver_unregister, most recent binding first)
 * calls remove, then releases devres in reverse order of acquisition.
 * The driver core may be re-entered from probe and remove (a probe that
 * registers a child device binds it on the spot).
 */
#ifndef _LINUX_DEVICE_H
#define _LINUX_DEVICE_H

#include <linux/types.h>
#include <linux/compiler.h>
#include <linux/list.h>
#include <linux/gfp.h>
#include <linux/limits.h>
#include <linux/printk.h>
#include <linux/container_of.h>
#include <linux/kdev_t.h>
#include <linux/kobject.h>
#include <linux/sysfs.h>
#include <linux/uidgid.h>
#include <linux/err.h>          /* as Linux's device.h reaches them (through kobject.h, */
#include <linux/workqueue.h>    /* ioport.h, mutex.h ...): drivers rely on the errno */
#include <asm/page.h>           /* values, delayed work and PAGE_SIZE it brings */

struct module;
struct device;
struct device_driver;
struct device_node;
struct of_device_id;
struct resource;
struct lx_devres;
struct class;
struct attribute_group;

struct bus_type {
	const char *name;
	const char *dev_name;
	/* 0: no match; positive: match; -EPROBE_DEFER: defer the device */
	int (*match)(struct device *dev, struct device_driver *drv);
	int (*probe)(struct device *dev);
	void (*remove)(struct device *dev);
	void (*shutdown)(struct device *dev);
	struct list_head lx_devices;    /* ev3lx: devices added, in order */
	struct list_head lx_drivers;    /* ev3lx: drivers registered, in order */
	struct list_head lx_node;       /* ev3lx: on the list of buses */
	bool lx_registered;
};

enum probe_type {
	PROBE_DEFAULT_STRATEGY,
	PROBE_PREFER_ASYNCHRONOUS,
	PROBE_FORCE_SYNCHRONOUS,
};

struct device_driver {
	const char *name;
	struct bus_type *bus;
	struct module *owner;
	const char *mod_name;
	bool suppress_bind_attrs;
	enum probe_type probe_type;
	const struct of_device_id *of_match_table;
	const struct attribute_group **groups;      /* the driver's own files (accepted; not served:
						     * there is no /sys/bus/<bus>/drivers here) */
	const struct attribute_group **dev_groups;  /* files of each bound device, after probe */
	int (*probe)(struct device *dev);
	int (*remove)(struct device *dev);
	void (*shutdown)(struct device *dev);
	struct list_head lx_node;       /* ev3lx: on its bus's driver list */
	struct list_head lx_bound;      /* ev3lx: its devices, in binding order */
};

/*
 * A kind of device (Linux 6.1's struct device_type): its files beside the
 * class's, its uevent variables, its /dev name and its release, used when
 * the device has no release of its own (before the class's).
 */
struct device_type {
	const char *name;
	const struct attribute_group **groups;
	int (*uevent)(struct device *dev, struct kobj_uevent_env *env);
	char *(*devnode)(struct device *dev, umode_t *mode, kuid_t *uid, kgid_t *gid);
	void (*release)(struct device *dev);
};

struct device {
	struct device *parent;
	const struct device_type *type;
	const char *init_name;          /* the device's name (dev_name) */
	u32 id;                         /* its instance number, where the bus or class numbers them */
	struct bus_type *bus;
	struct device_driver *driver;   /* bound driver, NULL while unbound */
	void *platform_data;            /* board-specific data (board files set it) */
	void *driver_data;              /* dev_set_drvdata */
	struct device_node *of_node;    /* its board description node, if any */
	u64 *dma_mask;
	u64 coherent_dma_mask;
	void (*release)(struct device *dev);
	struct class *class;
	const struct attribute_group **groups;  /* its own files (beside its class's) */
	__kernel_dev_t devt;            /* dev_t; a "dev" file "major:minor" when MAJOR(devt) != 0
					 * (the kernel type: a hosted test may see the C library's dev_t) */
	struct kobject kobj;            /* its name; sysfs_notify, kobject_uevent */
	struct lx_devres *lx_devres;    /* ev3lx: managed resources, newest first */
	struct list_head lx_bus_node;   /* ev3lx: on its bus's device list */
	struct list_head lx_bound_node; /* ev3lx: on its driver's list */
	struct list_head lx_deferred;   /* ev3lx: on the deferred-probe list */
	struct list_head lx_class_node; /* ev3lx: on its class's device list */
	struct list_head lx_files;      /* ev3lx: device_create_file's attributes */
	int lx_refcount;                /* ev3lx: get_device/put_device */
	bool lx_added;                  /* ev3lx: between device_add and device_del */
	bool lx_probing;                /* ev3lx: inside its driver's probe */
	char lx_name[32];               /* ev3lx: dev_set_name's buffer */
};

static inline const char *dev_name(const struct device *dev)
{
	return dev->init_name ? dev->init_name : "(unnamed)";
}

static inline void *dev_get_drvdata(const struct device *dev)
{
	return dev->driver_data;
}

static inline void dev_set_drvdata(struct device *dev, void *data)
{
	dev->driver_data = data;
}

static inline void *dev_get_platdata(const struct device *dev)
{
	return dev->platform_data;
}

static inline struct device_node *dev_of_node(struct device *dev)
{
	return dev->of_node;
}

/* Names dev (truncated to 31 characters); 0. */
__printf(2, 3) int dev_set_name(struct device *dev, const char *fmt, ...);

/* Registers a bus: its device and driver lists start empty.  -EINVAL without
 * a name, -EBUSY if a bus of that name is registered. */
int bus_register(struct bus_type *bus);
/* Unregisters a bus; its devices and drivers must be gone (reported if not). */
void bus_unregister(struct bus_type *bus);

/* Prepares dev for device_add: one reference, no driver, no devres. */
void device_initialize(struct device *dev);
/* Adds dev to its bus (dev->bus; none: added, never bound) and binds it to
 * the first matching driver.  0, or -EINVAL (unnamed, added twice). */
int device_add(struct device *dev);
/* device_initialize + device_add. */
int device_register(struct device *dev);
/* Unbinds dev and removes it from its bus. */
void device_del(struct device *dev);
/* device_del + put_device. */
void device_unregister(struct device *dev);
/* Takes a reference; returns dev (NULL for NULL). */
struct device *get_device(struct device *dev);
/* Drops a reference; the last calls release (a device without release is
 * reported, as Linux's "does not have a release() function" WARN). */
void put_device(struct device *dev);

/* Binds dev to drv (device_bind_driver's probe path, under the core lock):
 * 0 if bound, the probe's error otherwise.  For buses that bind by hand. */
int device_driver_attach(struct device_driver *drv, struct device *dev);
/* Tries every driver of dev's bus again (bus_rescan_devices for one device). */
int device_attach(struct device *dev);
/* Unbinds dev from its driver (remove, devres, drvdata). */
void device_release_driver(struct device *dev);
/* Whether dev is added (between device_add and device_del). */
static inline bool device_is_registered(struct device *dev)
{
	return dev->lx_added;
}

/* Whether dev is bound to a driver. */
static inline bool device_is_bound(struct device *dev)
{
	return dev->driver != NULL && !dev->lx_probing;
}

/* Registers drv on drv->bus and binds every matching unbound device.
 * 0, -EINVAL (no bus, no name), -EBUSY (a driver of that name on the bus). */
int driver_register(struct device_driver *drv);
/* Unbinds drv's devices (most recent first) and removes drv from its bus. */
void driver_unregister(struct device_driver *drv);
/* The driver called name on bus, or NULL. */
struct device_driver *driver_find(const char *name, struct bus_type *bus);

/* Runs the deferred probes now (Linux's driver_deferred_probe_trigger). */
void driver_deferred_probe_trigger(void);
/* The number of devices waiting on the deferred-probe list. */
unsigned int lx_deferred_probe_count(void);

/* Logs err for dev in a probe path and returns it: -EPROBE_DEFER quietly
 * (debug level), any other as dev_err "error <err>: <message>". */
__printf(3, 4) int dev_err_probe(const struct device *dev, int err, const char *fmt, ...);

/* devres (src/devres.c): resources tied to the device's binding, released
 * in reverse order of acquisition when the driver unbinds or its probe
 * fails (and any left on an unbound device when its last reference goes). */
typedef void (*dr_release_t)(struct device *dev, void *res);
typedef int (*dr_match_t)(struct device *dev, void *res, void *match_data);

/* Allocates a devres payload of size bytes (zeroed) that release frees;
 * not yet on any device. */
void *devres_alloc(dr_release_t release, size_t size, gfp_t gfp);
/* Adds res (from devres_alloc) to dev. */
void devres_add(struct device *dev, void *res);
/* Frees res (from devres_alloc) that was never added. */
void devres_free(void *res);
/* Finds the newest of dev's resources with release and match (NULL: any),
 * removes it, runs release and frees it; 0 or -ENOENT. */
int devres_release(struct device *dev, dr_release_t release, dr_match_t match, void *match_data);
/* Like devres_release without running release; 0 or -ENOENT. */
int devres_destroy(struct device *dev, dr_release_t release, dr_match_t match, void *match_data);
/* Releases all of dev's resources, newest first; returns how many. */
int devres_release_all(struct device *dev);

void *devm_kmalloc(struct device *dev, size_t size, gfp_t gfp) __malloc;
static inline void *devm_kzalloc(struct device *dev, size_t size, gfp_t gfp)
{
	return devm_kmalloc(dev, size, gfp | __GFP_ZERO);
}
static inline void *devm_kmalloc_array(struct device *dev, size_t n, size_t size, gfp_t flags)
{
	if (size != 0 && n > SIZE_MAX / size)
		return NULL;
	return devm_kmalloc(dev, n * size, flags);
}
static inline void *devm_kcalloc(struct device *dev, size_t n, size_t size, gfp_t flags)
{
	return devm_kmalloc_array(dev, n, size, flags | __GFP_ZERO);
}
/* Frees p from devm_kmalloc now; a p dev does not manage is reported (WARN). */
void devm_kfree(struct device *dev, const void *p);
char *devm_kstrdup(struct device *dev, const char *s, gfp_t gfp) __malloc;

/* Calls action(data) when dev's devres is released; 0 or -ENOMEM. */
int devm_add_action(struct device *dev, void (*action)(void *), void *data);
/* devm_add_action, calling action(data) at once if it cannot be added. */
static inline int devm_add_action_or_reset(struct device *dev, void (*action)(void *), void *data)
{
	int ret = devm_add_action(dev, action, data);

	if (ret)
		action(data);
	return ret;
}
/* Removes the (action, data) entry without calling it (reported if absent). */
void devm_remove_action(struct device *dev, void (*action)(void *), void *data);
/* Removes the (action, data) entry and calls it (reported if absent). */
void devm_release_action(struct device *dev, void (*action)(void *), void *data);

/* Claims res for dev and maps it, both undone on unbind: the mapping, or
 * ERR_PTR(-EINVAL) (NULL or not memory), -EBUSY (region taken) or -ENOMEM
 * (cannot be mapped), each logged. */
void __iomem *devm_ioremap_resource(struct device *dev, const struct resource *res);

/* ---- attributes (src/sysfs.c) ---- */

struct device_attribute {
	struct attribute attr;
	ssize_t (*show)(struct device *dev, struct device_attribute *attr, char *buf);
	ssize_t (*store)(struct device *dev, struct device_attribute *attr, const char *buf,
			 size_t count);
};

#define DEVICE_ATTR(_name, _mode, _show, _store) \
	struct device_attribute dev_attr_##_name = __ATTR(_name, _mode, _show, _store)
#define DEVICE_ATTR_RW(_name)	struct device_attribute dev_attr_##_name = __ATTR_RW(_name)
#define DEVICE_ATTR_ADMIN_RW(_name) \
	struct device_attribute dev_attr_##_name = __ATTR_RW_MODE(_name, 0600)
/* A driver's file (Linux 6.1's struct driver_attribute), for its groups. */
struct driver_attribute {
	struct attribute attr;
	ssize_t (*show)(struct device_driver *driver, char *buf);
	ssize_t (*store)(struct device_driver *driver, const char *buf, size_t count);
};

#define DRIVER_ATTR_RW(_name)	struct driver_attribute driver_attr_##_name = __ATTR_RW(_name)
#define DRIVER_ATTR_RO(_name)	struct driver_attribute driver_attr_##_name = __ATTR_RO(_name)
#define DRIVER_ATTR_WO(_name)	struct driver_attribute driver_attr_##_name = __ATTR_WO(_name)

#define DEVICE_ATTR_RO(_name)	struct device_attribute dev_attr_##_name = __ATTR_RO(_name)
#define DEVICE_ATTR_ADMIN_RO(_name) \
	struct device_attribute dev_attr_##_name = __ATTR_RO_MODE(_name, 0400)
#define DEVICE_ATTR_WO(_name)	struct device_attribute dev_attr_##_name = __ATTR_WO(_name)

static inline struct device *kobj_to_dev(struct kobject *kobj)
{
	return container_of(kobj, struct device, kobj);
}

/* Adds one attribute file to dev (process context): 0, -EINVAL (no device
 * or name), -EEXIST (a file of that name), -ENOMEM.  A mode with write bits
 * but no store, or read bits but no show, is reported as Linux WARNs. */
int device_create_file(struct device *dev, const struct device_attribute *attr);
/* Removes a file device_create_file added (process context). */
void device_remove_file(struct device *dev, const struct device_attribute *attr);

/* ---- classes (src/sysfs.c; Linux 6.1's include/linux/device/class.h) ---- */

struct class {
	const char *name;
	struct module *owner;
	const struct attribute_group **class_groups;
	const struct attribute_group **dev_groups;  /* files of every device of the class */
	int (*dev_uevent)(struct device *dev, struct kobj_uevent_env *env);
	char *(*devnode)(struct device *dev, umode_t *mode);
	void (*class_release)(struct class *class);
	void (*dev_release)(struct device *dev);     /* release for devices without their own */
	struct list_head lx_node;       /* ev3lx: on the list of classes */
	struct list_head lx_devices;    /* ev3lx: its devices, in order of device_add */
	bool lx_registered;
};

/* Registers cls (/sys/class/<name>): 0, -EINVAL (no name), -EEXIST (a class
 * of that name).  Process context. */
int class_register(struct class *cls);
/* Unregisters cls; devices left in it are reported.  Process context. */
void class_unregister(struct class *cls);
/* Allocates and registers a class called name: it, or ERR_PTR(-ENOMEM,
 * -EINVAL, -EEXIST).  Linux 6.1's two-argument form (6.4 dropped owner). */
struct class *__class_create(struct module *owner, const char *name);
#define class_create(owner, name)	__class_create(owner, name)
/* Unregisters and frees a class from class_create (NULL or an error: nothing). */
void class_destroy(struct class *cls);
/* The device of cls called name, with a reference (put_device it), or NULL. */
struct device *class_find_device_by_name(struct class *cls, const char *name);

/* Creates and registers a device of cls (its drvdata, number devt, name from
 * fmt): it, or ERR_PTR.  Freed by device_destroy/device_unregister. */
__printf(5, 6) struct device *device_create(struct class *cls, struct device *parent, __kernel_dev_t devt,
					    void *drvdata, const char *fmt, ...);
/* The same with extra attribute groups. */
__printf(6, 7) struct device *device_create_with_groups(struct class *cls, struct device *parent,
							__kernel_dev_t devt, void *drvdata,
							const struct attribute_group **groups,
							const char *fmt, ...);
/* Unregisters the device of cls with number devt (reported if none). */
void device_destroy(struct class *cls, __kernel_dev_t devt);

#define lx_dev_driver_name(dev)	((dev)->driver ? (dev)->driver->name : "")
#define dev_printk(level, dev, fmt, ...) \
	printk(level "%s %s: " fmt, lx_dev_driver_name(dev), dev_name(dev), ##__VA_ARGS__)
#define dev_emerg(dev, fmt, ...)	dev_printk(KERN_EMERG, dev, fmt, ##__VA_ARGS__)
#define dev_alert(dev, fmt, ...)	dev_printk(KERN_ALERT, dev, fmt, ##__VA_ARGS__)
#define dev_crit(dev, fmt, ...)		dev_printk(KERN_CRIT, dev, fmt, ##__VA_ARGS__)
#define dev_err(dev, fmt, ...)		dev_printk(KERN_ERR, dev, fmt, ##__VA_ARGS__)
#define dev_warn(dev, fmt, ...)		dev_printk(KERN_WARNING, dev, fmt, ##__VA_ARGS__)
#define dev_notice(dev, fmt, ...)	dev_printk(KERN_NOTICE, dev, fmt, ##__VA_ARGS__)
#define dev_info(dev, fmt, ...)		dev_printk(KERN_INFO, dev, fmt, ##__VA_ARGS__)
#define dev_err_ratelimited(dev, fmt, ...)	dev_err(dev, fmt, ##__VA_ARGS__)
#define dev_warn_ratelimited(dev, fmt, ...)	dev_warn(dev, fmt, ##__VA_ARGS__)
#define dev_err_once(dev, fmt, ...)	dev_err(dev, fmt, ##__VA_ARGS__)
#define dev_warn_once(dev, fmt, ...)	dev_warn(dev, fmt, ##__VA_ARGS__)
#define dev_dbg(dev, fmt, ...)		({ if (0) dev_printk(KERN_DEBUG, dev, fmt, ##__VA_ARGS__); })

#endif /* _LINUX_DEVICE_H */
