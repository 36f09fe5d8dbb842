/*
 * linux_compat/context.h — which Linux context the calling code is in, and
 * the might_sleep check built on it.
 *
 * Contexts linux_compat tracks on top of the RTOS's own (sns_ctx, sns_loc):
 *   - hard IRQ:         B2's IRQ layer brackets each Linux handler with
 *                       lx_irq_enter(irq) / lx_irq_exit();
 *   - hrtimer callback: the hrtimer engine brackets each callback;
 *   - timer callback:   the timer_list engine brackets each callback;
 *   - atomic sections:  spin locks and preempt_disable (atomic depth);
 *   - irqs disabled:    local_irq_save/disable and spin_lock_irq*.
 * Sleeping is legal only in task context outside all of these.
 * How much is tracked, and whether might_sleep reports, is set by
 * LX_DEBUG_ATOMIC_SLEEP (linux_compat/debug.h).
 */
#ifndef _LINUX_COMPAT_CONTEXT_H
#define _LINUX_COMPAT_CONTEXT_H

#include <stdbool.h>
#include <linux/compiler_types.h>
#include <linux_compat/debug.h>

/* A Linux interrupt handler for irq is about to run (interrupt context). */
void lx_irq_enter(int irq);
/* The handler lx_irq_enter announced has returned. */
void lx_irq_exit(void);
/* The Linux IRQ number whose handler is running, or -1. */
int lx_current_irq(void);

/* The hrtimer/timer_list engines: the callback of timer starts / ends
 * (for an hrtimer, timer is its struct hrtimer *: lx_running_hrtimer()). */
void lx_timer_callback_enter(bool hrtimer, const void *timer);
void lx_timer_callback_exit(void);
/* The hrtimer callback running now (its struct hrtimer *), or NULL. */
const void *lx_running_hrtimer(void);

/*
 * Atomic sections (spin locks when spinlock is true, else preempt_disable):
 * in a task, the first level disables dispatching (dis_dsp, unless the CPU
 * or interrupts are locked already, which excludes dispatching anyway), so
 * no other task runs until the last level ends; in an ISR only the depth is
 * counted.
 */
void lx_atomic_enter(bool spinlock);
void lx_atomic_exit(bool spinlock);
/* Depth of atomic sections (spin locks + preempt_disable) in the current context. */
unsigned int lx_preempt_count(void);

/* Interrupt-disabled sections opened by linux_compat (local_irq_save...). */
void lx_irqs_off_enter(void);
void lx_irqs_off_exit(void);
/* spin_lock_irqsave's bookkeeping in one call, interrupts just masked by the
 * caller: lx_irqs_off_enter then lx_atomic_enter(true); and its undoing,
 * lx_atomic_exit(true) then lx_irqs_off_exit, before the caller unmasks. */
void lx_irqs_off_atomic_enter(void);
void lx_irqs_off_atomic_exit(void);

/* Forgets all tracked state (at boot: a fresh system has no locks held). */
void lx_context_reset(void);

/* True if the calling code is in interrupt context (ISR, hrtimer/timer callback, handler). */
bool lx_in_interrupt(void);
/* True if the calling code must not sleep (interrupt, atomic section, irqs off, CPU locked). */
bool lx_in_atomic(void);
/* True in hard-IRQ context (Linux handler, hrtimer callback, ISR not running a timer_list callback). */
bool lx_in_hardirq(void);
/* True in softirq context (a timer_list callback runs). */
bool lx_in_softirq(void);
/* True with interrupts masked by linux_compat or by the RTOS CPU lock. */
bool lx_irqs_masked(void);
/* Linux's irqs_disabled(): interrupts masked, or hard-IRQ context. */
bool lx_irqs_disabled(void);

/*
 * Writes why the caller may not sleep into buf ("hrtimer callback", "hard IRQ 47",
 * "spinlock held", ...) and returns true; returns false (buf = "task") if it may.
 */
bool lx_context_forbids_sleep(char *buf, unsigned int len);

/*
 * The might_sleep check: if the caller may not sleep, reports
 * "sleeping function called from invalid context: <what> at <file>:<line> (<context>)"
 * and returns false; returns true if sleeping is legal.  file may be NULL.
 */
bool lx_might_sleep_check(const char *what, const char *file, int line);

#define LX_IRQ_NEST_MAX	16

/* What context.c tracks of the one CPU (see there). */
struct lx_context_state {
#if LX_DEBUG_ATOMIC_SLEEP
	unsigned int task_atomic;      /* atomic sections opened by the running task */
	unsigned int task_spin;        /* ... of which spin locks */
	unsigned int isr_atomic;       /* atomic sections opened in interrupt context */
	unsigned int isr_spin;
#else
	unsigned int preempt;          /* atomic sections open, in all contexts */
#endif
	bool dispatch_disabled_by_us;  /* the outermost section called dis_dsp */
	unsigned int irqs_off;         /* local_irq_save/disable nesting */
	int irq_stack[LX_IRQ_NEST_MAX];
	unsigned int irq_depth;
	unsigned int hrtimer_cb;       /* hrtimer callbacks running (nesting: 0 or 1) */
	unsigned int timer_cb;         /* timer_list callbacks running */
	const void *running_hrtimer;
};
extern struct lx_context_state lx_ctx;

#if !LX_DEBUG_ATOMIC_SLEEP
/* Interrupts just masked: one local_irq_save level and an atomic section (which
 * needs no dispatcher call, interrupts being masked).  Inline for the
 * production spin_lock_irqsave; lx_irqs_off_atomic_enter is the same call. */
static __always_inline void lx_irqs_off_atomic_enter_up(void)
{
	lx_ctx.irqs_off++;
	if (lx_ctx.preempt++ == 0)
		lx_ctx.dispatch_disabled_by_us = false;
}
#endif

/*
 * The annotation of a call that may sleep (Linux's might_sleep): the check
 * above with LX_DEBUG_ATOMIC_SLEEP, nothing without.  Calls that really
 * sleep use lx_might_sleep_check's result in both builds.
 */
#if LX_DEBUG_ATOMIC_SLEEP
#define lx_might_sleep(what, file, line)	((void)lx_might_sleep_check((what), (file), (line)))
#else
#define lx_might_sleep(what, file, line)	((void)0)
#endif

#endif /* _LINUX_COMPAT_CONTEXT_H */
