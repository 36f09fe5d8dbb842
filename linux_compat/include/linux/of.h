/*
 * linux/of.h — device-tree nodes as board code describes them here: there is
 * no flattened tree and no .dtb parser; a board file (or a hack) writes a
 * struct device_node for each device with its compatible list, most specific
 * first, and sets it as the device's of_node (platform_device.dev.of_node).
 * Matching follows Linux 6.1's drivers/of/base.c: of_match_node prefers the
 * table entry matching the node's earliest compatible string.
 * Implemented by linux_compat/src/of.c.
 */
#ifndef _LINUX_OF_H
#define _LINUX_OF_H

#include <linux/types.h>
#include <linux/string.h>
#include <linux/mod_devicetable.h>

struct device;

struct device_node {
	const char *name;
	const char *full_name;
	const char *type;
	const char *const *compatible;  /* ev3lx: NULL-terminated, most specific first */
	struct device_node *parent;
	void *data;
};

/* The table itself: board nodes exist in every build (CONFIG_OF, in effect). */
#define of_match_ptr(ptr)	(ptr)

/* A positive score if node lists compat (higher for earlier entries), else 0. */
int of_device_is_compatible(const struct device_node *node, const char *compat);
/* The entry of matches that best fits node (earliest compatible), or NULL. */
const struct of_device_id *of_match_node(const struct of_device_id *matches,
					 const struct device_node *node);
/* of_match_node on dev's of_node. */
const struct of_device_id *of_match_device(const struct of_device_id *matches,
					   const struct device *dev);
/* Whether np's device_type is type. */
static inline bool of_node_is_type(const struct device_node *np, const char *type)
{
	return np && np->type && type && !strcmp(np->type, type);
}
static inline struct device_node *of_node_get(struct device_node *node)
{
	return node;
}
static inline void of_node_put(struct device_node *node)
{
	(void)node;
}

#endif /* _LINUX_OF_H */
