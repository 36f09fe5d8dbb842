/*
 * lms_gpio_hack.c — the conformance module lms_gpio included verbatim; its
 * interface for the test, in C types only (the driver defines SIZE, ID, ER,
 * TRUE, ... itself, so no RTOS header may follow it in this file).
 */
#define KBUILD_MODNAME "lms_gpio"
#define LX_HACK_DRIVER_INIT lms_gpio_driver_init
#define LX_HACK_DRIVER_EXIT lms_gpio_driver_exit

#include "drivers/lms_gpio.c"

#include <linux_compat/hack.h>
#include "lms_gpio_hack.h"

/* The driver's own `#define pr_fmt` came first and is the one in effect. */
_Static_assert(sizeof(pr_fmt("x")) == sizeof("lms_gpio: x"), "the driver's pr_fmt is in effect");

int lms_gpio_load(void)
{
	return lms_gpio_driver_init();
}

void lms_gpio_unload(void)
{
	lms_gpio_driver_exit();
}

unsigned long lms_gpio_edges(void)
{
	return EdgeCount;
}

int lms_gpio_board(void)
{
	return Hw;
}
