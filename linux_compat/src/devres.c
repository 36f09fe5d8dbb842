/*
 * devres.c — managed device resources (linux/device.h states the contract),
 * after Linux 6.1's drivers/base/devres.c, lib/devres.c and
 * kernel/irq/devres.c.  Each resource is a node heading its payload, on the
 * device's list newest first, so releasing from the head releases in
 * reverse order of acquisition.  The list is guarded by a spin lock with
 * interrupts off (a GFP_ATOMIC devm allocation may come from any context);
 * release callbacks run outside it.
 */
#include <linux/device.h>
#include <linux/err.h>
#include <linux/interrupt.h>
#include <linux/io.h>
#include <linux/ioport.h>
#include <linux/kernel.h>
#include <linux/slab.h>
#include <linux/spinlock.h>
#include <linux/string.h>
#include <linux_compat/report.h>

struct lx_devres {
	struct lx_devres *next;
	dr_release_t release;
	u64 data[];             /* the payload, aligned for any member */
};

static DEFINE_SPINLOCK(devres_lock);

/* The node heading payload res. */
static struct lx_devres *to_node(const void *res)
{
	return container_of((u64 *)res, struct lx_devres, data[0]);
}

void *devres_alloc(dr_release_t release, size_t size, gfp_t gfp)
{
	struct lx_devres *dr;

	if (size > SIZE_MAX - sizeof(*dr))
		return NULL;
	dr = kmalloc(sizeof(*dr) + size, gfp);
	if (!dr)
		return NULL;
	dr->next = NULL;
	dr->release = release;
	return dr->data;
}

void devres_free(void *res)
{
	if (res)
		kfree(to_node(res));
}

void devres_add(struct device *dev, void *res)
{
	struct lx_devres *dr;
	unsigned long flags;

	if (!dev || !res) {
		lx_report("devres misuse", __FILE__, __LINE__, "devres_add with a NULL %s",
			  dev ? "resource" : "device");
		return;
	}
	dr = to_node(res);
	spin_lock_irqsave(&devres_lock, flags);
	dr->next = dev->lx_devres;
	dev->lx_devres = dr;
	spin_unlock_irqrestore(&devres_lock, flags);
}

/* Unlinks and returns the newest of dev's nodes with release whose payload
 * match accepts (NULL: any), or NULL. */
static struct lx_devres *devres_remove(struct device *dev, dr_release_t release, dr_match_t match,
				       void *match_data)
{
	struct lx_devres **link, *dr = NULL;
	unsigned long flags;

	spin_lock_irqsave(&devres_lock, flags);
	for (link = &dev->lx_devres; *link; link = &(*link)->next) {
		if ((*link)->release == release && (!match || match(dev, (*link)->data, match_data))) {
			dr = *link;
			*link = dr->next;
			break;
		}
	}
	spin_unlock_irqrestore(&devres_lock, flags);
	return dr;
}

int devres_destroy(struct device *dev, dr_release_t release, dr_match_t match, void *match_data)
{
	struct lx_devres *dr = devres_remove(dev, release, match, match_data);

	if (!dr)
		return -ENOENT;
	kfree(dr);
	return 0;
}

int devres_release(struct device *dev, dr_release_t release, dr_match_t match, void *match_data)
{
	struct lx_devres *dr = devres_remove(dev, release, match, match_data);

	if (!dr)
		return -ENOENT;
	dr->release(dev, dr->data);
	kfree(dr);
	return 0;
}

int devres_release_all(struct device *dev)
{
	struct lx_devres *dr;
	unsigned long flags;
	int n = 0;

	for (;;) {
		spin_lock_irqsave(&devres_lock, flags);
		dr = dev->lx_devres;
		if (dr)
			dev->lx_devres = dr->next;
		spin_unlock_irqrestore(&devres_lock, flags);
		if (!dr)
			return n;
		dr->release(dev, dr->data);
		kfree(dr);
		n++;
	}
}

/* devm_kmalloc's payload is the memory itself: nothing to release but the node. */
static void devm_kmalloc_release(struct device *dev, void *res)
{
}

static int devm_kmalloc_match(struct device *dev, void *res, void *p)
{
	return res == p;
}

void *devm_kmalloc(struct device *dev, size_t size, gfp_t gfp)
{
	void *p;

	if (!dev)
		return NULL;
	p = devres_alloc(devm_kmalloc_release, size, gfp);
	if (!p)
		return NULL;
	devres_add(dev, p);
	return p;
}

void devm_kfree(struct device *dev, const void *p)
{
	if (!p || p == ZERO_SIZE_PTR)
		return;
	if (devres_destroy(dev, devm_kmalloc_release, devm_kmalloc_match, (void *)p))
		lx_warn(__FILE__, __LINE__, "devm_kfree(%s, %p): not memory %s manages",
			dev_name(dev), p, dev_name(dev));
}

char *devm_kstrdup(struct device *dev, const char *s, gfp_t gfp)
{
	size_t len;
	char *p;

	if (!s)
		return NULL;
	len = strlen(s) + 1;
	p = devm_kmalloc(dev, len, gfp);
	if (p)
		memcpy(p, s, len);
	return p;
}

struct action_devres {
	void (*action)(void *);
	void *data;
};

static void devm_action_release(struct device *dev, void *res)
{
	struct action_devres *a = res;

	a->action(a->data);
}

static int devm_action_match(struct device *dev, void *res, void *match_data)
{
	struct action_devres *a = res, *want = match_data;

	return a->action == want->action && a->data == want->data;
}

int devm_add_action(struct device *dev, void (*action)(void *), void *data)
{
	struct action_devres *a;

	if (!dev || !action) {
		lx_report("devres misuse", __FILE__, __LINE__, "devm_add_action with a NULL %s",
			  dev ? "action" : "device");
		return -EINVAL;
	}
	a = devres_alloc(devm_action_release, sizeof(*a), GFP_KERNEL);
	if (!a)
		return -ENOMEM;
	a->action = action;
	a->data = data;
	devres_add(dev, a);
	return 0;
}

void devm_remove_action(struct device *dev, void (*action)(void *), void *data)
{
	struct action_devres want = { action, data };

	if (devres_destroy(dev, devm_action_release, devm_action_match, &want))
		lx_warn(__FILE__, __LINE__, "devm_remove_action(%s): no such action", dev_name(dev));
}

void devm_release_action(struct device *dev, void (*action)(void *), void *data)
{
	struct action_devres want = { action, data };

	if (devres_release(dev, devm_action_release, devm_action_match, &want))
		lx_warn(__FILE__, __LINE__, "devm_release_action(%s): no such action", dev_name(dev));
}

struct irq_devres {
	unsigned int irq;
	void *dev_id;
};

static void devm_irq_release(struct device *dev, void *res)
{
	struct irq_devres *r = res;

	free_irq(r->irq, r->dev_id);
}

static int devm_irq_match(struct device *dev, void *res, void *data)
{
	struct irq_devres *r = res, *want = data;

	return r->irq == want->irq && r->dev_id == want->dev_id;
}

int devm_request_threaded_irq(struct device *dev, unsigned int irq, irq_handler_t handler,
			      irq_handler_t thread_fn, unsigned long irqflags, const char *devname,
			      void *dev_id)
{
	struct irq_devres *r;
	int rc;

	r = devres_alloc(devm_irq_release, sizeof(*r), GFP_KERNEL);
	if (!r)
		return -ENOMEM;
	if (!devname)
		devname = dev_name(dev);
	rc = request_threaded_irq(irq, handler, thread_fn, irqflags, devname, dev_id);
	if (rc) {
		devres_free(r);
		return rc;
	}
	r->irq = irq;
	r->dev_id = dev_id;
	devres_add(dev, r);
	return 0;
}

void devm_free_irq(struct device *dev, unsigned int irq, void *dev_id)
{
	struct irq_devres want = { irq, dev_id };

	if (devres_release(dev, devm_irq_release, devm_irq_match, &want))
		lx_warn(__FILE__, __LINE__, "devm_free_irq(%s, %u): not an IRQ %s manages",
			dev_name(dev), irq, dev_name(dev));
}

struct region_devres {
	resource_size_t start, n;
};

static void devm_region_release(struct device *dev, void *res)
{
	struct region_devres *r = res;

	release_mem_region(r->start, r->n);
}

static void devm_ioremap_release(struct device *dev, void *res)
{
	iounmap(*(void __iomem **)res);
}

void __iomem *devm_ioremap(struct device *dev, resource_size_t offset, resource_size_t size)
{
	void __iomem **ptr, *addr;

	ptr = devres_alloc(devm_ioremap_release, sizeof(*ptr), GFP_KERNEL);
	if (!ptr)
		return NULL;
	addr = ioremap(offset, size);
	if (!addr) {
		devres_free(ptr);
		return NULL;
	}
	*ptr = addr;
	devres_add(dev, ptr);
	return addr;
}

void __iomem *devm_ioremap_resource(struct device *dev, const struct resource *res)
{
	struct region_devres *region;
	void __iomem *addr;
	resource_size_t size;

	if (!res || resource_type(res) != IORESOURCE_MEM) {
		dev_err(dev, "invalid resource %s\n", res ? "(not memory)" : "(none)");
		return IOMEM_ERR_PTR(-EINVAL);
	}
	size = resource_size(res);
	region = devres_alloc(devm_region_release, sizeof(*region), GFP_KERNEL);
	if (!region)
		return IOMEM_ERR_PTR(-ENOMEM);
	if (!request_mem_region(res->start, size, res->name ? res->name : dev_name(dev))) {
		devres_free(region);
		dev_err(dev, "can't request region for resource [mem %#llx-%#llx]\n",
			(unsigned long long)res->start, (unsigned long long)res->end);
		return IOMEM_ERR_PTR(-EBUSY);
	}
	region->start = res->start;
	region->n = size;
	devres_add(dev, region);
	addr = devm_ioremap(dev, res->start, size);
	if (!addr) {
		devres_release(dev, devm_region_release, NULL, NULL);
		dev_err(dev, "ioremap failed for resource [mem %#llx-%#llx]\n",
			(unsigned long long)res->start, (unsigned long long)res->end);
		return IOMEM_ERR_PTR(-ENOMEM);
	}
	return addr;
}
