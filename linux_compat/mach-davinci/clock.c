/*
 * clock.c — the DA850 (AM1808) clocks drivers look up by name (linux/clk.h).
 * Names as TI's DaVinci tree registers them for the PRU soft UART
 * (arch/arm/mach-davinci/da850.c: "pru_ck", "mcasp_pru"); both run from
 * PLL0_SYSCLK2, half the CPU clock (AM1808 TRM, Device Clocking), 150 MHz
 * on the EV3's 300 MHz CPU.
 */
#include <linux/clk.h>
#include <linux/kernel.h>
#include <linux/string.h>
#include <linux_compat/report.h>

struct clk {
	const char *con_id;
	unsigned long rate;
	unsigned int enables;
};

#define DA850_SYSCLK2_HZ	150000000UL

static struct clk da850_clocks[] = {
	{ "pru_ck", DA850_SYSCLK2_HZ, 0 },
	{ "mcasp_pru", DA850_SYSCLK2_HZ, 0 },
};

struct clk *clk_get(struct device *dev, const char *con_id)
{
	for (unsigned int i = 0; con_id && i < ARRAY_SIZE(da850_clocks); i++)
		if (!strcmp(da850_clocks[i].con_id, con_id))
			return &da850_clocks[i];
	return ERR_PTR(-ENOENT);
}

void clk_put(struct clk *clk)
{
}

int clk_enable(struct clk *clk)
{
	if (IS_ERR_OR_NULL(clk))
		return -EINVAL;
	clk->enables++;
	return 0;
}

void clk_disable(struct clk *clk)
{
	if (IS_ERR_OR_NULL(clk))
		return;
	if (!clk->enables) {
		WARN(1, "clk_disable(%s): not enabled", clk->con_id);
		return;
	}
	clk->enables--;
}

unsigned long clk_get_rate(struct clk *clk)
{
	return IS_ERR_OR_NULL(clk) ? 0 : clk->rate;
}
