/*
 * linux/tty.h — ttys (Linux 6.1's struct tty_struct, the fields line
 * disciplines use), the flip buffer drivers fill, termios and baud
 * rates (src/tty.c).
 *
 * A tty exists from its first open to its last close; it starts with N_TTY
 * (raw here: read returns the bytes received, write queues them to the
 * driver) and TIOCSETD gives it another discipline, as user space does on
 * Linux.  Received bytes go from the driver's tty_insert_flip_* (any
 * context) to the discipline's receive_buf in process context (the flip
 * buffer's work), as Linux's flush_to_ldisc.  Not provided: job control,
 * canonical mode and echo, hangup, consoles, pseudo-terminals, the serial
 * core (uart_driver/uart_port).
 */
#ifndef _LINUX_TTY_H
#define _LINUX_TTY_H

#include <linux/types.h>
#include <linux/bitops.h>
#include <linux/fs.h>
#include <linux/module.h>
#include <linux/mutex.h>
#include <linux/stringify.h>
#include <linux/spinlock.h>
#include <linux/wait.h>
#include <linux/workqueue.h>
#include <linux/tty_driver.h>
#include <linux/tty_ldisc.h>
#include <linux/termios.h>
#include <linux/semaphore.h>	/* 2.6's tty.h -> linux/fs.h -> linux/semaphore.h: serial drivers of that era rely on it */

/* line disciplines (uapi/linux/tty.h) */
#define N_TTY		0
#define N_SLIP		1
#define N_MOUSE		2
#define N_PPP		3
#define N_HDLC		13
#define N_GSM0710	21
#define N_NULL		27
#define N_DEVELOPMENT	29
#define NR_LDISCS	31

#define MODULE_ALIAS_LDISC(ldisc)	MODULE_ALIAS("tty-ldisc-" __stringify(ldisc))

/* flags of received bytes */
#define TTY_NORMAL	0
#define TTY_BREAK	1
#define TTY_FRAME	2
#define TTY_PARITY	3
#define TTY_OVERRUN	4

/* tty->flags bits */
#define TTY_THROTTLED		0
#define TTY_IO_ERROR		1
#define TTY_OTHER_CLOSED	2
#define TTY_EXCLUSIVE		3
#define TTY_DO_WRITE_WAKEUP	5
#define TTY_LDISC_OPEN		11

#define LX_TTY_FLIP_SIZE	512

struct tty_port {
	struct tty_struct *tty;         /* the open tty, NULL while closed */
	spinlock_t lock;
	unsigned char lx_flip[LX_TTY_FLIP_SIZE];        /* ev3lx: bytes not yet pushed */
	char lx_flags[LX_TTY_FLIP_SIZE];
	unsigned int lx_head, lx_tail;
	unsigned long lx_dropped;                       /* ev3lx: lost to a full buffer */
	struct work_struct lx_push;
};

struct tty_struct {
	struct tty_driver *driver;
	const struct tty_operations *ops;
	int index;
	struct tty_ldisc *ldisc;
	struct mutex ldisc_lock;        /* Linux: ldisc_sem */
	struct mutex termios_rwsem;
	struct ktermios termios;
	char name[64];
	unsigned long flags;
	int count;
	unsigned int receive_room;
	void *disc_data;
	void *driver_data;
	struct tty_port *port;
	struct device *dev;
	struct tty_ldisc lx_ldisc;      /* ev3lx: the current discipline */
	/* ev3lx: N_TTY's receive buffer */
	unsigned char lx_rx[256];
	unsigned int lx_rx_head, lx_rx_tail;
	wait_queue_head_t lx_read_wait;
};

static inline const char *tty_name(const struct tty_struct *tty)
{
	return tty ? tty->name : "NULL tty";
}

/* Driver side */
void tty_port_init(struct tty_port *port);
void tty_port_destroy(struct tty_port *port);
/* Line index of driver is served by port. */
void tty_port_link_device(struct tty_port *port, struct tty_driver *driver, unsigned int index);
/* Queues one received byte with its TTY_* flag: 1, or 0 if the buffer is full (any context). */
int tty_insert_flip_char(struct tty_port *port, unsigned char ch, char flag);
int tty_insert_flip_string(struct tty_port *port, const unsigned char *chars, size_t size);
/* Hands the queued bytes to the discipline, from the system workqueue (any context). */
void tty_flip_buffer_push(struct tty_port *port);
/* The driver can take more: calls the discipline's write_wakeup if it asked (any context). */
void tty_wakeup(struct tty_struct *tty);

/* Discipline side */
unsigned int tty_write_room(struct tty_struct *tty);
unsigned int tty_chars_in_buffer(struct tty_struct *tty);
void tty_driver_flush_buffer(struct tty_struct *tty);
/* Waits (sleeping) until the driver has sent what it holds, at most timeout jiffies (0: 1 s). */
void tty_wait_until_sent(struct tty_struct *tty, long timeout);
/* Sets the termios and tells the driver and the discipline: 0.  Process context. */
int tty_set_termios(struct tty_struct *tty, struct ktermios *kt);
/* Changes tty's discipline (TIOCSETD): 0, -EINVAL for an unregistered one,
 * or the new discipline's open error (the old one is restored).  Process context. */
int tty_set_ldisc(struct tty_struct *tty, int disc);
/* tty_set_ldisc's N_TTY (a discipline's close must not call it). */
void tty_ldisc_flush(struct tty_struct *tty);

speed_t tty_termios_baud_rate(const struct ktermios *termios);
speed_t tty_termios_input_baud_rate(const struct ktermios *termios);
/* Stores the rates in termios, as a B code where one is exact, else BOTHER. */
void tty_termios_encode_baud_rate(struct ktermios *termios, speed_t ibaud, speed_t obaud);

static inline void tty_encode_baud_rate(struct tty_struct *tty, speed_t ibaud, speed_t obaud)
{
	tty_termios_encode_baud_rate(&tty->termios, ibaud, obaud);
}

static inline speed_t tty_get_baud_rate(struct tty_struct *tty)
{
	return tty_termios_baud_rate(&tty->termios);
}

#endif /* _LINUX_TTY_H */
