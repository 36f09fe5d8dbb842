/*
 * ev3rt_gpio.c — EV3RT's GPIO driver interface on linux_compat's DaVinci GPIO
 * (linux_compat/ev3rt_gpio.h).
 */
/* Linux's gpio_get_value is an inline of mach/gpio.h: under another name here,
 * so that the function of EV3RT's name can call it. */
#define gpio_get_value lx_gpio_level
#include <mach/gpio.h>
#undef gpio_get_value

#include <linux/io.h>
#include <linux/kernel.h>
#include <linux/printk.h>
#include <mach/da8xx.h>
#include <linux_compat/ev3rt_gpio.h>

/* SYSCFG0's write protection keys (KICK0R, KICK1R: AM1808 Technical Reference Manual, SYSCFG). */
#define KICK0_KEY	0x83e70b13U
#define KICK1_KEY	0x95a4f1e0U

/* One pad's PINMUX field: register n, bits shift..shift+3, the value selecting the pin. */
struct pad_mux {
	u32 pin;
	u8 reg, shift, mode;
};

/*
 * The pads EV3RT's remaining drivers mux: Bluetooth's UART2 and slow clock
 * (ECAP2_APWM2) and its shutdown line GP4_9; GP4_1, the shutdown line of the
 * board's other revision.  Values: the AM1808's PINMUX fields, as EV3RT's
 * gpio_dri.c sets them (ev3rt-git/ev3rt-hrp2, its MuxRegMap).
 */
static const struct pad_mux pad_muxes[] = {
	{ EV3RT_PIN_UART2_TXD,   4, 20, 2 },
	{ EV3RT_PIN_UART2_RXD,   4, 16, 2 },
	{ EV3RT_PIN_UART2_CTS,   0, 28, 4 },
	{ EV3RT_PIN_UART2_RTS,   0, 24, 4 },
	{ EV3RT_PIN_ECAP2_APWM2, 1,  0, 4 },
	{ 4 * 16 + 1,           10, 24, 8 },	/* GP4_1 */
	{ 4 * 16 + 9,            9, 24, 8 },	/* GP4_9 */
};

void setup_pinmux(uint32_t pin)
{
	void __iomem *reg;
	size_t i;

	for (i = 0; i < ARRAY_SIZE(pad_muxes) && pad_muxes[i].pin != pin; i++)
		;
	if (i == ARRAY_SIZE(pad_muxes) || !da8xx_syscfg0_base) {
		pr_err("setup_pinmux: pin %u: %s\n", (unsigned int)pin,
		       i == ARRAY_SIZE(pad_muxes) ? "no pad multiplexing known" : "SYSCFG0 not mapped");
		return;
	}
	reg = DA8XX_SYSCFG0_VIRT(DA8XX_PINMUX_REG(pad_muxes[i].reg));
	writel(KICK0_KEY, DA8XX_SYSCFG0_VIRT(DA8XX_KICK0_REG));
	writel(KICK1_KEY, DA8XX_SYSCFG0_VIRT(DA8XX_KICK1_REG));
	writel((readl(reg) & ~(0xfU << pad_muxes[i].shift)) | ((u32)pad_muxes[i].mode << pad_muxes[i].shift), reg);
}

int gpio_get_value(unsigned int gpio)
{
	return lx_gpio_level(gpio);
}
