/*
 * lms_pins26_hack.c — the genuine 2.6-era module lms_pins26 included
 * verbatim; its interface for the test, in C types only.
 */
#define KBUILD_MODNAME "lms_pins26"
#define LX_HACK_DRIVER_INIT lms_pins26_driver_init
#define LX_HACK_DRIVER_EXIT lms_pins26_driver_exit

#include "drivers/lms_pins26.c"

#include <linux_compat/hack.h>
#include "lms_pins26_hack.h"

int lms_pins26_load(void)
{
	return lms_pins26_driver_init();
}

void lms_pins26_unload(void)
{
	lms_pins26_driver_exit();
}

void lms_pins26_drive(int level)
{
	PinsDrive(level);
}

int lms_pins26_mirror(void)
{
	PinsMirror();
	return Mirrored;
}
