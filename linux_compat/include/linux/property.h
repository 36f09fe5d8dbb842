/*
 * linux/property.h — firmware-independent device properties: here only the
 * match data from the board node (linux/of.h).
 */
#ifndef _LINUX_PROPERTY_H
#define _LINUX_PROPERTY_H

#include <linux/device.h>

/* The match data of dev's driver for dev (of_match_table), or NULL. */
const void *device_get_match_data(const struct device *dev);

#endif /* _LINUX_PROPERTY_H */
