/*
 * iio.c — the IIO core in direct mode and its in-kernel consumers
 * (linux/iio/iio.h, consumer.h, driver.h state the contracts), after Linux
 * 6.1's drivers/iio/industrialio-core.c and inkern.c: devices on the "iio"
 * bus with their channel files, the board's maps, and reads through
 * read_raw under the device's lock, which unregistering takes too (so a
 * read never runs into a provider that has gone: it gets -ENODEV).
 */
#include <linux/iio/iio.h>
#include <linux/iio/consumer.h>
#include <linux/iio/driver.h>
#include <linux/iio/machine.h>
#include <linux/err.h>
#include <linux/errno.h>
#include <linux/kernel.h>
#include <linux/math64.h>
#include <linux/slab.h>
#include <linux/string.h>
#include <linux/sysfs.h>
#include <linux_compat/irq.h>
#include <linux_compat/report.h>

/* One channel file: the device attribute, what it reads, its name. */
struct lx_iio_attr {
	struct device_attribute dev_attr;
	const struct iio_chan_spec *chan;
	long mask;
	char name[48];
};

/* One registered map entry. */
struct iio_map_entry {
	struct list_head node;
	const struct iio_map *map;
};

static struct bus_type iio_bus_type = { .name = "iio" };
static LIST_HEAD(iio_devices);
static DEFINE_MUTEX(iio_list_lock);
static unsigned long iio_ids;   /* bit per iio:device<n> taken */

static const char *const type_names[] = {
	[IIO_VOLTAGE] = "voltage", [IIO_CURRENT] = "current", [IIO_POWER] = "power",
	[IIO_ACCEL] = "accel", [IIO_ANGL_VEL] = "anglvel", [IIO_MAGN] = "magn",
	[IIO_LIGHT] = "illuminance", [IIO_INTENSITY] = "intensity", [IIO_PROXIMITY] = "proximity",
	[IIO_TEMP] = "temp", [IIO_INCLI] = "incli", [IIO_ROT] = "rot", [IIO_ANGL] = "angl",
	[IIO_TIMESTAMP] = "timestamp", [IIO_CAPACITANCE] = "capacitance",
	[IIO_ALTVOLTAGE] = "altvoltage", [IIO_PRESSURE] = "pressure",
	[IIO_DISTANCE] = "distance", [IIO_RESISTANCE] = "resistance", [IIO_COUNT] = "count",
};

static const char *const info_names[] = {
	[IIO_CHAN_INFO_RAW] = "raw", [IIO_CHAN_INFO_PROCESSED] = "input",
	[IIO_CHAN_INFO_SCALE] = "scale", [IIO_CHAN_INFO_OFFSET] = "offset",
	[IIO_CHAN_INFO_CALIBSCALE] = "calibscale", [IIO_CHAN_INFO_CALIBBIAS] = "calibbias",
	[IIO_CHAN_INFO_PEAK] = "peak_raw", [IIO_CHAN_INFO_PEAK_SCALE] = "peak_scale",
	[IIO_CHAN_INFO_QUADRATURE_CORRECTION_RAW] = "quadrature_correction_raw",
	[IIO_CHAN_INFO_AVERAGE_RAW] = "mean_raw",
	[IIO_CHAN_INFO_LOW_PASS_FILTER_3DB_FREQUENCY] = "filter_low_pass_3db_frequency",
	[IIO_CHAN_INFO_HIGH_PASS_FILTER_3DB_FREQUENCY] = "filter_high_pass_3db_frequency",
	[IIO_CHAN_INFO_SAMP_FREQ] = "sampling_frequency",
};

/* The name of chan's type, or NULL if it has none here. */
static const char *type_name(const struct iio_chan_spec *chan)
{
	return (unsigned int)chan->type < ARRAY_SIZE(type_names) ? type_names[chan->type] : NULL;
}

/* Formats a fixed-point value: integer part and 'digits' decimals of frac. */
static int emit_fixed(char *buf, int integer, int frac, int digits)
{
	bool negative = integer < 0 || frac < 0;

	if (integer < 0)
		integer = -integer;
	if (frac < 0)
		frac = -frac;
	return sysfs_emit(buf, "%s%d.%0*d\n", negative ? "-" : "", integer, digits, frac);
}

ssize_t iio_format_value(char *buf, unsigned int type, int size, int *vals)
{
	s64 tmp;

	switch (type) {
	case IIO_VAL_INT:
		return sysfs_emit(buf, "%d\n", vals[0]);
	case IIO_VAL_INT_PLUS_MICRO:
	case IIO_VAL_INT_PLUS_MICRO_DB:
		return emit_fixed(buf, vals[0], vals[1], 6);
	case IIO_VAL_INT_PLUS_NANO:
		return emit_fixed(buf, vals[0], vals[1], 9);
	case IIO_VAL_FRACTIONAL:
		if (!vals[1])
			return -EINVAL;
		tmp = div_s64((s64)vals[0] * 1000000000LL, vals[1]);
		return emit_fixed(buf, (int)div_s64(tmp, 1000000000), (int)(tmp % 1000000000), 9);
	case IIO_VAL_FRACTIONAL_LOG2:
		tmp = ((s64)vals[0] * 1000000000LL) >> vals[1];
		return emit_fixed(buf, (int)div_s64(tmp, 1000000000), (int)(tmp % 1000000000), 9);
	case IIO_VAL_INT_64:
		return sysfs_emit(buf, "%lld\n", (long long)(((u64)(u32)vals[1] << 32) | (u32)vals[0]));
	default:
		return -EINVAL;
	}
}

/* show() of a channel file: read_raw of its channel and info element. */
static ssize_t iio_read_channel_info(struct device *dev, struct device_attribute *attr, char *buf)
{
	struct iio_dev *indio_dev = dev_to_iio_dev(dev);
	struct lx_iio_attr *a = container_of(attr, struct lx_iio_attr, dev_attr);
	int vals[2] = { 0, 0 }, ret;

	ret = indio_dev->info->read_raw(indio_dev, a->chan, &vals[0], &vals[1], a->mask);
	if (ret < 0)
		return ret;
	return iio_format_value(buf, (unsigned int)ret, 2, vals);
}

static ssize_t name_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	return sysfs_emit(buf, "%s\n", dev_to_iio_dev(dev)->name);
}
static DEVICE_ATTR_RO(name);

/* devres release of devm_iio_device_alloc. */
static void devm_iio_device_release(struct device *dev, void *res)
{
	iio_device_free(*(struct iio_dev **)res);
}

/* release of an IIO device: frees it with its files. */
static void iio_dev_release(struct device *dev)
{
	struct iio_dev *indio_dev = dev_to_iio_dev(dev);

	kfree(indio_dev->lx_attrs);
	kfree(indio_dev);
}

struct iio_dev *iio_device_alloc(struct device *parent, int sizeof_priv)
{
	size_t head = ALIGN(sizeof(struct iio_dev), sizeof(u64));
	struct iio_dev *indio_dev;

	if (sizeof_priv < 0)
		return NULL;
	indio_dev = kzalloc(head + (size_t)sizeof_priv, GFP_KERNEL);
	if (!indio_dev)
		return NULL;
	if (sizeof_priv)
		indio_dev->priv = (char *)indio_dev + head;
	device_initialize(&indio_dev->dev);
	indio_dev->dev.parent = parent;
	indio_dev->dev.bus = &iio_bus_type;
	indio_dev->dev.release = iio_dev_release;
	mutex_init(&indio_dev->mlock);
	INIT_LIST_HEAD(&indio_dev->lx_maps);
	INIT_LIST_HEAD(&indio_dev->lx_node);
	indio_dev->lx_id = -1;
	return indio_dev;
}

void iio_device_free(struct iio_dev *indio_dev)
{
	if (!indio_dev)
		return;
	if (indio_dev->lx_id >= 0) {
		lx_report("iio_device_free of a registered device", __FILE__, __LINE__,
			  "%s: unregister it first", dev_name(&indio_dev->dev));
		return;
	}
	put_device(&indio_dev->dev);
}

struct iio_dev *devm_iio_device_alloc(struct device *parent, int sizeof_priv)
{
	struct iio_dev **res, *indio_dev;

	res = devres_alloc(devm_iio_device_release, sizeof(*res), GFP_KERNEL);
	if (!res)
		return NULL;
	indio_dev = iio_device_alloc(parent, sizeof_priv);
	if (!indio_dev) {
		devres_free(res);
		return NULL;
	}
	*res = indio_dev;
	devres_add(parent, res);
	return indio_dev;
}

/* Adds the file for chan's info element bit (shared: one per type) to the
 * device's files, unless a shared one of that name is there; 0 or -ENOSPC. */
static int add_channel_file(struct iio_dev *indio_dev, const struct iio_chan_spec *chan, long bit,
			    bool shared, unsigned int *n)
{
	struct lx_iio_attr *a = &indio_dev->lx_attrs[*n];
	const char *dir = chan->output ? "out" : "in";
	unsigned int i;

	if ((unsigned long)bit >= ARRAY_SIZE(info_names) || !info_names[bit])
		return 0;
	if (shared)
		scnprintf(a->name, sizeof(a->name), "%s_%s_%s", dir, type_name(chan), info_names[bit]);
	else if (chan->indexed && chan->extend_name)
		scnprintf(a->name, sizeof(a->name), "%s_%s%d_%s_%s", dir, type_name(chan), chan->channel,
			  chan->extend_name, info_names[bit]);
	else if (chan->indexed)
		scnprintf(a->name, sizeof(a->name), "%s_%s%d_%s", dir, type_name(chan), chan->channel,
			  info_names[bit]);
	else
		scnprintf(a->name, sizeof(a->name), "%s_%s_%s", dir, type_name(chan), info_names[bit]);
	for (i = 0; i < *n; i++)
		if (!strcmp(indio_dev->lx_attrs[i].name, a->name))
			return 0;       /* a shared file, made for an earlier channel */
	if (*n + 1 >= LX_IIO_MAX_FILES) {
		dev_err(indio_dev->dev.parent, "IIO: more than %d channel files\n", LX_IIO_MAX_FILES - 1);
		return -ENOSPC;
	}
	a->chan = chan;
	a->mask = bit;
	a->dev_attr.attr.name = a->name;
	a->dev_attr.attr.mode = 0444;
	a->dev_attr.show = iio_read_channel_info;
	(*n)++;
	return 0;
}

/* Builds the device's channel files and its attribute groups. */
static int build_files(struct iio_dev *indio_dev)
{
	struct attribute **attrs;
	unsigned int n = 0, i;
	long bit;
	int c, ret;

	indio_dev->lx_attrs = kzalloc(LX_IIO_MAX_FILES * sizeof(*indio_dev->lx_attrs) +
				      (LX_IIO_MAX_FILES + 1) * sizeof(*attrs), GFP_KERNEL);
	if (!indio_dev->lx_attrs)
		return -ENOMEM;
	attrs = (struct attribute **)(indio_dev->lx_attrs + LX_IIO_MAX_FILES);
	for (c = 0; c < indio_dev->num_channels; c++) {
		const struct iio_chan_spec *chan = &indio_dev->channels[c];

		if (!type_name(chan)) {
			dev_err(indio_dev->dev.parent, "IIO: channel %d has a type without a name here\n", c);
			return -EINVAL;
		}
		for (bit = 0; bit < BITS_PER_LONG; bit++) {
			ret = 0;
			if (chan->info_mask_separate & BIT(bit))
				ret = add_channel_file(indio_dev, chan, bit, false, &n);
			if (!ret && (chan->info_mask_shared_by_type & BIT(bit)))
				ret = add_channel_file(indio_dev, chan, bit, true, &n);
			if (ret)
				return ret;
		}
	}
	for (i = 0; i < n; i++)
		attrs[i] = &indio_dev->lx_attrs[i].dev_attr.attr;
	attrs[n++] = &dev_attr_name.attr;
	attrs[n] = NULL;
	indio_dev->lx_group.attrs = attrs;
	indio_dev->lx_groups[0] = &indio_dev->lx_group;
	indio_dev->lx_groups[1] = indio_dev->info->attrs;
	indio_dev->lx_groups[2] = NULL;
	indio_dev->dev.groups = indio_dev->lx_groups;
	return 0;
}

int __iio_device_register(struct iio_dev *indio_dev, struct module *this_mod)
{
	int id, ret;

	might_sleep();
	if (!indio_dev || !indio_dev->info || !indio_dev->info->read_raw || indio_dev->lx_id >= 0)
		return -EINVAL;
	ret = build_files(indio_dev);
	if (ret)
		goto fail;
	mutex_lock(&iio_list_lock);
	for (id = 0; id < BITS_PER_LONG && (iio_ids & BIT(id)); id++)
		;
	if (id == BITS_PER_LONG) {
		mutex_unlock(&iio_list_lock);
		ret = -ENOSPC;
		goto fail;
	}
	iio_ids |= BIT(id);
	mutex_unlock(&iio_list_lock);
	dev_set_name(&indio_dev->dev, "iio:device%d", id);
	ret = device_add(&indio_dev->dev);
	if (ret) {
		mutex_lock(&iio_list_lock);
		iio_ids &= ~BIT(id);
		mutex_unlock(&iio_list_lock);
		goto fail;
	}
	mutex_lock(&iio_list_lock);
	indio_dev->lx_id = id;
	list_add_tail(&indio_dev->lx_node, &iio_devices);
	mutex_unlock(&iio_list_lock);
	return 0;
fail:
	kfree(indio_dev->lx_attrs);
	indio_dev->lx_attrs = NULL;
	indio_dev->dev.groups = NULL;
	return ret;
}

void iio_device_unregister(struct iio_dev *indio_dev)
{
	might_sleep();
	if (!indio_dev || indio_dev->lx_id < 0) {
		lx_report("iio_device_unregister of a device not registered", __FILE__, __LINE__, "%s",
			  indio_dev && indio_dev->name ? indio_dev->name : "(unnamed)");
		return;
	}
	device_del(&indio_dev->dev);
	mutex_lock(&iio_list_lock);
	list_del_init(&indio_dev->lx_node);
	iio_ids &= ~BIT(indio_dev->lx_id);
	mutex_unlock(&iio_list_lock);
	/* no read runs now, and none starts: consumers see the info gone */
	mutex_lock(&indio_dev->mlock);
	indio_dev->info = NULL;
	indio_dev->lx_id = -1;
	mutex_unlock(&indio_dev->mlock);
	iio_map_array_unregister(indio_dev);
}

/* devres action of devm_iio_device_register. */
static void devm_iio_device_unreg(void *indio_dev)
{
	iio_device_unregister(indio_dev);
}

int __devm_iio_device_register(struct device *dev, struct iio_dev *indio_dev, struct module *this_mod)
{
	int ret = __iio_device_register(indio_dev, this_mod);

	if (ret)
		return ret;
	return devm_add_action_or_reset(dev, devm_iio_device_unreg, indio_dev);
}

/* ---- maps and consumers ---- */

int iio_map_array_register(struct iio_dev *indio_dev, struct iio_map *maps)
{
	struct iio_map_entry *e;

	might_sleep();
	for (; maps && maps->adc_channel_label; maps++) {
		e = kzalloc(sizeof(*e), GFP_KERNEL);
		if (!e) {
			iio_map_array_unregister(indio_dev);
			return -ENOMEM;
		}
		e->map = maps;
		mutex_lock(&iio_list_lock);
		list_add_tail(&e->node, &indio_dev->lx_maps);
		mutex_unlock(&iio_list_lock);
	}
	return 0;
}

int iio_map_array_unregister(struct iio_dev *indio_dev)
{
	struct iio_map_entry *e, *next;

	mutex_lock(&iio_list_lock);
	list_for_each_entry_safe(e, next, &indio_dev->lx_maps, node) {
		list_del(&e->node);
		kfree(e);
	}
	mutex_unlock(&iio_list_lock);
	return 0;
}

/* devres action of devm_iio_map_array_register. */
static void devm_iio_map_unreg(void *indio_dev)
{
	iio_map_array_unregister(indio_dev);
}

int devm_iio_map_array_register(struct device *dev, struct iio_dev *indio_dev, struct iio_map *maps)
{
	int ret = iio_map_array_register(indio_dev, maps);

	if (ret)
		return ret;
	return devm_add_action_or_reset(dev, devm_iio_map_unreg, indio_dev);
}

struct iio_channel *iio_channel_get(struct device *dev, const char *consumer_channel)
{
	const char *name = dev ? dev_name(dev) : NULL;
	struct iio_channel *channel;
	struct iio_map_entry *e;
	struct iio_dev *indio_dev;
	const struct iio_map *found = NULL;
	struct iio_dev *provider = NULL;
	int c;

	might_sleep();
	mutex_lock(&iio_list_lock);
	list_for_each_entry(indio_dev, &iio_devices, lx_node) {
		list_for_each_entry(e, &indio_dev->lx_maps, node) {
			if ((name && e->map->consumer_dev_name && strcmp(name, e->map->consumer_dev_name)) ||
			    (consumer_channel && e->map->consumer_channel &&
			     strcmp(consumer_channel, e->map->consumer_channel)))
				continue;
			found = e->map;
			provider = indio_dev;
			goto out;
		}
	}
out:
	if (provider)
		get_device(&provider->dev);
	mutex_unlock(&iio_list_lock);
	if (!found)
		return ERR_PTR(-ENODEV);
	channel = kzalloc(sizeof(*channel), GFP_KERNEL);
	if (!channel) {
		put_device(&provider->dev);
		return ERR_PTR(-ENOMEM);
	}
	channel->indio_dev = provider;
	channel->data = found->consumer_data;
	for (c = 0; c < provider->num_channels; c++) {
		if (provider->channels[c].datasheet_name &&
		    !strcmp(provider->channels[c].datasheet_name, found->adc_channel_label))
			channel->channel = &provider->channels[c];
	}
	if (!channel->channel) {
		pr_err("iio: %s has no channel %s\n", dev_name(&provider->dev), found->adc_channel_label);
		iio_channel_release(channel);
		return ERR_PTR(-ENODEV);
	}
	return channel;
}

void iio_channel_release(struct iio_channel *chan)
{
	if (!chan)
		return;
	put_device(&chan->indio_dev->dev);
	kfree(chan);
}

/* devres action of devm_iio_channel_get. */
static void devm_iio_channel_free(void *chan)
{
	iio_channel_release(chan);
}

struct iio_channel *devm_iio_channel_get(struct device *dev, const char *consumer_channel)
{
	struct iio_channel *chan = iio_channel_get(dev, consumer_channel);
	int ret;

	if (IS_ERR(chan))
		return chan;
	ret = devm_add_action_or_reset(dev, devm_iio_channel_free, chan);
	return ret ? ERR_PTR(ret) : chan;
}

/* read_raw of chan's info element under the provider's lock: its type, or -ENODEV once unregistered. */
static int channel_read(struct iio_channel *chan, int *val, int *val2, enum iio_chan_info_enum info)
{
	struct iio_dev *indio_dev = chan->indio_dev;
	int unused, ret;

	might_sleep();
	if (!val2)
		val2 = &unused;
	mutex_lock(&indio_dev->mlock);
	if (!indio_dev->info)
		ret = -ENODEV;
	else if (!iio_channel_has_info(chan->channel, info))
		ret = -EINVAL;
	else
		ret = indio_dev->info->read_raw(indio_dev, chan->channel, val, val2, info);
	mutex_unlock(&indio_dev->mlock);
	return ret;
}

int iio_read_channel_raw(struct iio_channel *chan, int *val)
{
	return channel_read(chan, val, NULL, IIO_CHAN_INFO_RAW);
}

int iio_read_channel_scale(struct iio_channel *chan, int *val, int *val2)
{
	return channel_read(chan, val, val2, IIO_CHAN_INFO_SCALE);
}

int iio_get_channel_type(struct iio_channel *chan, enum iio_chan_type *type)
{
	if (!chan->indio_dev->info)
		return -ENODEV;
	*type = chan->channel->type;
	return 0;
}

int iio_convert_raw_to_processed(struct iio_channel *chan, int raw, int *processed, unsigned int scale)
{
	int offset = 0, val, val2, type;
	s64 raw64;

	if (iio_channel_has_info(chan->channel, IIO_CHAN_INFO_OFFSET) &&
	    channel_read(chan, &offset, NULL, IIO_CHAN_INFO_OFFSET) < 0)
		offset = 0;
	raw64 = (s64)raw + offset;
	type = channel_read(chan, &val, &val2, IIO_CHAN_INFO_SCALE);
	if (type == -EINVAL) {
		/* no scale: the raw value is the processed one (inkern.c's rule) */
		*processed = (int)(raw64 * scale);
		return 0;
	}
	if (type < 0)
		return type;
	switch (type) {
	case IIO_VAL_INT:
		*processed = (int)(raw64 * val * scale);
		break;
	case IIO_VAL_INT_PLUS_MICRO:
		*processed = (int)(raw64 * val * scale + div_s64(raw64 * val2 * scale, 1000000));
		break;
	case IIO_VAL_INT_PLUS_NANO:
		*processed = (int)(raw64 * val * scale + div_s64(raw64 * val2 * scale, 1000000000));
		break;
	case IIO_VAL_FRACTIONAL:
		*processed = (int)div_s64(raw64 * val * scale, val2);
		break;
	case IIO_VAL_FRACTIONAL_LOG2:
		*processed = (int)((raw64 * val * scale) >> val2);
		break;
	default:
		return -EINVAL;
	}
	return 0;
}

int iio_read_channel_processed(struct iio_channel *chan, int *val)
{
	int raw, ret;

	if (iio_channel_has_info(chan->channel, IIO_CHAN_INFO_PROCESSED))
		return channel_read(chan, val, NULL, IIO_CHAN_INFO_PROCESSED);
	ret = channel_read(chan, &raw, NULL, IIO_CHAN_INFO_RAW);
	if (ret < 0)
		return ret;
	return iio_convert_raw_to_processed(chan, raw, val, 1);
}

void lx_iio_boot(void)
{
	INIT_LIST_HEAD(&iio_devices);
	mutex_init(&iio_list_lock);
	iio_ids = 0;
	lx_bus_register_boot(&iio_bus_type);
}
