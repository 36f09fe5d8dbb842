/*
 * linux/tty_ldisc.h — line disciplines (Linux 6.1's layout of struct
 * tty_ldisc_ops): the layer between a tty driver and the tty's users,
 * selected per tty with TIOCSETD (src/tty.c).
 */
#ifndef _LINUX_TTY_LDISC_H
#define _LINUX_TTY_LDISC_H

#include <linux/types.h>
#include <linux/fs.h>
#include <linux/poll.h>
#include <asm/termbits.h>

struct tty_struct;

struct tty_ldisc_ops {
	char *name;
	int num;
	/* from above, in process context */
	int (*open)(struct tty_struct *tty);
	void (*close)(struct tty_struct *tty);
	void (*flush_buffer)(struct tty_struct *tty);
	ssize_t (*read)(struct tty_struct *tty, struct file *file, unsigned char *buf, size_t nr,
			void **cookie, unsigned long offset);
	ssize_t (*write)(struct tty_struct *tty, struct file *file, const unsigned char *buf, size_t nr);
	int (*ioctl)(struct tty_struct *tty, unsigned int cmd, unsigned long arg);
	int (*compat_ioctl)(struct tty_struct *tty, unsigned int cmd, unsigned long arg);
	void (*set_termios)(struct tty_struct *tty, const struct ktermios *old);
	__poll_t (*poll)(struct tty_struct *tty, struct file *file, struct poll_table_struct *wait);
	void (*hangup)(struct tty_struct *tty);
	/* from below: received bytes (process context, the flip buffer's work) */
	void (*receive_buf)(struct tty_struct *tty, const unsigned char *cp, const char *fp, int count);
	/* the driver can take more (any context) */
	void (*write_wakeup)(struct tty_struct *tty);
	void (*dcd_change)(struct tty_struct *tty, bool active);
	int (*receive_buf2)(struct tty_struct *tty, const unsigned char *cp, const char *fp, int count);
	void (*lookahead_buf)(struct tty_struct *tty, const unsigned char *cp, const unsigned char *fp,
			      unsigned int count);
	struct module *owner;
};

struct tty_ldisc {
	struct tty_ldisc_ops *ops;
	struct tty_struct *tty;
};

/* Makes ops the discipline numbered ops->num: 0, -EINVAL outside 0..NR_LDISCS-1. */
int tty_register_ldisc(struct tty_ldisc_ops *new_ldisc);
/* Forgets the discipline (ttys using it keep it until they change or close). */
void tty_unregister_ldisc(struct tty_ldisc_ops *ldisc);

#endif /* _LINUX_TTY_LDISC_H */
