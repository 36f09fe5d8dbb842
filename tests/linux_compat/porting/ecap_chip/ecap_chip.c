// SPDX-License-Identifier: GPL-2.0
/*
 * ecap_chip.c - a PWM chip over one eCAP module of a TI AM1808 in its
 * auxiliary PWM mode (AM1808 TRM, "Enhanced Capture (eCAP) Module"): the
 * 32-bit counter runs from the functional clock up to CAP1 (the period) and
 * the output is active while it is below CAP2 (the duty cycle), high unless
 * APWMPOL makes it active low.  While the output runs, new values go to the
 * shadows CAP3 and CAP4, which the module loads at the end of the period;
 * leaving APWM mode holds the output low.
 */
#include <linux/bitops.h>
#include <linux/device.h>
#include <linux/io.h>
#include <linux/math64.h>
#include <linux/mod_devicetable.h>
#include <linux/module.h>
#include <linux/platform_device.h>
#include <linux/property.h>
#include <linux/pwm.h>
#include <linux/time64.h>

#define TSCTR			0x00
#define CAP1			0x08
#define CAP2			0x0c
#define CAP3			0x10
#define CAP4			0x14
#define ECCTL2			0x2a

#define ECCTL2_TSCTRSTOP	BIT(4)
#define ECCTL2_SYNCO_SEL_DIS	(BIT(6) | BIT(7))
#define ECCTL2_APWM		BIT(9)
#define ECCTL2_APWMPOL		BIT(10)

struct ecap_config {
	unsigned long clk_rate;	/* the functional clock (Hz) */
};

struct ecap {
	struct pwm_chip chip;
	void __iomem *base;
	unsigned long clk_rate;
};

static inline struct ecap *to_ecap(struct pwm_chip *chip)
{
	return container_of(chip, struct ecap, chip);
}

static int ecap_apply(struct pwm_chip *chip, struct pwm_device *pwm, const struct pwm_state *state)
{
	struct ecap *pc = to_ecap(chip);
	u16 ctl = readw(pc->base + ECCTL2);
	bool running = (ctl & (ECCTL2_APWM | ECCTL2_TSCTRSTOP)) == (ECCTL2_APWM | ECCTL2_TSCTRSTOP);
	u64 period, duty;

	if (!state->enabled) {
		writew(ctl & ~(ECCTL2_APWM | ECCTL2_TSCTRSTOP), pc->base + ECCTL2);
		return 0;
	}
	if (state->period > 10ULL * NSEC_PER_SEC)
		return -ERANGE;	/* the products below fit in 64 bits up to here */
	period = div64_u64(state->period * pc->clk_rate, NSEC_PER_SEC);
	duty = div64_u64(state->duty_cycle * pc->clk_rate, NSEC_PER_SEC);
	if (period < 2 || period > U32_MAX)
		return -ERANGE;
	if (running && (state->polarity == PWM_POLARITY_INVERSED) == !!(ctl & ECCTL2_APWMPOL)) {
		/* the running output takes the new values at the end of its period */
		writel((u32)(period - 1), pc->base + CAP3);
		writel((u32)duty, pc->base + CAP4);
		return 0;
	}
	ctl = ECCTL2_APWM | ECCTL2_SYNCO_SEL_DIS;
	if (state->polarity == PWM_POLARITY_INVERSED)
		ctl |= ECCTL2_APWMPOL;
	writew(ctl, pc->base + ECCTL2);
	writel((u32)(period - 1), pc->base + CAP1);
	writel((u32)duty, pc->base + CAP2);
	writel(0, pc->base + TSCTR);
	writew(ctl | ECCTL2_TSCTRSTOP, pc->base + ECCTL2);
	return 0;
}

static int ecap_get_state(struct pwm_chip *chip, struct pwm_device *pwm, struct pwm_state *state)
{
	struct ecap *pc = to_ecap(chip);
	u16 ctl = readw(pc->base + ECCTL2);
	u64 period = (u64)readl(pc->base + CAP1) + 1;

	state->period = div64_u64(period * NSEC_PER_SEC, pc->clk_rate);
	state->duty_cycle = div64_u64((u64)readl(pc->base + CAP2) * NSEC_PER_SEC, pc->clk_rate);
	state->polarity = ctl & ECCTL2_APWMPOL ? PWM_POLARITY_INVERSED : PWM_POLARITY_NORMAL;
	state->enabled = (ctl & (ECCTL2_APWM | ECCTL2_TSCTRSTOP)) == (ECCTL2_APWM | ECCTL2_TSCTRSTOP);
	state->usage_power = false;
	return 0;
}

static const struct pwm_ops ecap_ops = {
	.apply = ecap_apply,
	.get_state = ecap_get_state,
	.owner = THIS_MODULE,
};

static int ecap_probe(struct platform_device *pdev)
{
	const struct ecap_config *config = device_get_match_data(&pdev->dev);
	struct device *dev = &pdev->dev;
	struct ecap *pc;

	if (!config)
		return dev_err_probe(dev, -EINVAL, "no configuration for this device\n");
	pc = devm_kzalloc(dev, sizeof(*pc), GFP_KERNEL);
	if (!pc)
		return -ENOMEM;
	pc->base = devm_platform_ioremap_resource(pdev, 0);
	if (IS_ERR(pc->base))
		return PTR_ERR(pc->base);
	pc->clk_rate = config->clk_rate;
	pc->chip.dev = dev;
	pc->chip.ops = &ecap_ops;
	pc->chip.npwm = 1;
	pc->chip.base = -1;
	platform_set_drvdata(pdev, pc);
	return devm_pwmchip_add(dev, &pc->chip);
}

/* The AM1808's eCAP modules run from PLL1's SYSCLK2 domain as LEGO's EV3 sets it: 132 MHz. */
static const struct ecap_config am1808_ev3_config = { .clk_rate = 132000000 };

static const struct of_device_id ecap_of_match[] = {
	{ .compatible = "ev3lx,am1808-ecap", .data = &am1808_ev3_config },
	{ }
};
MODULE_DEVICE_TABLE(of, ecap_of_match);

static struct platform_driver ecap_driver = {
	.probe = ecap_probe,
	.driver = {
		.name = "ecap",
		.of_match_table = ecap_of_match,
	},
};
module_platform_driver(ecap_driver);

MODULE_DESCRIPTION("AM1808 eCAP in APWM mode as a PWM chip");
MODULE_AUTHOR("ev3lx");
MODULE_LICENSE("GPL");
