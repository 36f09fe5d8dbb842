/*
 * serial.c — the DaVinci UARTs as ttys (mach/serial.h states the
 * contract): one tty driver "ttyS" of DAVINCI_SERIAL_LINES lines, present
 * while the board has added at least one port; a line without a port
 * cannot be opened (-ENODEV), as an 8250 line without a UART.
 */
#include <mach/serial.h>
#include <linux/circ_buf.h>
#include <linux/interrupt.h>
#include <linux/io.h>
#include <linux/kernel.h>
#include <linux/mutex.h>
#include <linux/spinlock.h>
#include <linux/string.h>
#include <linux/tty.h>
#include <linux/tty_flip.h>
#include <linux_compat/irq.h>

/* Registers (AM1808 TRM, UART chapter). */
#define UART_RBR	0x00    /* THR on writes */
#define UART_IER	0x04
#define UART_IIR	0x08    /* FCR on writes */
#define UART_LCR	0x0c
#define UART_LSR	0x14
#define UART_DLL	0x20
#define UART_DLH	0x24
#define UART_PWREMU	0x30
#define UART_MDR	0x34

#define IER_ERBI	0x01
#define IER_ETBEI	0x02
#define IER_ELSI	0x04
#define IIR_NO_INT	0x01
#define FCR_FIFOEN	0x01
#define FCR_RXCLR	0x02
#define FCR_TXCLR	0x04
#define LCR_STB		0x04
#define LCR_PEN		0x08
#define LCR_EPS		0x10
#define LSR_DR		0x01
#define LSR_OE		0x02
#define LSR_PE		0x04
#define LSR_FE		0x08
#define LSR_BI		0x10
#define LSR_THRE	0x20
#define LSR_TEMT	0x40
#define PWREMU_RUN	0x6001  /* UTRST | URRST | FREE */
#define TX_FIFO		16

#define TX_SIZE		512     /* a power of two, for circ_buf */

struct davinci_uart {
	struct davinci_uart_port cfg;
	struct tty_port port;
	void __iomem *base;
	spinlock_t lock;        /* the TX buffer and IER */
	unsigned char tx_buf[TX_SIZE];
	unsigned int tx_head, tx_tail;
	u32 ier;
	bool present;
	bool opened;
};

static DEFINE_MUTEX(serial_lock);
static struct davinci_uart uarts[DAVINCI_SERIAL_LINES];
static struct tty_driver *serial_driver;
static unsigned int ports_added;

static u32 uart_read(struct davinci_uart *u, unsigned int reg)
{
	return readl((u8 __iomem *)u->base + reg);
}

static void uart_write(struct davinci_uart *u, unsigned int reg, u32 value)
{
	writel(value, (u8 __iomem *)u->base + reg);
}

/* Moves received bytes into the flip buffer with their flags. */
static void uart_receive(struct davinci_uart *u)
{
	u32 lsr;

	while ((lsr = uart_read(u, UART_LSR)) & (LSR_DR | LSR_BI)) {
		unsigned char ch = (unsigned char)uart_read(u, UART_RBR);
		char flag = TTY_NORMAL;

		if (lsr & LSR_BI)
			flag = TTY_BREAK;
		else if (lsr & LSR_PE)
			flag = TTY_PARITY;
		else if (lsr & LSR_FE)
			flag = TTY_FRAME;
		tty_insert_flip_char(&u->port, ch, flag);
		if (lsr & LSR_OE)
			tty_insert_flip_char(&u->port, 0, TTY_OVERRUN);
	}
	tty_flip_buffer_push(&u->port);
}

/* Fills the TX FIFO from the buffer (lock held); true when the buffer ran empty. */
static bool uart_transmit(struct davinci_uart *u)
{
	unsigned int n = 0;

	while (n < TX_FIFO && CIRC_CNT(u->tx_head, u->tx_tail, TX_SIZE)) {
		uart_write(u, UART_RBR, u->tx_buf[u->tx_tail]);
		u->tx_tail = (u->tx_tail + 1) & (TX_SIZE - 1);
		n++;
	}
	if (CIRC_CNT(u->tx_head, u->tx_tail, TX_SIZE))
		return false;
	u->ier &= ~IER_ETBEI;
	uart_write(u, UART_IER, u->ier);
	return true;
}

static irqreturn_t uart_interrupt(int irq, void *data)
{
	struct davinci_uart *u = data;
	irqreturn_t handled = IRQ_NONE;
	unsigned int rounds;

	/* bounded: a source nothing here serves (modem status) cannot hold the CPU */
	for (rounds = 0; rounds < 32 && !(uart_read(u, UART_IIR) & IIR_NO_INT); rounds++) {
		bool drained = false;

		handled = IRQ_HANDLED;
		if (uart_read(u, UART_LSR) & (LSR_DR | LSR_BI))
			uart_receive(u);
		spin_lock(&u->lock);
		if ((u->ier & IER_ETBEI) && (uart_read(u, UART_LSR) & LSR_THRE))
			drained = uart_transmit(u);
		spin_unlock(&u->lock);
		if (drained)
			tty_wakeup(u->port.tty);
	}
	return handled;
}

/* Programs the divisor and the frame format from termios. */
static void uart_apply_termios(struct davinci_uart *u, const struct ktermios *termios)
{
	speed_t baud = tty_termios_baud_rate(termios);
	u32 lcr, divisor;

	lcr = (termios->c_cflag & CSIZE) == CS5 ? 0 : (termios->c_cflag & CSIZE) == CS6 ? 1 :
	      (termios->c_cflag & CSIZE) == CS7 ? 2 : 3;
	if (termios->c_cflag & CSTOPB)
		lcr |= LCR_STB;
	if (termios->c_cflag & PARENB)
		lcr |= LCR_PEN | ((termios->c_cflag & PARODD) ? 0 : LCR_EPS);
	uart_write(u, UART_LCR, lcr);
	if (!baud)
		return;
	divisor = DIV_ROUND_CLOSEST(u->cfg.uartclk, 16 * baud);
	divisor = clamp_t(u32, divisor, 1, 0xffff);
	uart_write(u, UART_DLL, divisor & 0xff);
	uart_write(u, UART_DLH, divisor >> 8);
}

static int uart_install(struct tty_driver *driver, struct tty_struct *tty)
{
	struct davinci_uart *u = &uarts[tty->index];

	if (!u->present)
		return -ENODEV;
	tty->driver_data = u;
	tty->port = &u->port;
	return 0;
}

static int uart_open(struct tty_struct *tty, struct file *filp)
{
	struct davinci_uart *u = tty->driver_data;
	int ret;

	if (u->opened)
		return 0;
	u->base = ioremap(u->cfg.mapbase, 0x40);
	if (!u->base)
		return -ENOMEM;
	u->tx_head = u->tx_tail = 0;
	uart_write(u, UART_PWREMU, 0);
	uart_write(u, UART_IER, 0);
	uart_write(u, UART_MDR, 0);
	uart_apply_termios(u, &tty->termios);
	uart_write(u, UART_IIR, FCR_FIFOEN);
	uart_write(u, UART_IIR, FCR_FIFOEN | FCR_RXCLR | FCR_TXCLR);
	uart_write(u, UART_PWREMU, PWREMU_RUN);
	ret = request_irq(u->cfg.irq, uart_interrupt, 0, tty->name, u);
	if (ret) {
		uart_write(u, UART_PWREMU, 0);
		iounmap(u->base);
		return ret;
	}
	u->ier = IER_ERBI | IER_ELSI;
	uart_write(u, UART_IER, u->ier);
	u->opened = true;
	return 0;
}

static void uart_close(struct tty_struct *tty, struct file *filp)
{
	struct davinci_uart *u = tty->driver_data;

	if (!u || !u->opened || tty->count > 1)
		return;
	uart_write(u, UART_IER, 0);
	free_irq(u->cfg.irq, u);
	uart_write(u, UART_PWREMU, 0);
	iounmap(u->base);
	u->opened = false;
}

static int uart_tty_write(struct tty_struct *tty, const unsigned char *buf, int count)
{
	struct davinci_uart *u = tty->driver_data;
	unsigned long flags;
	int n = 0;

	spin_lock_irqsave(&u->lock, flags);
	while (n < count && CIRC_SPACE(u->tx_head, u->tx_tail, TX_SIZE)) {
		u->tx_buf[u->tx_head] = buf[n++];
		u->tx_head = (u->tx_head + 1) & (TX_SIZE - 1);
	}
	if (n && !(u->ier & IER_ETBEI)) {
		u->ier |= IER_ETBEI;        /* THRE interrupts from now, at once if THR is empty */
		uart_write(u, UART_IER, u->ier);
	}
	spin_unlock_irqrestore(&u->lock, flags);
	return n;
}

static unsigned int uart_write_room(struct tty_struct *tty)
{
	struct davinci_uart *u = tty->driver_data;

	return CIRC_SPACE(READ_ONCE(u->tx_head), READ_ONCE(u->tx_tail), TX_SIZE);
}

static unsigned int uart_chars_in_buffer(struct tty_struct *tty)
{
	struct davinci_uart *u = tty->driver_data;
	unsigned int n = CIRC_CNT(READ_ONCE(u->tx_head), READ_ONCE(u->tx_tail), TX_SIZE);

	return n + !(uart_read(u, UART_LSR) & LSR_TEMT);
}

static void uart_flush_buffer(struct tty_struct *tty)
{
	struct davinci_uart *u = tty->driver_data;
	unsigned long flags;

	spin_lock_irqsave(&u->lock, flags);
	u->tx_tail = u->tx_head;
	spin_unlock_irqrestore(&u->lock, flags);
}

static void uart_set_termios(struct tty_struct *tty, const struct ktermios *old)
{
	struct davinci_uart *u = tty->driver_data;

	if (u->opened)
		uart_apply_termios(u, &tty->termios);
}

static const struct tty_operations uart_ops = {
	.install = uart_install,
	.open = uart_open,
	.close = uart_close,
	.write = uart_tty_write,
	.write_room = uart_write_room,
	.chars_in_buffer = uart_chars_in_buffer,
	.flush_buffer = uart_flush_buffer,
	.set_termios = uart_set_termios,
};

/* Registers the ttyS driver (serial_lock held): 0 or -errno. */
static int register_serial_driver(void)
{
	struct tty_driver *driver = tty_alloc_driver(DAVINCI_SERIAL_LINES, 0);
	int ret;

	if (IS_ERR(driver))
		return (int)PTR_ERR(driver);
	driver->driver_name = "serial";
	driver->name = "ttyS";
	driver->major = 4;
	driver->minor_start = 64;
	driver->type = TTY_DRIVER_TYPE_SERIAL;
	driver->subtype = SERIAL_TYPE_NORMAL;
	driver->init_termios = tty_std_termios;
	driver->init_termios.c_cflag = B115200 | CS8 | CREAD | HUPCL | CLOCAL;
	driver->init_termios.c_ispeed = driver->init_termios.c_ospeed = 115200;
	tty_set_operations(driver, &uart_ops);
	ret = tty_register_driver(driver);
	if (ret) {
		tty_driver_kref_put(driver);
		return ret;
	}
	serial_driver = driver;
	return 0;
}

int davinci_serial_add(const struct davinci_uart_port *p)
{
	struct davinci_uart *u;
	int ret = 0;

	might_sleep();
	if (!p || p->line >= DAVINCI_SERIAL_LINES || !p->uartclk) {
		pr_err("davinci-serial: bad port (line %d, clock %u)\n", p ? (int)p->line : -1, p ? p->uartclk : 0);
		return -EINVAL;
	}
	mutex_lock(&serial_lock);
	u = &uarts[p->line];
	if (u->present) {
		mutex_unlock(&serial_lock);
		return -EBUSY;
	}
	if (!serial_driver)
		ret = register_serial_driver();
	if (!ret) {
		memset(u, 0, sizeof(*u));
		u->cfg = *p;
		spin_lock_init(&u->lock);
		tty_port_init(&u->port);
		tty_port_link_device(&u->port, serial_driver, p->line);
		u->present = true;
		ports_added++;
	}
	mutex_unlock(&serial_lock);
	return ret;
}

void davinci_serial_del(unsigned int line)
{
	struct davinci_uart *u;

	might_sleep();
	if (line >= DAVINCI_SERIAL_LINES)
		return;
	mutex_lock(&serial_lock);
	u = &uarts[line];
	if (u->present && !WARN_ON(u->opened)) {
		tty_port_destroy(&u->port);
		u->present = false;
		if (--ports_added == 0) {
			tty_unregister_driver(serial_driver);
			tty_driver_kref_put(serial_driver);
			serial_driver = NULL;
		}
	}
	mutex_unlock(&serial_lock);
}

void lx_davinci_serial_boot(void)
{
	mutex_init(&serial_lock);
	memset(uarts, 0, sizeof(uarts));
	serial_driver = NULL;
	ports_added = 0;
}
