// SPDX-License-Identifier: GPL-2.0
/*
 * gpio_events.c - timestamps the rising edges of a GPIO input, written as
 * upstream wants a driver today: a platform driver matched by compatible or
 * by name, its state and resources all device-managed, the lines from
 * gpiod ("event", and an optional "led" it toggles per edge), a threaded
 * IRQ (the hard handler stamps the edge into a typed kfifo, the thread does
 * the slow part with the line masked, IRQF_ONESHOT), and a misc device
 * whose read() blocks for whole event records.
 */
#include <linux/device.h>
#include <linux/fs.h>
#include <linux/gpio/consumer.h>
#include <linux/interrupt.h>
#include <linux/kfifo.h>
#include <linux/ktime.h>
#include <linux/miscdevice.h>
#include <linux/mod_devicetable.h>
#include <linux/module.h>
#include <linux/platform_device.h>
#include <linux/property.h>
#include <linux/spinlock.h>
#include <linux/uaccess.h>
#include <linux/wait.h>
#include "gpio_events_uapi.h"

#define GPIO_EVENTS_QUEUE	16

struct gpio_events_config {
	bool blink;		/* toggle the LED on every edge */
};

struct gpio_events {
	struct device *dev;
	const struct gpio_events_config *config;
	struct gpio_desc *input;
	struct gpio_desc *led;
	spinlock_t lock;	/* guards the queue's two ends and the counts */
	DECLARE_KFIFO(queue, struct gpio_event, GPIO_EVENTS_QUEUE);
	wait_queue_head_t wait;
	struct gpio_events_stats stats;
	u32 last_level;
	struct miscdevice misc;
	char name[24];
};

static irqreturn_t gpio_events_hard(int irq, void *data)
{
	struct gpio_events *ge = data;
	struct gpio_event ev = {
		.timestamp_ns = ktime_get_ns(),
	};

	spin_lock(&ge->lock);
	ev.seq = ge->stats.edges++;
	if (!kfifo_put(&ge->queue, ev))
		ge->stats.dropped++;
	spin_unlock(&ge->lock);
	return IRQ_WAKE_THREAD;
}

static irqreturn_t gpio_events_thread(int irq, void *data)
{
	struct gpio_events *ge = data;
	unsigned long flags;
	int level;

	if (ge->led && ge->config->blink)
		gpiod_set_value_cansleep(ge->led, !gpiod_get_value_cansleep(ge->led));
	level = gpiod_get_value_cansleep(ge->input);
	spin_lock_irqsave(&ge->lock, flags);
	ge->stats.handled++;
	ge->last_level = level;
	spin_unlock_irqrestore(&ge->lock, flags);
	wake_up_interruptible(&ge->wait);
	return IRQ_HANDLED;
}

static struct gpio_events *file_to_events(struct file *file)
{
	struct miscdevice *misc = file->private_data;

	return container_of(misc, struct gpio_events, misc);
}

static ssize_t gpio_events_read(struct file *file, char __user *buf, size_t count, loff_t *ppos)
{
	struct gpio_events *ge = file_to_events(file);
	struct gpio_event evs[GPIO_EVENTS_QUEUE];
	unsigned int n, i;
	int ret;

	if (count < sizeof(evs[0]))
		return -EINVAL;
	if (kfifo_is_empty_spinlocked(&ge->queue, &ge->lock)) {
		if (file->f_flags & O_NONBLOCK)
			return -EAGAIN;
		ret = wait_event_interruptible(ge->wait,
					       !kfifo_is_empty_spinlocked(&ge->queue, &ge->lock));
		if (ret)
			return ret;
	}
	n = kfifo_out_spinlocked(&ge->queue, evs, min_t(size_t, count / sizeof(evs[0]), ARRAY_SIZE(evs)),
				 &ge->lock);
	for (i = 0; i < n; i++)
		evs[i].level = READ_ONCE(ge->last_level);
	if (copy_to_user(buf, evs, n * sizeof(evs[0])))
		return -EFAULT;
	return n * sizeof(evs[0]);
}

static long gpio_events_ioctl(struct file *file, unsigned int cmd, unsigned long arg)
{
	struct gpio_events *ge = file_to_events(file);
	struct gpio_events_stats stats;
	unsigned long flags;

	if (cmd != GPIO_EVENTS_STATS)
		return -ENOTTY;
	spin_lock_irqsave(&ge->lock, flags);
	stats = ge->stats;
	spin_unlock_irqrestore(&ge->lock, flags);
	return copy_to_user((void __user *)arg, &stats, sizeof(stats)) ? -EFAULT : 0;
}

static const struct file_operations gpio_events_fops = {
	.owner = THIS_MODULE,
	.read = gpio_events_read,
	.unlocked_ioctl = gpio_events_ioctl,
	.llseek = noop_llseek,
};

static void gpio_events_misc_deregister(void *misc)
{
	misc_deregister(misc);
}

static int gpio_events_probe(struct platform_device *pdev)
{
	static const struct gpio_events_config plain = { .blink = false };
	struct device *dev = &pdev->dev;
	struct gpio_events *ge;
	int irq, ret;

	ge = devm_kzalloc(dev, sizeof(*ge), GFP_KERNEL);
	if (!ge)
		return -ENOMEM;
	ge->dev = dev;
	ge->config = device_get_match_data(dev);
	if (!ge->config)
		ge->config = &plain;
	spin_lock_init(&ge->lock);
	INIT_KFIFO(ge->queue);
	init_waitqueue_head(&ge->wait);

	ge->input = devm_gpiod_get(dev, "event", GPIOD_IN);
	if (IS_ERR(ge->input))
		return dev_err_probe(dev, PTR_ERR(ge->input), "no event GPIO\n");
	ge->led = devm_gpiod_get_optional(dev, "led", GPIOD_OUT_LOW);
	if (IS_ERR(ge->led))
		return dev_err_probe(dev, PTR_ERR(ge->led), "bad LED GPIO\n");

	irq = gpiod_to_irq(ge->input);
	if (irq < 0)
		return dev_err_probe(dev, irq, "event GPIO has no IRQ\n");
	ret = devm_request_threaded_irq(dev, irq, gpio_events_hard, gpio_events_thread,
					IRQF_TRIGGER_RISING | IRQF_ONESHOT, dev_name(dev), ge);
	if (ret)
		return dev_err_probe(dev, ret, "cannot request IRQ %d\n", irq);

	snprintf(ge->name, sizeof(ge->name), "gpio_events%d", pdev->id < 0 ? 0 : pdev->id);
	ge->misc.minor = MISC_DYNAMIC_MINOR;
	ge->misc.name = ge->name;
	ge->misc.fops = &gpio_events_fops;
	ge->misc.parent = dev;
	ret = misc_register(&ge->misc);
	if (ret)
		return dev_err_probe(dev, ret, "cannot register /dev/%s\n", ge->name);
	ret = devm_add_action_or_reset(dev, gpio_events_misc_deregister, &ge->misc);
	if (ret)
		return ret;

	platform_set_drvdata(pdev, ge);
	dev_info(dev, "/dev/%s: rising edges on IRQ %d\n", ge->name, irq);
	return 0;
}

static int gpio_events_remove(struct platform_device *pdev)
{
	struct gpio_events *ge = platform_get_drvdata(pdev);

	dev_info(&pdev->dev, "%u edges, %u dropped\n", ge->stats.edges, ge->stats.dropped);
	return 0;
}

static const struct gpio_events_config blink_config = { .blink = true };

static const struct of_device_id gpio_events_of_match[] = {
	{ .compatible = "ev3lx,gpio-events-blink", .data = &blink_config },
	{ .compatible = "ev3lx,gpio-events" },
	{ }
};
MODULE_DEVICE_TABLE(of, gpio_events_of_match);

static const struct platform_device_id gpio_events_ids[] = {
	{ "gpio-events" },
	{ }
};
MODULE_DEVICE_TABLE(platform, gpio_events_ids);

static struct platform_driver gpio_events_driver = {
	.probe = gpio_events_probe,
	.remove = gpio_events_remove,
	.id_table = gpio_events_ids,
	.driver = {
		.name = "gpio-events",
		.of_match_table = gpio_events_of_match,
	},
};
module_platform_driver(gpio_events_driver);

MODULE_DESCRIPTION("Timestamped rising edges of a GPIO input");
MODULE_AUTHOR("ev3lx");
MODULE_LICENSE("GPL");
