/*
 * tty.c — the tty layer (linux/tty.h, tty_driver.h and tty_ldisc.h state
 * the contract), after Linux 6.1's drivers/tty/tty_io.c, tty_ldisc.c,
 * tty_buffer.c and tty_baudrate.c: drivers' lines as /dev nodes, a tty per
 * open line, its discipline (N_TTY raw, or any registered one through
 * TIOCSETD), the flip buffer pushed to the discipline from a work item,
 * termios and baud rates.
 */
#include <linux/tty.h>
#include <linux/tty_flip.h>
#include <linux/delay.h>
#include <linux/jiffies.h>
#include <linux/kdev_t.h>
#include <linux/kernel.h>
#include <linux/module.h>
#include <linux/poll.h>
#include <linux/slab.h>
#include <linux/string.h>
#include <linux/uaccess.h>
#include <linux_compat/devfs.h>
#include <linux_compat/irq.h>

#define TTY_DEFAULT_MAJOR	4
#define TTY_DEFAULT_MINOR	64

static DEFINE_MUTEX(tty_mutex);
static struct tty_ldisc_ops *ldiscs[NR_LDISCS];
static struct tty_driver *drivers[8];

const struct ktermios tty_std_termios = {
	.c_iflag = ICRNL | IXON,
	.c_oflag = OPOST,
	.c_cflag = B38400 | CS8 | CREAD | HUPCL,
	.c_lflag = ISIG | ICANON | ECHO,
	.c_ispeed = 38400,
	.c_ospeed = 38400,
};

/* ---- baud rates (tty_baudrate.c) ---- */

static const speed_t baud_table[] = {
	0, 50, 75, 110, 134, 150, 200, 300, 600, 1200, 1800, 2400, 4800, 9600, 19200, 38400,
	57600, 115200, 230400, 460800, 500000, 576000, 921600, 1000000,
};
static const tcflag_t baud_bits[] = {
	B0, B50, B75, B110, B134, B150, B200, B300, B600, B1200, B1800, B2400, B4800, B9600, B19200, B38400,
	B57600, B115200, B230400, B460800, B500000, B576000, B921600, B1000000,
};

/* The rate of a CBAUD code (BOTHER: other), or 0 if unknown. */
static speed_t code_to_baud(tcflag_t cbaud, speed_t other)
{
	unsigned int i;

	if (cbaud == BOTHER)
		return other;
	for (i = 0; i < ARRAY_SIZE(baud_bits); i++)
		if (baud_bits[i] == cbaud)
			return baud_table[i];
	return 0;
}

speed_t tty_termios_baud_rate(const struct ktermios *termios)
{
	return code_to_baud(termios->c_cflag & CBAUD, termios->c_ospeed);
}

speed_t tty_termios_input_baud_rate(const struct ktermios *termios)
{
	tcflag_t cbaud = (termios->c_cflag >> IBSHIFT) & CBAUD;

	if (cbaud == B0)
		return tty_termios_baud_rate(termios);
	return code_to_baud(cbaud, termios->c_ispeed);
}

/* The B code of baud, or BOTHER if none is exact. */
static tcflag_t baud_to_code(speed_t baud)
{
	unsigned int i;

	for (i = 0; i < ARRAY_SIZE(baud_table); i++)
		if (baud_table[i] == baud)
			return baud_bits[i];
	return BOTHER;
}

void tty_termios_encode_baud_rate(struct ktermios *termios, speed_t ibaud, speed_t obaud)
{
	termios->c_ispeed = ibaud;
	termios->c_ospeed = obaud;
	termios->c_cflag &= ~(CBAUD | CIBAUD);
	termios->c_cflag |= baud_to_code(obaud);
	if (ibaud != obaud)
		termios->c_cflag |= baud_to_code(ibaud) << IBSHIFT;
}

/* ---- line disciplines ---- */

int tty_register_ldisc(struct tty_ldisc_ops *new_ldisc)
{
	if (!new_ldisc || new_ldisc->num < N_TTY || new_ldisc->num >= NR_LDISCS)
		return -EINVAL;
	mutex_lock(&tty_mutex);
	ldiscs[new_ldisc->num] = new_ldisc;
	mutex_unlock(&tty_mutex);
	return 0;
}

void tty_unregister_ldisc(struct tty_ldisc_ops *ldisc)
{
	if (!ldisc || ldisc->num < N_TTY || ldisc->num >= NR_LDISCS)
		return;
	mutex_lock(&tty_mutex);
	if (ldiscs[ldisc->num] == ldisc)
		ldiscs[ldisc->num] = NULL;
	mutex_unlock(&tty_mutex);
}

/* N_TTY, raw: received bytes wait in the tty for read(). */
static int n_tty_open(struct tty_struct *tty)
{
	tty->lx_rx_head = tty->lx_rx_tail = 0;
	tty->receive_room = sizeof(tty->lx_rx) - 1;
	return 0;
}

static void n_tty_receive_buf(struct tty_struct *tty, const unsigned char *cp, const char *fp, int count)
{
	int i;

	for (i = 0; i < count; i++) {
		unsigned int next = (tty->lx_rx_head + 1) % sizeof(tty->lx_rx);

		if (next == READ_ONCE(tty->lx_rx_tail))
			break;          /* full: the rest is lost, as an overrun */
		tty->lx_rx[tty->lx_rx_head] = cp[i];
		WRITE_ONCE(tty->lx_rx_head, next);
	}
	wake_up_interruptible(&tty->lx_read_wait);
}

static bool n_tty_has_data(struct tty_struct *tty)
{
	return READ_ONCE(tty->lx_rx_head) != READ_ONCE(tty->lx_rx_tail);
}

static ssize_t n_tty_read(struct tty_struct *tty, struct file *file, unsigned char *buf, size_t nr,
			  void **cookie, unsigned long offset)
{
	size_t n = 0;

	if (!n_tty_has_data(tty)) {
		if (file->f_flags & O_NONBLOCK)
			return -EAGAIN;
		if (wait_event_interruptible(tty->lx_read_wait, n_tty_has_data(tty)))
			return -ERESTARTSYS;
	}
	while (n < nr && n_tty_has_data(tty)) {
		buf[n++] = tty->lx_rx[tty->lx_rx_tail];
		WRITE_ONCE(tty->lx_rx_tail, (tty->lx_rx_tail + 1) % sizeof(tty->lx_rx));
	}
	return (ssize_t)n;
}

static ssize_t n_tty_write(struct tty_struct *tty, struct file *file, const unsigned char *buf, size_t nr)
{
	size_t done = 0;

	while (done < nr) {
		int n = tty->ops->write(tty, buf + done, (int)min_t(size_t, nr - done, INT_MAX));

		if (n < 0)
			return done ? (ssize_t)done : n;
		done += (size_t)n;
		if (done < nr) {
			if (file && (file->f_flags & O_NONBLOCK))
				break;
			msleep(1);
		}
	}
	return done ? (ssize_t)done : -EAGAIN;
}

static struct tty_ldisc_ops n_tty_ops = {
	.name = "n_tty",
	.num = N_TTY,
	.open = n_tty_open,
	.read = n_tty_read,
	.write = n_tty_write,
	.receive_buf = n_tty_receive_buf,
};

/* Opens discipline ops on tty (ldisc_lock held): 0 or its open's error. */
static int ldisc_open(struct tty_struct *tty, struct tty_ldisc_ops *ops)
{
	int ret = 0;

	tty->lx_ldisc.ops = ops;
	tty->lx_ldisc.tty = tty;
	tty->ldisc = &tty->lx_ldisc;
	tty->termios.c_line = (cc_t)ops->num;
	if (ops->open)
		ret = ops->open(tty);
	if (!ret)
		set_bit(TTY_LDISC_OPEN, &tty->flags);
	return ret;
}

/* Closes tty's discipline (ldisc_lock held). */
static void ldisc_close(struct tty_struct *tty)
{
	if (!test_bit(TTY_LDISC_OPEN, &tty->flags))
		return;
	clear_bit(TTY_LDISC_OPEN, &tty->flags);
	clear_bit(TTY_DO_WRITE_WAKEUP, &tty->flags);
	if (tty->ldisc->ops->close)
		tty->ldisc->ops->close(tty);
	tty->disc_data = NULL;
}

int tty_set_ldisc(struct tty_struct *tty, int disc)
{
	struct tty_ldisc_ops *old, *new;
	int ret;

	might_sleep();
	if (disc < N_TTY || disc >= NR_LDISCS)
		return -EINVAL;
	mutex_lock(&tty_mutex);
	new = ldiscs[disc];
	mutex_unlock(&tty_mutex);
	if (!new)
		return -EINVAL;
	/* what the old discipline was due to receive goes to it first */
	if (tty->port)
		flush_work(&tty->port->lx_push);
	mutex_lock(&tty->ldisc_lock);
	old = tty->ldisc->ops;
	if (old == new) {
		mutex_unlock(&tty->ldisc_lock);
		return 0;
	}
	ldisc_close(tty);
	ret = ldisc_open(tty, new);
	if (ret && ldisc_open(tty, old))
		(void)ldisc_open(tty, &n_tty_ops);
	mutex_unlock(&tty->ldisc_lock);
	return ret;
}

void tty_ldisc_flush(struct tty_struct *tty)
{
	if (tty->ldisc && tty->ldisc->ops->flush_buffer)
		tty->ldisc->ops->flush_buffer(tty);
}

/* ---- the flip buffer (tty_buffer.c) ---- */

/* Hands the port's queued bytes to its tty's discipline (the port's work). */
static void flip_push_work(struct work_struct *work)
{
	struct tty_port *port = container_of(work, struct tty_port, lx_push);
	unsigned char chars[64];
	char flags[64];

	for (;;) {
		struct tty_struct *tty;
		unsigned long irqflags;
		int n = 0;

		spin_lock_irqsave(&port->lock, irqflags);
		tty = port->tty;
		while (n < (int)sizeof(chars) && port->lx_tail != port->lx_head) {
			chars[n] = port->lx_flip[port->lx_tail];
			flags[n++] = port->lx_flags[port->lx_tail];
			port->lx_tail = (port->lx_tail + 1) % LX_TTY_FLIP_SIZE;
		}
		spin_unlock_irqrestore(&port->lock, irqflags);
		if (n == 0 || !tty)
			return;
		mutex_lock(&tty->ldisc_lock);
		if (test_bit(TTY_LDISC_OPEN, &tty->flags)) {
			struct tty_ldisc_ops *ops = tty->ldisc->ops;

			if (ops->receive_buf2)
				(void)ops->receive_buf2(tty, chars, flags, n);
			else if (ops->receive_buf)
				ops->receive_buf(tty, chars, flags, n);
		}
		mutex_unlock(&tty->ldisc_lock);
	}
}

void tty_port_init(struct tty_port *port)
{
	memset(port, 0, sizeof(*port));
	spin_lock_init(&port->lock);
	INIT_WORK(&port->lx_push, flip_push_work);
}

void tty_port_destroy(struct tty_port *port)
{
	cancel_work_sync(&port->lx_push);
}

void tty_port_link_device(struct tty_port *port, struct tty_driver *driver, unsigned int index)
{
	if (!WARN_ON(index >= driver->num))
		driver->lx_ports[index] = port;
}

int tty_insert_flip_char(struct tty_port *port, unsigned char ch, char flag)
{
	unsigned long irqflags;
	unsigned int next;
	int ret = 0;

	spin_lock_irqsave(&port->lock, irqflags);
	next = (port->lx_head + 1) % LX_TTY_FLIP_SIZE;
	if (next != port->lx_tail) {
		port->lx_flip[port->lx_head] = ch;
		port->lx_flags[port->lx_head] = flag;
		port->lx_head = next;
		ret = 1;
	} else {
		port->lx_dropped++;
	}
	spin_unlock_irqrestore(&port->lock, irqflags);
	return ret;
}

int tty_insert_flip_string(struct tty_port *port, const unsigned char *chars, size_t size)
{
	size_t i;

	for (i = 0; i < size; i++)
		if (!tty_insert_flip_char(port, chars[i], TTY_NORMAL))
			break;
	return (int)i;
}

void tty_flip_buffer_push(struct tty_port *port)
{
	schedule_work(&port->lx_push);
}

void tty_wakeup(struct tty_struct *tty)
{
	if (tty && test_bit(TTY_DO_WRITE_WAKEUP, &tty->flags) && test_bit(TTY_LDISC_OPEN, &tty->flags) &&
	    tty->ldisc->ops->write_wakeup)
		tty->ldisc->ops->write_wakeup(tty);
}

/* ---- what a discipline asks of the driver ---- */

unsigned int tty_write_room(struct tty_struct *tty)
{
	return tty->ops->write_room ? tty->ops->write_room(tty) : 2048;
}

unsigned int tty_chars_in_buffer(struct tty_struct *tty)
{
	return tty->ops->chars_in_buffer ? tty->ops->chars_in_buffer(tty) : 0;
}

void tty_driver_flush_buffer(struct tty_struct *tty)
{
	if (tty->ops->flush_buffer)
		tty->ops->flush_buffer(tty);
}

void tty_wait_until_sent(struct tty_struct *tty, long timeout)
{
	unsigned long waited = 0, limit = timeout > 0 ? (unsigned long)timeout : HZ;

	might_sleep();
	while (tty_chars_in_buffer(tty) && waited < limit) {
		msleep(1);
		waited += 1 + HZ / 1000 - 1;
	}
	if (tty->ops->wait_until_sent)
		tty->ops->wait_until_sent(tty, timeout);
}

int tty_set_termios(struct tty_struct *tty, struct ktermios *kt)
{
	struct ktermios old;

	might_sleep();
	mutex_lock(&tty->termios_rwsem);
	old = tty->termios;
	tty->termios = *kt;
	if (tty->ops->set_termios)
		tty->ops->set_termios(tty, &old);
	mutex_unlock(&tty->termios_rwsem);
	/* Linux takes the discipline with tty_ldisc_ref, which gives up while
	 * it is being changed: a discipline setting the rate from its own open
	 * or from its work is not told of it, and cannot deadlock on it */
	if (!mutex_trylock(&tty->ldisc_lock))
		return 0;
	if (test_bit(TTY_LDISC_OPEN, &tty->flags) && tty->ldisc->ops->set_termios)
		tty->ldisc->ops->set_termios(tty, &old);
	mutex_unlock(&tty->ldisc_lock);
	return 0;
}

/* ---- drivers and their /dev nodes (tty_io.c) ---- */

struct tty_driver *__tty_alloc_driver(unsigned int lines, struct module *owner, unsigned long flags)
{
	struct tty_driver *driver;

	if (!lines || lines > LX_TTY_MAX_LINES)
		return ERR_PTR(-EINVAL);
	driver = kzalloc(sizeof(*driver), GFP_KERNEL);
	if (!driver)
		return ERR_PTR(-ENOMEM);
	driver->num = lines;
	driver->owner = owner;
	driver->flags = flags;
	driver->init_termios = tty_std_termios;
	return driver;
}

void tty_driver_kref_put(struct tty_driver *driver)
{
	if (driver && !WARN_ON(driver->lx_registered))
		kfree(driver);
}

/* The device number of driver's line index. */
static __kernel_dev_t line_devt(const struct tty_driver *driver, unsigned int index)
{
	int major = driver->major ? driver->major : TTY_DEFAULT_MAJOR;
	int minor = (driver->major ? driver->minor_start : TTY_DEFAULT_MINOR + driver->minor_start) + (int)index;

	return MKDEV(major, minor);
}

/* The registered driver and line behind devt (tty_mutex held), or NULL. */
static struct tty_driver *driver_of(__kernel_dev_t devt, unsigned int *index)
{
	unsigned int i, line;

	for (i = 0; i < ARRAY_SIZE(drivers); i++) {
		if (!drivers[i])
			continue;
		for (line = 0; line < drivers[i]->num; line++)
			if (line_devt(drivers[i], line) == devt) {
				*index = line;
				return drivers[i];
			}
	}
	return NULL;
}

/* A new tty for line index of driver, with N_TTY open (tty_mutex held). */
static struct tty_struct *tty_create(struct tty_driver *driver, unsigned int index)
{
	struct tty_struct *tty = kzalloc(sizeof(*tty), GFP_KERNEL);

	if (!tty)
		return NULL;
	tty->driver = driver;
	tty->ops = driver->ops;
	tty->index = (int)index;
	tty->termios = driver->init_termios;
	tty->port = driver->lx_ports[index];
	mutex_init(&tty->ldisc_lock);
	mutex_init(&tty->termios_rwsem);
	init_waitqueue_head(&tty->lx_read_wait);
	snprintf(tty->name, sizeof(tty->name), "%s%u", driver->name, driver->name_base + index);
	(void)ldisc_open(tty, &n_tty_ops);
	return tty;
}

/* Drops file's hold on tty (calling the driver's close if it was opened);
 * the last one closes the discipline and frees the tty. */
static void tty_release_tty(struct tty_struct *tty, struct file *file, bool opened)
{
	struct tty_driver *driver = tty->driver;
	bool last;

	if (opened && tty->ops->close)
		tty->ops->close(tty, file);
	mutex_lock(&tty_mutex);
	last = --tty->count == 0;
	if (last)
		driver->lx_ttys[tty->index] = NULL;
	mutex_unlock(&tty_mutex);
	if (!last)
		return;
	if (tty->port) {
		unsigned long flags;

		spin_lock_irqsave(&tty->port->lock, flags);
		tty->port->tty = NULL;
		tty->port->lx_head = tty->port->lx_tail = 0;
		spin_unlock_irqrestore(&tty->port->lock, flags);
		cancel_work_sync(&tty->port->lx_push);
	}
	mutex_lock(&tty->ldisc_lock);
	ldisc_close(tty);
	mutex_unlock(&tty->ldisc_lock);
	if (tty->ops->cleanup)
		tty->ops->cleanup(tty);
	kfree(tty);
}

static int tty_open(struct inode *inode, struct file *file)
{
	struct tty_driver *driver;
	struct tty_struct *tty;
	unsigned int index = 0;
	int ret = 0;

	mutex_lock(&tty_mutex);
	driver = driver_of(inode->i_rdev, &index);
	if (!driver) {
		mutex_unlock(&tty_mutex);
		return -ENODEV;
	}
	tty = driver->lx_ttys[index];
	if (!tty) {
		tty = tty_create(driver, index);
		if (!tty) {
			mutex_unlock(&tty_mutex);
			return -ENOMEM;
		}
		if (driver->ops->install)
			ret = driver->ops->install(driver, tty);
		if (ret) {
			mutex_unlock(&tty_mutex);
			kfree(tty);
			return ret;
		}
		driver->lx_ttys[index] = tty;
		if (tty->port) {
			unsigned long flags;

			spin_lock_irqsave(&tty->port->lock, flags);
			tty->port->tty = tty;
			spin_unlock_irqrestore(&tty->port->lock, flags);
		}
	}
	tty->count++;
	mutex_unlock(&tty_mutex);
	file->private_data = tty;
	if (driver->ops->open)
		ret = driver->ops->open(tty, file);
	if (ret) {
		file->private_data = NULL;
		tty_release_tty(tty, file, false);
	}
	return ret;
}

static int tty_release(struct inode *inode, struct file *file)
{
	struct tty_struct *tty = file->private_data;

	if (tty)
		tty_release_tty(tty, file, true);
	return 0;
}

/* The file's tty with its discipline held: NULL if it has none open. */
static struct tty_struct *tty_lock_ldisc(struct file *file)
{
	struct tty_struct *tty = file->private_data;

	mutex_lock(&tty->ldisc_lock);
	if (!test_bit(TTY_LDISC_OPEN, &tty->flags)) {
		mutex_unlock(&tty->ldisc_lock);
		return NULL;
	}
	return tty;
}

static ssize_t tty_read(struct file *file, char __user *buf, size_t count, loff_t *ppos)
{
	unsigned char kbuf[64];
	struct tty_struct *tty = file->private_data;
	void *cookie = NULL;
	ssize_t n;

	if (!tty->ldisc->ops->read)
		return -EIO;
	/* N_TTY sleeps for data: the discipline lock is not held across its wait */
	n = tty->ldisc->ops->read(tty, file, kbuf, min(count, sizeof(kbuf)), &cookie, 0);
	if (n > 0 && copy_to_user(buf, kbuf, (size_t)n))
		return -EFAULT;
	return n;
}

static ssize_t tty_write(struct file *file, const char __user *buf, size_t count, loff_t *ppos)
{
	unsigned char kbuf[64];
	struct tty_struct *tty;
	size_t done = 0;
	ssize_t n = 0;

	while (done < count) {
		size_t chunk = min(count - done, sizeof(kbuf));

		if (copy_from_user(kbuf, buf + done, chunk))
			return done ? (ssize_t)done : -EFAULT;
		tty = tty_lock_ldisc(file);
		if (!tty)
			return -EIO;
		n = tty->ldisc->ops->write ? tty->ldisc->ops->write(tty, file, kbuf, chunk) : -EIO;
		mutex_unlock(&tty->ldisc_lock);
		if (n <= 0)
			break;
		done += (size_t)n;
		if ((size_t)n < chunk)
			break;
	}
	return done ? (ssize_t)done : n;
}

static long tty_ioctl(struct file *file, unsigned int cmd, unsigned long arg)
{
	struct tty_struct *tty = file->private_data;
	int disc, ret;

	switch (cmd) {
	case TIOCSETD:
		if (get_user(disc, (int __user *)arg))
			return -EFAULT;
		return tty_set_ldisc(tty, disc);
	case TIOCGETD:
		return put_user((int)tty->ldisc->ops->num, (int __user *)arg) ? -EFAULT : 0;
	default:
		break;
	}
	if (tty->ops->ioctl) {
		ret = tty->ops->ioctl(tty, cmd, arg);
		if (ret != -ENOIOCTLCMD)
			return ret;
	}
	tty = tty_lock_ldisc(file);
	if (!tty)
		return -EIO;
	ret = tty->ldisc->ops->ioctl ? tty->ldisc->ops->ioctl(tty, cmd, arg) : -ENOTTY;
	mutex_unlock(&tty->ldisc_lock);
	return ret == -ENOIOCTLCMD ? -ENOTTY : ret;
}

static const struct file_operations tty_fops = {
	.owner = THIS_MODULE,
	.open = tty_open,
	.release = tty_release,
	.read = tty_read,
	.write = tty_write,
	.unlocked_ioctl = tty_ioctl,
	.llseek = no_llseek,
};

int tty_register_driver(struct tty_driver *driver)
{
	unsigned int i, slot;
	int ret = 0;

	might_sleep();
	if (!driver || !driver->name || !driver->ops)
		return -EINVAL;
	mutex_lock(&tty_mutex);
	for (slot = 0; slot < ARRAY_SIZE(drivers) && drivers[slot]; slot++)
		;
	if (slot == ARRAY_SIZE(drivers)) {
		mutex_unlock(&tty_mutex);
		pr_err("tty: %s: no room for another tty driver\n", driver->name);
		return -EBUSY;
	}
	drivers[slot] = driver;
	driver->lx_registered = true;
	mutex_unlock(&tty_mutex);
	if (driver->flags & TTY_DRIVER_DYNAMIC_DEV)
		return 0;
	for (i = 0; i < driver->num && !ret; i++) {
		char name[LX_DEV_NAME_MAX + 1];

		snprintf(name, sizeof(name), "%s%u", driver->name, driver->name_base + i);
		ret = lx_dev_register(name, line_devt(driver, i), &tty_fops);
	}
	if (ret) {
		pr_err("tty: %s: cannot register its lines: %d\n", driver->name, ret);
		tty_unregister_driver(driver);
	}
	return ret;
}

void tty_unregister_driver(struct tty_driver *driver)
{
	unsigned int i;

	if (!driver || !driver->lx_registered)
		return;
	for (i = 0; i < driver->num; i++)
		lx_dev_unregister(line_devt(driver, i));
	mutex_lock(&tty_mutex);
	for (i = 0; i < ARRAY_SIZE(drivers); i++)
		if (drivers[i] == driver)
			drivers[i] = NULL;
	driver->lx_registered = false;
	mutex_unlock(&tty_mutex);
}

void lx_tty_boot(void)
{
	mutex_init(&tty_mutex);
	memset(ldiscs, 0, sizeof(ldiscs));
	memset(drivers, 0, sizeof(drivers));
	ldiscs[N_TTY] = &n_tty_ops;
}
