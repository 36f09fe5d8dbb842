/*
 * test_tty.c — the tty layer (linux/tty.h) over a test driver whose lines
 * loop written bytes back through the flip buffer: /dev nodes per line,
 * N_TTY's read and write, TIOCSETD / TIOCGETD and the discipline's open,
 * close and receive_buf (with the bytes' flags, in process context),
 * write_wakeup on request, a failing open keeping the old discipline,
 * termios and baud-rate encoding, tty_set_termios reaching the driver,
 * and the last close closing the discipline.
 */
#define KBUILD_MODNAME "ttytest"
#include "lx_log_test.h"
#include <linux/tty.h>
#include <linux/tty_flip.h>
#include <linux/delay.h>
#include <linux/err.h>
#include <linux/preempt.h>
#include <linux/hardirq.h>
#include <linux_compat/devfs.h>
#include "host_sim/board.h"

/* ---- a loopback driver ---- */

static struct tty_port ports[2];
static struct tty_driver *driver;
static int opens, closes, set_termios_calls;
static speed_t old_baud_seen, new_baud_seen;
static unsigned int room = 100;

static int loop_open(struct tty_struct *tty, struct file *filp)
{
	opens++;
	return 0;
}

static void loop_close(struct tty_struct *tty, struct file *filp)
{
	closes++;
}

/* Takes up to room bytes and sends them straight back, the last one flagged as a framing error. */
static int loop_write(struct tty_struct *tty, const unsigned char *buf, int count)
{
	int n = min_t(int, count, (int)room), i;

	for (i = 0; i < n; i++)
		tty_insert_flip_char(tty->port, buf[i], buf[i] == '!' ? TTY_FRAME : TTY_NORMAL);
	tty_flip_buffer_push(tty->port);
	return n;
}

static unsigned int loop_write_room(struct tty_struct *tty)
{
	return room;
}

static void loop_set_termios(struct tty_struct *tty, const struct ktermios *old)
{
	set_termios_calls++;
	old_baud_seen = tty_termios_baud_rate(old);
	new_baud_seen = tty_get_baud_rate(tty);
}

static const struct tty_operations loop_ops = {
	.open = loop_open,
	.close = loop_close,
	.write = loop_write,
	.write_room = loop_write_room,
	.set_termios = loop_set_termios,
};

/* ---- a test discipline ---- */

static int ld_opens, ld_closes, ld_wakeups, ld_open_result;
static unsigned char ld_got[64];
static char ld_flags[64];
static int ld_count;
static bool ld_in_task;

static int ld_open(struct tty_struct *tty)
{
	ld_opens++;
	if (!ld_open_result)
		tty->disc_data = &ld_count;
	return ld_open_result;
}

static void ld_close(struct tty_struct *tty)
{
	ld_closes++;
}

static void ld_receive_buf(struct tty_struct *tty, const unsigned char *cp, const char *fp, int count)
{
	int i;

	ld_in_task = !in_interrupt() && tty->disc_data == &ld_count;
	for (i = 0; i < count && ld_count < (int)sizeof(ld_got); i++) {
		ld_got[ld_count] = cp[i];
		ld_flags[ld_count++] = fp ? fp[i] : TTY_NORMAL;
	}
}

static void ld_write_wakeup(struct tty_struct *tty)
{
	ld_wakeups++;
	clear_bit(TTY_DO_WRITE_WAKEUP, &tty->flags);
}

static struct tty_ldisc_ops test_ldisc = {
	.num = N_DEVELOPMENT,
	.name = "test",
	.open = ld_open,
	.close = ld_close,
	.receive_buf = ld_receive_buf,
	.write_wakeup = ld_write_wakeup,
};

static void test_baud(void)
{
	struct ktermios t = tty_std_termios;

	tty_termios_encode_baud_rate(&t, 2400, 2400);
	ok((t.c_cflag & CBAUD) == B2400 && tty_termios_baud_rate(&t) == 2400, "2400: B2400");
	tty_termios_encode_baud_rate(&t, 57600, 57600);
	ok((t.c_cflag & CBAUD) == B57600 && tty_termios_baud_rate(&t) == 57600, "57600: B57600");
	tty_termios_encode_baud_rate(&t, 12345, 12345);
	ok((t.c_cflag & CBAUD) == BOTHER && tty_termios_baud_rate(&t) == 12345, "12345: BOTHER, c_ospeed");
	tty_termios_encode_baud_rate(&t, 9600, 115200);
	ok(tty_termios_baud_rate(&t) == 115200 && tty_termios_input_baud_rate(&t) == 9600,
	   "split rates: input in CIBAUD");
	ok((tty_std_termios.c_cflag & CSIZE) == CS8 && tty_termios_baud_rate(&tty_std_termios) == 38400,
	   "tty_std_termios: 38400 8N1 as Linux's");
}

static void body(void)
{
	struct file *f = NULL, *f2 = NULL;
	struct tty_struct *tty;
	struct ktermios termios;
	char buf[32];
	int disc = -1;

	test_baud();
	is_int(tty_register_ldisc(&(struct tty_ldisc_ops){ .num = NR_LDISCS }), -EINVAL,
	       "tty_register_ldisc beyond NR_LDISCS: -EINVAL");
	is_int(tty_register_ldisc(&test_ldisc), 0, "tty_register_ldisc(N_DEVELOPMENT)");

	driver = tty_alloc_driver(2, 0);
	ok(!IS_ERR(driver), "tty_alloc_driver(2)");
	is_int((int)PTR_ERR(tty_alloc_driver(LX_TTY_MAX_LINES + 1, 0)), -EINVAL, "too many lines: -EINVAL");
	driver->name = "ttyT";
	driver->major = 240;
	tty_set_operations(driver, &loop_ops);
	tty_port_init(&ports[0]);
	tty_port_init(&ports[1]);
	tty_port_link_device(&ports[0], driver, 0);
	tty_port_link_device(&ports[1], driver, 1);
	is_int(tty_register_driver(driver), 0, "tty_register_driver");
	ok(lx_dev_exists("ttyT0") && lx_dev_exists("ttyT1"), "/dev/ttyT0 and /dev/ttyT1");

	is_int(lx_dev_open("/dev/ttyT0", O_RDWR, &f), 0, "open /dev/ttyT0");
	if (!f)
		return;
	tty = f->private_data;
	ok(opens == 1 && tty && !strcmp(tty_name(tty), "ttyT0") && tty->index == 0, "the driver's open, tty ttyT0");
	is_int((int)lx_dev_write(f, (const char __user *)"hello", 5, NULL), 5, "write through N_TTY");
	memset(buf, 0, sizeof(buf));
	is_int((int)lx_dev_read(f, (char __user *)buf, sizeof(buf), NULL), 5, "read what came back");
	ok(!strcmp(buf, "hello"), "  the same bytes (%s)", buf);
	is_int(lx_dev_open("/dev/ttyT0", O_RDWR | O_NONBLOCK, &f2), 0, "a second open shares the tty");
	ok(f2 && f2->private_data == tty, "  the same tty_struct");
	is_int((int)lx_dev_read(f2, (char __user *)buf, sizeof(buf), NULL), -EAGAIN, "nothing to read: -EAGAIN");

	is_int((int)lx_dev_ioctl_kernel(f, TIOCGETD, &disc), 0, "TIOCGETD");
	is_int(disc, N_TTY, "  N_TTY");
	disc = 28;
	is_int((int)lx_dev_ioctl_kernel(f, TIOCSETD, &disc), -EINVAL, "TIOCSETD of an unregistered discipline: -EINVAL");
	disc = N_DEVELOPMENT;
	ld_open_result = -EIO;
	is_int((int)lx_dev_ioctl_kernel(f, TIOCSETD, &disc), -EIO, "a discipline whose open fails: its error");
	(void)lx_dev_ioctl_kernel(f, TIOCGETD, &disc);
	is_int(disc, N_TTY, "  and N_TTY is back");
	ld_open_result = 0;
	disc = N_DEVELOPMENT;
	is_int((int)lx_dev_ioctl_kernel(f, TIOCSETD, &disc), 0, "TIOCSETD N_DEVELOPMENT");
	ok(ld_opens == 2 && tty->disc_data == &ld_count, "the discipline's open ran");

	loop_write(tty, (const unsigned char *)"ab!", 3);
	msleep(1);
	ok(ld_count == 3 && !memcmp(ld_got, "ab!", 3), "receive_buf got the bytes (%d)", ld_count);
	ok(ld_flags[0] == TTY_NORMAL && ld_flags[2] == TTY_FRAME, "with their flags");
	ok(ld_in_task, "in process context (the flip buffer's work)");

	set_bit(TTY_DO_WRITE_WAKEUP, &tty->flags);
	tty_wakeup(tty);
	tty_wakeup(tty);
	is_int(ld_wakeups, 1, "write_wakeup once, while asked for");
	room = 7;
	is_int((int)tty_write_room(tty), 7, "tty_write_room: the driver's");

	termios = tty->termios;
	tty_encode_baud_rate(tty, 2400, 2400);
	ok(tty_get_baud_rate(tty) == 2400, "tty_encode_baud_rate sets the tty's termios");
	tty->termios = termios;
	tty_termios_encode_baud_rate(&termios, 57600, 57600);
	is_int(tty_set_termios(tty, &termios), 0, "tty_set_termios");
	ok(set_termios_calls == 1 && old_baud_seen == 38400 && new_baud_seen == 57600,
	   "the driver's set_termios sees old and new (%u -> %u)", old_baud_seen, new_baud_seen);

	lx_dev_close(f2);
	ok(closes == 1 && ld_closes == 0, "closing one file: the driver's close, the discipline stays");
	lx_dev_close(f);
	ok(closes == 2 && ld_closes == 1, "the last close closes the discipline");
	is_int(lx_dev_open("/dev/ttyT0", O_RDWR, &f), 0, "opened again");
	(void)lx_dev_ioctl_kernel(f, TIOCGETD, &disc);
	is_int(disc, N_TTY, "  a fresh tty: N_TTY");
	lx_dev_close(f);

	tty_unregister_ldisc(&test_ldisc);
	disc = N_DEVELOPMENT;
	is_int(lx_dev_open("/dev/ttyT1", O_RDWR, &f), 0, "open /dev/ttyT1");
	is_int((int)lx_dev_ioctl_kernel(f, TIOCSETD, &disc), -EINVAL, "an unregistered discipline cannot be set");
	lx_dev_close(f);
	tty_unregister_driver(driver);
	ok(!lx_dev_exists("ttyT0"), "tty_unregister_driver removes the nodes");
	tty_driver_kref_put(driver);
	tty_port_destroy(&ports[0]);
	tty_port_destroy(&ports[1]);
}

int main(void)
{
	tap_plan(43);
	is_int(hs_board_init(NULL), E_OK, "host_sim board");
	ok(lx_test_run(body), "test task ran to completion");
	hs_board_shutdown();
	return tap_done();
}
