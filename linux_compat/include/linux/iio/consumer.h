/*
 * linux/iio/consumer.h — reading another driver's IIO channel (Linux 6.1's
 * include/linux/iio/consumer.h): the channel the board's maps give a
 * consumer device (linux/iio/machine.h, linux/iio/driver.h), its raw value,
 * scale and the processed value (raw times scale, in the type's unit: mV for
 * a voltage).  All may sleep; a channel whose provider has unregistered
 * reads -ENODEV.
 */
#ifndef _IIO_INKERN_CONSUMER_H_
#define _IIO_INKERN_CONSUMER_H_

#include <linux/types.h>
#include <linux/iio/types.h>

struct device;
struct iio_dev;
struct iio_chan_spec;

struct iio_channel {
	struct iio_dev *indio_dev;
	const struct iio_chan_spec *channel;
	void *data;
};

/* The channel mapped to dev as consumer_channel (NULL: its first map): it,
 * or ERR_PTR(-ENODEV) (no map, or the provider lacks the channel), -ENOMEM. */
struct iio_channel *iio_channel_get(struct device *dev, const char *consumer_channel);
/* Releases a channel from iio_channel_get. */
void iio_channel_release(struct iio_channel *chan);
/* iio_channel_get released when dev's driver unbinds. */
struct iio_channel *devm_iio_channel_get(struct device *dev, const char *consumer_channel);

/* The raw value into *val: read_raw's IIO_VAL_* type (IIO_VAL_INT), or
 * -ENODEV or the provider's error. */
int iio_read_channel_raw(struct iio_channel *chan, int *val);
/* The scale: its IIO_VAL_* type, or -ENODEV / -EINVAL / the provider's error. */
int iio_read_channel_scale(struct iio_channel *chan, int *val, int *val2);
/* The processed value (PROCESSED if the channel has it, else RAW scaled):
 * 0, or an error. */
int iio_read_channel_processed(struct iio_channel *chan, int *val);
/* The channel's type through *type; 0 or -ENODEV. */
int iio_get_channel_type(struct iio_channel *chan, enum iio_chan_type *type);
/* raw scaled by the channel's SCALE (and OFFSET) times scale, into *processed. */
int iio_convert_raw_to_processed(struct iio_channel *chan, int raw, int *processed,
				 unsigned int scale);

#endif /* _IIO_INKERN_CONSUMER_H_ */
