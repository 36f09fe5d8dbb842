/*
 * test_ecap_chip.c — ecap_chip.c, an upstream-style PWM chip driver for the
 * AM1808's eCAP in APWM mode, taken unchanged, on host_sim's eCAP0 and
 * eCAP1 models.  The hack's init does the board's part — powers the eCAPs
 * in PSC1 as the boot loader does, declares both as platform devices with
 * their registers, and the lookup table of a consumer ("motor-test": eCAP0
 * as "c", eCAP1 as "d") — then runs the driver's init.  The test is the
 * consumer: the outputs' frequency and low fraction as the models compute
 * them, a change of a running output at its period's end (the shadows),
 * inversed polarity, disabling, and errors.
 */
#define KBUILD_MODNAME "ecap_chip"
#define LX_HACK_DRIVER_INIT chip_driver_init
#define LX_HACK_DRIVER_EXIT chip_driver_exit
#include "ecap_chip.c"

#include "driver_common.h"

#include "tap.h"
#include "brick_test.h"
#include "rtos_host.h"
#include <linux/delay.h>
#include <linux/ioport.h>
#include <linux/of.h>
#include <linux_compat/config.h>
#include "host_sim/board.h"
#include "host_sim/scenario.h"
#include "host_sim/devices/ev3_brick.h"
#include "host_sim/devices/pwm.h"

#define PSC1_BASE		0x01E27000
#define PSC_PTCMD		0x120
#define PSC_PTSTAT		0x128
#define PSC_MDCTL(n)		(0xA00 + 4 * (n))
#define PSC1_LPSC_ECAP		20

static struct resource ecap0_resources[] = { DEFINE_RES_MEM(0x01F06000, 0x60) };
static struct resource ecap1_resources[] = { DEFINE_RES_MEM(0x01F07000, 0x60) };
static const char *const ecap_compat[] = { "ev3lx,am1808-ecap", NULL };
static struct device_node ecap0_node = { .name = "pwm", .full_name = "/pwm@1f06000", .compatible = ecap_compat };
static struct device_node ecap1_node = { .name = "pwm", .full_name = "/pwm@1f07000", .compatible = ecap_compat };

static void board_release(struct device *dev)
{
}

static struct platform_device ecap_devs[] = {
	{ .name = "ecap", .id = 0, .resource = ecap0_resources, .num_resources = 1,
	  .dev = { .of_node = &ecap0_node, .release = board_release } },
	{ .name = "ecap", .id = 1, .resource = ecap1_resources, .num_resources = 1,
	  .dev = { .of_node = &ecap1_node, .release = board_release } },
};

static struct pwm_lookup board_pwms[] = {
	PWM_LOOKUP("ecap.0", 0, "motor-test", "c", 100000, PWM_POLARITY_NORMAL),
	PWM_LOOKUP("ecap.1", 0, "motor-test", "d", 100000, PWM_POLARITY_INVERSED),
};

/* What the boot loader does on the brick: PSC1 powers the eCAPs. */
static int board_power_ecap(void)
{
	void __iomem *psc = ioremap(PSC1_BASE, 0x1000);
	int i;

	if (!psc)
		return -ENOMEM;
	writel(3, psc + PSC_MDCTL(PSC1_LPSC_ECAP));
	writel(readl(psc + PSC_PTCMD) | 3, psc + PSC_PTCMD);
	for (i = 0; i < 100 && (readl(psc + PSC_PTSTAT) & 3); i++)
		udelay(1);
	iounmap(psc);
	return i < 100 ? 0 : -ETIMEDOUT;
}

static int __init hack_init(void)
{
	int ret = board_power_ecap();

	if (!ret)
		ret = platform_device_register(&ecap_devs[0]);
	if (!ret)
		ret = platform_device_register(&ecap_devs[1]);
	if (ret)
		return ret;
	pwm_add_table(board_pwms, ARRAY_SIZE(board_pwms));
	return chip_driver_init();
}
module_init(hack_init);

static void __exit hack_exit(void)
{
	chip_driver_exit();
	pwm_remove_table(board_pwms, ARRAY_SIZE(board_pwms));
	platform_device_unregister(&ecap_devs[1]);
	platform_device_unregister(&ecap_devs[0]);
}
module_exit(hack_exit);

static struct device consumer = { .init_name = "motor-test" };

static bool near(double a, double b)
{
	return a > b - 0.002 && a < b + 0.002;
}

static void body(void)
{
	struct pwm_device *c, *d;
	struct pwm_state st;

	ok(ecap_devs[0].dev.driver == &ecap_driver.driver && ecap_devs[1].dev.driver == &ecap_driver.driver,
	   "eCAP0 and eCAP1 bound by compatible");
	c = pwm_get(&consumer, "c");
	d = pwm_get(&consumer, "d");
	ok(!IS_ERR(c) && !IS_ERR(d), "pwm_get of both");
	if (IS_ERR(c) || IS_ERR(d))
		return;
	ok(!pwm_is_enabled(c), "get_state: stopped after reset");

	pwm_init_state(c, &st);
	st.enabled = true;
	pwm_set_relative_duty_cycle(&st, 30, 100);
	is_int(pwm_apply_state(c, &st), 0, "eCAP0 at 10 kHz, high 30 percent");
	msleep(1);
	ok(near(hs_pwm_frequency(HS_PWM_ECAP0), 10000.0), "10 kHz (%.1f Hz)", hs_pwm_frequency(HS_PWM_ECAP0));
	ok(near(hs_pwm_low_fraction(HS_PWM_ECAP0), 0.7), "low 70 percent (%.4f)", hs_pwm_low_fraction(HS_PWM_ECAP0));
	pwm_get_state(c, &st);
	ok(st.period == 100000 && st.duty_cycle == 30000, "the state kept");

	pwm_set_relative_duty_cycle(&st, 90, 100);
	is_int(pwm_apply_state(c, &st), 0, "the running output to 90 percent");
	ok(near(hs_pwm_low_fraction(HS_PWM_ECAP0), 0.7), "not before its period ends (the shadows)");
	msleep(1);
	ok(near(hs_pwm_low_fraction(HS_PWM_ECAP0), 0.1), "then low 10 percent (%.4f)", hs_pwm_low_fraction(HS_PWM_ECAP0));

	pwm_init_state(d, &st);
	st.enabled = true;
	pwm_set_relative_duty_cycle(&st, 25, 100);
	is_int(pwm_apply_state(d, &st), 0, "eCAP1 inversed at 25 percent");
	msleep(1);
	ok(near(hs_pwm_low_fraction(HS_PWM_ECAP1), 0.25), "active low: low 25 percent (%.4f)",
	   hs_pwm_low_fraction(HS_PWM_ECAP1));

	pwm_disable(c);
	msleep(1);
	ok(near(hs_pwm_low_fraction(HS_PWM_ECAP0), 1.0), "pwm_disable: held low");
	ok(!pwm_is_enabled(c), "and disabled");
	st.period = 20ULL * 1000 * 1000 * 1000;
	is_int(pwm_apply_state(d, &st), -ERANGE, "a 20 s period: -ERANGE");
	pwm_put(c);
	pwm_put(d);
}

int main(void)
{
	tap_plan(17);
	lx_test_on_brick(body, "the simulated brick with eCAP0 and eCAP1");
	return tap_done();
}
