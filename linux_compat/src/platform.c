/*
 * platform.c — the platform bus (linux/platform_device.h states the
 * contract), after Linux 6.1's drivers/base/platform.c: naming, matching
 * (driver_override, of_match_table, id_table, name), the probe and remove
 * wrappers, resources and IRQs, allocated devices.
 */
#include <linux/platform_device.h>
#include <linux/bitops.h>
#include <linux/err.h>
#include <linux/io.h>
#include <linux/kernel.h>
#include <linux/of.h>
#include <linux/slab.h>
#include <linux/string.h>
#include <linux_compat/irq.h>
#include <linux_compat/report.h>

#define PLATFORM_AUTO_IDS	64

struct device platform_bus;
static unsigned long auto_ids[PLATFORM_AUTO_IDS / BITS_PER_LONG];

/* The id_table entry naming pdev, or NULL. */
static const struct platform_device_id *platform_match_id(const struct platform_device_id *id,
							  struct platform_device *pdev)
{
	for (; id->name[0]; id++)
		if (!strcmp(pdev->name, id->name))
			return id;
	return NULL;
}

static int platform_match(struct device *dev, struct device_driver *drv)
{
	struct platform_device *pdev = to_platform_device(dev);
	struct platform_driver *pdrv = to_platform_driver(drv);

	if (pdev->driver_override)
		return !strcmp(pdev->driver_override, drv->name);
	if (drv->of_match_table && of_match_node(drv->of_match_table, dev->of_node))
		return 1;
	if (pdrv->id_table) {
		pdev->id_entry = platform_match_id(pdrv->id_table, pdev);
		return pdev->id_entry != NULL;
	}
	return strcmp(pdev->name, drv->name) == 0;
}

/* The probe of a platform_driver_probe driver after its registration:
 * later devices are not bound to it. */
static int platform_probe_fail(struct platform_device *pdev)
{
	return -ENXIO;
}

static int platform_probe(struct device *dev)
{
	struct platform_driver *drv = to_platform_driver(dev->driver);
	struct platform_device *pdev = to_platform_device(dev);
	int ret = 0;

	if (drv->probe == platform_probe_fail)
		return -ENXIO;
	if (drv->probe)
		ret = drv->probe(pdev);
	if (drv->prevent_deferred_probe && ret == -EPROBE_DEFER) {
		dev_warn(dev, "probe deferral not supported\n");
		ret = -ENXIO;
	}
	return ret;
}

static void platform_remove(struct device *dev)
{
	struct platform_driver *drv = to_platform_driver(dev->driver);
	struct platform_device *pdev = to_platform_device(dev);

	if (drv->remove_new) {
		drv->remove_new(pdev);
	} else if (drv->remove && drv->remove(pdev)) {
		dev_warn(dev, "remove callback returned a non-zero value. This will be ignored.\n");
	}
}

static void platform_shutdown(struct device *dev)
{
	struct platform_driver *drv;

	if (!dev->driver)
		return;
	drv = to_platform_driver(dev->driver);
	if (drv->shutdown)
		drv->shutdown(to_platform_device(dev));
}

struct bus_type platform_bus_type = {
	.name = "platform",
	.match = platform_match,
	.probe = platform_probe,
	.remove = platform_remove,
	.shutdown = platform_shutdown,
};

struct resource *platform_get_resource(struct platform_device *pdev, unsigned int type, unsigned int num)
{
	u32 i;

	for (i = 0; pdev && i < pdev->num_resources; i++) {
		struct resource *r = &pdev->resource[i];

		if (type == resource_type(r) && num-- == 0)
			return r;
	}
	return NULL;
}

struct resource *platform_get_resource_byname(struct platform_device *pdev, unsigned int type,
					      const char *name)
{
	u32 i;

	for (i = 0; pdev && name && i < pdev->num_resources; i++) {
		struct resource *r = &pdev->resource[i];

		if (type == resource_type(r) && r->name && !strcmp(r->name, name))
			return r;
	}
	return NULL;
}

/* The IRQ number of r: -ENXIO if none, -EINVAL (warned) for 0. */
static int resource_irq(struct resource *r)
{
	if (!r || (r->flags & IORESOURCE_DISABLED))
		return -ENXIO;
	if (r->start == 0) {
		lx_warn(__FILE__, __LINE__, "0 is an invalid IRQ number");
		return -EINVAL;
	}
	return (int)r->start;
}

int platform_get_irq_optional(struct platform_device *pdev, unsigned int num)
{
	return resource_irq(platform_get_resource(pdev, IORESOURCE_IRQ, num));
}

int platform_get_irq(struct platform_device *pdev, unsigned int num)
{
	int ret = platform_get_irq_optional(pdev, num);

	if (ret < 0)
		return dev_err_probe(&pdev->dev, ret, "IRQ index %u not found\n", num);
	return ret;
}

int platform_get_irq_byname(struct platform_device *pdev, const char *name)
{
	int ret = resource_irq(platform_get_resource_byname(pdev, IORESOURCE_IRQ, name));

	if (ret < 0)
		return dev_err_probe(&pdev->dev, ret, "IRQ %s not found\n", name);
	return ret;
}

int platform_irq_count(struct platform_device *pdev)
{
	int n = 0;

	while (platform_get_resource(pdev, IORESOURCE_IRQ, (unsigned int)n))
		n++;
	return n;
}

void __iomem *devm_platform_get_and_ioremap_resource(struct platform_device *pdev, unsigned int index,
						     struct resource **res)
{
	struct resource *r = platform_get_resource(pdev, IORESOURCE_MEM, index);

	if (res)
		*res = r;
	return devm_ioremap_resource(&pdev->dev, r);
}

void __iomem *devm_platform_ioremap_resource(struct platform_device *pdev, unsigned int index)
{
	return devm_platform_get_and_ioremap_resource(pdev, index, NULL);
}

int platform_device_add(struct platform_device *pdev)
{
	unsigned int id;
	int ret;

	might_sleep();
	if (!pdev || !pdev->name)
		return -EINVAL;
	if (pdev->id == PLATFORM_DEVID_AUTO) {
		for (id = 0; id < PLATFORM_AUTO_IDS && test_bit(id, auto_ids); id++)
			;
		if (id == PLATFORM_AUTO_IDS)
			return -ENOSPC;
		set_bit(id, auto_ids);
		pdev->id = (int)id;
		pdev->id_auto = true;
		dev_set_name(&pdev->dev, "%s.%d.auto", pdev->name, pdev->id);
	} else if (pdev->id == PLATFORM_DEVID_NONE) {
		dev_set_name(&pdev->dev, "%s", pdev->name);
	} else {
		dev_set_name(&pdev->dev, "%s.%d", pdev->name, pdev->id);
	}
	if (!pdev->dev.parent)
		pdev->dev.parent = &platform_bus;
	pdev->dev.bus = &platform_bus_type;
	ret = device_add(&pdev->dev);
	if (ret && pdev->id_auto) {
		clear_bit((unsigned int)pdev->id, auto_ids);
		pdev->id = PLATFORM_DEVID_AUTO;
		pdev->id_auto = false;
	}
	return ret;
}

int platform_device_register(struct platform_device *pdev)
{
	if (!pdev)
		return -EINVAL;
	device_initialize(&pdev->dev);
	return platform_device_add(pdev);
}

void platform_device_del(struct platform_device *pdev)
{
	if (!pdev)
		return;
	device_del(&pdev->dev);
	if (pdev->id_auto) {
		clear_bit((unsigned int)pdev->id, auto_ids);
		pdev->id = PLATFORM_DEVID_AUTO;
		pdev->id_auto = false;
	}
}

void platform_device_put(struct platform_device *pdev)
{
	if (pdev)
		put_device(&pdev->dev);
}

void platform_device_unregister(struct platform_device *pdev)
{
	platform_device_del(pdev);
	platform_device_put(pdev);
}

int platform_add_devices(struct platform_device **devs, int num)
{
	int i, ret;

	for (i = 0; i < num; i++) {
		ret = platform_device_register(devs[i]);
		if (ret) {
			while (--i >= 0)
				platform_device_unregister(devs[i]);
			return ret;
		}
	}
	return 0;
}

struct platform_object {
	struct platform_device pdev;
	char name[];
};

/* Frees a platform_device_alloc'd device and the copies it owns. */
static void platform_device_release(struct device *dev)
{
	struct platform_device *pdev = to_platform_device(dev);
	struct platform_object *pa = container_of(pdev, struct platform_object, pdev);

	kfree(pa->pdev.dev.platform_data);
	kfree(pa->pdev.resource);
	kfree(pa);
}

struct platform_device *platform_device_alloc(const char *name, int id)
{
	struct platform_object *pa;
	size_t len;

	if (!name)
		return NULL;
	len = strlen(name) + 1;
	pa = kzalloc(sizeof(*pa) + len, GFP_KERNEL);
	if (!pa)
		return NULL;
	memcpy(pa->name, name, len);
	pa->pdev.name = pa->name;
	pa->pdev.id = id;
	device_initialize(&pa->pdev.dev);
	pa->pdev.dev.release = platform_device_release;
	return &pa->pdev;
}

int platform_device_add_resources(struct platform_device *pdev, const struct resource *res,
				  unsigned int num)
{
	struct resource *r = NULL;

	if (res && num) {
		r = kmemdup(res, sizeof(*res) * num, GFP_KERNEL);
		if (!r)
			return -ENOMEM;
	}
	kfree(pdev->resource);
	pdev->resource = r;
	pdev->num_resources = num;
	return 0;
}

int platform_device_add_data(struct platform_device *pdev, const void *data, size_t size)
{
	void *d = NULL;

	if (data) {
		d = kmemdup(data, size, GFP_KERNEL);
		if (!d)
			return -ENOMEM;
	}
	kfree(pdev->dev.platform_data);
	pdev->dev.platform_data = d;
	return 0;
}

struct platform_device *platform_device_register_data(struct device *parent, const char *name, int id,
						      const void *data, size_t size)
{
	struct platform_device *pdev = platform_device_alloc(name, id);
	int ret;

	if (!pdev)
		return ERR_PTR(-ENOMEM);
	pdev->dev.parent = parent;
	ret = platform_device_add_data(pdev, data, size);
	if (!ret)
		ret = platform_device_add(pdev);
	if (ret) {
		platform_device_put(pdev);
		return ERR_PTR(ret);
	}
	return pdev;
}

struct platform_device *platform_device_register_simple(const char *name, int id,
							const struct resource *res, unsigned int num)
{
	struct platform_device *pdev = platform_device_alloc(name, id);
	int ret;

	if (!pdev)
		return ERR_PTR(-ENOMEM);
	ret = platform_device_add_resources(pdev, res, num);
	if (!ret)
		ret = platform_device_add(pdev);
	if (ret) {
		platform_device_put(pdev);
		return ERR_PTR(ret);
	}
	return pdev;
}

int __platform_driver_register(struct platform_driver *drv, struct module *owner)
{
	if (!drv)
		return -EINVAL;
	drv->driver.owner = owner;
	drv->driver.bus = &platform_bus_type;
	return driver_register(&drv->driver);
}

void platform_driver_unregister(struct platform_driver *drv)
{
	if (drv)
		driver_unregister(&drv->driver);
}

int __platform_driver_probe(struct platform_driver *drv, int (*probe)(struct platform_device *),
			    struct module *module)
{
	int ret;

	if (!drv || !probe)
		return -EINVAL;
	drv->prevent_deferred_probe = true;
	drv->driver.suppress_bind_attrs = true;
	drv->probe = probe;
	ret = __platform_driver_register(drv, module);
	if (ret)
		return ret;
	/* no later device binds to it, and a driver that bound nothing goes */
	drv->probe = platform_probe_fail;
	if (list_empty(&drv->driver.lx_bound)) {
		platform_driver_unregister(drv);
		return -ENODEV;
	}
	return 0;
}

void lx_platform_boot(void)
{
	memset(auto_ids, 0, sizeof(auto_ids));
	memset(&platform_bus, 0, sizeof(platform_bus));
	device_initialize(&platform_bus);
	dev_set_name(&platform_bus, "platform");
	lx_bus_register_boot(&platform_bus_type);
}
