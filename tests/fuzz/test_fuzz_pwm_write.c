/*
 * test_fuzz_pwm_write.c — fuzz harness: d_pwm's command stream through the
 * extended service call an application uses (pwm_command: one write() of
 * /dev/lms_pwm), and the busy write of /dev/lms_motor.  The input is split
 * into commands at 0xFF-free length bytes: each command is a length byte
 * (0..63) and that many bytes; motors on A and D turn under the commands.
 * Any command is answered with an error code or carried out; the stack
 * reports no bug.
 */
#define _POSIX_C_SOURCE 200809L
#define _FILE_OFFSET_BITS 64	/* readdir of a 64-bit host directory from a 32-bit guest (qemu-arm) */
#include "fuzz_brick.h"
#include "pwm_hack.h"

#define FUZZ_NAME "pwm_write"

static void work(const uint8_t *data, size_t size)
{
	size_t i = 0;

	while (i < size) {
		size_t len = data[i++] & 63U;

		if (len > size - i)
			len = size - i;
		if (len == 1)
			(void)pwm_set_busy(data[i]);
		else
			(void)pwm_command(&data[i], (uint_t)len);
		i += len;
	}
}

static void attach(void)
{
	ev3_attach_motor(0, HS_MOTOR_LARGE, NULL);
	ev3_attach_motor(3, HS_MOTOR_MEDIUM, NULL);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	if (!fz.booted) {
		fz_boot(NULL);
		attach();
	}
	fz_run(work, data, size);
	fz_settle(10, size);
	return 0;
}

#define FUZZ_FINISH fz_shutdown
#include "fuzz_replay.h"
