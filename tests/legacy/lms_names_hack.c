/*
 * lms_names_hack.c — the conformance module lms_names included verbatim: its
 * enumerators and types are TOPPERS's names (TRUE, ID, ER, SIZE, ...), so only
 * Linux names may stand before it and no RTOS header after it; its interface
 * for the test is in C types, reaching the driver through its device file.
 */
#define KBUILD_MODNAME "lms_names"
#define LX_HACK_DRIVER_INIT lms_names_driver_init
#define LX_HACK_DRIVER_EXIT lms_names_driver_exit

#include "drivers/lms_names.c"

#include <linux_compat/hack.h>
#include <linux_compat/devfs.h>
#include "lms_names_hack.h"

int lms_names_load(void)
{
	return lms_names_driver_init();
}

void lms_names_unload(void)
{
	lms_names_driver_exit();
}

int lms_names_command(unsigned char mode, unsigned char reply[3])
{
	struct file *file;
	loff_t pos = 0;
	ssize_t got;
	int ret;

	ret = lx_dev_open("/dev/" NAMES_DEVICE_NAME, O_RDWR, &file);
	if (ret)
		return ret;
	got = lx_dev_write(file, (const char __user *)&mode, 1, &pos);
	if (got == 1)
		got = lx_dev_read(file, (char __user *)reply, 3, &pos);
	lx_dev_close(file);
	if (got < 0)
		return (int)got;
	return got == 3 ? 0 : -EIO;
}
