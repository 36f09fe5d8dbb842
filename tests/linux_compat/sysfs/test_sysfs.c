/*
 * test_sysfs.c — classes, device attributes and uevents, read and written
 * by path as user space reads /sys: class_create and device_create, files
 * from the class's dev_groups, the device's groups (a named group is a
 * subdirectory, is_visible hides), device_create_file, "dev", a driver's
 * dev_groups while it is bound; show's page and sysfs_emit, store's
 * NUL-terminated copy and count; the errors open(2) and sysfs give
 * (-ENOENT, -EISDIR, -EACCES by the mode, -E2BIG, -EIO, -EINVAL);
 * sysfs_notify counted; uevents recorded with their devpath and variables;
 * misuse reported: a mode without its show/store, show overrunning the
 * page, sysfs_emit into a buffer that is not a page, a read from atomic
 * context, a class unregistered with devices left.
 */
#define KBUILD_MODNAME "sysfstest"
#include "lx_log_test.h"
#include <linux/device.h>
#include <linux/err.h>
#include <linux/kstrtox.h>
#include <linux/mm.h>
#include <linux/platform_device.h>
#include <linux/spinlock.h>
#include <linux/sysfs.h>
#include <linux_compat/sysfs.h>
#include "host_sim/board.h"

static char last_store[64];
static size_t last_count;
static int speed = 7;

static ssize_t speed_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	return sysfs_emit(buf, "%d\n", speed);
}

static ssize_t speed_store(struct device *dev, struct device_attribute *attr, const char *buf, size_t count)
{
	int ret;

	snprintf(last_store, sizeof(last_store), "%s", buf);
	last_count = count;
	ret = kstrtoint(buf, 10, &speed);
	return ret ? ret : (ssize_t)count;
}
static DEVICE_ATTR_RW(speed);

static ssize_t name_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	return sysfs_emit(buf, "%s\n", dev_name(dev));
}
static DEVICE_ATTR_RO(name);

static ssize_t reset_store(struct device *dev, struct device_attribute *attr, const char *buf, size_t count)
{
	speed = 0;
	sysfs_notify(&dev->kobj, NULL, "speed");
	return (ssize_t)count;
}
static DEVICE_ATTR_WO(reset);

static struct attribute *motor_attrs[] = { &dev_attr_speed.attr, &dev_attr_name.attr, NULL };
ATTRIBUTE_GROUPS(motor);

static ssize_t secret_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	return sysfs_emit(buf, "hidden\n");
}
static DEVICE_ATTR_RO(secret);

static ssize_t list_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	int at = 0, i;

	for (i = 0; i < 3; i++)
		at += sysfs_emit_at(buf, at, "%s%d", i ? " " : "", i);
	at += sysfs_emit_at(buf, at, "\n");
	return at;
}
static DEVICE_ATTR_RO(list);

static umode_t extra_visible(struct kobject *kobj, struct attribute *attr, int n)
{
	return attr == &dev_attr_secret.attr ? 0 : attr->mode;
}

static struct attribute *extra_attrs[] = { &dev_attr_secret.attr, &dev_attr_list.attr, NULL };
static const struct attribute_group extra_group = {
	.name = "extra", .attrs = extra_attrs, .is_visible = extra_visible,
};
static const struct attribute_group *extra_groups[] = { &extra_group, NULL };

/* A show() that overruns the page, and one that formats off the page. */
static ssize_t big_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	memset(buf, 'x', PAGE_SIZE);
	return PAGE_SIZE;
}
static DEVICE_ATTR_RO(big);

static ssize_t offpage_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	return sysfs_emit(buf + 1, "x");
}
static DEVICE_ATTR_RO(offpage);

/* Declares 0644 without a store: Linux WARNs when the file is created. */
static struct device_attribute dev_attr_nostore = __ATTR(nostore, 0644, name_show, NULL);

static char read_buf[PAGE_SIZE + 16];

/* The file at path as a string ("" and the error in *err if it fails). */
static const char *cat(const char *path)
{
	ssize_t n = lx_sysfs_read(path, read_buf, sizeof(read_buf) - 1);

	read_buf[n > 0 ? n : 0] = '\0';
	return read_buf;
}

static char listed[512];

/* Collects the paths lx_sysfs_for_each_class_file gives. */
static void list_file(const char *path, void *ctx)
{
	(*(unsigned int *)ctx)++;
	strncat(listed, path, sizeof(listed) - strlen(listed) - 2);
	strcat(listed, " ");
}

static void class_tests(void)
{
	unsigned int nlisted = 0;
	struct class *cls, *dup;
	struct device *m0, *m1;
	unsigned int ev0;
	const struct lx_uevent *ev;
	char *envp[] = { "PORT=in1", NULL };
	char *bad_envp[] = { "noequals", NULL };
	char big[PAGE_SIZE + 1];

	cls = class_create(THIS_MODULE, "tacho-motor");
	ok(!IS_ERR(cls), "class_create");
	cls->dev_groups = motor_groups;
	dup = class_create(THIS_MODULE, "tacho-motor");
	is_int((int)PTR_ERR(dup), -EEXIST, "a second class of that name: -EEXIST");

	ev0 = lx_uevent_count();
	m0 = device_create(cls, NULL, MKDEV(240, 0), &speed, "motor%d", 0);
	ok(!IS_ERR(m0) && dev_get_drvdata(m0) == &speed, "device_create with drvdata");
	ok(IS_ERR(device_create(cls, NULL, 0, NULL, "motor0")), "a second motor0 in the class: an error");
	m1 = device_create_with_groups(cls, NULL, 0, NULL, extra_groups, "motor%d", 1);
	ok(!IS_ERR(m1), "device_create_with_groups");

	is_int(lx_sysfs_for_each_class_file(list_file, &nlisted), 6, "six readable class files");
	ok(nlisted == 6 && strstr(listed, "/sys/class/tacho-motor/motor0/dev ") &&
	   strstr(listed, "/sys/class/tacho-motor/motor1/extra/list ") &&
	   !strstr(listed, "secret"), "dev, speed and name of each, the group's visible file (%s)", listed);
	is_str(cat("/sys/class/tacho-motor/motor0/speed"), "7\n", "a class dev_groups file reads through show");
	is_str(cat("/sys/class/tacho-motor/motor1/name"), "motor1\n", "the same file of another device");
	is_str(cat("/sys/class/tacho-motor/motor0/dev"), "240:0\n", "dev: the device's number");
	is_int((int)lx_sysfs_read("/sys/class/tacho-motor/motor1/dev", read_buf, 8), -ENOENT,
	       "no dev without a number");
	is_int((int)lx_sysfs_read("/sys/class/tacho-motor/motor0/speed", read_buf, 1), 1,
	       "a short read gets the first bytes");

	is_int((int)lx_sysfs_write("/sys/class/tacho-motor/motor0/speed", "42\nxx", 3), 3,
	       "a write returns store's count");
	ok(!strcmp(last_store, "42\n") && last_count == 3, "store gets a NUL-terminated copy and the count");
	is_str(cat("/sys/class/tacho-motor/motor0/speed"), "42\n", "and the value is read back");
	is_int((int)lx_sysfs_write("/sys/class/tacho-motor/motor0/speed", "fast", 4), -EINVAL,
	       "store's own error comes back");

	is_str(cat("/sys/class/tacho-motor/motor1/extra/list"), "0 1 2\n",
	       "a named group is a subdirectory; sysfs_emit_at appends");
	is_int((int)lx_sysfs_read("/sys/class/tacho-motor/motor1/extra/secret", read_buf, 8), -ENOENT,
	       "is_visible returning 0 hides a file");
	is_int((int)lx_sysfs_read("/sys/class/tacho-motor/motor1/extra", read_buf, 8), -EISDIR,
	       "a group directory: -EISDIR");
	is_int((int)lx_sysfs_read("/sys/class/tacho-motor/motor1", read_buf, 8), -EISDIR, "a device: -EISDIR");
	is_int((int)lx_sysfs_read("/sys/class/tacho-motor/motor2/speed", read_buf, 8), -ENOENT, "no motor2: -ENOENT");
	is_int((int)lx_sysfs_read("/sys/class/lego-port/port0/mode", read_buf, 8), -ENOENT, "no such class: -ENOENT");
	is_int((int)lx_sysfs_read("/proc/version", read_buf, 8), -EINVAL, "a path outside /sys: -EINVAL");
	is_int((int)lx_sysfs_read(NULL, read_buf, 8), -EINVAL, "NULL: -EINVAL");

	is_int((int)lx_sysfs_write("/sys/class/tacho-motor/motor0/name", "x", 1), -EACCES,
	       "writing a DEVICE_ATTR_RO file: -EACCES");
	is_int(device_create_file(m0, &dev_attr_reset), 0, "device_create_file");
	is_int(device_create_file(m0, &dev_attr_reset), -EEXIST, "twice: -EEXIST");
	is_int((int)lx_sysfs_read("/sys/class/tacho-motor/motor0/reset", read_buf, 8), -EACCES,
	       "reading a DEVICE_ATTR_WO file: -EACCES");
	memset(big, '1', sizeof(big));
	is_int((int)lx_sysfs_write("/sys/class/tacho-motor/motor0/reset", big, sizeof(big)), -E2BIG,
	       "a write longer than a page: -E2BIG");
	is_int(lx_sysfs_notify_count("/sys/class/tacho-motor/motor0/speed"), 0, "no notification yet");
	is_int((int)lx_sysfs_write("/sys/class/tacho-motor/motor0/reset", "1", 1), 1, "a write-only file");
	is_int(speed, 0, "its store ran");
	is_int(lx_sysfs_notify_count("/sys/class/tacho-motor/motor0/speed"), 1, "sysfs_notify counted for speed");
	device_remove_file(m0, &dev_attr_reset);
	is_int((int)lx_sysfs_write("/sys/class/tacho-motor/motor0/reset", "1", 1), -ENOENT,
	       "device_remove_file removed it");

	is_int(kobject_uevent_env(&m0->kobj, KOBJ_CHANGE, envp), 0, "kobject_uevent_env");
	is_int(kobject_uevent_env(&m0->kobj, KOBJ_CHANGE, bad_envp), -EINVAL, "a variable without '=': -EINVAL");
	ev = lx_uevent_get(lx_uevent_count() - 1);
	ok(ev && ev->action == KOBJ_CHANGE && !strcmp(ev->devpath, "/devices/virtual/tacho-motor/motor0") &&
	   !strcmp(ev->subsystem, "tacho-motor") && ev->nvars == 1 && !strcmp(ev->vars[0], "PORT=in1"),
	   "recorded: change of /devices/virtual/tacho-motor/motor0 with PORT=in1");
	ev = lx_uevent_get(ev0);
	ok(ev && ev->action == KOBJ_ADD && !strcmp(lx_uevent_action_name(ev->action), "add"),
	   "device_create recorded an add uevent");

	ev0 = lx_uevent_count();
	device_destroy(cls, MKDEV(240, 0));
	ev = lx_uevent_get(ev0);
	ok(ev && ev->action == KOBJ_REMOVE, "device_destroy: remove uevent");
	is_int((int)lx_sysfs_read("/sys/class/tacho-motor/motor0/speed", read_buf, 8), -ENOENT, "and its files are gone");
	device_unregister(m1);
	class_destroy(cls);
	is_int((int)lx_sysfs_read("/sys/class/tacho-motor", read_buf, 8), -ENOENT, "class_destroy removed the class");
}

static int probe_count;

static ssize_t mode_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	return sysfs_emit(buf, "auto\n");
}
static DEVICE_ATTR_RO(mode);
static struct attribute *port_attrs[] = { &dev_attr_mode.attr, NULL };
ATTRIBUTE_GROUPS(port);

static int port_probe(struct platform_device *pdev)
{
	probe_count++;
	return 0;
}

static struct platform_driver port_driver = {
	.probe = port_probe,
	.driver = { .name = "ev3-sysfs-port", .dev_groups = port_groups },
};

static void platform_tests(void)
{
	struct platform_device *pdev = platform_device_alloc("ev3-sysfs-port", 0);
	const struct lx_uevent *ev;
	unsigned int ev0;

	ok(pdev && platform_device_add(pdev) == 0, "a platform device");
	is_int((int)lx_sysfs_read("/sys/bus/platform/devices/ev3-sysfs-port.0/mode", read_buf, 8), -ENOENT,
	       "no driver, no driver dev_groups");
	is_int((int)lx_sysfs_read("/sys/bus/platform/devices/ev3-sysfs-port.0", read_buf, 8), -EISDIR,
	       "the device's directory under /sys/bus/platform/devices");
	ev0 = lx_uevent_count();
	is_int(platform_driver_register(&port_driver), 0, "its driver");
	ev = lx_uevent_get(ev0);
	ok(probe_count == 1 && ev && ev->action == KOBJ_BIND &&
	   !strcmp(ev->devpath, "/devices/platform/ev3-sysfs-port.0") && !strcmp(ev->subsystem, "platform"),
	   "bound: a bind uevent of /devices/platform/ev3-sysfs-port.0");
	is_str(cat("/sys/bus/platform/devices/ev3-sysfs-port.0/mode"), "auto\n",
	       "the driver's dev_groups while it is bound");
	platform_driver_unregister(&port_driver);
	is_int((int)lx_sysfs_read("/sys/bus/platform/devices/ev3-sysfs-port.0/mode", read_buf, 8), -ENOENT,
	       "gone on unbind");
	platform_device_unregister(pdev);
}

static DEFINE_SPINLOCK(test_lock);
static struct class static_class = { .name = "static" };

static void misuse_tests(void)
{
	struct class *cls = class_create(THIS_MODULE, "misuse");
	struct device *dev;
	unsigned long flags;

	dev = device_create(cls, NULL, 0, NULL, "m0");
	is_int(DC_EXPECT_BUG(device_create_file(dev, &dev_attr_nostore)), 1,
	       "a writable mode without store is reported when the file is created");
	is_int((int)lx_sysfs_write("/sys/class/misuse/m0/nostore", "1", 1), -EIO, "and a write gets -EIO");
	device_create_file(dev, &dev_attr_big);
	device_create_file(dev, &dev_attr_offpage);
	is_int(DC_EXPECT_BUG(lx_sysfs_read("/sys/class/misuse/m0/big", read_buf, sizeof(read_buf))), 1,
	       "a show() returning a whole page is reported");
	ok(strstr(dc_bug, "bad count") != NULL, "as a bad count (%s)", dc_bug);
	is_int(DC_EXPECT_BUG(lx_sysfs_read("/sys/class/misuse/m0/offpage", read_buf, 8)), 1,
	       "sysfs_emit into a buffer that is not the page is reported");
	spin_lock_irqsave(&test_lock, flags);
	ok(DC_EXPECT_BUG(lx_sysfs_read("/sys/class/misuse/m0/nostore", read_buf, 8)) >= 1,
	   "reading sysfs under a spin lock is reported (it may sleep)");
	spin_unlock_irqrestore(&test_lock, flags);
	device_unregister(dev);
	class_destroy(cls);

	is_int(class_register(&static_class), 0, "class_register of a static class");
	dev = device_create(&static_class, NULL, 0, NULL, "left");
	is_int(DC_EXPECT_BUG(class_unregister(&static_class)), 1, "class_unregister with a device left is reported");
	device_unregister(dev);
}

/* ---- device types: files, uevent variables, release (ev3dev's lego-port is one) ---- */

static int type_released;

static ssize_t port_name_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	return sysfs_emit(buf, "%s\n", dev->type->name);
}
static struct device_attribute dev_attr_port_name = __ATTR(port_name, 0444, port_name_show, NULL);
static struct attribute *port_type_attrs[] = { &dev_attr_port_name.attr, NULL };
ATTRIBUTE_GROUPS(port_type);

static int port_type_uevent(struct device *dev, struct kobj_uevent_env *env)
{
	return add_uevent_var(env, "LEGO_PORT_NAME=%s", dev_name(dev));
}

static int port_class_uevent(struct device *dev, struct kobj_uevent_env *env)
{
	return add_uevent_var(env, "LEGO_CLASS=%s", dev->class->name);
}

static void port_type_release(struct device *dev)
{
	type_released++;
}

static const struct device_type port_type = {
	.name = "ev3-input-port", .groups = port_type_groups, .uevent = port_type_uevent,
	.release = port_type_release,
};
static struct class port_class = { .name = "lego-port", .dev_uevent = port_class_uevent };
static struct device port_dev = { .type = &port_type, .class = &port_class, .init_name = "port0" };

static void device_type_tests(void)
{
	const struct lx_uevent *ev;
	unsigned int ev0;

	is_int(class_register(&port_class), 0, "a class with a dev_uevent");
	ev0 = lx_uevent_count();
	is_int(device_register(&port_dev), 0, "a device of a device type in it");
	ok(!strcmp(cat("/sys/class/lego-port/port0/port_name"), "ev3-input-port\n"),
	   "the type's files are the device's (%s)", read_buf);
	ev = lx_uevent_get(ev0);
	ok(ev && ev->action == KOBJ_ADD && ev->nvars == 2 && !strcmp(ev->vars[0], "LEGO_CLASS=lego-port") &&
	   !strcmp(ev->vars[1], "LEGO_PORT_NAME=port0"),
	   "its uevent carries the class's, then the type's variables");
	device_unregister(&port_dev);
	is_int(type_released, 1, "without a release of its own, the type's releases it");
	class_unregister(&port_class);
}

static void body(void)
{
	class_tests();
	platform_tests();
	misuse_tests();
	device_type_tests();
}

int main(void)
{
	tap_plan(63);
	is_int(hs_board_init(NULL), E_OK, "host_sim board");
	ok(lx_test_run(body), "test task ran to completion");
	hs_board_shutdown();
	return tap_done();
}
