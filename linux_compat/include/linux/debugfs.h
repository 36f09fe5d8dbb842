/*
 * linux/debugfs.h — debugfs is not built in: as in Linux with
 * CONFIG_DEBUG_FS=n, every call is an inline stub that creates nothing and
 * returns ERR_PTR(-ENODEV) (the value callers are told to ignore).
 */
#ifndef _LINUX_DEBUGFS_H
#define _LINUX_DEBUGFS_H

#include <linux/types.h>
#include <linux/errno.h>
#include <linux/compiler.h>

struct dentry;
struct file_operations;

/* ERR_PTR(-ENODEV) without needing linux/err.h. */
#define __lx_debugfs_nodev	((struct dentry *)(long)-ENODEV)

static inline struct dentry *debugfs_create_dir(const char *name, struct dentry *parent)
{
	(void)name;
	(void)parent;
	return __lx_debugfs_nodev;
}
static inline struct dentry *debugfs_create_file(const char *name, umode_t mode, struct dentry *parent,
						 void *data, const struct file_operations *fops)
{
	(void)name;
	(void)mode;
	(void)parent;
	(void)data;
	(void)fops;
	return __lx_debugfs_nodev;
}
static inline void debugfs_create_u8(const char *name, umode_t mode, struct dentry *parent, u8 *value)
{
	(void)name; (void)mode; (void)parent; (void)value;
}
static inline void debugfs_create_u16(const char *name, umode_t mode, struct dentry *parent, u16 *value)
{
	(void)name; (void)mode; (void)parent; (void)value;
}
static inline void debugfs_create_u32(const char *name, umode_t mode, struct dentry *parent, u32 *value)
{
	(void)name; (void)mode; (void)parent; (void)value;
}
static inline void debugfs_create_bool(const char *name, umode_t mode, struct dentry *parent, bool *value)
{
	(void)name; (void)mode; (void)parent; (void)value;
}
static inline void debugfs_remove(struct dentry *dentry)		{ (void)dentry; }
static inline void debugfs_remove_recursive(struct dentry *dentry)	{ (void)dentry; }
static inline bool debugfs_initialized(void)				{ return false; }

#endif /* _LINUX_DEBUGFS_H */
