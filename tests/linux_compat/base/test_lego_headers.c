/*
 * test_lego_headers.c — the 78 kernel symbols of LEGO's d_pwm, d_analog and
 * d_uart (the kernel symbols LEGO's d_pwm.c, d_analog.c and d_uart_mod.c use) are reachable through exactly the
 * headers those drivers include (their union; none includes linux/slab.h,
 * linux/string.h or linux/ioctl.h, as in 2.6.33 where kmalloc, the string
 * functions and _IOWR came through linux/mm.h and linux/fs.h), with the
 * values the drivers and their user space rely on.
 */
#define KBUILD_MODNAME "lego_headers"
#include <asm/types.h>
#include <linux/time.h>
#include <linux/kernel.h>
#include <linux/fs.h>
#include <linux/signal.h>
#include <linux/sched.h>
#include <linux/ioport.h>
#include <asm/gpio.h>
#include <asm/uaccess.h>
#include <linux/module.h>
#include <linux/miscdevice.h>
#include <linux/mm.h>
#include <linux/hrtimer.h>
#include <linux/init.h>
#include <asm/siginfo.h>
#include <linux/rcupdate.h>
#include <linux/uaccess.h>
#include <linux/debugfs.h>
#include <asm/io.h>
#include <linux/irq.h>
#include <linux/interrupt.h>
#include <mach/mux.h>
#include <mach/da8xx.h>
#include <mach/gpio.h>
#include <mach/irqs.h>
#include "tap.h"

/* The shapes LEGO's code has: a 12-byte DEVCON ioctl argument, a charp parameter. */
struct devcon { s8 connection[4]; s8 type[4]; s8 mode[4]; };
static char *HwId = "03";
module_param(HwId, charp, 0);

static enum hrtimer_restart tick(struct hrtimer *t)
{
	hrtimer_forward_now(t, ktime_set(0, 200000));
	return HRTIMER_RESTART;
}

static irqreturn_t isr(int irq, void *dev_id)
{
	return IRQ_HANDLED;
}

static ssize_t dev_read(struct file *file, char __user *buf, size_t count, loff_t *pos)
{
	return 0;
}

static int dev_ioctl(struct inode *inode, struct file *file, unsigned int cmd, unsigned long arg)
{
	return 0;
}

static int dev_mmap(struct file *file, struct vm_area_struct *vma)
{
	return -EAGAIN;
}

static const struct file_operations fops = {
	.owner = THIS_MODULE, .read = dev_read, .ioctl = dev_ioctl, .mmap = dev_mmap,
};
static struct miscdevice misc = { MISC_DYNAMIC_MINOR, "lego_headers", &fops };

/* Referenced, never called: the calls the drivers make must compile and link. */
void lego_headers_calls(void);
void lego_headers_calls(void)
{
	static struct hrtimer timer;
	char text[8], __user *user = NULL;
	void *mem = kmalloc(3 * PAGE_SIZE, GFP_KERNEL);
	void __iomem *regs = ioremap(DA8XX_GPIO_BASE, PAGE_SIZE);
	struct gpio_controller __iomem *bank = regs;

	memset(text, 0, sizeof(text));
	memcpy(text, HwId, strlen(HwId));
	if (memcmp(text, "03", 2) == 0)
		snprintf(text, sizeof(text), "%d", 1);
	SetPageReserved(virt_to_page(mem));
	ClearPageReserved(virt_to_page(mem));
	(void)remap_pfn_range(NULL, 0, virt_to_phys(mem) >> PAGE_SHIFT, PAGE_SIZE, PAGE_SHARED);
	(void)copy_to_user(user, text, 1);
	(void)copy_from_user(text, user, 1);
	(void)request_mem_region(DA8XX_GPIO_BASE, PAGE_SIZE, "lego_headers");
	iowrite32(ioread32(&bank->in_data), regs);
	iowrite16(0, regs);
	iowrite32(0, da8xx_syscfg0_base + 0x38);
	iowrite32(0, da8xx_syscfg1_base + 0x0c);
	hrtimer_init(&timer, CLOCK_MONOTONIC, HRTIMER_MODE_REL);
	timer.function = tick;
	hrtimer_start(&timer, ktime_set(0, 2000000), HRTIMER_MODE_REL);
	(void)hrtimer_cancel(&timer);
	(void)request_irq(gpio_to_irq(5), isr, 0, "lego_headers", NULL);
	(void)set_irq_type(gpio_to_irq(5), IRQ_TYPE_EDGE_RISING | IRQ_TYPE_EDGE_FALLING);
	(void)request_irq(IRQ_DA8XX_UARTINT1, isr, IRQF_SHARED, "lego_headers", text);
	free_irq(IRQ_DA8XX_UARTINT1, text);
	(void)misc_register(&misc);
	misc_deregister(&misc);
	printk(KERN_INFO "lego_headers\n");
	iounmap(regs);
	kfree(mem);
}

static int __init lego_headers_init(void)
{
	return 0;
}

static void __exit lego_headers_exit(void)
{
}

module_init(lego_headers_init);
module_exit(lego_headers_exit);
MODULE_LICENSE("GPL");
MODULE_AUTHOR("ev3lx");
MODULE_DESCRIPTION("the headers of LEGO's drivers");
MODULE_SUPPORTED_DEVICE("none");

int main(void)
{
	tap_plan(11);
	is_int(_IOWR('u', 0, struct devcon), 0xC00C7500, "_IOWR through linux/fs.h: DEVCON is 0xC00C7500");
	is_int(PAGE_SIZE, 4096, "PAGE_SIZE");
	is_int(PAGE_SHIFT, 12, "PAGE_SHIFT");
	is_int(IRQ_TYPE_EDGE_RISING | IRQ_TYPE_EDGE_FALLING, 3, "both edges");
	is_int(IRQ_HANDLED, 1, "IRQ_HANDLED");
	ok(IRQ_DA8XX_UARTINT0 == 25 && IRQ_DA8XX_UARTINT1 == 53, "UART interrupt numbers");
	is_int(MISC_DYNAMIC_MINOR, 255, "MISC_DYNAMIC_MINOR");
	is_int(DA8XX_GPIO_BASE, 0x01E26000, "DA8XX_GPIO_BASE");
	ok(EAGAIN == 11 && EBUSY == 16, "errno values");
	ok(gpio_to_irq(5) == gpio_to_irq(0) + 5, "gpio_to_irq: one IRQ per pin");
	ok(HRTIMER_RESTART != HRTIMER_NORESTART && sizeof(u16) == 2 && sizeof(u32) == 4 &&
	   sizeof(ktime_t) == 8, "hrtimer results, fixed-width types, 64-bit ktime_t");
	return tap_done();
}
