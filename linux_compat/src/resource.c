/*
 * resource.c — claims on I/O memory and port ranges (linux/ioport.h).
 *
 * Claims are kept as a sorted sibling list under each root, so an overlap
 * check walks the claims once; the records come from a fixed pool.
 */
#include <linux/ioport.h>
#include <linux/kernel.h>
#include <linux/string.h>
#include <linux_compat/irq.h>
#include <sil.h>

struct resource iomem_resource = {
	.name = "PCI mem", .start = 0, .end = (resource_size_t)-1, .flags = IORESOURCE_MEM,
};
struct resource ioport_resource = {
	.name = "PCI IO", .start = 0, .end = 0xffff, .flags = IORESOURCE_IO,
};

static struct resource resource_pool[LX_NR_RESOURCES];
static bool resource_in_use[LX_NR_RESOURCES];

/* A free record, or NULL.  Interrupts locked. */
static struct resource *resource_alloc_locked(void)
{
	unsigned int i;

	for (i = 0; i < LX_NR_RESOURCES; i++) {
		if (!resource_in_use[i]) {
			resource_in_use[i] = true;
			return &resource_pool[i];
		}
	}
	return NULL;
}

static void resource_free_locked(struct resource *res)
{
	resource_in_use[res - resource_pool] = false;
}

struct resource *__request_region(struct resource *parent, resource_size_t start,
				  resource_size_t n, const char *name, int flags)
{
	resource_size_t end = start + n - 1;
	struct resource *res = NULL, **link;
	bool conflict = false;
	SIL_PRE_LOC;

	lx_might_sleep("__request_region()", __FILE__, __LINE__);
	if (!parent || n == 0 || end < start || start < parent->start || end > parent->end)
		return NULL;

	SIL_LOC_INT();
	for (link = &parent->child; *link; link = &(*link)->sibling) {
		if ((*link)->start > end)
			break;
		if ((*link)->end >= start) {
			conflict = true;
			break;
		}
	}
	if (!conflict)
		res = resource_alloc_locked();
	if (res) {
		res->start = start;
		res->end = end;
		res->name = name;
		res->flags = resource_type(parent) | IORESOURCE_BUSY | (unsigned long)(unsigned int)flags;
		res->desc = 0;
		res->parent = parent;
		res->child = NULL;
		res->sibling = *link;
		*link = res;
	}
	SIL_UNL_INT();
	if (!conflict && !res)
		pr_err("request region %s [%#llx-%#llx]: all %d resource records in use\n",
		       name ? name : "?", (unsigned long long)start, (unsigned long long)end,
		       LX_NR_RESOURCES);
	return res;
}

void __release_region(struct resource *parent, resource_size_t start, resource_size_t n)
{
	resource_size_t end = start + n - 1;
	struct resource *res = NULL, **link;
	SIL_PRE_LOC;

	lx_might_sleep("__release_region()", __FILE__, __LINE__);
	if (parent) {
		SIL_LOC_INT();
		for (link = &parent->child; *link; link = &(*link)->sibling) {
			if ((*link)->start == start && (*link)->end == end) {
				res = *link;
				*link = res->sibling;
				resource_free_locked(res);
				break;
			}
		}
		SIL_UNL_INT();
	}
	WARN(!res, "Trying to free nonexistent resource <%#llx-%#llx>",
	     (unsigned long long)start, (unsigned long long)end);
}

void lx_resource_boot(void)
{
	iomem_resource.child = NULL;
	ioport_resource.child = NULL;
	memset(resource_pool, 0, sizeof(resource_pool));
	memset(resource_in_use, 0, sizeof(resource_in_use));
}
