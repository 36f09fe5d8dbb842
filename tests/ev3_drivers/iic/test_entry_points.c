/*
 * test_entry_points.c — /dev/lms_iic's file operations called as LEGO user
 * space calls them (through linux_compat's device registry), from a
 * user-domain task: LEGO's ioctls with good and bad ports, lengths and
 * pointers (-EINVAL, -EFAULT, -ENOTTY, nothing changed), READ_TYPE_INFO
 * copying the 44-byte IICSTR it really transfers (not the 60 bytes its
 * number declares), IIC_SETUP on a port not started (FAIL), read() of the
 * port states as LEGO prints them, write() accepted and ignored, mmap.
 */
#include <linux/fcntl.h>
#include <linux_compat/devfs.h>
#include "iic_test.h"

static struct file *f;

static long conn(int8_t c0)
{
	struct lms_iic_devcon dc = { { c0, 0, 0, 0 }, { 0 }, { 0 } };

	return lx_dev_ioctl(f, LMS_IIC_SET_CONN, (unsigned long)&dc);
}

static void bad_arguments(void)
{
	struct lms_iic_str s;
	struct lms_iic_dat d;

	is_int(lx_dev_ioctl(f, LMS_IIC_SET_CONN, 0), -EFAULT, "SET_CONN NULL: -EFAULT");
	is_int(lx_dev_ioctl(f, LMS_IIC_SET_CONN, (unsigned long)&f), -EFAULT,
	       "SET_CONN from memory the task may not touch: -EFAULT");
	is_int(lx_dev_ioctl(f, 0xC0046900U, 0), -ENOTTY, "LEGO's unhandled _IOW('i', 0, int): -ENOTTY");
	memset(&s, 0, sizeof(s));
	s.port = 4;
	is_int(lx_dev_ioctl(f, LMS_IIC_READ_TYPE_INFO, (unsigned long)&s), -EINVAL, "type info of port 5: -EINVAL");
	is_int(lx_dev_ioctl(f, LMS_IIC_READ_TYPE_INFO, (unsigned long)&f), -EFAULT, "type info to foreign memory: -EFAULT");
	s.port = 0;
	s.poll_lng = 5;
	is_int(lx_dev_ioctl(f, LMS_IIC_SET, (unsigned long)&s), -EINVAL, "IIC_SET poll string of 5: -EINVAL");
	s.poll_lng = 2;
	s.read_lng = 0;
	is_int(lx_dev_ioctl(f, LMS_IIC_SET, (unsigned long)&s), -EINVAL, "IIC_SET polling 0 bytes: -EINVAL");
	s.read_lng = -33;
	is_int(lx_dev_ioctl(f, LMS_IIC_SET, (unsigned long)&s), -EINVAL, "IIC_SET read -33: -EINVAL");
	s.read_lng = 2;
	s.time = -1;
	is_int(lx_dev_ioctl(f, LMS_IIC_SET, (unsigned long)&s), -EINVAL, "IIC_SET negative period: -EINVAL");
	memset(&d, 0, sizeof(d));
	d.wr_lng = 33;
	is_int(lx_dev_ioctl(f, LMS_IIC_SETUP, (unsigned long)&d), -EINVAL, "IIC_SETUP 33 bytes: -EINVAL");
	d.wr_lng = 2;
	d.port = -1;
	is_int(lx_dev_ioctl(f, LMS_IIC_SETUP, (unsigned long)&d), -EINVAL, "IIC_SETUP port -1: -EINVAL");
	d.port = 1;
	d.rd_lng = 8;
	is_int(lx_dev_ioctl(f, LMS_IIC_SETUP, (unsigned long)&d), 0, "IIC_SETUP on a port not started");
	is_int(d.result, LMS_IIC_FAIL, "answers FAIL");
	is_int(it_shm->status[1], 0, "and latches nothing");
}

static void type_info_size(void)
{
	uint8_t buf[60];
	struct lms_iic_str *s = (struct lms_iic_str *)buf;
	unsigned i;
	bool untouched = true;

	ev3_attach_nxt_iic(0, NXT_IIC_HT_ACCEL, NULL);
	is_int(conn(LMS_CONN_NXT_IIC), 0, "SET_CONN port 1 NXT I2C");
	ok(it_wait_state(0, LMS_IIC_STATE_SETUP_WAIT, 500), "probed");
	memset(buf, 0x55, sizeof(buf));
	s->port = 0;
	is_int(lx_dev_ioctl(f, LMS_IIC_READ_TYPE_INFO, (unsigned long)buf), 0, "READ_TYPE_INFO");
	ok(!strcmp(s->manufacturer, "HITECHNC") && !strcmp(s->sensor_type, "Accel.  "), "the strings");
	for (i = sizeof(struct lms_iic_str); i < sizeof(buf); i++)
		untouched &= buf[i] == 0x55;
	ok(untouched, "bytes 44..59 untouched: an IICSTR is transferred, as LEGO's user space passes");
}

static void reads_writes_maps(void)
{
	char text[32];
	void *map;
	loff_t pos = 0;
	ssize_t n;
	const uint8_t cmd[3] = { 0, 0x41, 0x00 };

	n = lx_dev_read(f, text, sizeof(text) - 1, &pos);
	text[n > 0 ? n : 0] = 0;
	ok(n == 12 && !strcmp(text, "13  0  0  0\r"), "read: the states as \"%%2u %%2u %%2u %%2u\\r\" (\"%s\")", text);
	is_int(lx_dev_read(f, text, sizeof(text), &pos), 0, "then end of file");
	is_int(lx_dev_read(f, (char *)&f, 4, &(loff_t){ 0 }), -EFAULT, "read into foreign memory: -EFAULT");
	is_int(lx_dev_write(f, (const char *)cmd, sizeof(cmd), NULL), 3, "write: accepted (count)");
	is_int(ev3_nxt_iic_register(0, 0x41), 0, "and ignored (nothing reaches the sensor)");
	is_int(lx_dev_mmap(f, LMS_IIC_MAP_SIZE + 4096, &map), -EINVAL, "mmap too long: -EINVAL");
	ok(lx_dev_mmap(f, LMS_IIC_SIZE, &map) == 0 && map == (void *)it_shm, "LEGO's size maps the IIC area");
	is_int(conn(0), 0, "SET_CONN without NXT I2C stops port 1");
	ok(it_wait_state(0, LMS_IIC_STATE_IDLE, 10), "idle");
	is_int(it_shm->status[0], 0, "status cleared");
}

static void body(void)
{
	if (lx_dev_open("/dev/" LMS_IIC_DEVICE_NAME, O_RDWR, &f)) {
		tap_diag("cannot open /dev/lms_iic");
		return;
	}
	bad_arguments();
	type_info_size();
	reads_writes_maps();
	lx_dev_close(f);
}

int main(void)
{
	it_domain = 1;		/* a user domain: only its stack is its memory */
	tap_plan(30);
	ok(it_run(body, 7), "scenario ran to its end");
	return tap_done();
}
