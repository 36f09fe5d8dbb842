/*
 * test_files.c — d_analog's file operations as a Linux caller sees them
 * (through linux_compat's /dev registry): the text dump honours count and
 * position, llseek and write behave as documented, mmap refuses more than
 * ANALOG's pages; /dev/lms_dcm refuses short reads and writes and bad pin
 * commands without applying any of them, accepts oversized writes as LEGO
 * did, and drives the pins of a connected port only.
 */
#include "analog_test.h"
#include <linux/fcntl.h>
#include <linux_compat/devfs.h>
#include "host_sim/gpio.h"

#define IN1_PIN5	HS_GPIO(0, 2)
#define IN1_PIN6	HS_GPIO(0, 15)
#define IN1_9V		HS_GPIO(8, 10)
#define IN2_PIN5	HS_GPIO(0, 14)

/* true if the SoC drives pin at level. */
static bool drives(unsigned pin, bool level)
{
	bool lvl;

	return hs_gpio_soc_output(pin, &lvl) && lvl == level;
}

static void files_body(void)
{
	struct file *an = NULL, *dcm = NULL;
	char whole[1024], part[1024], buf[64];
	ssize_t n, len = 0;
	void *map;

	ev3_attach_analog(0, EV3_INPUT_EV3_TOUCH, NULL);
	is_int(lx_dev_open("/dev/" LMS_ANALOG_DEVICE_NAME, O_RDWR, &an), 0, "lms_analog opens");
	is_int(lx_dev_open("/dev/" LMS_DCM_DEVICE_NAME, O_RDWR, &dcm), 0, "lms_dcm opens");

	/* the dump: count honoured, continued from the position, then end of file */
	n = lx_dev_read(an, part, 7, NULL);
	is_int(n, 7, "a 7-byte read returns 7 bytes");
	while (n > 0 && len + n < (ssize_t)sizeof(whole)) {
		memcpy(whole + len, part, (size_t)n);
		len += n;
		n = lx_dev_read(an, part, 50, NULL);
	}
	is_int(n, 0, "reads continue from the position up to end of file");
	whole[len] = 0;
	ok(strncmp(whole, "port conn type", 14) == 0 && strstr(whole, "cycles ") != NULL,
	   "the dump has the port table and the counters (%d bytes)", (int)len);
	is_int(lx_dev_llseek(an, 0, SEEK_SET), 0, "llseek to 0");
	is_int(lx_dev_read(an, part, sizeof(part), NULL), len, "a fresh dump of the same length");
	is_int(lx_dev_llseek(an, 0, SEEK_END), -EINVAL, "SEEK_END refused (the dump has no fixed end)");
	is_int(lx_dev_llseek(an, -1, SEEK_SET), -EINVAL, "negative position refused");
	is_int(lx_dev_write(an, "junk", 4, NULL), 0, "write is accepted and ignored (returns 0)");
	is_int(lx_dev_mmap(an, PAGE_ALIGN(sizeof(struct lms_analog)) + 1, &map), -EINVAL,
	       "mmap beyond ANALOG's pages refused");
	is_int(lx_dev_mmap(an, PAGE_ALIGN(sizeof(struct lms_analog)), &map), 0, "mmap of its pages");

	/* lms_dcm */
	is_int(lx_dev_read(dcm, buf, LMS_DCM_READ_SIZE - 1, NULL), -EINVAL, "dcm read of 9 bytes refused");
	is_int(lx_dev_read(dcm, buf, sizeof(buf), NULL), LMS_DCM_READ_SIZE, "dcm read returns 10 bytes");
	is_int(lx_dev_write(dcm, "---", 3, NULL), -EINVAL, "dcm write of 3 bytes refused");
	ok(wait_in_conn(0, LMS_CONN_INPUT_DUMB, 3000) > 0, "EV3 touch detected on port 1");
	is_int(lx_dev_write(dcm, "7-7x", 4, NULL), -EINVAL, "a bad character refuses the whole write");
	ok(!drives(IN1_PIN5, true) && !drives(IN1_PIN6, true), "and nothing was applied");
	is_int(lx_dev_write(dcm, "-\x0e--", 4, NULL), -EOPNOTSUPP, "NXT colour commands: -EOPNOTSUPP");
	is_int(lx_dev_write(dcm, "7-7-extra", 9, NULL), 9, "an oversized write returns its count");
	ok(drives(IN1_PIN5, true) && drives(IN1_PIN6, true) && drives(IN1_9V, true),
	   "'7' on a connected port drives pins 5, 6 and the 9 V supply high");
	ok(!drives(IN2_PIN5, true) && !drives(IN2_PIN5, false), "an empty port's pins stay floating");
	is_int(lx_dev_write(dcm, "1---", 4, NULL), 4, "'1'");
	ok(drives(IN1_PIN5, true) && drives(IN1_PIN6, false) && drives(IN1_9V, false),
	   "drives pin 5 high, pin 6 low, 9 V off");
	is_int(lx_dev_write(dcm, "f---", 4, NULL), 4, "'f'");
	ok(!drives(IN1_PIN5, true) && !drives(IN1_PIN5, false) && !drives(IN1_PIN6, false),
	   "floats the port again");
	is_int(analog_shm()->in_conn[0], LMS_CONN_INPUT_DUMB, "the port stays connected");

	lx_dev_close(dcm);
	lx_dev_close(an);
}

int main(void)
{
	tap_plan(28);
	ok(analog_test_run(files_body, 6, 5000), "the test body ran to its end");
	return tap_done();
}
