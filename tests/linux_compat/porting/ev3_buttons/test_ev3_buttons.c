/*
 * test_ev3_buttons.c — ev3_buttons.c, an upstream-style input driver for the
 * EV3's six buttons, taken unchanged: the hack's init gives the board's part
 * (the buttons' GPIO lines as ev3dev's EV3 board names them, a node with
 * the driver's compatible and a platform device), then runs the driver's
 * init.  host_sim's brick buttons (with contact bounce) are pressed; the
 * keys are read from /dev/input/event0 as an evdev reader reads them: one
 * press and one release per click after the debounce delay, with the
 * virtual clock's time, the state of a button held before the device was
 * opened (EVIOCGKEY, as evdev readers ask), and the sysfs name.
 */
#define KBUILD_MODNAME "ev3_buttons"
#define LX_HACK_DRIVER_INIT buttons_driver_init
#define LX_HACK_DRIVER_EXIT buttons_driver_exit
#include "ev3_buttons.c"

#include "driver_common.h"

#include "tap.h"
#include "brick_test.h"
#include "rtos_host.h"
#include <linux_compat/config.h>
#include <linux/gpio.h>
#include <linux/gpio/machine.h>
#include <linux/of.h>
#include <linux_compat/clock.h>
#include <linux_compat/devfs.h>
#include <linux_compat/sysfs.h>
#include "host_sim/board.h"
#include "host_sim/scenario.h"
#include "host_sim/devices/ev3_brick.h"
#include "host_sim/devices/ev3_ui.h"

/* The EV3's button lines (ev3dev's EV3 board file, as host_sim's ev3_ui_pins). */
static struct gpiod_lookup_table board_buttons = {
	.dev_id = "ev3-buttons",
	.table = {
		GPIO_LOOKUP("davinci_gpio", GPIO_TO_PIN(7, 15), "up", GPIO_ACTIVE_HIGH),
		GPIO_LOOKUP("davinci_gpio", GPIO_TO_PIN(1, 13), "enter", GPIO_ACTIVE_HIGH),
		GPIO_LOOKUP("davinci_gpio", GPIO_TO_PIN(7, 14), "down", GPIO_ACTIVE_HIGH),
		GPIO_LOOKUP("davinci_gpio", GPIO_TO_PIN(7, 12), "right", GPIO_ACTIVE_HIGH),
		GPIO_LOOKUP("davinci_gpio", GPIO_TO_PIN(6, 6), "left", GPIO_ACTIVE_HIGH),
		GPIO_LOOKUP("davinci_gpio", GPIO_TO_PIN(6, 10), "back", GPIO_ACTIVE_HIGH),
		{ },
	},
};
static const char *const buttons_compat[] = { "lego,ev3-buttons", NULL };
static struct device_node buttons_node = { .name = "buttons", .full_name = "/buttons",
					   .compatible = buttons_compat };

static void board_release(struct device *dev)
{
}

static struct platform_device board_buttons_dev = {
	.name = "ev3-buttons", .id = PLATFORM_DEVID_NONE,
	.dev = { .of_node = &buttons_node, .release = board_release },
};

/* The board's part, then the driver. */
static int __init hack_init(void)
{
	int ret;

	gpiod_add_lookup_table(&board_buttons);
	ret = platform_device_register(&board_buttons_dev);
	return ret ? ret : buttons_driver_init();
}
module_init(hack_init);

static void __exit hack_exit(void)
{
	buttons_driver_exit();
	platform_device_unregister(&board_buttons_dev);
	gpiod_remove_lookup_table(&board_buttons);
}
module_exit(hack_exit);

static int read_events(struct file *f, struct input_event *evs, unsigned int n)
{
	ssize_t got = lx_dev_read(f, (char *)evs, n * sizeof(*evs), NULL);

	return got < 0 ? (int)got : (int)(got / (ssize_t)sizeof(*evs));
}

static void body(void)
{
	static const struct { enum ev3_ui_button button; unsigned int code; } keys[] = {
		{ EV3_UI_BUTTON_UP, KEY_UP }, { EV3_UI_BUTTON_ENTER, KEY_ENTER },
		{ EV3_UI_BUTTON_DOWN, KEY_DOWN }, { EV3_UI_BUTTON_RIGHT, KEY_RIGHT },
		{ EV3_UI_BUTTON_LEFT, KEY_LEFT }, { EV3_UI_BUTTON_BACK, KEY_BACKSPACE },
	};
	struct input_event evs[16];
	struct file *f = NULL, *nb = NULL;
	char text[40];
	unsigned long keybits[BITS_TO_LONGS(KEY_CNT)];
	uint64_t t0, t_ev;
	unsigned int i, good = 0;
	int n;

	ok(board_buttons_dev.dev.driver == &ev3_buttons_driver.driver, "the board's device bound by compatible");
	n = (int)lx_sysfs_read("/sys/class/input/input0/name", text, sizeof(text) - 1);
	text[n > 0 ? n : 0] = '\0';
	is_str(text, "EV3 Brick Buttons\n", "/sys/class/input/input0/name");

	ev3_ui_button_set(EV3_UI_BUTTON_LEFT, true);
	msleep(20);
	if (lx_dev_open("/dev/input/event0", O_RDONLY, &f) != 0 ||
	    lx_dev_open("/dev/input/event0", O_RDONLY | O_NONBLOCK, &nb) != 0) {
		ok(0, "open /dev/input/event0");
		return;
	}
	memset(keybits, 0, sizeof(keybits));
	lx_dev_ioctl_kernel(f, EVIOCGKEY(sizeof(keybits)), keybits);
	ok(test_bit(KEY_LEFT, keybits) && !test_bit(KEY_UP, keybits),
	   "a button held before the device was opened: down in EVIOCGKEY");
	is_int(read_events(nb, evs, 16), -EAGAIN, "and no event (it did not change since)");
	ev3_ui_button_set(EV3_UI_BUTTON_LEFT, false);
	n = read_events(f, evs, 16);
	ok(n == 2 && evs[0].code == KEY_LEFT && evs[0].value == 0, "its release: KEY_LEFT 0");
	(void)read_events(nb, evs, 16);

	ev3_ui_set_bounce(2000);
	for (i = 0; i < ARRAY_SIZE(keys); i++) {
		t0 = lx_clock_now_ns() + 10000000;
		ev3_ui_click_at(t0, keys[i].button, 50000000);
		n = read_events(f, evs, 16);
		t_ev = (uint64_t)evs[0].input_event_sec * 1000000000ULL + (uint64_t)evs[0].input_event_usec * 1000;
		if (n == 2 && evs[0].code == keys[i].code && evs[0].value == 1 && evs[1].type == EV_SYN &&
		    t_ev >= t0 + 5000000 && t_ev < t0 + 10000000)
			good++;
		else
			tap_diag("button %u: %d events, code %u value %d at +%lld ns", i, n, evs[0].code,
				 evs[0].value, (long long)(t_ev - t0));
		n = read_events(f, evs, 16);
		if (n == 2 && evs[0].code == keys[i].code && evs[0].value == 0)
			good++;
	}
	is_int(good, 12, "each button, with bouncing contacts: one press, one release, after the debounce");
	n = read_events(nb, evs, 16);
	is_int(n, 16, "the other reader has all 24 events queued (16 read at once)");
	ev3_ui_set_bounce(0);
	lx_dev_close(f);
	lx_dev_close(nb);
}

int main(void)
{
	tap_plan(9);
	lx_test_on_brick(body, "the simulated brick, its buttons included");
	return tap_done();
}
