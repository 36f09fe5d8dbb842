/*
 * uart_hack.c — d_uart on the RTOS (the paper's Fig. 5 pattern): the Linux
 * driver source included byte-for-byte, then the module's Linux side: its exit,
 * and the device the service calls open and map on first use
 * (uart_module.h).  Only Linux headers: the service calls and the
 * configuration fragment are uart_svc.c.
 */
#define KBUILD_MODNAME "d_uart"
/* The driver's module_exit becomes a plain pointer, called by ours below. */
#define LX_HACK_DRIVER_EXIT uart_driver_exit

#include "d_uart.c"

#include "driver_common.h"

#include "uart_module.h"

struct file *uart_file;		/* /dev/lms_uart, opened at the first call */
const struct lms_uart_shm *uart_map;
static DEFINE_MUTEX(uart_hack_mutex);

/* The open device, opening it (and mapping its memory) on first use; NULL if d_uart is not up. */
struct file *uart_hack_file(void)
{
	struct file *file;
	void *map;

	if (likely(uart_file))
		return uart_file;
	mutex_lock(&uart_hack_mutex);
	if (!uart_file && !lx_dev_open("/dev/" LMS_UART_DEVICE_NAME, O_RDWR, &file)) {
		if (!lx_dev_mmap(file, LMS_UART_MAP_SIZE, &map)) {
			uart_map = map;
			uart_file = file;
		} else {
			lx_dev_close(file);
		}
	}
	mutex_unlock(&uart_hack_mutex);
	return uart_file;
}

/* Closes the device the service calls opened, then unloads d_uart. */
static void __exit uart_hack_exit(void)
{
	struct file *file;

	mutex_lock(&uart_hack_mutex);
	file = uart_file;
	uart_file = NULL;
	uart_map = NULL;
	mutex_unlock(&uart_hack_mutex);
	lx_dev_close(file);
	uart_driver_exit();
}
module_exit(uart_hack_exit);
