/*
 * irq.c — Linux IRQs on statically configured RTOS interrupt lines.
 *
 * One descriptor per Linux IRQ (AINTC lines 0..100, GPIO pin IRQs after
 * them, mach/irqs.h) holds the handler list, the disable depth and the
 * trigger type.  Handler records come from a fixed pool, so request_irq and
 * free_irq take bounded time and do not touch the kmalloc pool.
 *
 * The IRQ is unmasked through its chip (struct lx_irq_chip; the machine
 * says which chip serves which IRQ) exactly while it has a handler and its
 * disable depth is 0.  List changes happen with interrupts locked, the
 * chip's operations (which may make RTOS service calls) outside that lock,
 * as TOPPERS requires.
 *
 * An interrupt that comes while its IRQ is disabled (an edge latched just
 * before disable_irq) is recorded as pending and, for an IRQ not triggered
 * by a level, replayed once when enable_irq enables it again: Linux's
 * IRQS_PENDING and check_irq_resend (kernel/irq/resend.c).  Like Linux's
 * software resend (a tasklet), the replay runs soon after, not inside
 * enable_irq: from an hrtimer due at once, in the tick's interrupt.
 */
#include <linux/bitops.h>
#include <linux/hrtimer.h>
#include <linux/interrupt.h>
#include <linux/irq.h>
#include <linux/kernel.h>
#include <linux/errno.h>
#include <linux/string.h>
#include <linux/sched.h>
#include <linux/wait.h>
#include <linux_compat/config.h>
#include <linux_compat/context.h>
#include <linux_compat/irq.h>
#include <linux_compat/machine.h>
#include <linux_compat/report.h>
#include <linux_compat/sysfs.h>
#include <kernel.h>
#include <sil.h>

/* Consecutive unanswered interrupts after which a line is disabled ("nobody cared"). */
#define LX_IRQ_NOBODY_CARED	100000U

struct lx_irq_desc {
	struct irqaction *action;   /* handlers, in request order */
	unsigned int depth;         /* disable_irq nesting */
	unsigned int type;          /* IRQ_TYPE_* as last set */
	bool in_handler;            /* its handlers are running */
	bool pending;               /* an interrupt came while disabled (IRQS_PENDING) */
	unsigned int threads_oneshot;   /* IRQ threads of IRQF_ONESHOT handlers still to finish */
	unsigned long count;        /* dispatches */
	unsigned long unhandled;    /* dispatches nobody answered */
	unsigned int unanswered_run;
};

static struct lx_irq_desc irq_descs[NR_IRQS];
static struct irqaction action_pool[LX_NR_IRQ_ACTIONS];

/* An IRQ thread: one task, bound to one threaded handler at a time. */
struct lx_irq_thread {
	struct irqaction *action;   /* its handler, NULL while free */
	bool running;               /* inside thread_fn */
	wait_queue_head_t wake;     /* the task waits here for its handler to wake it */
	wait_queue_head_t idle;     /* free_irq waits here for thread_fn to return */
};

static struct lx_irq_thread irq_threads[LX_NR_IRQ_THREADS > 0 ? LX_NR_IRQ_THREADS : 1];

/* The IRQs enable_irq queued for a replay, and the timer that replays them. */
static unsigned long resend_queued[BITS_TO_LONGS(NR_IRQS)];
static struct hrtimer resend_timer;

bool lx_irq_valid(unsigned int irq)
{
	return irq < NR_IRQS && lx_mach_irq_chip(irq) != NULL;
}

/* Lets a valid irq deliver with its trigger type.  Returns 0 or -EINVAL. */
static int line_unmask(unsigned int irq)
{
	return lx_mach_irq_chip(irq)->irq_unmask(irq, irq_descs[irq].type);
}

/* Stops a valid irq delivering. */
static void line_mask(unsigned int irq)
{
	lx_mach_irq_chip(irq)->irq_mask(irq);
}

int lx_irq_line_unmask(unsigned int irq)
{
	return lx_irq_valid(irq) ? line_unmask(irq) : -EINVAL;
}

void lx_irq_line_mask(unsigned int irq)
{
	if (lx_irq_valid(irq))
		line_mask(irq);
}

/* Marks action's thread to run and wakes it (kernel/irq/handle.c's
 * __irq_wake_thread); an IRQF_ONESHOT handler's line is held masked until the
 * thread has run.  Interrupt context, or interrupts locked. */
static void wake_thread(struct lx_irq_desc *desc, struct irqaction *action)
{
	if (action->lx_thread < 0) {
		pr_warn("IRQ %u device %s returned IRQ_WAKE_THREAD but no thread function available.\n",
			action->irq, action->name ? action->name : "?");
		return;
	}
	if (action->thread_flags & 1UL)
		return;         /* already to run: one run serves both interrupts, as in Linux */
	action->thread_flags |= 1UL;
	if (action->flags & IRQF_ONESHOT)
		desc->threads_oneshot |= 1U << action->lx_thread;
	wake_up(&irq_threads[action->lx_thread].wake);
}

bool lx_handle_irq(unsigned int irq)
{
	struct lx_irq_desc *desc = &irq_descs[irq];
	struct irqaction *action = desc->action;
	unsigned int ret = IRQ_NONE;

	if (lx_fiq_take(irq))
		return true;            /* a channel mapped to nFIQ: the FIQ handler ran (or is pending) */

	if (unlikely(!action || desc->depth)) {
		/* An edge latched just before the line was masked: enable_irq replays it. */
		if (action)
			desc->pending = true;
		desc->unhandled++;
		return false;
	}
	lx_irq_enter((int)irq);
	desc->in_handler = true;
	do {
		irqreturn_t res = action->handler((int)irq, action->dev_id);

		if (res == IRQ_WAKE_THREAD)
			wake_thread(desc, action);
		ret |= (unsigned int)res;
		action = action->next;
	} while (action);
	desc->in_handler = false;
	lx_irq_exit();
	/* IRQF_ONESHOT (kernel/irq/chip.c's cond_unmask): masked until the threads are done */
	if (desc->threads_oneshot)
		line_mask(irq);

	desc->count++;
	if (likely(ret != IRQ_NONE)) {
		desc->unanswered_run = 0;
		return true;
	}
	desc->unhandled++;
	if (++desc->unanswered_run >= LX_IRQ_NOBODY_CARED) {
		lx_report("irq: nobody cared", __FILE__, __LINE__,
			  "irq %u: %u interrupts in a row answered IRQ_NONE by every handler; "
			  "disabling it", irq, desc->unanswered_run);
		desc->depth++;
		line_mask(irq);
	}
	return false;
}

void lx_irq_dispatch(intptr_t exinf)
{
	lx_handle_irq((unsigned int)exinf);
}

void lx_irq_set_pending(unsigned int irq)
{
	SIL_PRE_LOC;

	if (irq >= NR_IRQS)
		return;
	SIL_LOC_INT();
	if (irq_descs[irq].action)
		irq_descs[irq].pending = true;
	SIL_UNL_INT();
}

/* The resend timer's callback: runs the handlers of every queued IRQ once, in interrupt context. */
static enum hrtimer_restart resend_queued_irqs(struct hrtimer *timer)
{
	unsigned long irq;

	for (irq = find_first_bit(resend_queued, NR_IRQS); irq < NR_IRQS;
	     irq = find_next_bit(resend_queued, NR_IRQS, irq + 1))
		if (test_and_clear_bit(irq, resend_queued))
			lx_handle_irq((unsigned int)irq);
	return HRTIMER_NORESTART;
}

/* A free handler record, or NULL.  Interrupts locked. */
static struct irqaction *action_alloc_locked(void)
{
	unsigned int i;

	for (i = 0; i < LX_NR_IRQ_ACTIONS; i++)
		if (!action_pool[i].handler)
			return &action_pool[i];
	return NULL;
}

/* Records a trigger type for irq if the line supports it; 0 or -EINVAL. */
static int check_type(unsigned int irq, unsigned int type)
{
	if (type & ~(unsigned int)IRQ_TYPE_SENSE_MASK)
		return -EINVAL;
	return lx_mach_irq_chip(irq)->irq_check_type(type);
}

/* The primary handler of a threaded IRQ requested without one. */
static irqreturn_t irq_default_primary_handler(int irq, void *dev_id)
{
	return IRQ_WAKE_THREAD;
}

/* Binds a free IRQ thread to action; its index or -1.  Interrupts locked. */
static int thread_bind_locked(struct irqaction *action)
{
	int i;

	for (i = 0; i < LX_NR_IRQ_THREADS; i++) {
		if (!irq_threads[i].action) {
			irq_threads[i].action = action;
			return i;
		}
	}
	return -1;
}

/* Attaches handler (and thread_fn with a thread, if not NULL) to irq:
 * request_irq's and request_threaded_irq's common part. */
static int setup_irq(unsigned int irq, irq_handler_t handler, irq_handler_t thread_fn,
		     unsigned long flags, const char *name, void *dev)
{
	struct lx_irq_desc *desc;
	struct irqaction *action, **tail;
	unsigned int type = (unsigned int)(flags & IRQF_TRIGGER_MASK);
	bool first;
	int err = 0, thread;
	SIL_PRE_LOC;

	lx_might_sleep(thread_fn ? "request_threaded_irq()" : "request_irq()", __FILE__, __LINE__);
	if (!handler || !lx_irq_valid(irq))
		return -EINVAL;
	if ((flags & IRQF_SHARED) && !dev)
		return -EINVAL;
	if (type && check_type(irq, type))
		return -EINVAL;
	desc = &irq_descs[irq];

	SIL_LOC_INT();
	for (tail = &desc->action; *tail; tail = &(*tail)->next) {
		if (!((*tail)->flags & IRQF_SHARED) || !(flags & IRQF_SHARED))
			err = -EBUSY;
		else if (type && desc->type && type != desc->type)
			err = -EBUSY;   /* Linux: "type mismatch" for a shared line */
		else if (((*tail)->flags ^ flags) & IRQF_ONESHOT)
			err = -EBUSY;   /* Linux: all handlers of a shared line agree on ONESHOT */
		else if ((*tail)->dev_id == dev)
			err = -EINVAL;
		if (err)
			break;
	}
	action = err ? NULL : action_alloc_locked();
	if (!err && !action)
		err = -ENOMEM;
	thread = -1;
	if (!err && thread_fn) {
		thread = thread_bind_locked(action);
		if (thread < 0)
			err = -ENOSPC;
	}
	first = !desc->action;
	if (!err) {
		action->handler = handler;
		action->thread_fn = thread_fn;
		action->thread_flags = 0;
		action->lx_thread = thread;
		action->dev_id = dev;
		action->next = NULL;
		action->irq = irq;
		action->flags = (unsigned int)flags;
		action->name = name;
		if (first) {
			desc->depth = (flags & IRQF_NO_AUTOEN) ? 1U : 0U;
			desc->unanswered_run = 0;
			desc->pending = false;
			if (type)
				desc->type = type;
		}
		*tail = action;
	}
	SIL_UNL_INT();

	if (err) {
		if (err == -ENOMEM)
			pr_err("request_irq %u (%s): all %d handler records in use (raise LX_NR_IRQ_ACTIONS)\n",
			       irq, name ? name : "?", LX_NR_IRQ_ACTIONS);
		if (err == -ENOSPC) {
			pr_err("request_threaded_irq %u (%s): all %d IRQ threads in use (raise LX_NR_IRQ_THREADS)\n",
			       irq, name ? name : "?", LX_NR_IRQ_THREADS);
			err = -ENOMEM;
		}
		return err;
	}
	if (first && desc->depth == 0) {
		err = line_unmask(irq);
		if (err) {
			SIL_LOC_INT();
			desc->action = NULL;
			if (thread >= 0)
				irq_threads[thread].action = NULL;
			memset(action, 0, sizeof(*action));
			SIL_UNL_INT();
		}
	}
	return err;
}

int request_irq(unsigned int irq, irq_handler_t handler, unsigned long flags,
		const char *name, void *dev)
{
	return setup_irq(irq, handler, NULL, flags, name, dev);
}

int request_threaded_irq(unsigned int irq, irq_handler_t handler, irq_handler_t thread_fn,
			 unsigned long flags, const char *name, void *dev)
{
	if (!thread_fn)
		return request_irq(irq, handler, flags, name, dev);
	if (!handler) {
		if (!(flags & IRQF_ONESHOT)) {
			pr_err("Threaded irq requested with handler=NULL and !ONESHOT for %s (irq %u)\n",
			       name ? name : "?", irq);
			return -EINVAL;
		}
		handler = irq_default_primary_handler;
	}
	return setup_irq(irq, handler, thread_fn, flags, name, dev);
}

void irq_wake_thread(unsigned int irq, void *dev_id)
{
	struct irqaction *action;
	SIL_PRE_LOC;

	if (irq >= NR_IRQS || !dev_id)
		return;
	SIL_LOC_INT();
	for (action = irq_descs[irq].action; action; action = action->next) {
		if (action->dev_id == dev_id) {
			if (action->thread_fn)
				wake_thread(&irq_descs[irq], action);
			break;
		}
	}
	SIL_UNL_INT();
}

/* Runs the handler bound to thread t once it is woken: thread_fn in process
 * context, then (IRQF_ONESHOT) unmasks the line when no other oneshot thread
 * of it is pending (kernel/irq/manage.c's irq_thread and irq_finalize_oneshot). */
void lx_irq_thread_task(intptr_t exinf)
{
	struct lx_irq_thread *t = &irq_threads[exinf];
	struct irqaction *action;
	struct lx_irq_desc *desc;
	bool unmask;
	SIL_PRE_LOC;

	for (;;) {
		wait_event(t->wake, t->action && (t->action->thread_flags & 1UL));
		SIL_LOC_INT();
		action = t->action;
		action->thread_flags &= ~1UL;
		t->running = true;
		SIL_UNL_INT();

		action->thread_fn((int)action->irq, action->dev_id);

		desc = &irq_descs[action->irq];
		SIL_LOC_INT();
		t->running = false;
		unmask = false;
		if (desc->threads_oneshot & (1U << exinf)) {
			desc->threads_oneshot &= ~(1U << exinf);
			unmask = !desc->threads_oneshot && desc->depth == 0 && desc->action;
		}
		SIL_UNL_INT();
		if (unmask)
			(void)line_unmask(action->irq);
		wake_up(&t->idle);
	}
}

/* Waits until action's thread has no run pending or running (process context). */
static void wait_thread_idle(struct irqaction *action)
{
	struct lx_irq_thread *t = &irq_threads[action->lx_thread];

	wait_event(t->idle, !t->running && !(action->thread_flags & 1UL));
}

/* The IRQ threads' IDs as the configurator gave them (cfg/ev3lx.cfg). */
static const ID irq_thread_tskids[] = {
#if LX_NR_IRQ_THREADS >= 1
	LX_IRQ_THREAD1_TSKID,
#endif
#if LX_NR_IRQ_THREADS >= 2
	LX_IRQ_THREAD2_TSKID,
#endif
#if LX_NR_IRQ_THREADS >= 3
	LX_IRQ_THREAD3_TSKID,
#endif
#if LX_NR_IRQ_THREADS >= 4
	LX_IRQ_THREAD4_TSKID,
#endif
	0	/* no thread */
};

/* The IRQ thread the calling task is, or NULL. */
static struct lx_irq_thread *current_irq_thread(void)
{
	int i;
	int tid = in_task() ? (int)current->pid : 0;

	for (i = 0; i < LX_NR_IRQ_THREADS; i++)
		if (tid == irq_thread_tskids[i])
			return &irq_threads[i];
	return NULL;
}

const void *free_irq(unsigned int irq, void *dev_id)
{
	struct lx_irq_desc *desc;
	struct irqaction *action = NULL, **link;
	const char *name = NULL;
	bool last = false;
	SIL_PRE_LOC;

	lx_might_sleep("free_irq()", __FILE__, __LINE__);
	if (irq >= NR_IRQS) {
		WARN(1, "free_irq: invalid irq %u", irq);
		return NULL;
	}
	desc = &irq_descs[irq];

	SIL_LOC_INT();
	for (link = &desc->action; *link; link = &(*link)->next) {
		if ((*link)->dev_id == dev_id) {
			action = *link;
			break;
		}
	}
	last = action && desc->action == action && !action->next;
	SIL_UNL_INT();

	if (!action) {
		WARN(1, "Trying to free already-free IRQ %u", irq);
		return NULL;
	}
	/* The last handler: stop the line before the list empties. */
	if (last && desc->depth == 0)
		line_mask(irq);

	SIL_LOC_INT();
	for (link = &desc->action; *link != action; link = &(*link)->next)
		;
	*link = action->next;
	SIL_UNL_INT();
	/* Linux's free_irq waits for the thread to finish a run already asked for */
	if (action->lx_thread >= 0)
		wait_thread_idle(action);
	SIL_LOC_INT();
	if (action->lx_thread >= 0) {
		irq_threads[action->lx_thread].action = NULL;
		desc->threads_oneshot &= ~(1U << action->lx_thread);
	}
	name = action->name;
	memset(action, 0, sizeof(*action));
	if (!desc->action) {
		desc->pending = false;
		__clear_bit(irq, resend_queued);
	}
	SIL_UNL_INT();
	return name;
}

void disable_irq_nosync(unsigned int irq)
{
	struct lx_irq_desc *desc;
	bool mask;
	SIL_PRE_LOC;

	if (irq >= NR_IRQS)
		return;
	desc = &irq_descs[irq];
	SIL_LOC_INT();
	mask = desc->depth++ == 0 && desc->action;
	SIL_UNL_INT();
	if (mask)
		line_mask(irq);
}

void synchronize_irq(unsigned int irq)
{
	struct lx_irq_thread *self = current_irq_thread();
	struct irqaction *action, *next;

	if (irq >= NR_IRQS)
		return;
	if (irq_descs[irq].in_handler && lx_current_irq() == (int)irq) {
		lx_report("synchronize_irq from the IRQ's own handler", __FILE__, __LINE__,
			  "irq %u: waiting for its own handler deadlocks in Linux", irq);
		return;
	}
	if (self && self->action && self->action->irq == irq) {
		lx_report("synchronize_irq from the IRQ's own thread", __FILE__, __LINE__,
			  "irq %u: waiting for its own threaded handler deadlocks in Linux; "
			  "use disable_irq_nosync", irq);
		return;
	}
	if (!in_task())
		return;
	/* kernel/irq/manage.c: also wait for the threaded handlers */
	for (action = irq_descs[irq].action; action; action = next) {
		next = action->next;
		if (action->lx_thread >= 0)
			wait_thread_idle(action);
	}
}

void disable_irq(unsigned int irq)
{
	if (irq < NR_IRQS && irq_descs[irq].in_handler && lx_current_irq() == (int)irq)
		lx_report("disable_irq from the IRQ's own handler", __FILE__, __LINE__,
			  "irq %u: disable_irq waits for the handler and deadlocks in Linux; "
			  "use disable_irq_nosync", irq);
	disable_irq_nosync(irq);
	if (irq < NR_IRQS && !(irq_descs[irq].in_handler && lx_current_irq() == (int)irq))
		synchronize_irq(irq);
}

void enable_irq(unsigned int irq)
{
	struct lx_irq_desc *desc;
	bool unmask = false, unbalanced = false, resend = false;
	SIL_PRE_LOC;

	if (irq >= NR_IRQS)
		return;
	desc = &irq_descs[irq];
	SIL_LOC_INT();
	if (desc->depth == 0)
		unbalanced = true;
	else
		unmask = --desc->depth == 0 && desc->action && !desc->threads_oneshot;
	if (unmask) {
		desc->unanswered_run = 0;
		/* Linux drops a pending level interrupt: the level, if still there, fires again. */
		resend = desc->pending && !(desc->type & IRQ_TYPE_LEVEL_MASK);
		desc->pending = false;
		if (resend)
			__set_bit(irq, resend_queued);
	}
	SIL_UNL_INT();
	if (unbalanced)
		WARN(1, "Unbalanced enable for IRQ %u", irq);
	else if (unmask)
		(void)line_unmask(irq);
	if (resend)
		hrtimer_start(&resend_timer, 0, HRTIMER_MODE_REL);
}

int irq_set_irq_type(unsigned int irq, unsigned int type)
{
	struct lx_irq_desc *desc;
	bool live;
	SIL_PRE_LOC;

	if (irq >= NR_IRQS || !lx_irq_valid(irq))
		return -EINVAL;
	type &= IRQ_TYPE_SENSE_MASK;
	if (check_type(irq, type))
		return -EINVAL;
	desc = &irq_descs[irq];
	SIL_LOC_INT();
	desc->type = type;
	live = desc->action && desc->depth == 0;
	SIL_UNL_INT();
	if (live)
		return lx_mach_irq_chip(irq)->irq_unmask(irq, type);
	return 0;
}

int set_irq_type(unsigned int irq, unsigned int type)
{
	return irq_set_irq_type(irq, type);
}

unsigned int irq_get_trigger_type(unsigned int irq)
{
	return irq < NR_IRQS ? irq_descs[irq].type : IRQ_TYPE_NONE;
}

unsigned long lx_irq_unhandled_count(unsigned int irq)
{
	return irq < NR_IRQS ? irq_descs[irq].unhandled : 0;
}

unsigned long lx_irq_count(unsigned int irq)
{
	return irq < NR_IRQS ? irq_descs[irq].count : 0;
}

/* Forgets every handler and IRQ state (part of lx_io_boot). */
static void irq_boot(void)
{
	unsigned int i;

	memset(irq_descs, 0, sizeof(irq_descs));
	memset(action_pool, 0, sizeof(action_pool));
	memset(irq_threads, 0, sizeof(irq_threads));
	for (i = 0; i < ARRAY_SIZE(irq_threads); i++) {
		init_waitqueue_head(&irq_threads[i].wake);
		init_waitqueue_head(&irq_threads[i].idle);
	}
	memset(resend_queued, 0, sizeof(resend_queued));
	/* a previous boot's timer belongs to a queue the tick's boot empties */
	memset(&resend_timer, 0, sizeof(resend_timer));
	hrtimer_setup(&resend_timer, resend_queued_irqs, CLOCK_MONOTONIC, HRTIMER_MODE_REL);
}

void lx_io_boot(intptr_t exinf)
{
	(void)exinf;
	irq_boot();
	lx_fiq_boot();
	lx_mach_boot();
	lx_resource_boot();
	lx_devfs_boot();
	lx_driver_core_boot();
	lx_sysfs_boot();
	lx_input_boot();
	lx_platform_boot();
	lx_gpiolib_boot();
	lx_spi_boot();
	lx_pwm_boot();
	lx_iio_boot();
	lx_i2c_boot();
	lx_legoev3_i2c_boot();
	lx_tty_boot();
	lx_davinci_serial_boot();
	lx_davinci_i2c_boot();
	lx_fb_boot();
	lx_uaccess_boot();
}
