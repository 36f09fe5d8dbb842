/*
 * spi.c — the SPI bus core (linux/spi/spi.h states the contract): the
 * controllers, the board's device declarations, protocol drivers and their
 * matching, and spi_sync running a message through the controller's
 * transfer_one with the chip select around it.  The lists change in process
 * context under one mutex; a message holds its controller's bus lock.
 */
#include <linux/spi/spi.h>
#include <linux/delay.h>
#include <linux/gpio.h>
#include <linux/kernel.h>
#include <linux/mutex.h>
#include <linux/slab.h>
#include <linux/string.h>
#include <linux_compat/context.h>
#include <linux_compat/irq.h>

#ifndef LX_NR_SPI_BOARD_INFO
#define LX_NR_SPI_BOARD_INFO	8
#endif

static DEFINE_MUTEX(spi_lists_lock);
static LIST_HEAD(spi_controllers);
static LIST_HEAD(spi_devices);
static LIST_HEAD(spi_drivers);
static struct spi_board_info board_info[LX_NR_SPI_BOARD_INFO];
static unsigned int board_info_count;

/* The id_table entry of sdrv naming modalias, or NULL. */
static const struct spi_device_id *spi_match_id(const struct spi_device_id *id, const char *modalias)
{
	for (; id && id->name[0]; id++)
		if (!strcmp(id->name, modalias))
			return id;
	return NULL;
}

static bool spi_driver_matches(const struct spi_driver *sdrv, const struct spi_device *spi)
{
	if (sdrv->id_table)
		return spi_match_id(sdrv->id_table, spi->modalias) != NULL;
	return sdrv->driver.name && !strcmp(sdrv->driver.name, spi->modalias);
}

const struct spi_device_id *spi_get_device_id(const struct spi_device *sdev)
{
	const struct spi_driver *sdrv = to_spi_driver(sdev->dev.driver);

	return sdrv ? spi_match_id(sdrv->id_table, sdev->modalias) : NULL;
}

/* Binds spi to sdrv through its probe.  Lists locked. */
static void spi_bind(struct spi_device *spi, struct spi_driver *sdrv)
{
	int err;

	spi->dev.driver = &sdrv->driver;
	err = sdrv->probe ? sdrv->probe(spi) : 0;
	if (err) {
		pr_warn("spi %s: probe of %s failed with error %d\n", sdrv->driver.name, dev_name(&spi->dev), err);
		devres_release_all(&spi->dev);
		spi->dev.driver = NULL;
		dev_set_drvdata(&spi->dev, NULL);
	}
}

/* Unbinds spi from its driver through remove.  Lists locked. */
static void spi_unbind(struct spi_device *spi)
{
	struct spi_driver *sdrv = to_spi_driver(spi->dev.driver);

	if (!sdrv)
		return;
	if (sdrv->remove)
		sdrv->remove(spi);
	devres_release_all(&spi->dev);
	spi->dev.driver = NULL;
	dev_set_drvdata(&spi->dev, NULL);
}

int __spi_register_driver(struct module *owner, struct spi_driver *sdrv)
{
	struct spi_driver *d;
	struct spi_device *spi;

	might_sleep();
	if (!sdrv || !sdrv->driver.name)
		return -EINVAL;
	mutex_lock(&spi_lists_lock);
	list_for_each_entry(d, &spi_drivers, lx_node) {
		if (d == sdrv || !strcmp(d->driver.name, sdrv->driver.name)) {
			mutex_unlock(&spi_lists_lock);
			return -EBUSY;
		}
	}
	sdrv->driver.owner = owner;
	list_add_tail(&sdrv->lx_node, &spi_drivers);
	list_for_each_entry(spi, &spi_devices, lx_node)
		if (!spi->dev.driver && spi_driver_matches(sdrv, spi))
			spi_bind(spi, sdrv);
	mutex_unlock(&spi_lists_lock);
	return 0;
}

void spi_unregister_driver(struct spi_driver *sdrv)
{
	struct spi_device *spi;

	might_sleep();
	if (!sdrv)
		return;
	mutex_lock(&spi_lists_lock);
	list_for_each_entry(spi, &spi_devices, lx_node)
		if (spi->dev.driver == &sdrv->driver)
			spi_unbind(spi);
	list_del_init(&sdrv->lx_node);
	mutex_unlock(&spi_lists_lock);
}

struct spi_controller *spi_alloc_master(struct device *host, unsigned int size)
{
	struct spi_controller *ctlr;

	might_sleep();
	ctlr = kzalloc(sizeof(*ctlr) + ALIGN(size, sizeof(long)), GFP_KERNEL);
	if (!ctlr)
		return NULL;
	ctlr->dev.parent = host;
	ctlr->num_chipselect = 1;
	ctlr->bus_num = -1;
	mutex_init(&ctlr->bus_lock_mutex);
	INIT_LIST_HEAD(&ctlr->lx_node);
	spi_controller_set_devdata(ctlr, (void *)(ctlr + 1));
	return ctlr;
}

void spi_controller_put(struct spi_controller *ctlr)
{
	if (!ctlr)
		return;
	if (ctlr->lx_registered) {
		WARN(1, "spi%d: spi_controller_put on a registered controller (use spi_unregister_controller)\n",
		     ctlr->bus_num);
		return;
	}
	kfree(ctlr);
}

/* Adds a new device on ctlr and binds it.  Lists locked. */
static struct spi_device *spi_add_locked(struct spi_controller *ctlr, const struct spi_board_info *chip)
{
	struct spi_device *spi;
	struct spi_driver *sdrv;

	if (chip->chip_select >= ctlr->num_chipselect) {
		pr_err("spi%d: chip select %u beyond the controller's %u\n", ctlr->bus_num,
		       chip->chip_select, ctlr->num_chipselect);
		return NULL;
	}
	list_for_each_entry(spi, &spi_devices, lx_node) {
		if (spi->controller == ctlr && spi->chip_select == chip->chip_select) {
			pr_err("spi%d: chip select %u already in use\n", ctlr->bus_num, chip->chip_select);
			return NULL;
		}
	}
	spi = kzalloc(sizeof(*spi), GFP_KERNEL);
	if (!spi)
		return NULL;
	spi->controller = spi->master = ctlr;
	spi->dev.parent = &ctlr->dev;
	spi->dev.platform_data = (void *)chip->platform_data;
	spi->controller_data = chip->controller_data;
	spi->irq = chip->irq;
	spi->max_speed_hz = chip->max_speed_hz;
	spi->chip_select = (u8)chip->chip_select;
	spi->mode = chip->mode;
	spi->bits_per_word = 8;
	spi->cs_gpio = ctlr->cs_gpios ? ctlr->cs_gpios[chip->chip_select] : -1;
	strscpy(spi->modalias, chip->modalias, sizeof(spi->modalias));
	snprintf(spi->lx_name, sizeof(spi->lx_name), "spi%d.%u", ctlr->bus_num, chip->chip_select);
	spi->dev.init_name = spi->lx_name;
	if (spi_setup(spi)) {
		kfree(spi);
		return NULL;
	}
	list_add_tail(&spi->lx_node, &spi_devices);
	list_for_each_entry(sdrv, &spi_drivers, lx_node) {
		if (spi_driver_matches(sdrv, spi)) {
			spi_bind(spi, sdrv);
			break;
		}
	}
	return spi;
}

struct spi_device *spi_new_device(struct spi_controller *ctlr, const struct spi_board_info *chip)
{
	struct spi_device *spi;

	might_sleep();
	if (!ctlr || !chip || !ctlr->lx_registered)
		return NULL;
	mutex_lock(&spi_lists_lock);
	spi = spi_add_locked(ctlr, chip);
	mutex_unlock(&spi_lists_lock);
	return spi;
}

/* Unbinds, unlinks and frees spi.  Lists locked. */
static void spi_remove_locked(struct spi_device *spi)
{
	spi_unbind(spi);
	if (spi->controller->cleanup)
		spi->controller->cleanup(spi);
	list_del(&spi->lx_node);
	kfree(spi);
}

void spi_unregister_device(struct spi_device *spi)
{
	might_sleep();
	if (!spi)
		return;
	mutex_lock(&spi_lists_lock);
	spi_remove_locked(spi);
	mutex_unlock(&spi_lists_lock);
}

int spi_register_controller(struct spi_controller *ctlr)
{
	struct spi_controller *c;
	unsigned int i;

	might_sleep();
	if (!ctlr || ctlr->bus_num < 0 || !ctlr->transfer_one || ctlr->num_chipselect == 0)
		return -EINVAL;
	mutex_lock(&spi_lists_lock);
	list_for_each_entry(c, &spi_controllers, lx_node) {
		if (c->bus_num == ctlr->bus_num) {
			mutex_unlock(&spi_lists_lock);
			return -EBUSY;
		}
	}
	list_add_tail(&ctlr->lx_node, &spi_controllers);
	ctlr->lx_registered = true;
	for (i = 0; i < board_info_count; i++)
		if (board_info[i].bus_num == (u16)ctlr->bus_num)
			spi_add_locked(ctlr, &board_info[i]);
	mutex_unlock(&spi_lists_lock);
	return 0;
}

void spi_unregister_controller(struct spi_controller *ctlr)
{
	struct spi_device *spi, *next;

	might_sleep();
	if (!ctlr)
		return;
	mutex_lock(&spi_lists_lock);
	list_for_each_entry_safe(spi, next, &spi_devices, lx_node)
		if (spi->controller == ctlr)
			spi_remove_locked(spi);
	if (ctlr->lx_registered)
		list_del(&ctlr->lx_node);
	mutex_unlock(&spi_lists_lock);
	kfree(ctlr);
}

int spi_register_board_info(const struct spi_board_info *info, unsigned int n)
{
	struct spi_controller *ctlr;
	unsigned int i;

	might_sleep();
	if (!info && n)
		return -EINVAL;
	mutex_lock(&spi_lists_lock);
	if (n > LX_NR_SPI_BOARD_INFO - board_info_count) {
		mutex_unlock(&spi_lists_lock);
		return -ENOMEM;
	}
	for (i = 0; i < n; i++) {
		board_info[board_info_count++] = info[i];
		list_for_each_entry(ctlr, &spi_controllers, lx_node)
			if (ctlr->bus_num == (s16)info[i].bus_num)
				spi_add_locked(ctlr, &info[i]);
	}
	mutex_unlock(&spi_lists_lock);
	return 0;
}

int spi_setup(struct spi_device *spi)
{
	struct spi_controller *ctlr;
	u32 bpw_mask;

	if (!spi)
		return -EINVAL;
	ctlr = spi->controller;
	if (!spi->bits_per_word)
		spi->bits_per_word = 8;
	bpw_mask = ctlr->bits_per_word_mask ? ctlr->bits_per_word_mask : SPI_BPW_MASK(8);
	if (spi->bits_per_word > 32 || !(bpw_mask & SPI_BPW_MASK(spi->bits_per_word))) {
		dev_err(&spi->dev, "%u bits per word not supported by the controller\n", spi->bits_per_word);
		return -EINVAL;
	}
	if (spi->mode & ~(ctlr->mode_bits | SPI_CPOL | SPI_CPHA)) {
		dev_err(&spi->dev, "setup: unsupported mode bits %x\n", spi->mode & ~(ctlr->mode_bits | SPI_CPOL | SPI_CPHA));
		return -EINVAL;
	}
	if (!spi->max_speed_hz || (ctlr->max_speed_hz && spi->max_speed_hz > ctlr->max_speed_hz))
		spi->max_speed_hz = ctlr->max_speed_hz;
	if (spi->cs_gpio >= 0 && !(spi->mode & SPI_NO_CS))
		gpio_direction_output((unsigned int)spi->cs_gpio, !(spi->mode & SPI_CS_HIGH));
	return ctlr->setup ? ctlr->setup(spi) : 0;
}

/* Asserts (enable) or deasserts the device's chip select. */
static void spi_set_cs(struct spi_device *spi, bool enable)
{
	if (spi->mode & SPI_NO_CS)
		return;
	if (spi->cs_gpio >= 0)
		gpio_set_value((unsigned int)spi->cs_gpio, (spi->mode & SPI_CS_HIGH) ? enable : !enable);
	else if (spi->controller->set_cs)
		spi->controller->set_cs(spi, (spi->mode & SPI_CS_HIGH) ? enable : !enable);
}

/* Checks a message and fills in the defaults of its transfers: 0 or -EINVAL. */
static int spi_validate(struct spi_device *spi, struct spi_message *msg)
{
	struct spi_controller *ctlr = spi->controller;
	u32 bpw_mask = ctlr->bits_per_word_mask ? ctlr->bits_per_word_mask : SPI_BPW_MASK(8);
	struct spi_transfer *xfer;

	if (list_empty(&msg->transfers))
		return -EINVAL;
	msg->frame_length = 0;
	list_for_each_entry(xfer, &msg->transfers, transfer_list) {
		if (xfer->len && !xfer->tx_buf && !xfer->rx_buf)
			return -EINVAL;
		if (!xfer->bits_per_word)
			xfer->bits_per_word = spi->bits_per_word;
		if (xfer->bits_per_word > 32 || !(bpw_mask & SPI_BPW_MASK(xfer->bits_per_word)))
			return -EINVAL;
		if (!xfer->speed_hz || xfer->speed_hz > spi->max_speed_hz)
			xfer->speed_hz = spi->max_speed_hz;
		msg->frame_length += xfer->len;
	}
	return 0;
}

int spi_sync(struct spi_device *spi, struct spi_message *message)
{
	struct spi_controller *ctlr;
	struct spi_transfer *xfer;
	bool keep_cs = false;
	int status;

	lx_might_sleep("spi_sync()", __FILE__, __LINE__);
	if (!spi || !message)
		return -EINVAL;
	ctlr = spi->controller;
	message->spi = spi;
	message->actual_length = 0;
	status = spi_validate(spi, message);
	if (status)
		goto out;
	mutex_lock(&ctlr->bus_lock_mutex);
	spi_set_cs(spi, true);
	list_for_each_entry(xfer, &message->transfers, transfer_list) {
		if (xfer->len) {
			status = ctlr->transfer_one(ctlr, spi, xfer);
			if (status)
				break;
			message->actual_length += xfer->len;
		}
		if (xfer->delay_usecs)
			udelay(xfer->delay_usecs);
		if (xfer->cs_change) {
			if (list_is_last(&xfer->transfer_list, &message->transfers)) {
				keep_cs = true;
			} else {
				spi_set_cs(spi, false);
				udelay(10);
				spi_set_cs(spi, true);
			}
		}
	}
	if (status || !keep_cs)
		spi_set_cs(spi, false);
	mutex_unlock(&ctlr->bus_lock_mutex);
out:
	message->status = status;
	if (message->complete)
		message->complete(message->context);
	return status;
}

void lx_spi_boot(void)
{
	mutex_init(&spi_lists_lock);
	INIT_LIST_HEAD(&spi_controllers);
	INIT_LIST_HEAD(&spi_devices);
	INIT_LIST_HEAD(&spi_drivers);
	board_info_count = 0;
}
