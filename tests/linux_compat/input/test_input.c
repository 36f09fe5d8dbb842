/*
 * test_input.c — the input core and evdev: a registered device is
 * /dev/input/event0 and /sys/class/input/input0; events it did not declare
 * are dropped, a key only when it changes, a packet passes on SYN_REPORT
 * (a lone SYN_REPORT does not), stamped with the virtual clock; each open
 * file has its own queue, a full one restarts with SYN_DROPPED; reads are
 * of whole records, -EAGAIN when non-blocking, woken by an event from an
 * hrtimer callback; evdev's query ioctls; unregistering ends the readers
 * (-ENODEV); a devm device goes with its driver; misuse reported.
 */
#define KBUILD_MODNAME "inputtest"
#include "lx_log_test.h"
#include <linux/delay.h>
#include <linux/hrtimer.h>
#include <linux/input.h>
#include <linux/ktime.h>
#include <linux/platform_device.h>
#include <linux/spinlock.h>
#include <linux_compat/clock.h>
#include <linux_compat/devfs.h>
#include <linux_compat/sysfs.h>
#include "host_sim/board.h"

static struct input_dev *timer_dev;
static struct hrtimer press_timer;

/* Presses KEY_ENTER from an hrtimer callback (hard-IRQ context). */
static enum hrtimer_restart press_later(struct hrtimer *t)
{
	input_report_key(timer_dev, KEY_ENTER, 1);
	input_sync(timer_dev);
	return HRTIMER_NORESTART;
}

static int read_events(struct file *f, struct input_event *evs, unsigned int n)
{
	ssize_t got = lx_dev_read(f, (char *)evs, n * sizeof(*evs), NULL);

	return got < 0 ? (int)got : (int)(got / (ssize_t)sizeof(*evs));
}

static void core_tests(void)
{
	struct input_event evs[LX_EVDEV_BUFFER + 8];
	struct file *f = NULL, *g = NULL;
	struct input_dev *in;
	char name[32], sys[32];
	unsigned long keys[BITS_TO_LONGS(KEY_CNT)];
	uint64_t t0;
	int n, i, version = 0;

	in = input_allocate_device();
	ok(in != NULL, "input_allocate_device");
	in->name = "EV3 test keys";
	in->id.bustype = BUS_HOST;
	input_set_capability(in, EV_KEY, KEY_UP);
	input_set_capability(in, EV_KEY, KEY_ENTER);
	is_int(input_register_device(in), 0, "input_register_device");
	ok(lx_dev_exists("/dev/input/event0"), "/dev/input/event0");
	n = (int)lx_sysfs_read("/sys/class/input/input0/name", sys, sizeof(sys) - 1);
	sys[n > 0 ? n : 0] = '\0';
	is_str(sys, "EV3 test keys\n", "/sys/class/input/input0/name");

	is_int(lx_dev_open("/dev/input/event0", O_RDONLY | O_NONBLOCK, &f), 0, "open non-blocking");
	is_int(lx_dev_open("/dev/input/event0", O_RDONLY, &g), 0, "and a second reader");
	is_int(read_events(f, evs, 4), -EAGAIN, "nothing yet: -EAGAIN");
	is_int((int)lx_dev_read(f, (char *)evs, sizeof(evs[0]) - 1, NULL), -EINVAL, "a read shorter than a record: -EINVAL");

	input_sync(in);
	is_int(read_events(f, evs, 4), -EAGAIN, "a SYN_REPORT with nothing before it is not passed");
	input_report_key(in, KEY_DOWN, 1);
	input_sync(in);
	is_int(read_events(f, evs, 4), -EAGAIN, "a key not declared is dropped");

	msleep(2);
	t0 = lx_clock_now_ns();
	input_report_key(in, KEY_UP, 1);
	input_report_key(in, KEY_UP, 1);
	input_report_key(in, KEY_ENTER, 5);
	input_sync(in);
	n = read_events(f, evs, 8);
	is_int(n, 3, "two keys and a SYN_REPORT (the repeated press dropped)");
	ok(evs[0].type == EV_KEY && evs[0].code == KEY_UP && evs[0].value == 1 &&
	   evs[1].code == KEY_ENTER && evs[1].value == 1 && evs[2].type == EV_SYN && evs[2].code == SYN_REPORT,
	   "KEY_UP 1, KEY_ENTER 1 (a non-zero value is 1), SYN_REPORT");
	ok((uint64_t)evs[0].input_event_sec * 1000000 + evs[0].input_event_usec == t0 / 1000 &&
	   evs[2].input_event_usec == evs[0].input_event_usec, "stamped with the virtual clock, one time per packet");
	is_int(read_events(g, evs, 8), 3, "the second reader has its own copy");

	input_event(in, EV_KEY, KEY_UP, 2);
	input_report_key(in, KEY_UP, 0);
	input_event(in, EV_KEY, KEY_UP, 2);
	input_sync(in);
	n = read_events(f, evs, 8);
	ok(n == 3 && evs[0].value == 2 && evs[1].value == 0 && evs[2].type == EV_SYN,
	   "autorepeat passes while the key is down, not after its release");

	is_int((int)lx_dev_ioctl_kernel(f, EVIOCGNAME(sizeof(name)), name), 14, "EVIOCGNAME: 14 bytes");
	is_str(name, "EV3 test keys", "the device's name");
	is_int((int)lx_dev_ioctl_kernel(f, EVIOCGVERSION, &version), 0, "EVIOCGVERSION");
	is_int(version, EV_VERSION, "0x010001");
	memset(keys, 0, sizeof(keys));
	lx_dev_ioctl_kernel(f, EVIOCGBIT(EV_KEY, sizeof(keys)), keys);
	ok(test_bit(KEY_UP, keys) && test_bit(KEY_ENTER, keys) && !test_bit(KEY_DOWN, keys), "EVIOCGBIT(EV_KEY)");
	lx_dev_ioctl_kernel(f, EVIOCGKEY(sizeof(keys)), keys);
	ok(!test_bit(KEY_UP, keys) && test_bit(KEY_ENTER, keys), "EVIOCGKEY: ENTER is down");

	for (i = 0; i < LX_EVDEV_BUFFER; i++) {
		input_report_key(in, KEY_UP, i % 2 == 0);
		input_sync(in);
	}
	n = read_events(f, evs, LX_EVDEV_BUFFER + 8);
	/* 128 events into 64 places: full at the 64th and the 126th, each time
	 * leaving SYN_DROPPED and that event, then the last two come */
	ok(n == 4 && evs[0].type == EV_SYN && evs[0].code == SYN_DROPPED && evs[1].code == SYN_REPORT && evs[2].code == KEY_UP &&
	   evs[3].code == SYN_REPORT, "an overflowing queue restarts with SYN_DROPPED and the newest event (%d)", n);
	(void)read_events(g, evs, LX_EVDEV_BUFFER + 8);
	input_report_key(in, KEY_ENTER, 0);
	input_sync(in);
	(void)read_events(g, evs, 8);
	lx_dev_close(f);

	timer_dev = in;
	hrtimer_init(&press_timer, CLOCK_MONOTONIC, HRTIMER_MODE_REL);
	press_timer.function = press_later;
	hrtimer_start(&press_timer, ms_to_ktime(3), HRTIMER_MODE_REL);
	t0 = lx_clock_now_ns();
	n = read_events(g, evs, 8);
	ok(n == 2 && evs[0].code == KEY_ENTER && evs[0].value == 1, "a blocking read wakes on an event from an hrtimer");
	in_range((long long)(lx_clock_now_ns() - t0), 3000000LL, 3400000LL, "3 ms later");

	input_unregister_device(in);
	ok(!lx_dev_exists("/dev/input/event0"), "unregistered: the node is gone");
	is_int(read_events(g, evs, 8), -ENODEV, "and an open reader gets -ENODEV");
	lx_dev_close(g);
}

static struct input_dev *devm_in;

static int keys_probe(struct platform_device *pdev)
{
	devm_in = devm_input_allocate_device(&pdev->dev);
	if (!devm_in)
		return -ENOMEM;
	devm_in->name = "devm keys";
	input_set_capability(devm_in, EV_KEY, KEY_LEFT);
	return input_register_device(devm_in);
}

static struct platform_driver keys_driver = {
	.probe = keys_probe, .driver = { .name = "ev3-test-keys" },
};

static DEFINE_SPINLOCK(test_lock);

static void devm_and_misuse_tests(void)
{
	struct platform_device *pdev = platform_device_alloc("ev3-test-keys", -1);
	struct input_dev *in;
	const struct lx_uevent *ev;
	unsigned long flags;
	char sys[32];
	int n;

	platform_device_add(pdev);
	is_int(platform_driver_register(&keys_driver), 0, "a driver with a devm input device");
	ok(lx_dev_exists("/dev/input/event0"), "registered by its probe");
	n = (int)lx_sysfs_read("/sys/class/input/input0/name", sys, sizeof(sys) - 1);
	sys[n > 0 ? n : 0] = '\0';
	is_str(sys, "devm keys\n", "in sysfs");
	ev = lx_uevent_get(lx_uevent_count() - 2);
	ok(ev && ev->action == KOBJ_ADD && !strcmp(ev->devpath, "/devices/platform/ev3-test-keys/input/input0"),
	   "its add uevent, under its parent (%s)", ev ? ev->devpath : "none");
	platform_driver_unregister(&keys_driver);
	ok(!lx_dev_exists("/dev/input/event0"), "unbinding unregistered it");
	platform_device_unregister(pdev);

	in = input_allocate_device();
	input_set_capability(in, EV_KEY, KEY_UP);
	is_int(input_register_device(in), 0, "a device");
	is_int(DC_EXPECT_BUG(input_free_device(in)), 1, "input_free_device of a registered device is reported");
	input_unregister_device(in);
	in = input_allocate_device();
	is_int(DC_EXPECT_BUG(input_unregister_device(in)), 1, "unregistering a device never registered is reported");
	input_free_device(in);

	in = input_allocate_device();
	spin_lock_irqsave(&test_lock, flags);
	ok(DC_EXPECT_BUG(n = input_register_device(in)) >= 1, "input_register_device under a spin lock is reported");
	spin_unlock_irqrestore(&test_lock, flags);
	input_unregister_device(in);
}

static void body(void)
{
	core_tests();
	devm_and_misuse_tests();
}

int main(void)
{
	tap_plan(37);
	is_int(hs_board_init(NULL), E_OK, "host_sim board");
	ok(lx_test_run(body), "test task ran to completion");
	hs_board_shutdown();
	return tap_done();
}
