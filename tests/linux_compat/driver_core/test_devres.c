/*
 * test_devres.c — managed resources (drivers/base/devres.c's rules) on a
 * bare device: reverse order of release, devm_kfree and devm_kstrdup,
 * devm_add_action_or_reset calling the action when it cannot be added,
 * devm_remove_action/devm_release_action, devres_release_all on the last
 * put_device of an unbound device, and misuse reported: devm_kfree of
 * memory the device does not manage, a NULL action, removing an action
 * never added, and a GFP_KERNEL devm allocation under a spin lock.
 */
#include "lx_log_test.h"
#include <linux/device.h>
#include <linux/errno.h>
#include <linux/slab.h>
#include <linux/spinlock.h>
#include <linux_compat/fault_inject.h>

static char trail[256];

static void note(void *data)
{
	strncat(trail, data, sizeof(trail) - strlen(trail) - 1);
}

static void released(struct device *dev)
{
	note("rel ");
}

static DEFINE_SPINLOCK(test_lock);

static void body(void)
{
	struct device dev;
	unsigned long flags;
	char *s, *p, *q;
	void *unmanaged;

	memset(&dev, 0, sizeof(dev));
	dev_set_name(&dev, "devres0");
	dev.release = released;
	device_initialize(&dev);

	p = devm_kzalloc(&dev, 100, GFP_KERNEL);
	ok(p && p[0] == 0 && p[99] == 0, "devm_kzalloc gives zeroed memory");
	q = devm_kmalloc_array(&dev, 4, sizeof(int), GFP_KERNEL);
	ok(q != NULL, "devm_kmalloc_array");
	ok(devm_kmalloc_array(&dev, SIZE_MAX / 2, 4, GFP_KERNEL) == NULL, "an overflowing array size: NULL");
	s = devm_kstrdup(&dev, "name", GFP_KERNEL);
	ok(s && !strcmp(s, "name"), "devm_kstrdup");
	is_int(devm_add_action(&dev, note, "one "), 0, "devm_add_action");
	is_int(devm_add_action(&dev, note, "two "), 0, "a second action");
	is_int(devm_add_action(&dev, note, "three "), 0, "a third action");
	devm_kfree(&dev, q);
	devm_remove_action(&dev, note, "two ");
	is_str(trail, "", "devm_kfree and devm_remove_action run nothing");
	devm_release_action(&dev, note, "three ");
	is_str(trail, "three ", "devm_release_action runs the action now");

	trail[0] = '\0';
	lx_fail_alloc_nth(lx_alloc_attempts() + 1);
	is_int(devm_add_action_or_reset(&dev, note, "reset "), -ENOMEM, "devm_add_action_or_reset out of memory");
	lx_fail_alloc_off();
	is_str(trail, "reset ", "... calls the action at once");

	trail[0] = '\0';
	is_int(devm_add_action(&dev, note, "four "), 0, "a fourth action");
	is_int(devres_release_all(&dev), 4, "devres_release_all released the four left (two allocations, two actions)");
	is_str(trail, "four one ", "the actions ran newest first");

	unmanaged = kmalloc(8, GFP_KERNEL);
	is_int(DC_EXPECT_BUG(devm_kfree(&dev, unmanaged)), 1, "devm_kfree of memory the device does not manage");
	ok(strstr(dc_bug, "devm_kfree") != NULL, "is reported: %s", dc_bug);
	kfree(unmanaged);
	is_int(DC_EXPECT_BUG(devm_add_action(&dev, NULL, NULL)), 1, "devm_add_action without an action");
	ok(strstr(dc_bug, "devres misuse") != NULL, "is reported as devres misuse: %s", dc_bug);
	is_int(DC_EXPECT_BUG(devm_remove_action(&dev, note, "never ")), 1, "removing an action never added");

	spin_lock_irqsave(&test_lock, flags);
	ok(DC_EXPECT_BUG(p = devm_kzalloc(&dev, 16, GFP_KERNEL)) >= 1, "devm_kzalloc(GFP_KERNEL) under a spin lock");
	spin_unlock_irqrestore(&test_lock, flags);
	ok(strstr(dc_bug, "GFP_KERNEL") != NULL || strstr(dc_bug, "sleeping") != NULL,
	   "is reported as kmalloc reports it: %s", dc_bug);

	trail[0] = '\0';
	is_int(devm_add_action(&dev, note, "last "), 0, "an action on an unbound device");
	put_device(&dev);
	is_str(trail, "last rel ", "the last put_device releases its devres, then the device");
}

int main(void)
{
	tap_plan(24);
	ok(lx_test_run(body), "test task ran to completion");
	return tap_done();
}
