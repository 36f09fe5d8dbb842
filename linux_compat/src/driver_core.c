/*
 * driver_core.c — buses, devices, drivers and their binding (linux/device.h
 * states the contract), after Linux 6.1's drivers/base/core.c, bus.c and
 * dd.c.  Every list is changed in process context under one core lock,
 * which the task holding it may take again: a probe that registers a child
 * device, or a remove that unregisters one, re-enters the core.  Deferred
 * probes run when the outermost holder releases the lock after a device
 * bound (where Linux queues deferred_probe_work).
 */
#include <linux/device.h>
#include <linux/errno.h>
#include <linux/kernel.h>
#include <linux/mutex.h>
#include <linux/sched.h>
#include <linux/string.h>
#include <linux_compat/context.h>
#include <linux_compat/irq.h>
#include <linux_compat/report.h>
#include <linux_compat/sysfs.h>

static DEFINE_MUTEX(core_mutex);
static struct task_struct *core_owner;
static unsigned int core_depth;
static LIST_HEAD(buses);
static LIST_HEAD(deferred_pending);
static bool deferred_trigger;

static void run_deferred_probes(void);

/* Takes the core lock (again, if the calling task holds it). */
static void core_lock(void);
void lx_driver_core_lock(void)
{
	core_lock();
}

static void core_unlock(void);
void lx_driver_core_unlock(void)
{
	core_unlock();
}

static void core_lock(void)
{
	if (core_depth && core_owner == current) {
		core_depth++;
		return;
	}
	mutex_lock(&core_mutex);
	core_owner = current;
	core_depth = 1;
}

/* Releases one level of the core lock; the outermost release first runs the
 * deferred probes a binding triggered. */
static void core_unlock(void)
{
	if (core_depth == 1) {
		while (deferred_trigger) {
			deferred_trigger = false;
			run_deferred_probes();
		}
	}
	if (--core_depth)
		return;
	core_owner = NULL;
	mutex_unlock(&core_mutex);
}

int dev_set_name(struct device *dev, const char *fmt, ...)
{
	va_list args;

	va_start(args, fmt);
	vsnprintf(dev->lx_name, sizeof(dev->lx_name), fmt, args);
	va_end(args);
	dev->init_name = dev->lx_name;
	return 0;
}

int bus_register(struct bus_type *bus)
{
	struct bus_type *b;

	might_sleep();
	if (!bus || !bus->name)
		return -EINVAL;
	core_lock();
	list_for_each_entry(b, &buses, lx_node) {
		if (b == bus || !strcmp(b->name, bus->name)) {
			core_unlock();
			pr_err("bus '%s' is already registered\n", bus->name);
			return -EBUSY;
		}
	}
	INIT_LIST_HEAD(&bus->lx_devices);
	INIT_LIST_HEAD(&bus->lx_drivers);
	list_add_tail(&bus->lx_node, &buses);
	bus->lx_registered = true;
	core_unlock();
	return 0;
}

void bus_unregister(struct bus_type *bus)
{
	might_sleep();
	if (!bus || !bus->lx_registered)
		return;
	core_lock();
	if (!list_empty(&bus->lx_devices) || !list_empty(&bus->lx_drivers))
		lx_report("bus_unregister with devices or drivers left", __FILE__, __LINE__,
			  "bus '%s' still has %s", bus->name,
			  list_empty(&bus->lx_devices) ? "drivers" : "devices");
	list_del_init(&bus->lx_node);
	bus->lx_registered = false;
	core_unlock();
}

/* Whether drv matches dev: the bus's match (any driver if it has none). */
static int driver_match_device(struct device_driver *drv, struct device *dev)
{
	return drv->bus->match ? drv->bus->match(dev, drv) : 1;
}

/* Takes dev off the deferred list if it is on it.  Core locked. */
static void deferred_probe_del(struct device *dev)
{
	if (!list_empty(&dev->lx_deferred))
		list_del_init(&dev->lx_deferred);
}

/* Puts dev on the deferred list (once).  Core locked. */
static void deferred_probe_add(struct device *dev)
{
	if (list_empty(&dev->lx_deferred))
		list_add_tail(&dev->lx_deferred, &deferred_pending);
}

/* Probes dev with drv (Linux's really_probe): 0 if bound, else the probe's
 * error, with dev's devres released and its driver and drvdata cleared.
 * Core locked. */
static int really_probe(struct device *dev, struct device_driver *drv)
{
	int ret = 0;

	dev->driver = drv;
	dev->lx_probing = true;
	if (dev->bus->probe)
		ret = dev->bus->probe(dev);
	else if (drv->probe)
		ret = drv->probe(dev);
	dev->lx_probing = false;
	if (ret == 0) {
		list_add_tail(&dev->lx_bound_node, &drv->lx_bound);
		deferred_probe_del(dev);
		deferred_trigger = true;
		kobject_uevent(&dev->kobj, KOBJ_BIND);
		return 0;
	}
	devres_release_all(dev);
	dev->driver = NULL;
	dev_set_drvdata(dev, NULL);
	switch (ret) {
	case -EPROBE_DEFER:
		deferred_probe_add(dev);
		break;
	case -ENODEV:
	case -ENXIO:
		pr_debug("%s: probe of %s rejects match %d\n", drv->name, dev_name(dev), ret);
		break;
	default:
		pr_warn("%s: probe of %s failed with error %d\n", drv->name, dev_name(dev), ret);
	}
	return ret;
}

/* Binds dev to the first driver of its bus that matches and probes it
 * (Linux's __device_attach): 1 if bound, 0 if not.  Core locked. */
static int bus_attach_device(struct device *dev)
{
	struct device_driver *drv;
	int match;

	if (!dev->bus || dev->driver)
		return dev->driver != NULL;
	list_for_each_entry(drv, &dev->bus->lx_drivers, lx_node) {
		match = driver_match_device(drv, dev);
		if (match == 0)
			continue;
		if (match == -EPROBE_DEFER)
			deferred_probe_add(dev);
		if (match < 0)
			return 0;
		if (really_probe(dev, drv) == 0)
			return 1;
		if (!list_empty(&dev->lx_deferred))
			return 0;       /* deferral stops the search, as in Linux */
	}
	return 0;
}

/* Probes every device on the deferred list once; those that defer again go
 * back on it.  Core locked. */
static void run_deferred_probes(void)
{
	LIST_HEAD(active);
	struct device *dev;

	list_splice_init(&deferred_pending, &active);
	while (!list_empty(&active)) {
		dev = list_first_entry(&active, struct device, lx_deferred);
		list_del_init(&dev->lx_deferred);
		get_device(dev);
		bus_attach_device(dev);
		put_device(dev);
	}
}

void driver_deferred_probe_trigger(void)
{
	might_sleep();
	core_lock();
	deferred_trigger = true;
	core_unlock();
}

unsigned int lx_deferred_probe_count(void)
{
	struct device *dev;
	unsigned int n = 0;

	list_for_each_entry(dev, &deferred_pending, lx_deferred)
		n++;
	return n;
}

/* Unbinds dev (Linux's __device_release_driver): remove, then devres in
 * reverse order, then drvdata.  Core locked. */
static void release_driver_locked(struct device *dev)
{
	struct device_driver *drv = dev->driver;

	if (!drv || dev->lx_probing)
		return;
	if (dev->bus && dev->bus->remove)
		dev->bus->remove(dev);
	else if (drv->remove)
		drv->remove(dev);
	devres_release_all(dev);
	list_del_init(&dev->lx_bound_node);
	dev->driver = NULL;
	dev_set_drvdata(dev, NULL);
	kobject_uevent(&dev->kobj, KOBJ_UNBIND);
}

void device_initialize(struct device *dev)
{
	dev->lx_refcount = 1;
	dev->driver = NULL;
	dev->lx_devres = NULL;
	dev->lx_added = false;
	dev->lx_probing = false;
	INIT_LIST_HEAD(&dev->lx_bus_node);
	INIT_LIST_HEAD(&dev->lx_bound_node);
	INIT_LIST_HEAD(&dev->lx_deferred);
	INIT_LIST_HEAD(&dev->lx_class_node);
	INIT_LIST_HEAD(&dev->lx_files);
}

int device_add(struct device *dev)
{
	int ret;

	might_sleep();
	if (!dev)
		return -EINVAL;
	if (dev->lx_refcount <= 0) {
		lx_report("device_add before device_initialize", __FILE__, __LINE__, "device %s",
			  dev_name(dev));
		return -EINVAL;
	}
	if (!dev->init_name || !dev->init_name[0]) {
		pr_err("device_add: a device without a name\n");
		return -EINVAL;
	}
	core_lock();
	if (dev->lx_added) {
		core_unlock();
		pr_err("device_add: %s is already added\n", dev_name(dev));
		return -EINVAL;
	}
	if (dev->bus && !dev->bus->lx_registered) {
		core_unlock();
		pr_err("device_add: %s on bus '%s', which is not registered\n", dev_name(dev),
		       dev->bus->name);
		return -EINVAL;
	}
	ret = lx_sysfs_device_add(dev);
	if (ret) {
		core_unlock();
		return ret;
	}
	dev->lx_added = true;
	kobject_uevent(&dev->kobj, KOBJ_ADD);
	if (dev->bus) {
		list_add_tail(&dev->lx_bus_node, &dev->bus->lx_devices);
		bus_attach_device(dev);
	}
	core_unlock();
	return 0;
}

int device_register(struct device *dev)
{
	if (!dev)
		return -EINVAL;
	device_initialize(dev);
	return device_add(dev);
}

void device_del(struct device *dev)
{
	might_sleep();
	if (!dev)
		return;
	core_lock();
	if (!dev->lx_added) {
		core_unlock();
		lx_report("device_del of a device not added", __FILE__, __LINE__, "device %s",
			  dev_name(dev));
		return;
	}
	release_driver_locked(dev);
	deferred_probe_del(dev);
	list_del_init(&dev->lx_bus_node);
	kobject_uevent(&dev->kobj, KOBJ_REMOVE);
	lx_sysfs_device_del(dev);
	dev->lx_added = false;
	core_unlock();
}

void device_unregister(struct device *dev)
{
	device_del(dev);
	put_device(dev);
}

struct device *get_device(struct device *dev)
{
	if (dev)
		dev->lx_refcount++;
	return dev;
}

void put_device(struct device *dev)
{
	if (!dev)
		return;
	if (dev->lx_refcount <= 0) {
		lx_report("put_device without a reference", __FILE__, __LINE__, "device %s",
			  dev_name(dev));
		return;
	}
	if (--dev->lx_refcount)
		return;
	/* an unbound device can still hold devres (drivers/base/core.c's device_release) */
	devres_release_all(dev);
	if (dev->release)
		dev->release(dev);
	else if (dev->type && dev->type->release)
		dev->type->release(dev);
	else if (dev->class && dev->class->dev_release)
		dev->class->dev_release(dev);
	else
		lx_warn(__FILE__, __LINE__,
			"Device '%s' does not have a release() function, it is broken and must be fixed.",
			dev_name(dev));
}

int device_driver_attach(struct device_driver *drv, struct device *dev)
{
	int ret;

	might_sleep();
	if (!drv || !dev)
		return -EINVAL;
	core_lock();
	if (dev->driver)
		ret = dev->driver == drv ? 0 : -EBUSY;
	else
		ret = really_probe(dev, drv);
	core_unlock();
	return ret;
}

int device_attach(struct device *dev)
{
	int ret;

	might_sleep();
	if (!dev)
		return -EINVAL;
	core_lock();
	ret = bus_attach_device(dev);
	core_unlock();
	return ret;
}

void device_release_driver(struct device *dev)
{
	might_sleep();
	if (!dev)
		return;
	core_lock();
	release_driver_locked(dev);
	core_unlock();
}

struct device_driver *driver_find(const char *name, struct bus_type *bus)
{
	struct device_driver *drv;

	if (!name || !bus || !bus->lx_registered)
		return NULL;
	list_for_each_entry(drv, &bus->lx_drivers, lx_node)
		if (!strcmp(drv->name, name))
			return drv;
	return NULL;
}

int driver_register(struct device_driver *drv)
{
	struct device *dev, *next;
	int match;

	might_sleep();
	if (!drv || !drv->name || !drv->bus) {
		pr_err("driver_register: %s\n", !drv || !drv->name ? "a driver without a name"
								: "a driver without a bus");
		return -EINVAL;
	}
	if (!drv->bus->lx_registered) {
		pr_err("Driver '%s' was unable to register with bus_type '%s' because the bus was not initialized.\n",
		       drv->name, drv->bus->name);
		return -EINVAL;
	}
	core_lock();
	if (driver_find(drv->name, drv->bus)) {
		core_unlock();
		pr_err("Error: Driver '%s' is already registered, aborting...\n", drv->name);
		return -EBUSY;
	}
	INIT_LIST_HEAD(&drv->lx_bound);
	list_add_tail(&drv->lx_node, &drv->bus->lx_drivers);
	/* Linux's driver_attach: each unbound device in bus order */
	list_for_each_entry_safe(dev, next, &drv->bus->lx_devices, lx_bus_node) {
		if (dev->driver)
			continue;
		match = driver_match_device(drv, dev);
		if (match == -EPROBE_DEFER)
			deferred_probe_add(dev);
		if (match <= 0)
			continue;
		really_probe(dev, drv);
	}
	core_unlock();
	return 0;
}

void driver_unregister(struct device_driver *drv)
{
	struct device *dev;

	might_sleep();
	if (!drv || !drv->bus)
		return;
	core_lock();
	if (driver_find(drv->name, drv->bus) != drv) {
		core_unlock();
		lx_report("driver_unregister of a driver not registered", __FILE__, __LINE__,
			  "driver '%s'", drv->name);
		return;
	}
	/* Linux's driver_detach: the most recently bound device first */
	while (!list_empty(&drv->lx_bound)) {
		dev = list_last_entry(&drv->lx_bound, struct device, lx_bound_node);
		release_driver_locked(dev);
	}
	list_del_init(&drv->lx_node);
	core_unlock();
}

int dev_err_probe(const struct device *dev, int err, const char *fmt, ...)
{
	char msg[160];
	va_list args;

	va_start(args, fmt);
	vsnprintf(msg, sizeof(msg), fmt, args);
	va_end(args);
	if (err != -EPROBE_DEFER)
		dev_err(dev, "error %d: %s", err, msg);
	else
		dev_dbg(dev, "error %d: %s", err, msg);
	return err;
}

struct device *lx_bus_find_device_by_name(const char *bus_name, const char *name)
{
	struct bus_type *bus;
	struct device *dev;

	list_for_each_entry(bus, &buses, lx_node) {
		if (strcmp(bus->name, bus_name))
			continue;
		list_for_each_entry(dev, &bus->lx_devices, lx_bus_node)
			if (!name || !strcmp(dev_name(dev), name))
				return dev;
	}
	return NULL;
}

void lx_bus_register_boot(struct bus_type *bus)
{
	INIT_LIST_HEAD(&bus->lx_devices);
	INIT_LIST_HEAD(&bus->lx_drivers);
	list_add_tail(&bus->lx_node, &buses);
	bus->lx_registered = true;
}

void lx_driver_core_boot(void)
{
	mutex_init(&core_mutex);
	core_owner = NULL;
	core_depth = 0;
	INIT_LIST_HEAD(&buses);
	INIT_LIST_HEAD(&deferred_pending);
	deferred_trigger = false;
}
