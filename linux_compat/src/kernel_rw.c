/*
 * kernel_rw.c — file operations on kernel buffers: kernel_write, kernel_read
 * (linux/fs.h) and lx_dev_ioctl_kernel (linux_compat/devfs.h).  Each runs the
 * driver's operation with the calling task's address limit set to KERNEL_DS,
 * so the driver's copy_*_user accept the kernel buffer (on HRP2 a service
 * routine's stack is not in the caller's domain), and restores it after.
 */
#include <linux/fs.h>
#include <linux/uaccess.h>
#include <linux_compat/devfs.h>

ssize_t kernel_write(struct file *file, const void *buf, size_t count, loff_t *pos)
{
	mm_segment_t old_fs = get_fs();
	ssize_t ret;

	set_fs(KERNEL_DS);
	ret = lx_dev_write(file, (__force const char __user *)buf, count, pos);
	set_fs(old_fs);
	return ret;
}

ssize_t kernel_read(struct file *file, void *buf, size_t count, loff_t *pos)
{
	mm_segment_t old_fs = get_fs();
	ssize_t ret;

	set_fs(KERNEL_DS);
	ret = lx_dev_read(file, (__force char __user *)buf, count, pos);
	set_fs(old_fs);
	return ret;
}

long lx_dev_ioctl_kernel(struct file *file, unsigned int cmd, void *arg)
{
	mm_segment_t old_fs = get_fs();
	long ret;

	set_fs(KERNEL_DS);
	ret = lx_dev_ioctl(file, cmd, (unsigned long)arg);
	set_fs(old_fs);
	return ret;
}
