/*
 * cdev.c — device number regions and struct cdev over the device registry
 * (linux/cdev.h states the naming).  Regions live in a small table changed
 * with interrupts locked; registration of the nodes is devfs.c's.
 */
#include <linux/cdev.h>
#include <linux/fs.h>
#include <linux/kernel.h>
#include <linux/miscdevice.h>
#include <linux/slab.h>
#include <linux/string.h>
#include <linux_compat/context.h>
#include <linux_compat/devfs.h>
#include <sil.h>

#ifndef LX_NR_CHRDEV_REGIONS
#define LX_NR_CHRDEV_REGIONS	8
#endif
#define REGION_DYNAMIC_FIRST	254U

struct chrdev_region {
	__kernel_dev_t first;
	unsigned int count;     /* 0: slot free */
	char name[LX_DEV_NAME_MAX + 1];
};

static struct chrdev_region regions[LX_NR_CHRDEV_REGIONS];

/* Forgets every region (boot). */
void lx_cdev_boot(void)
{
	memset(regions, 0, sizeof(regions));
}

/* True if [first, first + count) overlaps a region.  Interrupts locked. */
static bool overlaps_locked(__kernel_dev_t first, unsigned int count)
{
	unsigned int i;

	for (i = 0; i < LX_NR_CHRDEV_REGIONS; i++)
		if (regions[i].count && first < regions[i].first + regions[i].count &&
		    regions[i].first < first + count)
			return true;
	return false;
}

/* True if a region or a registered device uses major.  Interrupts locked. */
static bool major_used_locked(unsigned int major)
{
	unsigned int i;

	for (i = 0; i < LX_NR_CHRDEV_REGIONS; i++)
		if (regions[i].count && MAJOR(regions[i].first) == major)
			return true;
	return false;
}

/* Records a region; 0, -EBUSY or -ENOMEM.  Interrupts locked. */
static int add_region_locked(__kernel_dev_t first, unsigned int count, const char *name)
{
	unsigned int i;

	if (overlaps_locked(first, count))
		return -EBUSY;
	for (i = 0; i < LX_NR_CHRDEV_REGIONS; i++) {
		if (regions[i].count == 0) {
			regions[i].first = first;
			regions[i].count = count;
			strscpy(regions[i].name, name, sizeof(regions[i].name));
			return 0;
		}
	}
	return -ENOMEM;
}

static bool region_args_ok(unsigned int minor, unsigned int count, const char *name)
{
	return count > 0 && count <= MINORMASK + 1 - minor && name != NULL && name[0] != '\0' &&
	       strlen(name) <= LX_DEV_NAME_MAX - 4 && strchr(name, '/') == NULL;
}

int register_chrdev_region(__kernel_dev_t first, unsigned int count, const char *name)
{
	int err;
	SIL_PRE_LOC;

	lx_might_sleep("register_chrdev_region()", __FILE__, __LINE__);
	if (!region_args_ok(MINOR(first), count, name) || MAJOR(first) == 0 || MAJOR(first) > 511)
		return -EINVAL;
	SIL_LOC_INT();
	err = add_region_locked(first, count, name);
	SIL_UNL_INT();
	return err;
}

int alloc_chrdev_region(__kernel_dev_t *dev, unsigned int baseminor, unsigned int count,
			const char *name)
{
	unsigned int major;
	int err = -EBUSY;
	SIL_PRE_LOC;

	lx_might_sleep("alloc_chrdev_region()", __FILE__, __LINE__);
	if (!dev || !region_args_ok(baseminor, count, name))
		return -EINVAL;
	SIL_LOC_INT();
	for (major = REGION_DYNAMIC_FIRST; major > 0; major--) {
		if (major == MISC_MAJOR || major_used_locked(major) || lx_dev_major_taken(major))
			continue;
		err = add_region_locked(MKDEV(major, baseminor), count, name);
		if (!err)
			*dev = MKDEV(major, baseminor);
		break;
	}
	SIL_UNL_INT();
	return err;
}

void unregister_chrdev_region(__kernel_dev_t first, unsigned int count)
{
	bool found = false;
	unsigned int i;
	SIL_PRE_LOC;

	lx_might_sleep("unregister_chrdev_region()", __FILE__, __LINE__);
	SIL_LOC_INT();
	for (i = 0; i < LX_NR_CHRDEV_REGIONS; i++) {
		if (regions[i].count && regions[i].first == first && regions[i].count == count) {
			regions[i].count = 0;
			found = true;
			break;
		}
	}
	SIL_UNL_INT();
	WARN(!found, "unregister_chrdev_region(%u:%u, %u): not registered", MAJOR(first), MINOR(first),
	     count);
}

void cdev_init(struct cdev *cdev, const struct file_operations *fops)
{
	memset(cdev, 0, sizeof(*cdev));
	cdev->ops = fops;
}

struct cdev *cdev_alloc(void)
{
	struct cdev *cdev = kzalloc(sizeof(*cdev), GFP_KERNEL);

	if (cdev)
		cdev->lx_allocated = true;
	return cdev;
}

/* The registry name of number dev: 0, or -EINVAL if no region holds it. */
static int node_name(__kernel_dev_t dev, char *buf, size_t len)
{
	const struct chrdev_region *r = NULL;
	unsigned int i;
	SIL_PRE_LOC;

	SIL_LOC_INT();
	for (i = 0; i < LX_NR_CHRDEV_REGIONS; i++)
		if (regions[i].count && dev >= regions[i].first && dev < regions[i].first + regions[i].count)
			r = &regions[i];
	if (r && r->count == 1)
		snprintf(buf, len, "%s", r->name);
	else if (r)
		snprintf(buf, len, "%s%u", r->name, dev - r->first);
	SIL_UNL_INT();
	return r ? 0 : -EINVAL;
}

int cdev_add(struct cdev *cdev, __kernel_dev_t dev, unsigned int count)
{
	char name[LX_DEV_NAME_MAX + 16];   /* region names leave room for a 7-digit index */
	unsigned int i;
	int err = 0;

	lx_might_sleep("cdev_add()", __FILE__, __LINE__);
	if (!cdev || !cdev->ops || count == 0 || cdev->lx_added)
		return -EINVAL;
	for (i = 0; i < count && !err; i++) {
		err = node_name(dev + i, name, sizeof(name));
		if (!err)
			err = lx_dev_register(name, dev + i, cdev->ops);
	}
	if (err) {
		while (i-- > 1)
			lx_dev_unregister(dev + i - 1);
		return err;
	}
	cdev->dev = dev;
	cdev->count = count;
	cdev->lx_added = true;
	return 0;
}

void cdev_del(struct cdev *cdev)
{
	unsigned int i;

	lx_might_sleep("cdev_del()", __FILE__, __LINE__);
	if (!cdev)
		return;
	if (cdev->lx_added)
		for (i = 0; i < cdev->count; i++)
			lx_dev_unregister(cdev->dev + i);
	cdev->lx_added = false;
	if (cdev->lx_allocated)
		kfree(cdev);
}
