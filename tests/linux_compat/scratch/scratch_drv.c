// SPDX-License-Identifier: GPL-2.0
/*
 * scratch_drv.c — a small Linux driver written only against Linux headers,
 * to show that such code runs on ev3lx unchanged; it also builds as an
 * out-of-tree module against Linux 6.1 (make scratch-kbuild-check).
 *
 * /dev/scratch: a periodic hrtimer counts ticks, a GPIO interrupt (both
 * edges) counts edges and signals a semaphore; read() waits for an edge
 * (or -EAGAIN with O_NONBLOCK) and reports the counters as text; write()
 * "reset" clears them; ioctls read the edge count and set the period; mmap
 * shows struct scratch_shared, kmalloc'd and page-aligned.
 */
#include <linux/module.h>
#include <linux/kernel.h>
#include <linux/init.h>
#include <linux/errno.h>
#include <linux/fs.h>
#include <linux/miscdevice.h>
#include <linux/mm.h>
#include <linux/slab.h>
#include <linux/uaccess.h>
#include <linux/interrupt.h>
#include <linux/gpio.h>
#include <linux/hrtimer.h>
#include <linux/ktime.h>
#include <linux/semaphore.h>
#include <linux/spinlock.h>
#include <linux/string.h>

#include "scratch_uapi.h"

static int gpio_pin = 91;
module_param(gpio_pin, int, 0444);
MODULE_PARM_DESC(gpio_pin, "GPIO whose edges are counted");

static DEFINE_SPINLOCK(scratch_lock);
static struct semaphore edge_sem;
static struct hrtimer tick_timer;
static ktime_t tick_period;
static void *shared_alloc;
static struct scratch_shared *shared;
static int irq_number = -1;

static enum hrtimer_restart scratch_tick(struct hrtimer *timer)
{
	spin_lock(&scratch_lock);
	shared->ticks++;
	hrtimer_forward_now(timer, tick_period);
	spin_unlock(&scratch_lock);
	return HRTIMER_RESTART;
}

static irqreturn_t scratch_edge(int irq, void *dev_id)
{
	spin_lock(&scratch_lock);
	shared->edges++;
	shared->level = gpio_get_value(gpio_pin);
	spin_unlock(&scratch_lock);
	up(&edge_sem);
	return IRQ_HANDLED;
}

static ssize_t scratch_read(struct file *file, char __user *buf, size_t count, loff_t *ppos)
{
	char text[64];
	unsigned long flags;
	u32 ticks, edges;
	int len;

	if (file->f_flags & O_NONBLOCK) {
		if (down_trylock(&edge_sem))
			return -EAGAIN;
	} else if (down_interruptible(&edge_sem)) {
		return -ERESTARTSYS;
	}
	spin_lock_irqsave(&scratch_lock, flags);
	ticks = shared->ticks;
	edges = shared->edges;
	spin_unlock_irqrestore(&scratch_lock, flags);
	len = scnprintf(text, sizeof(text), "edges=%u ticks=%u\n", edges, ticks);
	if (count > (size_t)len)
		count = (size_t)len;
	if (copy_to_user(buf, text, count))
		return -EFAULT;
	return (ssize_t)count;
}

static ssize_t scratch_write(struct file *file, const char __user *buf, size_t count, loff_t *ppos)
{
	char cmd[16];
	unsigned long flags;
	size_t len = min(count, sizeof(cmd) - 1);

	if (copy_from_user(cmd, buf, len))
		return -EFAULT;
	cmd[len] = '\0';
	if (strncmp(cmd, "reset", 5) != 0)
		return -EINVAL;
	spin_lock_irqsave(&scratch_lock, flags);
	shared->ticks = 0;
	shared->edges = 0;
	spin_unlock_irqrestore(&scratch_lock, flags);
	while (!down_trylock(&edge_sem))
		;
	return (ssize_t)count;
}

static long scratch_ioctl(struct file *file, unsigned int cmd, unsigned long arg)
{
	u32 period_us;
	unsigned long flags;

	switch (cmd) {
	case SCRATCH_GET_EDGES:
		return put_user(shared->edges, (u32 __user *)arg);
	case SCRATCH_SET_PERIOD:
		if (get_user(period_us, (u32 __user *)arg))
			return -EFAULT;
		if (period_us < 100 || period_us > 1000000)
			return -EINVAL;
		spin_lock_irqsave(&scratch_lock, flags);
		tick_period = ktime_set(0, period_us * 1000UL);
		shared->period_us = period_us;
		spin_unlock_irqrestore(&scratch_lock, flags);
		return 0;
	default:
		return -ENOTTY;
	}
}

static int scratch_mmap(struct file *file, struct vm_area_struct *vma)
{
	unsigned long size = vma->vm_end - vma->vm_start;

	if (size > PAGE_SIZE)
		return -EINVAL;
	if (remap_pfn_range(vma, vma->vm_start, virt_to_phys(shared) >> PAGE_SHIFT,
			    size, vma->vm_page_prot))
		return -EAGAIN;
	return 0;
}

static const struct file_operations scratch_fops = {
	.owner = THIS_MODULE,
	.read = scratch_read,
	.write = scratch_write,
	.unlocked_ioctl = scratch_ioctl,
	.mmap = scratch_mmap,
	.llseek = noop_llseek,
};

static struct miscdevice scratch_misc = {
	.minor = MISC_DYNAMIC_MINOR,
	.name = SCRATCH_DEVICE_NAME,
	.fops = &scratch_fops,
};

static int __init scratch_init(void)
{
	int ret;

	shared_alloc = kzalloc(2 * PAGE_SIZE, GFP_KERNEL);
	if (!shared_alloc)
		return -ENOMEM;
	shared = (struct scratch_shared *)PAGE_ALIGN((unsigned long)shared_alloc);
	SetPageReserved(virt_to_page(shared));
	sema_init(&edge_sem, 0);
	shared->period_us = 1000;
	tick_period = ktime_set(0, 1000 * 1000);

	ret = gpio_request(gpio_pin, "scratch");
	if (ret)
		goto fail_gpio;
	ret = gpio_direction_input(gpio_pin);
	if (ret)
		goto fail_irq;
	irq_number = gpio_to_irq(gpio_pin);
	ret = request_irq(irq_number, scratch_edge, IRQF_TRIGGER_RISING | IRQF_TRIGGER_FALLING,
			  "scratch", &scratch_misc);
	if (ret)
		goto fail_irq;
	ret = misc_register(&scratch_misc);
	if (ret)
		goto fail_misc;
	hrtimer_init(&tick_timer, CLOCK_MONOTONIC, HRTIMER_MODE_REL);
	tick_timer.function = scratch_tick;
	hrtimer_start(&tick_timer, tick_period, HRTIMER_MODE_REL);
	pr_info("scratch: gpio %d (irq %d)\n", gpio_pin, irq_number);
	return 0;

fail_misc:
	free_irq(irq_number, &scratch_misc);
fail_irq:
	gpio_free(gpio_pin);
fail_gpio:
	ClearPageReserved(virt_to_page(shared));
	kfree(shared_alloc);
	return ret;
}

static void __exit scratch_exit(void)
{
	hrtimer_cancel(&tick_timer);
	misc_deregister(&scratch_misc);
	free_irq(irq_number, &scratch_misc);
	gpio_free(gpio_pin);
	ClearPageReserved(virt_to_page(shared));
	kfree(shared_alloc);
}

module_init(scratch_init);
module_exit(scratch_exit);

MODULE_LICENSE("GPL");
MODULE_AUTHOR("ev3lx");
MODULE_DESCRIPTION("Scratch driver: hrtimer, GPIO IRQ, misc device, semaphore, kmalloc");
