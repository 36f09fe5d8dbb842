/*
 * test_platform.c — the platform bus (drivers/base/platform.c's rules) on
 * the host_sim board: device names from name and id (none, numbered, auto),
 * matching by of_match_table compatible on a board node (the earliest
 * compatible winning), by id_table (platform_get_device_id) and by name,
 * driver_override; resources and IRQs; devm_platform_ioremap_resource
 * claiming the region until unbind; devm_request_irq freed on unbind and on
 * probe failure; module_platform_driver's init and exit; platform_driver_probe;
 * allocated devices freed by their last reference.
 */
#define KBUILD_MODNAME "pltest"
#include "lx_log_test.h"
#include <linux/platform_device.h>
#include <linux/interrupt.h>
#include <linux/io.h>
#include <linux/of.h>
#include <linux/of_device.h>
#include <linux/property.h>
#include <linux/slab.h>
#include <mach/da8xx.h>
#include <mach/irqs.h>
#include "host_sim/board.h"

#define TEST_IRQ	IRQ_DA8XX_UARTINT0

static char trail[256];
static void __iomem *mapped;
static const void *match_data;
static kernel_ulong_t id_data;
static int irq_seen;
static int fail_after_irq;

static irqreturn_t test_handler(int irq, void *dev)
{
	return IRQ_HANDLED;
}

/* Maps the registers, takes the IRQ, records what matched. */
static int full_probe(struct platform_device *pdev)
{
	const struct platform_device_id *id = platform_get_device_id(pdev);
	int irq, ret;

	strncat(trail, dev_name(&pdev->dev), sizeof(trail) - strlen(trail) - 2);
	strcat(trail, " ");
	match_data = device_get_match_data(&pdev->dev);
	id_data = id ? id->driver_data : 0;
	mapped = devm_platform_ioremap_resource(pdev, 0);
	if (IS_ERR(mapped))
		return PTR_ERR(mapped);
	irq = platform_get_irq(pdev, 0);
	if (irq < 0)
		return irq;
	irq_seen = irq;
	ret = devm_request_irq(&pdev->dev, (unsigned int)irq, test_handler, 0, NULL, pdev);
	if (ret)
		return dev_err_probe(&pdev->dev, ret, "cannot take IRQ %d\n", irq);
	platform_set_drvdata(pdev, pdev);
	return fail_after_irq;
}

static int full_remove(struct platform_device *pdev)
{
	strcat(trail, "remove ");
	return 0;
}

static const struct of_device_id test_of_ids[] = {
	{ .compatible = "lego,ev3-test-v1", .data = "v1" },
	{ .compatible = "lego,ev3-test-v2", .data = "v2" },
	{ }
};

static const struct platform_device_id test_ids[] = {
	{ "ev3-test-a", 0xa },
	{ "ev3-test-b", 0xb },
	{ }
};

static struct platform_driver of_driver = {
	.probe = full_probe, .remove = full_remove,
	.driver = { .name = "ev3-test-of", .of_match_table = of_match_ptr(test_of_ids) },
};
static struct platform_driver id_driver = {
	.probe = full_probe, .remove = full_remove, .id_table = test_ids,
	.driver = { .name = "ev3-test-ids" },
};

static const char *const node_compat[] = { "lego,ev3-test-v2", "lego,ev3-test-v1", NULL };
static struct device_node test_node = { .name = "test", .full_name = "/test@1e26000",
					.compatible = node_compat };

static struct resource test_res[] = {
	DEFINE_RES_MEM(DA8XX_GPIO_BASE, 0x100),
	DEFINE_RES_IRQ(TEST_IRQ),
};

static void pdev_release(struct device *dev)
{
	strcat(trail, "release ");
}

static struct platform_device of_dev = {
	.name = "whatever", .id = PLATFORM_DEVID_NONE, .resource = test_res,
	.num_resources = ARRAY_SIZE(test_res), .dev = { .of_node = &test_node, .release = pdev_release },
};
static struct platform_device b_dev = {
	.name = "ev3-test-b", .id = 3, .resource = test_res,
	.num_resources = ARRAY_SIZE(test_res), .dev = { .release = pdev_release },
};

static void matching_tests(void)
{
	struct resource *r;

	trail[0] = '\0';
	is_int(platform_device_register(&of_dev), 0, "a device with a board node");
	is_str(dev_name(&of_dev.dev), "whatever", "PLATFORM_DEVID_NONE: named after the device");
	ok(of_dev.dev.parent == &platform_bus && dev_is_platform(&of_dev.dev), "under the platform bus");
	is_int(platform_driver_register(&of_driver), 0, "a driver with an of_match_table");
	ok(of_dev.dev.driver == &of_driver.driver, "bound by compatible");
	ok(match_data && !strcmp(match_data, "v2"), "the node's earliest compatible wins: %s",
	   match_data ? (const char *)match_data : "(none)");
	ok(of_device_get_match_data(&of_dev.dev) == match_data, "of_device_get_match_data");
	ok(mapped && !IS_ERR(mapped), "devm_platform_ioremap_resource mapped the registers");
	is_int(irq_seen, TEST_IRQ, "platform_get_irq");
	ok(platform_get_drvdata(&of_dev) == &of_dev, "drvdata");
	r = platform_get_resource(&of_dev, IORESOURCE_MEM, 0);
	ok(r == &test_res[0] && platform_get_resource(&of_dev, IORESOURCE_MEM, 1) == NULL,
	   "platform_get_resource by type and index");
	is_int(platform_irq_count(&of_dev), 1, "platform_irq_count");
	is_int(of_device_is_compatible(&test_node, "lego,ev3-test-v1") > 0, 1, "of_device_is_compatible");
	ok(request_mem_region(DA8XX_GPIO_BASE, 0x100, "other") == NULL, "the region is claimed while bound");
	is_int(request_irq(TEST_IRQ, test_handler, 0, "other", &trail), -EBUSY, "the IRQ is taken while bound");

	is_int(platform_device_register(&b_dev), 0, "a second device on the same region");
	is_str(dev_name(&b_dev.dev), "ev3-test-b.3", "a numbered device: <name>.<id>");
	ok(b_dev.dev.driver == NULL, "no driver for it yet");
	dc_log_start();
	is_int(platform_driver_register(&id_driver), 0, "a driver with an id_table");
	ok(b_dev.dev.driver == NULL, "its probe failed");
	ok(dc_logged("can't request region for resource"), "devm_ioremap_resource logs the busy region");
	ok(dc_logged("probe of ev3-test-b.3 failed with error -16"), "and the probe fails with -EBUSY");
	ok(of_dev.dev.driver == &of_driver.driver, "the node's device stays with its driver");

	platform_driver_unregister(&of_driver);
	ok(of_dev.dev.driver == NULL && !platform_get_drvdata(&of_dev), "unbound by driver_unregister");
	ok(request_mem_region(DA8XX_GPIO_BASE, 0x100, "other") != NULL, "the region released on unbind");
	release_mem_region(DA8XX_GPIO_BASE, 0x100);
	is_int(request_irq(TEST_IRQ, test_handler, 0, "other", &trail), 0, "the IRQ freed on unbind");
	free_irq(TEST_IRQ, &trail);

	match_data = NULL;
	is_int(device_attach(&b_dev.dev), 1, "device_attach tries the drivers again");
	ok(b_dev.dev.driver == &id_driver.driver, "bound by its id_table");
	is_int((int)id_data, 0xb, "platform_get_device_id gives the entry's driver_data");
	ok(match_data == NULL, "no match data without a board node");
	ok(of_dev.dev.driver == NULL, "the node's device matches no id");
	trail[0] = '\0';
	platform_driver_unregister(&id_driver);
	is_str(trail, "remove ", "platform_driver's remove on unbind");

	trail[0] = '\0';
	platform_device_unregister(&of_dev);
	platform_device_unregister(&b_dev);
	is_str(trail, "release release ", "unregistered devices released");
}

static void failure_tests(void)
{
	struct platform_device *pdev;

	dc_log_start();
	fail_after_irq = -EIO;
	is_int(platform_driver_register(&id_driver), 0, "a driver whose probe fails after taking the IRQ");
	pdev = platform_device_register_simple("ev3-test-a", PLATFORM_DEVID_AUTO, test_res, ARRAY_SIZE(test_res));
	ok(!IS_ERR(pdev), "platform_device_register_simple with an auto id");
	is_str(dev_name(&pdev->dev), "ev3-test-a.0.auto", "named <name>.<n>.auto");
	ok(pdev->dev.driver == NULL, "the probe failed");
	is_int(request_irq(TEST_IRQ, test_handler, 0, "other", &trail), 0, "its devm IRQ was freed by the failure");
	free_irq(TEST_IRQ, &trail);
	ok(request_mem_region(DA8XX_GPIO_BASE, 0x100, "other") != NULL, "and its region");
	release_mem_region(DA8XX_GPIO_BASE, 0x100);
	platform_device_unregister(pdev);
	platform_driver_unregister(&id_driver);
	fail_after_irq = 0;

	pdev = platform_device_alloc("ev3-test-none", 1);
	is_int(platform_device_add_resources(pdev, test_res, 1), 0, "a device with only a memory resource");
	is_int(platform_device_add(pdev), 0, "platform_device_add");
	dc_log_start();
	is_int(platform_get_irq(pdev, 0), -ENXIO, "platform_get_irq without an IRQ: -ENXIO");
	ok(dc_logged("ev3-test-none.1: error -6: IRQ index 0 not found"), "logged as Linux logs it");
	is_int(platform_get_irq_optional(pdev, 0), -ENXIO, "platform_get_irq_optional");
	platform_device_unregister(pdev);
}

static int probes_of_simple;

static int simple_probe(struct platform_device *pdev)
{
	probes_of_simple++;
	return 0;
}

static struct platform_driver simple_driver = {
	.probe = simple_probe, .driver = { .name = "ev3-test-simple" },
};
module_platform_driver(simple_driver);

static struct platform_driver once_driver = { .driver = { .name = "ev3-test-once" } };

static void registration_tests(void)
{
	struct platform_device *pdev, *late;
	struct platform_driver override_drv = { .probe = simple_probe, .driver = { .name = "ev3-over" } };

	ok(driver_find("ev3-test-simple", &platform_bus_type) == &simple_driver.driver,
	   "module_platform_driver registered the driver at module init");
	pdev = platform_device_register_data(NULL, "ev3-test-simple", 7, "pdata", 6);
	ok(!IS_ERR(pdev) && pdev->dev.driver == &simple_driver.driver, "bound by name");
	ok(!strcmp(dev_get_platdata(&pdev->dev), "pdata"), "platform_device_register_data copies the data");
	platform_device_unregister(pdev);

	pdev = platform_device_alloc("ev3-test-once", PLATFORM_DEVID_NONE);
	is_int(platform_device_add(pdev), 0, "a device for platform_driver_probe");
	probes_of_simple = 0;
	is_int(platform_driver_probe(&once_driver, simple_probe), 0, "platform_driver_probe bound it");
	late = platform_device_alloc("ev3-test-once", 2);
	is_int(platform_device_add(late), 0, "a later device");
	ok(probes_of_simple == 1 && late->dev.driver == NULL, "is not bound to a platform_driver_probe driver");
	platform_device_unregister(late);
	platform_driver_unregister(&once_driver);
	platform_device_unregister(pdev);
	is_int(platform_driver_probe(&once_driver, simple_probe), -ENODEV,
	       "platform_driver_probe with nothing to bind: -ENODEV");
	ok(driver_find("ev3-test-once", &platform_bus_type) == NULL, "... and the driver is gone");

	pdev = platform_device_alloc("ev3-test-simple", 9);
	pdev->driver_override = "ev3-over";
	is_int(platform_device_add(pdev), 0, "a device with driver_override");
	ok(pdev->dev.driver == NULL, "its own name's driver does not bind it");
	is_int(platform_driver_register(&override_drv), 0, "the named driver");
	ok(pdev->dev.driver == &override_drv.driver, "binds it");
	platform_device_unregister(pdev);
	platform_driver_unregister(&override_drv);
}

static void body(void)
{
	matching_tests();
	failure_tests();
	registration_tests();
}

int main(void)
{
	tap_plan(59);
	is_int(hs_board_init(NULL), E_OK, "host_sim board");
	ok(lx_test_run(body), "test task ran to completion");
	hs_board_shutdown();
	return tap_done();
}
