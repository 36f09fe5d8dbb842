/*
 * test_fuzz_dev_ops.c — fuzz harness: the write(), read() and ioctl() paths
 * of every device the EV3 drivers register (/dev/lms_analog, lms_dcm,
 * lms_ui, lms_uart, lms_pwm, lms_motor, lms_iic), opened non-blocking (a read that
 * waits for an event is no hang) and called as a process would, with
 * whatever bytes, lengths and ioctl numbers.  The input is a sequence of
 * operations: a selector byte (device = low 3 bits modulo 7, operation =
 * bits 3-4: write, read, ioctl), for an ioctl a 32-bit command (little
 * endian), then a length byte and that many bytes of data (the ioctl's
 * argument buffer, zero-padded to the largest size an ioctl number can
 * encode).  Each call returns a count or an errno; the stack reports no bug.
 */
#define _POSIX_C_SOURCE 200809L
#define _FILE_OFFSET_BITS 64	/* readdir of a 64-bit host directory from a 32-bit guest (qemu-arm) */
#include "fuzz_brick.h"
#include <linux/fs.h>
#include <linux_compat/devfs.h>
#include "lms_analog.h"
#include "lms_pwm.h"
#include "lms_uart.h"
#include "lms_ui.h"
#include "lms_iic.h"

#define FUZZ_NAME "dev_ops"
#define NDEV 7
#define ARG_SIZE 16384		/* _IOC_SIZE's largest value is 16383 */

static const char *const dev_names[NDEV] = {
	LMS_ANALOG_DEVICE_NAME, LMS_DCM_DEVICE_NAME, LMS_UI_DEVICE_NAME,
	LMS_UART_DEVICE_NAME, LMS_PWM_DEVICE_NAME, LMS_MOTOR_DEVICE_NAME, LMS_IIC_DEVICE_NAME,
};
static struct file *files[NDEV];
static uint8_t arg[ARG_SIZE];

static void open_all(void)
{
	for (unsigned i = 0; i < NDEV; i++)
		if (lx_dev_open(dev_names[i], O_RDWR | O_NONBLOCK, &files[i]) != 0)
			files[i] = NULL;
}

static void work(const uint8_t *data, size_t size)
{
	size_t i = 0;

	while (i < size) {
		uint8_t sel = data[i++];
		struct file *f = files[(sel & 7U) % NDEV];
		unsigned op = (sel >> 3) & 3U;
		uint32_t cmd = 0;
		size_t len;
		loff_t pos = 0;

		if (op == 2) {
			for (unsigned b = 0; b < 4 && i < size; b++)
				cmd |= (uint32_t)data[i++] << (8 * b);
		}
		len = i < size ? data[i++] : 0;
		if (len > size - i)
			len = size - i;
		memset(arg, 0, sizeof(arg));
		memcpy(arg, &data[i], len);
		i += len;
		if (f == NULL)
			continue;
		switch (op) {
		case 0:
			(void)kernel_write(f, arg, len, &pos);
			break;
		case 1:
			(void)kernel_read(f, arg, len, &pos);
			break;
		default:
			(void)lx_dev_ioctl_kernel(f, cmd, arg);
			break;
		}
	}
}

static void close_all(const uint8_t *data, size_t size)
{
	(void)data;
	(void)size;
	for (unsigned i = 0; i < NDEV; i++)
		if (files[i])
			lx_dev_close(files[i]);
}

/* After the corpus: the files are closed, so that nothing is left at the modules' exit. */
static inline void finish(void)
{
	fz_run(close_all, NULL, 0);
	fz_shutdown();
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	fz_boot(open_all);
	fz_run(work, data, size);
	fz_settle(5, size);
	return 0;
}

#define FUZZ_FINISH finish
#include "fuzz_replay.h"
