/*
 * test_lms_pins26.c — lms_pins26, a module as Linux 2.6.33's DaVinci kernel
 * built them (<asm/gpio.h>; not built under kbuild against today's headers,
 * which lack it), built with linux_compat alone and run at the
 * configuration's -O2 on the simulated EV3: it claims its pins, drives the
 * output, mirrors the input, and frees both at exit.
 */
#include "legacy_test.h"
#include "sil.h"
#include "host_sim/gpio.h"

#include "lms_pins26_hack.h"

#define OUT_PIN   HS_GPIO(3, 13)
#define IN_PIN    HS_GPIO(0, 3)
/* SYSCFG0 (AM1808 TRM, SYSCFG chapter): KICK0R/KICK1R unlock, PINMUXn 4 bits a pin */
#define SYSCFG0   0x01C14000U
#define KICK0R    0x38U
#define KICK1R    0x3CU
#define PINMUX(n) (0x120U + 4U * (n))

/* 1 if the SoC drives pin high, 0 if low, -1 if the pin is not an output. */
static int output(unsigned pin)
{
	bool level = false;

	return hs_gpio_soc_output(pin, &level) ? level : -1;
}

static void body(void)
{
	is_int(lms_pins26_load(), 0, "lms_pins26's init claims GP3[13] and GP0[3]");
	is_int(output(OUT_PIN), 1, "gpio_direction_output(OutPin, 1): GP3[13] is an output, high");
	lms_pins26_drive(0);
	is_int(output(OUT_PIN), 0, "gpio_set_value(OutPin, 0): low");
	hs_gpio_set_input(IN_PIN, 1);
	is_int(lms_pins26_mirror(), 1, "PinsMirror ran");
	is_int(output(OUT_PIN), 1, "gpio_get_value(InPin) read GP0[3] high and the output follows");
	hs_gpio_set_input(IN_PIN, 0);
	lms_pins26_mirror();
	is_int(output(OUT_PIN), 0, "and low");
	lms_pins26_unload();
	is_int(output(OUT_PIN), -1, "exit: the output pin is an input again");
	is_int(lms_pins26_load(), 0, "exit freed both pins: a second init claims them again");
	lms_pins26_unload();
}

/* Sets PINMUXn[shift + 3 : shift] to mode, as a 2.6 board file's pin set-up does before the modules load. */
static void board_mux(unsigned n, unsigned shift, unsigned mode)
{
	uint32_t *kick0 = rtos_host_map_io(SYSCFG0 + KICK0R, 4), *kick1 = rtos_host_map_io(SYSCFG0 + KICK1R, 4);
	uint32_t *mux = rtos_host_map_io(SYSCFG0 + PINMUX(n), 4);

	sil_wrw_mem(kick0, 0x83E70B13U);
	sil_wrw_mem(kick1, 0x95A4F1E0U);
	sil_wrw_mem(mux, (sil_rew_mem(mux) & ~(0xFU << shift)) | mode << shift);
	sil_wrw_mem(kick0, 0);
	sil_wrw_mem(kick1, 0);
}

/* The board file's part: GP3[13] and GP0[3] muxed as GPIOs. */
static void power_on(void)
{
	board_mux(7, 8, 8);     /* GP3[13] */
	board_mux(1, 16, 8);    /* GP0[3] */
}

int main(void)
{
	static const struct lt_test test = {
		.name = "lms_pins26", .power_on = power_on, .body = body,
	};

	tap_plan(9);
	lt_run(&test);
	ok(lt_done, "the test body ran to its end");
	return tap_done();
}
