/*
 * test_entry_points.c — every entry point of d_ui and ui_hack with good and
 * bad input: the service calls from a user domain (reserved codes, NULL and
 * foreign pointers, timeouts, non-task context), /dev/lms_ui's read, write,
 * poll and mmap as Linux user space calls them (short buffers, faults that
 * must lose no click, O_NONBLOCK, a blocking read woken by a click and
 * ended by rel_wai), and the module's life cycle: unload ends the waits in
 * progress and frees every pin,
 * interrupt and byte, a reload works, a load that finds a pin taken fails
 * cleanly.
 */
#include <linux/fcntl.h>
#include <linux/gpio.h>
#include <linux/interrupt.h>
#include <linux/module.h>
#include <linux_compat/devfs.h>
#include <linux_compat/heap.h>
#include "ui_test.h"

static struct lms_ui_click foreign_click;	/* outside the test task's domain */
static const struct lms_ui *foreign_map;
static ER irq_ercd[3];

/* A click of button now + 1 ms, held 50 ms; waits until it is queued. */
static void click(enum ev3_ui_button button)
{
	ev3_ui_click_at(rtos_host_now() + UIT_MS, button, 50 * UIT_MS);
	dly_tsk(1 + 50 + UIT_DEBOUNCE_MS + 2);
}

/* Runs in the hardware's (non-task) context. */
static void from_irq(void *arg)
{
	struct lms_ui_click c;
	const struct lms_ui *m;

	(void)arg;
	irq_ercd[0] = ui_svc_led(LMS_UI_LED_RED);
	irq_ercd[1] = ui_svc_map(&m);
	irq_ercd[2] = ui_svc_wait_click(&c, TMO_POL);
}

static void service_calls(void)
{
	struct lms_ui_click c;
	const struct lms_ui *map = NULL;
	int reserved = 0;

	for (FN fn = UI_FN_WAIT_CLICK + 1; fn <= UI_FN_LAST; fn++)
		reserved += cal_svc(fn, 0, 0, 0, 0, 0) == E_RSFN;
	is_int(reserved, UI_FN_LAST - UI_FN_WAIT_CLICK, "function codes %d..%d are reserved: E_RSFN", UI_FN_WAIT_CLICK + 1, UI_FN_LAST);
	is_int(ui_svc_map(NULL), E_MACV, "map: NULL is E_MACV");
	is_int(ui_svc_map(&foreign_map), E_MACV, "map: foreign memory is E_MACV");
	ok(ui_svc_map(&map) == E_OK && map == uit_shm, "map: the shared page");
	is_int(ui_svc_wait_click(NULL, TMO_POL), E_MACV, "wait_click: NULL is E_MACV");
	is_int(ui_svc_wait_click(&foreign_click, TMO_POL), E_MACV, "wait_click: foreign memory is E_MACV");
	is_int(ui_svc_wait_click((struct lms_ui_click *)(intptr_t)-4, TMO_POL), E_MACV,
	       "wait_click: a wrapping range is E_MACV");
	is_int(ui_svc_wait_click(&c, -2), E_PAR, "wait_click: timeout -2 is E_PAR");
	is_int(ui_svc_wait_click(&c, TMO_POL), E_TMOUT, "wait_click: TMO_POL, nothing queued: E_TMOUT");

	click(EV3_UI_BUTTON_RIGHT);
	is_int(ui_svc_wait_click(&foreign_click, 100), E_MACV, "a bad pointer with a click queued: E_MACV");
	ok(ui_svc_wait_click(&c, TMO_POL) == E_OK && c.button == LMS_UI_BUTTON_RIGHT,
	   "and the click is still there");

	hs_sim_at(rtos_host_now() + UIT_MS, from_irq, NULL);
	dly_tsk(2);
	ok(irq_ercd[0] == E_CTX && irq_ercd[1] == E_CTX && irq_ercd[2] == E_CTX,
	   "non-task context: E_CTX for led, map, wait_click");
	ok(ev3_ui_led_color(EV3_UI_LED_LEFT) == EV3_UI_LED_OFF, "and the LEDs did not change");
}

static void file_operations(void)
{
	struct lms_ui_click buf[8];
	char x[] = "x", two[] = "2\n";		/* on the stack: the task's own memory */
	struct file *f, *nb;
	void *map;

	if (lx_dev_open("/dev/" LMS_UI_DEVICE_NAME, O_RDWR, &f) ||
	    lx_dev_open("/dev/" LMS_UI_DEVICE_NAME, O_RDWR | O_NONBLOCK, &nb)) {
		tap_bail_out("cannot open /dev/lms_ui");
	}
	is_int(lx_dev_read(f, (char *)buf, sizeof(buf[0]) - 1, NULL), -EINVAL, "read of 7 bytes: -EINVAL");
	is_int(lx_dev_read(f, (char *)buf, 0, NULL), -EINVAL, "read of 0 bytes: -EINVAL");
	is_int(lx_dev_read(nb, (char *)buf, sizeof(buf), NULL), -EAGAIN, "O_NONBLOCK, empty: -EAGAIN");
	is_int(lx_dev_poll(f), EPOLLOUT | EPOLLWRNORM, "poll, empty: writable only");
	click(EV3_UI_BUTTON_UP);
	click(EV3_UI_BUTTON_DOWN);
	is_int(lx_dev_poll(f), EPOLLIN | EPOLLRDNORM | EPOLLOUT | EPOLLWRNORM, "poll: readable");
	is_int(lx_dev_read(f, NULL, sizeof(buf), NULL), -EFAULT, "read into NULL: -EFAULT");
	is_int(lx_dev_read(f, (char *)&foreign_click, sizeof(foreign_click), NULL), -EFAULT,
	       "read into foreign memory: -EFAULT");
	is_int(lx_dev_read(f, (char *)buf, sizeof(buf), NULL), 2 * sizeof(buf[0]),
	       "no click lost: both read at once (16 bytes)");
	ok(buf[0].button == LMS_UI_BUTTON_UP && buf[1].button == LMS_UI_BUTTON_DOWN &&
	   buf[1].seq == buf[0].seq + 1, "UP then DOWN, consecutive seqs");
	click(EV3_UI_BUTTON_BACK);
	click(EV3_UI_BUTTON_LEFT);
	is_int(lx_dev_read(nb, (char *)buf, sizeof(buf[0]) + 7, NULL), sizeof(buf[0]),
	       "a 15-byte buffer takes one whole click");
	ok(buf[0].button == LMS_UI_BUTTON_BACK && lx_dev_read(nb, (char *)buf, sizeof(buf), NULL) == 8 &&
	   buf[0].button == LMS_UI_BUTTON_LEFT, "the next read the other");

	is_int(lx_dev_write(f, two, 0, NULL), 0, "write of 0 bytes: 0, nothing changes");
	is_int(lx_dev_write(f, NULL, 1, NULL), -EFAULT, "write from NULL: -EFAULT");
	is_int(lx_dev_write(f, (const char *)&foreign_click, 1, NULL), -EFAULT, "write from foreign memory: -EFAULT");
	is_int(lx_dev_write(f, x, 1, NULL), -EINVAL, "write of 'x': -EINVAL");
	ok(ev3_ui_led_color(EV3_UI_LED_RIGHT) == EV3_UI_LED_OFF && uit_shm->led == LMS_UI_LED_OFF,
	   "refused writes change nothing");
	is_int(lx_dev_write(f, two, 2, NULL), 2, "write of \"2\\n\": the count");
	ok(ev3_ui_led_color(EV3_UI_LED_RIGHT) == EV3_UI_LED_RED, "LEDs red");

	is_int(lx_dev_mmap(f, LMS_UI_MAP_SIZE + 1, &map), -EINVAL, "mmap beyond the page: -EINVAL");
	ok(lx_dev_mmap(f, sizeof(struct lms_ui), &map) == 0 && map == (void *)uit_shm,
	   "mmap of the struct: the shared page");
	lx_dev_close(nb);
	lx_dev_close(f);
}

static volatile ssize_t helper_ret = 1;
static struct lms_ui_click helper_buf[4];

/* A blocking read(), as Linux user space does it. */
static void blocking_reader(void)
{
	struct file *f;

	helper_ret = 1;
	if (lx_dev_open("/dev/" LMS_UI_DEVICE_NAME, O_RDONLY, &f)) {
		helper_ret = -ENODEV;
		return;
	}
	helper_ret = lx_dev_read(f, (char *)helper_buf, sizeof(helper_buf), NULL);
	lx_dev_close(f);
}

static void blocking_read(void)
{
	uit_start_helper(blocking_reader);
	dly_tsk(10);
	is_int(helper_ret, 1, "a blocking read waits");
	click(EV3_UI_BUTTON_ENTER);
	ok(helper_ret == sizeof(helper_buf[0]) && helper_buf[0].button == LMS_UI_BUTTON_ENTER,
	   "a click wakes it with one click (%d)", (int)helper_ret);
	uit_start_helper(blocking_reader);
	dly_tsk(10);
	rel_wai(UIT_HELPER_ID);
	dly_tsk(1);
	is_int(helper_ret, -ERESTARTSYS, "rel_wai ends it: -ERESTARTSYS");
}

static int probe_isr_calls;

static irqreturn_t probe_isr(int irq, void *dev_id)
{
	probe_isr_calls++;
	return IRQ_HANDLED;
}

/* Every button interrupt and every pin d_ui used is free. */
static bool all_released(void)
{
	bool free_ = true;

	for (unsigned b = 0; b < EV3_UI_BUTTONS; b++) {
		unsigned pin = ev3_ui_pins.button[b];

		if (request_irq(gpio_to_irq(pin), probe_isr, 0, "probe", &probe_isr_calls))
			free_ = false;
		else
			free_irq(gpio_to_irq(pin), &probe_isr_calls);
		if (gpio_request(pin, "probe"))
			free_ = false;
		else
			gpio_free(pin);
	}
	for (unsigned l = 0; l < EV3_UI_LEDS; l++) {
		if (gpio_request(ev3_ui_pins.red[l], "probe") || gpio_request(ev3_ui_pins.green[l], "probe"))
			free_ = false;
		gpio_free(ev3_ui_pins.red[l]);
		gpio_free(ev3_ui_pins.green[l]);
	}
	return free_;
}

static bool all_obj(void)
{
	struct lms_ui_click c;
	const struct lms_ui *m;

	return ui_svc_led(LMS_UI_LED_GREEN) == E_OBJ && ui_svc_map(&m) == E_OBJ &&
	       ui_svc_wait_click(&c, TMO_POL) == E_OBJ;
}

static int life_cycle_results[12];

/* In the kernel-domain helper: unload, reload, a failing load. */
static void life_cycle(void)
{
	struct module *mod = lx_module_find("d_ui");
	struct lx_heap_stats before, after;
	int *r = life_cycle_results;

	dly_tsk(20);		/* the test task is waiting for a click by now */
	lx_heap_get_stats(&before);
	lx_modules_exit();
	lx_heap_get_stats(&after);
	dly_tsk(30);		/* the woken test task runs and returns */
	r[0] = !lx_dev_exists("/dev/" LMS_UI_DEVICE_NAME);
	r[1] = after.in_use < before.in_use;
	r[2] = all_obj();
	r[3] = ev3_ui_led_color(EV3_UI_LED_LEFT) == EV3_UI_LED_OFF &&
	       ev3_ui_led_color(EV3_UI_LED_RIGHT) == EV3_UI_LED_OFF;
	r[4] = all_released();

	r[5] = lx_modules_init() == 0 && ui_svc_led(LMS_UI_LED_GREEN) == E_OK &&
	       ev3_ui_led_color(EV3_UI_LED_LEFT) == EV3_UI_LED_GREEN;
	ev3_ui_click_at(rtos_host_now() + UIT_MS, EV3_UI_BUTTON_UP, 50 * UIT_MS);
	{
		struct lms_ui_click c;

		r[6] = ui_svc_wait_click(&c, 200) == E_OK && c.button == LMS_UI_BUTTON_UP && c.seq == 1;
	}

	lx_modules_exit();
	lx_heap_get_stats(&before);
	if (gpio_request(ev3_ui_pins.green[EV3_UI_LED_RIGHT], "squatter") == 0) {
		r[7] = lx_modules_init() == 1;
		r[8] = mod && mod->state == MODULE_STATE_FAILED && mod->init_result == -EBUSY;
		gpio_free(ev3_ui_pins.green[EV3_UI_LED_RIGHT]);
	}
	lx_heap_get_stats(&after);
	r[9] = !lx_dev_exists("/dev/" LMS_UI_DEVICE_NAME) && after.in_use == before.in_use;
	r[10] = all_released();
	r[11] = all_obj();
}

static void module_life_cycle(void)
{
	static const char *const what[12] = {
		"unload removes /dev/lms_ui", "unload returns the shared page",
		"every service call answers E_OBJ after the unload", "the LEDs are off after the unload",
		"every pin and button interrupt is free after the unload",
		"loading again: LEDs work", "loading again: a fresh click queue (seq 1)",
		"a load that finds an LED pin taken fails", "d_ui's init answered -EBUSY",
		"the failed load leaves no device and no memory",
		"the failed load leaves every pin and interrupt free",
		"every service call answers E_OBJ after the failed load",
	};

	struct lms_ui_click c;
	uint64_t t0;

	ui_svc_led(LMS_UI_LED_RED);
	uit_start_helper(life_cycle);
	t0 = uit_now_ms();
	is_int(ui_svc_wait_click(&c, 1000), E_OBJ, "a wait in progress when d_ui unloads ends: E_OBJ");
	ok(uit_now_ms() - t0 < 25, "at the unload, not at its timeout (%u ms)", (unsigned)(uit_now_ms() - t0));
	dly_tsk(500);
	for (unsigned i = 0; i < 12; i++)
		ok(life_cycle_results[i], "%s", what[i]);
	is_int(probe_isr_calls, 0, "no probe handler ran");
}

static void body(void)
{
	service_calls();
	file_operations();
	blocking_read();
	module_life_cycle();
}

int main(void)
{
	uit_domain = 1;		/* a user domain: only its stack is its memory */
	tap_plan(1 + 13 + 20 + 3 + 15);
	ok(uit_run(body, 9), "scenario ran to its end");
	return tap_done();
}
