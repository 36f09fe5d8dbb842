/*
 * test_entry_points.c — /dev/lms_uart's file operations with good and bad
 * input, called as LEGO user space would (through linux_compat's device
 * registry): LEGO's ioctl semantics (READ_MODE_INFO once per change,
 * NACK_MODE_INFO, CLEAR_CHANGED), write() of WRITE commands reaching the
 * sensor, read() of the states, mmap; and bad ports, modes, lengths,
 * pointers (from a user-domain task) and commands answered with -EINVAL/-EFAULT/-ENXIO/-EBUSY/-ENOTTY
 * without side effects (sanitizers watch for memory damage); a port started again stores its
 * samples from slot 0, as LEGO's driver does.
 */
#include <linux/fcntl.h>
#include <linux_compat/devfs.h>
#include "uart_test.h"

static struct file *f;

static long conn(int8_t c0, int8_t m0, int8_t c1, int8_t m1)
{
	struct lms_uart_devcon dc = { { c0, c1, 0, 0 }, { 0 }, { m0, m1, 0, 0 } };

	return lx_dev_ioctl(f, LMS_UART_SET_CONN, (unsigned long)&dc);
}

static long ctl(unsigned int cmd, int8_t port, int8_t mode, struct lms_uart_ctl *c)
{
	memset(c, 0x55, sizeof(*c));
	c->port = port;
	c->mode = mode;
	return lx_dev_ioctl(f, cmd, (unsigned long)c);
}

static void ioctls(void)
{
	struct lms_uart_ctl c;
	const int8_t U = LMS_CONN_INPUT_UART;

	is_int(lx_dev_ioctl(f, LMS_UART_SET_CONN, 0), -EFAULT, "SET_CONN NULL: -EFAULT");
	is_int(conn(U, 8, 0, 0), -EINVAL, "SET_CONN mode 8: -EINVAL");
	is_int(conn(U, -1, 0, 0), -EINVAL, "SET_CONN mode -1: -EINVAL");
	is_int(conn(U, 0, U, 9), -EINVAL, "one bad port refuses the whole DEVCON");
	is_int(ut_ext(0)->state, LMS_UART_STATE_IDLE, "and changes nothing");
	is_int(lx_dev_ioctl(f, 0xC00C7599U, 0), -ENOTTY, "unknown ioctl: -ENOTTY");
	is_int(lx_dev_ioctl(f, LMS_UART_READ_MODE_INFO, 0), -EFAULT, "READ_MODE_INFO NULL: -EFAULT");
	is_int(lx_dev_ioctl(f, LMS_UART_READ_MODE_INFO, (unsigned long)&f), -EFAULT,
	       "READ_MODE_INFO on memory the task may not touch: -EFAULT");
	is_int(lx_dev_ioctl(f, LMS_UART_SET_CONN, (unsigned long)&f), -EFAULT,
	       "SET_CONN from memory the task may not touch: -EFAULT");
	is_int(ctl(LMS_UART_READ_MODE_INFO, 4, 0, &c), -EINVAL, "port 4: -EINVAL");
	is_int(ctl(LMS_UART_NACK_MODE_INFO, -1, 0, &c), -EINVAL, "port -1: -EINVAL");
	is_int(ctl(LMS_UART_CLEAR_CHANGED, 0, 8, &c), -EINVAL, "mode 8: -EINVAL");

	ev3_attach_uart_sensor(0, UART_SENSOR_TYPE_COLOR, NULL);
	is_int(conn(U, 0, 0, 0), 0, "SET_CONN port 1");
	ok(ut_wait_state(0, LMS_UART_STATE_DATA, 3000), "DATA");
	is_int(ctl(LMS_UART_READ_MODE_INFO, 0, 2, &c), 0, "READ_MODE_INFO mode 2");
	ok(!strcmp(c.type_data.name, "COL-COLOR") && c.type_data.mode == 2, "gives COL-COLOR");
	ctl(LMS_UART_READ_MODE_INFO, 0, 2, &c);
	ok(c.type_data.name[0] == 0 && c.type_data.type == 29, "a second read: name[0] = 0 (unchanged)");
	is_int(ctl(LMS_UART_NACK_MODE_INFO, 0, 2, &c), 0, "NACK_MODE_INFO");
	ctl(LMS_UART_READ_MODE_INFO, 0, 2, &c);
	ok(!strcmp(c.type_data.name, "COL-COLOR"), "flags it changed again");
	ok(ut_status(0) & LMS_UART_PORT_CHANGED, "CHANGED still set");
	is_int(ctl(LMS_UART_CLEAR_CHANGED, 0, 0, &c), 0, "CLEAR_CHANGED");
	ok(!(ut_status(0) & LMS_UART_PORT_CHANGED) && ut_wait_sample(0, 0, 300), "data flows");
	is_int(conn(U, 6, 0, 0), -EINVAL, "mode 6 of a 6-mode sensor: -EINVAL");
	ok(lms_uart_sample(ut_shm, 0, 0) != NULL, "data kept");
}

static void writes(void)
{
	uint8_t cmd[40] = { 0, 0x11, 0x22, 0x33 };
	const struct uart_sensor_stats *st = uart_sensor_get_stats(ev3_input_uart_sensor(0));
	uint32_t before = st->writes;

	is_int(lx_dev_write(f, (const char *)cmd, 0, NULL), -EINVAL, "write of 0 bytes: -EINVAL");
	is_int(lx_dev_write(f, (const char *)cmd, 1, NULL), -EINVAL, "port without data: -EINVAL");
	is_int(lx_dev_write(f, (const char *)cmd, 34, NULL), -EINVAL, "33 data bytes: -EINVAL");
	is_int(lx_dev_write(f, NULL, 4, NULL), -EFAULT, "NULL buffer: -EFAULT");
	is_int(lx_dev_write(f, (const char *)&f, 4, NULL), -EFAULT, "foreign buffer: -EFAULT");
	cmd[0] = 4;
	is_int(lx_dev_write(f, (const char *)cmd, 4, NULL), -EINVAL, "port 4: -EINVAL");
	cmd[0] = 1;
	is_int(lx_dev_write(f, (const char *)cmd, 4, NULL), -ENXIO, "port 2 not started: -ENXIO");
	cmd[0] = 0;
	is_int(lx_dev_write(f, (const char *)cmd, 4, NULL), 4, "3 bytes to port 1: count returned");
	is_int(lx_dev_write(f, (const char *)cmd, 4, NULL), -EBUSY, "again before it left: -EBUSY");
	dly_tsk(20);
	is_int(st->writes - before, 1, "the sensor got one WRITE");
	ok(st->last_write_len == 4 && st->last_write[0] == 0x11 && st->last_write[2] == 0x33 &&
	   st->last_write[3] == 0, "3 bytes padded to 4: %u bytes", st->last_write_len);
	is_int(lx_dev_write(f, (const char *)cmd, 33, NULL), 33, "32 bytes accepted");
	dly_tsk(20);
	is_int(st->writes - before, 2, "and sent");
	ok(ut_ext(0)->state == LMS_UART_STATE_DATA, "sensor still in DATA");
}

static void reads_and_maps(void)
{
	char text[32];
	void *map;
	ssize_t n;
	loff_t pos = 0;

	is_int(lx_dev_read(f, NULL, 10, &pos), -EFAULT, "read into NULL: -EFAULT");
	is_int(lx_dev_read(f, (char *)&f, 10, &pos), -EFAULT, "read into foreign memory: -EFAULT");
	n = lx_dev_read(f, text, 3, &pos);
	ok(n == 3 && !memcmp(text, "5 0", 3), "read in pieces: \"%.3s\"", text);
	n = lx_dev_read(f, text + 3, sizeof(text) - 4, &pos);
	text[3 + (n > 0 ? n : 0)] = 0;
	ok(n == 5 && !strcmp(text, "5 0 0 0\n"), "the four states: \"%.7s\\n\"", text);
	is_int(lx_dev_read(f, text, sizeof(text), &pos), 0, "then end of file");
	is_int(lx_dev_mmap(f, LMS_UART_MAP_SIZE + 4096, &map), -EINVAL, "mmap too long: -EINVAL");
	ok(lx_dev_mmap(f, LMS_UART_SIZE, &map) == 0 && map == (void *)ut_shm, "LEGO's size maps");
	is_int(ut_shm->ext.magic, LMS_UART_EXT_MAGIC, "extension magic");
	is_int(ut_shm->ext.size, sizeof(struct lms_uart_ext), "extension size");
	is_int(conn(0, 0, 0, 0), 0, "SET_CONN with no UART stops port 1");
	ok(ut_ext(0)->state == LMS_UART_STATE_IDLE && !lms_uart_sample(ut_shm, 0, 0),
	   "idle, data withdrawn");
}

/* Waits until the port has stored n more samples (ext seq), at most ms; true if it did. */
static bool more_samples(unsigned port, uint32_t n, unsigned ms)
{
	uint32_t seq = ut_ext(port)->seq;

	while (ut_ext(port)->seq - seq < n) {
		if (!ms--)
			return false;
		dly_tsk(1);
	}
	return true;
}

/*
 * Actual over a restart: a port started again by SET_CONN stores its samples from slot 0
 * (Actual and LogIn 0 at once, the first sample in slot 0), as LEGO's driver does at
 * SET_CONN and at every restart.
 */
static void restarts(void)
{
	struct lms_uart_ctl c;
	const int8_t U = LMS_CONN_INPUT_UART;
	const int8_t *s;

	is_int(conn(U, 0, 0, 0), 0, "SET_CONN port 1 again");
	ok(ut_wait_state(0, LMS_UART_STATE_DATA, 3000) && ctl(LMS_UART_CLEAR_CHANGED, 0, 0, &c) == 0 &&
	   more_samples(0, 3, 500) && ut_shm->lms.actual[0] >= 2,
	   "streaming: newest sample in slot %u", ut_shm->lms.actual[0]);
	is_int(conn(0, 0, 0, 0), 0, "stopped");
	is_int(conn(U, 0, 0, 0), 0, "and started again");
	ok(ut_shm->lms.actual[0] == 0 && ut_shm->lms.log_in[0] == 0,
	   "Actual %u, LogIn %u at once (LEGO's 0, 0)", ut_shm->lms.actual[0], ut_shm->lms.log_in[0]);
	ok(ut_wait_state(0, LMS_UART_STATE_DATA, 3000) && ut_shm->lms.actual[0] == 0 &&
	   !lms_uart_sample(ut_shm, 0, 0), "Actual 0 at the new handshake, no sample served");
	ctl(LMS_UART_CLEAR_CHANGED, 0, 0, &c);
	s = ut_wait_sample(0, 0, 300);
	ok(s && ut_shm->lms.actual[0] == 0 && ut_shm->lms.log_in[0] == 1,
	   "the first sample in slot %u, LogIn %u", ut_shm->lms.actual[0], ut_shm->lms.log_in[0]);
	ok(more_samples(0, 1, 300) && ut_shm->lms.actual[0] == 1, "the next in slot %u",
	   ut_shm->lms.actual[0]);
	is_int(conn(0, 0, 0, 0), 0, "stopped");
}

static void body(void)
{
	if (lx_dev_open("/dev/" LMS_UART_DEVICE_NAME, O_RDWR, &f)) {
		tap_diag("cannot open /dev/lms_uart");
		return;
	}
	ioctls();
	writes();
	reads_and_maps();
	restarts();
	lx_dev_close(f);
}

int main(void)
{
	ut_domain = 1;		/* a user domain: only its stack is its memory */
	tap_plan(59);
	ok(ut_run(body, 7, NULL), "scenario ran to its end");
	return tap_done();
}
