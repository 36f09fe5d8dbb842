/*
 * linux/sysfs.h — attributes and attribute groups (Linux 6.1's
 * include/linux/sysfs.h), sysfs_emit and sysfs_notify; implemented by
 * linux_compat/src/sysfs.c, where a device's files are found when they are
 * opened (linux_compat/sysfs.h: lx_sysfs_read/lx_sysfs_write by path).
 *
 * As in Linux, show() fills one page (PAGE_SIZE bytes, page-aligned:
 * sysfs_emit checks it) and returns the bytes it wrote; store() gets a
 * NUL-terminated copy of what was written and its count.  A group's
 * is_visible is asked for each attribute when the file is looked up (Linux
 * asks when the group is created and again at sysfs_update_group).
 */
#ifndef _LINUX_SYSFS_H
#define _LINUX_SYSFS_H

#include <linux/types.h>
#include <linux/compiler.h>
#include <linux/kobject.h>
#include <linux/stat.h>
#include <linux/stringify.h>

struct attribute {
	const char *name;
	umode_t mode;
};

struct bin_attribute;

struct attribute_group {
	const char *name;       /* a subdirectory of the device's directory, or NULL */
	umode_t (*is_visible)(struct kobject *kobj, struct attribute *attr, int n);
	struct attribute **attrs;
	struct bin_attribute **bin_attrs;
};

#define __ATTR(_name, _mode, _show, _store) {				\
	.attr = { .name = __stringify(_name), .mode = (_mode) },	\
	.show = _show,							\
	.store = _store,						\
}
#define __ATTR_RO_MODE(_name, _mode) {					\
	.attr = { .name = __stringify(_name), .mode = (_mode) },	\
	.show = _name##_show,						\
}
#define __ATTR_RO(_name)	__ATTR_RO_MODE(_name, 0444)
#define __ATTR_RW_MODE(_name, _mode)	__ATTR(_name, _mode, _name##_show, _name##_store)
#define __ATTR_RW(_name)	__ATTR(_name, 0644, _name##_show, _name##_store)
#define __ATTR_WO(_name) {						\
	.attr = { .name = __stringify(_name), .mode = 0200 },		\
	.store = _name##_store,						\
}
#define __ATTR_NULL { .attr = { .name = NULL } }

/* foo_groups[] = { &foo_group, NULL } from foo_attrs[] (Linux's macros). */
#define __ATTRIBUTE_GROUPS(_name)					\
static const struct attribute_group *_name##_groups[] = {		\
	&_name##_group,							\
	NULL,								\
}
#define ATTRIBUTE_GROUPS(_name)						\
static const struct attribute_group _name##_group = {			\
	.attrs = _name##_attrs,						\
};									\
__ATTRIBUTE_GROUPS(_name)

/* Formats into a show() buffer (a page): the bytes written, at most
 * PAGE_SIZE - 1; a buffer that is not page-aligned is reported (WARN) and
 * gets nothing (0). */
__printf(2, 3) int sysfs_emit(char *buf, const char *fmt, ...);
/* The same at offset at of the page (0 <= at < PAGE_SIZE, else WARN and 0). */
__printf(3, 4) int sysfs_emit_at(char *buf, int at, const char *fmt, ...);

/* Tells pollers of the attribute attr (in group directory dir, or NULL) of
 * kobj's device that it changed: counted (lx_sysfs_notify_count).  Any
 * context, as Linux's. */
void sysfs_notify(struct kobject *kobj, const char *dir, const char *attr);

#endif /* _LINUX_SYSFS_H */
