/*
 * linux/preempt.h — preemption control and context predicates.
 *
 * preempt_disable in a task disables dispatching (no other task runs;
 * interrupts still do); in an ISR it only counts.  in_interrupt/in_irq are
 * true in every non-task context: ISRs, hrtimer and timer callbacks (all of
 * which run in the tick's or a line's interrupt context).
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
#define in_irq()		lx_in_interrupt()
#define in_hardirq()		lx_in_interrupt()
#define in_softirq()		lx_in_interrupt()
#define in_serving_softirq()	0
#define in_nmi()		0
#define in_task()		(!lx_in_interrupt())
#define in_atomic()		lx_in_atomic()

#define migrate_disable()	preempt_disable()
#define migrate_enable()	preempt_enable()

#endif /* _LINUX_PREEMPT_H */
