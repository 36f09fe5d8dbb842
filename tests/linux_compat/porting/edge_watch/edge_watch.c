// SPDX-License-Identifier: GPL-2.0
/*
 * edge_watch.c - counts both edges of a GPIO input and watches it with an
 * hrtimer: a period of timeout_ms without an edge counts a timeout.  Every
 * edge and every timeout is an event; read() of /dev/edge_watch blocks until
 * there is one the file has not seen and returns a text line, poll() waits
 * for one, ioctl() reads or resets the counters.
 */
#include <linux/module.h>
#include <linux/init.h>
#include <linux/kernel.h>
#include <linux/gpio.h>
#include <linux/interrupt.h>
#include <linux/hrtimer.h>
#include <linux/ktime.h>
#include <linux/miscdevice.h>
#include <linux/fs.h>
#include <linux/poll.h>
#include <linux/wait.h>
#include <linux/spinlock.h>
#include <linux/uaccess.h>
#include "edge_watch_uapi.h"

static int gpio = 91;
module_param(gpio, int, 0444);
MODULE_PARM_DESC(gpio, "GPIO number of the watched input");

static unsigned int timeout_ms = 10;
module_param(timeout_ms, uint, 0444);
MODULE_PARM_DESC(timeout_ms, "watchdog period in ms");

static DEFINE_SPINLOCK(ew_lock);
static DECLARE_WAIT_QUEUE_HEAD(ew_wait);
static struct edge_watch_counts ew_counts;
static unsigned int ew_events;		/* edges + timeouts, never reset */
static struct hrtimer ew_timer;
static int ew_irq;

static void ew_event(bool edge)
{
	unsigned long flags;

	spin_lock_irqsave(&ew_lock, flags);
	if (edge)
		ew_counts.edges++;
	else
		ew_counts.timeouts++;
	ew_events++;
	spin_unlock_irqrestore(&ew_lock, flags);
	wake_up_interruptible(&ew_wait);
}

static irqreturn_t ew_isr(int irq, void *dev_id)
{
	ew_event(true);
	hrtimer_start(&ew_timer, ms_to_ktime(timeout_ms), HRTIMER_MODE_REL);
	return IRQ_HANDLED;
}

static enum hrtimer_restart ew_watchdog(struct hrtimer *timer)
{
	ew_event(false);
	hrtimer_forward_now(timer, ms_to_ktime(timeout_ms));
	return HRTIMER_RESTART;
}

static unsigned int ew_seen(struct file *file)
{
	return (unsigned int)(unsigned long)file->private_data;
}

static int ew_open(struct inode *inode, struct file *file)
{
	file->private_data = (void *)(unsigned long)READ_ONCE(ew_events);
	return stream_open(inode, file);
}

static ssize_t ew_read(struct file *file, char __user *buf, size_t count, loff_t *ppos)
{
	struct edge_watch_counts now;
	unsigned long flags;
	char line[48];
	int len, ret;

	if (!(file->f_flags & O_NONBLOCK)) {
		ret = wait_event_interruptible(ew_wait, READ_ONCE(ew_events) != ew_seen(file));
		if (ret)
			return ret;
	} else if (READ_ONCE(ew_events) == ew_seen(file)) {
		return -EAGAIN;
	}
	spin_lock_irqsave(&ew_lock, flags);
	now = ew_counts;
	file->private_data = (void *)(unsigned long)ew_events;
	spin_unlock_irqrestore(&ew_lock, flags);
	len = scnprintf(line, sizeof(line), "edges=%u timeouts=%u\n", now.edges, now.timeouts);
	if (count < (size_t)len)
		return -EINVAL;
	if (copy_to_user(buf, line, len))
		return -EFAULT;
	return len;
}

static __poll_t ew_poll(struct file *file, poll_table *wait)
{
	poll_wait(file, &ew_wait, wait);
	return READ_ONCE(ew_events) != ew_seen(file) ? EPOLLIN | EPOLLRDNORM : 0;
}

static long ew_ioctl(struct file *file, unsigned int cmd, unsigned long arg)
{
	struct edge_watch_counts now;
	unsigned long flags;

	switch (cmd) {
	case EDGE_WATCH_GET:
		spin_lock_irqsave(&ew_lock, flags);
		now = ew_counts;
		spin_unlock_irqrestore(&ew_lock, flags);
		return copy_to_user((void __user *)arg, &now, sizeof(now)) ? -EFAULT : 0;
	case EDGE_WATCH_RESET:
		spin_lock_irqsave(&ew_lock, flags);
		ew_counts.edges = 0;
		ew_counts.timeouts = 0;
		spin_unlock_irqrestore(&ew_lock, flags);
		return 0;
	default:
		return -ENOTTY;
	}
}

static const struct file_operations ew_fops = {
	.owner = THIS_MODULE,
	.open = ew_open,
	.read = ew_read,
	.poll = ew_poll,
	.unlocked_ioctl = ew_ioctl,
	.llseek = no_llseek,
};

static struct miscdevice ew_misc = {
	.minor = MISC_DYNAMIC_MINOR,
	.name = "edge_watch",
	.fops = &ew_fops,
};

static int __init ew_init(void)
{
	int ret;

	if (timeout_ms == 0)
		return -EINVAL;
	ret = gpio_request(gpio, "edge_watch");
	if (ret)
		return ret;
	ret = gpio_direction_input(gpio);
	if (ret)
		goto free_gpio;
	ew_irq = gpio_to_irq(gpio);
	if (ew_irq < 0) {
		ret = ew_irq;
		goto free_gpio;
	}
	hrtimer_init(&ew_timer, CLOCK_MONOTONIC, HRTIMER_MODE_REL);
	ew_timer.function = ew_watchdog;
	ret = request_irq(ew_irq, ew_isr, IRQF_TRIGGER_RISING | IRQF_TRIGGER_FALLING,
			  "edge_watch", &ew_misc);
	if (ret)
		goto free_gpio;
	ret = misc_register(&ew_misc);
	if (ret)
		goto free_irq;
	hrtimer_start(&ew_timer, ms_to_ktime(timeout_ms), HRTIMER_MODE_REL);
	pr_info("edge_watch: GPIO %d, IRQ %d, watchdog %u ms\n", gpio, ew_irq, timeout_ms);
	return 0;

free_irq:
	free_irq(ew_irq, &ew_misc);
free_gpio:
	gpio_free(gpio);
	return ret;
}

static void __exit ew_exit(void)
{
	misc_deregister(&ew_misc);
	free_irq(ew_irq, &ew_misc);
	hrtimer_cancel(&ew_timer);
	gpio_free(gpio);
}

module_init(ew_init);
module_exit(ew_exit);
MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("GPIO edge counter with an hrtimer watchdog");
