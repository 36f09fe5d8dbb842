/*
 * driver_common.h — the one header a hack file includes (hacks/<drv>_hack.c):
 * the Linux kernel API the reference drivers and drivers like them use, plus
 * linux_compat's own Linux-side interfaces a hack needs around the driver:
 *   - the device registry (linux_compat/devfs.h): lx_dev_open, lx_dev_read,
 *     lx_dev_write, lx_dev_ioctl, lx_dev_mmap, lx_dev_poll, lx_dev_close;
 *   - the Linux interrupt lines (linux_compat/irq.h);
 *   - the kmalloc pool's size and statistics (linux_compat/heap.h).
 * Nothing of the RTOS: the hack file is the driver's translation unit, built
 * without the kernel's headers on its include path (mk/config.mk), so a kernel
 * header reaching it is a build error in every configuration.  The hack's
 * RTOS side — its service calls and configuration — is a file of its own
 * (hacks/<drv>_svc.c, through hacks/hack_svc.h).
 * A hack defines KBUILD_MODNAME (and LX_HACK_DRIVER_INIT/_EXIT, see
 * linux/module.h), includes the driver verbatim, then this: no pr_fmt stands
 * before the driver, as under kbuild.  From here on module_init/module_exit
 * register the hack's own init and exit.
 */
#ifndef EV3LX_DRIVER_COMMON_H
#define EV3LX_DRIVER_COMMON_H

#include <linux/types.h>
#include <linux/kernel.h>
#include <linux/module.h>
#include <linux/moduleparam.h>
#include <linux/init.h>
#include <linux/errno.h>
#include <linux/string.h>
#include <linux/slab.h>
#include <linux/mm.h>
#include <linux/fs.h>
#include <linux/fcntl.h>
#include <linux/miscdevice.h>
#include <linux/poll.h>
#include <linux/uaccess.h>
#include <linux/io.h>
#include <linux/ioport.h>
#include <linux/interrupt.h>
#include <linux/irq.h>
#include <linux/gpio.h>
#include <linux/hrtimer.h>
#include <linux/ktime.h>
#include <linux/timer.h>
#include <linux/jiffies.h>
#include <linux/delay.h>
#include <linux/spinlock.h>
#include <linux/semaphore.h>
#include <linux/mutex.h>
#include <linux/completion.h>
#include <linux/wait.h>
#include <linux/workqueue.h>
#include <linux/atomic.h>
#include <asm/io.h>
#include <asm/gpio.h>
#include <asm/uaccess.h>
#include <mach/irqs.h>
#include <mach/gpio.h>
#include <mach/da8xx.h>

#include <linux_compat/devfs.h>
#include <linux_compat/irq.h>
#include <linux_compat/heap.h>
#include <linux_compat/hack.h>

#endif /* EV3LX_DRIVER_COMMON_H */
