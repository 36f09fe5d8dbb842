// SPDX-License-Identifier: GPL-2.0
/*
 * d_power.c - LEGO EV3 power pins and battery type (/dev/lms_power).
 *
 * Interface-compatible with LEGO's lms2012 d_power (see lms_power.h): read() tells whether a
 * rechargeable pack is fitted, write() drives the board's test pin, ioctl() is accepted.
 *
 * At load the driver keeps the brick powered: P_EN (the main supply enable) and 5VPENON (the
 * 5 V rail for the sensors and motors) are driven high, the rechargeable-pack sense pin is an
 * input and the test pin is driven low.  Unloading leaves the supplies on: turning them off
 * is the board's power-off hook's job, not this driver's.
 *
 * GPIO pins (LEGO's EP2 and retail boards, lms2012's d_power pin table): P_EN GP6_5,
 * 5VPENON GP6_11, SW_RECHARGE GP8_8 (low = rechargeable pack), test pin GP6_2 (GP2_7 on the
 * FINAL and FINALB prototypes).  Every pin is a module parameter; the pins must already be
 * muxed to GPIO (board code / boot loader).
 */
#include <linux/module.h>
#include <linux/init.h>
#include <linux/kernel.h>
#include <linux/types.h>
#include <linux/errno.h>
#include <linux/fs.h>
#include <linux/miscdevice.h>
#include <linux/gpio.h>
#include <linux/uaccess.h>

#include "lms_power.h"

#define GP(bank, bit)		((bank) * 16 + (bit))	/* DaVinci GPIO number */

/* One pin parameter: DaVinci GPIO number 16 * bank + bit, GP<bank>_<bit> by default. */
#define POWER_GPIO_PARAM(name, bank, bit, what)					\
	static int name = GP(bank, bit);					\
	module_param(name, int, 0444);						\
	MODULE_PARM_DESC(name, "GPIO of " what " (default GP" #bank "_" #bit ")")

POWER_GPIO_PARAM(p_en_gpio, 6, 5, "P_EN, the main supply enable");
POWER_GPIO_PARAM(pen5v_gpio, 6, 11, "5VPENON, the 5 V rail enable");
POWER_GPIO_PARAM(recharge_gpio, 8, 8, "SW_RECHARGE, low with a rechargeable pack");
POWER_GPIO_PARAM(test_gpio, 6, 2, "the test pin");

/* The pins in request order, with the level each output starts at (-1: input). */
struct power_pin {
	const int *gpio;
	const char *label;
	int start;
};

static const struct power_pin power_pins[] = {
	{ &p_en_gpio,     "d_power P_EN",        1 },
	{ &pen5v_gpio,    "d_power 5VPENON",     1 },
	{ &recharge_gpio, "d_power SW_RECHARGE", -1 },
	{ &test_gpio,     "d_power test",        0 },
};

static unsigned int power_pins_requested;

/* "1\r" with a rechargeable pack (sense pin low), "0\r" without. */
static ssize_t power_read(struct file *file, char __user *buf, size_t count, loff_t *ppos)
{
	char text[LMS_POWER_READ_SIZE];

	text[0] = gpio_get_value(recharge_gpio) ? LMS_POWER_ALKALINE : LMS_POWER_RECHARGEABLE;
	text[1] = '\r';
	return simple_read_from_buffer(buf, count, ppos, text, sizeof(text));
}

/* One byte: non-zero drives the test pin high, zero low. */
static ssize_t power_write(struct file *file, const char __user *buf, size_t count, loff_t *ppos)
{
	u8 level;

	if (count != 1)
		return -EINVAL;
	if (get_user(level, buf))
		return -EFAULT;
	gpio_set_value(test_gpio, level != 0);
	return 1;
}

/* LEGO's user space issues ioctl 0 on this device; there is nothing to control. */
static long power_ioctl(struct file *file, unsigned int cmd, unsigned long arg)
{
	return 0;
}

static const struct file_operations power_fops = {
	.owner		= THIS_MODULE,
	.read		= power_read,
	.write		= power_write,
	.unlocked_ioctl	= power_ioctl,
	.llseek		= noop_llseek,
};

static struct miscdevice power_misc = {
	.minor	= MISC_DYNAMIC_MINOR,
	.name	= LMS_POWER_DEVICE_NAME,
	.fops	= &power_fops,
};

/* Frees the pins requested so far, newest first (outputs keep their level). */
static void power_pins_exit(void)
{
	while (power_pins_requested)
		gpio_free(*power_pins[--power_pins_requested].gpio);
}

static int power_pins_init(void)
{
	int ret;

	for (power_pins_requested = 0; power_pins_requested < ARRAY_SIZE(power_pins);
	     power_pins_requested++) {
		const struct power_pin *pin = &power_pins[power_pins_requested];

		ret = gpio_request(*pin->gpio, pin->label);
		if (ret) {
			pr_err("d_power: %s: GPIO %d: %d\n", pin->label, *pin->gpio, ret);
			goto fail;
		}
		if (pin->start < 0)
			ret = gpio_direction_input(*pin->gpio);
		else
			ret = gpio_direction_output(*pin->gpio, pin->start);
		if (ret) {
			pr_err("d_power: %s: GPIO %d direction: %d\n", pin->label, *pin->gpio, ret);
			gpio_free(*pin->gpio);
			goto fail;
		}
	}
	return 0;

fail:
	power_pins_exit();
	return ret;
}

static int __init d_power_init(void)
{
	int ret;

	power_pins_requested = 0;
	ret = power_pins_init();
	if (ret)
		return ret;
	ret = misc_register(&power_misc);
	if (ret)
		power_pins_exit();
	return ret;
}

static void __exit d_power_exit(void)
{
	misc_deregister(&power_misc);
	power_pins_exit();
}

module_init(d_power_init);
module_exit(d_power_exit);

MODULE_LICENSE("GPL");
MODULE_AUTHOR("ev3lx");
MODULE_DESCRIPTION("LEGO EV3 power pins and battery type (/dev/lms_power)");
