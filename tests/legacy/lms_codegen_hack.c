/*
 * lms_codegen_hack.c — the conformance module lms_codegen included verbatim;
 * its interface for the test, in C types only.
 */
#define KBUILD_MODNAME "lms_codegen"
#define LX_HACK_DRIVER_INIT lms_codegen_driver_init
#define LX_HACK_DRIVER_EXIT lms_codegen_driver_exit

#include "drivers/lms_codegen.c"

#include <linux_compat/hack.h>
#include "lms_codegen_hack.h"

int lms_codegen_load(void)
{
	return lms_codegen_driver_init();
}

void lms_codegen_unload(void)
{
	lms_codegen_driver_exit();
}

int lms_codegen_command(const void *cmd, int len)
{
	return Command(cmd, len);
}

unsigned lms_codegen_frequency(void)
{
	return Frequency;
}
