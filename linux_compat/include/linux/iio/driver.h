/*
 * linux/iio/driver.h — a provider's in-kernel consumers (Linux 6.1's
 * include/linux/iio/driver.h).
 */
#ifndef _IIO_INKERN_H_
#define _IIO_INKERN_H_

struct device;
struct iio_dev;
struct iio_map;

/* Registers maps (an array ended by an entry without adc_channel_label) for
 * indio_dev's channels: 0 or -ENOMEM.  Process context. */
int iio_map_array_register(struct iio_dev *indio_dev, struct iio_map *maps);
/* Forgets every map of indio_dev; 0. */
int iio_map_array_unregister(struct iio_dev *indio_dev);
/* iio_map_array_register undone when dev's driver unbinds. */
int devm_iio_map_array_register(struct device *dev, struct iio_dev *indio_dev, struct iio_map *maps);

#endif /* _IIO_INKERN_H_ */
