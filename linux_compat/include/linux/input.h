/*
 * linux/input.h — the input core (Linux 6.1's include/linux/input.h and
 * uapi/linux/input.h), implemented by linux_compat/src/input.c with evdev:
 * every registered device is /dev/input/event<n> (major 13, minor 64 + n),
 * read as user space reads an event device, and /sys/class/input/input<n>.
 *
 * As in Linux: an event reaches readers only if the device declared it
 * (input_set_capability or the bitmaps); a key or switch event only when its
 * state changes (value 2, autorepeat, only while the key is down); events
 * are held until SYN_REPORT and passed as one packet, a SYN_REPORT with
 * nothing before it is dropped.  Each reader (open file) has its own queue of
 * LX_EVDEV_BUFFER events; when it is full, what it holds is dropped and a
 * SYN_DROPPED starts the queue (evdev's rule).  Times are the monotonic
 * clock (the virtual clock on the host; evdev's default is CLOCK_REALTIME,
 * which the RTOS does not have), the packet's time when it is passed.
 * input_event and the input_report_* calls may be called in any context.
 */
#ifndef _LINUX_INPUT_H
#define _LINUX_INPUT_H

#include <linux/types.h>
#include <linux/bitops.h>
#include <linux/device.h>
#include <linux/list.h>
#include <linux/mod_devicetable.h>
#include <linux/spinlock.h>
#include <linux/wait.h>
#include <linux/ioctl.h>
#include <linux/input-event-codes.h>

/* The event record read from /dev/input/event<n> (the kernel's layout). */
struct input_event {
	unsigned long __sec;
	unsigned long __usec;
	__u16 type;
	__u16 code;
	__s32 value;
};
#define input_event_sec  __sec
#define input_event_usec __usec

#define EV_VERSION		0x010001

struct input_id {
	__u16 bustype;
	__u16 vendor;
	__u16 product;
	__u16 version;
};

#define BUS_PCI			0x01
#define BUS_USB			0x03
#define BUS_BLUETOOTH		0x05
#define BUS_VIRTUAL		0x06
#define BUS_I2C			0x18
#define BUS_HOST		0x19
#define BUS_SPI			0x1C

/* evdev's ioctls (uapi/linux/input.h) that linux_compat's event devices answer. */
#define EVIOCGVERSION		_IOR('E', 0x01, int)
#define EVIOCGID		_IOR('E', 0x02, struct input_id)
#define EVIOCGNAME(len)		_IOC(_IOC_READ, 'E', 0x06, len)
#define EVIOCGPHYS(len)		_IOC(_IOC_READ, 'E', 0x07, len)
#define EVIOCGKEY(len)		_IOC(_IOC_READ, 'E', 0x18, len)
#define EVIOCGSW(len)		_IOC(_IOC_READ, 'E', 0x1b, len)
#define EVIOCGBIT(ev, len)	_IOC(_IOC_READ, 'E', 0x20 + (ev), len)

/* Events one packet may hold before it is passed on with a SYN_REPORT. */
#define LX_INPUT_MAX_VALS	16
/* Events each reader's queue holds (a power of two, as evdev's). */
#define LX_EVDEV_BUFFER		64
/* Input devices registered at once (event0 .. event<n-1>). */
#define LX_INPUT_MAX_DEVICES	8

struct input_value {
	__u16 type;
	__u16 code;
	__s32 value;
};

struct input_dev {
	const char *name;
	const char *phys;
	const char *uniq;
	struct input_id id;

	unsigned long propbit[BITS_TO_LONGS(INPUT_PROP_CNT)];
	unsigned long evbit[BITS_TO_LONGS(EV_CNT)];
	unsigned long keybit[BITS_TO_LONGS(KEY_CNT)];
	unsigned long relbit[BITS_TO_LONGS(REL_CNT)];
	unsigned long absbit[BITS_TO_LONGS(ABS_CNT)];
	unsigned long mscbit[BITS_TO_LONGS(MSC_CNT)];
	unsigned long ledbit[BITS_TO_LONGS(LED_CNT)];
	unsigned long sndbit[BITS_TO_LONGS(SND_CNT)];
	unsigned long ffbit[BITS_TO_LONGS(FF_CNT)];
	unsigned long swbit[BITS_TO_LONGS(SW_CNT)];

	unsigned long key[BITS_TO_LONGS(KEY_CNT)];   /* keys down now */
	unsigned long led[BITS_TO_LONGS(LED_CNT)];
	unsigned long snd[BITS_TO_LONGS(SND_CNT)];
	unsigned long sw[BITS_TO_LONGS(SW_CNT)];
	int abs[ABS_CNT];                            /* ev3lx: each axis's last value */

	int (*open)(struct input_dev *dev);
	void (*close)(struct input_dev *dev);

	struct device dev;
	unsigned int users;

	spinlock_t event_lock;
	struct input_value vals[LX_INPUT_MAX_VALS];  /* the packet being built */
	unsigned int num_vals;
	struct list_head lx_clients;    /* ev3lx: open event files */
	wait_queue_head_t lx_wait;      /* ev3lx: their readers */
	int lx_minor;                   /* ev3lx: event<n>, -1 while unregistered */
	bool lx_registered;
	bool lx_devres;                 /* ev3lx: from devm_input_allocate_device */
};
#define to_input_dev(d) container_of(d, struct input_dev, dev)

/* Allocates a device (class "input"): it, or NULL.  Process context. */
struct input_dev *input_allocate_device(void);
/* The same, freed (and unregistered) when dev's driver unbinds. */
struct input_dev *devm_input_allocate_device(struct device *dev);
/* Frees a device that was never registered (a registered one is reported). */
void input_free_device(struct input_dev *dev);
/* Registers dev: /sys/class/input/input<n> and /dev/input/event<n>; 0,
 * -EINVAL (NULL, or registered already), -ENFILE (all LX_INPUT_MAX_DEVICES
 * taken), or device_add's error.  EV_SYN is always set.  Process context. */
int __must_check input_register_device(struct input_dev *dev);
/* Unregisters dev (its readers get -ENODEV) and drops the allocation's
 * reference (not for devm devices, freed on unbind).  Process context. */
void input_unregister_device(struct input_dev *dev);

/* Declares that dev can generate event type/code. */
void input_set_capability(struct input_dev *dev, unsigned int type, unsigned int code);
/* Reports an event (dropped unless declared; keys and switches on change). */
void input_event(struct input_dev *dev, unsigned int type, unsigned int code, int value);

static inline void input_report_key(struct input_dev *dev, unsigned int code, int value)
{
	input_event(dev, EV_KEY, code, !!value);
}
static inline void input_report_rel(struct input_dev *dev, unsigned int code, int value)
{
	input_event(dev, EV_REL, code, value);
}
static inline void input_report_abs(struct input_dev *dev, unsigned int code, int value)
{
	input_event(dev, EV_ABS, code, value);
}
static inline void input_report_switch(struct input_dev *dev, unsigned int code, int value)
{
	input_event(dev, EV_SW, code, !!value);
}
static inline void input_sync(struct input_dev *dev)
{
	input_event(dev, EV_SYN, SYN_REPORT, 0);
}

static inline void *input_get_drvdata(struct input_dev *dev)
{
	return dev_get_drvdata(&dev->dev);
}
static inline void input_set_drvdata(struct input_dev *dev, void *data)
{
	dev_set_drvdata(&dev->dev, data);
}
static inline struct input_dev *input_get_device(struct input_dev *dev)
{
	if (dev)
		get_device(&dev->dev);
	return dev;
}
static inline void input_put_device(struct input_dev *dev)
{
	if (dev)
		put_device(&dev->dev);
}

/* The input class (/sys/class/input). */
extern struct class input_class;

#endif /* _LINUX_INPUT_H */
