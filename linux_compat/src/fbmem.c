/*
 * fbmem.c — frame buffer registration and the /dev/fbN file operations
 * (linux/fb.h states the contract).  The table of registered frame buffers
 * changes under one mutex; each fb_info's own lock serialises its ioctls,
 * opens and releases, as Linux's fbmem does.
 */
#include <linux/fb.h>
#include <linux/kdev_t.h>
#include <linux/kernel.h>
#include <linux/mm.h>
#include <linux/mutex.h>
#include <linux/slab.h>
#include <linux/string.h>
#include <linux/uaccess.h>
#include <linux_compat/devfs.h>
#include <linux_compat/fbdev.h>
#include <linux_compat/irq.h>

#define FB_MAJOR	29

static DEFINE_MUTEX(registration_lock);
static struct fb_info *registered_fb[FB_MAX];

struct fb_info *framebuffer_alloc(size_t size, struct device *dev)
{
	struct fb_info *info;

	might_sleep();
	info = kzalloc(sizeof(*info) + ALIGN(size, sizeof(long)), GFP_KERNEL);
	if (!info)
		return NULL;
	if (size)
		info->par = info + 1;
	info->device = dev;
	info->node = -1;
	mutex_init(&info->lock);
	return info;
}

void framebuffer_release(struct fb_info *info)
{
	kfree(info);
}

/* The fb_info of an open /dev/fbN. */
static struct fb_info *file_fb_info(struct file *file)
{
	return file ? file->private_data : NULL;
}

static int fb_open(struct inode *inode, struct file *file)
{
	unsigned int minor = iminor(inode);
	struct fb_info *info;
	int res = 0;

	if (minor >= FB_MAX)
		return -ENODEV;
	mutex_lock(&registration_lock);
	info = registered_fb[minor];
	mutex_unlock(&registration_lock);
	if (!info)
		return -ENODEV;
	/* no module reference: as for every device in the registry, module lifetimes are the
	 * module list's (a hack holding its own driver's device open could never unload) */
	mutex_lock(&info->lock);
	file->private_data = info;
	if (info->fbops->fb_open)
		res = info->fbops->fb_open(info, 1);
	if (!res)
		info->lx_open_count++;
	mutex_unlock(&info->lock);
	return res;
}

static int fb_release(struct inode *inode, struct file *file)
{
	struct fb_info *info = file_fb_info(file);

	mutex_lock(&info->lock);
	if (info->fbops->fb_release)
		info->fbops->fb_release(info, 1);
	info->lx_open_count--;
	mutex_unlock(&info->lock);
	return 0;
}

ssize_t fb_sys_read(struct fb_info *info, char __user *buf, size_t count, loff_t *ppos)
{
	unsigned long total = info->screen_size ? info->screen_size : info->fix.smem_len;
	unsigned long p = (unsigned long)*ppos;

	if (*ppos < 0 || p >= total)
		return 0;
	if (count > total - p)
		count = total - p;
	if (copy_to_user(buf, info->screen_buffer + p, count))
		return -EFAULT;
	*ppos += count;
	return (ssize_t)count;
}

ssize_t fb_sys_write(struct fb_info *info, const char __user *buf, size_t count, loff_t *ppos)
{
	unsigned long total = info->screen_size ? info->screen_size : info->fix.smem_len;
	unsigned long p = (unsigned long)*ppos;
	int err = 0;
	unsigned long left;

	if (*ppos < 0 || p > total)
		return -EFBIG;
	if (count > total) {
		err = -EFBIG;
		count = total;
	}
	if (count + p > total) {
		if (!err)
			err = -ENOSPC;
		count = total - p;
	}
	if (!count)
		return err;
	left = copy_from_user(info->screen_buffer + p, buf, count);
	if (left == count)
		return -EFAULT;
	count -= left;
	*ppos += count;
	return (ssize_t)count;
}

static ssize_t fb_read(struct file *file, char __user *buf, size_t count, loff_t *ppos)
{
	struct fb_info *info = file_fb_info(file);

	if (info->fbops->fb_read)
		return info->fbops->fb_read(info, buf, count, ppos);
	return fb_sys_read(info, buf, count, ppos);
}

static ssize_t fb_write(struct file *file, const char __user *buf, size_t count, loff_t *ppos)
{
	struct fb_info *info = file_fb_info(file);

	if (info->fbops->fb_write)
		return info->fbops->fb_write(info, buf, count, ppos);
	return fb_sys_write(info, buf, count, ppos);
}

/* FBIOPUT_VSCREENINFO: the driver checks and applies var.  info->lock held. */
static int fb_set_var(struct fb_info *info, struct fb_var_screeninfo *var)
{
	int ret;

	if (!info->fbops->fb_check_var) {
		*var = info->var;
		return 0;
	}
	ret = info->fbops->fb_check_var(var, info);
	if (ret)
		return ret;
	info->var = *var;
	return info->fbops->fb_set_par ? info->fbops->fb_set_par(info) : 0;
}

static long fb_ioctl(struct file *file, unsigned int cmd, unsigned long arg)
{
	struct fb_info *info = file_fb_info(file);
	void __user *argp = (void __user *)arg;
	struct fb_var_screeninfo var;
	long ret;

	mutex_lock(&info->lock);
	switch (cmd) {
	case FBIOGET_VSCREENINFO:
		ret = copy_to_user(argp, &info->var, sizeof(var)) ? -EFAULT : 0;
		break;
	case FBIOPUT_VSCREENINFO:
		if (copy_from_user(&var, argp, sizeof(var))) {
			ret = -EFAULT;
			break;
		}
		ret = fb_set_var(info, &var);
		if (!ret && copy_to_user(argp, &var, sizeof(var)))
			ret = -EFAULT;
		break;
	case FBIOGET_FSCREENINFO:
		ret = copy_to_user(argp, &info->fix, sizeof(info->fix)) ? -EFAULT : 0;
		break;
	case FBIOBLANK:
		ret = info->fbops->fb_blank ? info->fbops->fb_blank((int)arg, info) : -EINVAL;
		break;
	default:
		ret = info->fbops->fb_ioctl ? info->fbops->fb_ioctl(info, cmd, arg) : -ENOTTY;
		break;
	}
	mutex_unlock(&info->lock);
	return ret;
}

static int fb_mmap(struct file *file, struct vm_area_struct *vma)
{
	struct fb_info *info = file_fb_info(file);
	unsigned long len = vma->vm_end - vma->vm_start;
	unsigned long off = vma->vm_pgoff << PAGE_SHIFT;

	if (info->fbops->fb_mmap)
		return info->fbops->fb_mmap(info, vma);
	if (info->fbdefio)
		return fb_deferred_io_mmap(info, vma);
	if (!info->screen_buffer || off > PAGE_ALIGN(info->fix.smem_len) ||
	    len > PAGE_ALIGN(info->fix.smem_len) - off)
		return -EINVAL;
	return remap_pfn_range(vma, vma->vm_start, virt_to_pfn(info->screen_buffer + off), len,
			       vma->vm_page_prot);
}

static const struct file_operations fb_fops = {
	.owner = THIS_MODULE,
	.read = fb_read,
	.write = fb_write,
	.unlocked_ioctl = fb_ioctl,
	.mmap = fb_mmap,
	.open = fb_open,
	.release = fb_release,
	.llseek = default_llseek,
};

int register_framebuffer(struct fb_info *fb_info)
{
	char name[8];
	int i, err;

	might_sleep();
	if (!fb_info || !fb_info->fbops)
		return -EINVAL;
	mutex_lock(&registration_lock);
	for (i = 0; i < FB_MAX; i++)
		if (registered_fb[i] == fb_info) {
			mutex_unlock(&registration_lock);
			return -EBUSY;
		}
	for (i = 0; i < FB_MAX && registered_fb[i]; i++)
		;
	if (i == FB_MAX) {
		mutex_unlock(&registration_lock);
		return -ENXIO;
	}
	snprintf(name, sizeof(name), "fb%d", i);
	err = lx_dev_register(name, MKDEV(FB_MAJOR, i), &fb_fops);
	if (!err) {
		fb_info->node = i;
		registered_fb[i] = fb_info;
	}
	mutex_unlock(&registration_lock);
	return err;
}

void unregister_framebuffer(struct fb_info *fb_info)
{
	might_sleep();
	if (!fb_info || fb_info->node < 0 || fb_info->node >= FB_MAX)
		return;
	mutex_lock(&registration_lock);
	if (registered_fb[fb_info->node] == fb_info) {
		lx_dev_unregister(MKDEV(FB_MAJOR, fb_info->node));
		registered_fb[fb_info->node] = NULL;
		fb_info->node = -1;
	}
	mutex_unlock(&registration_lock);
}

/* true if file is an open /dev/fbN. */
bool lx_fb_file(struct file *file)
{
	return file && file->f_op == &fb_fops;
}

void lx_fb_boot(void)
{
	mutex_init(&registration_lock);
	memset(registered_fb, 0, sizeof(registered_fb));
}
