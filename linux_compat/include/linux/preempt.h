/*
 * linux/preempt.h — preemption control and context predicates.
 *
 * preempt_disable in a task disables dispatching (no other task runs;
 * interrupts still do); in an ISR it only counts.  As in Linux, IRQ handlers
 * and hrtimer callbacks are hard-IRQ context (in_irq), timer_list callbacks
 * are softirq context (in_softirq, not in_irq); in_interrupt covers both.
 */
#ifndef _LINUX_PREEMPT_H
#define _LINUX_PREEMPT_H

#include <linux/compiler.h>
#include <linux_compat/context.h>

#define preempt_disable()		lx_atomic_enter(false)
#define preempt_enable()		lx_atomic_exit(false)
#define preempt_enable_no_resched()	lx_atomic_exit(false)
#define preempt_count()			lx_preempt_count()
#define preemptible()			(!lx_in_atomic())

#define in_interrupt()		lx_in_interrupt()
#define in_irq()		lx_in_hardirq()
#define in_hardirq()		lx_in_hardirq()
#define in_softirq()		lx_in_softirq()
#define in_serving_softirq()	lx_in_softirq()
#define in_nmi()		0
#define in_task()		(!lx_in_interrupt())
#define in_atomic()		lx_in_atomic()

#define migrate_disable()	preempt_disable()
#define migrate_enable()	preempt_enable()

#endif /* _LINUX_PREEMPT_H */
