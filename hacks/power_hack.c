/*
 * power_hack.c — d_power on the RTOS (the paper's Fig. 5 pattern): the Linux
 * driver source included byte-for-byte, then the module's Linux side: its init and
 * exit and the device it opens for the service calls
 * (power_module.h).  Only Linux headers: the service calls and the
 * configuration fragment are power_svc.c.
 */
#define KBUILD_MODNAME "d_power"
#include "driver_common.h"

/* Renames: the driver's module_init/exit become plain pointers, called by ours below. */
#pragma push_macro("module_init")
#pragma push_macro("module_exit")
#undef module_init
#undef module_exit
#define module_init(fn) static int (*const power_driver_init)(void) = fn
#define module_exit(fn) static void (*const power_driver_exit)(void) = fn

#include "d_power.c"

#undef module_init
#undef module_exit
#pragma pop_macro("module_init")
#pragma pop_macro("module_exit")

#include "power_module.h"

struct file *power_file;		/* /dev/lms_power */

/* Loads d_power, then opens its device for the service calls. */
static int __init power_hack_init(void)
{
	int ret;

	power_file = NULL;
	ret = power_driver_init();
	if (ret)
		return ret;
	ret = lx_dev_open("/dev/" LMS_POWER_DEVICE_NAME, O_RDWR, &power_file);
	if (ret) {
		pr_err("power_hack: cannot open d_power's device (%d)\n", ret);
		power_file = NULL;
		power_driver_exit();
	}
	return ret;
}
module_init(power_hack_init);

/* Closes the device (the service calls then answer E_OBJ) and unloads d_power. */
static void __exit power_hack_exit(void)
{
	struct file *file = power_file;

	WRITE_ONCE(power_file, NULL);
	lx_dev_close(file);
	power_driver_exit();
}
module_exit(power_hack_exit);
