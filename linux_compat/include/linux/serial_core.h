/*
 * linux/serial_core.h — the serial core's port description as a low-level
 * serial driver fills it (Linux's include/linux/serial_core.h; the layout
 * of the 2.6 era, with TI's OMAPL_PRU_SUART port type as LEGO's EV3 kernel
 * defines it, e.g. ev3dev/ev3-kernel include/linux/serial_core.h).
 *
 * Provided: struct uart_port / uart_ops / uart_icount / uart_driver, the
 * UPIO_, UPF_ and UART_CONFIG_ constants, the uart_circ_ helpers and
 * uart_update_timeout (linux_compat/src/serial_core.c).  ev3lx has no tty
 * layer, so there is no uart_register_driver / uart_add_one_port: a driver
 * calling them fails to link, naming them.  LEGO's PRU soft-UART glue (d_uart)
 * calls its ports' uart_ops itself, as its own comments say ("Simulate calls
 * from TTY implementation").
 */
#ifndef LINUX_SERIAL_CORE_H
#define LINUX_SERIAL_CORE_H

#include <linux/types.h>
#include <linux/compiler.h>
#include <linux/interrupt.h>
#include <linux/circ_buf.h>
#include <linux/spinlock.h>
#include <linux/sched.h>
#include <linux/tty.h>
#include <linux/mutex.h>
#include <linux/serial.h>

/* Port types (the subset named here) */
#define PORT_UNKNOWN	0
#define PORT_8250	1
#define PORT_16550A	4
#define PORT_AR7	18
#define OMAPL_PRU_SUART	100	/* TI's PRU soft UART */

struct uart_port;
struct device;
struct module;

struct uart_ops {
	unsigned int	(*tx_empty)(struct uart_port *);
	void		(*set_mctrl)(struct uart_port *, unsigned int mctrl);
	unsigned int	(*get_mctrl)(struct uart_port *);
	void		(*stop_tx)(struct uart_port *);
	void		(*start_tx)(struct uart_port *);
	void		(*send_xchar)(struct uart_port *, char ch);
	void		(*stop_rx)(struct uart_port *);
	void		(*enable_ms)(struct uart_port *);
	void		(*break_ctl)(struct uart_port *, int ctl);
	int		(*startup)(struct uart_port *);
	void		(*shutdown)(struct uart_port *);
	void		(*flush_buffer)(struct uart_port *);
	void		(*set_termios)(struct uart_port *, struct ktermios *new, struct ktermios *old);
	void		(*set_ldisc)(struct uart_port *, int new);
	void		(*pm)(struct uart_port *, unsigned int state, unsigned int oldstate);
	int		(*set_wake)(struct uart_port *, unsigned int state);
	const char	*(*type)(struct uart_port *);
	void		(*release_port)(struct uart_port *);
	int		(*request_port)(struct uart_port *);
	void		(*config_port)(struct uart_port *, int);
	int		(*verify_port)(struct uart_port *, struct serial_struct *);
	int		(*ioctl)(struct uart_port *, unsigned int, unsigned long);
};

#define NO_POLL_CHAR		0x00ff0000
#define UART_CONFIG_TYPE	(1 << 0)
#define UART_CONFIG_IRQ		(1 << 1)

struct uart_icount {
	__u32	cts;
	__u32	dsr;
	__u32	rng;
	__u32	dcd;
	__u32	rx;
	__u32	tx;
	__u32	frame;
	__u32	overrun;
	__u32	parity;
	__u32	brk;
	__u32	buf_overrun;
};

typedef unsigned int upf_t;

struct uart_port {
	spinlock_t		lock;			/* port lock */
	unsigned long		iobase;			/* in/out[bwl] */
	unsigned char __iomem	*membase;		/* read/write[bwl] */
	unsigned int		(*serial_in)(struct uart_port *, int);
	void			(*serial_out)(struct uart_port *, int, int);
	unsigned int		irq;			/* irq number */
	unsigned long		irqflags;		/* irq flags */
	unsigned int		uartclk;		/* base uart clock */
	unsigned int		fifosize;		/* tx fifo size */
	unsigned char		x_char;			/* xon/xoff char */
	unsigned char		regshift;		/* reg offset shift */
	unsigned char		iotype;			/* io access style */
	unsigned char		unused1;

#define UPIO_PORT		(SERIAL_IO_PORT)
#define UPIO_HUB6		(SERIAL_IO_HUB6)
#define UPIO_MEM		(SERIAL_IO_MEM)
#define UPIO_MEM32		(SERIAL_IO_MEM32)

	unsigned int		read_status_mask;	/* driver specific */
	unsigned int		ignore_status_mask;	/* driver specific */
	struct uart_state	*state;			/* pointer to parent state */
	struct uart_icount	icount;			/* statistics */
	struct console		*cons;			/* struct console, if any */
	upf_t			flags;

#define UPF_FOURPORT		((upf_t) (1 << 1))
#define UPF_SAK			((upf_t) (1 << 2))
#define UPF_SKIP_TEST		((upf_t) (1 << 6))
#define UPF_AUTO_IRQ		((upf_t) (1 << 7))
#define UPF_LOW_LATENCY		((upf_t) (1 << 13))
#define UPF_BUGGY_UART		((upf_t) (1 << 14))
#define UPF_SHARE_IRQ		((upf_t) (1 << 24))
#define UPF_FIXED_TYPE		((upf_t) (1 << 27))
#define UPF_BOOT_AUTOCONF	((upf_t) (1 << 28))
#define UPF_FIXED_PORT		((upf_t) (1 << 29))
#define UPF_DEAD		((upf_t) (1 << 30))
#define UPF_IOREMAP		((upf_t) (1U << 31))

	unsigned int		mctrl;			/* current modem ctrl settings */
	unsigned int		timeout;		/* character-based timeout, jiffies */
	unsigned int		type;			/* port type */
	const struct uart_ops	*ops;
	unsigned int		custom_divisor;
	unsigned int		line;			/* port index */
	resource_size_t		mapbase;		/* for ioremap */
	struct device		*dev;			/* parent device */
	unsigned char		hub6;
	unsigned char		suspended;
	unsigned char		irq_wake;
	unsigned char		unused[2];
	void			*private_data;		/* generic platform data pointer */
};

/* A serial driver's registration with the serial core (named by drivers;
 * ev3lx has no tty layer to register it with). */
struct uart_driver {
	struct module		*owner;
	const char		*driver_name;
	const char		*dev_name;
	int			major;
	int			minor;
	int			nr;
	struct console		*cons;
	struct uart_state	*state;
	struct tty_driver	*tty_driver;
};

/* Number of characters left in the xmit buffer before the tty layer is asked for more. */
#define WAKEUP_CHARS		256

#define uart_circ_empty(circ)		((circ)->head == (circ)->tail)
#define uart_circ_clear(circ)		((circ)->head = (circ)->tail = 0)

/* Sets port->timeout (jiffies) for the character format in cflag at baud:
 * a FIFO of characters of 7..12 bits, plus 20 ms, as Linux's serial core does. */
void uart_update_timeout(struct uart_port *port, unsigned int cflag, unsigned int baud);

#endif
