/*
 * context.c — tracking of Linux contexts and the might_sleep check.
 *
 * Uniprocessor: a task in an atomic section cannot be preempted by another
 * task (dispatching is disabled) and interrupts return balanced, so one set
 * of counters describes the CPU.  Only the outermost atomic section opened
 * by a task touches the dispatcher.
 *
 * With LX_DEBUG_ATOMIC_SLEEP the depths opened in task and in interrupt
 * context, and of spin locks among them, are kept apart, so that a report
 * can say what forbids sleeping; every section asks the RTOS which context
 * it is in.  Without it there is one preempt count, as in Linux: a section
 * costs a counter update, and the context is asked only by the outermost
 * section opened with interrupts enabled (whether it may call dis_dsp).
 */
#include <linux/kernel.h>
#include <linux/string.h>
#include <linux_compat/context.h>
#include <linux_compat/report.h>
#include <kernel.h>
#include <linux_compat/platform.h>


/* The CPU's context state (linux_compat/context.h; the production build's
 * inline spin_lock_irqsave updates its counters directly). */
struct lx_context_state lx_ctx;

/* Forgets all tracked state. */
void lx_context_reset(void)
{
	memset(&lx_ctx, 0, sizeof(lx_ctx));
}

/* Records that a Linux handler for irq starts. */
void lx_irq_enter(int irq)
{
	if (lx_ctx.irq_depth < LX_IRQ_NEST_MAX)
		lx_ctx.irq_stack[lx_ctx.irq_depth] = irq;
	lx_ctx.irq_depth++;
}

/* Records that the innermost Linux handler returned. */
void lx_irq_exit(void)
{
	if (lx_ctx.irq_depth == 0) {
		lx_report("unbalanced lx_irq_exit", NULL, 0, "no IRQ handler is running");
		return;
	}
	lx_ctx.irq_depth--;
}

/* The IRQ whose handler is running, or -1. */
int lx_current_irq(void)
{
	if (lx_ctx.irq_depth == 0)
		return -1;
	return lx_ctx.irq_depth <= LX_IRQ_NEST_MAX ? lx_ctx.irq_stack[lx_ctx.irq_depth - 1] : -1;
}

/* Records that a timer callback starts (an hrtimer's: timer is the running hrtimer). */
void lx_timer_callback_enter(bool hrtimer, const void *timer)
{
	if (hrtimer) {
		lx_ctx.hrtimer_cb++;
		lx_ctx.running_hrtimer = timer;
	} else {
		lx_ctx.timer_cb++;
	}
}

/* Records that the running timer callback returned (hrtimer first, as nesting allows). */
void lx_timer_callback_exit(void)
{
	if (lx_ctx.hrtimer_cb > 0) {
		lx_ctx.hrtimer_cb--;
		lx_ctx.running_hrtimer = NULL;
	} else if (lx_ctx.timer_cb > 0) {
		lx_ctx.timer_cb--;
	}
}

/* The hrtimer whose callback runs now, or NULL. */
const void *lx_running_hrtimer(void)
{
	return lx_ctx.running_hrtimer;
}

#if LX_DEBUG_ATOMIC_SLEEP
/* Opens an atomic section; in a task the outermost one disables dispatching. */
void lx_atomic_enter(bool spinlock)
{
	if (sns_ctx()) {
		lx_ctx.isr_atomic++;
		if (spinlock)
			lx_ctx.isr_spin++;
		return;
	}
	if (lx_ctx.task_atomic++ == 0) {
		/* With the CPU or interrupts locked, no dispatch can happen (and HRP2
		 * forbids service calls under SIL_LOC_INT). */
		lx_ctx.dispatch_disabled_by_us = !sns_loc() && lx_ctx.irqs_off == 0 && !sns_dsp();
		if (lx_ctx.dispatch_disabled_by_us)
			(void)dis_dsp();
	}
	if (spinlock)
		lx_ctx.task_spin++;
}

/* Closes an atomic section; the outermost one in a task re-enables dispatching. */
void lx_atomic_exit(bool spinlock)
{
	if (sns_ctx()) {
		if (lx_ctx.isr_atomic == 0) {
			lx_report("unbalanced unlock", NULL, 0, "no atomic section open in interrupt context");
			return;
		}
		lx_ctx.isr_atomic--;
		if (spinlock && lx_ctx.isr_spin > 0)
			lx_ctx.isr_spin--;
		return;
	}
	if (lx_ctx.task_atomic == 0) {
		lx_report("unbalanced unlock", NULL, 0, "no atomic section open in task context");
		return;
	}
	if (spinlock && lx_ctx.task_spin > 0)
		lx_ctx.task_spin--;
	if (--lx_ctx.task_atomic == 0 && lx_ctx.dispatch_disabled_by_us) {
		lx_ctx.dispatch_disabled_by_us = false;
		(void)ena_dsp();
	}
}

/* Atomic depth of the current context. */
unsigned int lx_preempt_count(void)
{
	return sns_ctx() ? lx_ctx.isr_atomic : lx_ctx.task_atomic;
}

/* Counts one local_irq_save/disable level. */
void lx_irqs_off_enter(void)
{
	lx_ctx.irqs_off++;
}

/* Uncounts one local_irq_restore/enable level. */
void lx_irqs_off_exit(void)
{
	if (lx_ctx.irqs_off > 0)
		lx_ctx.irqs_off--;
}

/* Interrupts just masked: one local_irq_save level, then a spin lock's atomic section. */
void lx_irqs_off_atomic_enter(void)
{
	lx_irqs_off_enter();
	lx_atomic_enter(true);
}

/* The spin lock's atomic section ends, then the local_irq_save level. */
void lx_irqs_off_atomic_exit(void)
{
	lx_atomic_exit(true);
	lx_irqs_off_exit();
}

#else /* !LX_DEBUG_ATOMIC_SLEEP */

/* Opens an atomic section; the outermost one, in a task with interrupts enabled, disables dispatching. */
void lx_atomic_enter(bool spinlock)
{
	(void)spinlock;
	if (lx_ctx.preempt++ != 0)
		return;
	/* With interrupts or the CPU locked no dispatch can happen (and HRP2
	 * forbids service calls under SIL_LOC_INT); an interrupt cannot dispatch. */
	lx_ctx.dispatch_disabled_by_us = lx_ctx.irqs_off == 0 && !sns_ctx() && !sns_loc() && !sns_dsp();
	if (lx_ctx.dispatch_disabled_by_us)
		(void)dis_dsp();
}

/* Closes an atomic section; the outermost one re-enables dispatching if it disabled it. */
void lx_atomic_exit(bool spinlock)
{
	(void)spinlock;
	if (lx_ctx.preempt == 0) {
		lx_report("unbalanced unlock", NULL, 0, "no atomic section is open");
		return;
	}
	if (--lx_ctx.preempt == 0 && lx_ctx.dispatch_disabled_by_us) {
		lx_ctx.dispatch_disabled_by_us = false;
		(void)ena_dsp();
	}
}

/* Atomic sections open (in an interrupt: with those of what it interrupted, as Linux counts). */
unsigned int lx_preempt_count(void)
{
	return lx_ctx.preempt;
}

/* Counts one local_irq_save/disable level. */
void lx_irqs_off_enter(void)
{
	lx_ctx.irqs_off++;
}

/* Uncounts one local_irq_restore/enable level. */
void lx_irqs_off_exit(void)
{
	if (lx_ctx.irqs_off > 0)
		lx_ctx.irqs_off--;
}

/* Interrupts just masked: one local_irq_save level and an atomic section. */
void lx_irqs_off_atomic_enter(void)
{
	lx_irqs_off_atomic_enter_up();
}

/* The atomic section ends, then the local_irq_save level (interrupts still masked). */
void lx_irqs_off_atomic_exit(void)
{
	lx_atomic_exit(true);
	if (lx_ctx.irqs_off > 0)
		lx_ctx.irqs_off--;
}
#endif /* LX_DEBUG_ATOMIC_SLEEP */

/* True in interrupt context (ISRs, handlers, timer callbacks). */
bool lx_in_interrupt(void)
{
	return sns_ctx() || lx_ctx.irq_depth > 0 || lx_ctx.hrtimer_cb > 0 || lx_ctx.timer_cb > 0;
}

/* True in hard-IRQ context: a Linux handler, an hrtimer callback, or an ISR
 * outside a timer_list callback (which Linux runs as a softirq). */
bool lx_in_hardirq(void)
{
	return lx_ctx.irq_depth > 0 || lx_ctx.hrtimer_cb > 0 || (sns_ctx() && lx_ctx.timer_cb == 0);
}

/* True in softirq context: a timer_list callback is running. */
bool lx_in_softirq(void)
{
	return lx_ctx.timer_cb > 0;
}

/* True if the calling code must not sleep. */
bool lx_in_atomic(void)
{
#if LX_DEBUG_ATOMIC_SLEEP
	/* The context is asked once: outside interrupt context the depth is the task's. */
	if (lx_in_interrupt())
		return true;
	return lx_ctx.task_atomic > 0 || lx_ctx.irqs_off > 0 || sns_loc() || sns_dsp();
#else
	return lx_ctx.preempt > 0 || lx_ctx.irqs_off > 0 || lx_in_interrupt() || sns_loc() || sns_dsp();
#endif
}

/* True with interrupts masked by linux_compat or by the CPU lock. */
bool lx_irqs_masked(void)
{
	return lx_ctx.irqs_off > 0 || sns_loc();
}

/* Linux's irqs_disabled: masked, or in hard-IRQ context (where Linux runs
 * every handler and hrtimer callback with local interrupts off since 2.6.35). */
bool lx_irqs_disabled(void)
{
	return lx_irqs_masked() || lx_in_hardirq();
}

/* Appends ", text" (or just text if buf is empty) to buf, bounded. */
static void append_reason(char *buf, unsigned int len, const char *text)
{
	size_t used = strlen(buf);

	if (used + 1 >= len)
		return;
	snprintf(buf + used, len - used, "%s%s", used ? ", " : "", text);
}

/* Describes why the caller may not sleep; false (buf "task") if it may. */
bool lx_context_forbids_sleep(char *buf, unsigned int len)
{
	char item[48];
#if LX_DEBUG_ATOMIC_SLEEP
	unsigned int spin, atomic;
#endif

	if (buf == NULL || len == 0)
		return lx_in_atomic();
	buf[0] = '\0';
	if (lx_ctx.hrtimer_cb > 0)
		append_reason(buf, len, "hrtimer callback");
	if (lx_ctx.timer_cb > 0)
		append_reason(buf, len, "timer callback");
	if (lx_ctx.irq_depth > 0) {
		snprintf(item, sizeof(item), "hard IRQ %d", lx_current_irq());
		append_reason(buf, len, item);
	}
	if (sns_ctx() && buf[0] == '\0') {
		lx_platform_describe_interrupt(item, sizeof(item));
		append_reason(buf, len, item);
	}
#if LX_DEBUG_ATOMIC_SLEEP
	spin = sns_ctx() ? lx_ctx.isr_spin : lx_ctx.task_spin;
	atomic = lx_preempt_count();
	if (spin > 0)
		append_reason(buf, len, "spinlock held");
	if (atomic > spin)
		append_reason(buf, len, "preemption disabled");
#else
	if (lx_ctx.preempt > 0)
		append_reason(buf, len, "spinlock held or preemption disabled");
#endif
	if (lx_ctx.irqs_off > 0)
		append_reason(buf, len, "interrupts disabled");
	else if (sns_loc())
		append_reason(buf, len, "CPU locked");
	if (buf[0] == '\0' && sns_dsp())
		append_reason(buf, len, "dispatching disabled");
	if (buf[0] == '\0') {
		snprintf(buf, len, "task");
		return false;
	}
	return true;
}

/* Reports a sleeping call from a context that may not sleep; true if sleeping is legal. */
bool lx_might_sleep_check(const char *what, const char *file, int line)
{
	char why[128];

	/* The common case costs a few flag tests; the reason is only put into
	 * words when there is something to report. */
	if (!lx_in_atomic() || !lx_context_forbids_sleep(why, sizeof(why)))
		return true;
	lx_report("sleeping function called from invalid context", file, line,
		  "%s; context: %s", what != NULL ? what : "?", why);
	return false;
}
