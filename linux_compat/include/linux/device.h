/*
 * linux/device.h — the part of the driver model the bus drivers here use:
 * struct device with its parent, platform data and driver data, struct
 * device_driver, and the dev_* printing helpers (prefix "<driver> <device>: "
 * as Linux's dev_printk prints it).  There is no sysfs and no generic bus:
 * a bus (linux/spi/spi.h) matches its drivers and devices itself.
 */
#ifndef _LINUX_DEVICE_H
#define _LINUX_DEVICE_H

#include <linux/types.h>
#include <linux/compiler.h>
#include <linux/printk.h>

struct module;

struct device_driver {
	const char *name;
	struct module *owner;
};

struct device {
	struct device *parent;
	const char *init_name;          /* the device's name (dev_name) */
	struct device_driver *driver;   /* bound driver, NULL while unbound */
	void *platform_data;            /* board-specific data (board files set it) */
	void *driver_data;              /* dev_set_drvdata */
	void (*release)(struct device *dev);
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

#define lx_dev_driver_name(dev)	((dev)->driver ? (dev)->driver->name : "")
#define dev_printk(level, dev, fmt, ...) \
	printk(level "%s %s: " fmt, lx_dev_driver_name(dev), dev_name(dev), ##__VA_ARGS__)
#define dev_emerg(dev, fmt, ...)	dev_printk(KERN_EMERG, dev, fmt, ##__VA_ARGS__)
#define dev_crit(dev, fmt, ...)		dev_printk(KERN_CRIT, dev, fmt, ##__VA_ARGS__)
#define dev_err(dev, fmt, ...)		dev_printk(KERN_ERR, dev, fmt, ##__VA_ARGS__)
#define dev_warn(dev, fmt, ...)		dev_printk(KERN_WARNING, dev, fmt, ##__VA_ARGS__)
#define dev_notice(dev, fmt, ...)	dev_printk(KERN_NOTICE, dev, fmt, ##__VA_ARGS__)
#define dev_info(dev, fmt, ...)		dev_printk(KERN_INFO, dev, fmt, ##__VA_ARGS__)
#define dev_err_ratelimited(dev, fmt, ...)	dev_err(dev, fmt, ##__VA_ARGS__)
#define dev_warn_ratelimited(dev, fmt, ...)	dev_warn(dev, fmt, ##__VA_ARGS__)
#define dev_dbg(dev, fmt, ...)		({ if (0) dev_printk(KERN_DEBUG, dev, fmt, ##__VA_ARGS__); })

#endif /* _LINUX_DEVICE_H */
