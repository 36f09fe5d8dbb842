// SPDX-License-Identifier: GPL-2.0
/*
 * ev3_buttons.c - the six buttons of a LEGO MINDSTORMS EV3 brick as an input
 * device, in the way of gpio-keys: one GPIO line per button from the board
 * ("up", "enter", "down", "right", "left", "back"; a pressed button drives
 * its line high), an interrupt on both edges of each, and a debounce delay
 * after which the line's level is reported as the button's key.  The keys
 * are those ev3dev reports: KEY_UP, KEY_ENTER, KEY_DOWN, KEY_RIGHT,
 * KEY_LEFT and KEY_BACKSPACE.  The state of every button is reported when
 * the event device is first opened.
 */
#include <linux/device.h>
#include <linux/gpio/consumer.h>
#include <linux/input.h>
#include <linux/interrupt.h>
#include <linux/jiffies.h>
#include <linux/mod_devicetable.h>
#include <linux/module.h>
#include <linux/moduleparam.h>
#include <linux/platform_device.h>
#include <linux/workqueue.h>

#define EV3_BUTTONS	6

static unsigned int debounce_ms = 5;
module_param(debounce_ms, uint, 0444);
MODULE_PARM_DESC(debounce_ms, "time a line must be still before its level is reported (ms)");

struct ev3_button_def {
	const char *con_id;
	unsigned int code;
};

static const struct ev3_button_def ev3_button_defs[EV3_BUTTONS] = {
	{ "up", KEY_UP },
	{ "enter", KEY_ENTER },
	{ "down", KEY_DOWN },
	{ "right", KEY_RIGHT },
	{ "left", KEY_LEFT },
	{ "back", KEY_BACKSPACE },
};

struct ev3_button {
	struct ev3_buttons *owner;
	const struct ev3_button_def *def;
	struct gpio_desc *gpiod;
	struct delayed_work work;
	int irq;
};

struct ev3_buttons {
	struct input_dev *input;
	struct ev3_button button[EV3_BUTTONS];
};

/* Reports the button's line level as its key. */
static void ev3_button_report(struct ev3_button *b)
{
	int level = gpiod_get_value_cansleep(b->gpiod);

	if (level < 0)
		return;
	input_report_key(b->owner->input, b->def->code, level);
	input_sync(b->owner->input);
}

static void ev3_button_work(struct work_struct *work)
{
	struct ev3_button *b = container_of(to_delayed_work(work), struct ev3_button, work);

	ev3_button_report(b);
}

static irqreturn_t ev3_button_irq(int irq, void *data)
{
	struct ev3_button *b = data;

	mod_delayed_work(system_wq, &b->work, msecs_to_jiffies(debounce_ms));
	return IRQ_HANDLED;
}

static int ev3_buttons_open(struct input_dev *input)
{
	struct ev3_buttons *eb = input_get_drvdata(input);
	int i;

	for (i = 0; i < EV3_BUTTONS; i++)
		ev3_button_report(&eb->button[i]);
	return 0;
}

static void ev3_buttons_cancel_work(void *data)
{
	struct ev3_buttons *eb = data;
	int i;

	for (i = 0; i < EV3_BUTTONS; i++)
		cancel_delayed_work_sync(&eb->button[i].work);
}

static int ev3_buttons_probe(struct platform_device *pdev)
{
	struct device *dev = &pdev->dev;
	struct ev3_buttons *eb;
	struct ev3_button *b;
	int i, ret;

	eb = devm_kzalloc(dev, sizeof(*eb), GFP_KERNEL);
	if (!eb)
		return -ENOMEM;
	eb->input = devm_input_allocate_device(dev);
	if (!eb->input)
		return -ENOMEM;
	eb->input->name = "EV3 Brick Buttons";
	eb->input->phys = "ev3-buttons/input0";
	eb->input->id.bustype = BUS_HOST;
	eb->input->open = ev3_buttons_open;
	input_set_drvdata(eb->input, eb);

	for (i = 0; i < EV3_BUTTONS; i++) {
		b = &eb->button[i];
		b->owner = eb;
		b->def = &ev3_button_defs[i];
		INIT_DELAYED_WORK(&b->work, ev3_button_work);
		b->gpiod = devm_gpiod_get(dev, b->def->con_id, GPIOD_IN);
		if (IS_ERR(b->gpiod))
			return dev_err_probe(dev, PTR_ERR(b->gpiod), "no GPIO for button %s\n",
					     b->def->con_id);
		b->irq = gpiod_to_irq(b->gpiod);
		if (b->irq < 0)
			return dev_err_probe(dev, b->irq, "button %s has no IRQ\n", b->def->con_id);
		input_set_capability(eb->input, EV_KEY, b->def->code);
	}
	/* added before the IRQs, so released after them (devres runs in reverse):
	 * no IRQ queues a work once they are cancelled */
	ret = devm_add_action_or_reset(dev, ev3_buttons_cancel_work, eb);
	if (ret)
		return ret;
	for (i = 0; i < EV3_BUTTONS; i++) {
		b = &eb->button[i];
		ret = devm_request_irq(dev, b->irq, ev3_button_irq,
				       IRQF_TRIGGER_RISING | IRQF_TRIGGER_FALLING, b->def->con_id, b);
		if (ret)
			return dev_err_probe(dev, ret, "cannot request IRQ %d\n", b->irq);
	}
	ret = input_register_device(eb->input);
	if (ret)
		return dev_err_probe(dev, ret, "cannot register the input device\n");
	platform_set_drvdata(pdev, eb);
	return 0;
}

static const struct of_device_id ev3_buttons_of_match[] = {
	{ .compatible = "lego,ev3-buttons" },
	{ }
};
MODULE_DEVICE_TABLE(of, ev3_buttons_of_match);

static struct platform_driver ev3_buttons_driver = {
	.probe = ev3_buttons_probe,
	.driver = {
		.name = "ev3-buttons",
		.of_match_table = ev3_buttons_of_match,
	},
};
module_platform_driver(ev3_buttons_driver);

MODULE_DESCRIPTION("LEGO MINDSTORMS EV3 brick buttons");
MODULE_AUTHOR("ev3lx");
MODULE_LICENSE("GPL");
