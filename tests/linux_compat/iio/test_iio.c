/*
 * test_iio.c — the IIO core with a device whose read_raw answers from a
 * table: iio:device<n> numbering, the channel files (separate, shared by
 * type written once, extend_name, output channels) and how each IIO_VAL_*
 * type reads in sysfs; maps and iio_channel_get (by consumer device and
 * channel, -ENODEV without a map); raw, scale and processed values
 * (FRACTIONAL, INT_PLUS_MICRO, FRACTIONAL_LOG2, with OFFSET; without a
 * scale the raw value); -ENODEV after unregistering; devm registration
 * undone on unbind; misuse reported.
 */
#define KBUILD_MODNAME "iiotest"
#include "lx_log_test.h"
#include <linux/iio/consumer.h>
#include <linux/iio/driver.h>
#include <linux/iio/iio.h>
#include <linux/iio/machine.h>
#include <linux/platform_device.h>
#include <linux/spinlock.h>
#include <linux_compat/sysfs.h>
#include "host_sim/board.h"

static int scale_type = IIO_VAL_FRACTIONAL;
static int scale_val = 3300, scale_val2 = 4096;

static int table_read_raw(struct iio_dev *indio_dev, struct iio_chan_spec const *chan, int *val,
			  int *val2, long mask)
{
	switch (mask) {
	case IIO_CHAN_INFO_RAW:
		*val = 1000 + chan->channel;
		return IIO_VAL_INT;
	case IIO_CHAN_INFO_SCALE:
		*val = scale_val;
		*val2 = scale_val2;
		return scale_type;
	case IIO_CHAN_INFO_OFFSET:
		*val = -24;
		return IIO_VAL_INT;
	case IIO_CHAN_INFO_PROCESSED:
		*val = -1234;
		*val2 = -500000;
		return IIO_VAL_INT_PLUS_MICRO;
	default:
		return -EINVAL;
	}
}

static const struct iio_info table_info = { .read_raw = table_read_raw };

static const struct iio_chan_spec table_channels[] = {
	{ .type = IIO_VOLTAGE, .indexed = 1, .channel = 0, .datasheet_name = "AIN0",
	  .info_mask_separate = BIT(IIO_CHAN_INFO_RAW), .info_mask_shared_by_type = BIT(IIO_CHAN_INFO_SCALE) },
	{ .type = IIO_VOLTAGE, .indexed = 1, .channel = 1, .datasheet_name = "AIN1", .extend_name = "supply",
	  .info_mask_separate = BIT(IIO_CHAN_INFO_RAW), .info_mask_shared_by_type = BIT(IIO_CHAN_INFO_SCALE) },
	{ .type = IIO_TEMP, .datasheet_name = "TEMP",
	  .info_mask_separate = BIT(IIO_CHAN_INFO_RAW) | BIT(IIO_CHAN_INFO_OFFSET) | BIT(IIO_CHAN_INFO_SCALE) },
	{ .type = IIO_CURRENT, .indexed = 1, .channel = 0, .datasheet_name = "I0",
	  .info_mask_separate = BIT(IIO_CHAN_INFO_PROCESSED) },
	{ .type = IIO_VOLTAGE, .indexed = 1, .channel = 2, .datasheet_name = "RAWONLY",
	  .info_mask_separate = BIT(IIO_CHAN_INFO_RAW) },
};

static struct iio_map table_maps[] = {
	IIO_MAP("AIN0", "consumer", "vin"),
	IIO_MAP("TEMP", "consumer", "temp"),
	IIO_MAP("I0", "consumer", "current"),
	IIO_MAP("AIN1", "other", NULL),
	IIO_MAP("NOPE", "consumer", "missing"),
	{ }
};

static char text[64];

static const char *cat(const char *path)
{
	ssize_t n = lx_sysfs_read(path, text, sizeof(text) - 1);

	text[n > 0 ? n : 0] = '\0';
	return text;
}

static struct device consumer = { .init_name = "consumer" };
static struct device other = { .init_name = "other" };
static DEFINE_SPINLOCK(test_lock);

static void core_tests(void)
{
	struct iio_dev *first = iio_device_alloc(NULL, 0), *indio_dev;
	struct iio_channel *vin, *temp, *cur, *any;
	unsigned long flags;
	int val, val2;

	first->name = "first";
	first->info = &table_info;
	first->channels = table_channels;
	first->num_channels = 1;
	is_int(iio_device_register(first), 0, "a first device: iio:device0");

	indio_dev = iio_device_alloc(NULL, 16);
	ok(indio_dev && iio_priv(indio_dev) != NULL, "iio_device_alloc with private data");
	is_int(iio_device_register(indio_dev), -EINVAL, "without info: -EINVAL");
	indio_dev->name = "table";
	indio_dev->info = &table_info;
	indio_dev->channels = table_channels;
	indio_dev->num_channels = ARRAY_SIZE(table_channels);
	is_int(iio_map_array_register(indio_dev, table_maps), 0, "iio_map_array_register");
	is_int(iio_device_register(indio_dev), 0, "iio_device_register");
	is_int(iio_device_id(indio_dev), 1, "iio:device1");

	is_str(cat("/sys/bus/iio/devices/iio:device1/name"), "table\n", "name");
	is_str(cat("/sys/bus/iio/devices/iio:device1/in_voltage0_raw"), "1000\n", "in_voltage0_raw");
	is_str(cat("/sys/bus/iio/devices/iio:device1/in_voltage1_supply_raw"), "1001\n",
	       "an extend_name: in_voltage1_supply_raw");
	is_str(cat("/sys/bus/iio/devices/iio:device1/in_voltage_scale"), "0.805664062\n",
	       "one in_voltage_scale for both (IIO_VAL_FRACTIONAL 3300/4096)");
	is_int((int)lx_sysfs_read("/sys/bus/iio/devices/iio:device1/in_voltage0_scale", text, 8), -ENOENT,
	       "no per-channel scale");
	is_str(cat("/sys/bus/iio/devices/iio:device1/in_temp_offset"), "-24\n", "in_temp_offset");
	is_str(cat("/sys/bus/iio/devices/iio:device1/in_current0_input"), "-1234.500000\n",
	       "PROCESSED as in_current0_input, IIO_VAL_INT_PLUS_MICRO");
	is_int((int)lx_sysfs_write("/sys/bus/iio/devices/iio:device1/in_voltage0_raw", "1", 1), -EACCES,
	       "channel files are read-only");

	vin = iio_channel_get(&consumer, "vin");
	temp = iio_channel_get(&consumer, "temp");
	cur = iio_channel_get(&consumer, "current");
	any = iio_channel_get(&other, NULL);
	ok(!IS_ERR(vin) && !IS_ERR(temp) && !IS_ERR(cur) && !IS_ERR(any), "iio_channel_get of four maps");
	ok(!IS_ERR(any) && any->channel == &table_channels[1], "a NULL consumer channel: the device's map");
	ok(PTR_ERR(iio_channel_get(&consumer, "missing")) == -ENODEV, "a map to a channel the device lacks: -ENODEV");
	ok(PTR_ERR(iio_channel_get(&consumer, "absent")) == -ENODEV, "no map: -ENODEV");
	is_int(iio_read_channel_raw(vin, &val), IIO_VAL_INT, "iio_read_channel_raw");
	is_int(val, 1000, "the raw value");
	is_int(iio_read_channel_scale(vin, &val, &val2), IIO_VAL_FRACTIONAL, "iio_read_channel_scale's type");
	is_int(iio_read_channel_processed(vin, &val), 0, "iio_read_channel_processed");
	is_int(val, 805, "1000 * 3300 / 4096");
	scale_type = IIO_VAL_INT_PLUS_MICRO;
	scale_val = 2;
	scale_val2 = 500000;
	iio_read_channel_processed(temp, &val);
	is_int(val, 2440, "TEMP: (1000 - 24) * 2.5 (OFFSET and IIO_VAL_INT_PLUS_MICRO)");
	scale_type = IIO_VAL_FRACTIONAL_LOG2;
	scale_val = 5000;
	scale_val2 = 10;
	iio_read_channel_processed(vin, &val);
	is_int(val, 4882, "1000 * 5000 >> 10 (IIO_VAL_FRACTIONAL_LOG2)");
	is_str(cat("/sys/bus/iio/devices/iio:device1/in_voltage_scale"), "4.882812500\n", "and so reads its file");
	is_int(iio_read_channel_processed(cur, &val), IIO_VAL_INT_PLUS_MICRO, "a PROCESSED channel is read as is");
	is_int(val, -1234, "its integer part");
	{
		struct iio_channel raw_only = { .indio_dev = indio_dev, .channel = &table_channels[4] };

		is_int(iio_read_channel_processed(&raw_only, &val), 0, "a channel without a scale");
		is_int(val, 1002, "reads its raw value");
	}

	spin_lock_irqsave(&test_lock, flags);
	ok(DC_EXPECT_BUG(iio_read_channel_raw(vin, &val)) >= 1, "reading a channel under a spin lock is reported");
	spin_unlock_irqrestore(&test_lock, flags);
	is_int(DC_EXPECT_BUG(iio_device_free(indio_dev)), 1, "iio_device_free of a registered device is reported");

	iio_device_unregister(indio_dev);
	is_int(iio_read_channel_raw(vin, &val), -ENODEV, "unregistered: a held channel reads -ENODEV");
	is_int((int)lx_sysfs_read("/sys/bus/iio/devices/iio:device1/name", text, 8), -ENOENT, "and its files are gone");
	ok(PTR_ERR(iio_channel_get(&consumer, "vin")) == -ENODEV, "and its maps");
	iio_channel_release(vin);
	iio_channel_release(temp);
	iio_channel_release(cur);
	iio_channel_release(any);
	iio_device_free(indio_dev);
	iio_device_unregister(first);
	iio_device_free(first);
}

static struct iio_dev *devm_dev;

static int adc_probe(struct platform_device *pdev)
{
	devm_dev = devm_iio_device_alloc(&pdev->dev, 8);
	if (!devm_dev)
		return -ENOMEM;
	devm_dev->name = "devm-adc";
	devm_dev->info = &table_info;
	devm_dev->channels = table_channels;
	devm_dev->num_channels = 1;
	return devm_iio_device_register(&pdev->dev, devm_dev);
}

static struct platform_driver adc_driver = { .probe = adc_probe, .driver = { .name = "iiotest-adc" } };

static void devm_tests(void)
{
	struct platform_device *pdev = platform_device_alloc("iiotest-adc", -1);

	platform_device_add(pdev);
	is_int(platform_driver_register(&adc_driver), 0, "a driver with devm IIO");
	is_str(cat("/sys/bus/iio/devices/iio:device0/name"), "devm-adc\n", "registered as iio:device0 (numbers are reused)");
	platform_driver_unregister(&adc_driver);
	is_int((int)lx_sysfs_read("/sys/bus/iio/devices/iio:device0/name", text, 8), -ENOENT, "gone on unbind");
	platform_device_unregister(pdev);
}

static void body(void)
{
	core_tests();
	devm_tests();
}

int main(void)
{
	tap_plan(40);
	is_int(hs_board_init(NULL), E_OK, "host_sim board");
	ok(lx_test_run(body), "test task ran to completion");
	hs_board_shutdown();
	return tap_done();
}
