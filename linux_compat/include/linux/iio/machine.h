/*
 * linux/iio/machine.h — the board's map from an IIO device's channels to
 * their consumers (Linux 6.1's include/linux/iio/machine.h).
 */
#ifndef __LINUX_IIO_MACHINE_H__
#define __LINUX_IIO_MACHINE_H__

/* The provider's channel adc_channel_label (its datasheet_name) serves the
 * device called consumer_dev_name as consumer_channel. */
struct iio_map {
	const char *adc_channel_label;
	const char *consumer_dev_name;
	const char *consumer_channel;
	void *consumer_data;
};

#define IIO_MAP(_provider_channel, _consumer_dev_name, _consumer_channel)	\
{										\
	.adc_channel_label = _provider_channel,					\
	.consumer_dev_name = _consumer_dev_name,				\
	.consumer_channel = _consumer_channel,					\
}

#endif /* __LINUX_IIO_MACHINE_H__ */
