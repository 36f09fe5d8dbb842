/*
 * i2c-core.c — the I2C core (linux/i2c.h states the contract), after Linux
 * 6.1's drivers/i2c/i2c-core-base.c and i2c-core-smbus.c: adapter numbering
 * and the board's static clients, clients on the I2C bus matched by
 * of_match_table then id_table, i2c_transfer with its retries and its
 * context rule, and the SMBus transactions emulated as I2C messages.
 * Lists change in process context under one mutex, never held across a
 * probe.
 */
#include <linux/i2c.h>
#include <linux/err.h>
#include <linux/jiffies.h>
#include <linux/kernel.h>
#include <linux/mutex.h>
#include <linux/property.h>
#include <linux/slab.h>
#include <linux/string.h>
#include <linux_compat/context.h>
#include <linux_compat/irq.h>

#ifndef LX_NR_I2C_BOARD_INFO
#define LX_NR_I2C_BOARD_INFO	16
#endif

struct board_entry {
	int busnum;
	struct i2c_board_info info;
};

static DEFINE_MUTEX(core_lock);
static LIST_HEAD(adapters);
static LIST_HEAD(clients);
static LIST_HEAD(drivers);      /* registered drivers, for detection on new adapters */
static struct board_entry board_info[LX_NR_I2C_BOARD_INFO];
static unsigned int board_info_count;
static int first_dynamic_bus_num;

/* ---- the bus ---- */

const struct i2c_device_id *i2c_match_id(const struct i2c_device_id *id, const struct i2c_client *client)
{
	if (!id || !client)
		return NULL;
	for (; id->name[0]; id++)
		if (!strcmp(client->name, id->name))
			return id;
	return NULL;
}

struct i2c_client *i2c_verify_client(struct device *dev)
{
	return dev && dev->bus == &i2c_bus_type ? to_i2c_client(dev) : NULL;
}

const struct of_device_id *i2c_of_match_device(const struct of_device_id *matches, struct i2c_client *client)
{
	return client ? of_match_node(matches, client->dev.of_node) : NULL;
}

const struct i2c_device_id *i2c_client_get_device_id(const struct i2c_client *client)
{
	if (!client || !client->dev.driver)
		return NULL;
	return i2c_match_id(to_i2c_driver(client->dev.driver)->id_table, client);
}

const void *i2c_get_match_data(const struct i2c_client *client)
{
	const struct i2c_device_id *id;
	const void *data = device_get_match_data(&client->dev);

	if (data)
		return data;
	id = i2c_client_get_device_id(client);
	return id ? (const void *)id->driver_data : NULL;
}

/* Linux's i2c_device_match: the node's compatible, then the id_table. */
static int i2c_device_match(struct device *dev, struct device_driver *drv)
{
	struct i2c_client *client = i2c_verify_client(dev);

	if (!client)
		return 0;
	if (drv->of_match_table && of_match_node(drv->of_match_table, dev->of_node))
		return 1;
	return i2c_match_id(to_i2c_driver(drv)->id_table, client) != NULL;
}

static int i2c_device_probe(struct device *dev)
{
	struct i2c_client *client = to_i2c_client(dev);
	struct i2c_driver *driver = to_i2c_driver(dev->driver);

	client->irq = client->init_irq;
	/* Linux: a driver matched by neither table has no business probing */
	if (!driver->id_table && !i2c_of_match_device(dev->driver->of_match_table, client))
		return -ENODEV;
	if (!driver->probe)
		return -EINVAL;
	return driver->probe(client);
}

static void i2c_device_remove(struct device *dev)
{
	struct i2c_driver *driver = to_i2c_driver(dev->driver);

	if (driver->remove)
		driver->remove(to_i2c_client(dev));
}

static void i2c_device_shutdown(struct device *dev)
{
	struct i2c_driver *driver;

	if (!dev->driver)
		return;
	driver = to_i2c_driver(dev->driver);
	if (driver->shutdown)
		driver->shutdown(to_i2c_client(dev));
}

struct bus_type i2c_bus_type = {
	.name = "i2c",
	.match = i2c_device_match,
	.probe = i2c_device_probe,
	.remove = i2c_device_remove,
	.shutdown = i2c_device_shutdown,
};

static int detect(struct i2c_adapter *adap, struct i2c_driver *driver);
static void remove_detected(struct i2c_driver *driver, struct i2c_adapter *adap);

int i2c_register_driver(struct module *owner, struct i2c_driver *driver)
{
	struct i2c_adapter *adap;
	int ret;

	if (!driver)
		return -EINVAL;
	driver->driver.owner = owner;
	driver->driver.bus = &i2c_bus_type;
	INIT_LIST_HEAD(&driver->clients);
	ret = driver_register(&driver->driver);
	if (ret)
		return ret;
	mutex_lock(&core_lock);
	list_add_tail(&driver->lx_node, &drivers);
	mutex_unlock(&core_lock);
	/* Linux's __process_new_driver: detection on every adapter there is */
	list_for_each_entry(adap, &adapters, lx_node)
		if (adap->lx_added)
			detect(adap, driver);
	return 0;
}

void i2c_del_driver(struct i2c_driver *driver)
{
	if (!driver)
		return;
	remove_detected(driver, NULL);
	mutex_lock(&core_lock);
	list_del(&driver->lx_node);
	mutex_unlock(&core_lock);
	driver_unregister(&driver->driver);
}

/* ---- clients ---- */

static void i2c_client_release(struct device *dev)
{
	kfree(to_i2c_client(dev));
}

/* Linux's i2c_check_addr_validity: 7-bit 0x01..0x7f, 10-bit up to 0x3ff. */
static int check_addr_validity(unsigned int addr, unsigned short flags)
{
	if (flags & I2C_CLIENT_TEN)
		return addr > 0x3ff ? -EINVAL : 0;
	return (addr == 0x00 || addr > 0x7f) ? -EINVAL : 0;
}

/* Whether a client on adap already has addr (core_lock held). */
static bool addr_busy(struct i2c_adapter *adap, unsigned short addr)
{
	struct i2c_client *c;

	list_for_each_entry(c, &clients, lx_node)
		if (c->adapter == adap && c->addr == addr)
			return true;
	return false;
}

struct i2c_client *i2c_new_client_device(struct i2c_adapter *adap, const struct i2c_board_info *info)
{
	struct i2c_client *client;
	int ret;

	might_sleep();
	if (!adap || !info)
		return ERR_PTR(-EINVAL);
	ret = check_addr_validity(info->addr, info->flags);
	if (ret) {
		dev_err(&adap->dev, "Invalid %d-bit I2C address 0x%02hx\n",
			info->flags & I2C_CLIENT_TEN ? 10 : 7, info->addr);
		return ERR_PTR(ret);
	}
	client = kzalloc(sizeof(*client), GFP_KERNEL);
	if (!client)
		return ERR_PTR(-ENOMEM);
	client->adapter = adap;
	client->flags = info->flags;
	client->addr = info->addr;
	client->init_irq = info->irq;
	strscpy(client->name, info->type, sizeof(client->name));
	device_initialize(&client->dev);
	client->dev.parent = &adap->dev;
	client->dev.bus = &i2c_bus_type;
	client->dev.platform_data = info->platform_data;
	client->dev.of_node = info->of_node;
	client->dev.release = i2c_client_release;
	if (info->dev_name)
		dev_set_name(&client->dev, "i2c-%s", info->dev_name);
	else
		dev_set_name(&client->dev, "%d-%04x", adap->nr,
			     client->addr | ((client->flags & I2C_CLIENT_TEN) ? 0xa000 : 0));

	mutex_lock(&core_lock);
	if (addr_busy(adap, client->addr)) {
		mutex_unlock(&core_lock);
		dev_err(&adap->dev, "Failed to register i2c client %s at 0x%02x (%d)\n",
			client->name, client->addr, -EBUSY);
		put_device(&client->dev);
		return ERR_PTR(-EBUSY);
	}
	list_add_tail(&client->lx_node, &clients);
	mutex_unlock(&core_lock);

	ret = device_add(&client->dev);
	if (ret) {
		mutex_lock(&core_lock);
		list_del(&client->lx_node);
		mutex_unlock(&core_lock);
		put_device(&client->dev);
		return ERR_PTR(ret);
	}
	dev_dbg(&adap->dev, "client [%s] registered with bus id %s\n", client->name, dev_name(&client->dev));
	return client;
}

void i2c_unregister_device(struct i2c_client *client)
{
	if (IS_ERR_OR_NULL(client))
		return;
	mutex_lock(&core_lock);
	list_del(&client->lx_node);
	mutex_unlock(&core_lock);
	device_unregister(&client->dev);
}

struct i2c_client *i2c_new_dummy_device(struct i2c_adapter *adap, u16 address)
{
	struct i2c_board_info info = { I2C_BOARD_INFO("dummy", address) };

	return i2c_new_client_device(adap, &info);
}

static void devm_i2c_release_dummy(void *client)
{
	i2c_unregister_device(client);
}

struct i2c_client *devm_i2c_new_dummy_device(struct device *dev, struct i2c_adapter *adap, u16 address)
{
	struct i2c_client *client = i2c_new_dummy_device(adap, address);
	int ret;

	if (IS_ERR(client))
		return client;
	ret = devm_add_action_or_reset(dev, devm_i2c_release_dummy, client);
	return ret ? ERR_PTR(ret) : client;
}

int i2c_register_board_info(int busnum, struct i2c_board_info const *info, unsigned int n)
{
	unsigned int i;

	mutex_lock(&core_lock);
	if (board_info_count + n > LX_NR_I2C_BOARD_INFO) {
		mutex_unlock(&core_lock);
		pr_err("i2c-core: %u board infos for bus %d: table full (LX_NR_I2C_BOARD_INFO %d)\n",
		       n, busnum, LX_NR_I2C_BOARD_INFO);
		return -ENOMEM;
	}
	if (busnum >= first_dynamic_bus_num)
		first_dynamic_bus_num = busnum + 1;
	for (i = 0; i < n; i++) {
		board_info[board_info_count].busnum = busnum;
		board_info[board_info_count++].info = info[i];
	}
	mutex_unlock(&core_lock);
	return 0;
}

/* ---- adapters ---- */

static void i2c_adapter_release(struct device *dev)
{
}

/* The adapter numbered nr (core_lock held), or NULL. */
static struct i2c_adapter *find_adapter(int nr)
{
	struct i2c_adapter *a;

	list_for_each_entry(a, &adapters, lx_node)
		if (a->nr == nr)
			return a;
	return NULL;
}

/* Registers adap, numbered already and on the list; then the board's clients of its bus. */
static int register_adapter(struct i2c_adapter *adap)
{
	struct i2c_driver *driver;
	unsigned int i;
	int ret;

	mutex_init(&adap->bus_lock);
	if (adap->timeout == 0)
		adap->timeout = HZ;
	device_initialize(&adap->dev);
	adap->dev.release = i2c_adapter_release;
	dev_set_name(&adap->dev, "i2c-%d", adap->nr);
	ret = device_add(&adap->dev);
	if (ret) {
		mutex_lock(&core_lock);
		list_del(&adap->lx_node);
		mutex_unlock(&core_lock);
		put_device(&adap->dev);
		return ret;
	}
	adap->lx_added = true;
	dev_dbg(&adap->dev, "adapter [%s] registered\n", adap->name);
	for (i = 0; i < board_info_count; i++)
		if (board_info[i].busnum == adap->nr &&
		    IS_ERR(i2c_new_client_device(adap, &board_info[i].info)))
			dev_err(&adap->dev, "Can't create device at 0x%02x\n", board_info[i].info.addr);
	/* Linux's i2c_do_add_adapter: every driver's detection on the new bus */
	list_for_each_entry(driver, &drivers, lx_node)
		detect(adap, driver);
	return 0;
}

/* ---- detection (Linux 6.1's i2c_detect, i2c_detect_address, i2c_default_probe) ---- */

/* Whether a device answers at addr: a receive byte where a quick write could
 * corrupt EEPROMs or write-only chips (0x30..0x37, 0x50..0x5f), else a quick
 * write, else a receive byte. */
static bool default_probe(struct i2c_adapter *adap, unsigned short addr)
{
	union i2c_smbus_data dummy;
	int err;

	if (((addr & ~0x0fU) == 0x50 || (addr & ~0x07U) == 0x30) &&
	    i2c_check_functionality(adap, I2C_FUNC_SMBUS_READ_BYTE))
		err = i2c_smbus_xfer(adap, addr, 0, I2C_SMBUS_READ, 0, I2C_SMBUS_BYTE, &dummy);
	else if (i2c_check_functionality(adap, I2C_FUNC_SMBUS_QUICK))
		err = i2c_smbus_xfer(adap, addr, 0, I2C_SMBUS_WRITE, 0, I2C_SMBUS_QUICK, NULL);
	else if (i2c_check_functionality(adap, I2C_FUNC_SMBUS_READ_BYTE))
		err = i2c_smbus_xfer(adap, addr, 0, I2C_SMBUS_READ, 0, I2C_SMBUS_BYTE, &dummy);
	else {
		dev_warn(&adap->dev, "No suitable probing method supported for address 0x%02X\n", addr);
		err = -EOPNOTSUPP;
	}
	return err >= 0;
}

/* Offers temp's address to driver's detect and creates the client it names:
 * 0, or detect's error other than -ENODEV (which ends the adapter's scan). */
static int detect_address(struct i2c_client *temp, struct i2c_driver *driver)
{
	struct i2c_adapter *adap = temp->adapter;
	unsigned short addr = temp->addr;
	struct i2c_board_info info;
	struct i2c_client *client;
	bool busy;
	int err;

	if (addr < 0x08 || addr > 0x77) {
		dev_warn(&adap->dev, "Invalid probe address 0x%02x\n", addr);
		return 0;
	}
	mutex_lock(&core_lock);
	busy = addr_busy(adap, addr);
	mutex_unlock(&core_lock);
	if (busy || !default_probe(adap, addr))
		return 0;
	memset(&info, 0, sizeof(info));
	info.addr = addr;
	err = driver->detect(temp, &info);
	if (err)
		return err == -ENODEV ? 0 : err;
	if (info.type[0] == '\0') {
		dev_err(&adap->dev, "%s detection function provided no name for 0x%x\n", driver->driver.name,
			addr);
		return 0;
	}
	dev_dbg(&adap->dev, "Creating %s at 0x%02x\n", info.type, info.addr);
	client = i2c_new_client_device(adap, &info);
	if (IS_ERR(client)) {
		dev_err(&adap->dev, "Failed creating %s at 0x%02x\n", info.type, info.addr);
		return 0;
	}
	mutex_lock(&core_lock);
	list_add_tail(&client->detected, &driver->clients);
	mutex_unlock(&core_lock);
	return 0;
}

/* Runs driver's detection on adap where their classes meet: 0 or detect's error. */
static int detect(struct i2c_adapter *adap, struct i2c_driver *driver)
{
	const unsigned short *address_list = driver->address_list;
	struct i2c_client *temp;
	int err = 0;

	if (!driver->detect || !address_list)
		return 0;
	if (adap->class == I2C_CLASS_DEPRECATED) {
		dev_dbg(&adap->dev, "This adapter dropped support for I2C classes\n");
		return 0;
	}
	if (!(adap->class & driver->class))
		return 0;
	temp = kzalloc(sizeof(*temp), GFP_KERNEL);
	if (!temp)
		return -ENOMEM;
	temp->adapter = adap;
	for (; *address_list != I2C_CLIENT_END && !err; address_list++) {
		temp->addr = *address_list;
		err = detect_address(temp, driver);
	}
	kfree(temp);
	return err;
}

/* Removes the clients driver's detection created (on adap, or on any adapter when NULL). */
static void remove_detected(struct i2c_driver *driver, struct i2c_adapter *adap)
{
	struct i2c_client *client, *next;
	LIST_HEAD(victims);

	mutex_lock(&core_lock);
	list_for_each_entry_safe(client, next, &driver->clients, detected)
		if (!adap || client->adapter == adap)
			list_move_tail(&client->detected, &victims);
	mutex_unlock(&core_lock);
	list_for_each_entry_safe(client, next, &victims, detected) {
		list_del(&client->detected);
		dev_dbg(&client->adapter->dev, "Removing %s at 0x%x\n", client->name, client->addr);
		i2c_unregister_device(client);
	}
}

/* Linux's i2c_register_adapter checks: a name and an algorithm. */
static int adapter_valid(struct i2c_adapter *adap)
{
	if (!adap)
		return -EINVAL;
	if (!adap->name[0]) {
		pr_err("i2c-core: i2c adapter has no name\n");
		return -EINVAL;
	}
	if (!adap->algo) {
		pr_err("i2c-core: adapter '%s': no algo supplied!\n", adap->name);
		return -EINVAL;
	}
	if (adap->lx_added) {
		pr_err("i2c-core: adapter '%s' is already registered\n", adap->name);
		return -EBUSY;
	}
	return 0;
}

int i2c_add_adapter(struct i2c_adapter *adap)
{
	int nr, ret;

	might_sleep();
	ret = adapter_valid(adap);
	if (ret)
		return ret;
	mutex_lock(&core_lock);
	for (nr = first_dynamic_bus_num; find_adapter(nr); nr++)
		;
	adap->nr = nr;
	list_add_tail(&adap->lx_node, &adapters);
	mutex_unlock(&core_lock);
	return register_adapter(adap);
}

int i2c_add_numbered_adapter(struct i2c_adapter *adap)
{
	int ret;

	if (adap && adap->nr == -1)
		return i2c_add_adapter(adap);
	might_sleep();
	ret = adapter_valid(adap);
	if (ret)
		return ret;
	if (adap->nr < 0)
		return -EINVAL;
	mutex_lock(&core_lock);
	if (find_adapter(adap->nr)) {
		mutex_unlock(&core_lock);
		pr_err("i2c-core: adapter '%s': bus number %d is taken\n", adap->name, adap->nr);
		return -EBUSY;
	}
	list_add_tail(&adap->lx_node, &adapters);
	mutex_unlock(&core_lock);
	return register_adapter(adap);
}

void i2c_del_adapter(struct i2c_adapter *adap)
{
	struct i2c_driver *driver;
	struct i2c_client *c;

	might_sleep();
	if (!adap || !adap->lx_added) {
		pr_err("i2c-core: attempting to delete unregistered adapter [%s]\n", adap ? adap->name : "");
		return;
	}
	/* Linux's i2c_do_del_adapter: the clients detection created here go first */
	list_for_each_entry(driver, &drivers, lx_node)
		remove_detected(driver, adap);
	for (;;) {
		struct i2c_client *victim = NULL;

		mutex_lock(&core_lock);
		list_for_each_entry_reverse(c, &clients, lx_node)
			if (c->adapter == adap) {
				victim = c;
				break;
			}
		mutex_unlock(&core_lock);
		if (!victim)
			break;
		i2c_unregister_device(victim);
	}
	mutex_lock(&core_lock);
	list_del(&adap->lx_node);
	mutex_unlock(&core_lock);
	adap->lx_added = false;
	device_unregister(&adap->dev);
	/* Linux: the device may be added again, as if never used */
	memset(&adap->dev, 0, sizeof(adap->dev));
}

static void devm_i2c_del_adapter(void *adap)
{
	i2c_del_adapter(adap);
}

int devm_i2c_add_adapter(struct device *dev, struct i2c_adapter *adap)
{
	int ret = i2c_add_adapter(adap);

	return ret ? ret : devm_add_action_or_reset(dev, devm_i2c_del_adapter, adap);
}

struct i2c_adapter *i2c_get_adapter(int nr)
{
	struct i2c_adapter *adap;

	mutex_lock(&core_lock);
	adap = find_adapter(nr);
	if (adap)
		get_device(&adap->dev);
	mutex_unlock(&core_lock);
	return adap;
}

void i2c_put_adapter(struct i2c_adapter *adap)
{
	if (adap)
		put_device(&adap->dev);
}

u32 i2c_get_functionality(struct i2c_adapter *adap)
{
	return adap && adap->algo && adap->algo->functionality ? adap->algo->functionality(adap) : 0;
}

void i2c_lock_bus(struct i2c_adapter *adap, unsigned int flags)
{
	mutex_lock(&adap->bus_lock);
}

int i2c_trylock_bus(struct i2c_adapter *adap, unsigned int flags)
{
	return mutex_trylock(&adap->bus_lock);
}

void i2c_unlock_bus(struct i2c_adapter *adap, unsigned int flags)
{
	mutex_unlock(&adap->bus_lock);
}

/* ---- transfers ---- */

/* Runs xfer until it stops reporting a lost arbitration, adap->retries
 * resends at most, within adap->timeout (Linux's __i2c_transfer loop). */
static int xfer_with_retries(struct i2c_adapter *adap, struct i2c_msg *msgs, int num,
			     int (*xfer)(struct i2c_adapter *, struct i2c_msg *, int))
{
	unsigned long start = jiffies;
	int ret = -EAGAIN, attempt;

	for (attempt = 0; attempt <= adap->retries; attempt++) {
		ret = xfer(adap, msgs, num);
		if (ret != -EAGAIN || time_after(jiffies, start + (unsigned long)adap->timeout))
			break;
	}
	return ret;
}

int __i2c_transfer(struct i2c_adapter *adap, struct i2c_msg *msgs, int num)
{
	if (!adap || !adap->algo || !adap->algo->master_xfer) {
		if (adap)
			dev_dbg(&adap->dev, "I2C level transfers not supported\n");
		return -EOPNOTSUPP;
	}
	if (WARN_ON(!msgs || num < 1))
		return -EINVAL;
	return xfer_with_retries(adap, msgs, num, adap->algo->master_xfer);
}

/* A transfer where the caller may not sleep (already reported): the
 * algorithm's atomic form on a free bus, else -EAGAIN. */
static int atomic_transfer(struct i2c_adapter *adap, struct i2c_msg *msgs, int num)
{
	if (!adap->algo || !adap->algo->master_xfer_atomic) {
		dev_err(&adap->dev, "No atomic I2C transfer handler for '%s'\n", dev_name(&adap->dev));
		return -EAGAIN;
	}
	if (mutex_is_locked(&adap->bus_lock))
		return -EAGAIN;
	if (WARN_ON(!msgs || num < 1))
		return -EINVAL;
	/* one CPU and no preemption here: nothing else can take the bus meanwhile */
	return xfer_with_retries(adap, msgs, num, adap->algo->master_xfer_atomic);
}

int i2c_transfer(struct i2c_adapter *adap, struct i2c_msg *msgs, int num)
{
	int ret;

	if (!adap)
		return -EINVAL;
	if (!lx_might_sleep_check("i2c_transfer()", __FILE__, __LINE__))
		return atomic_transfer(adap, msgs, num);
	i2c_lock_bus(adap, I2C_LOCK_SEGMENT);
	ret = __i2c_transfer(adap, msgs, num);
	i2c_unlock_bus(adap, I2C_LOCK_SEGMENT);
	return ret;
}

int i2c_transfer_buffer_flags(const struct i2c_client *client, char *buf, int count, u16 flags)
{
	struct i2c_msg msg = {
		.addr = client->addr,
		.flags = (u16)(flags | (client->flags & I2C_M_TEN)),
		.len = (u16)count,
		.buf = (u8 *)buf,
	};
	int ret = i2c_transfer(client->adapter, &msg, 1);

	return ret == 1 ? count : ret;
}

/* ---- SMBus ---- */

/* Linux's i2c_smbus_xfer_emulated without PEC: the transaction as one or
 * two I2C messages (a write of the command, then the read). */
static s32 smbus_xfer_emulated(struct i2c_adapter *adap, u16 addr, unsigned short flags, char read_write,
			       u8 command, int size, union i2c_smbus_data *data)
{
	u8 buf0[I2C_SMBUS_BLOCK_MAX + 3];
	u8 buf1[I2C_SMBUS_BLOCK_MAX + 2];
	int nmsgs = read_write == I2C_SMBUS_READ ? 2 : 1;
	struct i2c_msg msg[2] = {
		{ .addr = addr, .flags = flags, .len = 1, .buf = buf0 },
		{ .addr = addr, .flags = flags | I2C_M_RD, .len = 0, .buf = buf1 },
	};
	int ret;

	buf0[0] = command;
	switch (size) {
	case I2C_SMBUS_QUICK:
		msg[0].len = 0;
		msg[0].flags = flags | (read_write == I2C_SMBUS_READ ? I2C_M_RD : 0);
		nmsgs = 1;
		break;
	case I2C_SMBUS_BYTE:
		if (read_write == I2C_SMBUS_READ) {
			msg[0].flags = I2C_M_RD | flags;
			nmsgs = 1;
		}
		break;
	case I2C_SMBUS_BYTE_DATA:
		if (read_write == I2C_SMBUS_READ) {
			msg[1].len = 1;
		} else {
			msg[0].len = 2;
			buf0[1] = data->byte;
		}
		break;
	case I2C_SMBUS_WORD_DATA:
		if (read_write == I2C_SMBUS_READ) {
			msg[1].len = 2;
		} else {
			msg[0].len = 3;
			buf0[1] = data->word & 0xff;
			buf0[2] = data->word >> 8;
		}
		break;
	case I2C_SMBUS_PROC_CALL:
		nmsgs = 2;
		read_write = I2C_SMBUS_READ;
		msg[0].len = 3;
		msg[1].len = 2;
		buf0[1] = data->word & 0xff;
		buf0[2] = data->word >> 8;
		break;
	case I2C_SMBUS_BLOCK_DATA:
		if (read_write == I2C_SMBUS_READ) {
			msg[1].flags |= I2C_M_RECV_LEN;
			msg[1].len = 1;   /* the algorithm adds the length byte's count */
		} else {
			if (data->block[0] > I2C_SMBUS_BLOCK_MAX) {
				dev_err(&adap->dev, "Invalid block write size %d\n", data->block[0]);
				return -EINVAL;
			}
			msg[0].len = (u16)(data->block[0] + 2);
			memcpy(buf0 + 1, data->block, (size_t)data->block[0] + 1);
		}
		break;
	case I2C_SMBUS_I2C_BLOCK_DATA:
		if (data->block[0] > I2C_SMBUS_BLOCK_MAX) {
			dev_err(&adap->dev, "Invalid block %s size %d\n",
				read_write == I2C_SMBUS_READ ? "read" : "write", data->block[0]);
			return -EINVAL;
		}
		if (read_write == I2C_SMBUS_READ) {
			msg[1].len = data->block[0];
		} else {
			msg[0].len = (u16)(data->block[0] + 1);
			memcpy(buf0 + 1, data->block + 1, data->block[0]);
		}
		break;
	default:
		dev_err(&adap->dev, "Unsupported transaction %d\n", size);
		return -EOPNOTSUPP;
	}

	ret = __i2c_transfer(adap, msg, nmsgs);
	if (ret < 0)
		return ret;
	if (ret != nmsgs)
		return -EIO;
	if (read_write == I2C_SMBUS_WRITE)
		return 0;
	switch (size) {
	case I2C_SMBUS_BYTE:
		data->byte = buf0[0];
		break;
	case I2C_SMBUS_BYTE_DATA:
		data->byte = buf1[0];
		break;
	case I2C_SMBUS_WORD_DATA:
	case I2C_SMBUS_PROC_CALL:
		data->word = (u16)(buf1[0] | (buf1[1] << 8));
		break;
	case I2C_SMBUS_I2C_BLOCK_DATA:
		memcpy(data->block + 1, buf1, data->block[0]);
		break;
	case I2C_SMBUS_BLOCK_DATA:
		if (buf1[0] > I2C_SMBUS_BLOCK_MAX) {
			dev_err(&adap->dev, "Invalid block size returned: %d\n", buf1[0]);
			return -EPROTO;
		}
		memcpy(data->block, buf1, (size_t)buf1[0] + 1);
		break;
	default:
		break;
	}
	return 0;
}

/* The adapter's own SMBus transfer with retries, as xfer_with_retries. */
static s32 smbus_native(struct i2c_adapter *adap, u16 addr, unsigned short flags, char read_write,
			u8 command, int protocol, union i2c_smbus_data *data)
{
	unsigned long start = jiffies;
	s32 ret = -EAGAIN;
	int attempt;

	for (attempt = 0; attempt <= adap->retries; attempt++) {
		ret = adap->algo->smbus_xfer(adap, addr, flags, read_write, command, protocol, data);
		if (ret != -EAGAIN || time_after(jiffies, start + (unsigned long)adap->timeout))
			break;
	}
	return ret;
}

s32 __i2c_smbus_xfer(struct i2c_adapter *adap, u16 addr, unsigned short flags, char read_write,
		     u8 command, int protocol, union i2c_smbus_data *data)
{
	if (!adap || !adap->algo)
		return -EOPNOTSUPP;
	flags &= I2C_M_TEN | I2C_CLIENT_PEC | I2C_CLIENT_SCCB;
	if (adap->algo->smbus_xfer) {
		s32 ret = smbus_native(adap, addr, flags, read_write, command, protocol, data);

		/* Linux: fall back to emulation when the adapter refuses the size */
		if (ret != -EOPNOTSUPP || !adap->algo->master_xfer)
			return ret;
	}
	if (!adap->algo->master_xfer)
		return -EOPNOTSUPP;
	return smbus_xfer_emulated(adap, addr, flags & I2C_M_TEN, read_write, command, protocol, data);
}

s32 i2c_smbus_xfer(struct i2c_adapter *adap, u16 addr, unsigned short flags, char read_write,
		   u8 command, int protocol, union i2c_smbus_data *data)
{
	s32 ret;

	if (!adap)
		return -EINVAL;
	if (!lx_might_sleep_check("i2c_smbus_xfer()", __FILE__, __LINE__))
		return -EAGAIN;
	i2c_lock_bus(adap, I2C_LOCK_SEGMENT);
	ret = __i2c_smbus_xfer(adap, addr, flags, read_write, command, protocol, data);
	i2c_unlock_bus(adap, I2C_LOCK_SEGMENT);
	return ret;
}

/* One SMBus transaction for client. */
static s32 client_xfer(const struct i2c_client *client, char read_write, u8 command, int protocol,
		       union i2c_smbus_data *data)
{
	return i2c_smbus_xfer(client->adapter, client->addr, client->flags, read_write, command, protocol, data);
}

s32 i2c_smbus_read_byte(const struct i2c_client *client)
{
	union i2c_smbus_data data;
	s32 ret = client_xfer(client, I2C_SMBUS_READ, 0, I2C_SMBUS_BYTE, &data);

	return ret < 0 ? ret : data.byte;
}

s32 i2c_smbus_write_byte(const struct i2c_client *client, u8 value)
{
	return client_xfer(client, I2C_SMBUS_WRITE, value, I2C_SMBUS_BYTE, NULL);
}

s32 i2c_smbus_read_byte_data(const struct i2c_client *client, u8 command)
{
	union i2c_smbus_data data;
	s32 ret = client_xfer(client, I2C_SMBUS_READ, command, I2C_SMBUS_BYTE_DATA, &data);

	return ret < 0 ? ret : data.byte;
}

s32 i2c_smbus_write_byte_data(const struct i2c_client *client, u8 command, u8 value)
{
	union i2c_smbus_data data = { .byte = value };

	return client_xfer(client, I2C_SMBUS_WRITE, command, I2C_SMBUS_BYTE_DATA, &data);
}

s32 i2c_smbus_read_word_data(const struct i2c_client *client, u8 command)
{
	union i2c_smbus_data data;
	s32 ret = client_xfer(client, I2C_SMBUS_READ, command, I2C_SMBUS_WORD_DATA, &data);

	return ret < 0 ? ret : data.word;
}

s32 i2c_smbus_write_word_data(const struct i2c_client *client, u8 command, u16 value)
{
	union i2c_smbus_data data = { .word = value };

	return client_xfer(client, I2C_SMBUS_WRITE, command, I2C_SMBUS_WORD_DATA, &data);
}

s32 i2c_smbus_process_call(const struct i2c_client *client, u8 command, u16 value)
{
	union i2c_smbus_data data = { .word = value };
	s32 ret = client_xfer(client, I2C_SMBUS_WRITE, command, I2C_SMBUS_PROC_CALL, &data);

	return ret < 0 ? ret : data.word;
}

s32 i2c_smbus_read_block_data(const struct i2c_client *client, u8 command, u8 *values)
{
	union i2c_smbus_data data;
	s32 ret = client_xfer(client, I2C_SMBUS_READ, command, I2C_SMBUS_BLOCK_DATA, &data);

	if (ret)
		return ret;
	memcpy(values, &data.block[1], data.block[0]);
	return data.block[0];
}

s32 i2c_smbus_write_block_data(const struct i2c_client *client, u8 command, u8 length, const u8 *values)
{
	union i2c_smbus_data data;

	if (length > I2C_SMBUS_BLOCK_MAX)
		length = I2C_SMBUS_BLOCK_MAX;
	data.block[0] = length;
	memcpy(&data.block[1], values, length);
	return client_xfer(client, I2C_SMBUS_WRITE, command, I2C_SMBUS_BLOCK_DATA, &data);
}

s32 i2c_smbus_read_i2c_block_data(const struct i2c_client *client, u8 command, u8 length, u8 *values)
{
	union i2c_smbus_data data;
	s32 ret;

	if (length > I2C_SMBUS_BLOCK_MAX)
		length = I2C_SMBUS_BLOCK_MAX;
	data.block[0] = length;
	ret = client_xfer(client, I2C_SMBUS_READ, command, I2C_SMBUS_I2C_BLOCK_DATA, &data);
	if (ret < 0)
		return ret;
	memcpy(values, &data.block[1], data.block[0]);
	return data.block[0];
}

s32 i2c_smbus_write_i2c_block_data(const struct i2c_client *client, u8 command, u8 length, const u8 *values)
{
	union i2c_smbus_data data;

	if (length > I2C_SMBUS_BLOCK_MAX)
		length = I2C_SMBUS_BLOCK_MAX;
	data.block[0] = length;
	memcpy(data.block + 1, values, length);
	return client_xfer(client, I2C_SMBUS_WRITE, command, I2C_SMBUS_I2C_BLOCK_DATA, &data);
}

s32 i2c_smbus_read_i2c_block_data_or_emulated(const struct i2c_client *client, u8 command, u8 length,
					      u8 *values)
{
	u8 i = 0;
	s32 status;

	if (length > I2C_SMBUS_BLOCK_MAX)
		length = I2C_SMBUS_BLOCK_MAX;
	if (i2c_check_functionality(client->adapter, I2C_FUNC_SMBUS_READ_I2C_BLOCK))
		return i2c_smbus_read_i2c_block_data(client, command, length, values);
	if (!i2c_check_functionality(client->adapter, I2C_FUNC_SMBUS_READ_BYTE_DATA))
		return -EOPNOTSUPP;
	if (i2c_check_functionality(client->adapter, I2C_FUNC_SMBUS_READ_WORD_DATA)) {
		while ((i + 2) <= length) {
			status = i2c_smbus_read_word_data(client, (u8)(command + i));
			if (status < 0)
				return status;
			values[i] = status & 0xff;
			values[i + 1] = (u8)(status >> 8);
			i += 2;
		}
	}
	while (i < length) {
		status = i2c_smbus_read_byte_data(client, (u8)(command + i));
		if (status < 0)
			return status;
		values[i] = (u8)status;
		i++;
	}
	return i;
}

void lx_i2c_boot(void)
{
	mutex_init(&core_lock);
	INIT_LIST_HEAD(&adapters);
	INIT_LIST_HEAD(&clients);
	INIT_LIST_HEAD(&drivers);
	memset(board_info, 0, sizeof(board_info));
	board_info_count = 0;
	first_dynamic_bus_num = 0;
	lx_bus_register_boot(&i2c_bus_type);
}
