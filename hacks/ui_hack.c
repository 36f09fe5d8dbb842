/*
 * ui_hack.c — d_ui on the RTOS (the paper's Fig. 5 pattern): the Linux
 * driver source included byte-for-byte, then the module's Linux side: its init and
 * exit and the device it opens and maps for the service calls
 * (ui_module.h).  Only Linux headers: the service calls and the
 * configuration fragment are ui_svc.c.
 */
#define KBUILD_MODNAME "d_ui"
/* The driver's module_init/exit become plain pointers, called by ours below. */
#define LX_HACK_DRIVER_INIT ui_driver_init
#define LX_HACK_DRIVER_EXIT ui_driver_exit

#include "d_ui.c"

#include "driver_common.h"

#include "ui_module.h"

struct file *ui_file;		/* /dev/lms_ui, non-blocking */
const struct lms_ui *ui_map;

/* Loads d_ui, then opens its device and maps the shared page for the service calls. */
static int __init ui_hack_init(void)
{
	void *map;
	int ret;

	ret = ui_driver_init();
	if (ret)
		return ret;
	ret = lx_dev_open("/dev/" LMS_UI_DEVICE_NAME, O_RDWR | O_NONBLOCK, &ui_file);
	if (!ret)
		ret = lx_dev_mmap(ui_file, LMS_UI_MAP_SIZE, &map);
	if (ret) {
		pr_err("ui_hack: cannot open d_ui's device (%d)\n", ret);
		lx_dev_close(ui_file);
		ui_file = NULL;
		ui_driver_exit();
		return ret;
	}
	ui_map = map;
	return 0;
}
module_init(ui_hack_init);

/*
 * Withdraws the device (the service calls then answer E_OBJ), wakes the
 * tasks waiting for a click so that they see it gone, then closes the file
 * and unloads d_ui.  (In Linux an open file would keep the module loaded.)
 */
static void __exit ui_hack_exit(void)
{
	struct file *file = ui_file;

	WRITE_ONCE(ui_file, NULL);
	ui_map = NULL;
	wake_up_all(&ui.readers);
	lx_dev_close(file);
	ui_driver_exit();
}
module_exit(ui_hack_exit);
