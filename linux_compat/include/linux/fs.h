/*
 * linux/fs.h — struct file, struct inode, file_operations, char devices.
 *
 * There is no VFS: device files are opened through ev3lx's registry
 * (linux_compat/devfs.h), which builds the struct file and struct inode a
 * driver's operations receive and calls them with Linux's conventions.
 * file_operations has both ioctl entry points: .unlocked_ioctl (modern) and
 * the legacy .ioctl(inode, file, cmd, arg) of 2.6.33, which the registry
 * calls (with the file's inode, under a big kernel lock as 2.6.33 did) when
 * there is no .unlocked_ioctl.
 *
 * register_chrdev (linux_compat/src/devfs.c) registers the device in the
 * registry as /dev/<name> with minor 0; major 0 asks for a free major
 * (254 downwards), returned on success.
 */
#ifndef _LINUX_FS_H
#define _LINUX_FS_H

#include <linux/types.h>
#include <linux/compiler.h>
#include <linux/errno.h>
#include <linux/limits.h>
#include <linux/limits.h>
#include <linux/kdev_t.h>
#include <linux/fcntl.h>
#include <linux/ioctl.h>     /* as in Linux: drivers reach _IOWR & co. through fs.h */
#include <asm/page.h>

struct module;
struct vm_area_struct;
struct poll_table_struct;

typedef unsigned int __poll_t;
typedef void *fl_owner_t;

#ifndef SEEK_SET
#define SEEK_SET	0
#define SEEK_CUR	1
#define SEEK_END	2
#endif
#define SEEK_MAX	SEEK_END

/* The largest count read/write pass to a driver (Linux's MAX_RW_COUNT). */
#define MAX_RW_COUNT	((size_t)(INT_MAX & PAGE_MASK))

#define FMODE_READ		((__force fmode_t)0x1)
#define FMODE_WRITE		((__force fmode_t)0x2)
#define FMODE_LSEEK		((__force fmode_t)0x4)
#define FMODE_PREAD		((__force fmode_t)0x8)
#define FMODE_PWRITE		((__force fmode_t)0x10)
#define FMODE_EXEC		((__force fmode_t)0x20)
#define FMODE_NONOTIFY		((__force fmode_t)0x4000000)

#define S_IFMT		00170000
#define S_IFCHR		0020000
#ifndef S_ISCHR
#define S_ISCHR(m)	(((m) & S_IFMT) == S_IFCHR)
#endif

struct inode {
	umode_t i_mode;
	__kernel_dev_t i_rdev;
	loff_t i_size;
	unsigned long i_ino;
	void *i_private;
};

struct file {
	const struct file_operations *f_op;
	void *private_data;
	unsigned int f_flags;       /* O_* flags given to open */
	fmode_t f_mode;             /* FMODE_* */
	loff_t f_pos;
	struct inode *f_inode;
};

struct file_operations {
	struct module *owner;
	loff_t (*llseek)(struct file *file, loff_t offset, int whence);
	ssize_t (*read)(struct file *file, char __user *buf, size_t count, loff_t *ppos);
	ssize_t (*write)(struct file *file, const char __user *buf, size_t count, loff_t *ppos);
	__poll_t (*poll)(struct file *file, struct poll_table_struct *wait);
	/* 2.6.33's ioctl, run under the big kernel lock (removed in 2.6.36). */
	int (*ioctl)(struct inode *inode, struct file *file, unsigned int cmd, unsigned long arg);
	long (*unlocked_ioctl)(struct file *file, unsigned int cmd, unsigned long arg);
	long (*compat_ioctl)(struct file *file, unsigned int cmd, unsigned long arg);
	int (*mmap)(struct file *file, struct vm_area_struct *vma);
	int (*open)(struct inode *inode, struct file *file);
	int (*flush)(struct file *file, fl_owner_t id);
	int (*release)(struct inode *inode, struct file *file);
	int (*fsync)(struct file *file, loff_t start, loff_t end, int datasync);
	int (*fasync)(int fd, struct file *file, int on);
};

static inline unsigned int iminor(const struct inode *inode)
{
	return MINOR(inode->i_rdev);
}

static inline unsigned int imajor(const struct inode *inode)
{
	return MAJOR(inode->i_rdev);
}

static inline struct inode *file_inode(const struct file *file)
{
	return file->f_inode;
}

/* llseek for devices that cannot seek: -ESPIPE. */
loff_t no_llseek(struct file *file, loff_t offset, int whence);
/* llseek that accepts anything and moves nothing: returns the current position. */
loff_t noop_llseek(struct file *file, loff_t offset, int whence);
/* SEEK_SET/SEEK_CUR (and SEEK_END from the inode's i_size) on f_pos; -EINVAL if negative. */
loff_t default_llseek(struct file *file, loff_t offset, int whence);
#define generic_file_llseek	default_llseek

/* Marks the file unseekable (no llseek, pread, pwrite); returns 0. */
int nonseekable_open(struct inode *inode, struct file *file);
/* Marks the file a stream (no position); returns 0. */
int stream_open(struct inode *inode, struct file *file);

/* Copies from buffer [from, from + available) at *ppos to user memory and
 * advances *ppos: bytes copied, 0 at the end, -EFAULT if nothing could be copied, -EINVAL if *ppos < 0. */
ssize_t simple_read_from_buffer(void __user *to, size_t count, loff_t *ppos,
				const void *from, size_t available);
/* The reverse: user memory into [to, to + available) at *ppos. */
ssize_t simple_write_to_buffer(void *to, size_t available, loff_t *ppos,
			       const void __user *from, size_t count);

/* The file's write() with a kernel buffer (the address limit KERNEL_DS for the
 * call): bytes written or -errno; pos NULL: the file position. */
ssize_t kernel_write(struct file *file, const void *buf, size_t count, loff_t *pos);
/* The file's read() into a kernel buffer, likewise. */
ssize_t kernel_read(struct file *file, void *buf, size_t count, loff_t *pos);

/* Registers a char device as /dev/<name>, minor 0 (see above): the major
 * (major 0) or 0, -EINVAL, -EBUSY (major or name taken), -ENOMEM (registry full).  Process context. */
int register_chrdev(unsigned int major, const char *name, const struct file_operations *fops);
/* Removes a register_chrdev registration; warns if there is none. */
void unregister_chrdev(unsigned int major, const char *name);

/* Reserves the count device numbers from first under name (linux/cdev.h
 * names the nodes after it): 0, -EINVAL, -EBUSY (overlap) or -ENOMEM. */
int register_chrdev_region(__kernel_dev_t first, unsigned int count, const char *name);
/* As register_chrdev_region on a free major (254 downwards); *dev is the first number. */
int alloc_chrdev_region(__kernel_dev_t *dev, unsigned int baseminor, unsigned int count,
			const char *name);
/* Releases a region; warns if there is none at first. */
void unregister_chrdev_region(__kernel_dev_t first, unsigned int count);

#endif /* _LINUX_FS_H */
