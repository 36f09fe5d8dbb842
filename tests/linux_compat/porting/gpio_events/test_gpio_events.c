/*
 * test_gpio_events.c — a modern platform driver taken unchanged:
 * gpio_events.c (module_platform_driver, of_match_table and id_table,
 * devm_kzalloc, devm_gpiod_get(_optional), a threaded IRQ with
 * IRQF_ONESHOT, a typed kfifo filled by the hard handler, a misc device
 * torn down through devm_add_action_or_reset) is included verbatim, as a
 * hack file does; the hack's init gives the board's part first — a gpiod
 * lookup table, a device-tree-like node and a platform device, as a board
 * file does before the drivers load — then runs the driver's init.  host_sim drives the input pin; the
 * records, the LED, the counts, unbinding and a second device matched by
 * name are checked through the driver's file operations.
 */
#define KBUILD_MODNAME "gpio_events"
#define LX_HACK_DRIVER_INIT events_driver_init
#define LX_HACK_DRIVER_EXIT events_driver_exit
#include "gpio_events.c"

#include "driver_common.h"

#include "lx_test.h"
#include <linux/gpio.h>
#include <linux/gpio/machine.h>
#include <linux/of.h>
#include <linux_compat/devfs.h>
#include <linux_compat/clock.h>
#include "host_sim/board.h"
#include "host_sim/gpio.h"
#include "host_sim/clock.h"

#define EVENT_PIN	GPIO_TO_PIN(5, 11)
#define LED_PIN		GPIO_TO_PIN(6, 7)
#define EVENT2_PIN	GPIO_TO_PIN(5, 8)

static struct gpiod_lookup_table board_gpios0 = {
	.dev_id = "ev3-events.0",
	.table = {
		GPIO_LOOKUP("davinci_gpio", EVENT_PIN, "event", GPIO_ACTIVE_HIGH),
		GPIO_LOOKUP("davinci_gpio", LED_PIN, "led", GPIO_ACTIVE_HIGH),
		{ },
	},
};

static struct gpiod_lookup_table board_gpios1 = {
	.dev_id = "gpio-events.1",
	.table = {
		GPIO_LOOKUP("davinci_gpio", EVENT2_PIN, "event", GPIO_ACTIVE_LOW),
		{ },
	},
};

static const char *const blink_compat[] = { "ev3lx,gpio-events-blink", "ev3lx,gpio-events", NULL };
static struct device_node board_node0 = { .name = "events", .full_name = "/events@0",
					  .compatible = blink_compat };

static void board_release(struct device *dev)
{
}

static struct platform_device board_dev0 = {
	.name = "ev3-events", .id = 0,
	.dev = { .of_node = &board_node0, .release = board_release },
};
static struct platform_device board_dev1 = {
	.name = "gpio-events", .id = 1, .dev = { .release = board_release },
};

/* The board file's part (lines and the first device), then the driver. */
static int __init hack_init(void)
{
	int ret;

	gpiod_add_lookup_table(&board_gpios0);
	gpiod_add_lookup_table(&board_gpios1);
	ret = platform_device_register(&board_dev0);
	return ret ? ret : events_driver_init();
}
module_init(hack_init);

static void __exit hack_exit(void)
{
	events_driver_exit();
	gpiod_remove_lookup_table(&board_gpios1);
	gpiod_remove_lookup_table(&board_gpios0);
}
module_exit(hack_exit);

static void edge_at(void *arg)
{
	unsigned int pin = (unsigned int)(uintptr_t)arg;

	hs_gpio_set_input(pin, 1);
}

/* A rising edge on pin now (the pin is brought low first). */
static void pulse(unsigned int pin)
{
	hs_gpio_set_input(pin, 0);
	hs_gpio_set_input(pin, 1);
}

static void body(void)
{
	struct gpio_event evs[GPIO_EVENTS_QUEUE + 4];
	struct gpio_events_stats stats;
	struct file *f = NULL, *nb = NULL;
	bool led = false;
	uint64_t t0;
	ssize_t n;
	int i;

	ok(board_dev0.dev.driver == &gpio_events_driver.driver, "the board's device bound at module init (by compatible)");
	if (lx_dev_open("/dev/gpio_events0", O_RDONLY, &f) != 0 ||
	    lx_dev_open("/dev/gpio_events0", O_RDONLY | O_NONBLOCK, &nb) != 0) {
		ok(0, "open /dev/gpio_events0");
		return;
	}
	is_int((int)lx_dev_read(nb, (char *)evs, sizeof(evs), NULL), -EAGAIN, "nothing yet: -EAGAIN");
	is_int((int)lx_dev_read(f, (char *)evs, 3, NULL), -EINVAL, "a read shorter than a record: -EINVAL");

	t0 = lx_clock_now_ns();
	hs_gpio_set_input(EVENT_PIN, 1);
	n = lx_dev_read(f, (char *)evs, sizeof(evs), NULL);
	is_int((int)n, (int)sizeof(evs[0]), "one rising edge: one record");
	ok(evs[0].seq == 0 && evs[0].level == 1 && evs[0].timestamp_ns >= t0 &&
	   evs[0].timestamp_ns - t0 < 1000000, "seq 0, level 1, stamped at the edge");
	ok(hs_gpio_soc_output(LED_PIN, &led) && led, "the thread toggled the LED on (blink by compatible)");

	for (i = 0; i < 3; i++)
		pulse(EVENT_PIN);
	hs_gpio_set_input(EVENT_PIN, 0);
	n = lx_dev_read(f, (char *)evs, sizeof(evs), NULL);
	is_int((int)n, (int)(3 * sizeof(evs[0])), "three edges: three records in one read");
	ok(evs[0].seq == 1 && evs[2].seq == 3 && evs[1].timestamp_ns <= evs[2].timestamp_ns, "in order");
	ok(hs_gpio_soc_output(LED_PIN, &led) && !led, "four toggles: the LED is off");

	hs_event_after(2000000, edge_at, (void *)(uintptr_t)EVENT_PIN);
	t0 = lx_clock_now_ns();
	n = lx_dev_read(f, (char *)evs, sizeof(evs), NULL);
	ok(n == (ssize_t)sizeof(evs[0]) && evs[0].seq == 4, "a blocking read wakes on the next edge");
	in_range((long long)(lx_clock_now_ns() - t0), 2000000LL, 2400000LL, "2 ms later, when it came");

	for (i = 0; i < GPIO_EVENTS_QUEUE + 4; i++)
		pulse(EVENT_PIN);
	is_int((int)lx_dev_ioctl(f, GPIO_EVENTS_STATS, (unsigned long)&stats), 0, "GPIO_EVENTS_STATS");
	ok(stats.edges == 25 && stats.handled == 25 && stats.dropped == 4,
	   "25 edges, each handled by the thread, 4 dropped by the full queue (%u, %u, %u)",
	   stats.edges, stats.handled, stats.dropped);
	n = lx_dev_read(f, (char *)evs, sizeof(evs), NULL);
	is_int((int)n, (int)(GPIO_EVENTS_QUEUE * sizeof(evs[0])), "the queue held 16 records");
	(void)lx_dev_close(f);
	(void)lx_dev_close(nb);

	platform_device_unregister(&board_dev0);
	ok(!lx_dev_exists("gpio_events0"), "unbinding removed /dev/gpio_events0");
	ok(gpio_label(EVENT_PIN) == NULL && gpio_label(LED_PIN) == NULL, "and released both lines");
	is_int(request_irq((unsigned int)gpio_to_irq(EVENT_PIN), gpio_events_hard, 0, "x", &board_dev0), 0,
	       "and freed the IRQ");
	free_irq((unsigned int)gpio_to_irq(EVENT_PIN), &board_dev0);

	is_int(platform_device_register(&board_dev1), 0, "a second device, matched by name");
	ok(board_dev1.dev.driver == &gpio_events_driver.driver && platform_get_device_id(&board_dev1),
	   "bound through the id_table");
	if (lx_dev_open("/dev/gpio_events1", O_RDONLY, &f) == 0) {
		hs_gpio_set_input(EVENT2_PIN, 0);
		hs_gpio_set_input(EVENT2_PIN, 1);
		n = lx_dev_read(f, (char *)evs, sizeof(evs), NULL);
		ok(n == (ssize_t)sizeof(evs[0]) && evs[0].seq == 0 && evs[0].level == 0,
		   "an active-low input: the IRQ triggers on the pin's rising edge (triggers are physical), "
		   "its logical level 0 (n %d, seq %u, level %u)", (int)n, evs[0].seq, evs[0].level);
		(void)lx_dev_close(f);
	} else {
		ok(0, "open /dev/gpio_events1");
	}
	platform_device_unregister(&board_dev1);
}

int main(void)
{
	static const unsigned int pins[] = { EVENT_PIN, LED_PIN, EVENT2_PIN };
	unsigned int i;

	tap_plan(22);
	is_int(hs_board_init(NULL), E_OK, "host_sim board (the AM1808 registers)");
	for (i = 0; i < ARRAY_SIZE(pins); i++)
		hs_gpio_mux_as_gpio(pins[i]);   /* the board's pinmux, as U-Boot leaves it */
	ok(lx_test_run(body), "test task ran to completion");
	hs_board_shutdown();
	return tap_done();
}
