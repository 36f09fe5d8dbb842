/*
 * sysfs.c — classes, device attributes, uevents and the /sys paths by which
 * the API side reads and writes them (linux/device.h, linux/sysfs.h,
 * linux/kobject.h and linux_compat/sysfs.h state the contracts), after
 * Linux 6.1's drivers/base/class.c, core.c and fs/sysfs/file.c.
 *
 * No directory tree is built: a path is resolved when it is opened, by
 * walking the classes or buses to the device and the device's attribute
 * groups to the file.  Lookups, show and store run under the driver core's
 * lock (linux_compat/irq.h), so a device and its driver cannot go away
 * under them, as kernfs's active reference ensures on Linux.
 */
#include <linux/device.h>
#include <linux/err.h>
#include <linux/errno.h>
#include <linux/kernel.h>
#include <linux/mm.h>
#include <linux/slab.h>
#include <linux/spinlock.h>
#include <linux/string.h>
#include <linux/sysfs.h>
#include <linux_compat/irq.h>
#include <linux_compat/report.h>
#include <linux_compat/sysfs.h>

#define NOTIFY_SLOTS	32
#define PATH_PARTS	8
#define PART_MAX	48

struct notify_slot {
	struct device *dev;
	char dir[PART_MAX];
	char attr[PART_MAX];
	unsigned int count;
};

/* A file device_create_file added. */
struct dev_file {
	struct list_head node;
	const struct device_attribute *attr;
};

static LIST_HEAD(classes);
static struct lx_uevent uevents[LX_UEVENT_LOG];
static unsigned int nuevents;
static struct notify_slot notify_slots[NOTIFY_SLOTS];
static DEFINE_SPINLOCK(notify_lock);

/* "dev" of a device with a number, as Linux's dev_attr_dev. */
static ssize_t dev_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	return sysfs_emit(buf, "%u:%u\n", MAJOR(dev->devt), MINOR(dev->devt));
}
static DEVICE_ATTR_RO(dev);

/* ---- formatting into a show() page ---- */

int sysfs_emit(char *buf, const char *fmt, ...)
{
	va_list args;
	int len;

	if (!buf || offset_in_page(buf)) {
		lx_warn(__FILE__, __LINE__, "invalid sysfs_emit: buf:%p", buf);
		return 0;
	}
	va_start(args, fmt);
	len = vscnprintf(buf, PAGE_SIZE, fmt, args);
	va_end(args);
	return len;
}

int sysfs_emit_at(char *buf, int at, const char *fmt, ...)
{
	va_list args;
	int len;

	if (!buf || offset_in_page(buf) || at < 0 || at >= (int)PAGE_SIZE) {
		lx_warn(__FILE__, __LINE__, "invalid sysfs_emit_at: buf:%p at:%d", buf, at);
		return 0;
	}
	va_start(args, fmt);
	len = vscnprintf(buf + at, PAGE_SIZE - (size_t)at, fmt, args);
	va_end(args);
	return len;
}

/* ---- classes ---- */

int class_register(struct class *cls)
{
	struct class *c;

	might_sleep();
	if (!cls || !cls->name || !cls->name[0]) {
		pr_err("class_register: a class without a name\n");
		return -EINVAL;
	}
	lx_driver_core_lock();
	list_for_each_entry(c, &classes, lx_node) {
		if (c == cls || !strcmp(c->name, cls->name)) {
			lx_driver_core_unlock();
			pr_err("class '%s' is already registered\n", cls->name);
			return -EEXIST;
		}
	}
	INIT_LIST_HEAD(&cls->lx_devices);
	list_add_tail(&cls->lx_node, &classes);
	cls->lx_registered = true;
	lx_driver_core_unlock();
	return 0;
}

void class_unregister(struct class *cls)
{
	might_sleep();
	if (!cls || !cls->lx_registered) {
		lx_report("class_unregister of a class not registered", __FILE__, __LINE__, "class '%s'",
			  cls && cls->name ? cls->name : "(null)");
		return;
	}
	lx_driver_core_lock();
	if (!list_empty(&cls->lx_devices))
		lx_report("class_unregister with devices left", __FILE__, __LINE__,
			  "class '%s' still has %s", cls->name,
			  dev_name(list_first_entry(&cls->lx_devices, struct device, lx_class_node)));
	list_del_init(&cls->lx_node);
	cls->lx_registered = false;
	lx_driver_core_unlock();
	if (cls->class_release)
		cls->class_release(cls);
}

/* class_release of a class from class_create. */
static void class_create_release(struct class *cls)
{
	kfree(cls);
}

struct class *__class_create(struct module *owner, const char *name)
{
	struct class *cls;
	int ret;

	cls = kzalloc(sizeof(*cls), GFP_KERNEL);
	if (!cls)
		return ERR_PTR(-ENOMEM);
	cls->name = name;
	cls->owner = owner;
	cls->class_release = class_create_release;
	ret = class_register(cls);
	if (ret) {
		kfree(cls);
		return ERR_PTR(ret);
	}
	return cls;
}

void class_destroy(struct class *cls)
{
	if (IS_ERR_OR_NULL(cls))
		return;
	class_unregister(cls);
}

/* The registered class called name, or NULL.  Core locked. */
static struct class *class_find(const char *name)
{
	struct class *cls;

	list_for_each_entry(cls, &classes, lx_node)
		if (!strcmp(cls->name, name))
			return cls;
	return NULL;
}

/* The device of cls called name, or NULL.  Core locked. */
static struct device *class_dev_find(struct class *cls, const char *name)
{
	struct device *dev;

	list_for_each_entry(dev, &cls->lx_devices, lx_class_node)
		if (!strcmp(dev_name(dev), name))
			return dev;
	return NULL;
}

struct device *class_find_device_by_name(struct class *cls, const char *name)
{
	struct device *dev = NULL;

	if (!cls || !name || !cls->lx_registered)
		return NULL;
	lx_driver_core_lock();
	dev = get_device(class_dev_find(cls, name));
	lx_driver_core_unlock();
	return dev;
}

/* release of a device from device_create. */
static void device_create_release(struct device *dev)
{
	kfree(dev);
}

/* The body of device_create and device_create_with_groups. */
static __printf(6, 0) struct device *device_create_vargs(struct class *cls, struct device *parent,
							 __kernel_dev_t devt, void *drvdata,
							 const struct attribute_group **groups,
							 const char *fmt, va_list args)
{
	struct device *dev;
	int ret;

	if (IS_ERR_OR_NULL(cls))
		return ERR_PTR(-ENODEV);
	dev = kzalloc(sizeof(*dev), GFP_KERNEL);
	if (!dev)
		return ERR_PTR(-ENOMEM);
	device_initialize(dev);
	dev->devt = devt;
	dev->class = cls;
	dev->parent = parent;
	dev->groups = groups;
	dev->release = device_create_release;
	dev_set_drvdata(dev, drvdata);
	vsnprintf(dev->lx_name, sizeof(dev->lx_name), fmt, args);
	dev->init_name = dev->lx_name;
	ret = device_add(dev);
	if (ret) {
		put_device(dev);
		return ERR_PTR(ret);
	}
	return dev;
}

struct device *device_create(struct class *cls, struct device *parent, __kernel_dev_t devt, void *drvdata,
			     const char *fmt, ...)
{
	struct device *dev;
	va_list args;

	va_start(args, fmt);
	dev = device_create_vargs(cls, parent, devt, drvdata, NULL, fmt, args);
	va_end(args);
	return dev;
}

struct device *device_create_with_groups(struct class *cls, struct device *parent, __kernel_dev_t devt,
					 void *drvdata, const struct attribute_group **groups,
					 const char *fmt, ...)
{
	struct device *dev;
	va_list args;

	va_start(args, fmt);
	dev = device_create_vargs(cls, parent, devt, drvdata, groups, fmt, args);
	va_end(args);
	return dev;
}

void device_destroy(struct class *cls, __kernel_dev_t devt)
{
	struct device *dev, *found = NULL;

	might_sleep();
	if (IS_ERR_OR_NULL(cls) || !cls->lx_registered)
		return;
	lx_driver_core_lock();
	list_for_each_entry(dev, &cls->lx_devices, lx_class_node) {
		if (dev->devt == devt) {
			found = dev;
			break;
		}
	}
	lx_driver_core_unlock();
	if (!found) {
		lx_report("device_destroy of a number the class has no device for", __FILE__, __LINE__,
			  "class '%s', %u:%u", cls->name, MAJOR(devt), MINOR(devt));
		return;
	}
	device_unregister(found);
}

/* ---- a device's files ---- */

/* Reports a mode the attribute cannot serve, as Linux's device_create_file WARNs. */
static void check_attr_mode(const struct device *dev, const struct device_attribute *attr)
{
	if ((attr->attr.mode & S_IWUGO) && !attr->store)
		lx_warn(__FILE__, __LINE__, "Attribute %s: write permission without 'store' (device %s)",
			attr->attr.name, dev_name(dev));
	if ((attr->attr.mode & S_IRUGO) && !attr->show)
		lx_warn(__FILE__, __LINE__, "Attribute %s: read permission without 'show' (device %s)",
			attr->attr.name, dev_name(dev));
}

/* Checks every attribute of groups (a NULL-terminated list, or NULL). */
static void check_groups(const struct device *dev, const struct attribute_group **groups)
{
	struct attribute **a;

	for (; groups && *groups; groups++)
		for (a = (*groups)->attrs; a && *a; a++)
			check_attr_mode(dev, container_of(*a, struct device_attribute, attr));
}

/* A file found by name: the attribute and its mode (after is_visible). */
struct found_file {
	struct device_attribute *attr;
	umode_t mode;
	const char *dir;        /* its group's directory, or NULL */
};

/* Looks for dir/name (dir NULL: the device's own directory) among groups;
 * true and *out if found and visible.  With name NULL, true if the group
 * directory dir exists.  Core locked. */
static bool groups_find(struct device *dev, const struct attribute_group **groups, const char *dir,
			const char *name, struct found_file *out)
{
	struct attribute **a;
	umode_t mode;
	int n;

	for (; groups && *groups; groups++) {
		const struct attribute_group *grp = *groups;

		if (dir ? !grp->name || strcmp(grp->name, dir) : grp->name != NULL)
			continue;
		if (!name)
			return true;
		for (a = grp->attrs, n = 0; a && *a; a++, n++) {
			if (strcmp((*a)->name, name))
				continue;
			mode = grp->is_visible ? grp->is_visible(&dev->kobj, *a, n) : (*a)->mode;
			if (!mode)
				continue;
			out->attr = container_of(*a, struct device_attribute, attr);
			out->mode = mode;
			out->dir = grp->name;
			return true;
		}
	}
	return false;
}

/* The file dir/name of dev (dir NULL: its own directory); with name NULL,
 * whether directory dir exists.  Core locked. */
static bool dev_find_file(struct device *dev, const char *dir, const char *name, struct found_file *out)
{
	struct dev_file *f;

	if (dev->class && groups_find(dev, dev->class->dev_groups, dir, name, out))
		return true;
	if (dev->type && groups_find(dev, dev->type->groups, dir, name, out))
		return true;
	if (groups_find(dev, dev->groups, dir, name, out))
		return true;
	if (dev->driver && !dev->lx_probing && groups_find(dev, dev->driver->dev_groups, dir, name, out))
		return true;
	if (dir || !name)
		return false;
	list_for_each_entry(f, &dev->lx_files, node) {
		if (!strcmp(f->attr->attr.name, name)) {
			out->attr = (struct device_attribute *)f->attr;
			out->mode = f->attr->attr.mode;
			out->dir = NULL;
			return true;
		}
	}
	if (MAJOR(dev->devt) && !strcmp(name, "dev")) {
		out->attr = &dev_attr_dev;
		out->mode = dev_attr_dev.attr.mode;
		out->dir = NULL;
		return true;
	}
	return false;
}

int device_create_file(struct device *dev, const struct device_attribute *attr)
{
	struct found_file existing;
	struct dev_file *f;

	might_sleep();
	if (!dev || !attr || !attr->attr.name)
		return -EINVAL;
	check_attr_mode(dev, attr);
	f = kzalloc(sizeof(*f), GFP_KERNEL);
	if (!f)
		return -ENOMEM;
	lx_driver_core_lock();
	if (dev->lx_files.next == NULL)
		INIT_LIST_HEAD(&dev->lx_files);
	if (dev_find_file(dev, NULL, attr->attr.name, &existing)) {
		lx_driver_core_unlock();
		kfree(f);
		pr_err("sysfs: cannot create duplicate filename '%s/%s'\n", dev_name(dev), attr->attr.name);
		return -EEXIST;
	}
	f->attr = attr;
	list_add_tail(&f->node, &dev->lx_files);
	lx_driver_core_unlock();
	return 0;
}

void device_remove_file(struct device *dev, const struct device_attribute *attr)
{
	struct dev_file *f;

	might_sleep();
	if (!dev || !attr || dev->lx_files.next == NULL)
		return;
	lx_driver_core_lock();
	list_for_each_entry(f, &dev->lx_files, node) {
		if (f->attr == attr) {
			list_del(&f->node);
			kfree(f);
			break;
		}
	}
	lx_driver_core_unlock();
}

int lx_sysfs_device_add(struct device *dev)
{
	struct class *cls = dev->class;

	dev->kobj.name = dev_name(dev);
	if (dev->lx_files.next == NULL)
		INIT_LIST_HEAD(&dev->lx_files);
	if (cls) {
		if (!cls->lx_registered) {
			pr_err("device_add: %s in class '%s', which is not registered\n", dev_name(dev),
			       cls->name ? cls->name : "(null)");
			return -EINVAL;
		}
		if (class_dev_find(cls, dev_name(dev))) {
			pr_err("sysfs: cannot create duplicate filename '/class/%s/%s'\n", cls->name,
			       dev_name(dev));
			return -EEXIST;
		}
		check_groups(dev, cls->dev_groups);
		list_add_tail(&dev->lx_class_node, &cls->lx_devices);
	}
	if (dev->type)
		check_groups(dev, dev->type->groups);
	check_groups(dev, dev->groups);
	return 0;
}

void lx_sysfs_device_del(struct device *dev)
{
	struct dev_file *f, *next;
	unsigned long flags;
	unsigned int i;

	if (dev->class && !list_empty(&dev->lx_class_node))
		list_del_init(&dev->lx_class_node);
	if (dev->lx_files.next) {
		list_for_each_entry_safe(f, next, &dev->lx_files, node) {
			list_del(&f->node);
			kfree(f);
		}
	}
	spin_lock_irqsave(&notify_lock, flags);
	for (i = 0; i < NOTIFY_SLOTS; i++)
		if (notify_slots[i].dev == dev)
			notify_slots[i].dev = NULL;
	spin_unlock_irqrestore(&notify_lock, flags);
}

/* ---- notifications and uevents ---- */

void sysfs_notify(struct kobject *kobj, const char *dir, const char *attr)
{
	struct device *dev;
	struct notify_slot *slot = NULL;
	unsigned long flags;
	unsigned int i;

	if (!kobj || !attr)
		return;
	dev = kobj_to_dev(kobj);
	spin_lock_irqsave(&notify_lock, flags);
	for (i = 0; i < NOTIFY_SLOTS; i++) {
		struct notify_slot *s = &notify_slots[i];

		if (s->dev == dev && !strcmp(s->attr, attr) && !strcmp(s->dir, dir ? dir : "")) {
			slot = s;
			break;
		}
		if (!s->dev && !slot)
			slot = s;
	}
	if (slot && slot->dev != dev) {
		slot->dev = dev;
		strscpy(slot->dir, dir ? dir : "", sizeof(slot->dir));
		strscpy(slot->attr, attr, sizeof(slot->attr));
		slot->count = 0;
	}
	if (slot)
		slot->count++;
	spin_unlock_irqrestore(&notify_lock, flags);
	if (!slot)
		pr_warn("sysfs_notify: more than %d notified files, %s/%s not counted\n", NOTIFY_SLOTS,
			dev_name(dev), attr);
}

const char *lx_uevent_action_name(enum kobject_action action)
{
	static const char *const names[] = {
		[KOBJ_ADD] = "add", [KOBJ_REMOVE] = "remove", [KOBJ_CHANGE] = "change",
		[KOBJ_MOVE] = "move", [KOBJ_ONLINE] = "online", [KOBJ_OFFLINE] = "offline",
		[KOBJ_BIND] = "bind", [KOBJ_UNBIND] = "unbind",
	};

	return (unsigned int)action < ARRAY_SIZE(names) ? names[action] : "?";
}

/* Writes dev's devpath (Linux's layout: /devices/<parents>/[<class>/]<name>,
 * /devices/virtual/<class>/<name> for a class device without a parent). */
static void devpath_of(struct device *dev, char *buf, size_t len)
{
	const char *names[8];
	unsigned int n = 0;
	struct device *d;
	size_t at;

	for (d = dev; d && n < ARRAY_SIZE(names); d = d->parent)
		names[n++] = dev_name(d);
	at = (size_t)scnprintf(buf, len, "/devices");
	if (dev->class && !dev->parent)
		at += (size_t)scnprintf(buf + at, len - at, "/virtual");
	while (n-- > 1)
		at += (size_t)scnprintf(buf + at, len - at, "/%s", names[n]);
	if (dev->class)
		at += (size_t)scnprintf(buf + at, len - at, "/%s", dev->class->name);
	scnprintf(buf + at, len - at, "/%s", dev_name(dev));
}

int add_uevent_var(struct kobj_uevent_env *env, const char *format, ...)
{
	va_list args;
	int len;

	if (env->envp_idx >= (int)ARRAY_SIZE(env->envp)) {
		pr_err("add_uevent_var: too many keys\n");
		return -ENOMEM;
	}
	va_start(args, format);
	len = vsnprintf(&env->buf[env->buflen], sizeof(env->buf) - (size_t)env->buflen, format, args);
	va_end(args);
	if (len >= (int)sizeof(env->buf) - env->buflen) {
		pr_err("add_uevent_var: buffer size too small\n");
		return -ENOMEM;
	}
	env->envp[env->envp_idx++] = &env->buf[env->buflen];
	env->buflen += len + 1;
	return 0;
}

/* The variables of dev's class and type (Linux's dev_uevent): 0, or their error. */
static int device_uevent_vars(struct device *dev, struct kobj_uevent_env *env)
{
	int ret = 0;

	if (dev->class && dev->class->dev_uevent)
		ret = dev->class->dev_uevent(dev, env);
	if (!ret && dev->type && dev->type->uevent)
		ret = dev->type->uevent(dev, env);
	return ret;
}

int kobject_uevent_env(struct kobject *kobj, enum kobject_action action, char *envp[])
{
	struct kobj_uevent_env *env;
	struct device *dev;
	struct lx_uevent *ev;
	unsigned int i, n;
	int ret;

	might_sleep();
	if (!kobj)
		return -EINVAL;
	for (i = 0; envp && envp[i]; i++) {
		if (!strchr(envp[i], '=')) {
			pr_err("kobject_uevent_env: '%s' is not KEY=value\n", envp[i]);
			return -EINVAL;
		}
	}
	dev = kobj_to_dev(kobj);
	env = kzalloc(sizeof(*env), GFP_KERNEL);
	if (!env)
		return -ENOMEM;
	ret = device_uevent_vars(dev, env);
	if (ret) {
		kfree(env);
		return ret;
	}
	ev = &uevents[nuevents % LX_UEVENT_LOG];
	memset(ev, 0, sizeof(*ev));
	ev->action = action;
	devpath_of(dev, ev->devpath, sizeof(ev->devpath));
	strscpy(ev->subsystem, dev->class ? dev->class->name : dev->bus ? dev->bus->name : "",
		sizeof(ev->subsystem));
	n = 0;
	for (i = 0; envp && envp[i] && n < LX_UEVENT_VARS; i++)
		strscpy(ev->vars[n++], envp[i], sizeof(ev->vars[0]));
	for (i = 0; i < (unsigned int)env->envp_idx && n < LX_UEVENT_VARS; i++)
		strscpy(ev->vars[n++], env->envp[i], sizeof(ev->vars[0]));
	ev->nvars = n;
	nuevents++;
	kfree(env);
	return 0;
}

int kobject_uevent(struct kobject *kobj, enum kobject_action action)
{
	return kobject_uevent_env(kobj, action, NULL);
}

unsigned int lx_uevent_count(void)
{
	return nuevents;
}

const struct lx_uevent *lx_uevent_get(unsigned int i)
{
	if (i >= nuevents || nuevents - i > LX_UEVENT_LOG)
		return NULL;
	return &uevents[i % LX_UEVENT_LOG];
}

/* ---- paths ---- */

/* Splits path ("/sys/a/b/...") into parts; their number, or -EINVAL (not
 * under /sys) or -ENOENT (too deep or a part too long to exist). */
static int split_path(const char *path, char parts[PATH_PARTS][PART_MAX])
{
	const char *p, *end;
	int n = 0;
	size_t len;

	if (strncmp(path, "/sys/", 5))
		return -EINVAL;
	for (p = path + 5; *p; p = end) {
		while (*p == '/')
			p++;
		if (!*p)
			break;
		end = strchr(p, '/');
		if (!end)
			end = p + strlen(p);
		len = (size_t)(end - p);
		if (n == PATH_PARTS || len >= PART_MAX)
			return -ENOENT;
		memcpy(parts[n], p, len);
		parts[n][len] = '\0';
		n++;
	}
	return n;
}

/* Resolves path to a file of a device: 0 with *devp and *file, -EISDIR for
 * a directory, or -EINVAL/-ENOENT.  Core locked. */
static int resolve(const char *path, struct device **devp, struct found_file *file)
{
	char parts[PATH_PARTS][PART_MAX];
	struct device *dev = NULL;
	struct class *cls;
	int n, at;

	n = split_path(path, parts);
	if (n < 0)
		return n;
	if (n == 0)
		return -EISDIR;
	if (!strcmp(parts[0], "class")) {
		if (n == 1)
			return -EISDIR;
		cls = class_find(parts[1]);
		if (!cls)
			return -ENOENT;
		if (n == 2)
			return -EISDIR;
		dev = class_dev_find(cls, parts[2]);
		at = 3;
	} else if (!strcmp(parts[0], "bus")) {
		if (n >= 3 && strcmp(parts[2], "devices"))
			return -ENOENT;
		if (n < 4)
			return lx_bus_find_device_by_name(parts[1], NULL) || n == 1 ? -EISDIR : -ENOENT;
		dev = lx_bus_find_device_by_name(parts[1], parts[3]);
		at = 4;
	} else {
		return -ENOENT;
	}
	if (!dev)
		return -ENOENT;
	if (n == at)
		return -EISDIR;
	if (n == at + 1) {
		if (dev_find_file(dev, NULL, parts[at], file)) {
			*devp = dev;
			return 0;
		}
		return dev_find_file(dev, parts[at], NULL, NULL) ? -EISDIR : -ENOENT;
	}
	if (n == at + 2 && dev_find_file(dev, parts[at], parts[at + 1], file)) {
		*devp = dev;
		return 0;
	}
	return -ENOENT;
}

ssize_t lx_sysfs_read(const char *path, char *buf, size_t len)
{
	struct found_file file;
	struct device *dev;
	ssize_t ret;
	char *page;

	might_sleep();
	if (!path || (!buf && len))
		return -EINVAL;
	page = (char *)get_zeroed_page(GFP_KERNEL);
	if (!page)
		return -ENOMEM;
	lx_driver_core_lock();
	ret = resolve(path, &dev, &file);
	if (ret == 0 && !(file.mode & S_IRUSR))
		ret = -EACCES;
	else if (ret == 0 && !file.attr->show)
		ret = -EIO;
	else if (ret == 0)
		ret = file.attr->show(dev, file.attr, page);
	if (ret >= (ssize_t)PAGE_SIZE) {
		lx_report("sysfs show returned a bad count", __FILE__, __LINE__,
			  "%s: %zd bytes, more than a page", path, ret);
		ret = PAGE_SIZE - 1;
	}
	lx_driver_core_unlock();
	if (ret > 0) {
		if ((size_t)ret > len)
			ret = (ssize_t)len;
		memcpy(buf, page, (size_t)ret);
	}
	free_page((unsigned long)page);
	return ret;
}

ssize_t lx_sysfs_write(const char *path, const char *buf, size_t len)
{
	struct found_file file;
	struct device *dev;
	ssize_t ret;
	char *copy;

	might_sleep();
	if (!path || (!buf && len))
		return -EINVAL;
	copy = kmalloc(len + 1, GFP_KERNEL);
	if (!copy)
		return -ENOMEM;
	if (len)
		memcpy(copy, buf, len);
	copy[len] = '\0';
	lx_driver_core_lock();
	ret = resolve(path, &dev, &file);
	if (ret == 0 && !(file.mode & S_IWUSR))
		ret = -EACCES;
	else if (ret == 0 && len > PAGE_SIZE)
		ret = -E2BIG;
	else if (ret == 0 && !file.attr->store)
		ret = -EIO;
	else if (ret == 0 && len)
		ret = file.attr->store(dev, file.attr, copy, len);
	lx_driver_core_unlock();
	kfree(copy);
	return ret;
}

unsigned int lx_sysfs_notify_count(const char *path)
{
	struct found_file file;
	struct device *dev;
	unsigned long flags;
	unsigned int i, count = 0;

	if (!path)
		return 0;
	lx_driver_core_lock();
	if (resolve(path, &dev, &file) == 0) {
		spin_lock_irqsave(&notify_lock, flags);
		for (i = 0; i < NOTIFY_SLOTS; i++)
			if (notify_slots[i].dev == dev &&
			    !strcmp(notify_slots[i].attr, file.attr->attr.name) &&
			    !strcmp(notify_slots[i].dir, file.dir ? file.dir : ""))
				count = notify_slots[i].count;
		spin_unlock_irqrestore(&notify_lock, flags);
	}
	lx_driver_core_unlock();
	return count;
}

/* Calls fn for each readable file of dev among groups (class dir prefix). */
static unsigned int for_each_group_file(struct device *dev, const struct attribute_group **groups,
					const char *prefix, void (*fn)(const char *path, void *ctx),
					void *ctx)
{
	char path[160];
	struct attribute **a;
	unsigned int count = 0;
	umode_t mode;
	int n;

	for (; groups && *groups; groups++) {
		for (a = (*groups)->attrs, n = 0; a && *a; a++, n++) {
			mode = (*groups)->is_visible ? (*groups)->is_visible(&dev->kobj, *a, n) : (*a)->mode;
			if (!(mode & S_IRUSR))
				continue;
			if ((*groups)->name)
				scnprintf(path, sizeof(path), "%s/%s/%s", prefix, (*groups)->name, (*a)->name);
			else
				scnprintf(path, sizeof(path), "%s/%s", prefix, (*a)->name);
			fn(path, ctx);
			count++;
		}
	}
	return count;
}

unsigned int lx_sysfs_for_each_class_file(void (*fn)(const char *path, void *ctx), void *ctx)
{
	char prefix[128], path[160];
	struct device *dev;
	struct class *cls;
	struct dev_file *f;
	unsigned int count = 0;

	if (!fn)
		return 0;
	lx_driver_core_lock();
	list_for_each_entry(cls, &classes, lx_node) {
		list_for_each_entry(dev, &cls->lx_devices, lx_class_node) {
			scnprintf(prefix, sizeof(prefix), "/sys/class/%s/%s", cls->name, dev_name(dev));
			if (MAJOR(dev->devt)) {
				scnprintf(path, sizeof(path), "%s/dev", prefix);
				fn(path, ctx);
				count++;
			}
			count += for_each_group_file(dev, cls->dev_groups, prefix, fn, ctx);
			if (dev->type)
				count += for_each_group_file(dev, dev->type->groups, prefix, fn, ctx);
			count += for_each_group_file(dev, dev->groups, prefix, fn, ctx);
			list_for_each_entry(f, &dev->lx_files, node) {
				if (!(f->attr->attr.mode & S_IRUSR))
					continue;
				scnprintf(path, sizeof(path), "%s/%s", prefix, f->attr->attr.name);
				fn(path, ctx);
				count++;
			}
			if (dev->driver && !dev->lx_probing)
				count += for_each_group_file(dev, dev->driver->dev_groups, prefix, fn, ctx);
		}
	}
	lx_driver_core_unlock();
	return count;
}

void lx_class_register_boot(struct class *cls)
{
	INIT_LIST_HEAD(&cls->lx_devices);
	list_add_tail(&cls->lx_node, &classes);
	cls->lx_registered = true;
}

void lx_sysfs_boot(void)
{
	INIT_LIST_HEAD(&classes);
	memset(uevents, 0, sizeof(uevents));
	nuevents = 0;
	memset(notify_slots, 0, sizeof(notify_slots));
	spin_lock_init(&notify_lock);
}
