/*
 * test_devfs.c — misc and char devices through the registry: registration
 * rules (dynamic minors, duplicates), open/read/write/ioctl (both the
 * modern and the 2.6.33 form)/mmap/poll/llseek/close round trips with
 * Linux's error codes, and deregistration.
 */
#include "lx_test.h"
#include <linux/fs.h>
#include <linux/miscdevice.h>
#include <linux/mm.h>
#include <linux/poll.h>
#include <linux/slab.h>
#include <linux/uaccess.h>
#include <linux/ioctl.h>
#include <linux_compat/devfs.h>

#define TEST_IOC_ADD	_IOWR('t', 1, int)
#define TEST_IOC_MAGIC	_IO('t', 2)
#define MMAP_BYTES	5000

static char store[64];
static size_t store_len;
static int opens, releases, legacy_calls;
static struct inode *legacy_inode;
static unsigned int legacy_minor;
static unsigned char *mmap_area;       /* page-aligned inside mmap_alloc */
static void *mmap_alloc;
static bool map_short;
static struct miscdevice test_misc;

static int t_open(struct inode *inode, struct file *file)
{
	opens++;
	return file->private_data == &test_misc ? 0 : -EIO;
}

static int t_release(struct inode *inode, struct file *file)
{
	releases++;
	return 0;
}

static ssize_t t_read(struct file *file, char __user *buf, size_t count, loff_t *ppos)
{
	return simple_read_from_buffer(buf, count, ppos, store, store_len);
}

static ssize_t t_write(struct file *file, const char __user *buf, size_t count, loff_t *ppos)
{
	if (count > sizeof(store))
		count = sizeof(store);
	if (copy_from_user(store, buf, count))
		return -EFAULT;
	store_len = count;
	return (ssize_t)count;
}

static long t_ioctl(struct file *file, unsigned int cmd, unsigned long arg)
{
	int v;

	switch (cmd) {
	case TEST_IOC_ADD:
		if (get_user(v, (int __user *)arg))
			return -EFAULT;
		return put_user(v + 1, (int __user *)arg);
	case TEST_IOC_MAGIC:
		return 4242;
	default:
		return -ENOTTY;
	}
}

static int t_mmap(struct file *file, struct vm_area_struct *vma)
{
	unsigned long size = vma->vm_end - vma->vm_start;

	if (size > 2 * PAGE_SIZE)
		return -EINVAL;
	if (map_short)
		size = PAGE_SIZE;
	return remap_pfn_range(vma, vma->vm_start, virt_to_phys(mmap_area) >> PAGE_SHIFT,
			       size, vma->vm_page_prot);
}

static __poll_t t_poll(struct file *file, poll_table *wait)
{
	return store_len ? EPOLLIN | EPOLLRDNORM : 0;
}

static const struct file_operations test_fops = {
	.owner = NULL,
	.open = t_open,
	.release = t_release,
	.read = t_read,
	.write = t_write,
	.unlocked_ioctl = t_ioctl,
	.mmap = t_mmap,
	.poll = t_poll,
	.llseek = no_llseek,
};

static struct miscdevice test_misc = {
	.minor = MISC_DYNAMIC_MINOR, .name = "lx_test", .fops = &test_fops,
};

/* A 2.6.33-style driver: legacy .ioctl with the inode, positional miscdevice. */
static int legacy_ioctl(struct inode *inode, struct file *file, unsigned int cmd, unsigned long arg)
{
	legacy_calls++;
	legacy_inode = inode;
	legacy_minor = iminor(inode);
	if (cmd == TEST_IOC_MAGIC)
		return 7;
	return -ENOIOCTLCMD;
}

static const struct file_operations legacy_fops = {
	.owner = NULL,
	.ioctl = legacy_ioctl,
};

static struct miscdevice legacy_misc = { MISC_DYNAMIC_MINOR, "lx_legacy", &legacy_fops };
static struct miscdevice static_misc = { 200, "lx_static", &legacy_fops };

static void test_register(void)
{
	struct miscdevice dup_name = { MISC_DYNAMIC_MINOR, "lx_test", &legacy_fops };
	struct miscdevice dup_minor = { 200, "lx_other", &legacy_fops };
	struct miscdevice no_fops = { MISC_DYNAMIC_MINOR, "lx_nofops", NULL };

	is_int(misc_register(&test_misc), 0, "misc_register");
	is_int(test_misc.minor, 63, "the first dynamic minor is 63, as 2.6.33 gave");
	is_int(misc_register(&legacy_misc), 0, "a positional { minor, name, fops } miscdevice registers");
	is_int(legacy_misc.minor, 62, "and gets the next dynamic minor");
	is_int(misc_register(&static_misc), 0, "a fixed minor");
	is_int(misc_register(&dup_name), -EBUSY, "a taken name: -EBUSY");
	is_int(misc_register(&dup_minor), -EBUSY, "a taken minor: -EBUSY");
	is_int(misc_register(&no_fops), -EINVAL, "no fops: -EINVAL");
	ok(lx_dev_exists("/dev/lx_test") && lx_dev_exists("lx_legacy") && !lx_dev_exists("/dev/nothing"),
	   "lx_dev_exists");
}

static void test_file_ops(void)
{
	struct file *f = NULL, *ro = NULL, *wo = NULL;
	char buf[32] = "";
	loff_t pos = 0;
	int v = 41;
	void *addr = NULL;

	is_int(lx_dev_open("/dev/nothing", O_RDWR, &f), -ENODEV, "an unknown name: -ENODEV");
	ok(f == NULL, "and no file");
	is_int(lx_dev_open("/dev/lx_test", 3, &f), -EINVAL, "a bad access mode: -EINVAL");
	is_int(lx_dev_open("/dev/lx_test", O_RDWR, &f), 0, "open /dev/lx_test");
	is_int(opens, 1, "the driver's open ran once, with private_data = the miscdevice");
	is_int(imajor(f->f_inode), MISC_MAJOR, "inode: major 10");
	is_int(iminor(f->f_inode), 63, "inode: its minor");

	is_int(lx_dev_write(f, "hello", 5, NULL), 5, "write 5 bytes");
	is_int(lx_dev_read(f, buf, sizeof(buf), &pos), 5, "read them back");
	ok(memcmp(buf, "hello", 5) == 0 && pos == 5, "same bytes, position advanced");
	is_int(lx_dev_read(f, buf, sizeof(buf), &pos), 0, "then end of file: 0");
	pos = -1;
	is_int(lx_dev_read(f, buf, sizeof(buf), &pos), -EINVAL, "a negative position: -EINVAL");
	is_int(lx_dev_read(NULL, buf, 1, NULL), -EBADF, "a NULL file: -EBADF");

	is_int(lx_dev_ioctl(f, TEST_IOC_ADD, (unsigned long)&v), 0, "unlocked_ioctl with get_user/put_user");
	is_int(v, 42, "the argument was read and written back");
	is_int(lx_dev_ioctl(f, TEST_IOC_MAGIC, 0), 4242, "an ioctl's return value passes through");
	is_int(lx_dev_ioctl(f, _IO('t', 99), 0), -ENOTTY, "an unknown command: -ENOTTY");
	ok(lx_dev_poll(f) == (EPOLLIN | EPOLLRDNORM), "poll: readable");
	is_int(lx_dev_llseek(f, 0, SEEK_SET), -ESPIPE, "no_llseek: -ESPIPE");

	is_int(lx_dev_mmap(f, MMAP_BYTES, &addr), 0, "mmap 5000 bytes");
	ok(addr == mmap_area, "the caller gets the driver's buffer");
	memcpy(addr, "shared", 7);
	ok(strcmp((char *)mmap_area, "shared") == 0, "writes through the mapping reach the driver");
	is_int(lx_dev_mmap(f, 3 * PAGE_SIZE, &addr), -EINVAL, "the driver refuses a too-long mapping: its -EINVAL");
	ok(addr == NULL, "and no address");
	map_short = true;
	is_int(lx_dev_mmap(f, MMAP_BYTES, &addr), -ENXIO, "a driver mapping less than asked: -ENXIO");
	map_short = false;
	is_int(lx_dev_mmap(f, 0, &addr), -EINVAL, "length 0: -EINVAL");

	is_int(lx_dev_open("lx_test", O_RDONLY, &ro), 0, "open without /dev/, read-only");
	is_int(lx_dev_write(ro, "x", 1, NULL), -EBADF, "write on a read-only file: -EBADF");
	is_int(lx_dev_open("lx_test", O_WRONLY, &wo), 0, "open write-only");
	is_int(lx_dev_read(wo, buf, 1, NULL), -EBADF, "read on a write-only file: -EBADF");
	is_int(lx_dev_mmap(wo, MMAP_BYTES, &addr), -EACCES, "mmap of a write-only file: -EACCES");
	is_int(lx_dev_close(ro), 0, "close");
	is_int(lx_dev_close(wo), 0, "close");
	is_int(releases, 2, "release ran for each close");
	is_int(lx_dev_close(NULL), -EBADF, "close(NULL): -EBADF");

	misc_deregister(&test_misc);
	is_int(test_misc.minor, MISC_DYNAMIC_MINOR, "deregistering gives the dynamic minor back");
	is_int(lx_dev_open("/dev/lx_test", O_RDWR, &ro), -ENODEV, "a deregistered device cannot be opened");
	is_int(lx_dev_read(f, buf, sizeof(buf), NULL), 5, "but an open file keeps working");
	is_int(lx_dev_close(f), 0, "and closes");
	is_int(releases, 3, "with its release");
}

static void test_legacy(void)
{
	struct file *f = NULL;
	char c;
	void *addr;

	is_int(lx_dev_open("/dev/lx_legacy", O_RDWR, &f), 0, "open a driver without open/read/write");
	is_int(lx_dev_ioctl(f, TEST_IOC_MAGIC, 0), 7, "the legacy .ioctl is called");
	ok(legacy_inode == f->f_inode && legacy_minor == 62, "with the file's inode (iminor 62)");
	is_int(lx_dev_ioctl(f, _IO('t', 3), 0), -ENOTTY, "-ENOIOCTLCMD becomes -ENOTTY");
	is_int(lx_dev_read(f, &c, 1, NULL), -EINVAL, "no read operation: -EINVAL");
	ok(lx_dev_poll(f) == DEFAULT_POLLMASK, "no poll operation: always ready");
	is_int(lx_dev_mmap(f, 10, &addr), -ENODEV, "no mmap operation: -ENODEV");
	is_int(lx_dev_close(f), 0, "close");
	misc_deregister(&legacy_misc);
	misc_deregister(&static_misc);
	rtos_host_expect_bugs(true);
	misc_deregister(&static_misc);
	rtos_host_expect_bugs(false);
	ok(strstr(rtos_host_last_bug(), "misc_deregister") != NULL, "deregistering twice warns");
}

static void test_chrdev(void)
{
	struct file *f = NULL;
	int major;

	major = register_chrdev(0, "lx_chr", &legacy_fops);
	is_int(major, 254, "register_chrdev(0) allocates major 254");
	is_int(register_chrdev((unsigned int)major, "lx_chr2", &legacy_fops), -EBUSY, "a taken major: -EBUSY");
	is_int(register_chrdev(0, "lx_chr", &test_fops), -EBUSY, "a taken name: -EBUSY");
	is_int(register_chrdev(60, "lx_fixed", &legacy_fops), 0, "a fixed major: 0");
	is_int(lx_dev_open("/dev/lx_chr", O_RDWR, &f), 0, "open /dev/lx_chr");
	ok(imajor(f->f_inode) == 254 && iminor(f->f_inode) == 0, "major 254, minor 0");
	ok(f->private_data == NULL, "no private_data for a plain char device");
	is_int(lx_dev_ioctl(f, TEST_IOC_MAGIC, 0), 7, "its ioctl");
	is_int(lx_dev_close(f), 0, "close");
	unregister_chrdev((unsigned int)major, "lx_chr");
	unregister_chrdev(60, "lx_fixed");
	is_int(lx_dev_open("/dev/lx_chr", O_RDWR, &f), -ENODEV, "gone after unregister_chrdev");
}

static void body(void)
{
	mmap_alloc = kmalloc(3 * PAGE_SIZE, GFP_KERNEL);
	mmap_area = (unsigned char *)PAGE_ALIGN((unsigned long)mmap_alloc);
	SetPageReserved(virt_to_page(mmap_area));
	test_register();
	test_file_ops();
	test_legacy();
	test_chrdev();
	ClearPageReserved(virt_to_page(mmap_area));
	kfree(mmap_alloc);
}

/* A buffer of the kernel's, outside the user domain the next body runs in. */
static char kernel_buf[8] = "kernel!";
static int kernel_value = 41;

/* kernel_write/kernel_read/lx_dev_ioctl_kernel from a user-domain task: the
 * driver's copy_*_user accept the kernel buffer for that one call only. */
static void user_domain_body(void)
{
	struct file *f;
	char back[8] = { 0 };

	is_int(misc_register(&test_misc), 0, "misc_register (user-domain run)");
	is_int(lx_dev_open("/dev/lx_test", O_RDWR, &f), 0, "open");
	is_int(lx_dev_write(f, (const char __user *)kernel_buf, sizeof(kernel_buf), NULL), -EFAULT,
	       "write() of a kernel buffer on the caller's behalf: -EFAULT");
	is_int(kernel_write(f, kernel_buf, sizeof(kernel_buf), NULL), sizeof(kernel_buf),
	       "kernel_write of the same buffer");
	{
		loff_t pos = 0;

		is_int(kernel_read(f, back, sizeof(back), &pos), sizeof(back), "kernel_read");
		is_str(back, "kernel!", "reads back what kernel_write wrote");
	}
	is_int(lx_dev_ioctl(f, TEST_IOC_ADD, (unsigned long)&kernel_value), -EFAULT,
	       "ioctl with a kernel structure on the caller's behalf: -EFAULT");
	is_int(lx_dev_ioctl_kernel(f, TEST_IOC_ADD, &kernel_value), 0, "lx_dev_ioctl_kernel");
	is_int(kernel_value, 42, "the driver updated the kernel structure");
	ok(segment_eq(get_fs(), USER_DS), "the address limit is back to USER_DS");
	lx_dev_close(f);
	misc_deregister(&test_misc);
}

int main(void)
{
	tap_plan(80);
	ok(lx_test_run(body), "test task ran to completion");
	ok(lx_test_run_in(user_domain_body, 1, NULL), "user-domain task ran to completion");
	return tap_done();
}
