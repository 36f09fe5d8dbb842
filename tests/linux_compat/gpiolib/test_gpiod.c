/*
 * test_gpiod.c — GPIO descriptors over the DaVinci banks on host_sim
 * (drivers/gpio/gpiolib.c's rules): lookup by device name, con_id and
 * index; GPIOD_OUT_HIGH / GPIOD_IN applied at get; active-low lines
 * inverting logical values (raw ones not); open drain released for high;
 * claims shared with gpio_request (-EBUSY both ways); -ENOENT and the
 * optional forms' NULL, which every call ignores; an unknown chip defers;
 * gpiod_count; gpiod_to_irq delivering edges; devm_gpiod_get released when
 * the platform driver unbinds; _cansleep from atomic context reported.
 */
#include "lx_log_test.h"
#include <linux/gpio.h>
#include <linux/gpio/consumer.h>
#include <linux/gpio/machine.h>
#include <linux/interrupt.h>
#include <linux/platform_device.h>
#include <linux/spinlock.h>
#include "host_sim/board.h"
#include "host_sim/gpio.h"

#define LED	GPIO_TO_PIN(6, 7)
#define RESET	GPIO_TO_PIN(6, 8)
#define BUTTON	GPIO_TO_PIN(5, 11)
#define BUS	GPIO_TO_PIN(3, 15)
#define DATA0	GPIO_TO_PIN(1, 2)
#define DATA1	GPIO_TO_PIN(1, 3)

static struct gpiod_lookup_table board_gpios = {
	.dev_id = "ev3-gpiod.0",
	.table = {
		GPIO_LOOKUP("davinci_gpio", LED, "led", GPIO_ACTIVE_HIGH),
		GPIO_LOOKUP("davinci_gpio", RESET, "reset", GPIO_ACTIVE_LOW),
		GPIO_LOOKUP("davinci_gpio", BUTTON, "button", GPIO_ACTIVE_LOW),
		GPIO_LOOKUP("davinci_gpio", BUS, "bus", GPIO_OPEN_DRAIN),
		GPIO_LOOKUP_IDX("davinci_gpio", DATA0, "data", 0, GPIO_ACTIVE_HIGH),
		GPIO_LOOKUP_IDX("davinci_gpio", DATA1, "data", 1, GPIO_ACTIVE_HIGH),
		GPIO_LOOKUP("other_chip", 3, "late", GPIO_ACTIVE_HIGH),
		{ },
	},
};

static struct device consumer = { .init_name = "ev3-gpiod.0" };
static int edges;

static irqreturn_t edge(int irq, void *dev)
{
	edges++;
	return IRQ_HANDLED;
}

static void lookup_tests(void)
{
	struct gpio_desc *led, *reset, *button, *bus, *d1, *none;
	struct gpio_descs *data;
	bool level = false;

	gpiod_add_lookup_table(&board_gpios);
	led = gpiod_get(&consumer, "led", GPIOD_OUT_HIGH);
	ok(!IS_ERR(led) && desc_to_gpio(led) == LED, "gpiod_get finds the line by device and con_id");
	ok(hs_gpio_soc_output(LED, &level) && level, "GPIOD_OUT_HIGH: an output, driven high");
	gpiod_set_value(led, 0);
	ok(hs_gpio_soc_output(LED, &level) && !level, "gpiod_set_value(0) drives it low");
	is_int(gpiod_get_direction(led), GPIO_LINE_DIRECTION_OUT, "gpiod_get_direction: out");
	is_str(gpio_label(LED), "led", "claimed under its con_id");
	is_int(gpio_request(LED, "legacy"), -EBUSY, "gpio_request of a gpiod line: -EBUSY");
	ok(gpiod_get(&consumer, "led", GPIOD_ASIS) == ERR_PTR(-EBUSY), "a second gpiod_get: -EBUSY");

	reset = gpiod_get(&consumer, "reset", GPIOD_OUT_HIGH);
	ok(!IS_ERR(reset) && gpiod_is_active_low(reset), "an active-low line");
	ok(hs_gpio_soc_output(RESET, &level) && !level, "asserted (logical 1) is driven low");
	gpiod_set_raw_value(reset, 1);
	ok(hs_gpio_soc_output(RESET, &level) && level, "the raw value is physical");
	is_int(gpiod_get_value(reset), 0, "and reads back as logical 0");

	button = gpiod_get(&consumer, "button", GPIOD_IN);
	is_int(gpiod_get_direction(button), GPIO_LINE_DIRECTION_IN, "GPIOD_IN: an input");
	hs_gpio_set_input(BUTTON, 0);
	is_int(gpiod_get_value(button), 1, "active low: a pin pulled low reads pressed");
	is_int(gpiod_get_raw_value(button), 0, "raw: 0");
	is_int(request_irq((unsigned int)gpiod_to_irq(button), edge, IRQF_TRIGGER_RISING, "button", NULL), 0,
	       "request_irq on gpiod_to_irq");
	hs_gpio_set_input(BUTTON, 1);
	is_int(edges, 1, "the edge reaches the handler");
	free_irq((unsigned int)gpiod_to_irq(button), NULL);

	bus = gpiod_get(&consumer, "bus", GPIOD_OUT_LOW);
	ok(hs_gpio_soc_output(BUS, &level) && !level, "open drain low: driven low");
	gpiod_set_value(bus, 1);
	ok(!hs_gpio_soc_output(BUS, &level), "open drain high: released (an input)");

	is_int(gpiod_count(&consumer, "data"), 2, "gpiod_count: two data lines");
	d1 = gpiod_get_index(&consumer, "data", 1, GPIOD_OUT_LOW);
	ok(!IS_ERR(d1) && desc_to_gpio(d1) == DATA1, "gpiod_get_index picks index 1");
	ok(gpiod_get_array(&consumer, "data", GPIOD_IN) == ERR_PTR(-EBUSY),
	   "gpiod_get_array with one line taken: its error, the other line put back");
	gpiod_put(d1);
	data = gpiod_get_array(&consumer, "data", GPIOD_IN);
	ok(!IS_ERR(data) && data->ndescs == 2 && desc_to_gpio(data->desc[0]) == DATA0 &&
	   desc_to_gpio(data->desc[1]) == DATA1, "gpiod_get_array: both data lines, in index order");
	ok(gpiod_get_array(&consumer, "missing", GPIOD_IN) == ERR_PTR(-ENOENT) &&
	   gpiod_get_array_optional(&consumer, "missing", GPIOD_IN) == NULL,
	   "no lines: -ENOENT, or NULL when optional");
	gpiod_put_array(data);
	d1 = gpiod_get_index(&consumer, "data", 1, GPIOD_OUT_LOW);
	ok(!IS_ERR(d1), "gpiod_put_array gave the lines back");

	ok(gpiod_get(&consumer, "missing", GPIOD_IN) == ERR_PTR(-ENOENT), "a line no table names: -ENOENT");
	none = gpiod_get_optional(&consumer, "missing", GPIOD_IN);
	ok(none == NULL, "gpiod_get_optional: NULL");
	gpiod_set_value(none, 1);
	is_int(gpiod_get_value(none), 0, "a NULL descriptor is ignored");
	dc_log_start();
	ok(gpiod_get(&consumer, "late", GPIOD_IN) == ERR_PTR(-EPROBE_DEFER), "an unknown chip: -EPROBE_DEFER");
	ok(dc_logged("cannot find GPIO chip other_chip, deferring"), "with Linux's message");
	gpiod_set_value(ERR_PTR(-ENOENT), 1);
	ok(dc_logged("gpiod_set_value: invalid GPIO (errorpointer)"), "an error pointer is warned about");

	gpiod_put(led);
	gpiod_put(reset);
	gpiod_put(button);
	gpiod_put(bus);
	gpiod_put(d1);
	is_int(gpio_request(LED, "legacy"), 0, "gpiod_put releases the claim");
	gpio_free(LED);
}

static int probe_gpiod(struct platform_device *pdev)
{
	struct gpio_desc *led = devm_gpiod_get(&pdev->dev, "led", GPIOD_OUT_HIGH);
	struct gpio_desc *opt = devm_gpiod_get_optional(&pdev->dev, "nothing", GPIOD_IN);

	if (IS_ERR(led))
		return PTR_ERR(led);
	if (IS_ERR(opt))
		return PTR_ERR(opt);
	platform_set_drvdata(pdev, led);
	return 0;
}

static struct platform_driver gpiod_driver = {
	.probe = probe_gpiod, .driver = { .name = "ev3-gpiod" },
};

static void pdev_release(struct device *dev)
{
}

static struct platform_device gpiod_pdev = { .name = "ev3-gpiod", .id = 0, .dev = { .release = pdev_release } };

static DEFINE_SPINLOCK(test_lock);

static void devm_tests(void)
{
	struct gpio_desc *d;
	unsigned long flags;

	is_int(platform_device_register(&gpiod_pdev), 0, "a platform device ev3-gpiod.0");
	is_int(platform_driver_register(&gpiod_driver), 0, "its driver gets its lines with devm_gpiod_get");
	ok(gpiod_pdev.dev.driver != NULL, "bound");
	is_str(gpio_label(LED), "led", "the line is claimed");
	platform_driver_unregister(&gpiod_driver);
	ok(gpio_label(LED) == NULL, "unbinding released it");
	platform_device_unregister(&gpiod_pdev);

	d = gpiod_get(&consumer, "led", GPIOD_OUT_LOW);
	spin_lock_irqsave(&test_lock, flags);
	gpiod_set_value(d, 1);
	ok(DC_EXPECT_BUG(gpiod_set_value_cansleep(d, 0)) == 1, "gpiod_set_value_cansleep under a spin lock");
	spin_unlock_irqrestore(&test_lock, flags);
	ok(strstr(dc_bug, "sleeping function called from invalid context") != NULL, "is reported: %s", dc_bug);
	gpiod_put(d);
	gpiod_remove_lookup_table(&board_gpios);
	ok(gpiod_get(&consumer, "led", GPIOD_ASIS) == ERR_PTR(-ENOENT), "the table removed");
}

static void body(void)
{
	lookup_tests();
	devm_tests();
}

int main(void)
{
	static const unsigned int pins[] = { LED, RESET, BUTTON, BUS, DATA0, DATA1 };
	unsigned int i;

	tap_plan(41);
	is_int(hs_board_init(NULL), E_OK, "host_sim board");
	for (i = 0; i < ARRAY_SIZE(pins); i++)
		hs_gpio_mux_as_gpio(pins[i]);   /* the board's pinmux, as U-Boot leaves it */
	ok(lx_test_run(body), "test task ran to completion");
	hs_board_shutdown();
	return tap_done();
}
