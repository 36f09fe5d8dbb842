/*
 * linux/tty_driver.h — tty drivers (Linux 6.1's struct tty_operations and
 * struct tty_driver, the fields linux_compat uses): a driver registers its
 * lines as /dev/<name><n> (src/tty.c).
 */
#ifndef _LINUX_TTY_DRIVER_H
#define _LINUX_TTY_DRIVER_H

#include <linux/types.h>
#include <linux/err.h>
#include <linux/fs.h>
#include <linux/module.h>
#include <asm/termbits.h>

struct tty_struct;
struct tty_driver;

struct tty_operations {
	int (*install)(struct tty_driver *driver, struct tty_struct *tty);
	int (*open)(struct tty_struct *tty, struct file *filp);
	void (*close)(struct tty_struct *tty, struct file *filp);
	void (*cleanup)(struct tty_struct *tty);
	/* queues count bytes: the number taken (any context) */
	int (*write)(struct tty_struct *tty, const unsigned char *buf, int count);
	unsigned int (*write_room)(struct tty_struct *tty);
	unsigned int (*chars_in_buffer)(struct tty_struct *tty);
	int (*ioctl)(struct tty_struct *tty, unsigned int cmd, unsigned long arg);
	void (*set_termios)(struct tty_struct *tty, const struct ktermios *old);
	void (*flush_buffer)(struct tty_struct *tty);
	void (*hangup)(struct tty_struct *tty);
	int (*break_ctl)(struct tty_struct *tty, int state);
	void (*wait_until_sent)(struct tty_struct *tty, int timeout);
	/* Linux 6.1's other operations: kept for the drivers that fill them;
	 * this tty core writes with write() and never calls these. */
	int (*put_char)(struct tty_struct *tty, unsigned char ch);
	void (*flush_chars)(struct tty_struct *tty);
	void (*throttle)(struct tty_struct *tty);
	void (*unthrottle)(struct tty_struct *tty);
	void (*stop)(struct tty_struct *tty);
	void (*start)(struct tty_struct *tty);
	void (*send_xchar)(struct tty_struct *tty, char ch);
	int (*tiocmget)(struct tty_struct *tty);
	int (*tiocmset)(struct tty_struct *tty, unsigned int set, unsigned int clear);
};

#define TTY_DRIVER_TYPE_SYSTEM		0x0001
#define TTY_DRIVER_TYPE_CONSOLE		0x0002
#define TTY_DRIVER_TYPE_SERIAL		0x0003
#define SERIAL_TYPE_NORMAL		1

#define TTY_DRIVER_INSTALLED		0x0001
#define TTY_DRIVER_RESET_TERMIOS	0x0002
#define TTY_DRIVER_REAL_RAW		0x0004
#define TTY_DRIVER_DYNAMIC_DEV		0x0008

#define LX_TTY_MAX_LINES		8

struct tty_driver {
	struct module *owner;
	const char *driver_name;
	const char *name;               /* "ttyS": lines are /dev/ttyS<name_base + n> */
	int name_base;
	int major;
	int minor_start;
	unsigned int num;
	short type;
	short subtype;
	struct ktermios init_termios;
	unsigned long flags;
	void *driver_state;
	const struct tty_operations *ops;
	struct tty_struct *lx_ttys[LX_TTY_MAX_LINES];   /* ev3lx: the open ttys */
	struct tty_port *lx_ports[LX_TTY_MAX_LINES];    /* ev3lx: tty_port_link_device */
	bool lx_registered;
};

extern const struct ktermios tty_std_termios;

/* A driver for lines lines (at most LX_TTY_MAX_LINES): the driver, or ERR_PTR(-EINVAL / -ENOMEM). */
struct tty_driver *__tty_alloc_driver(unsigned int lines, struct module *owner, unsigned long flags);
#define tty_alloc_driver(lines, flags)	__tty_alloc_driver(lines, THIS_MODULE, flags)
/* Frees an unregistered driver. */
void tty_driver_kref_put(struct tty_driver *driver);

static inline void tty_set_operations(struct tty_driver *driver, const struct tty_operations *op)
{
	driver->ops = op;
}

/* Registers /dev/<name><n> for each line (none with TTY_DRIVER_DYNAMIC_DEV): 0 or -errno. */
int tty_register_driver(struct tty_driver *driver);
void tty_unregister_driver(struct tty_driver *driver);

#endif /* _LINUX_TTY_DRIVER_H */
