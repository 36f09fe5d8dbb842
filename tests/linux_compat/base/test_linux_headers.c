/*
 * test_linux_headers.c — the Linux headers drivers of every era include:
 * in_task via linux/interrupt.h alone (it brings linux/hardirq.h, as in
 * Linux), linux/err.h, linux/bitops.h, linux/kfifo.h, linux/vmalloc.h,
 * linux/version.h and linux/cdev.h with char device regions opened through
 * the registry.
 */
#include <linux/interrupt.h>
#include <linux/err.h>
#include <linux/bitops.h>
#include <linux/kfifo.h>
#include <linux/vmalloc.h>
#include <linux/version.h>
#include <linux/cdev.h>
#include <linux/fs.h>
#include <linux/module.h>
#include <linux/uaccess.h>
#include <linux_compat/devfs.h>
#include "lx_test.h"

#if LINUX_VERSION_CODE < KERNEL_VERSION(2, 6, 33)
#error "LINUX_VERSION_CODE must describe a kernel at least as new as 2.6.33"
#endif

static int probe_open(struct inode *inode, struct file *file)
{
	file->private_data = (void *)(uintptr_t)iminor(inode);
	return 0;
}

static ssize_t probe_read(struct file *file, char __user *buf, size_t count, loff_t *ppos)
{
	char c = (char)('0' + (uintptr_t)file->private_data);

	(void)ppos;
	if (count < 1)
		return 0;
	return copy_to_user(buf, &c, 1) ? -EFAULT : 1;
}

static const struct file_operations probe_fops = {
	.owner = THIS_MODULE,
	.open = probe_open,
	.read = probe_read,
};

static void test_err(void)
{
	void *p = ERR_PTR(-ENOMEM);
	int x;

	ok(IS_ERR(p) && PTR_ERR(p) == -ENOMEM, "ERR_PTR(-ENOMEM): IS_ERR, PTR_ERR gives -ENOMEM back");
	ok(!IS_ERR(&x) && !IS_ERR_OR_NULL(&x) && IS_ERR_OR_NULL(NULL), "valid pointers are not errors; NULL is IS_ERR_OR_NULL");
	ok(IS_ERR(ERR_PTR(-MAX_ERRNO)) && !IS_ERR(ERR_PTR(-MAX_ERRNO - 1)), "the error range is -1..-MAX_ERRNO");
	is_int(PTR_ERR_OR_ZERO(&x), 0, "PTR_ERR_OR_ZERO of a valid pointer: 0");
}

static void test_bitops(void)
{
	unsigned long map[BITS_TO_LONGS(100)] = { 0 };
	unsigned long bit, n = 0;

	set_bit(3, map);
	set_bit(70, map);
	__set_bit(99, map);
	ok(test_bit(3, map) && test_bit(70, map) && test_bit(99, map) && !test_bit(4, map), "set_bit/test_bit");
	ok(test_and_clear_bit(70, map) && !test_bit(70, map) && !test_and_clear_bit(70, map),
	   "test_and_clear_bit returns the old value");
	ok(!test_and_set_bit(5, map) && test_and_set_bit(5, map), "test_and_set_bit returns the old value");
	for_each_set_bit(bit, map, 100)
		n++;
	is_int((int)n, 3, "for_each_set_bit visits 3, 5 and 99");
	is_int((int)find_next_zero_bit(map, 100, 3), 4, "find_next_zero_bit");
	ok(ffs(0) == 0 && ffs(8) == 4 && fls(0) == 0 && fls(0x80000000U) == 32 && __ffs(8) == 3,
	   "ffs/fls count from 1, __ffs from 0");
	is_int((int)hweight32(0xF0F0U), 8, "hweight32");
}

static void test_kfifo(void)
{
	static DEFINE_KFIFO(small, unsigned char, 8);
	struct kfifo dyn;
	unsigned char out[16] = { 0 };
	unsigned int i;

	is_int((int)kfifo_in(&small, (const unsigned char *)"abcdefghij", 10), 8, "kfifo_in into 8 bytes takes 8");
	ok(kfifo_is_full(&small) && kfifo_len(&small) == 8, "full, length 8");
	is_int((int)kfifo_out(&small, out, 3), 3, "kfifo_out 3");
	is_int((int)kfifo_in(&small, (const unsigned char *)"XYZ", 3), 3, "kfifo_in wraps around");
	is_int((int)kfifo_out(&small, out, sizeof(out)), 8, "kfifo_out takes the 8 left");
	ok(memcmp(out, "defghXYZ", 8) == 0, "in FIFO order across the wrap");
	is_int(kfifo_alloc(&dyn, 100, GFP_KERNEL), 0, "kfifo_alloc(100)");
	is_int((int)kfifo_size(&dyn), 128, "rounded up to a power of two");
	for (i = 0; i < 200; i++)
		kfifo_put(&dyn, (unsigned char)i);
	ok(kfifo_len(&dyn) == 128 && kfifo_get(&dyn, out) == 1 && out[0] == 0, "kfifo_put/kfifo_get");
	kfifo_free(&dyn);
}

static void test_vmalloc(void)
{
	unsigned char *p = vzalloc(3000);

	ok(p != NULL && p[0] == 0 && p[2999] == 0, "vzalloc gives zeroed memory");
	vfree(p);
	vfree(NULL);
	ok(1, "vfree(NULL) is allowed");
}

static void test_cdev(void)
{
	static struct cdev one, many;
	__kernel_dev_t fixed = MKDEV(200, 0), dyn = 0;
	struct file *f;
	char c = 0;

	is_int(register_chrdev_region(fixed, 1, "lxone"), 0, "register_chrdev_region(200:0, 1)");
	is_int(register_chrdev_region(MKDEV(200, 0), 2, "clash"), -EBUSY, "an overlapping region: -EBUSY");
	is_int(alloc_chrdev_region(&dyn, 4, 3, "lxmany"), 0, "alloc_chrdev_region(baseminor 4, 3)");
	ok(MAJOR(dyn) != 0 && MAJOR(dyn) != 200 && MINOR(dyn) == 4, "a free major, the base minor (%u:%u)",
	   MAJOR(dyn), MINOR(dyn));
	cdev_init(&one, &probe_fops);
	one.owner = THIS_MODULE;
	is_int(cdev_add(&one, fixed, 1), 0, "cdev_add of the one-number region");
	ok(lx_dev_exists("/dev/lxone"), "is /dev/lxone");
	cdev_init(&many, &probe_fops);
	is_int(cdev_add(&many, dyn, 3), 0, "cdev_add of three numbers");
	ok(lx_dev_exists("/dev/lxmany0") && lx_dev_exists("/dev/lxmany2") && !lx_dev_exists("/dev/lxmany3"),
	   "are /dev/lxmany0..2");
	is_int(cdev_add(&one, MKDEV(201, 0), 1), -EINVAL, "cdev_add twice: -EINVAL");
	if (lx_dev_open("/dev/lxmany2", O_RDONLY, &f) == 0) {
		ok(kernel_read(f, &c, 1, NULL) == 1 && c == '6', "open sees its minor (6) in the inode");
		(void)lx_dev_close(f);
	} else {
		ok(0, "open /dev/lxmany2");
	}
	cdev_del(&many);
	cdev_del(&one);
	ok(!lx_dev_exists("/dev/lxone") && !lx_dev_exists("/dev/lxmany1"), "cdev_del removes the nodes");
	unregister_chrdev_region(dyn, 3);
	unregister_chrdev_region(fixed, 1);
	is_int(register_chrdev_region(MKDEV(200, 0), 2, "again"), 0, "the released numbers are free again");
	unregister_chrdev_region(MKDEV(200, 0), 2);
}

static void body(void)
{
	ok(in_task() && !in_irq(), "in_task/in_irq through linux/interrupt.h alone");
	test_err();
	test_bitops();
	test_kfifo();
	test_vmalloc();
	test_cdev();
}

int main(void)
{
	tap_plan(36);
	ok(lx_test_run(body), "test task ran to completion");
	return tap_done();
}
