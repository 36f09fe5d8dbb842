// SPDX-License-Identifier: GPL-2.0
/*
 * dc_motor.c - DC motors on PWM outputs as a device class, with the
 * attributes of ev3dev's dc-motor class (its documented sysfs ABI):
 * /sys/class/dc-motor/motor<n>/ address, commands, command, duty_cycle,
 * duty_cycle_sp, polarity, state.  Each motor is a platform device whose
 * PWM output comes from the board's lookup table ("pwm") and, optionally,
 * a direction line ("dir", high for reverse).  "run-direct" drives the
 * motor at duty_cycle_sp percent (-100..100, the sign its direction) and
 * follows later writes to it; "stop" stops it.  A change of state notifies
 * pollers of "state" and sends a change uevent.
 */
#include <linux/device.h>
#include <linux/gpio/consumer.h>
#include <linux/idr.h>
#include <linux/kstrtox.h>
#include <linux/mod_devicetable.h>
#include <linux/module.h>
#include <linux/mutex.h>
#include <linux/platform_device.h>
#include <linux/pwm.h>
#include <linux/sysfs.h>

#define DC_MOTOR_PERIOD_NS	50000	/* 20 kHz unless the board's lookup says otherwise */

struct dc_motor {
	struct device *cdev;		/* the class device */
	struct device *parent;
	struct pwm_device *pwm;
	struct gpio_desc *dir;
	struct mutex lock;		/* guards the fields below and the PWM's state */
	int duty_cycle_sp;
	int duty_cycle;
	bool inversed;
	bool running;
	int id;
};

static struct class dc_motor_class;
static DEFINE_IDA(dc_motor_ida);

/* Drives the output at duty percent (sign: direction); 0 or an error. */
static int dc_motor_drive(struct dc_motor *m, int duty)
{
	struct pwm_state state;
	int ret;

	pwm_init_state(m->pwm, &state);
	if (!state.period)
		state.period = DC_MOTOR_PERIOD_NS;
	if (m->inversed)
		duty = -duty;
	if (m->dir)
		gpiod_set_value_cansleep(m->dir, duty < 0);
	ret = pwm_set_relative_duty_cycle(&state, abs(duty), 100);
	if (ret)
		return ret;
	state.enabled = duty != 0;
	ret = pwm_apply_state(m->pwm, &state);
	if (!ret)
		m->duty_cycle = m->inversed ? -duty : duty;
	return ret;
}

/* Sets running and tells pollers and udev when it changed. */
static void dc_motor_set_running(struct dc_motor *m, bool running)
{
	if (m->running == running)
		return;
	m->running = running;
	sysfs_notify(&m->cdev->kobj, NULL, "state");
	kobject_uevent(&m->cdev->kobj, KOBJ_CHANGE);
}

static ssize_t address_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	struct dc_motor *m = dev_get_drvdata(dev);

	return sysfs_emit(buf, "%s\n", dev_name(m->parent));
}
static DEVICE_ATTR_RO(address);

static ssize_t commands_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	return sysfs_emit(buf, "run-direct stop\n");
}
static DEVICE_ATTR_RO(commands);

static ssize_t command_store(struct device *dev, struct device_attribute *attr, const char *buf,
			     size_t count)
{
	struct dc_motor *m = dev_get_drvdata(dev);
	int ret;

	mutex_lock(&m->lock);
	if (sysfs_streq(buf, "run-direct")) {
		ret = dc_motor_drive(m, m->duty_cycle_sp);
		if (!ret)
			dc_motor_set_running(m, true);
	} else if (sysfs_streq(buf, "stop")) {
		ret = dc_motor_drive(m, 0);
		if (!ret)
			dc_motor_set_running(m, false);
	} else {
		ret = -EINVAL;
	}
	mutex_unlock(&m->lock);
	return ret ? ret : (ssize_t)count;
}
static DEVICE_ATTR_WO(command);

static ssize_t duty_cycle_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	struct dc_motor *m = dev_get_drvdata(dev);

	return sysfs_emit(buf, "%d\n", m->duty_cycle);
}
static DEVICE_ATTR_RO(duty_cycle);

static ssize_t duty_cycle_sp_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	struct dc_motor *m = dev_get_drvdata(dev);

	return sysfs_emit(buf, "%d\n", m->duty_cycle_sp);
}

static ssize_t duty_cycle_sp_store(struct device *dev, struct device_attribute *attr, const char *buf,
				   size_t count)
{
	struct dc_motor *m = dev_get_drvdata(dev);
	int value, ret;

	ret = kstrtoint(buf, 10, &value);
	if (ret)
		return ret;
	if (value < -100 || value > 100)
		return -EINVAL;
	mutex_lock(&m->lock);
	m->duty_cycle_sp = value;
	ret = m->running ? dc_motor_drive(m, value) : 0;
	mutex_unlock(&m->lock);
	return ret ? ret : (ssize_t)count;
}
static DEVICE_ATTR_RW(duty_cycle_sp);

static ssize_t polarity_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	struct dc_motor *m = dev_get_drvdata(dev);

	return sysfs_emit(buf, "%s\n", m->inversed ? "inversed" : "normal");
}

static ssize_t polarity_store(struct device *dev, struct device_attribute *attr, const char *buf,
			      size_t count)
{
	struct dc_motor *m = dev_get_drvdata(dev);
	bool inversed;
	int ret = 0;

	if (sysfs_streq(buf, "normal"))
		inversed = false;
	else if (sysfs_streq(buf, "inversed"))
		inversed = true;
	else
		return -EINVAL;
	mutex_lock(&m->lock);
	if (inversed != m->inversed) {
		m->inversed = inversed;
		if (m->running)
			ret = dc_motor_drive(m, m->duty_cycle_sp);
	}
	mutex_unlock(&m->lock);
	return ret ? ret : (ssize_t)count;
}
static DEVICE_ATTR_RW(polarity);

static ssize_t state_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	struct dc_motor *m = dev_get_drvdata(dev);

	return sysfs_emit(buf, "%s\n", m->running ? "running" : "");
}
static DEVICE_ATTR_RO(state);

static struct attribute *dc_motor_attrs[] = {
	&dev_attr_address.attr,
	&dev_attr_commands.attr,
	&dev_attr_command.attr,
	&dev_attr_duty_cycle.attr,
	&dev_attr_duty_cycle_sp.attr,
	&dev_attr_polarity.attr,
	&dev_attr_state.attr,
	NULL
};
ATTRIBUTE_GROUPS(dc_motor);

static struct class dc_motor_class = {
	.name = "dc-motor",
	.dev_groups = dc_motor_groups,
};

static void dc_motor_unregister(void *data)
{
	struct dc_motor *m = data;

	device_unregister(m->cdev);
	ida_free(&dc_motor_ida, m->id);
}

static int dc_motor_probe(struct platform_device *pdev)
{
	struct device *dev = &pdev->dev;
	struct dc_motor *m;
	int ret;

	m = devm_kzalloc(dev, sizeof(*m), GFP_KERNEL);
	if (!m)
		return -ENOMEM;
	m->parent = dev;
	mutex_init(&m->lock);
	m->pwm = devm_pwm_get(dev, "pwm");
	if (IS_ERR(m->pwm))
		return dev_err_probe(dev, PTR_ERR(m->pwm), "no PWM output\n");
	m->dir = devm_gpiod_get_optional(dev, "dir", GPIOD_OUT_LOW);
	if (IS_ERR(m->dir))
		return dev_err_probe(dev, PTR_ERR(m->dir), "bad direction line\n");
	ret = dc_motor_drive(m, 0);
	if (ret)
		return dev_err_probe(dev, ret, "cannot stop the output\n");
	m->id = ida_alloc(&dc_motor_ida, GFP_KERNEL);
	if (m->id < 0)
		return m->id;
	m->cdev = device_create(&dc_motor_class, dev, 0, m, "motor%d", m->id);
	if (IS_ERR(m->cdev)) {
		ida_free(&dc_motor_ida, m->id);
		return dev_err_probe(dev, PTR_ERR(m->cdev), "cannot create the class device\n");
	}
	ret = devm_add_action_or_reset(dev, dc_motor_unregister, m);
	if (ret)
		return ret;
	platform_set_drvdata(pdev, m);
	return 0;
}

static const struct of_device_id dc_motor_of_match[] = {
	{ .compatible = "ev3lx,dc-motor" },
	{ }
};
MODULE_DEVICE_TABLE(of, dc_motor_of_match);

static struct platform_driver dc_motor_driver = {
	.probe = dc_motor_probe,
	.driver = {
		.name = "dc-motor",
		.of_match_table = dc_motor_of_match,
	},
};

static int __init dc_motor_init(void)
{
	int ret = class_register(&dc_motor_class);

	if (ret)
		return ret;
	ret = platform_driver_register(&dc_motor_driver);
	if (ret)
		class_unregister(&dc_motor_class);
	return ret;
}
module_init(dc_motor_init);

static void __exit dc_motor_exit(void)
{
	platform_driver_unregister(&dc_motor_driver);
	class_unregister(&dc_motor_class);
}
module_exit(dc_motor_exit);

MODULE_DESCRIPTION("DC motors on PWM outputs, as ev3dev's dc-motor class");
MODULE_AUTHOR("ev3lx");
MODULE_LICENSE("GPL");
