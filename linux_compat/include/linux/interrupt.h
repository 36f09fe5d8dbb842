/*
 * linux/interrupt.h — requesting interrupt lines and handler flags.
 *
 * linux_compat/src/irq.c; the line model is in linux_compat/irq.h.
 * - request_irq (process context, may sleep): 0, or -EINVAL (no handler, no
 *   RTOS line for irq, IRQF_SHARED without a dev_id, or a dev_id already on
 *   the line), -EBUSY (line taken and not both sides IRQF_SHARED), -ENOMEM
 *   (LX_NR_IRQ_ACTIONS handler records in use).  The line is enabled on
 *   return - the handler may run before request_irq returns - unless
 *   IRQF_NO_AUTOEN.  IRQF_TRIGGER_* flags set the trigger type.
 * - Handlers of a shared line are all called, in request order; an interrupt
 *   every handler answered IRQ_NONE is counted (lx_irq_unhandled_count).
 * - free_irq (process context): removes the (irq, dev_id) handler and
 *   returns its name, as modern kernels do (void in 2.6.33); the last one
 *   disables the line.  No handler can be running then: one CPU.
 * - enable_irq/disable_irq nest (a depth count) as in Linux; disable_irq from
 *   the line's own handler would deadlock in Linux and is reported here.
 * Threaded handlers: request_threaded_irq below; the threads are
 * statically configured tasks (linux_compat/config.h, LX_NR_IRQ_THREADS).
 */
#ifndef _LINUX_INTERRUPT_H
#define _LINUX_INTERRUPT_H

#include <linux/kernel.h>
#include <linux/types.h>
#include <linux/irqreturn.h>
#include <linux/irq.h>
#include <linux/errno.h>
#include <linux/hardirq.h>   /* as in Linux: in_irq, in_task & co. */

#define IRQF_TRIGGER_NONE	0x00000000
#define IRQF_TRIGGER_RISING	0x00000001
#define IRQF_TRIGGER_FALLING	0x00000002
#define IRQF_TRIGGER_HIGH	0x00000004
#define IRQF_TRIGGER_LOW	0x00000008
#define IRQF_TRIGGER_MASK	(IRQF_TRIGGER_HIGH | IRQF_TRIGGER_LOW | \
				 IRQF_TRIGGER_RISING | IRQF_TRIGGER_FALLING)
#define IRQF_TRIGGER_PROBE	0x00000010

#define IRQF_DISABLED		0x00000020   /* 2.6.33; handlers never nest here anyway */
#define IRQF_SAMPLE_RANDOM	0x00000040   /* 2.6.33; ignored */
#define IRQF_SHARED		0x00000080
#define IRQF_PROBE_SHARED	0x00000100
#define __IRQF_TIMER		0x00000200
#define IRQF_PERCPU		0x00000400
#define IRQF_NOBALANCING	0x00000800
#define IRQF_IRQPOLL		0x00001000
#define IRQF_ONESHOT		0x00002000
#define IRQF_NO_SUSPEND		0x00004000
#define IRQF_FORCE_RESUME	0x00008000
#define IRQF_NO_THREAD		0x00010000
#define IRQF_EARLY_RESUME	0x00020000
#define IRQF_COND_SUSPEND	0x00040000
#define IRQF_NO_AUTOEN		0x00080000
#define IRQF_NO_DEBUG		0x00100000
#define IRQF_TIMER		(__IRQF_TIMER | IRQF_NO_SUSPEND | IRQF_NO_THREAD)

typedef irqreturn_t (*irq_handler_t)(int irq, void *dev_id);

struct irqaction {
	irq_handler_t handler;
	void *dev_id;
	irq_handler_t thread_fn;
	unsigned long thread_flags;     /* bit 0: the thread is to run (IRQTF_RUNTHREAD) */
	int lx_thread;                  /* ev3lx: its IRQ thread's index, -1 without one */
	struct irqaction *next;
	unsigned int irq;
	unsigned int flags;
	const char *name;
};

/* Attaches handler to irq (see above).  Process context. */
int request_irq(unsigned int irq, irq_handler_t handler, unsigned long flags,
		const char *name, void *dev);

/* request_irq with a thread function (kernel/irq/manage.c): handler runs in
 * interrupt context and returns IRQ_WAKE_THREAD to run thread_fn in the
 * IRQ's kernel thread (a task of its own, process context: it may sleep);
 * handler NULL wakes the thread on every interrupt and then requires
 * IRQF_ONESHOT (-EINVAL otherwise, as Linux).  With IRQF_ONESHOT the line
 * stays masked from the interrupt until thread_fn returns.  -ENOMEM when
 * all LX_NR_IRQ_THREADS threads are taken; on a shared line every handler
 * must agree on IRQF_ONESHOT (-EBUSY). */
int request_threaded_irq(unsigned int irq, irq_handler_t handler, irq_handler_t thread_fn,
			 unsigned long flags, const char *name, void *dev);

/* Runs the thread of the (irq, dev_id) handler as if its handler had
 * returned IRQ_WAKE_THREAD.  Any context. */
void irq_wake_thread(unsigned int irq, void *dev_id);

struct device;

/* request_threaded_irq whose free_irq runs when dev's driver unbinds (or its
 * probe fails); devname NULL names the line after dev. */
int devm_request_threaded_irq(struct device *dev, unsigned int irq, irq_handler_t handler,
			      irq_handler_t thread_fn, unsigned long irqflags, const char *devname,
			      void *dev_id);
static inline int devm_request_irq(struct device *dev, unsigned int irq, irq_handler_t handler,
				   unsigned long irqflags, const char *devname, void *dev_id)
{
	return devm_request_threaded_irq(dev, irq, handler, NULL, irqflags, devname, dev_id);
}
/* Frees a devm-requested IRQ now (reported if dev does not manage it). */
void devm_free_irq(struct device *dev, unsigned int irq, void *dev_id);

/* Detaches the (irq, dev_id) handler; returns its name, or NULL (with a warning) if absent. */
const void *free_irq(unsigned int irq, void *dev_id);

/* Masks irq (nesting) and waits for its handler: process or other-IRQ context. */
void disable_irq(unsigned int irq);
/* Masks irq (nesting) without waiting: any context, also its own handler. */
void disable_irq_nosync(unsigned int irq);
/* Undoes one disable_irq; warns if irq is not disabled.  Any context. */
void enable_irq(unsigned int irq);
/* Waits until no handler of irq runs: with one CPU, only checks the caller is not one. */
void synchronize_irq(unsigned int irq);

/* Wake-up sources: ev3lx has no suspend, so these only succeed. */
static inline int irq_set_irq_wake(unsigned int irq, unsigned int on)
{
	(void)irq;
	(void)on;
	return 0;
}
#define enable_irq_wake(irq)	irq_set_irq_wake((irq), 1)
#define disable_irq_wake(irq)	irq_set_irq_wake((irq), 0)

#endif /* _LINUX_INTERRUPT_H */
