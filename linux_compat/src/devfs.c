/*
 * devfs.c — the device registry (misc devices and char devices by /dev
 * name), the open/close/mmap entry points of linux_compat/devfs.h, and the
 * generic file helpers of linux/fs.h.
 *
 * The registry is a small table changed and searched with interrupts locked
 * for a few string compares; everything that may sleep (allocation, the
 * driver's open/release/mmap) runs outside that lock.
 */
#include <linux/fs.h>
#include <linux/miscdevice.h>
#include <linux/mm.h>
#include <linux/slab.h>
#include <linux/kernel.h>
#include <linux/string.h>
#include <linux/uaccess.h>
#include <linux/semaphore.h>
#include <linux_compat/devfs.h>
#include <linux_compat/irq.h>
#include <sil.h>

#define DEV_PREFIX		"/dev/"
#define CHRDEV_DYNAMIC_FIRST	254U

struct dev_node {
	bool in_use;
	char name[LX_DEV_NAME_MAX + 1];
	__kernel_dev_t devt;
	const struct file_operations *fops;
	struct miscdevice *misc;        /* NULL for register_chrdev devices */
};

/* What lx_dev_open allocates: the file and its inode together. */
struct open_file {
	struct file file;
	struct inode inode;
};

static struct dev_node nodes[LX_NR_DEV_NODES];

/* 2.6.33 ran the legacy .ioctl under the big kernel lock, so such drivers
 * never see two of their ioctls interleave; nor do they here.  Unlike the
 * BKL it stays held if the ioctl sleeps. */
static struct semaphore big_kernel_lock = __SEMAPHORE_INITIALIZER(big_kernel_lock, 1);

/* name without a leading "/dev/". */
static const char *node_name(const char *path)
{
	return strncmp(path, DEV_PREFIX, sizeof(DEV_PREFIX) - 1) == 0 ?
		path + sizeof(DEV_PREFIX) - 1 : path;
}

/* The registered node called name, or NULL.  Interrupts locked. */
static struct dev_node *find_locked(const char *name)
{
	unsigned int i;

	for (i = 0; i < LX_NR_DEV_NODES; i++)
		if (nodes[i].in_use && strcmp(nodes[i].name, name) == 0)
			return &nodes[i];
	return NULL;
}

/* Adds a node; 0, -EBUSY (name or devt taken) or -ENOMEM.  Interrupts locked. */
static int add_locked(const char *name, __kernel_dev_t devt, const struct file_operations *fops,
		      struct miscdevice *misc)
{
	struct dev_node *free_node = NULL;
	unsigned int i;

	for (i = 0; i < LX_NR_DEV_NODES; i++) {
		if (!nodes[i].in_use) {
			if (!free_node)
				free_node = &nodes[i];
		} else if (strcmp(nodes[i].name, name) == 0 || nodes[i].devt == devt) {
			return -EBUSY;
		}
	}
	if (!free_node)
		return -ENOMEM;
	free_node->in_use = true;
	strcpy(free_node->name, name);
	free_node->devt = devt;
	free_node->fops = fops;
	free_node->misc = misc;
	return 0;
}

/* True if a node with that devt exists.  Interrupts locked. */
static bool devt_taken_locked(__kernel_dev_t devt)
{
	unsigned int i;

	for (i = 0; i < LX_NR_DEV_NODES; i++)
		if (nodes[i].in_use && nodes[i].devt == devt)
			return true;
	return false;
}

/* True if some node has that major.  Interrupts locked. */
static bool major_taken_locked(unsigned int major)
{
	unsigned int i;

	for (i = 0; i < LX_NR_DEV_NODES; i++)
		if (nodes[i].in_use && MAJOR(nodes[i].devt) == major)
			return true;
	return false;
}

/* A node name: 1..LX_DEV_NAME_MAX characters; a '/' only between two names
 * (a subdirectory of /dev, as input/event0). */
static bool name_ok(const char *name)
{
	size_t len;

	if (!name)
		return false;
	len = strlen(name);
	return len > 0 && len <= LX_DEV_NAME_MAX && name[0] != '/' && name[len - 1] != '/' &&
	       !strstr(name, "//");
}

int misc_register(struct miscdevice *misc)
{
	bool dynamic;
	int minor, err;
	SIL_PRE_LOC;

	lx_might_sleep("misc_register()", __FILE__, __LINE__);
	if (!misc || !misc->fops || !name_ok(misc->name))
		return -EINVAL;
	dynamic = misc->minor == MISC_DYNAMIC_MINOR;
	if (!dynamic && (misc->minor < 0 || misc->minor > 255))
		return -EINVAL;

	SIL_LOC_INT();
	minor = misc->minor;
	if (dynamic) {
		for (minor = MISC_DYNAMIC_MINORS - 1; minor >= 0; minor--)
			if (!devt_taken_locked(MKDEV(MISC_MAJOR, minor)))
				break;
	}
	if (minor < 0)
		err = -EBUSY;
	else
		err = add_locked(misc->name, MKDEV(MISC_MAJOR, minor), misc->fops, misc);
	if (!err)
		misc->minor = minor;
	SIL_UNL_INT();

	if (err == -ENOMEM)
		pr_err("misc_register %s: all %d registry slots in use (raise LX_NR_DEV_NODES)\n",
		       misc->name, LX_NR_DEV_NODES);
	return err;
}

void misc_deregister(struct miscdevice *misc)
{
	bool found = false;
	unsigned int i;
	SIL_PRE_LOC;

	lx_might_sleep("misc_deregister()", __FILE__, __LINE__);
	if (!misc)
		return;
	SIL_LOC_INT();
	for (i = 0; i < LX_NR_DEV_NODES; i++) {
		if (nodes[i].in_use && nodes[i].misc == misc) {
			nodes[i].in_use = false;
			found = true;
			if (MINOR(nodes[i].devt) < MISC_DYNAMIC_MINORS && misc->minor >= 0 &&
			    misc->minor < MISC_DYNAMIC_MINORS)
				misc->minor = MISC_DYNAMIC_MINOR;
			break;
		}
	}
	SIL_UNL_INT();
	WARN(!found, "misc_deregister(%s): not registered", misc->name ? misc->name : "?");
}

int register_chrdev(unsigned int major, const char *name, const struct file_operations *fops)
{
	unsigned int m = major;
	int err = 0;
	SIL_PRE_LOC;

	lx_might_sleep("register_chrdev()", __FILE__, __LINE__);
	if (!fops || !name_ok(name) || major > 511 || major == MISC_MAJOR)
		return -EINVAL;
	SIL_LOC_INT();
	if (major == 0) {
		for (m = CHRDEV_DYNAMIC_FIRST; m > 0; m--)
			if (m != MISC_MAJOR && !major_taken_locked(m))
				break;
		if (m == 0)
			err = -EBUSY;
	} else if (major_taken_locked(major)) {
		err = -EBUSY;
	}
	if (!err)
		err = add_locked(name, MKDEV(m, 0), fops, NULL);
	SIL_UNL_INT();
	if (err)
		return err;
	return major == 0 ? (int)m : 0;
}

void unregister_chrdev(unsigned int major, const char *name)
{
	bool found = false;
	unsigned int i;
	SIL_PRE_LOC;

	lx_might_sleep("unregister_chrdev()", __FILE__, __LINE__);
	SIL_LOC_INT();
	for (i = 0; i < LX_NR_DEV_NODES; i++) {
		if (nodes[i].in_use && !nodes[i].misc && MAJOR(nodes[i].devt) == major &&
		    (!name || strcmp(nodes[i].name, name) == 0)) {
			nodes[i].in_use = false;
			found = true;
			break;
		}
	}
	SIL_UNL_INT();
	WARN(!found, "unregister_chrdev(%u, %s): not registered", major, name ? name : "?");
}

int lx_dev_register(const char *name, __kernel_dev_t devt, const struct file_operations *fops)
{
	int err;
	SIL_PRE_LOC;

	if (!fops || !name_ok(name) || MAJOR(devt) == MISC_MAJOR)
		return -EINVAL;
	SIL_LOC_INT();
	err = add_locked(name, devt, fops, NULL);
	SIL_UNL_INT();
	return err;
}

void lx_dev_unregister(__kernel_dev_t devt)
{
	unsigned int i;
	SIL_PRE_LOC;

	SIL_LOC_INT();
	for (i = 0; i < LX_NR_DEV_NODES; i++)
		if (nodes[i].in_use && !nodes[i].misc && nodes[i].devt == devt)
			nodes[i].in_use = false;
	SIL_UNL_INT();
}

bool lx_dev_major_taken(unsigned int major)
{
	return major_taken_locked(major);
}

bool lx_dev_exists(const char *path)
{
	bool found;
	SIL_PRE_LOC;

	if (!path)
		return false;
	SIL_LOC_INT();
	found = find_locked(node_name(path)) != NULL;
	SIL_UNL_INT();
	return found;
}

int lx_dev_open(const char *path, int flags, struct file **filep)
{
	struct dev_node node;
	struct dev_node *found;
	struct open_file *of;
	unsigned int mode;
	int err;
	SIL_PRE_LOC;

	lx_might_sleep("lx_dev_open()", __FILE__, __LINE__);
	if (!filep)
		return -EINVAL;
	*filep = NULL;
	if (!path)
		return -EINVAL;
	switch (flags & O_ACCMODE) {
	case O_RDONLY:
		mode = (__force unsigned int)FMODE_READ;
		break;
	case O_WRONLY:
		mode = (__force unsigned int)FMODE_WRITE;
		break;
	case O_RDWR:
		mode = (__force unsigned int)(FMODE_READ | FMODE_WRITE);
		break;
	default:
		return -EINVAL;
	}

	SIL_LOC_INT();
	found = find_locked(node_name(path));
	if (found)
		node = *found;
	SIL_UNL_INT();
	if (!found)
		return -ENODEV;

	of = kzalloc(sizeof(*of), GFP_KERNEL);
	if (!of)
		return -ENOMEM;
	of->inode.i_mode = S_IFCHR | 0666;
	of->inode.i_rdev = node.devt;
	of->file.f_op = node.fops;
	of->file.f_flags = (unsigned int)flags;
	of->file.f_mode = (__force fmode_t)(mode | (__force unsigned int)(FMODE_LSEEK | FMODE_PREAD |
									     FMODE_PWRITE));
	of->file.f_inode = &of->inode;
	of->file.private_data = node.misc;
	if (node.fops->open) {
		err = node.fops->open(&of->inode, &of->file);
		if (err) {
			kfree(of);
			return err;
		}
	}
	*filep = &of->file;
	return 0;
}

int lx_dev_close(struct file *file)
{
	struct open_file *of;

	lx_might_sleep("lx_dev_close()", __FILE__, __LINE__);
	if (!file)
		return -EBADF;
	of = container_of(file, struct open_file, file);
	if (file->f_op->flush)
		(void)file->f_op->flush(file, NULL);
	if (file->f_op->release)
		(void)file->f_op->release(file->f_inode, file);
	kfree(of);
	return 0;
}

long lx_dev_legacy_ioctl(struct file *file, unsigned int cmd, unsigned long arg)
{
	long ret;

	down(&big_kernel_lock);
	ret = file->f_op->ioctl(file->f_inode, file, cmd, arg);
	up(&big_kernel_lock);
	return ret;
}

int lx_dev_mmap(struct file *file, size_t length, void **addr)
{
	struct vm_area_struct vma;
	int err;

	lx_might_sleep("lx_dev_mmap()", __FILE__, __LINE__);
	if (!file)
		return -EBADF;
	if (!addr)
		return -EINVAL;
	*addr = NULL;
	if (length == 0 || length > (size_t)(~0UL - LX_MMAP_VM_START - PAGE_SIZE))
		return -EINVAL;
	if (!file->f_op->mmap)
		return -ENODEV;
	if (!((__force unsigned int)file->f_mode & (__force unsigned int)FMODE_READ))
		return -EACCES;

	memset(&vma, 0, sizeof(vma));
	vma.vm_start = LX_MMAP_VM_START;
	vma.vm_end = LX_MMAP_VM_START + PAGE_ALIGN((unsigned long)length);
	vma.vm_pgoff = 0;
	vma.vm_page_prot = PAGE_SHARED;
	vma.vm_flags = VM_READ | VM_SHARED | VM_MAYREAD | VM_MAYSHARE;
	if ((__force unsigned int)file->f_mode & (__force unsigned int)FMODE_WRITE)
		vma.vm_flags |= VM_WRITE | VM_MAYWRITE;
	vma.vm_file = file;

	err = file->f_op->mmap(file, &vma);
	if (err)
		return err;
	if (vma.lx_mapped < length) {
		pr_err("mmap: the driver mapped %lu of %lu bytes\n",
		       vma.lx_mapped, (unsigned long)length);
		return -ENXIO;
	}
	*addr = (void *)(uintptr_t)vma.lx_kaddr;
	return 0;
}

loff_t no_llseek(struct file *file, loff_t offset, int whence)
{
	return -ESPIPE;
}

loff_t noop_llseek(struct file *file, loff_t offset, int whence)
{
	return file->f_pos;
}

loff_t default_llseek(struct file *file, loff_t offset, int whence)
{
	loff_t pos;

	switch (whence) {
	case SEEK_SET:
		pos = offset;
		break;
	case SEEK_CUR:
		pos = file->f_pos + offset;
		break;
	case SEEK_END:
		pos = file->f_inode ? file->f_inode->i_size + offset : -1;
		break;
	default:
		return -EINVAL;
	}
	if (pos < 0)
		return -EINVAL;
	file->f_pos = pos;
	return pos;
}

int nonseekable_open(struct inode *inode, struct file *file)
{
	file->f_mode = (__force fmode_t)((__force unsigned int)file->f_mode &
		~(__force unsigned int)(FMODE_LSEEK | FMODE_PREAD | FMODE_PWRITE));
	return 0;
}

int stream_open(struct inode *inode, struct file *file)
{
	return nonseekable_open(inode, file);
}

ssize_t simple_read_from_buffer(void __user *to, size_t count, loff_t *ppos,
				const void *from, size_t available)
{
	loff_t pos = *ppos;
	size_t n, left;

	if (pos < 0)
		return -EINVAL;
	if ((size_t)pos >= available || !count)
		return 0;
	n = available - (size_t)pos;
	if (n > count)
		n = count;
	left = copy_to_user(to, (const char *)from + pos, n);
	if (left == n)
		return -EFAULT;
	n -= left;
	*ppos = pos + (loff_t)n;
	return (ssize_t)n;
}

ssize_t simple_write_to_buffer(void *to, size_t available, loff_t *ppos,
			       const void __user *from, size_t count)
{
	loff_t pos = *ppos;
	size_t n, left;

	if (pos < 0)
		return -EINVAL;
	if ((size_t)pos >= available || !count)
		return 0;
	n = available - (size_t)pos;
	if (n > count)
		n = count;
	left = copy_from_user((char *)to + pos, from, n);
	if (left == n)
		return -EFAULT;
	n -= left;
	*ppos = pos + (loff_t)n;
	return (ssize_t)n;
}

void lx_devfs_boot(void)
{
	memset(nodes, 0, sizeof(nodes));
	sema_init(&big_kernel_lock, 1);
	lx_cdev_boot();
}
