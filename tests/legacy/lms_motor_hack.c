/*
 * lms_motor_hack.c — the conformance module lms_motor included verbatim;
 * its interface for the test, in C types only.
 */
#define KBUILD_MODNAME "lms_motor"
#define LX_HACK_DRIVER_INIT lms_motor_driver_init
#define LX_HACK_DRIVER_EXIT lms_motor_driver_exit

#include "drivers/lms_motor.c"

#include <linux_compat/hack.h>
#include "lms_motor_hack.h"

int lms_motor_load(void)
{
	return lms_motor_driver_init();
}

void lms_motor_unload(void)
{
	lms_motor_driver_exit();
}

void lms_motor_duty(unsigned short duty)
{
	SetDuty(duty);
}

int lms_motor_board(void)
{
	return Hw;
}
