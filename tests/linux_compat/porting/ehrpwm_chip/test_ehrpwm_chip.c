/*
 * test_ehrpwm_chip.c — ehrpwm_chip.c, an upstream-style PWM chip driver for
 * the AM1808's eHRPWM, taken unchanged, on host_sim's eHRPWM1 model.  The
 * hack's init does the board's part — powers the module in PSC1 and starts
 * the time-base clock in SYSCFG0 as the boot loader and clock code do on
 * the brick, declares eHRPWM1 as a platform device with its registers and
 * the PWM lookup table of a consumer ("motor-test": output A as "a", B as
 * "b", 20 kHz) — then runs the driver's init.  The test is the consumer:
 * pwm_get, pwm_init_state, pwm_apply_state, and the outputs' low fraction and
 * frequency as the model computes them; the shared period, the legacy calls,
 * errors, and misuse reported.
 */
#define KBUILD_MODNAME "ehrpwm_chip"
#define LX_HACK_DRIVER_INIT chip_driver_init
#define LX_HACK_DRIVER_EXIT chip_driver_exit
#include "ehrpwm_chip.c"

#include "driver_common.h"

#include "tap.h"
#include "brick_test.h"
#include "rtos_host.h"
#include <linux/bits.h>
#include <linux/delay.h>
#include <linux/ioport.h>
#include <linux/spinlock.h>
#include <linux/of.h>
#include <mach/da8xx.h>
#include <linux_compat/config.h>
#include "host_sim/board.h"
#include "host_sim/scenario.h"
#include "host_sim/devices/ev3_brick.h"
#include "host_sim/devices/pwm.h"

#define PSC1_BASE		0x01E27000
#define PSC_PTCMD		0x120
#define PSC_PTSTAT		0x128
#define PSC_MDCTL(n)		(0xA00 + 4 * (n))
#define PSC1_LPSC_EHRPWM	17
#define CFGCHIP1_TBCLKSYNC	BIT(12)

static struct resource ehrpwm1_resources[] = {
	DEFINE_RES_MEM(0x01F02000, 0x40),
};
static const char *const ehrpwm1_compat[] = { "ev3lx,am1808-ehrpwm", NULL };
static struct device_node ehrpwm1_node = { .name = "pwm", .full_name = "/pwm@1f02000",
					   .compatible = ehrpwm1_compat };

static void board_release(struct device *dev)
{
}

static struct platform_device ehrpwm1_dev = {
	.name = "ehrpwm", .id = 1,
	.resource = ehrpwm1_resources, .num_resources = ARRAY_SIZE(ehrpwm1_resources),
	.dev = { .of_node = &ehrpwm1_node, .release = board_release },
};

static struct pwm_lookup board_pwms[] = {
	PWM_LOOKUP("ehrpwm.1", 0, "motor-test", "a", 50000, PWM_POLARITY_NORMAL),
	PWM_LOOKUP("ehrpwm.1", 1, "motor-test", "b", 50000, PWM_POLARITY_INVERSED),
	PWM_LOOKUP("ehrpwm.7", 0, "motor-test", "absent", 50000, PWM_POLARITY_NORMAL),
};

/* What the boot loader and the clock code do on the brick: PSC1 powers eHRPWM1,
 * SYSCFG0's CFGCHIP1 starts the eHRPWM time-base clocks. */
static int board_power_ehrpwm(void)
{
	void __iomem *psc = ioremap(PSC1_BASE, 0x1000);
	int i;

	if (!psc)
		return -ENOMEM;
	writel(3, psc + PSC_MDCTL(PSC1_LPSC_EHRPWM));
	writel(readl(psc + PSC_PTCMD) | 3, psc + PSC_PTCMD);
	for (i = 0; i < 100 && (readl(psc + PSC_PTSTAT) & 3); i++)
		udelay(1);
	iounmap(psc);
	writel(0x83E70B13, DA8XX_SYSCFG0_VIRT(DA8XX_KICK0_REG));
	writel(0x95A4F1E0, DA8XX_SYSCFG0_VIRT(DA8XX_KICK1_REG));
	writel(readl(DA8XX_SYSCFG0_VIRT(DA8XX_CFGCHIP1_REG)) | CFGCHIP1_TBCLKSYNC,
	       DA8XX_SYSCFG0_VIRT(DA8XX_CFGCHIP1_REG));
	return i < 100 ? 0 : -ETIMEDOUT;
}

static int __init hack_init(void)
{
	int ret = board_power_ehrpwm();

	if (ret)
		return ret;
	pwm_add_table(board_pwms, ARRAY_SIZE(board_pwms));
	ret = platform_device_register(&ehrpwm1_dev);
	return ret ? ret : chip_driver_init();
}
module_init(hack_init);

static void __exit hack_exit(void)
{
	chip_driver_exit();
	if (device_is_registered(&ehrpwm1_dev.dev))
		platform_device_unregister(&ehrpwm1_dev);
	pwm_remove_table(board_pwms, ARRAY_SIZE(board_pwms));
}
module_exit(hack_exit);

static struct device consumer = { .init_name = "motor-test" };
static DEFINE_SPINLOCK(test_lock);

static bool near(double a, double b)
{
	return a > b - 0.002 && a < b + 0.002;
}

static void body(void)
{
	struct pwm_device *a, *b;
	struct pwm_state st;
	unsigned long flags;

	ok(ehrpwm1_dev.dev.driver == &ehrpwm_driver.driver, "eHRPWM1 bound by compatible");
	ok(near(hs_pwm_low_fraction(HS_PWM_EHRPWM1_A), 1.0), "output A forced low at probe");
	ok(PTR_ERR(pwm_get(&consumer, "absent")) == -EPROBE_DEFER, "a lookup whose chip is absent: -EPROBE_DEFER");
	ok(PTR_ERR(pwm_get(&consumer, "c")) == -ENODEV, "a con_id without a lookup entry: -ENODEV");
	a = pwm_get(&consumer, "a");
	b = pwm_get(&consumer, "b");
	ok(!IS_ERR(a) && !IS_ERR(b), "pwm_get of outputs A and B");
	ok(PTR_ERR(pwm_get(&consumer, "a")) == -EBUSY, "A twice: -EBUSY");
	ok(!pwm_is_enabled(a), "get_state: A is disabled");

	pwm_init_state(a, &st);
	ok(st.period == 50000 && st.duty_cycle == 0 && st.polarity == PWM_POLARITY_NORMAL,
	   "pwm_init_state: the lookup's 50 us, duty 0, normal polarity");
	st.enabled = true;
	is_int(pwm_set_relative_duty_cycle(&st, 25, 100), 0, "a quarter of the period");
	is_int(pwm_apply_state(a, &st), 0, "pwm_apply_state");
	msleep(1);
	ok(near(hs_pwm_frequency(HS_PWM_EHRPWM1_A), 20000.0), "20 kHz (%.1f Hz)", hs_pwm_frequency(HS_PWM_EHRPWM1_A));
	ok(near(hs_pwm_low_fraction(HS_PWM_EHRPWM1_A), 0.75), "high a quarter of the period (low %.4f)",
	   hs_pwm_low_fraction(HS_PWM_EHRPWM1_A));

	pwm_init_state(b, &st);
	st.enabled = true;
	st.duty_cycle = 10000;
	is_int(pwm_apply_might_sleep(b, &st), 0, "B inversed at a fifth, by pwm_apply_might_sleep");
	msleep(1);
	ok(near(hs_pwm_low_fraction(HS_PWM_EHRPWM1_B), 0.2), "inversed: low for the duty (low %.4f)",
	   hs_pwm_low_fraction(HS_PWM_EHRPWM1_B));
	st.period = 40000;
	is_int(pwm_apply_state(b, &st), -EINVAL, "another period while A runs: -EINVAL (one time base)");
	pwm_get_state(b, &st);
	ok(st.period == 50000, "and B keeps its state");
	st.duty_cycle = 60000;
	is_int(pwm_apply_state(b, &st), -EINVAL, "a duty cycle beyond the period: -EINVAL");
	st.duty_cycle = 0;
	st.period = 0;
	is_int(pwm_apply_state(b, &st), -EINVAL, "no period: -EINVAL");

	is_int(pwm_config(a, 40000, 50000), 0, "pwm_config: 40 of 50 us");
	msleep(1);
	ok(near(hs_pwm_low_fraction(HS_PWM_EHRPWM1_A), 0.2), "A high four fifths (low %.4f)",
	   hs_pwm_low_fraction(HS_PWM_EHRPWM1_A));
	pwm_disable(a);
	msleep(1);
	ok(near(hs_pwm_low_fraction(HS_PWM_EHRPWM1_A), 1.0), "pwm_disable: A held at its inactive level, low");
	pwm_disable(b);
	pwm_init_state(a, &st);
	st.period = 2000000000ULL;
	st.enabled = true;
	is_int(pwm_apply_state(a, &st), -ERANGE, "a 2 s period is beyond the prescaler: -ERANGE");

	pwm_get_state(a, &st);
	spin_lock_irqsave(&test_lock, flags);
	st.duty_cycle = 1000;
	rtos_host_expect_bugs(true);
	ok(pwm_apply_state(a, &st) == 0 && rtos_host_bug_count() > 0, "pwm_apply_state under a spin lock is reported");
	rtos_host_expect_bugs(false);
	spin_unlock_irqrestore(&test_lock, flags);

	pwm_put(b);
	rtos_host_expect_bugs(true);
	platform_device_unregister(&ehrpwm1_dev);
	ok(rtos_host_bug_count() > 1, "removing the chip with A still requested is reported");
	rtos_host_expect_bugs(false);
}

int main(void)
{
	tap_plan(26);
	lx_test_on_brick(body, "the simulated brick with eHRPWM1");
	return tap_done();
}
