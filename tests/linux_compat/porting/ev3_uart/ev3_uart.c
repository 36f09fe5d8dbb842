// SPDX-License-Identifier: GPL-2.0
/*
 * ev3_uart.c - a tty line discipline for LEGO EV3 UART sensors, written as
 * upstream wants one today: attached to a serial port with TIOCSETD, it
 * listens at 2400 baud for the sensor's introduction (TYPE, MODES, SPEED,
 * then NAME and FORMAT per mode, ended by ACK), answers ACK, moves the
 * port to the sensor's speed, keeps the sensor alive with a NACK every
 * 100 ms and decodes its data frames; a misc device per port gives the
 * readings and selects modes.
 *
 * The protocol (LEGO's EV3 firmware, lms2012 d_uart_mod.c; ev3dev's
 * legoev3_uart.c): a message starts with a header byte, class in bits 7-6
 * (system 0x00, command 0x40, info 0x80, data 0xc0), payload size
 * 1 << bits 5-3, command or mode in bits 2-0; info messages carry an info
 * byte next (bit 5 adds 8 to the mode); all but system messages end with
 * a check byte, 0xff xor every byte before it.  System messages are one
 * byte: SYNC 0x00, NACK 0x02, ACK 0x04.
 */
#include <linux/device.h>
#include <linux/fs.h>
#include <linux/jiffies.h>
#include <linux/kernel.h>
#include <linux/miscdevice.h>
#include <linux/module.h>
#include <linux/slab.h>
#include <linux/spinlock.h>
#include <linux/string.h>
#include <linux/tty.h>
#include <linux/uaccess.h>
#include <linux/wait.h>
#include <linux/workqueue.h>
#include "ev3_uart_uapi.h"

#define EV3_UART_HANDSHAKE_BAUD	2400
#define EV3_UART_KEEPALIVE_MS	100

#define MSG_CLASS_MASK		0xc0
#define MSG_SYS			0x00
#define MSG_CMD			0x40
#define MSG_INFO		0x80
#define MSG_DATA		0xc0
#define SYS_NACK		0x02
#define SYS_ACK			0x04
#define CMD_TYPE		0x00
#define CMD_MODES		0x01
#define CMD_SPEED		0x02
#define CMD_SELECT		0x03
#define INFO_NAME		0x00
#define INFO_FORMAT		0x80
#define INFO_MODE_PLUS_8	0x20
#define MAX_PAYLOAD		32
#define MAX_MSG			(MAX_PAYLOAD + 3)

enum ev3_uart_state {
	EV3_UART_ST_SYNCING,	/* looking for the TYPE message */
	EV3_UART_ST_INFO,	/* collecting the introduction */
	EV3_UART_ST_ACKING,	/* the work answers and changes speed */
	EV3_UART_ST_DATA,		/* data frames at the sensor's speed */
};

struct ev3_uart {
	struct tty_struct *tty;
	spinlock_t lock;	/* the state, the info and the reading */
	enum ev3_uart_state state;
	u8 msg[MAX_MSG + 1];
	unsigned int msg_len;
	struct ev3_uart_info info;
	u8 format[EV3_UART_MAX_MODES];
	u8 datasets[EV3_UART_MAX_MODES];
	struct ev3_uart_reading reading;
	u32 read_frames;	/* frames count at the last read() */
	u32 bad_messages;
	wait_queue_head_t wait;
	struct work_struct handshake;
	struct delayed_work keepalive;
	struct miscdevice misc;
	char name[80];		/* "ev3_uart_" and the tty's name */
};

/* The number of bytes of the message starting with header h, 0 if h is invalid. */
static unsigned int ev3_uart_msg_len(u8 h)
{
	unsigned int payload = 1U << ((h >> 3) & 7);

	if ((h & MSG_CLASS_MASK) == MSG_SYS)
		return 1;
	if (payload > MAX_PAYLOAD)
		return 0;
	return ((h & MSG_CLASS_MASK) == MSG_INFO ? 3 : 2) + payload;
}

static bool ev3_uart_check_ok(const u8 *msg, unsigned int len)
{
	u8 check = 0xff;
	unsigned int i;

	for (i = 0; i < len - 1; i++)
		check ^= msg[i];
	return check == msg[len - 1];
}

/* Sends bytes to the sensor (any context). */
static void ev3_uart_send(struct ev3_uart *eu, const u8 *bytes, int len)
{
	if (eu->tty->ops->write(eu->tty, bytes, len) != len)
		pr_warn_ratelimited("%s: transmit buffer full\n", eu->name);
}

static s32 ev3_uart_value(const u8 *p, u8 format, unsigned int i)
{
	switch (format) {
	case 0:
		return (s8)p[i];
	case 1:
		return (s16)(p[2 * i] | p[2 * i + 1] << 8);
	default:
		return (s32)(p[4 * i] | p[4 * i + 1] << 8 | p[4 * i + 2] << 16 | (u32)p[4 * i + 3] << 24);
	}
}

/* Acts on one whole, checked message (lock held). */
static void ev3_uart_handle(struct ev3_uart *eu, const u8 *msg, unsigned int len)
{
	u8 h = msg[0];
	unsigned int mode = h & 7;
	const u8 *p = msg + 1;

	switch (h & MSG_CLASS_MASK) {
	case MSG_SYS:
		if (h == SYS_ACK && eu->state == EV3_UART_ST_INFO && eu->info.modes) {
			eu->state = EV3_UART_ST_ACKING;
			schedule_work(&eu->handshake);
		}
		break;
	case MSG_CMD:
		if (mode == CMD_MODES && eu->state == EV3_UART_ST_INFO) {
			eu->info.modes = min_t(u8, p[0] + 1, EV3_UART_MAX_MODES);
			eu->info.views = len > 3 ? min_t(u8, p[1] + 1, eu->info.modes) : eu->info.modes;
		} else if (mode == CMD_SPEED && eu->state == EV3_UART_ST_INFO && len == 6) {
			eu->info.speed = p[0] | p[1] << 8 | p[2] << 16 | (u32)p[3] << 24;
		}
		break;
	case MSG_INFO:
		if (eu->state != EV3_UART_ST_INFO)
			break;
		if (p[0] & INFO_MODE_PLUS_8)
			mode += 8;
		if (mode >= EV3_UART_MAX_MODES)
			break;
		if ((p[0] & ~INFO_MODE_PLUS_8) == INFO_NAME)
			strscpy(eu->info.name[mode], (const char *)p + 1,
				min_t(size_t, len - 2, EV3_UART_NAME_LEN));
		else if (p[0] == INFO_FORMAT && len >= 7) {
			eu->datasets[mode] = min_t(u8, p[1], ARRAY_SIZE(eu->reading.value));
			eu->format[mode] = p[2];
		}
		break;
	case MSG_DATA:
		if (eu->state == EV3_UART_ST_DATA && mode < EV3_UART_MAX_MODES) {
			struct ev3_uart_reading *r = &eu->reading;
			unsigned int i, size = len - 2;
			unsigned int width = eu->format[mode] == 0 ? 1 : eu->format[mode] == 1 ? 2 : 4;

			r->mode = mode;
			r->format = eu->format[mode];
			r->datasets = min_t(u8, eu->datasets[mode], size / width);
			for (i = 0; i < r->datasets; i++)
				r->value[i] = ev3_uart_value(p, r->format, i);
			r->frames++;
			wake_up_interruptible(&eu->wait);
		}
		break;
	}
}

static void ev3_uart_receive_buf(struct tty_struct *tty, const unsigned char *cp, const char *fp, int count)
{
	struct ev3_uart *eu = tty->disc_data;
	unsigned long flags;
	int i;

	spin_lock_irqsave(&eu->lock, flags);
	for (i = 0; i < count; i++) {
		unsigned int need;

		if (fp && fp[i] != TTY_NORMAL) {
			eu->msg_len = 0;	/* a damaged byte: drop the message under way */
			eu->bad_messages++;
			continue;
		}
		eu->msg[eu->msg_len++] = cp[i];
		if (eu->state == EV3_UART_ST_SYNCING) {
			/* the introduction starts with TYPE: 0x40, the type, its check */
			if (eu->msg[0] != (MSG_CMD | CMD_TYPE)) {
				eu->msg_len = 0;
				continue;
			}
			if (eu->msg_len < 3)
				continue;
			if (ev3_uart_check_ok(eu->msg, 3)) {
				memset(&eu->info, 0, sizeof(eu->info));
				eu->info.type = eu->msg[1];
				eu->state = EV3_UART_ST_INFO;
				eu->msg_len = 0;
			} else {
				memmove(eu->msg, eu->msg + 1, --eu->msg_len);
			}
			continue;
		}
		need = ev3_uart_msg_len(eu->msg[0]);
		if (!need) {
			eu->msg_len = 0;
			eu->bad_messages++;
			continue;
		}
		if (eu->msg_len < need)
			continue;
		if (need == 1 || ev3_uart_check_ok(eu->msg, need))
			ev3_uart_handle(eu, eu->msg, need);
		else
			eu->bad_messages++;
		eu->msg_len = 0;
	}
	spin_unlock_irqrestore(&eu->lock, flags);
}

/* Answers the sensor's ACK, then moves the port to the sensor's speed. */
static void ev3_uart_handshake_work(struct work_struct *work)
{
	struct ev3_uart *eu = container_of(work, struct ev3_uart, handshake);
	static const u8 ack = SYS_ACK;
	struct ktermios termios;
	unsigned long flags;

	ev3_uart_send(eu, &ack, 1);
	tty_wait_until_sent(eu->tty, HZ / 10);
	termios = eu->tty->termios;
	tty_termios_encode_baud_rate(&termios, eu->info.speed, eu->info.speed);
	tty_set_termios(eu->tty, &termios);
	spin_lock_irqsave(&eu->lock, flags);
	eu->state = EV3_UART_ST_DATA;
	eu->msg_len = 0;
	spin_unlock_irqrestore(&eu->lock, flags);
	pr_info("%s: sensor type %u, %u modes, %u baud\n", eu->name, eu->info.type, eu->info.modes,
		eu->info.speed);
	schedule_delayed_work(&eu->keepalive, msecs_to_jiffies(EV3_UART_KEEPALIVE_MS));
}

/* Keeps the sensor from resetting itself: a NACK every 100 ms. */
static void ev3_uart_keepalive_work(struct work_struct *work)
{
	struct ev3_uart *eu = container_of(to_delayed_work(work), struct ev3_uart, keepalive);
	static const u8 nack = SYS_NACK;

	ev3_uart_send(eu, &nack, 1);
	schedule_delayed_work(&eu->keepalive, msecs_to_jiffies(EV3_UART_KEEPALIVE_MS));
}

static struct ev3_uart *file_to_eu(struct file *file)
{
	struct miscdevice *misc = file->private_data;

	return container_of(misc, struct ev3_uart, misc);
}

static bool ev3_uart_new_frame(struct ev3_uart *eu)
{
	return READ_ONCE(eu->reading.frames) != eu->read_frames;
}

static ssize_t ev3_uart_read(struct file *file, char __user *buf, size_t count, loff_t *ppos)
{
	struct ev3_uart *eu = file_to_eu(file);
	struct ev3_uart_reading r;
	unsigned long flags;

	if (count < sizeof(r))
		return -EINVAL;
	if (!ev3_uart_new_frame(eu)) {
		if (file->f_flags & O_NONBLOCK)
			return -EAGAIN;
		if (wait_event_interruptible(eu->wait, ev3_uart_new_frame(eu)))
			return -ERESTARTSYS;
	}
	spin_lock_irqsave(&eu->lock, flags);
	r = eu->reading;
	eu->read_frames = r.frames;
	spin_unlock_irqrestore(&eu->lock, flags);
	return copy_to_user(buf, &r, sizeof(r)) ? -EFAULT : (ssize_t)sizeof(r);
}

static long ev3_uart_ioctl(struct file *file, unsigned int cmd, unsigned long arg)
{
	struct ev3_uart *eu = file_to_eu(file);
	struct ev3_uart_info info;
	unsigned long flags;
	u8 select[3];
	int mode;

	switch (cmd) {
	case EV3_UART_INFO:
		spin_lock_irqsave(&eu->lock, flags);
		info = eu->info;
		spin_unlock_irqrestore(&eu->lock, flags);
		return copy_to_user((void __user *)arg, &info, sizeof(info)) ? -EFAULT : 0;
	case EV3_UART_SET_MODE:
		if (get_user(mode, (int __user *)arg))
			return -EFAULT;
		if (READ_ONCE(eu->state) != EV3_UART_ST_DATA)
			return -EAGAIN;
		if (mode < 0 || mode >= eu->info.modes)
			return -EINVAL;
		select[0] = MSG_CMD | CMD_SELECT;
		select[1] = mode;
		select[2] = 0xff ^ select[0] ^ select[1];
		ev3_uart_send(eu, select, sizeof(select));
		WRITE_ONCE(eu->info.mode, mode);
		return 0;
	default:
		return -ENOTTY;
	}
}

static const struct file_operations ev3_uart_fops = {
	.owner = THIS_MODULE,
	.read = ev3_uart_read,
	.unlocked_ioctl = ev3_uart_ioctl,
	.llseek = no_llseek,
};

static int ev3_uart_open(struct tty_struct *tty)
{
	struct ev3_uart *eu;
	struct ktermios termios;
	int ret;

	if (!tty->ops->write)
		return -EOPNOTSUPP;
	eu = kzalloc(sizeof(*eu), GFP_KERNEL);
	if (!eu)
		return -ENOMEM;
	eu->tty = tty;
	spin_lock_init(&eu->lock);
	init_waitqueue_head(&eu->wait);
	INIT_WORK(&eu->handshake, ev3_uart_handshake_work);
	INIT_DELAYED_WORK(&eu->keepalive, ev3_uart_keepalive_work);
	snprintf(eu->name, sizeof(eu->name), "ev3_uart_%s", tty->name);
	eu->misc.minor = MISC_DYNAMIC_MINOR;
	eu->misc.name = eu->name;
	eu->misc.fops = &ev3_uart_fops;
	ret = misc_register(&eu->misc);
	if (ret) {
		kfree(eu);
		return ret;
	}
	tty->disc_data = eu;
	tty->receive_room = 4096;
	termios = tty->termios;
	termios.c_cflag = (termios.c_cflag & ~(CSIZE | PARENB | CSTOPB | CRTSCTS)) | CS8 | CREAD | CLOCAL;
	tty_termios_encode_baud_rate(&termios, EV3_UART_HANDSHAKE_BAUD, EV3_UART_HANDSHAKE_BAUD);
	tty_set_termios(tty, &termios);
	return 0;
}

static void ev3_uart_close(struct tty_struct *tty)
{
	struct ev3_uart *eu = tty->disc_data;

	cancel_work_sync(&eu->handshake);
	cancel_delayed_work_sync(&eu->keepalive);
	misc_deregister(&eu->misc);
	tty->disc_data = NULL;
	kfree(eu);
}

static struct tty_ldisc_ops ev3_uart_ldisc = {
	.owner = THIS_MODULE,
	.num = N_DEVELOPMENT,
	.name = "ev3-uart",
	.open = ev3_uart_open,
	.close = ev3_uart_close,
	.receive_buf = ev3_uart_receive_buf,
};

static int __init ev3_uart_init(void)
{
	return tty_register_ldisc(&ev3_uart_ldisc);
}
module_init(ev3_uart_init);

static void __exit ev3_uart_exit(void)
{
	tty_unregister_ldisc(&ev3_uart_ldisc);
}
module_exit(ev3_uart_exit);

MODULE_DESCRIPTION("LEGO EV3 UART sensor line discipline");
MODULE_AUTHOR("ev3lx");
MODULE_LICENSE("GPL");
MODULE_ALIAS_LDISC(N_DEVELOPMENT);
