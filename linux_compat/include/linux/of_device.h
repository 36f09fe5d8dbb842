/*
 * linux/of_device.h — a device's match data from its driver's
 * of_match_table (linux/of.h for the board nodes).
 */
#ifndef _LINUX_OF_DEVICE_H
#define _LINUX_OF_DEVICE_H

#include <linux/of.h>
#include <linux/device.h>

/* The data of the of_match_table entry of dev's driver matching dev, or NULL. */
const void *of_device_get_match_data(const struct device *dev);

#endif /* _LINUX_OF_DEVICE_H */
