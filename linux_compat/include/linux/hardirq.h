/*
 * linux/hardirq.h — hard-IRQ context: the predicates (linux/preempt.h) and
 * the irq_enter/irq_exit brackets of a Linux handler (linux_compat/context.h).
 */
#ifndef _LINUX_HARDIRQ_H
#define _LINUX_HARDIRQ_H

#include <linux/preempt.h>
#include <linux_compat/context.h>

#endif /* _LINUX_HARDIRQ_H */
