/*
 * test_scratch.c — the scratch driver (scratch_drv.c, Linux headers only,
 * included unchanged) loaded by linux_compat's module init at boot and
 * driven through the device registry while the RTOS runs: GPIO edges from
 * the register model reach its interrupt handler, its hrtimer ticks in
 * virtual time, and read/write/ioctl/mmap round-trip.
 */
#define KBUILD_MODNAME "scratch"
#include "scratch_drv.c"	/* NOLINT(bugprone-suspicious-include): a driver verbatim, as the hacks do */

#include "lx_test.h"
#include "fake_mmio.h"
#include <linux/fcntl.h>
#include <linux_compat/devfs.h>

static void body(void)
{
	struct file *f = NULL;
	const struct scratch_shared *view = NULL;
	char text[64] = "";
	ssize_t n;
	u32 value = 0;

	is_int(lx_dev_open("/dev/" SCRATCH_DEVICE_NAME, O_RDWR | O_NONBLOCK, &f), 0,
	       "module init ran at boot: /dev/scratch opens");
	is_int(lx_dev_mmap(f, sizeof(struct scratch_shared), (void **)&view), 0, "mmap the shared area");
	ok(view == shared, "the mapping is the driver's page-aligned kmalloc buffer");
	is_int(lx_dev_read(f, text, sizeof(text), NULL), -EAGAIN, "no edge yet: a non-blocking read says -EAGAIN");

	is_int(lx_dev_write(f, "reset", 5, NULL), 5, "write reset");
	dly_tsk(10);
	in_range(view->ticks, 9, 10, "1 ms hrtimer: about 10 ticks in 10 ms (%u)", view->ticks);

	fake_gpio_edge(91, true);
	fake_gpio_edge(91, false);
	is_int(view->edges, 2, "both edges of GP5_11 reached the interrupt handler");
	is_int(view->level, 0, "which read the pin's level with gpio_get_value");
	n = lx_dev_read(f, text, sizeof(text), NULL);
	ok(n > 0 && strncmp(text, "edges=2 ticks=", 14) == 0, "read reports the counters: %.*s",
	   (int)(n > 0 ? n - 1 : 0), text);
	is_int(lx_dev_ioctl(f, SCRATCH_GET_EDGES, (unsigned long)&value), 0, "ioctl GET_EDGES");
	is_int(value, 2, "put_user delivered the count");

	value = 500;
	is_int(lx_dev_ioctl(f, SCRATCH_SET_PERIOD, (unsigned long)&value), 0, "ioctl SET_PERIOD 500 us");
	is_int(view->period_us, 500, "visible through the mapping");
	is_int(lx_dev_write(f, "reset", 5, NULL), 5, "reset again");
	dly_tsk(10);
	in_range(view->ticks, 18, 21, "500 us period: about 20 ticks in 10 ms (%u)", view->ticks);
	value = 5;
	is_int(lx_dev_ioctl(f, SCRATCH_SET_PERIOD, (unsigned long)&value), -EINVAL, "a bad period: -EINVAL");
	is_int(lx_dev_write(f, "bogus", 5, NULL), -EINVAL, "an unknown command: -EINVAL");
	is_int(lx_dev_mmap(f, 2 * PAGE_SIZE, (void **)&view), -EINVAL, "a mapping larger than the area: -EINVAL");
	is_int(lx_dev_close(f), 0, "close");
	is_str(gpio_label(91), "scratch", "the driver holds its GPIO");
}

int main(void)
{
	tap_plan(21);
	fake_mmio_install();
	ok(lx_test_run(body), "test task ran to completion");
	rtos_host_set_mmio_handler(NULL);
	return tap_done();
}
