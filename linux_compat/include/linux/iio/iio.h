/*
 * linux/iio/iio.h — the IIO core for drivers (Linux 6.1's
 * include/linux/iio/iio.h), implemented by linux_compat/src/iio.c: devices
 * with direct-mode channels read through read_raw (no buffers, triggers or
 * events).  A registered device is /sys/bus/iio/devices/iio:device<n> with
 * Linux's channel files — in_voltage<n>_raw for each info element in
 * info_mask_separate, in_voltage_scale for those in info_mask_shared_by_type
 * (in_voltage<n>_<extend_name>_raw with an extend_name) — and "name"; the
 * consumer side is linux/iio/consumer.h.
 */
#ifndef _INDUSTRIAL_IO_H_
#define _INDUSTRIAL_IO_H_

#include <linux/bits.h>
#include <linux/device.h>
#include <linux/mutex.h>
#include <linux/iio/types.h>

struct iio_chan_spec;
struct iio_dev;

struct iio_chan_spec {
	enum iio_chan_type type;
	int channel;
	int channel2;
	unsigned long address;
	int scan_index;
	struct {
		char sign;
		u8 realbits;
		u8 storagebits;
		u8 shift;
		u8 repeat;
		enum iio_endian endianness;
	} scan_type;
	long info_mask_separate;
	long info_mask_separate_available;
	long info_mask_shared_by_type;
	long info_mask_shared_by_type_available;
	long info_mask_shared_by_dir;
	long info_mask_shared_by_dir_available;
	long info_mask_shared_by_all;
	long info_mask_shared_by_all_available;
	const void *event_spec;
	unsigned int num_event_specs;
	const void *ext_info;
	const char *extend_name;
	const char *datasheet_name;
	unsigned modified:1;
	unsigned indexed:1;
	unsigned output:1;
	unsigned differential:1;
};

/* Whether chan has info element type (separate or shared). */
static inline bool iio_channel_has_info(const struct iio_chan_spec *chan, enum iio_chan_info_enum type)
{
	return (chan->info_mask_separate & BIT(type)) | (chan->info_mask_shared_by_type & BIT(type)) |
	       (chan->info_mask_shared_by_dir & BIT(type)) | (chan->info_mask_shared_by_all & BIT(type));
}

struct iio_info {
	const struct attribute_group *event_attrs;
	const struct attribute_group *attrs;
	int (*read_raw)(struct iio_dev *indio_dev, struct iio_chan_spec const *chan, int *val,
			int *val2, long mask);
	int (*write_raw)(struct iio_dev *indio_dev, struct iio_chan_spec const *chan, int val,
			 int val2, long mask);
};

#define INDIO_DIRECT_MODE		0x01
#define INDIO_BUFFER_TRIGGERED		0x02
#define INDIO_BUFFER_SOFTWARE		0x04
#define INDIO_BUFFER_HARDWARE		0x08

/* Channels a device may have (its sysfs files are built from them). */
#define LX_IIO_MAX_FILES	48

struct lx_iio_attr;

struct iio_dev {
	int modes;
	struct device dev;
	struct mutex mlock;
	struct iio_chan_spec const *channels;
	int num_channels;
	const char *name;
	const char *label;
	const struct iio_info *info;
	void *priv;
	int lx_id;                              /* ev3lx: iio:device<id>, -1 unregistered */
	struct lx_iio_attr *lx_attrs;           /* ev3lx: its channel files */
	struct attribute_group lx_group;
	const struct attribute_group *lx_groups[3];
	struct list_head lx_maps;               /* ev3lx: iio_map_array_register's */
	struct list_head lx_node;               /* ev3lx: on the list of registered devices */
};

static inline void *iio_priv(const struct iio_dev *indio_dev)
{
	return indio_dev->priv;
}
static inline struct iio_dev *dev_to_iio_dev(struct device *dev)
{
	return container_of(dev, struct iio_dev, dev);
}
static inline void iio_device_set_drvdata(struct iio_dev *indio_dev, void *data)
{
	dev_set_drvdata(&indio_dev->dev, data);
}
static inline void *iio_device_get_drvdata(const struct iio_dev *indio_dev)
{
	return dev_get_drvdata(&indio_dev->dev);
}

/* Allocates a device with sizeof_priv bytes of private data (iio_priv),
 * zeroed; NULL if out of memory.  Process context. */
struct iio_dev *iio_device_alloc(struct device *parent, int sizeof_priv);
/* Frees a device from iio_device_alloc (a registered one is reported). */
void iio_device_free(struct iio_dev *indio_dev);
/* iio_device_alloc freed when parent's driver unbinds. */
struct iio_dev *devm_iio_device_alloc(struct device *parent, int sizeof_priv);
/* Registers indio_dev: 0, -EINVAL (no info or read_raw, a channel without
 * a type's name), -ENOMEM, or device_add's error.  Process context. */
int __iio_device_register(struct iio_dev *indio_dev, struct module *this_mod);
#define iio_device_register(indio_dev) __iio_device_register(indio_dev, THIS_MODULE)
/* Unregisters indio_dev: consumers' reads get -ENODEV from then on. */
void iio_device_unregister(struct iio_dev *indio_dev);
/* iio_device_register undone when dev's driver unbinds. */
int __devm_iio_device_register(struct device *dev, struct iio_dev *indio_dev, struct module *this_mod);
#define devm_iio_device_register(dev, indio_dev) __devm_iio_device_register(dev, indio_dev, THIS_MODULE)
/* The device's number (iio:device<n>). */
static inline int iio_device_id(struct iio_dev *indio_dev)
{
	return indio_dev->lx_id;
}

/* Formats a value of type (IIO_VAL_*) as its sysfs file shows it ("%d",
 * "%d.%06u", ...) into buf (a page), with a newline: the bytes written. */
ssize_t iio_format_value(char *buf, unsigned int type, int size, int *vals);

#endif /* _INDUSTRIAL_IO_H_ */
