// SPDX-License-Identifier: GPL-2.0
/*
 * ads7957_adc.c - the TI ADS7957 (10-bit, 16 channels, SPI) as an IIO
 * device, read one channel at a time in the converter's manual mode (TI's
 * ADS79xx datasheet): a 16-bit command word selects the channel and the
 * 0..2*VREF range, the converter samples it during the next frame and
 * shifts the result out in the frame after that, as bits 15-12 the channel
 * and bits 11-2 the code.  A read is three frames, each with its own chip
 * select; the third answer must name the channel asked for.  The scale
 * comes from the reference (2.5 V on LEGO's EV3: 2 * 2500 mV / 1024 per
 * code).  Consumers find the channels through the maps the board gives as
 * platform data (an array of struct iio_map).
 */
#include <linux/iio/driver.h>
#include <linux/iio/iio.h>
#include <linux/iio/machine.h>
#include <linux/mod_devicetable.h>
#include <linux/module.h>
#include <linux/mutex.h>
#include <linux/spi/spi.h>

#define ADS7957_CHANNELS	16
#define ADS7957_CMD_MANUAL	(1 << 12)	/* mode control: manual channel selection */
#define ADS7957_CMD_PROGRAM	(1 << 11)	/* take bits 10-0 of this word */
#define ADS7957_CMD_RANGE2	(1 << 6)	/* 0..2*VREF */
#define ADS7957_CMD_CHANNEL(c)	((c) << 7)
#define ADS7957_VREF_MV		2500
#define ADS7957_BITS		10

struct ads7957 {
	struct spi_device *spi;
	struct mutex lock;	/* one three-frame read at a time */
	u16 tx[3];
	u16 rx[3];
};

#define ADS7957_CHAN(n) {						\
	.type = IIO_VOLTAGE,						\
	.indexed = 1,							\
	.channel = n,							\
	.datasheet_name = "CH" #n,					\
	.info_mask_separate = BIT(IIO_CHAN_INFO_RAW),			\
	.info_mask_shared_by_type = BIT(IIO_CHAN_INFO_SCALE),		\
}

static const struct iio_chan_spec ads7957_channels[ADS7957_CHANNELS] = {
	ADS7957_CHAN(0), ADS7957_CHAN(1), ADS7957_CHAN(2), ADS7957_CHAN(3),
	ADS7957_CHAN(4), ADS7957_CHAN(5), ADS7957_CHAN(6), ADS7957_CHAN(7),
	ADS7957_CHAN(8), ADS7957_CHAN(9), ADS7957_CHAN(10), ADS7957_CHAN(11),
	ADS7957_CHAN(12), ADS7957_CHAN(13), ADS7957_CHAN(14), ADS7957_CHAN(15),
};

/* The code of channel ch, or a negative errno. */
static int ads7957_read_code(struct ads7957 *adc, unsigned int ch)
{
	struct spi_transfer xfers[3] = { };
	unsigned int i;
	int ret;

	mutex_lock(&adc->lock);
	for (i = 0; i < ARRAY_SIZE(xfers); i++) {
		adc->tx[i] = ADS7957_CMD_MANUAL | ADS7957_CMD_PROGRAM | ADS7957_CMD_RANGE2 |
			     ADS7957_CMD_CHANNEL(ch);
		xfers[i].tx_buf = &adc->tx[i];
		xfers[i].rx_buf = &adc->rx[i];
		xfers[i].len = 2;
		xfers[i].bits_per_word = 16;
		xfers[i].cs_change = i + 1 < ARRAY_SIZE(xfers);
	}
	ret = spi_sync_transfer(adc->spi, xfers, ARRAY_SIZE(xfers));
	if (!ret) {
		if ((adc->rx[2] >> 12) != ch)
			ret = -EIO;
		else
			ret = (adc->rx[2] >> 2) & ((1 << ADS7957_BITS) - 1);
	}
	mutex_unlock(&adc->lock);
	return ret;
}

static int ads7957_read_raw(struct iio_dev *indio_dev, struct iio_chan_spec const *chan, int *val,
			    int *val2, long mask)
{
	struct ads7957 *adc = iio_priv(indio_dev);
	int code;

	switch (mask) {
	case IIO_CHAN_INFO_RAW:
		code = ads7957_read_code(adc, chan->channel);
		if (code < 0)
			return code;
		*val = code;
		return IIO_VAL_INT;
	case IIO_CHAN_INFO_SCALE:
		*val = 2 * ADS7957_VREF_MV;
		*val2 = ADS7957_BITS;
		return IIO_VAL_FRACTIONAL_LOG2;
	default:
		return -EINVAL;
	}
}

static const struct iio_info ads7957_info = {
	.read_raw = ads7957_read_raw,
};

static int ads7957_probe(struct spi_device *spi)
{
	struct iio_map *maps = dev_get_platdata(&spi->dev);
	struct iio_dev *indio_dev;
	struct ads7957 *adc;
	int ret;

	indio_dev = devm_iio_device_alloc(&spi->dev, sizeof(*adc));
	if (!indio_dev)
		return -ENOMEM;
	adc = iio_priv(indio_dev);
	adc->spi = spi;
	mutex_init(&adc->lock);
	spi->bits_per_word = 16;
	spi->mode = SPI_MODE_0;
	ret = spi_setup(spi);
	if (ret)
		return dev_err_probe(&spi->dev, ret, "cannot set up 16-bit words\n");
	indio_dev->name = spi_get_device_id(spi)->name;
	indio_dev->modes = INDIO_DIRECT_MODE;
	indio_dev->channels = ads7957_channels;
	indio_dev->num_channels = ARRAY_SIZE(ads7957_channels);
	indio_dev->info = &ads7957_info;
	if (maps) {
		ret = devm_iio_map_array_register(&spi->dev, indio_dev, maps);
		if (ret)
			return ret;
	}
	return devm_iio_device_register(&spi->dev, indio_dev);
}

static const struct spi_device_id ads7957_ids[] = {
	{ "ads7957" },
	{ }
};
MODULE_DEVICE_TABLE(spi, ads7957_ids);

static struct spi_driver ads7957_driver = {
	.driver = {
		.name = "ads7957",
	},
	.probe = ads7957_probe,
	.id_table = ads7957_ids,
};
module_spi_driver(ads7957_driver);

MODULE_DESCRIPTION("TI ADS7957 analog-to-digital converter");
MODULE_AUTHOR("ev3lx");
MODULE_LICENSE("GPL");
