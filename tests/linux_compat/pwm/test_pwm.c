/*
 * test_pwm.c — the PWM core with a chip that records what it is asked:
 * global numbers (dynamic bases one after another), lookups (the entry
 * naming both the device and the connection wins over one naming the
 * device, which wins over one naming neither), the chip's request and
 * get_state at pwm_get, -EPROBE_DEFER before the chip, -EBUSY, state
 * validation, an unchanged state not applied, a failing apply leaving the
 * state, pwm_adjust_config, devm_pwm_get and devm_pwmchip_add undone on
 * unbind, and misuse reported (pwm_put twice, applying in atomic context).
 */
#define KBUILD_MODNAME "pwmtest"
#include "lx_log_test.h"
#include <linux/platform_device.h>
#include <linux/pwm.h>
#include <linux/spinlock.h>
#include "host_sim/board.h"

static char trail[256];
static int fail_apply;

static void note(const char *fmt, unsigned int hwpwm)
{
	size_t at = strlen(trail);

	snprintf(trail + at, sizeof(trail) - at, fmt, hwpwm);
}

static int rec_request(struct pwm_chip *chip, struct pwm_device *pwm)
{
	note("req%u ", pwm->hwpwm);
	return pwm->hwpwm == 3 ? -EIO : 0;
}

static void rec_free(struct pwm_chip *chip, struct pwm_device *pwm)
{
	note("free%u ", pwm->hwpwm);
}

static int rec_apply(struct pwm_chip *chip, struct pwm_device *pwm, const struct pwm_state *state)
{
	note("apply%u ", pwm->hwpwm);
	return fail_apply;
}

static int rec_get_state(struct pwm_chip *chip, struct pwm_device *pwm, struct pwm_state *state)
{
	state->period = 1000;
	state->duty_cycle = 500;
	state->polarity = PWM_POLARITY_NORMAL;
	state->enabled = pwm->hwpwm == 1;
	return 0;
}

static const struct pwm_ops rec_ops = {
	.request = rec_request, .free = rec_free, .apply = rec_apply, .get_state = rec_get_state,
};

static struct device chip_dev0 = { .init_name = "recpwm.0" };
static struct device chip_dev1 = { .init_name = "recpwm.1" };
static struct device user = { .init_name = "user" };
static struct device other = { .init_name = "other" };

static struct pwm_lookup table[] = {
	PWM_LOOKUP("recpwm.0", 0, NULL, NULL, 100, PWM_POLARITY_NORMAL),
	PWM_LOOKUP("recpwm.0", 1, "user", NULL, 200, PWM_POLARITY_NORMAL),
	PWM_LOOKUP("recpwm.0", 2, "user", "fan", 300, PWM_POLARITY_INVERSED),
	PWM_LOOKUP("recpwm.0", 3, "user", "broken", 300, PWM_POLARITY_NORMAL),
	PWM_LOOKUP("recpwm.9", 0, "user", "later", 300, PWM_POLARITY_NORMAL),
};

static DEFINE_SPINLOCK(test_lock);

static void core_tests(void)
{
	struct pwm_chip chip0 = { .dev = &chip_dev0, .ops = &rec_ops, .npwm = 4, .base = -1 };
	struct pwm_chip chip1 = { .dev = &chip_dev1, .ops = &rec_ops, .npwm = 2, .base = -1 };
	struct pwm_chip bad = { .dev = &chip_dev1, .ops = &rec_ops, .npwm = 0 };
	struct pwm_device *fan, *plain, *any;
	struct pwm_state st;
	unsigned long flags;

	is_int(pwmchip_add(&chip0), 0, "pwmchip_add");
	is_int(pwmchip_add(&chip1), 0, "a second chip");
	ok(chip0.base == 0 && chip1.base == 4 && chip1.pwms[1].pwm == 5, "dynamic bases follow each other");
	is_int(pwmchip_add(&bad), -EINVAL, "a chip without PWMs: -EINVAL");
	pwm_add_table(table, ARRAY_SIZE(table));

	ok(PTR_ERR(pwm_get(&user, "later")) == -EPROBE_DEFER, "the entry's chip is not registered: -EPROBE_DEFER");
	fan = pwm_get(&user, "fan");
	ok(!IS_ERR(fan) && fan->hwpwm == 2 && fan->args.period == 300 && fan->args.polarity == PWM_POLARITY_INVERSED,
	   "device and connection named: that entry, with its period and polarity");
	plain = pwm_get(&user, "motor");
	ok(!IS_ERR(plain) && plain->hwpwm == 1, "only the device named: the device's entry");
	any = pwm_get(&other, NULL);
	ok(!IS_ERR(any) && any->hwpwm == 0, "another device: the entry naming neither");
	ok(PTR_ERR(pwm_get(&user, "broken")) == -EIO, "the chip's request error comes back");
	ok(PTR_ERR(pwm_get(&user, "fan")) == -EBUSY, "a requested device: -EBUSY");
	is_str(trail, "req2 req1 req0 req3 ", "the chip was asked to request each");
	ok(pwm_is_enabled(plain) && pwm_get_period(plain) == 1000 && pwm_get_duty_cycle(plain) == 500,
	   "pwm_get read the hardware's state through get_state");

	trail[0] = '\0';
	pwm_get_state(plain, &st);
	is_int(pwm_apply_state(plain, &st), 0, "applying the state it has");
	is_str(trail, "", "calls nothing");
	st.duty_cycle = 1001;
	is_int(pwm_apply_state(plain, &st), -EINVAL, "a duty cycle beyond the period: -EINVAL");
	st.period = 0;
	st.duty_cycle = 0;
	is_int(pwm_apply_state(plain, &st), -EINVAL, "no period: -EINVAL");
	is_int(pwm_apply_state(NULL, &st), -EINVAL, "no device: -EINVAL");
	pwm_init_state(plain, &st);
	ok(st.period == 200 && st.duty_cycle == 0 && st.enabled, "pwm_init_state: the lookup's period, duty 0");
	fail_apply = -ERANGE;
	is_int(pwm_apply_state(plain, &st), -ERANGE, "the chip's error");
	ok(pwm_get_period(plain) == 1000, "and the device keeps its state");
	fail_apply = 0;
	is_int(pwm_adjust_config(fan), 0, "pwm_adjust_config");
	ok(pwm_get_period(fan) == 300 && pwm_get_polarity(fan) == PWM_POLARITY_INVERSED,
	   "sets the lookup's period and polarity");
	is_str(trail, "apply1 apply2 ", "two applies reached the chip");

	spin_lock_irqsave(&test_lock, flags);
	st.duty_cycle = 10;
	ok(DC_EXPECT_BUG(pwm_apply_state(plain, &st)) >= 1, "pwm_apply_state under a spin lock is reported");
	spin_unlock_irqrestore(&test_lock, flags);

	trail[0] = '\0';
	pwm_put(fan);
	pwm_put(plain);
	pwm_put(any);
	is_str(trail, "free2 free1 free0 ", "pwm_put frees each");
	is_int(DC_EXPECT_BUG(pwm_put(fan)), 1, "pwm_put twice is reported");
	pwmchip_remove(&chip1);
	pwmchip_remove(&chip0);
	ok(PTR_ERR(pwm_get(&user, "fan")) == -EPROBE_DEFER, "its chip removed: the entry defers again");
	pwm_remove_table(table, ARRAY_SIZE(table));
	ok(PTR_ERR(pwm_get(&user, "fan")) == -ENODEV, "the table removed: -ENODEV");
}

static struct pwm_chip devm_chip = { .ops = &rec_ops, .npwm = 1, .base = -1 };
static struct pwm_device *devm_pwm;
static struct pwm_lookup devm_table[] = {
	PWM_LOOKUP("pwmtest-chip", 0, "pwmtest-user", NULL, 100, PWM_POLARITY_NORMAL),
};

static int chip_probe(struct platform_device *pdev)
{
	devm_chip.dev = &pdev->dev;
	return devm_pwmchip_add(&pdev->dev, &devm_chip);
}

static int user_probe(struct platform_device *pdev)
{
	devm_pwm = devm_pwm_get(&pdev->dev, NULL);
	return PTR_ERR_OR_ZERO(devm_pwm);
}

static struct platform_driver chip_driver = { .probe = chip_probe, .driver = { .name = "pwmtest-chip" } };
static struct platform_driver user_driver = { .probe = user_probe, .driver = { .name = "pwmtest-user" } };

static void devm_tests(void)
{
	struct platform_device *chip = platform_device_alloc("pwmtest-chip", -1);
	struct platform_device *consumer = platform_device_alloc("pwmtest-user", -1);

	pwm_add_table(devm_table, ARRAY_SIZE(devm_table));
	platform_device_add(consumer);
	platform_driver_register(&user_driver);
	ok(consumer->dev.driver == NULL && lx_deferred_probe_count() == 1,
	   "the consumer's probe defers: no chip yet");
	platform_device_add(chip);
	platform_driver_register(&chip_driver);
	ok(consumer->dev.driver == &user_driver.driver && !IS_ERR_OR_NULL(devm_pwm),
	   "the chip's arrival binds the deferred consumer");
	trail[0] = '\0';
	platform_driver_unregister(&user_driver);
	is_str(trail, "free0 ", "unbinding the consumer put its PWM");
	platform_driver_unregister(&chip_driver);
	ok(devm_chip.pwms == NULL, "unbinding the chip removed it");
	platform_device_unregister(consumer);
	platform_device_unregister(chip);
	pwm_remove_table(devm_table, ARRAY_SIZE(devm_table));
}

static void body(void)
{
	core_tests();
	devm_tests();
}

int main(void)
{
	tap_plan(34);
	is_int(hs_board_init(NULL), E_OK, "host_sim board");
	ok(lx_test_run(body), "test task ran to completion");
	hs_board_shutdown();
	return tap_done();
}
