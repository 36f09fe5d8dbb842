// SPDX-License-Identifier: GPL-2.0
/*
 * ehrpwm_chip.c - a PWM chip over one eHRPWM module of a TI AM1808 (AM1808
 * TRM, "Enhanced High-Resolution Pulse-Width Modulator"): its two outputs A
 * and B share the time base, which counts up to TBPRD from a prescaled
 * functional clock; output A is set at counter zero and cleared when the
 * counter reaches CMPA (B: CMPB), the other way round for inversed
 * polarity; a disabled output is forced to its inactive level by the
 * continuous software force.  Compare values load from their shadows at
 * counter zero, so a change takes effect at the next period.
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

#define TBCTL		0x00
#define TBCNT		0x08
#define TBPRD		0x0a
#define CMPCTL		0x0e
#define CMPA		0x12
#define CMPB		0x14
#define AQCTLA		0x16
#define AQCTLB		0x18
#define AQCSFRC		0x1c

#define TBCTL_CTRMODE_UP	0x0
#define TBCTL_CTRMODE_STOP	0x3
#define TBCTL_CTRMODE_MASK	0x3
#define TBCTL_HSPCLKDIV_SHIFT	7
#define TBCTL_CLKDIV_SHIFT	10
#define TBCTL_DIV_MASK		(0x3f << TBCTL_HSPCLKDIV_SHIFT)
#define TBCTL_FREE_RUN		(0x2 << 14)

#define AQ_CLEAR		0x1
#define AQ_SET			0x2
#define AQCTL_ZRO_SHIFT		0
#define AQCTL_CAU_SHIFT		4
#define AQCTL_CBU_SHIFT		8
#define AQCSFRC_LOW		0x1
#define AQCSFRC_HIGH		0x2
#define AQCSFRC_MASK		0x3

#define EHRPWM_NPWM		2
#define EHRPWM_PERIOD_MAX	0x10000	/* TBPRD + 1 counts */

struct ehrpwm_config {
	unsigned long clk_rate;	/* the functional clock (Hz) */
};

struct ehrpwm {
	struct pwm_chip chip;
	void __iomem *base;
	unsigned long clk_rate;
	u64 period_ns;		/* the time base's period while an output is enabled */
	unsigned long enabled;	/* bit per output */
};

static inline struct ehrpwm *to_ehrpwm(struct pwm_chip *chip)
{
	return container_of(chip, struct ehrpwm, chip);
}

static void ehrpwm_modify(struct ehrpwm *pc, unsigned int reg, u16 mask, u16 val)
{
	writew((readw(pc->base + reg) & ~mask) | val, pc->base + reg);
}

/* TBCTL's divider fields for the smallest prescale >= want: the prescale, or 0. */
static unsigned int ehrpwm_prescale(u64 want, u16 *tbctl_div)
{
	unsigned int clkdiv, hspclkdiv, prescale;

	for (clkdiv = 0; clkdiv <= 7; clkdiv++) {
		for (hspclkdiv = 0; hspclkdiv <= 7; hspclkdiv++) {
			prescale = (1U << clkdiv) * (hspclkdiv ? 2 * hspclkdiv : 1);
			if (prescale >= want) {
				*tbctl_div = (u16)(hspclkdiv << TBCTL_HSPCLKDIV_SHIFT |
						   clkdiv << TBCTL_CLKDIV_SHIFT);
				return prescale;
			}
		}
	}
	return 0;
}

/* The prescale TBCTL's dividers give. */
static unsigned int ehrpwm_tbctl_prescale(u16 tbctl)
{
	unsigned int hsp = (tbctl >> TBCTL_HSPCLKDIV_SHIFT) & 7, clk = (tbctl >> TBCTL_CLKDIV_SHIFT) & 7;

	return (1U << clk) * (hsp ? 2 * hsp : 1);
}

static int ehrpwm_apply(struct pwm_chip *chip, struct pwm_device *pwm, const struct pwm_state *state)
{
	struct ehrpwm *pc = to_ehrpwm(chip);
	unsigned int ch = pwm->hwpwm, prescale, other = ch ^ 1;
	u64 cycles, duty;
	u16 div, aq;

	if (!state->enabled) {
		ehrpwm_modify(pc, AQCSFRC, AQCSFRC_MASK << (2 * ch),
			      (state->polarity == PWM_POLARITY_NORMAL ? AQCSFRC_LOW : AQCSFRC_HIGH) << (2 * ch));
		clear_bit(ch, &pc->enabled);
		if (!pc->enabled)
			ehrpwm_modify(pc, TBCTL, TBCTL_CTRMODE_MASK, TBCTL_CTRMODE_STOP);
		return 0;
	}
	if (test_bit(other, &pc->enabled) && state->period != pc->period_ns) {
		dev_err(chip->dev, "period %llu ns: output %u runs at %llu ns, and they share one\n",
			state->period, other, pc->period_ns);
		return -EINVAL;
	}
	if (state->period > NSEC_PER_SEC)
		return -ERANGE;	/* beyond the largest prescale's 0.9 s; the products below fit in 64 bits */
	cycles = div64_u64(state->period * pc->clk_rate, NSEC_PER_SEC);
	prescale = ehrpwm_prescale(div64_u64(cycles + EHRPWM_PERIOD_MAX - 1, EHRPWM_PERIOD_MAX), &div);
	if (!prescale || cycles < 2)
		return -ERANGE;
	cycles = div64_u64(cycles, prescale);
	duty = div64_u64(div64_u64(state->duty_cycle * pc->clk_rate, NSEC_PER_SEC), prescale);

	ehrpwm_modify(pc, TBCTL, TBCTL_DIV_MASK, div);
	writew((u16)(cycles - 1), pc->base + TBPRD);
	writew((u16)duty, pc->base + (ch ? CMPB : CMPA));
	if (state->polarity == PWM_POLARITY_NORMAL)
		aq = AQ_SET << AQCTL_ZRO_SHIFT | AQ_CLEAR << (ch ? AQCTL_CBU_SHIFT : AQCTL_CAU_SHIFT);
	else
		aq = AQ_CLEAR << AQCTL_ZRO_SHIFT | AQ_SET << (ch ? AQCTL_CBU_SHIFT : AQCTL_CAU_SHIFT);
	writew(aq, pc->base + (ch ? AQCTLB : AQCTLA));
	ehrpwm_modify(pc, AQCSFRC, AQCSFRC_MASK << (2 * ch), 0);
	if (!pc->enabled)
		writew(0, pc->base + TBCNT);
	ehrpwm_modify(pc, TBCTL, TBCTL_CTRMODE_MASK, TBCTL_CTRMODE_UP);
	set_bit(ch, &pc->enabled);
	pc->period_ns = state->period;
	return 0;
}

static int ehrpwm_get_state(struct pwm_chip *chip, struct pwm_device *pwm, struct pwm_state *state)
{
	struct ehrpwm *pc = to_ehrpwm(chip);
	unsigned int ch = pwm->hwpwm;
	u16 tbctl = readw(pc->base + TBCTL), aq = readw(pc->base + (ch ? AQCTLB : AQCTLA));
	u64 prescale = ehrpwm_tbctl_prescale(tbctl);
	u64 counts = (u64)readw(pc->base + TBPRD) + 1;
	u64 duty = readw(pc->base + (ch ? CMPB : CMPA));

	state->period = div64_u64(counts * prescale * NSEC_PER_SEC, pc->clk_rate);
	state->duty_cycle = div64_u64(duty * prescale * NSEC_PER_SEC, pc->clk_rate);
	state->polarity = ((aq >> AQCTL_ZRO_SHIFT) & 3) == AQ_CLEAR ? PWM_POLARITY_INVERSED
								      : PWM_POLARITY_NORMAL;
	state->enabled = (tbctl & TBCTL_CTRMODE_MASK) != TBCTL_CTRMODE_STOP &&
			 !((readw(pc->base + AQCSFRC) >> (2 * ch)) & AQCSFRC_MASK);
	state->usage_power = false;
	return 0;
}

static const struct pwm_ops ehrpwm_ops = {
	.apply = ehrpwm_apply,
	.get_state = ehrpwm_get_state,
	.owner = THIS_MODULE,
};

static int ehrpwm_probe(struct platform_device *pdev)
{
	const struct ehrpwm_config *config = device_get_match_data(&pdev->dev);
	struct device *dev = &pdev->dev;
	struct ehrpwm *pc;

	if (!config)
		return dev_err_probe(dev, -EINVAL, "no configuration for this device\n");
	pc = devm_kzalloc(dev, sizeof(*pc), GFP_KERNEL);
	if (!pc)
		return -ENOMEM;
	pc->base = devm_platform_ioremap_resource(pdev, 0);
	if (IS_ERR(pc->base))
		return PTR_ERR(pc->base);
	pc->clk_rate = config->clk_rate;
	/* stopped, free-running under a debugger, compares loaded from their shadows at zero,
	 * both outputs forced low until a consumer enables them */
	writew(TBCTL_FREE_RUN | TBCTL_CTRMODE_STOP, pc->base + TBCTL);
	writew(0, pc->base + CMPCTL);
	writew(AQCSFRC_LOW | AQCSFRC_LOW << 2, pc->base + AQCSFRC);
	pc->chip.dev = dev;
	pc->chip.ops = &ehrpwm_ops;
	pc->chip.npwm = EHRPWM_NPWM;
	pc->chip.base = -1;
	platform_set_drvdata(pdev, pc);
	return devm_pwmchip_add(dev, &pc->chip);
}

/* The AM1808's eHRPWM modules run from PLL1's SYSCLK2 domain as LEGO's EV3 sets it: 132 MHz. */
static const struct ehrpwm_config am1808_ev3_config = { .clk_rate = 132000000 };

static const struct of_device_id ehrpwm_of_match[] = {
	{ .compatible = "ev3lx,am1808-ehrpwm", .data = &am1808_ev3_config },
	{ }
};
MODULE_DEVICE_TABLE(of, ehrpwm_of_match);

static struct platform_driver ehrpwm_driver = {
	.probe = ehrpwm_probe,
	.driver = {
		.name = "ehrpwm",
		.of_match_table = ehrpwm_of_match,
	},
};
module_platform_driver(ehrpwm_driver);

MODULE_DESCRIPTION("AM1808 eHRPWM as a PWM chip");
MODULE_AUTHOR("ev3lx");
MODULE_LICENSE("GPL");
