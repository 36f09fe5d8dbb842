/*
 * iic_hack.c — d_iic on the RTOS (the paper's Fig. 5 pattern): the Linux
 * driver source included byte-for-byte, then the module's Linux side: its exit, the
 * device the service calls open and map on first use, and the ports' state
 * from the driver's own table
 * (iic_module.h).  Only Linux headers: the service calls and the
 * configuration fragment are iic_svc.c.
 */
#define KBUILD_MODNAME "d_iic"
/* The driver's module_exit becomes a plain pointer, called by ours below. */
#define LX_HACK_DRIVER_EXIT iic_driver_exit

#include "d_iic.c"

#include "driver_common.h"

#include "iic_module.h"

struct file *iic_file;		/* /dev/lms_iic, opened at the first call */
const struct lms_iic *iic_hack_map;
static DEFINE_MUTEX(iic_hack_mutex);

/* The open device, opening it (and mapping its memory) on first use; NULL if d_iic is not up. */
struct file *iic_hack_file(void)
{
	struct file *file;
	void *map;

	if (likely(iic_file))
		return iic_file;
	mutex_lock(&iic_hack_mutex);
	if (!iic_file && !lx_dev_open("/dev/" LMS_IIC_DEVICE_NAME, O_RDWR, &file)) {
		if (!lx_dev_mmap(file, LMS_IIC_MAP_SIZE, &map)) {
			iic_hack_map = map;
			iic_file = file;
		} else {
			lx_dev_close(file);
		}
	}
	mutex_unlock(&iic_hack_mutex);
	return iic_file;
}

/* Closes the device the service calls opened, then unloads d_iic. */
static void __exit iic_hack_exit(void)
{
	struct file *file;

	mutex_lock(&iic_hack_mutex);
	file = iic_file;
	iic_file = NULL;
	iic_hack_map = NULL;
	mutex_unlock(&iic_hack_mutex);
	lx_dev_close(file);
	iic_driver_exit();
}
module_exit(iic_hack_exit);

/* Port @port's state in d_iic's table. */
u8 iic_module_port_state(unsigned int port)
{
	return READ_ONCE(iic.port[port].state);
}

/* Port @port's mode in d_iic's table. */
s8 iic_module_port_mode(unsigned int port)
{
	return (s8)READ_ONCE(iic.port[port].mode);
}
