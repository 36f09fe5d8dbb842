/*
 * linux_compat/devfs.h — the device registry: how hacks (and tests) open a
 * Linux device by its /dev name and call its file operations.
 *
 * misc_register and register_chrdev add devices by name; lx_dev_open builds
 * the struct file / struct inode pair a driver expects and runs its .open.
 * After that every call on the struct file is an inline check plus one
 * indirect call into the driver - no name lookups - so a service call can
 * reach a driver's write() in a few dozen instructions.  Errors follow Linux:
 * -ENODEV (no device of that name), -EBADF (NULL file, or not opened for
 * reading/writing), -EINVAL (no such operation, bad arguments), -ENOTTY (no
 * ioctl), -ESPIPE (no llseek), driver errors passed through.
 *
 * A struct file stays valid until lx_dev_close, even if the driver
 * deregisters meanwhile (as in Linux, where open files keep their f_op).
 * Buffers passed to read/write/ioctl are user memory: the driver's
 * copy_*_user checks them against the calling task's domain.
 * open/close/mmap are process context (they may sleep); read/write/ioctl/
 * poll are whatever the driver's operation allows (process context).
 */
#ifndef _LINUX_COMPAT_DEVFS_H
#define _LINUX_COMPAT_DEVFS_H

#include <linux/types.h>
#include <linux/compiler.h>
#include <linux/errno.h>
#include <linux/fs.h>
#include <linux/poll.h>

/* Devices the registry can hold (misc devices and char devices together). */
#ifndef LX_NR_DEV_NODES
#define LX_NR_DEV_NODES		16
#endif
/* Longest device name, without "/dev/" and the NUL. */
#define LX_DEV_NAME_MAX		31

/* Where lx_dev_mmap's vm_area_struct starts (any page-aligned value would do:
 * the caller gets the kernel address of the mapped memory, not this). */
#define LX_MMAP_VM_START	0x40000000UL

/* Opens /dev/<name> ("/dev/" optional) with O_RDONLY/O_WRONLY/O_RDWR (plus
 * O_NONBLOCK...): 0 and *file, or -ENODEV, -EINVAL, -ENOMEM, or the driver's
 * .open error.  Process context. */
int lx_dev_open(const char *path, int flags, struct file **file);

/* Runs the driver's .release and frees the file: 0, or -EBADF for NULL.  Process context. */
int lx_dev_close(struct file *file);

/* True if a device of that name is registered. */
bool lx_dev_exists(const char *path);

/* For cdev_add: registers /dev/<name> as number devt with fops; 0, -EINVAL,
 * -EBUSY (name or number taken) or -ENOMEM.  Process context. */
int lx_dev_register(const char *name, __kernel_dev_t devt, const struct file_operations *fops);
/* Removes the registry's node of number devt (not a misc device), if any. */
void lx_dev_unregister(__kernel_dev_t devt);
/* True if a registered device has that major; called with interrupts locked. */
bool lx_dev_major_taken(unsigned int major);
/* Forgets the device number regions (cdev.c; at boot, with the registry). */
void lx_cdev_boot(void);

/* Calls the legacy .ioctl with the file's inode under the big kernel lock (out of line). */
long lx_dev_legacy_ioctl(struct file *file, unsigned int cmd, unsigned long arg);

/*
 * The checks read() and write() share: the file open for mode, the driver
 * has the operation, a valid position (pos NULL: the file's f_pos) and the
 * count clamped to MAX_RW_COUNT.  0, or -EBADF / -EINVAL.
 */
static inline int lx_dev_rw_check(struct file *file, unsigned int mode, bool has_op,
				  loff_t **pos, size_t *count)
{
	if (unlikely(!file || !((__force unsigned int)file->f_mode & mode)))
		return -EBADF;
	if (unlikely(!has_op))
		return -EINVAL;
	if (!*pos)
		*pos = &file->f_pos;
	if (unlikely(**pos < 0))
		return -EINVAL;
	if (unlikely(*count > MAX_RW_COUNT))
		*count = MAX_RW_COUNT;
	return 0;
}

/* The driver's read(): bytes read, 0 at end of file, or -errno.  pos NULL: the file's f_pos. */
static inline ssize_t lx_dev_read(struct file *file, char __user *buf, size_t count, loff_t *pos)
{
	int ret = lx_dev_rw_check(file, (__force unsigned int)FMODE_READ,
				  file && file->f_op->read, &pos, &count);

	return ret ? ret : file->f_op->read(file, buf, count, pos);
}

/* The driver's write(): bytes written (0 is not an error), or -errno.  pos NULL: f_pos. */
static inline ssize_t lx_dev_write(struct file *file, const char __user *buf, size_t count,
				   loff_t *pos)
{
	int ret = lx_dev_rw_check(file, (__force unsigned int)FMODE_WRITE,
				  file && file->f_op->write, &pos, &count);

	return ret ? ret : file->f_op->write(file, buf, count, pos);
}

/* The driver's .unlocked_ioctl, else its legacy .ioctl (with the file's
 * inode, under the big kernel lock); -ENOTTY if it has neither or answers
 * -ENOIOCTLCMD. */
static inline long lx_dev_ioctl(struct file *file, unsigned int cmd, unsigned long arg)
{
	long ret;

	if (unlikely(!file))
		return -EBADF;
	if (likely(file->f_op->unlocked_ioctl))
		ret = file->f_op->unlocked_ioctl(file, cmd, arg);
	else if (file->f_op->ioctl)
		ret = lx_dev_legacy_ioctl(file, cmd, arg);
	else
		return -ENOTTY;
	return ret == -ENOIOCTLCMD ? -ENOTTY : ret;
}

/* The driver's llseek: the new position or -errno (-ESPIPE without llseek). */
static inline loff_t lx_dev_llseek(struct file *file, loff_t offset, int whence)
{
	if (unlikely(!file))
		return -EBADF;
	if (!file->f_op->llseek || !((__force unsigned int)file->f_mode & (__force unsigned int)FMODE_LSEEK))
		return -ESPIPE;
	return file->f_op->llseek(file, offset, whence);
}

/* What the device is ready for now (the driver's .poll with no table;
 * DEFAULT_POLLMASK without .poll; EPOLLNVAL for a NULL file). */
static inline __poll_t lx_dev_poll(struct file *file)
{
	if (unlikely(!file))
		return EPOLLNVAL;
	if (!file->f_op->poll)
		return DEFAULT_POLLMASK;
	return file->f_op->poll(file, NULL);
}

/* Maps length bytes of the device (offset 0) through the driver's .mmap:
 * 0 and *addr = the kernel address of the memory the driver mapped with
 * remap_pfn_range, or -EBADF, -EACCES (not open for reading), -EINVAL
 * (length 0), -ENODEV (no .mmap), -ENXIO (the driver mapped less than
 * length), or the driver's error.  Process context. */
int lx_dev_mmap(struct file *file, size_t length, void **addr);

/* lx_dev_ioctl whose argument points to a kernel buffer (KERNEL_DS for the
 * call): how a hack hands the driver a structure of its own. */
long lx_dev_ioctl_kernel(struct file *file, unsigned int cmd, void *arg);

#endif /* _LINUX_COMPAT_DEVFS_H */
