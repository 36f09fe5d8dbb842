/*
 * of.c — matching board nodes against of_match_table (linux/of.h), after
 * Linux 6.1's drivers/of/base.c (__of_device_is_compatible, of_match_node)
 * and drivers/of/device.c (of_device_get_match_data): of the table entries
 * that match, the one fitting the node's earliest compatible wins.
 */
#include <linux/of.h>
#include <linux/of_device.h>
#include <linux/property.h>
#include <linux/device.h>
#include <linux/string.h>

/* How well entry fits node: 0 no; higher for an earlier compatible. */
static int entry_score(const struct of_device_id *entry, const struct device_node *node)
{
	int score = 0;

	if (entry->name[0] && (!node->name || strcmp(entry->name, node->name)))
		return 0;
	if (entry->type[0] && (!node->type || strcmp(entry->type, node->type)))
		return 0;
	if (entry->compatible[0]) {
		score = of_device_is_compatible(node, entry->compatible);
		if (!score)
			return 0;
	}
	return score + (entry->name[0] ? 2 : 0) + (entry->type[0] ? 1 : 0);
}

int of_device_is_compatible(const struct device_node *node, const char *compat)
{
	const char *const *c;
	int index = 0;

	if (!node || !node->compatible || !compat)
		return 0;
	for (c = node->compatible; *c; c++, index++)
		if (!strcasecmp(*c, compat))
			return (256 - index) * 4;   /* Linux's INT_MAX/2 - (index << 2), scaled */
	return 0;
}

const struct of_device_id *of_match_node(const struct of_device_id *matches,
					 const struct device_node *node)
{
	const struct of_device_id *best = NULL;
	int score, best_score = 0;

	if (!matches || !node)
		return NULL;
	for (; matches->name[0] || matches->type[0] || matches->compatible[0]; matches++) {
		score = entry_score(matches, node);
		if (score > best_score) {
			best = matches;
			best_score = score;
		}
	}
	return best;
}

const struct of_device_id *of_match_device(const struct of_device_id *matches,
					   const struct device *dev)
{
	return dev ? of_match_node(matches, dev->of_node) : NULL;
}

const void *of_device_get_match_data(const struct device *dev)
{
	const struct of_device_id *match;

	if (!dev || !dev->driver)
		return NULL;
	match = of_match_device(dev->driver->of_match_table, dev);
	return match ? match->data : NULL;
}

const void *device_get_match_data(const struct device *dev)
{
	return of_device_get_match_data(dev);
}
