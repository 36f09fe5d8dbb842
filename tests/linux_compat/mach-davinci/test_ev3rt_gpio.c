/*
 * test_ev3rt_gpio.c — EV3RT's GPIO driver interface on linux_compat
 * (linux_compat/ev3rt_gpio.h), against host_sim's SYSCFG0 (kick-protected
 * PINMUX registers) and GPIO models: setup_pinmux sets exactly the pad's
 * field for Bluetooth's UART2, slow clock and shutdown line and leaves the
 * rest of the register alone; an unknown pin changes nothing; EV3RT's
 * gpio_get_value is a function reading the pin's level.
 */
#include "lx_test.h"
/* Linux's inline gpio_get_value under another name: the one tested is EV3RT's function. */
#define gpio_get_value lx_gpio_level
#include <linux/gpio.h>
#undef gpio_get_value
#include <linux/io.h>
#include <mach/da8xx.h>
#include <linux_compat/ev3rt_gpio.h>
#include "host_sim/board.h"
#include "host_sim/gpio.h"

/* PINMUX register n as the SoC has it now. */
static u32 pinmux(unsigned int n)
{
	return readl(DA8XX_SYSCFG0_VIRT(DA8XX_PINMUX_REG(n)));
}

static void body(void)
{
	u32 before4 = pinmux(4), before0 = pinmux(0), before9 = pinmux(9);
	u32 regs[20];
	int same = 1;

	setup_pinmux(EV3RT_PIN_UART2_TXD);
	setup_pinmux(EV3RT_PIN_UART2_RXD);
	is_int((int)((pinmux(4) >> 16) & 0xff), 0x22, "UART2 TXD and RXD: PINMUX4[23:16] = 2, 2");
	is_int((int)(pinmux(4) & ~0x00ff0000U), (int)(before4 & ~0x00ff0000U), "the rest of PINMUX4 unchanged");
	setup_pinmux(EV3RT_PIN_UART2_CTS);
	setup_pinmux(EV3RT_PIN_UART2_RTS);
	is_int((int)(pinmux(0) >> 24), 0x44, "UART2 CTS and RTS: PINMUX0[31:24] = 4, 4");
	is_int((int)(pinmux(0) & 0x00ffffffU), (int)(before0 & 0x00ffffffU), "the rest of PINMUX0 unchanged");
	setup_pinmux(EV3RT_PIN_ECAP2_APWM2);
	is_int((int)(pinmux(1) & 0xf), 4, "ECAP2_APWM2: PINMUX1[3:0] = 4");
	setup_pinmux(4 * 16 + 9);
	is_int((int)((pinmux(9) >> 24) & 0xf), 8, "GP4_9: PINMUX9[27:24] = 8 (GPIO)");
	is_int((int)(pinmux(9) & ~0x0f000000U), (int)(before9 & ~0x0f000000U), "the rest of PINMUX9 unchanged");

	for (unsigned int n = 0; n < 20; n++)
		regs[n] = pinmux(n);
	setup_pinmux(200);
	for (unsigned int n = 0; n < 20; n++)
		same &= regs[n] == pinmux(n);
	ok(same, "an unknown pin changes no PINMUX register");

	is_int(gpio_direction_input(GPIO_TO_PIN(1, 13)), 0, "the ENTER button's pin an input");
	hs_gpio_set_input(GPIO_TO_PIN(1, 13), 1);
	is_int(gpio_get_value(GPIO_TO_PIN(1, 13)), 1, "EV3RT's gpio_get_value sees it high");
	hs_gpio_set_input(GPIO_TO_PIN(1, 13), 0);
	is_int(gpio_get_value(GPIO_TO_PIN(1, 13)), 0, "and low");
}

int main(void)
{
	tap_plan(13);
	is_int(hs_board_init(NULL), E_OK, "host_sim board");
	ok(lx_test_run(body), "test task ran to completion");
	hs_board_shutdown();
	return tap_done();
}
