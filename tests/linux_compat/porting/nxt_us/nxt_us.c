// SPDX-License-Identifier: GPL-2.0
/*
 * nxt_us.c - the LEGO NXT ultrasonic sensor (9846) on an I2C bus, written
 * as upstream wants an I2C client driver today: matched by compatible or
 * by I2C id, state device-managed, the sensor identified by its SMBus
 * registers before anything is registered, and a misc device per sensor.
 *
 * Registers (LEGO's NXT Hardware Developer Kit, the ultrasonic sensor's
 * I2C appendix): 0x00 version, 0x08 vendor "LEGO", 0x10 product "Sonar"
 * (8 bytes each, space padded); 0x41 the command (1 single shot,
 * 2 continuous); 0x42..0x49 the echoes of the last ping in cm.
 */
#include <linux/device.h>
#include <linux/fs.h>
#include <linux/i2c.h>
#include <linux/kernel.h>
#include <linux/miscdevice.h>
#include <linux/mod_devicetable.h>
#include <linux/module.h>
#include <linux/mutex.h>
#include <linux/string.h>
#include <linux/uaccess.h>
#include "nxt_us_uapi.h"

#define NXT_US_REG_VENDOR	0x08
#define NXT_US_REG_PRODUCT	0x10
#define NXT_US_REG_COMMAND	0x41
#define NXT_US_REG_ECHO0	0x42
#define NXT_US_ID_LEN		8

#define NXT_US_CMD_SINGLE_SHOT	0x01
#define NXT_US_CMD_CONTINUOUS	0x02

struct nxt_us {
	struct i2c_client *client;
	struct mutex lock;	/* one transaction sequence at a time */
	struct miscdevice misc;
	char name[16];
};

static struct nxt_us *file_to_us(struct file *file)
{
	struct miscdevice *misc = file->private_data;

	return container_of(misc, struct nxt_us, misc);
}

static ssize_t nxt_us_read(struct file *file, char __user *buf, size_t count, loff_t *ppos)
{
	struct nxt_us *us = file_to_us(file);
	char text[8];
	int cm, len;

	mutex_lock(&us->lock);
	cm = i2c_smbus_read_byte_data(us->client, NXT_US_REG_ECHO0);
	mutex_unlock(&us->lock);
	if (cm < 0)
		return cm;
	len = scnprintf(text, sizeof(text), "%d\n", cm);
	return simple_read_from_buffer(buf, count, ppos, text, len);
}

static long nxt_us_ioctl(struct file *file, unsigned int cmd, unsigned long arg)
{
	struct nxt_us *us = file_to_us(file);
	struct nxt_us_echoes echoes;
	int ret;

	switch (cmd) {
	case NXT_US_SINGLE_SHOT:
		mutex_lock(&us->lock);
		ret = i2c_smbus_write_byte_data(us->client, NXT_US_REG_COMMAND, NXT_US_CMD_SINGLE_SHOT);
		if (!ret)
			ret = i2c_smbus_read_i2c_block_data(us->client, NXT_US_REG_ECHO0,
							    sizeof(echoes.cm), echoes.cm);
		mutex_unlock(&us->lock);
		if (ret < 0)
			return ret;
		if (ret != sizeof(echoes.cm))
			return -EIO;
		return copy_to_user((void __user *)arg, &echoes, sizeof(echoes)) ? -EFAULT : 0;
	case NXT_US_CONTINUOUS:
		mutex_lock(&us->lock);
		ret = i2c_smbus_write_byte_data(us->client, NXT_US_REG_COMMAND, NXT_US_CMD_CONTINUOUS);
		mutex_unlock(&us->lock);
		return ret;
	default:
		return -ENOTTY;
	}
}

static const struct file_operations nxt_us_fops = {
	.owner = THIS_MODULE,
	.read = nxt_us_read,
	.unlocked_ioctl = nxt_us_ioctl,
	.llseek = no_llseek,
};

/* Reads an 8-byte identification string and compares its non-blank part. */
static int nxt_us_check_id(struct i2c_client *client, u8 reg, const char *expected)
{
	u8 id[NXT_US_ID_LEN + 1] = { };
	char *text;
	int ret;

	ret = i2c_smbus_read_i2c_block_data(client, reg, NXT_US_ID_LEN, id);
	if (ret < 0)
		return ret;
	if (ret != NXT_US_ID_LEN)
		return -EIO;
	text = strim((char *)id);
	if (strcmp(text, expected))
		return dev_err_probe(&client->dev, -ENODEV, "register 0x%02x is '%s', not '%s'\n",
				     reg, text, expected);
	return 0;
}

static void nxt_us_misc_deregister(void *misc)
{
	misc_deregister(misc);
}

static int nxt_us_probe(struct i2c_client *client)
{
	struct device *dev = &client->dev;
	struct nxt_us *us;
	int ret;

	if (!i2c_check_functionality(client->adapter, I2C_FUNC_SMBUS_BYTE_DATA |
				     I2C_FUNC_SMBUS_READ_I2C_BLOCK))
		return dev_err_probe(dev, -EOPNOTSUPP, "adapter lacks SMBus byte and block reads\n");

	us = devm_kzalloc(dev, sizeof(*us), GFP_KERNEL);
	if (!us)
		return -ENOMEM;
	us->client = client;
	mutex_init(&us->lock);

	ret = nxt_us_check_id(client, NXT_US_REG_VENDOR, "LEGO");
	if (ret)
		return dev_err_probe(dev, ret, "no NXT ultrasonic sensor\n");
	ret = nxt_us_check_id(client, NXT_US_REG_PRODUCT, "Sonar");
	if (ret)
		return dev_err_probe(dev, ret, "not an ultrasonic sensor\n");
	ret = i2c_smbus_write_byte_data(client, NXT_US_REG_COMMAND, NXT_US_CMD_CONTINUOUS);
	if (ret)
		return dev_err_probe(dev, ret, "cannot start continuous measurement\n");

	snprintf(us->name, sizeof(us->name), "nxt_us%d", i2c_adapter_id(client->adapter));
	us->misc.minor = MISC_DYNAMIC_MINOR;
	us->misc.name = us->name;
	us->misc.fops = &nxt_us_fops;
	us->misc.parent = dev;
	ret = misc_register(&us->misc);
	if (ret)
		return dev_err_probe(dev, ret, "cannot register /dev/%s\n", us->name);
	ret = devm_add_action_or_reset(dev, nxt_us_misc_deregister, &us->misc);
	if (ret)
		return ret;

	i2c_set_clientdata(client, us);
	dev_info(dev, "/dev/%s: NXT ultrasonic sensor at 0x%02x\n", us->name, client->addr);
	return 0;
}

static void nxt_us_remove(struct i2c_client *client)
{
	struct nxt_us *us = i2c_get_clientdata(client);

	/* leave the sensor quiet, as it is when plugged in afresh */
	if (i2c_smbus_write_byte_data(client, NXT_US_REG_COMMAND, 0))
		dev_warn(&client->dev, "%s: could not switch the sensor off\n", us->name);
}

static const struct of_device_id nxt_us_of_match[] = {
	{ .compatible = "lego,nxt-ultrasonic" },
	{ }
};
MODULE_DEVICE_TABLE(of, nxt_us_of_match);

static const struct i2c_device_id nxt_us_id[] = {
	{ "nxt-ultrasonic", 0 },
	{ }
};
MODULE_DEVICE_TABLE(i2c, nxt_us_id);

static struct i2c_driver nxt_us_driver = {
	.driver = {
		.name = "nxt-us",
		.of_match_table = nxt_us_of_match,
	},
	.probe_new = nxt_us_probe,
	.remove = nxt_us_remove,
	.id_table = nxt_us_id,
};
module_i2c_driver(nxt_us_driver);

MODULE_DESCRIPTION("LEGO NXT ultrasonic sensor");
MODULE_AUTHOR("ev3lx");
MODULE_LICENSE("GPL");
