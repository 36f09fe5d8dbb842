/*
 * lms_serial_hack.c — the conformance module lms_serial included verbatim;
 * its interface for the test, in C types only.
 */
#define KBUILD_MODNAME "lms_serial"
#define LX_HACK_DRIVER_INIT lms_serial_driver_init
#define LX_HACK_DRIVER_EXIT lms_serial_driver_exit

#include "drivers/lms_serial.c"

#include <linux_compat/hack.h>
#include <linux/string.h>
#include "lms_serial_hack.h"

int lms_serial_load(void)
{
	return lms_serial_driver_init();
}

void lms_serial_unload(void)
{
	lms_serial_driver_exit();
}

unsigned lms_serial_adc_answer(int frame)
{
	return frame >= 0 && frame < 3 ? AdcAnswer[frame] : 0;
}

int lms_serial_echo(char *buf, int max)
{
	int n = EchoCount < max ? EchoCount : max;

	memcpy(buf, Echo, (size_t)n);
	return n;
}

unsigned long lms_serial_pwm_period(void)
{
	return PwmPeriod;
}

int lms_serial_board(void)
{
	return Hw;
}
