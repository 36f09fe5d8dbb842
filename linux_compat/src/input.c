/*
 * input.c — the input core and evdev (linux/input.h states the contract),
 * after Linux 6.1's drivers/input/input.c and evdev.c: capabilities, the
 * key/switch state that filters repeats, packets passed on SYN_REPORT to
 * every open event file, each with its own queue, read() of whole
 * struct input_event records, poll, and evdev's query ioctls.
 */
#include <linux/input.h>
#include <linux/err.h>
#include <linux/errno.h>
#include <linux/fs.h>
#include <linux/kernel.h>
#include <linux/ktime.h>
#include <linux/poll.h>
#include <linux/slab.h>
#include <linux/string.h>
#include <linux/uaccess.h>
#include <linux_compat/devfs.h>
#include <linux_compat/report.h>
#include <linux_compat/sysfs.h>

#define INPUT_MAJOR		13
#define EVDEV_MINOR_BASE	64

/* One open event file: its queue of events not yet read. */
struct evdev_client {
	struct list_head node;
	struct input_dev *dev;
	unsigned int head, tail;        /* written at head, read at tail */
	struct input_event buffer[LX_EVDEV_BUFFER];
};

static struct input_dev *event_devs[LX_INPUT_MAX_DEVICES];

static ssize_t name_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	struct input_dev *input = to_input_dev(dev);

	return sysfs_emit(buf, "%s\n", input->name ? input->name : "");
}
static DEVICE_ATTR_RO(name);

static ssize_t phys_show(struct device *dev, struct device_attribute *attr, char *buf)
{
	struct input_dev *input = to_input_dev(dev);

	return sysfs_emit(buf, "%s\n", input->phys ? input->phys : "");
}
static DEVICE_ATTR_RO(phys);

static struct attribute *input_dev_attrs[] = { &dev_attr_name.attr, &dev_attr_phys.attr, NULL };
ATTRIBUTE_GROUPS(input_dev);

struct class input_class = { .name = "input", .dev_groups = input_dev_groups };

/* release of every input device: frees it. */
static void input_dev_release(struct device *dev)
{
	kfree(to_input_dev(dev));
}

struct input_dev *input_allocate_device(void)
{
	struct input_dev *dev = kzalloc(sizeof(*dev), GFP_KERNEL);

	if (!dev)
		return NULL;
	device_initialize(&dev->dev);
	dev->dev.class = &input_class;
	dev->dev.release = input_dev_release;
	spin_lock_init(&dev->event_lock);
	INIT_LIST_HEAD(&dev->lx_clients);
	init_waitqueue_head(&dev->lx_wait);
	dev->lx_minor = -1;
	return dev;
}

void input_free_device(struct input_dev *dev)
{
	if (!dev)
		return;
	if (dev->lx_registered) {
		lx_report("input_free_device of a registered device", __FILE__, __LINE__,
			  "%s: unregister it instead", dev->name ? dev->name : dev_name(&dev->dev));
		return;
	}
	if (dev->lx_devres) {
		lx_report("input_free_device of a devm device", __FILE__, __LINE__,
			  "%s: it is freed when its driver unbinds", dev->name ? dev->name : "(unnamed)");
		return;
	}
	put_device(&dev->dev);
}

/* devres release of devm_input_allocate_device: unregisters and frees. */
static void devm_input_release(struct device *owner, void *res)
{
	struct input_dev *dev = *(struct input_dev **)res;

	dev->lx_devres = false;
	if (dev->lx_registered)
		input_unregister_device(dev);   /* drops the allocation's reference */
	else
		put_device(&dev->dev);
}

struct input_dev *devm_input_allocate_device(struct device *owner)
{
	struct input_dev **res, *dev;

	res = devres_alloc(devm_input_release, sizeof(*res), GFP_KERNEL);
	if (!res)
		return NULL;
	dev = input_allocate_device();
	if (!dev) {
		devres_free(res);
		return NULL;
	}
	dev->dev.parent = owner;
	dev->lx_devres = true;
	*res = dev;
	devres_add(owner, res);
	return dev;
}

/* The bitmap of event type type and its highest code, or NULL. */
static unsigned long *type_bits(struct input_dev *dev, unsigned int type, unsigned int *max)
{
	switch (type) {
	case EV_KEY: *max = KEY_MAX; return dev->keybit;
	case EV_REL: *max = REL_MAX; return dev->relbit;
	case EV_ABS: *max = ABS_MAX; return dev->absbit;
	case EV_MSC: *max = MSC_MAX; return dev->mscbit;
	case EV_SW:  *max = SW_MAX;  return dev->swbit;
	case EV_LED: *max = LED_MAX; return dev->ledbit;
	case EV_SND: *max = SND_MAX; return dev->sndbit;
	case EV_FF:  *max = FF_MAX;  return dev->ffbit;
	default: return NULL;
	}
}

void input_set_capability(struct input_dev *dev, unsigned int type, unsigned int code)
{
	unsigned long *bits;
	unsigned int max;

	if (type == EV_SYN || type == EV_REP || type == EV_PWR) {
		__set_bit(type, dev->evbit);
		return;
	}
	bits = type_bits(dev, type, &max);
	if (!bits || code > max) {
		pr_err("input_set_capability: unknown type %u (code %u)\n", type, code);
		return;
	}
	__set_bit(code, bits);
	__set_bit(type, dev->evbit);
}

/* Appends ev to client's queue; a full queue keeps a SYN_DROPPED and the
 * newest event only (evdev's __pass_event).  event_lock held. */
static void client_push(struct evdev_client *client, const struct input_event *ev)
{
	const unsigned int mask = LX_EVDEV_BUFFER - 1;

	client->buffer[client->head] = *ev;
	client->head = (client->head + 1) & mask;
	if (client->head == client->tail) {
		client->tail = (client->head - 2) & mask;
		client->buffer[client->tail] = (struct input_event){
			.__sec = ev->__sec, .__usec = ev->__usec, .type = EV_SYN, .code = SYN_DROPPED,
		};
	}
}

/* Passes the packet in dev->vals to every open event file.  event_lock held. */
static void pass_packet(struct input_dev *dev)
{
	struct evdev_client *client;
	struct input_event ev;
	u64 now_us = ktime_to_us(ktime_get());
	unsigned int i;

	ev.__sec = (unsigned long)(now_us / USEC_PER_SEC);
	ev.__usec = (unsigned long)(now_us % USEC_PER_SEC);
	list_for_each_entry(client, &dev->lx_clients, node) {
		for (i = 0; i < dev->num_vals; i++) {
			ev.type = dev->vals[i].type;
			ev.code = dev->vals[i].code;
			ev.value = dev->vals[i].value;
			client_push(client, &ev);
		}
	}
	dev->num_vals = 0;
	if (!list_empty(&dev->lx_clients))
		wake_up_interruptible(&dev->lx_wait);
}

/* Whether the event passes on (input_get_disposition's filter); updates the
 * key, switch and axis state.  event_lock held. */
static bool event_passes(struct input_dev *dev, unsigned int type, unsigned int code, int value)
{
	switch (type) {
	case EV_KEY:
		if (value == 2)
			return test_bit(code, dev->key);
		if (!!test_bit(code, dev->key) == !!value)
			return false;
		__change_bit(code, dev->key);
		return true;
	case EV_SW:
		if (!!test_bit(code, dev->sw) == !!value)
			return false;
		__change_bit(code, dev->sw);
		return true;
	case EV_ABS:
		if (dev->abs[code] == value)
			return false;
		dev->abs[code] = value;
		return true;
	case EV_REL:
		return value != 0;
	default:
		return true;
	}
}

void input_event(struct input_dev *dev, unsigned int type, unsigned int code, int value)
{
	unsigned long flags, *bits;
	unsigned int max;

	if (!dev || type > EV_MAX || !test_bit(type, dev->evbit))
		return;
	spin_lock_irqsave(&dev->event_lock, flags);
	if (type == EV_SYN) {
		if (code == SYN_REPORT && dev->num_vals > 0) {
			dev->vals[dev->num_vals++] = (struct input_value){ EV_SYN, SYN_REPORT, 0 };
			pass_packet(dev);
		}
		spin_unlock_irqrestore(&dev->event_lock, flags);
		return;
	}
	bits = type_bits(dev, type, &max);
	if (bits && code <= max && test_bit(code, bits) && event_passes(dev, type, code, value)) {
		dev->vals[dev->num_vals++] = (struct input_value){ (u16)type, (u16)code, value };
		if (dev->num_vals >= LX_INPUT_MAX_VALS - 1) {
			/* a full packet goes on with a SYN_REPORT of its own (input.c's rule) */
			dev->vals[dev->num_vals++] = (struct input_value){ EV_SYN, SYN_REPORT, 0 };
			pass_packet(dev);
		}
	}
	spin_unlock_irqrestore(&dev->event_lock, flags);
}

/* ---- evdev ---- */

/* The open file's queue. */
static struct evdev_client *file_client(struct file *file)
{
	return file->private_data;
}

static int evdev_open(struct inode *inode, struct file *file)
{
	unsigned int minor = MINOR(inode->i_rdev) - EVDEV_MINOR_BASE;
	struct evdev_client *client;
	struct input_dev *dev;
	unsigned long flags;
	int ret;

	if (minor >= LX_INPUT_MAX_DEVICES || !event_devs[minor])
		return -ENODEV;
	dev = event_devs[minor];
	client = kzalloc(sizeof(*client), GFP_KERNEL);
	if (!client)
		return -ENOMEM;
	client->dev = input_get_device(dev);
	/* attached before the device opens, so that what open() reports reaches it (evdev's order) */
	spin_lock_irqsave(&dev->event_lock, flags);
	list_add_tail(&client->node, &dev->lx_clients);
	spin_unlock_irqrestore(&dev->event_lock, flags);
	if (dev->users++ == 0 && dev->open) {
		ret = dev->open(dev);
		if (ret) {
			dev->users--;
			spin_lock_irqsave(&dev->event_lock, flags);
			list_del(&client->node);
			spin_unlock_irqrestore(&dev->event_lock, flags);
			input_put_device(dev);
			kfree(client);
			return ret;
		}
	}
	file->private_data = client;
	return 0;
}

static int evdev_release(struct inode *inode, struct file *file)
{
	struct evdev_client *client = file_client(file);
	struct input_dev *dev = client->dev;
	unsigned long flags;

	spin_lock_irqsave(&dev->event_lock, flags);
	list_del(&client->node);
	spin_unlock_irqrestore(&dev->event_lock, flags);
	if (--dev->users == 0 && dev->close && dev->lx_registered)
		dev->close(dev);
	input_put_device(dev);
	kfree(client);
	return 0;
}

/* Takes the oldest queued event into *ev; false if none.  event_lock held. */
static bool client_pop(struct evdev_client *client, struct input_event *ev)
{
	if (client->head == client->tail)
		return false;
	*ev = client->buffer[client->tail];
	client->tail = (client->tail + 1) & (LX_EVDEV_BUFFER - 1);
	return true;
}

static ssize_t evdev_read(struct file *file, char __user *buf, size_t count, loff_t *ppos)
{
	struct evdev_client *client = file_client(file);
	struct input_dev *dev = client->dev;
	struct input_event ev;
	unsigned long flags;
	size_t done = 0;
	bool got;
	int ret;

	if (count < sizeof(ev))
		return -EINVAL;
	for (;;) {
		if (!dev->lx_registered)
			return -ENODEV;
		while (done + sizeof(ev) <= count) {
			spin_lock_irqsave(&dev->event_lock, flags);
			got = client_pop(client, &ev);
			spin_unlock_irqrestore(&dev->event_lock, flags);
			if (!got)
				break;
			if (copy_to_user(buf + done, &ev, sizeof(ev)))
				return -EFAULT;
			done += sizeof(ev);
		}
		if (done)
			return (ssize_t)done;
		if (file->f_flags & O_NONBLOCK)
			return -EAGAIN;
		ret = wait_event_interruptible(dev->lx_wait,
					       client->head != client->tail || !dev->lx_registered);
		if (ret)
			return ret;
	}
}

static __poll_t evdev_poll(struct file *file, poll_table *wait)
{
	struct evdev_client *client = file_client(file);
	struct input_dev *dev = client->dev;
	__poll_t mask;

	poll_wait(file, &dev->lx_wait, wait);
	mask = dev->lx_registered ? EPOLLOUT | EPOLLWRNORM : EPOLLHUP | EPOLLERR;
	if (client->head != client->tail)
		mask |= EPOLLIN | EPOLLRDNORM;
	return mask;
}

/* Copies a bitmap of nbits bits to user memory, at most len bytes: the bytes copied or -EFAULT. */
static long bits_to_user(const unsigned long *bits, unsigned int nbits, unsigned int len, void __user *p)
{
	unsigned int size = BITS_TO_LONGS(nbits) * (unsigned int)sizeof(long);

	if (len > size)
		len = size;
	return copy_to_user(p, bits, len) ? -EFAULT : (long)len;
}

/* Copies string s (with its NUL) to user memory, at most len bytes: the bytes copied or -EFAULT/-ENOENT. */
static long str_to_user(const char *s, unsigned int len, void __user *p)
{
	unsigned int n;

	if (!s)
		return -ENOENT;
	n = (unsigned int)strlen(s) + 1;
	if (n > len)
		n = len;
	return copy_to_user(p, s, n) ? -EFAULT : (long)n;
}

static long evdev_ioctl(struct file *file, unsigned int cmd, unsigned long arg)
{
	struct input_dev *dev = file_client(file)->dev;
	void __user *p = (void __user *)arg;
	unsigned int size = _IOC_SIZE(cmd), max, type;
	unsigned long *bits;

	if (!dev->lx_registered)
		return -ENODEV;
	switch (cmd) {
	case EVIOCGVERSION:
		return put_user(EV_VERSION, (int __user *)p);
	case EVIOCGID:
		return copy_to_user(p, &dev->id, sizeof(dev->id)) ? -EFAULT : 0;
	}
	if (_IOC_TYPE(cmd) != 'E' || _IOC_DIR(cmd) != _IOC_READ)
		return -EINVAL;
	switch (_IOC_NR(cmd)) {
	case 0x06:
		return str_to_user(dev->name, size, p);
	case 0x07:
		return str_to_user(dev->phys, size, p);
	case 0x18:
		return bits_to_user(dev->key, KEY_CNT, size, p);
	case 0x1b:
		return bits_to_user(dev->sw, SW_CNT, size, p);
	}
	if ((_IOC_NR(cmd) & ~EV_MAX) == 0x20) {
		type = _IOC_NR(cmd) & EV_MAX;
		if (type == 0)
			return bits_to_user(dev->evbit, EV_CNT, size, p);
		bits = type_bits(dev, type, &max);
		return bits ? bits_to_user(bits, max + 1, size, p) : -EINVAL;
	}
	return -EINVAL;
}

static const struct file_operations evdev_fops = {
	.open = evdev_open,
	.release = evdev_release,
	.read = evdev_read,
	.poll = evdev_poll,
	.unlocked_ioctl = evdev_ioctl,
	.llseek = no_llseek,
};

int input_register_device(struct input_dev *dev)
{
	char node[24];
	int minor, ret;

	might_sleep();
	if (!dev || dev->lx_registered)
		return -EINVAL;
	for (minor = 0; minor < LX_INPUT_MAX_DEVICES; minor++)
		if (!event_devs[minor])
			break;
	if (minor == LX_INPUT_MAX_DEVICES) {
		pr_err("input: more than %d input devices\n", LX_INPUT_MAX_DEVICES);
		return -ENFILE;
	}
	__set_bit(EV_SYN, dev->evbit);
	dev_set_name(&dev->dev, "input%d", minor);
	dev->lx_minor = minor;
	ret = device_add(&dev->dev);
	if (ret)
		return ret;
	scnprintf(node, sizeof(node), "input/event%d", minor);
	ret = lx_dev_register(node, MKDEV(INPUT_MAJOR, EVDEV_MINOR_BASE + minor), &evdev_fops);
	if (ret) {
		device_del(&dev->dev);
		return ret;
	}
	event_devs[minor] = dev;
	dev->lx_registered = true;
	pr_info("input: %s as /devices/virtual/input/%s\n", dev->name ? dev->name : "Unspecified device",
		dev_name(&dev->dev));
	return 0;
}

void input_unregister_device(struct input_dev *dev)
{
	unsigned long flags;

	might_sleep();
	if (!dev || !dev->lx_registered) {
		lx_report("input_unregister_device of a device not registered", __FILE__, __LINE__, "%s",
			  dev && dev->name ? dev->name : "(unnamed)");
		return;
	}
	spin_lock_irqsave(&dev->event_lock, flags);
	dev->lx_registered = false;
	dev->num_vals = 0;
	spin_unlock_irqrestore(&dev->event_lock, flags);
	wake_up_interruptible(&dev->lx_wait);
	lx_dev_unregister(MKDEV(INPUT_MAJOR, EVDEV_MINOR_BASE + dev->lx_minor));
	event_devs[dev->lx_minor] = NULL;
	if (dev->users && dev->close)
		dev->close(dev);
	device_del(&dev->dev);
	if (!dev->lx_devres)
		put_device(&dev->dev);
}

void lx_input_boot(void)
{
	memset(event_devs, 0, sizeof(event_devs));
	memset(&input_class, 0, sizeof(input_class));
	input_class.name = "input";
	input_class.dev_groups = input_dev_groups;
	lx_class_register_boot(&input_class);
}
