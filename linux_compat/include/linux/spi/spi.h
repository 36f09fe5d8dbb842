/*
 * linux/spi/spi.h — the SPI bus as Linux 6.1 defines it for protocol
 * drivers (struct spi_device, spi_driver, spi_message, spi_transfer,
 * spi_sync/spi_write/spi_read) and for controller drivers
 * (struct spi_controller with transfer_one and set_cs), implemented by
 * linux_compat/src/spi.c.
 *
 * Matching: a device binds to the first registered driver whose id_table
 * holds its modalias (else whose driver.name equals it), when either is
 * registered; board code declares devices with spi_register_board_info
 * (created when the controller of their bus_num registers) or spi_new_device.
 * spi_sync runs the message on the caller's thread: the controller's
 * transfer_one completes each transfer before returning (0) or fails it
 * (-errno); the chip select is asserted from the first transfer to the end
 * of the message, deasserted between transfers that set cs_change, and
 * driven by the core through a GPIO when the controller gives one for the
 * chip select (cs_gpios[], as Linux's legacy GPIO chip selects), else by
 * set_cs.  Process context (the bus lock is a mutex): -EINVAL for a NULL
 * or empty message, a transfer without buffers, or an unsupported
 * bits_per_word; -ESHUTDOWN after the controller went away.
 */
#ifndef _LINUX_SPI_SPI_H
#define _LINUX_SPI_SPI_H

#include <linux/types.h>
#include <linux/list.h>
#include <linux/device.h>
#include <linux/mutex.h>
#include <linux/module.h>
#include <linux/mod_devicetable.h>
#include <linux/init.h>
#include <linux/string.h>

#define SPI_CPHA	0x01
#define SPI_CPOL	0x02
#define SPI_MODE_0	(0 | 0)
#define SPI_MODE_1	(0 | SPI_CPHA)
#define SPI_MODE_2	(SPI_CPOL | 0)
#define SPI_MODE_3	(SPI_CPOL | SPI_CPHA)
#define SPI_CS_HIGH	0x04
#define SPI_LSB_FIRST	0x08
#define SPI_3WIRE	0x10
#define SPI_LOOP	0x20
#define SPI_NO_CS	0x40
#define SPI_READY	0x80

#define SPI_BPW_MASK(bits)		(1U << ((bits) - 1))

struct spi_controller;

struct spi_device {
	struct device dev;
	struct spi_controller *controller;
	struct spi_controller *master;  /* = controller (older drivers' name) */
	u32 max_speed_hz;
	u8 chip_select;
	u8 bits_per_word;
	u32 mode;
	int irq;
	void *controller_state;
	void *controller_data;
	char modalias[SPI_NAME_SIZE];
	int cs_gpio;                    /* chip select GPIO, -1: the controller's */
	struct list_head lx_node;       /* ev3lx: on the bus's device list */
	char lx_name[SPI_NAME_SIZE];    /* ev3lx: "spiB.C", dev_name */
};

static inline struct spi_device *to_spi_device(struct device *dev)
{
	return container_of(dev, struct spi_device, dev);
}

static inline void spi_set_drvdata(struct spi_device *spi, void *data)
{
	dev_set_drvdata(&spi->dev, data);
}

static inline void *spi_get_drvdata(struct spi_device *spi)
{
	return dev_get_drvdata(&spi->dev);
}

struct spi_driver {
	const struct spi_device_id *id_table;
	int (*probe)(struct spi_device *spi);
	void (*remove)(struct spi_device *spi);
	void (*shutdown)(struct spi_device *spi);
	struct device_driver driver;
	struct list_head lx_node;       /* ev3lx: on the bus's driver list */
};

static inline struct spi_driver *to_spi_driver(struct device_driver *drv)
{
	return drv ? container_of(drv, struct spi_driver, driver) : NULL;
}

/* Registers sdrv and binds it to the matching unbound devices: 0 or -EINVAL/-EBUSY. */
int __spi_register_driver(struct module *owner, struct spi_driver *sdrv);
#define spi_register_driver(driver)	__spi_register_driver(THIS_MODULE, (driver))
/* Unbinds sdrv from its devices (their remove) and forgets it. */
void spi_unregister_driver(struct spi_driver *sdrv);

#define module_spi_driver(__spi_driver)						\
	static int __init __spi_driver##_init(void)				\
	{ return spi_register_driver(&(__spi_driver)); }			\
	module_init(__spi_driver##_init);					\
	static void __exit __spi_driver##_exit(void)				\
	{ spi_unregister_driver(&(__spi_driver)); }				\
	module_exit(__spi_driver##_exit)

/* The id_table entry the device matched (NULL if it matched by driver name). */
const struct spi_device_id *spi_get_device_id(const struct spi_device *sdev);

struct spi_transfer {
	const void *tx_buf;
	void *rx_buf;
	unsigned int len;
	unsigned int cs_change:1;
	u8 bits_per_word;               /* 0: the device's */
	u32 speed_hz;                   /* 0: the device's */
	u16 delay_usecs;                /* after the transfer, before the chip select changes */
	struct list_head transfer_list;
};

struct spi_message {
	struct list_head transfers;
	struct spi_device *spi;
	void (*complete)(void *context);
	void *context;
	unsigned int frame_length;
	unsigned int actual_length;
	int status;
};

static inline void spi_message_init_no_memset(struct spi_message *m)
{
	INIT_LIST_HEAD(&m->transfers);
}

static inline void spi_message_init(struct spi_message *m)
{
	memset(m, 0, sizeof(*m));
	spi_message_init_no_memset(m);
}

static inline void spi_message_add_tail(struct spi_transfer *t, struct spi_message *m)
{
	list_add_tail(&t->transfer_list, &m->transfers);
}

static inline void spi_message_init_with_transfers(struct spi_message *m, struct spi_transfer *xfers,
						   unsigned int num_xfers)
{
	unsigned int i;

	spi_message_init(m);
	for (i = 0; i < num_xfers; ++i)
		spi_message_add_tail(&xfers[i], m);
}

struct spi_controller {
	struct device dev;
	s16 bus_num;
	u16 num_chipselect;
	u32 mode_bits;                  /* SPI_* flags the controller supports */
	u32 bits_per_word_mask;         /* SPI_BPW_MASK(n) of the supported widths; 0: 8 only */
	u32 min_speed_hz;
	u32 max_speed_hz;
	int *cs_gpios;                  /* per chip select: a GPIO, or -1 (set_cs) */
	int (*setup)(struct spi_device *spi);
	void (*cleanup)(struct spi_device *spi);
	void (*set_cs)(struct spi_device *spi, bool enable);
	int (*transfer_one)(struct spi_controller *ctlr, struct spi_device *spi, struct spi_transfer *xfer);
	struct mutex bus_lock_mutex;
	struct list_head lx_node;       /* ev3lx: on the list of controllers */
	bool lx_registered;
};
#define spi_master	spi_controller

static inline void *spi_controller_get_devdata(struct spi_controller *ctlr)
{
	return dev_get_drvdata(&ctlr->dev);
}

static inline void spi_controller_set_devdata(struct spi_controller *ctlr, void *data)
{
	dev_set_drvdata(&ctlr->dev, data);
}
#define spi_master_get_devdata	spi_controller_get_devdata
#define spi_master_set_devdata	spi_controller_set_devdata

/* A controller with size bytes of driver data behind it (spi_controller_get_devdata); NULL without memory. */
struct spi_controller *spi_alloc_master(struct device *host, unsigned int size);
/* Drops the reference spi_alloc_master gave, for a controller never registered
 * (a registered one is released by spi_unregister_controller). */
void spi_controller_put(struct spi_controller *ctlr);
/* Registers ctlr on its bus_num and creates the board's devices on it: 0, -EINVAL, -EBUSY. */
int spi_register_controller(struct spi_controller *ctlr);
#define spi_register_master	spi_register_controller
/* Unbinds and frees its devices, then forgets and frees ctlr. */
void spi_unregister_controller(struct spi_controller *ctlr);
#define spi_unregister_master	spi_unregister_controller

struct spi_board_info {
	char modalias[SPI_NAME_SIZE];
	const void *platform_data;
	void *controller_data;
	int irq;
	u32 max_speed_hz;
	u16 bus_num;
	u16 chip_select;
	u32 mode;
};

/* Declares n devices of the board (copied); each is created when its bus's controller registers. */
int spi_register_board_info(const struct spi_board_info *info, unsigned int n);
/* Creates and adds a device on ctlr now (bound to a matching driver): the device or NULL. */
struct spi_device *spi_new_device(struct spi_controller *ctlr, const struct spi_board_info *chip);
/* Unbinds and frees a device. */
void spi_unregister_device(struct spi_device *spi);

/* Checks the device's mode and word size against its controller and runs the controller's setup. */
int spi_setup(struct spi_device *spi);
/* Runs message on the bus, waiting for the end (see above): 0 or -errno, also in message->status. */
int spi_sync(struct spi_device *spi, struct spi_message *message);

static inline int spi_sync_transfer(struct spi_device *spi, struct spi_transfer *xfers, unsigned int num_xfers)
{
	struct spi_message msg;

	spi_message_init_with_transfers(&msg, xfers, num_xfers);
	return spi_sync(spi, &msg);
}

static inline int spi_write(struct spi_device *spi, const void *buf, size_t len)
{
	struct spi_transfer t = {
		.tx_buf = buf,
		.len = len,
	};

	return spi_sync_transfer(spi, &t, 1);
}

static inline int spi_read(struct spi_device *spi, void *buf, size_t len)
{
	struct spi_transfer t = {
		.rx_buf = buf,
		.len = len,
	};

	return spi_sync_transfer(spi, &t, 1);
}

#endif /* _LINUX_SPI_SPI_H */
