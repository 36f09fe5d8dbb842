/*
 * test_lms_modules.c — two modules written in the 2.6-era idiom (tests/legacy/
 * drivers/), each included verbatim by its hack and linked as one relocatable
 * object with a private namespace, run together at the configuration's -O2
 * on the simulated EV3: both define Hw, HwId, InitGpio, PinTable and GpioBase
 * and keep their own; a HwId module parameter selects a board table; GPIO
 * registers through plain `volatile unsigned long *` and struct-of-ULONG
 * pointers with compound read-modify-write statements; a GPIO edge interrupt;
 * eHRPWM1 as 16-bit registers through one 0x2854-byte ioremap window; SPI0
 * frames to the EV3's converter (SPIBUF's data half read as 16 bits), UART0
 * in loopback polled by 8-bit LSR reads, eCAP0's 32-bit CAP1 written as two
 * 16-bit halves.
 */
#include <stdio.h>
#include <string.h>

#include "legacy_test.h"
#include "sil.h"
#include "host_sim/gpio.h"
#include "host_sim/psc.h"
#include <linux_compat/modparam.h>

#include "lms_gpio_hack.h"
#include "lms_motor_hack.h"
#include "lms_serial_hack.h"
#include "host_sim/devices/spi_adc.h"

#define GPIO_OUT_EP2  HS_GPIO(3, 13)   /* lms_gpio's output on board EP2 */
#define GPIO_IN_EP2   HS_GPIO(0, 3)    /* and its edge input */
#define MOTOR_EN      HS_GPIO(2, 1)    /* lms_motor's enable pin on board FINAL */
#define PWM1_PHYS     0x01F02000U

static bool output(unsigned pin)
{
	bool level = false;

	return hs_gpio_soc_output(pin, &level) && level;
}

static uint16_t pwm_reg(unsigned offset)
{
	return sil_reh_mem(rtos_host_map_io(PWM1_PHYS + offset, 2));
}

static void body(void)
{
	is_int(lx_module_param_set("lms_gpio", "HwId", "1"), E_OK, "lms_gpio.HwId=1 (board EP2) before init");
	is_int(lms_gpio_load(), 0, "lms_gpio's init succeeds");
	is_int(lms_motor_load(), 0, "lms_motor's init succeeds");
	is_int(lms_gpio_board(), 1, "lms_gpio's Hw is its own: board EP2");
	is_int(lms_motor_board(), 0, "lms_motor's Hw is its own: board FINAL");

	ok(!output(GPIO_OUT_EP2), "lms_gpio: its EP2 output pin is an output, low (CLR_DATA, DIR &= ~m)");
	for (int i = 0; i < 3; i++) {
		hs_gpio_set_input(GPIO_IN_EP2, 1);
		dly_tsk(1);
		hs_gpio_set_input(GPIO_IN_EP2, 0);
		dly_tsk(1);
	}
	is_int((int)lms_gpio_edges(), 3, "lms_gpio: three rising edges, three interrupts");
	ok(output(GPIO_OUT_EP2), "the handler's OUT_DATA |= m left the output high after an odd count");
	hs_gpio_set_input(GPIO_IN_EP2, 1);
	dly_tsk(1);
	ok(!output(GPIO_OUT_EP2), "and p[i] = (p[i] & ~m) | 0 cleared it on the fourth");

	ok(output(MOTOR_EN), "lms_motor: enable pin driven high (SET_DATA, then DIR &= ~m)");
	is_int(pwm_reg(0x0A), 9999, "lms_motor: TBPRD written through a u16 pointer");
	is_int(pwm_reg(0x00) & 0x33, 0x30, "TBCTL &= ~3; TBCTL |= 0x30 (16-bit read-modify-write)");
	lms_motor_duty(2500);
	is_int(pwm_reg(0x12), 2500, "SetDuty: CMPA");
	is_int(pwm_reg(0x16), 0x21, "AQCTLA = (AQCTLA & ~0xFFF) | 0x21");

	lms_motor_unload();
	lms_gpio_unload();
	hs_gpio_set_input(GPIO_IN_EP2, 0);
	dly_tsk(1);
	hs_gpio_set_input(GPIO_IN_EP2, 1);
	dly_tsk(1);
	is_int((int)lms_gpio_edges(), 4, "after unload the interrupt is released: no more edges counted");

	/* lms_serial: SPI0 and the converter, UART0 in loopback, eCAP0's 32-bit CAP1 in 16-bit halves */
	is_int(lx_module_param_set("lms_serial", "HwId", "2"), E_OK, "lms_serial.HwId=2");
	is_int(lms_serial_load(), 0, "lms_serial's init succeeds");
	is_int(lms_serial_board(), 2, "lms_serial's Hw is its own too");
	is_int((int)(lms_serial_adc_answer(2) >> 12), 5,
	       "SPI0: the third frame answers the channel the first one asked for (ADS7957 pipeline)");
	is_int((int)lms_serial_adc_answer(2), (int)ads7957_word(5, ev3_adc_channel_mv(5)),
	       "with the converter's value for it (SPIBUF's data half read as 16 bits)");
	{
		char echo[8] = "";

		is_int(lms_serial_echo(echo, sizeof(echo)), 3, "UART0 loopback: three bytes came back");
		ok(memcmp(echo, "EV3", 3) == 0, "the bytes sent, polled by 8-bit reads of LSR");
	}
	is_int((int)lms_serial_pwm_period(), 0x12345, "eCAP0 CAP1 written as two 16-bit halves reads back whole");
	lms_serial_unload();
}

/* The boot loader's part on the brick: PSC1 powers eHRPWM1 and eCAP, PSC0 SPI0 and UART0. */
static void power_on(void)
{
	hs_psc_force(HS_PSC1_MODULE(HS_LPSC1_EHRPWM), HS_PSC_ENABLE);
	hs_psc_force(HS_PSC1_MODULE(HS_LPSC1_ECAP), HS_PSC_ENABLE);
	hs_psc_force(HS_PSC0_MODULE(HS_LPSC0_SPI0), HS_PSC_ENABLE);
	hs_psc_force(HS_PSC0_MODULE(HS_LPSC0_UART0), HS_PSC_ENABLE);
}

int main(void)
{
	static const struct lt_test test = {
		.name = "lms_modules", .power_on = power_on, .body = body, .after_boot = 24, .plain_pointers = true,
	};

	tap_plan(24);
	if (lt_run(&test))
		ok(lt_done, "the test body ran to its end");
	return tap_done();
}
