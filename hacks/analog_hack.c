/*
 * analog_hack.c — d_analog on the RTOS (the paper's Fig. 5 pattern): the Linux
 * driver source included byte-for-byte, then the module's Linux side: its init and
 * exit and the devices it opens and maps for the service calls
 * (analog_module.h).  Only Linux headers: the service calls and the
 * configuration fragment are analog_svc.c.
 */
#define KBUILD_MODNAME "d_analog"
/* The driver's module_init/exit become plain pointers, called by ours below. */
#define LX_HACK_DRIVER_INIT analog_driver_init
#define LX_HACK_DRIVER_EXIT analog_driver_exit

#include "d_analog.c"

#include "driver_common.h"

#include "analog_module.h"

struct file *analog_file;	/* /dev/lms_analog */
struct file *dcm_file;		/* /dev/lms_dcm */
const struct lms_analog *analog_map_addr;

/* Loads d_analog, then opens its devices and maps ANALOG for the service calls. */
static int __init analog_hack_init(void)
{
	void *map;
	int ret;

	analog_file = dcm_file = NULL;		/* nothing left from an earlier boot */
	analog_map_addr = NULL;
	ret = analog_driver_init();
	if (ret)
		goto fail;
	ret = lx_dev_open("/dev/" LMS_ANALOG_DEVICE_NAME, O_RDWR, &analog_file);
	if (!ret)
		ret = lx_dev_open("/dev/" LMS_DCM_DEVICE_NAME, O_RDWR, &dcm_file);
	if (!ret)
		ret = lx_dev_mmap(analog_file, sizeof(struct lms_analog), &map);
	if (ret) {
		/* Unload again: a module whose init fails must leave nothing behind. */
		lx_dev_close(dcm_file);
		lx_dev_close(analog_file);
		analog_file = dcm_file = NULL;
		analog_driver_exit();
		goto fail;
	}
	analog_map_addr = map;
	return 0;

fail:
	pr_err("analog_hack: cannot load d_analog (%d)\n", ret);
	return ret;
}
module_init(analog_hack_init);

/* Closes the devices (the service calls then answer E_OBJ), then unloads d_analog. */
static void __exit analog_hack_exit(void)
{
	struct file *adc = analog_file, *dcm = dcm_file;

	analog_file = dcm_file = NULL;
	analog_map_addr = NULL;
	lx_dev_close(dcm);
	lx_dev_close(adc);
	analog_driver_exit();
}
module_exit(analog_hack_exit);
