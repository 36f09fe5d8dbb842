/*
 * lms_spi_hack.c — the conformance module lms_spi included verbatim; its
 * interface for the test, in C types only.
 */
#define KBUILD_MODNAME "lms_spi"
#define LX_HACK_DRIVER_INIT lms_spi_driver_init
#define LX_HACK_DRIVER_EXIT lms_spi_driver_exit

#include "drivers/lms_spi.c"

#include <linux_compat/hack.h>
#include "lms_spi_hack.h"

int lms_spi_load(void)
{
	return lms_spi_driver_init();
}

void lms_spi_unload(void)
{
	lms_spi_driver_exit();
}

unsigned lms_spi_adc_answer(int frame)
{
	return frame >= 0 && frame < 3 ? AdcAnswer[frame] : 0;
}

unsigned lms_spi_setup(int reg)
{
	return reg >= 0 && reg < 4 ? SpiSetup[reg] : 0;
}

unsigned long lms_spi_base(void)
{
	return (unsigned long)Spi0;
}
