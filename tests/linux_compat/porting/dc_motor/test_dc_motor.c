/*
 * test_dc_motor.c — dc_motor.c, an upstream-style class driver with sysfs
 * attributes (ev3dev's dc-motor ABI) and a PWM consumer, taken unchanged.
 * The hack's init gives the board's part: a PWM chip of its own that
 * records the states applied to it, the PWM and GPIO lookup tables of the
 * motor's platform device, and the device; then the driver's init, which
 * registers the class.  The test is user space: it reads and writes
 * /sys/class/dc-motor/motor0/... and checks what reached the PWM output
 * and the direction line, the state's notification and uevent, the
 * errors the attributes give, and that unbinding removes the motor.
 */
#define KBUILD_MODNAME "dc_motor"
#define LX_HACK_DRIVER_INIT motor_driver_init
#define LX_HACK_DRIVER_EXIT motor_driver_exit
#include "dc_motor.c"

#include "driver_common.h"

#include "lx_test.h"
#include <linux/gpio.h>
#include <linux/gpio/machine.h>
#include <linux/of.h>
#include <linux_compat/sysfs.h>
#include "host_sim/board.h"
#include "host_sim/gpio.h"

#define DIR_PIN		GPIO_TO_PIN(5, 11)

static struct pwm_state applied;
static unsigned int applies;

static int board_pwm_apply(struct pwm_chip *chip, struct pwm_device *pwm, const struct pwm_state *state)
{
	applied = *state;
	applies++;
	return 0;
}

static const struct pwm_ops board_pwm_ops = { .apply = board_pwm_apply };
static struct device board_pwm_dev = { .init_name = "board-pwm" };
static struct pwm_chip board_pwm = { .dev = &board_pwm_dev, .ops = &board_pwm_ops, .npwm = 1, .base = -1 };

static struct pwm_lookup board_pwms[] = {
	PWM_LOOKUP("board-pwm", 0, "dc-motor.0", "pwm", 50000, PWM_POLARITY_NORMAL),
};
static struct gpiod_lookup_table board_gpios = {
	.dev_id = "dc-motor.0",
	.table = { GPIO_LOOKUP("davinci_gpio", DIR_PIN, "dir", GPIO_ACTIVE_HIGH), { } },
};

static void board_release(struct device *dev)
{
}

static struct platform_device board_motor = {
	.name = "dc-motor", .id = 0, .dev = { .release = board_release },
};

static int __init hack_init(void)
{
	int ret = pwmchip_add(&board_pwm);

	if (ret)
		return ret;
	pwm_add_table(board_pwms, ARRAY_SIZE(board_pwms));
	gpiod_add_lookup_table(&board_gpios);
	ret = motor_driver_init();
	return ret ? ret : platform_device_register(&board_motor);
}
module_init(hack_init);

static void __exit hack_exit(void)
{
	if (device_is_registered(&board_motor.dev))
		platform_device_unregister(&board_motor);
	motor_driver_exit();
	gpiod_remove_lookup_table(&board_gpios);
	pwm_remove_table(board_pwms, ARRAY_SIZE(board_pwms));
	pwmchip_remove(&board_pwm);
}
module_exit(hack_exit);

#define MOTOR	"/sys/class/dc-motor/motor0/"

static char text[64];

static const char *cat(const char *file)
{
	char path[96];
	ssize_t n;

	snprintf(path, sizeof(path), MOTOR "%s", file);
	n = lx_sysfs_read(path, text, sizeof(text) - 1);
	text[n > 0 ? n : 0] = '\0';
	return text;
}

static int echo(const char *file, const char *value)
{
	char path[96];

	snprintf(path, sizeof(path), MOTOR "%s", file);
	return (int)lx_sysfs_write(path, value, strlen(value));
}

static bool dir_level(void)
{
	bool level = false;

	return hs_gpio_soc_output(DIR_PIN, &level) && level;
}

static void body(void)
{
	const struct lx_uevent *ev;
	unsigned int ev0;

	ok(board_motor.dev.driver == &dc_motor_driver.driver, "the motor's device bound");
	is_str(cat("address"), "dc-motor.0\n", "address: the motor's device");
	is_str(cat("commands"), "run-direct stop\n", "commands");
	is_str(cat("state"), "\n", "state: stopped");
	ok(applies == 1 && !applied.enabled && applied.period == 50000, "probe stopped the output (50 us period)");

	is_int(echo("duty_cycle_sp", "60\n"), 3, "duty_cycle_sp 60");
	is_int(applies, 1, "nothing applied while stopped");
	ev0 = lx_uevent_count();
	is_int(echo("command", "run-direct\n"), 11, "command run-direct");
	ok(applied.enabled && applied.duty_cycle == 30000 && !dir_level(), "60 %% forward: 30 of 50 us, dir low");
	is_str(cat("state"), "running\n", "state: running");
	is_str(cat("duty_cycle"), "60\n", "duty_cycle: 60");
	is_int(lx_sysfs_notify_count(MOTOR "state"), 1, "pollers of state were notified");
	ev = lx_uevent_get(ev0);
	ok(ev && ev->action == KOBJ_CHANGE && !strcmp(ev->devpath, "/devices/platform/dc-motor.0/dc-motor/motor0"),
	   "a change uevent of /devices/platform/dc-motor.0/dc-motor/motor0");

	is_int(echo("duty_cycle_sp", "-40"), 3, "duty_cycle_sp -40 while running");
	ok(applied.duty_cycle == 20000 && dir_level(), "follows at once: 20 of 50 us, dir high (reverse)");
	is_int(echo("polarity", "inversed"), 8, "polarity inversed");
	ok(applied.duty_cycle == 20000 && !dir_level(), "the same speed the other way");
	is_str(cat("polarity"), "inversed\n", "polarity reads back");

	is_int(echo("command", "spin"), -EINVAL, "an unknown command: -EINVAL");
	is_int(echo("duty_cycle_sp", "101"), -EINVAL, "duty_cycle_sp beyond 100: -EINVAL");
	is_int(echo("duty_cycle_sp", "fast"), -EINVAL, "not a number: -EINVAL");
	is_int(echo("duty_cycle", "10"), -EACCES, "duty_cycle is read-only: -EACCES");
	is_int((int)lx_sysfs_read(MOTOR "command", text, 8), -EACCES, "command is write-only: -EACCES");

	is_int(echo("command", "stop"), 4, "command stop");
	ok(!applied.enabled, "the output is off");
	is_str(cat("state"), "\n", "state: stopped");
	is_int(lx_sysfs_notify_count(MOTOR "state"), 2, "notified again");

	platform_device_unregister(&board_motor);
	is_int((int)lx_sysfs_read(MOTOR "state", text, 8), -ENOENT, "unbound: motor0 is gone");
	is_int(platform_device_register(&board_motor), 0, "the device again");
	is_str(cat("address"), "dc-motor.0\n", "motor0 again (its number was given back)");
}

int main(void)
{
	tap_plan(32);
	is_int(hs_board_init(NULL), E_OK, "host_sim board");
	hs_gpio_mux_as_gpio(DIR_PIN);
	ok(lx_test_run(body), "test task ran to completion");
	hs_board_shutdown();
	return tap_done();
}
