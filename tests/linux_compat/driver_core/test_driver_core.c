/*
 * test_driver_core.c — buses, devices and drivers (drivers/base/dd.c's
 * rules): binding whichever of device and driver comes first, the bus's
 * match, probe failure unwinding devres in reverse and clearing driver and
 * drvdata, silent -ENODEV, the next driver trying after a failure, deferred
 * probe retried when another device binds, remove before devres on unbind,
 * the most recent binding undone first, a probe registering a child,
 * dev_err_probe, reference counting, and the misuse reported.
 */
#include "lx_log_test.h"
#include <linux/device.h>
#include <linux/errno.h>
#include <linux/slab.h>
#include <linux/spinlock.h>

static char trail[512];

/* Appends a step to the trail the assertions read. */
static void step(const char *fmt, const char *name)
{
	char s[64];

	snprintf(s, sizeof(s), fmt, name);
	strncat(trail, s, sizeof(trail) - strlen(trail) - 1);
}

/* A bus that matches a device to a driver whose name starts its own. */
static int prefix_match(struct device *dev, struct device_driver *drv)
{
	return strncmp(dev_name(dev), drv->name, strlen(drv->name)) == 0;
}

static struct bus_type test_bus = { .name = "testbus", .match = prefix_match };

static void released(struct device *dev)
{
	step("rel:%s ", dev_name(dev));
}

static void undo(void *data)
{
	step("undo:%s ", data);
}

static int probe_result;
static bool supplier_ready;
static struct device child;

static int good_probe(struct device *dev)
{
	step("probe:%s ", dev_name(dev));
	if (!devm_kzalloc(dev, 32, GFP_KERNEL))
		return -ENOMEM;
	if (devm_add_action_or_reset(dev, undo, "first") || devm_add_action_or_reset(dev, undo, "second"))
		return -ENOMEM;
	dev_set_drvdata(dev, dev);
	return 0;
}

static int good_remove(struct device *dev)
{
	step("remove:%s ", dev_name(dev));
	return 0;
}

/* Acquires two resources, then fails with probe_result. */
static int failing_probe(struct device *dev)
{
	step("fprobe:%s ", dev_name(dev));
	devm_add_action(dev, undo, "a");
	devm_add_action(dev, undo, "b");
	dev_set_drvdata(dev, dev);
	return probe_result;
}

/* Defers until the supplier has bound. */
static int consumer_probe(struct device *dev)
{
	step("cprobe:%s ", dev_name(dev));
	devm_add_action(dev, undo, "c");
	if (!supplier_ready)
		return dev_err_probe(dev, -EPROBE_DEFER, "supplier not ready\n");
	return 0;
}

static int supplier_probe(struct device *dev)
{
	step("sprobe:%s ", dev_name(dev));
	supplier_ready = true;
	return 0;
}

/* Registers a child device that the "child" driver binds on the spot. */
static int parent_probe(struct device *dev)
{
	int ret;

	step("pprobe:%s ", dev_name(dev));
	device_initialize(&child);
	dev_set_name(&child, "childdev");
	child.parent = dev;
	child.bus = &test_bus;
	child.release = released;
	ret = device_add(&child);
	step(child.driver ? "child-bound%s " : "child-unbound%s ", "");
	return ret;
}

static int parent_remove(struct device *dev)
{
	device_unregister(&child);
	return 0;
}

static struct device_driver good = { .name = "good", .bus = &test_bus, .probe = good_probe,
				     .remove = good_remove };
static struct device_driver good_again = { .name = "good", .bus = &test_bus };
static struct device_driver failing = { .name = "fail", .bus = &test_bus, .probe = failing_probe };
static struct device_driver fail_fallback = { .name = "failo", .bus = &test_bus, .probe = good_probe,
					      .remove = good_remove };
static struct device_driver consumer = { .name = "cons", .bus = &test_bus, .probe = consumer_probe };
static struct device_driver supplier = { .name = "supp", .bus = &test_bus, .probe = supplier_probe };
static struct device_driver parent_drv = { .name = "parent", .bus = &test_bus, .probe = parent_probe,
					   .remove = parent_remove };
static struct device_driver child_drv = { .name = "child", .bus = &test_bus, .probe = good_probe,
					  .remove = good_remove };

static struct device good1, good2, fail1, fail2, cons1, supp1, par1, nobus;

/* Names and registers dev on the test bus. */
static int add(struct device *dev, const char *name)
{
	memset(dev, 0, sizeof(*dev));
	dev_set_name(dev, "%s", name);
	dev->bus = &test_bus;
	dev->release = released;
	return device_register(dev);
}

static void binding_tests(void)
{
	is_int(bus_register(&test_bus), 0, "bus_register");
	is_int(bus_register(&test_bus), -EBUSY, "the same bus twice: -EBUSY");

	trail[0] = '\0';
	is_int(add(&good1, "good1"), 0, "a device before its driver registers");
	ok(good1.driver == NULL, "... and stays unbound");
	is_int(driver_register(&good), 0, "driver_register");
	ok(good1.driver == &good && dev_get_drvdata(&good1) == &good1 && device_is_bound(&good1),
	   "the waiting device bound at driver_register, drvdata set by probe");
	is_int(add(&good2, "good2"), 0, "a device after its driver");
	ok(good2.driver == &good, "bound at device_add");
	is_int(driver_register(&good_again), -EBUSY, "a second driver of the same name on the bus: -EBUSY");
	ok(driver_find("good", &test_bus) == &good && driver_find("none", &test_bus) == NULL, "driver_find");
	is_int(add(&nobus, "other"), 0, "a device no driver matches");
	ok(nobus.driver == NULL, "the bus's match keeps it unbound");
	is_str(trail, "probe:good1 probe:good2 ", "each probed once, in order");

	trail[0] = '\0';
	driver_unregister(&good);
	is_str(trail, "remove:good2 undo:second undo:first remove:good1 undo:second undo:first ",
	       "driver_unregister: most recent binding first, remove then devres in reverse");
	ok(!good1.driver && !good2.driver && !dev_get_drvdata(&good1), "both unbound, drvdata cleared");
	ok(good1.lx_devres == NULL, "no devres left");
	trail[0] = '\0';
	device_unregister(&good1);
	device_unregister(&good2);
	device_unregister(&nobus);
	is_str(trail, "rel:good1 rel:good2 rel:other ", "device_unregister drops the last reference: release");
}

static void failure_tests(void)
{
	dc_log_start();
	trail[0] = '\0';
	probe_result = -EIO;
	is_int(driver_register(&failing), 0, "a driver whose probe fails registers");
	is_int(driver_register(&fail_fallback), 0, "a second driver matching the same devices");
	is_int(add(&fail1, "failone"), 0, "device_add");
	is_str(trail, "fprobe:failone undo:b undo:a probe:failone ",
	       "a failed probe releases its devres in reverse, then the next driver tries");
	ok(fail1.driver == &fail_fallback, "bound to the next driver");
	ok(dc_logged("fail: probe of failone failed with error -5"), "the failure is logged as Linux logs it");
	driver_unregister(&fail_fallback);

	dc_log_start();
	trail[0] = '\0';
	probe_result = -ENODEV;
	is_int(add(&fail2, "failtwo"), 0, "a device whose probe says -ENODEV");
	ok(fail2.driver == NULL && dev_get_drvdata(&fail2) == NULL, "unbound, drvdata cleared");
	is_str(trail, "fprobe:failtwo undo:b undo:a ", "devres released");
	ok(!dc_logged("failtwo"), "-ENODEV is not logged");
	device_unregister(&fail2);
	driver_unregister(&failing);
	device_unregister(&fail1);
}

static void deferred_tests(void)
{
	dc_log_start();
	trail[0] = '\0';
	supplier_ready = false;
	is_int(driver_register(&consumer), 0, "consumer driver");
	is_int(driver_register(&supplier), 0, "supplier driver");
	is_int(add(&cons1, "cons1"), 0, "consumer device");
	ok(cons1.driver == NULL, "its probe deferred");
	is_int(lx_deferred_probe_count(), 1, "one device waits on the deferred list");
	ok(!dc_logged("supplier not ready") && !dc_logged("cons1"), "dev_err_probe(-EPROBE_DEFER) logs nothing");
	is_int(add(&supp1, "supp1"), 0, "supplier device");
	is_str(trail, "cprobe:cons1 undo:c sprobe:supp1 cprobe:cons1 ",
	       "the supplier binding retried the deferred consumer, which bound");
	ok(cons1.driver == &consumer, "consumer bound");
	is_int(lx_deferred_probe_count(), 0, "deferred list empty");
	device_unregister(&cons1);
	device_unregister(&supp1);
	driver_unregister(&consumer);
	driver_unregister(&supplier);

	supplier_ready = false;
	is_int(driver_register(&consumer), 0, "consumer again");
	is_int(add(&cons1, "cons1"), 0, "a device that defers");
	is_int(lx_deferred_probe_count(), 1, "deferred");
	device_unregister(&cons1);
	is_int(lx_deferred_probe_count(), 0, "device_unregister takes it off the deferred list");
	driver_unregister(&consumer);
}

static void reentry_tests(void)
{
	trail[0] = '\0';
	is_int(driver_register(&child_drv), 0, "child driver");
	is_int(driver_register(&parent_drv), 0, "parent driver");
	is_int(add(&par1, "parent1"), 0, "a parent whose probe adds a child");
	is_str(trail, "pprobe:parent1 probe:childdev child-bound ", "the child bound during the parent's probe");
	ok(child.parent == &par1 && par1.driver == &parent_drv, "both bound");
	trail[0] = '\0';
	device_unregister(&par1);
	is_str(trail, "remove:childdev undo:second undo:first rel:childdev rel:parent1 ",
	       "the parent's remove unregistered the child first");
	driver_unregister(&parent_drv);
	driver_unregister(&child_drv);
}

static void dev_err_probe_tests(void)
{
	struct device d = { .init_name = "errdev" };

	dc_log_start();
	is_int(dev_err_probe(&d, -EIO, "clock %s missing\n", "ref"), -EIO, "dev_err_probe returns the error");
	ok(dc_logged("errdev: error -5: clock ref missing"), "and logs it with the device");
}

static DEFINE_SPINLOCK(test_lock);

static void misuse_tests(void)
{
	struct device raw = { .init_name = "raw" };
	struct device norel;
	unsigned long flags;
	int ret = 0;

	is_int(DC_EXPECT_BUG(ret = device_add(&raw)), 1, "device_add before device_initialize is reported");
	ok(ret == -EINVAL && strstr(dc_bug, "device_initialize") != NULL, "... and refused: %s", dc_bug);
	is_int(DC_EXPECT_BUG(device_del(&raw)), 1, "device_del of a device never added is reported");

	memset(&norel, 0, sizeof(norel));
	dev_set_name(&norel, "norel");
	device_initialize(&norel);
	is_int(DC_EXPECT_BUG(put_device(&norel)), 1, "the last put_device of a device without release");
	ok(strstr(dc_bug, "does not have a release() function") != NULL, "warns as Linux does: %s", dc_bug);
	is_int(DC_EXPECT_BUG(put_device(&norel)), 1, "put_device without a reference is reported");

	spin_lock_irqsave(&test_lock, flags);
	ok(DC_EXPECT_BUG(ret = driver_register(&good)) >= 1, "driver_register under a spin lock");
	spin_unlock_irqrestore(&test_lock, flags);
	ok(strstr(dc_bug, "sleeping function called from invalid context") != NULL &&
	   ret == 0, "reported as might_sleep (and registered): %s", dc_bug);
	driver_unregister(&good);
	is_int(DC_EXPECT_BUG(driver_unregister(&good)), 1, "driver_unregister of a driver not registered");
}

static void body(void)
{
	binding_tests();
	failure_tests();
	deferred_tests();
	reentry_tests();
	dev_err_probe_tests();
	misuse_tests();
	bus_unregister(&test_bus);
}

int main(void)
{
	tap_plan(59);
	ok(lx_test_run(body), "test task ran to completion");
	return tap_done();
}
