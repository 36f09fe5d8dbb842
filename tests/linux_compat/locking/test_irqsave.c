/*
 * test_irqsave.c — spin_lock_irqsave / spin_unlock_irqrestore as a
 * uniprocessor Linux has them, in the checked build and (mk/bench.mk) in the
 * production build, whose fast path is inline: interrupts stay masked until
 * the outermost restore and are delivered there; the lock is one atomic
 * section (preempt_count, irqs_disabled); a wake_up under the lock takes
 * effect at the unlock, before the unlocking task goes on; nesting, a lock
 * taken in an ISR, spin_lock inside irqsave; an unbalanced unlock is reported.
 */
#include "tap.h"
#include "lx_core_test.h"
#include "rtos_test.h"
#include <linux/spinlock.h>
#include <linux/wait.h>
#include <linux/delay.h>
#include <kernel.h>

#define IRQ_TEST	90U

static DEFINE_SPINLOCK(lock);
static DEFINE_SPINLOCK(inner);
static DECLARE_WAIT_QUEUE_HEAD(wq);
static volatile int isr_runs, woken_runs, flag;
static volatile bool isr_lock_balanced;

static int in_lock_preempt, in_lock_irqs_disabled, isr_seen_inside, isr_seen_nested, isr_seen_after;
static int woken_inside, woken_after_unlock, after_preempt, after_irqs_disabled, nested_preempt;
static unsigned int unbalanced_bugs;
static bool finished;

static void irq_isr(intptr_t exinf)
{
	unsigned long flags;
	unsigned int before = preempt_count();

	(void)exinf;
	spin_lock_irqsave(&inner, flags);
	isr_runs++;
	spin_unlock_irqrestore(&inner, flags);
	isr_lock_balanced = preempt_count() == before;
}

static void waiter(intptr_t exinf)
{
	(void)exinf;
	wait_event(wq, flag != 0);
	woken_runs++;
}

static void main_task(intptr_t exinf)
{
	unsigned long flags, flags2;
	unsigned int before;

	(void)exinf;
	act_tsk(2);                          /* the waiter (higher priority) blocks on wq */
	msleep(1);

	spin_lock_irqsave(&lock, flags);
	in_lock_preempt = (int)preempt_count();
	in_lock_irqs_disabled = irqs_disabled();
	rtos_host_irq_raise(IRQ_TEST);
	isr_seen_inside = isr_runs;
	spin_lock_irqsave(&inner, flags2);   /* nested */
	nested_preempt = (int)preempt_count();
	spin_unlock_irqrestore(&inner, flags2);
	isr_seen_nested = isr_runs;          /* the outer level still masks */
	flag = 1;
	wake_up(&wq);
	woken_inside = woken_runs;
	spin_unlock_irqrestore(&lock, flags);
	woken_after_unlock = woken_runs;     /* it ran at the unlock */
	isr_seen_after = isr_runs;
	after_preempt = (int)preempt_count();
	after_irqs_disabled = irqs_disabled();

	before = rtos_host_bug_count();
	rtos_host_expect_bugs(true);
	flags = arch_local_irq_save();
	arch_local_irq_restore(flags);
	spin_unlock_irqrestore(&lock, flags);   /* never locked: reported */
	rtos_host_expect_bugs(false);
	unbalanced_bugs = rtos_host_bug_count() - before;
	finished = true;
}

int main(void)
{
	static const struct rtos_task_cfg tasks[] = {
		LXC_TASK(1, main_task, 8, true),
		LXC_TASK(2, waiter, 5, false),
	};
	static const struct rtos_int_cfg ints[] = { { IRQ_TEST, TA_ENAINT | TA_EDGE, -3 } };
	static const struct rtos_isr_cfg isrs[] = { { TA_NULL, 0, IRQ_TEST, irq_isr, 1 } };

	tap_plan(15);
	if (!lxc_boot(tasks, 2, ints, 1, isrs, 1))
		return tap_done();
	rtos_host_run_for(20 * NSEC_PER_MSEC);
	rtos_host_shutdown();

	ok(finished, "the test task ran to its end");
	is_int(in_lock_preempt, 1, "under spin_lock_irqsave preempt_count() is 1");
	ok(in_lock_irqs_disabled, "and irqs_disabled()");
	is_int(isr_seen_inside, 0, "an interrupt raised under the lock does not run there");
	is_int(nested_preempt, 2, "a nested irqsave lock counts a second atomic section");
	is_int(isr_seen_nested, 0, "the inner restore leaves interrupts masked by the outer lock");
	is_int(woken_inside, 0, "a task woken under the lock does not run before the unlock");
	is_int(woken_after_unlock, 1, "it runs at the unlock, before the unlocking task goes on");
	is_int(isr_seen_after, 1, "the interrupt is delivered at the outermost restore");
	is_int(after_preempt, 0, "after the unlock preempt_count() is 0");
	ok(!after_irqs_disabled, "and interrupts are enabled");
	ok(isr_lock_balanced, "an irqsave lock taken in the ISR leaves its preempt count balanced");
	is_int(isr_runs, 1, "the ISR ran once");
	ok(unbalanced_bugs >= 1, "an unlock without a lock is reported (%u)", unbalanced_bugs);
	is_int((int)rtos_host_bug_count(), (int)unbalanced_bugs, "nothing else was reported");
	return tap_done();
}
