/*
 * linux/platform_device.h — the platform bus (Linux 6.1's
 * drivers/base/platform.c), implemented by linux_compat/src/platform.c.
 *
 * A platform device is named "<name>.<id>" (just "<name>" for
 * PLATFORM_DEVID_NONE, "<name>.<n>.auto" for PLATFORM_DEVID_AUTO) and
 * matches a driver, in this order, by driver_override, by its of_node
 * against the driver's of_match_table, by its name in the driver's id_table
 * (which sets platform_get_device_id), else by the driver's name.  A driver
 * with prevent_deferred_probe turns a probe's -EPROBE_DEFER into -ENXIO.
 * Resources are the board's: platform_device_register does not claim them
 * (the iomem tree is flat), devm_platform_ioremap_resource claims and maps.
 */
#ifndef _LINUX_PLATFORM_DEVICE_H
#define _LINUX_PLATFORM_DEVICE_H

#include <linux/device.h>
#include <linux/ioport.h>
#include <linux/mod_devicetable.h>
#include <linux/module.h>
#include <linux/init.h>
#include <linux/err.h>

#define PLATFORM_DEVID_NONE	(-1)
#define PLATFORM_DEVID_AUTO	(-2)

struct platform_device {
	const char *name;
	int id;
	bool id_auto;
	struct device dev;
	u64 platform_dma_mask;
	u32 num_resources;
	struct resource *resource;
	const struct platform_device_id *id_entry;
	const char *driver_override;
};

#define to_platform_device(x)	container_of((x), struct platform_device, dev)
#define dev_is_platform(dev)	((dev)->bus == &platform_bus_type)
#define platform_get_device_id(pdev)	((pdev)->id_entry)

extern struct bus_type platform_bus_type;
extern struct device platform_bus;

/* A power-management transition (ev3lx never suspends: the hooks are only kept). */
typedef struct pm_message {
	int event;
} pm_message_t;

struct platform_driver {
	int (*probe)(struct platform_device *);
	int (*remove)(struct platform_device *);       /* 6.1: the result is ignored */
	void (*remove_new)(struct platform_device *);  /* 6.3 */
	void (*shutdown)(struct platform_device *);
	int (*suspend)(struct platform_device *, pm_message_t state);  /* never called: no suspend */
	int (*resume)(struct platform_device *);
	struct device_driver driver;
	const struct platform_device_id *id_table;
	bool prevent_deferred_probe;
	bool driver_managed_dma;
};

#define to_platform_driver(drv)	(container_of((drv), struct platform_driver, driver))

static inline void *platform_get_drvdata(const struct platform_device *pdev)
{
	return dev_get_drvdata(&pdev->dev);
}

static inline void platform_set_drvdata(struct platform_device *pdev, void *data)
{
	dev_set_drvdata(&pdev->dev, data);
}

/* The num-th resource of pdev of type (IORESOURCE_MEM, _IRQ, ...), or NULL. */
struct resource *platform_get_resource(struct platform_device *pdev, unsigned int type, unsigned int num);
/* The resource of type named name, or NULL. */
struct resource *platform_get_resource_byname(struct platform_device *pdev, unsigned int type,
					      const char *name);
/* The num-th IRQ of pdev: its number, or -ENXIO (logged, as Linux does). */
int platform_get_irq(struct platform_device *pdev, unsigned int num);
/* platform_get_irq without the message. */
int platform_get_irq_optional(struct platform_device *pdev, unsigned int num);
/* The IRQ resource named name, or -ENXIO (logged). */
int platform_get_irq_byname(struct platform_device *pdev, const char *name);
/* The number of IRQ resources of pdev. */
int platform_irq_count(struct platform_device *pdev);

/* Claims the index-th memory resource of pdev and maps it, both undone when
 * the driver unbinds: the mapping, or ERR_PTR(-EINVAL) (no such resource),
 * -EBUSY (region taken), -ENOMEM (cannot be mapped), each logged. */
void __iomem *devm_platform_ioremap_resource(struct platform_device *pdev, unsigned int index);
/* The same, also returning the resource through res (may be NULL). */
void __iomem *devm_platform_get_and_ioremap_resource(struct platform_device *pdev, unsigned int index,
						     struct resource **res);
/* Adds a board's statically defined device (named from name and id). */
int platform_device_register(struct platform_device *pdev);
/* Unbinds and removes pdev; the last reference calls its dev.release. */
void platform_device_unregister(struct platform_device *pdev);
/* Registers each of n devices in order; on failure unregisters those done. */
int platform_add_devices(struct platform_device **devs, int num);

/* Allocates a device named name.id whose release frees it (and its copies). */
struct platform_device *platform_device_alloc(const char *name, int id);
/* Gives pdev copies of res[0..num). 0 or -ENOMEM. */
int platform_device_add_resources(struct platform_device *pdev, const struct resource *res,
				  unsigned int num);
/* Gives pdev a copy of size bytes of data as its platform_data. */
int platform_device_add_data(struct platform_device *pdev, const void *data, size_t size);
/* Adds an allocated device to the bus (names it, binds it). */
int platform_device_add(struct platform_device *pdev);
/* Removes pdev from the bus (unbinding it). */
void platform_device_del(struct platform_device *pdev);
/* Drops a reference to pdev (platform_device_alloc's is freed by the last). */
void platform_device_put(struct platform_device *pdev);
/* Allocates, fills and adds a device: it, or ERR_PTR(-errno). */
struct platform_device *platform_device_register_simple(const char *name, int id,
							const struct resource *res, unsigned int num);
struct platform_device *platform_device_register_data(struct device *parent, const char *name, int id,
						      const void *data, size_t size);

/* Registers drv on the platform bus for owner. */
int __platform_driver_register(struct platform_driver *drv, struct module *owner);
#define platform_driver_register(drv)	__platform_driver_register((drv), THIS_MODULE)
void platform_driver_unregister(struct platform_driver *drv);
/* Registers drv, binds it to what exists, and keeps it only if it bound a
 * device; -ENODEV otherwise (the probe is not retried later). */
int __platform_driver_probe(struct platform_driver *drv, int (*probe)(struct platform_device *),
			    struct module *module);
#define platform_driver_probe(drv, probe)	__platform_driver_probe((drv), (probe), THIS_MODULE)

/* The registering module init/exit pair of a driver (linux/device/driver.h). */
#define module_driver(__driver, __register, __unregister, ...)		\
static int __init __driver##_init(void)					\
{									\
	return __register(&(__driver), ##__VA_ARGS__);			\
}									\
module_init(__driver##_init);						\
static void __exit __driver##_exit(void)				\
{									\
	__unregister(&(__driver), ##__VA_ARGS__);			\
}									\
module_exit(__driver##_exit)

#define module_platform_driver(__platform_driver) \
	module_driver(__platform_driver, platform_driver_register, platform_driver_unregister)
#define builtin_platform_driver(__platform_driver) \
	module_platform_driver(__platform_driver)

#endif /* _LINUX_PLATFORM_DEVICE_H */
