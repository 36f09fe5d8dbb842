// SPDX-License-Identifier: GPL-2.0
/*
 * d_ui.c - LEGO EV3 brick buttons and LEDs (/dev/lms_ui).
 *
 * Interface-compatible with LEGO's lms2012 d_ui where it has one (the mmap'ed pressed[] bytes,
 * the LED pattern bytes '0'..'9' written to the device; see lms_ui.h), written for the EV3's
 * GPIOs, with what LEGO's driver lacks: edge interrupts instead of polling, debouncing, and
 * click events delivered by a blocking read() and poll().
 *
 * Buttons: six GPIO inputs, each with a both-edge interrupt.  An edge only (re)starts its
 * button's debounce window; one hrtimer, armed for the earliest open window, settles a button
 * whose level has not changed for debounce_ms: then pressed[] changes, and a release after a
 * press queues a click (a button already held when the driver loads reads pressed, but its
 * release is no click) (LMS_UI_CLICK_QUEUE deep; when full, new clicks are counted as dropped)
 * and wakes the readers.  Nothing runs while no button moves.
 *
 * LEDs: two bicolour LEDs, each a red and a green GPIO output; orange is both.  Steady patterns
 * cost nothing; flash and pulse patterns run a 100 ms hrtimer only while selected.
 *
 * GPIO pins - NOT from our EV3 facts sheet: the buttons follow ev3dev's EV3 board support as
 * we know it (UP GP7_15, ENTER GP1_13, DOWN GP7_14, RIGHT GP7_12, LEFT GP6_6, BACK GP6_10,
 * pressed = high); the LEDs (left red GP6_13, left green GP6_7, right red GP6_12, right green
 * GP6_14, lit = high) LEGO's lms2012 d_ui pin table (mindboards/ev3sources) and EV3RT's brick
 * driver (ev3rt-git/ev3rt-hrp2), which both make GP6_12 and GP6_13 red, GP6_7 and GP6_14 green.  Check them against the EV3 schematic before loading this on a brick; every
 * pin and both active levels are module parameters.  The pins must already be muxed to GPIO
 * (board code / boot loader), as for gpio-keys and gpio-leds.
 */
#include <linux/module.h>
#include <linux/init.h>
#include <linux/kernel.h>
#include <linux/types.h>
#include <linux/errno.h>
#include <linux/bits.h>
#include <linux/fs.h>
#include <linux/miscdevice.h>
#include <linux/mm.h>
#include <linux/slab.h>
#include <linux/gpio.h>
#include <linux/interrupt.h>
#include <linux/irq.h>
#include <linux/hrtimer.h>
#include <linux/ktime.h>
#include <linux/spinlock.h>
#include <linux/mutex.h>
#include <linux/wait.h>
#include <linux/poll.h>
#include <linux/uaccess.h>

#include "lms_ui.h"

#define GP(bank, bit)		((bank) * 16 + (bit))	/* DaVinci GPIO number */

static int debounce_ms = 20;
module_param(debounce_ms, int, 0444);
MODULE_PARM_DESC(debounce_ms, "ms a button level must hold to count (1..500, default 20)");

static bool buttons_active_low;
module_param(buttons_active_low, bool, 0444);
MODULE_PARM_DESC(buttons_active_low, "a pressed button reads low (default: high)");

static bool leds_active_low;
module_param(leds_active_low, bool, 0444);
MODULE_PARM_DESC(leds_active_low, "an LED is lit by driving its pin low (default: high)");

/* One pin parameter: DaVinci GPIO number 16 * bank + bit, GP<bank>_<bit> by default. */
#define UI_GPIO_PARAM(name, bank, bit, what)					\
	static int name = GP(bank, bit);					\
	module_param(name, int, 0444);						\
	MODULE_PARM_DESC(name, "GPIO of " what " (default GP" #bank "_" #bit ")")

UI_GPIO_PARAM(up_gpio, 7, 15, "the UP button");
UI_GPIO_PARAM(enter_gpio, 1, 13, "the ENTER button");
UI_GPIO_PARAM(down_gpio, 7, 14, "the DOWN button");
UI_GPIO_PARAM(right_gpio, 7, 12, "the RIGHT button");
UI_GPIO_PARAM(left_gpio, 6, 6, "the LEFT button");
UI_GPIO_PARAM(back_gpio, 6, 10, "the BACK button");
UI_GPIO_PARAM(left_red_gpio, 6, 13, "the left LED's red half");
UI_GPIO_PARAM(left_green_gpio, 6, 7, "the left LED's green half");
UI_GPIO_PARAM(right_red_gpio, 6, 12, "the right LED's red half");
UI_GPIO_PARAM(right_green_gpio, 6, 14, "the right LED's green half");

#define LED_PINS		4
#define LED_RED			BIT(0)		/* colour bits */
#define LED_GREEN		BIT(1)
#define BLINK_STEP_MS		100
#define BLINK_STEPS		10		/* one period: 1 s */

struct ui_button {
	unsigned int gpio;
	int irq;			/* 0 until requested */
	bool down;			/* the debounced state */
	bool press_seen;		/* down since a press we saw (not held at load) */
	bool unsettled;			/* an edge's debounce window is open */
	ktime_t edge;			/* time of the newest edge */
	ktime_t pressed_at;		/* edge that started the current press */
};

static struct {
	struct lms_ui *shm;		/* the shared page */
	spinlock_t lock;		/* buttons, queue, LED state: IRQ, timers and file ops */
	struct ui_button button[LMS_UI_BUTTONS];
	struct hrtimer debounce;	/* armed for the earliest open debounce window */
	struct lms_ui_click queue[LMS_UI_CLICK_QUEUE];
	unsigned int head, count;	/* oldest queued click, clicks queued */
	u32 seq;			/* the newest click's seq */
	wait_queue_head_t readers;
	struct mutex read_mutex;	/* one reader takes clicks at a time */
	unsigned int led_gpio[LED_PINS];	/* left red, left green, right red, right green */
	unsigned int leds_requested;
	u8 led;				/* pattern byte */
	unsigned int blink_step;
	struct hrtimer blink;		/* runs only for flash/pulse patterns */
} ui;

/* ---- LEDs ---- */

/* Colour of each pattern '0'..'9', and which of its ten 100 ms steps are lit. */
static const u8 pattern_colour[10] = {
	0, LED_GREEN, LED_RED, LED_RED | LED_GREEN,
	LED_GREEN, LED_RED, LED_RED | LED_GREEN,
	LED_GREEN, LED_RED, LED_RED | LED_GREEN,
};

#define STEADY_STEPS		0x3ff		/* every step lit */
#define FLASH_STEPS		0x01f		/* 500 ms on, 500 ms off */
#define PULSE_STEPS		0x005		/* 100 ms on, 100 off, 100 on, 700 off */

static u16 pattern_steps(u8 pattern)
{
	if (pattern >= '7')
		return PULSE_STEPS;
	return pattern >= '4' ? FLASH_STEPS : STEADY_STEPS;
}

/* Drives all four LED pins for @colour (LED_RED | LED_GREEN bits), on both LEDs. */
static void ui_leds_show(u8 colour)
{
	bool red = colour & LED_RED, green = colour & LED_GREEN;

	gpio_set_value(ui.led_gpio[0], red ^ leds_active_low);
	gpio_set_value(ui.led_gpio[1], green ^ leds_active_low);
	gpio_set_value(ui.led_gpio[2], red ^ leds_active_low);
	gpio_set_value(ui.led_gpio[3], green ^ leds_active_low);
}

/* Shows step ui.blink_step of the current pattern.  Called with ui.lock held. */
static void ui_leds_show_step(void)
{
	u8 pattern = ui.led - '0';
	bool lit = pattern_steps(ui.led) & BIT(ui.blink_step);

	ui_leds_show(lit ? pattern_colour[pattern] : 0);
}

static enum hrtimer_restart ui_blink_step(struct hrtimer *timer)
{
	unsigned long flags;
	bool blinking;

	spin_lock_irqsave(&ui.lock, flags);
	blinking = pattern_steps(ui.led) != STEADY_STEPS;
	if (blinking) {
		ui.blink_step = (ui.blink_step + 1) % BLINK_STEPS;
		ui_leds_show_step();
	}
	spin_unlock_irqrestore(&ui.lock, flags);
	if (!blinking)
		return HRTIMER_NORESTART;
	hrtimer_forward_now(timer, ms_to_ktime(BLINK_STEP_MS));
	return HRTIMER_RESTART;
}

/* Selects LED pattern '0'..'9' from its first step; process context. */
static void ui_leds_set(u8 pattern)
{
	unsigned long flags;

	spin_lock_irqsave(&ui.lock, flags);
	ui.led = pattern;
	ui.blink_step = 0;
	ui_leds_show_step();
	WRITE_ONCE(ui.shm->led, pattern);
	spin_unlock_irqrestore(&ui.lock, flags);
	if (pattern_steps(pattern) != STEADY_STEPS)
		hrtimer_start(&ui.blink, ms_to_ktime(BLINK_STEP_MS), HRTIMER_MODE_REL);
	else
		hrtimer_cancel(&ui.blink);
}

/* Requests the four LED pins as outputs, LEDs off. */
static int ui_leds_init(void)
{
	int ret;

	ui.led_gpio[0] = left_red_gpio;
	ui.led_gpio[1] = left_green_gpio;
	ui.led_gpio[2] = right_red_gpio;
	ui.led_gpio[3] = right_green_gpio;
	ui.led = LMS_UI_LED_OFF;
	ui.shm->led = LMS_UI_LED_OFF;
	for (ui.leds_requested = 0; ui.leds_requested < LED_PINS; ui.leds_requested++) {
		unsigned int gpio = ui.led_gpio[ui.leds_requested];

		ret = gpio_request(gpio, "d_ui");
		if (ret) {
			pr_err("d_ui: LED GPIO %u: %d\n", gpio, ret);
			return ret;
		}
		ret = gpio_direction_output(gpio, leds_active_low);
		if (ret) {
			gpio_free(gpio);
			return ret;
		}
	}
	return 0;
}

/* Stops blinking, turns the LEDs off and frees the pins that were requested. */
static void ui_leds_exit(void)
{
	hrtimer_cancel(&ui.blink);
	while (ui.leds_requested) {
		unsigned int gpio = ui.led_gpio[--ui.leds_requested];

		gpio_set_value(gpio, leds_active_low);
		gpio_free(gpio);
	}
}

/* ---- buttons ---- */

static bool ui_button_level_down(const struct ui_button *b)
{
	return !!gpio_get_value(b->gpio) ^ buttons_active_low;
}

/* Queues a click of button @index; true if a reader should be woken.  ui.lock held. */
static bool ui_queue_click(unsigned int index, s64 held_ms)
{
	struct lms_ui_click *c;

	ui.seq++;
	WRITE_ONCE(ui.shm->clicks, ui.seq);
	if (ui.count == LMS_UI_CLICK_QUEUE) {
		WRITE_ONCE(ui.shm->dropped, ui.shm->dropped + 1);
		return false;
	}
	c = &ui.queue[(ui.head + ui.count) % LMS_UI_CLICK_QUEUE];
	c->button = index;
	c->reserved = 0;
	c->held_ms = clamp_t(s64, held_ms, 0, U16_MAX);
	c->seq = ui.seq;
	WRITE_ONCE(ui.count, ui.count + 1);
	return true;
}

/* A button whose level held for debounce_ms takes it; true if a click was queued.  ui.lock held. */
static bool ui_button_settle(struct ui_button *b)
{
	unsigned int index = b - ui.button;
	bool down = ui_button_level_down(b);

	b->unsettled = false;
	if (down == b->down)
		return false;		/* it bounced back: nothing happened */
	b->down = down;
	WRITE_ONCE(ui.shm->pressed[index], down);
	if (down) {
		b->press_seen = true;
		b->pressed_at = b->edge;
		WRITE_ONCE(ui.shm->presses[index], ui.shm->presses[index] + 1);
		return false;
	}
	if (!b->press_seen)
		return false;		/* held since before we loaded: not a click we saw */
	b->press_seen = false;
	/* Rounded: the two edges' interrupts may be served a few microseconds apart. */
	return ui_queue_click(index, ktime_to_ms(ktime_add_ns(ktime_sub(b->edge, b->pressed_at),
							      NSEC_PER_MSEC / 2)));
}

static enum hrtimer_restart ui_debounce_expired(struct hrtimer *timer)
{
	ktime_t now = ktime_get(), window = ms_to_ktime(debounce_ms), next = KTIME_MAX;
	bool wake = false;
	unsigned long flags;
	unsigned int i;

	spin_lock_irqsave(&ui.lock, flags);
	for (i = 0; i < LMS_UI_BUTTONS; i++) {
		struct ui_button *b = &ui.button[i];
		ktime_t settle = ktime_add(b->edge, window);

		if (!b->unsettled)
			continue;
		if (ktime_before(now, settle))
			next = min(next, settle);
		else
			wake |= ui_button_settle(b);
	}
	spin_unlock_irqrestore(&ui.lock, flags);
	if (wake)
		wake_up_interruptible(&ui.readers);
	if (next == KTIME_MAX)
		return HRTIMER_NORESTART;
	hrtimer_set_expires(timer, next);
	return HRTIMER_RESTART;
}

/* Any edge of a button: (re)open its debounce window. */
static irqreturn_t ui_button_irq(int irq, void *dev_id)
{
	struct ui_button *b = dev_id;
	ktime_t now = ktime_get();
	unsigned long flags;

	spin_lock_irqsave(&ui.lock, flags);
	if (b->unsettled)
		WRITE_ONCE(ui.shm->bounces, ui.shm->bounces + 1);
	b->unsettled = true;
	b->edge = now;
	if (!hrtimer_is_queued(&ui.debounce))
		hrtimer_start(&ui.debounce, ktime_add_ms(now, debounce_ms), HRTIMER_MODE_ABS);
	spin_unlock_irqrestore(&ui.lock, flags);
	return IRQ_HANDLED;
}

/* Releases button @b's interrupt and pin (either may not have been taken yet). */
static void ui_button_exit(struct ui_button *b)
{
	if (b->irq > 0)
		free_irq(b->irq, b);
	b->irq = 0;
	gpio_free(b->gpio);
}

/* Takes button @b's pin as an input with a both-edge interrupt, then reads its state. */
static int ui_button_init(struct ui_button *b, unsigned int gpio)
{
	unsigned long flags;
	int irq, ret;

	b->gpio = gpio;
	b->irq = 0;
	ret = gpio_request(gpio, "d_ui");
	if (ret) {
		pr_err("d_ui: button GPIO %u: %d\n", gpio, ret);
		return ret;
	}
	ret = gpio_direction_input(gpio);
	if (ret)
		goto fail;
	irq = gpio_to_irq(gpio);
	if (irq <= 0) {
		ret = irq ? irq : -EINVAL;
		goto fail;
	}
	ret = request_irq(irq, ui_button_irq, 0, "d_ui", b);
	if (ret)
		goto fail;
	b->irq = irq;
	ret = irq_set_irq_type(irq, IRQ_TYPE_EDGE_BOTH);
	if (ret)
		goto fail;
	/* After the interrupt is live, so no edge falls between reading and watching. */
	spin_lock_irqsave(&ui.lock, flags);
	if (!b->unsettled) {
		b->down = ui_button_level_down(b);
		ui.shm->pressed[b - ui.button] = b->down;
	}
	spin_unlock_irqrestore(&ui.lock, flags);
	return 0;

fail:
	pr_err("d_ui: button GPIO %u: interrupt: %d\n", gpio, ret);
	ui_button_exit(b);
	return ret;
}

static int ui_buttons_init(void)
{
	const int gpio[LMS_UI_BUTTONS] = {
		[LMS_UI_BUTTON_UP] = up_gpio,		[LMS_UI_BUTTON_ENTER] = enter_gpio,
		[LMS_UI_BUTTON_DOWN] = down_gpio,	[LMS_UI_BUTTON_RIGHT] = right_gpio,
		[LMS_UI_BUTTON_LEFT] = left_gpio,	[LMS_UI_BUTTON_BACK] = back_gpio,
	};
	unsigned int i;
	int ret;

	for (i = 0; i < LMS_UI_BUTTONS; i++) {
		ret = ui_button_init(&ui.button[i], gpio[i]);
		if (ret)
			goto unwind;
	}
	return 0;

unwind:
	while (i--)
		ui_button_exit(&ui.button[i]);
	return ret;
}

/* Frees the interrupts first, then stops a debounce the last edges may have started. */
static void ui_buttons_exit(void)
{
	unsigned int i;

	for (i = 0; i < LMS_UI_BUTTONS; i++)
		ui_button_exit(&ui.button[i]);
	hrtimer_cancel(&ui.debounce);
}

/* ---- file operations ---- */

/* Clicks, oldest first, as many whole ones as fit in @count bytes. */
static ssize_t ui_read(struct file *file, char __user *buf, size_t count, loff_t *ppos)
{
	struct lms_ui_click clicks[LMS_UI_CLICK_QUEUE];
	unsigned int n, i;
	ssize_t ret;

	if (count < sizeof(clicks[0]))
		return -EINVAL;
	if (file->f_flags & O_NONBLOCK) {
		if (!mutex_trylock(&ui.read_mutex))
			return -EAGAIN;
	} else if (mutex_lock_interruptible(&ui.read_mutex)) {
		return -ERESTARTSYS;
	}
	for (;;) {
		/* Copy, and remove only what reached the reader: a fault loses no click. */
		spin_lock_irq(&ui.lock);
		n = min_t(size_t, count / sizeof(clicks[0]), ui.count);
		for (i = 0; i < n; i++)
			clicks[i] = ui.queue[(ui.head + i) % LMS_UI_CLICK_QUEUE];
		spin_unlock_irq(&ui.lock);
		if (n)
			break;
		if (file->f_flags & O_NONBLOCK) {
			ret = -EAGAIN;
			goto unlock;
		}
		ret = wait_event_interruptible(ui.readers, READ_ONCE(ui.count) != 0);
		if (ret)
			goto unlock;
	}
	if (copy_to_user(buf, clicks, n * sizeof(clicks[0]))) {
		ret = -EFAULT;
		goto unlock;
	}
	spin_lock_irq(&ui.lock);
	ui.head = (ui.head + n) % LMS_UI_CLICK_QUEUE;
	WRITE_ONCE(ui.count, ui.count - n);
	spin_unlock_irq(&ui.lock);
	ret = n * sizeof(clicks[0]);
unlock:
	mutex_unlock(&ui.read_mutex);
	return ret;
}

/* Byte 0 selects the LED pattern of both LEDs. */
static ssize_t ui_write(struct file *file, const char __user *buf, size_t count, loff_t *ppos)
{
	char pattern;

	if (!count)
		return 0;
	if (get_user(pattern, buf))
		return -EFAULT;
	if (pattern < LMS_UI_LED_OFF || pattern > LMS_UI_LED_ORANGE_PULSE)
		return -EINVAL;
	ui_leds_set(pattern);
	return count;
}

static __poll_t ui_poll(struct file *file, poll_table *wait)
{
	__poll_t mask = EPOLLOUT | EPOLLWRNORM;

	poll_wait(file, &ui.readers, wait);
	if (READ_ONCE(ui.count))
		mask |= EPOLLIN | EPOLLRDNORM;
	return mask;
}

/* Maps the shared page from offset 0. */
static int ui_mmap(struct file *file, struct vm_area_struct *vma)
{
	unsigned long len = vma->vm_end - vma->vm_start;

	if (vma->vm_pgoff || len > LMS_UI_MAP_SIZE)
		return -EINVAL;
	if (remap_pfn_range(vma, vma->vm_start, virt_to_phys(ui.shm) >> PAGE_SHIFT, len,
			    vma->vm_page_prot))
		return -EAGAIN;
	return 0;
}

static const struct file_operations ui_fops = {
	.owner		= THIS_MODULE,
	.read		= ui_read,
	.write		= ui_write,
	.poll		= ui_poll,
	.mmap		= ui_mmap,
	.llseek		= noop_llseek,
};

static struct miscdevice ui_misc = {
	.minor	= MISC_DYNAMIC_MINOR,
	.name	= LMS_UI_DEVICE_NAME,
	.fops	= &ui_fops,
};

/* ---- module ---- */

static void ui_check_layout(void)
{
	BUILD_BUG_ON(sizeof(struct lms_ui_click) != 8);
	BUILD_BUG_ON(offsetof(struct lms_ui, led) != LMS_UI_BUTTONS);
	BUILD_BUG_ON(offsetof(struct lms_ui, clicks) != 8);
	BUILD_BUG_ON(offsetof(struct lms_ui, presses) != 20);
	BUILD_BUG_ON(sizeof(struct lms_ui) != 44);
	BUILD_BUG_ON(sizeof(struct lms_ui) > LMS_UI_MAP_SIZE);
	BUILD_BUG_ON(LMS_UI_MAP_SIZE != PAGE_SIZE);
	BUILD_BUG_ON(ARRAY_SIZE(pattern_colour) != LMS_UI_LED_ORANGE_PULSE - LMS_UI_LED_OFF + 1);
}

static int __init d_ui_init(void)
{
	int ret;

	ui_check_layout();
	debounce_ms = clamp(debounce_ms, 1, 500);
	memset(&ui, 0, sizeof(ui));
	spin_lock_init(&ui.lock);
	init_waitqueue_head(&ui.readers);
	mutex_init(&ui.read_mutex);
	hrtimer_init(&ui.debounce, CLOCK_MONOTONIC, HRTIMER_MODE_ABS);
	ui.debounce.function = ui_debounce_expired;
	hrtimer_init(&ui.blink, CLOCK_MONOTONIC, HRTIMER_MODE_REL);
	ui.blink.function = ui_blink_step;

	ui.shm = kzalloc(LMS_UI_MAP_SIZE, GFP_KERNEL);
	if (!ui.shm)
		return -ENOMEM;
	SetPageReserved(virt_to_page(ui.shm));

	ret = ui_leds_init();
	if (ret)
		goto leds_exit;
	ret = ui_buttons_init();
	if (ret)
		goto leds_exit;
	ret = misc_register(&ui_misc);
	if (ret)
		goto buttons_exit;
	return 0;

buttons_exit:
	ui_buttons_exit();
leds_exit:
	ui_leds_exit();
	ClearPageReserved(virt_to_page(ui.shm));
	kfree(ui.shm);
	ui.shm = NULL;
	return ret;
}

static void __exit d_ui_exit(void)
{
	misc_deregister(&ui_misc);
	ui_buttons_exit();
	ui_leds_exit();
	ClearPageReserved(virt_to_page(ui.shm));
	kfree(ui.shm);
	ui.shm = NULL;
}

module_init(d_ui_init);
module_exit(d_ui_exit);

MODULE_LICENSE("GPL");
MODULE_AUTHOR("ev3lx");
MODULE_DESCRIPTION("LEGO EV3 brick buttons and LEDs (/dev/lms_ui)");
