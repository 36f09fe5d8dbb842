/*
 * test_might_sleep.c — sleeping where Linux forbids it is caught and reported
 * with what, where and which context: in an hrtimer callback, in an ISR, in a
 * Linux IRQ handler, under a spinlock, with interrupts disabled; and the
 * context predicates (in_interrupt, in_atomic, irqs_disabled) agree.
 */
#include "tap.h"
#include "lx_core_test.h"
#include <linux/kernel.h>
#include <linux/hrtimer.h>
#include <linux/delay.h>
#include <linux/spinlock.h>
#include <linux/mutex.h>
#include <linux/semaphore.h>
#include <linux/preempt.h>
#include <linux/irqflags.h>
#include <linux/sched.h>
#include <kernel.h>

#define IRQ_TEST	90U

static char reports[8][320];
static int nreports;
static bool task_flags[4], isr_flags[3], timer_flags[2];
static bool dispatch_disabled_in_spin, dispatch_enabled_after;
static DEFINE_SPINLOCK(test_lock);
static DEFINE_MUTEX(test_mutex);
static struct semaphore test_sem;
static struct hrtimer sleepy_timer;

/* Runs stmt expecting exactly one report and keeps its text. */
#define EXPECT_REPORT(stmt) do {					\
	uint_t before_ = rtos_host_bug_count();				\
	rtos_host_expect_bugs(true);					\
	stmt;								\
	rtos_host_expect_bugs(false);					\
	if (nreports < 8)						\
		snprintf(reports[nreports++], sizeof(reports[0]), "%u|%s",	\
			 rtos_host_bug_count() - before_, rtos_host_last_bug()); \
} while (0)

static enum hrtimer_restart sleepy_cb(struct hrtimer *t)
{
	(void)t;
	timer_flags[0] = in_interrupt() && in_atomic();
	timer_flags[1] = !preemptible();
	EXPECT_REPORT(msleep(1));
	return HRTIMER_NORESTART;
}

static void test_isr(intptr_t exinf)
{
	(void)exinf;
	/* NOLINTNEXTLINE(misc-redundant-expression): the same test today, but both names are API */
	isr_flags[0] = in_interrupt() && in_irq() && !in_task();
	EXPECT_REPORT(might_sleep());
	lx_irq_enter(47);
	EXPECT_REPORT(down(&test_sem));
	lx_irq_exit();
	isr_flags[1] = lx_current_irq() == -1;
}

static void main_task(intptr_t exinf)
{
	unsigned long flags;
	uint_t before;

	(void)exinf;
	sema_init(&test_sem, 0);
	task_flags[0] = !in_interrupt() && !in_atomic() && !irqs_disabled() && in_task();
	before = rtos_host_bug_count();
	might_sleep();
	msleep(1);
	task_flags[1] = rtos_host_bug_count() == before;

	hrtimer_setup(&sleepy_timer, sleepy_cb, CLOCK_MONOTONIC, HRTIMER_MODE_REL);
	hrtimer_start(&sleepy_timer, us_to_ktime(300), HRTIMER_MODE_REL);
	msleep(2);

	rtos_host_irq_raise(IRQ_TEST);
	msleep(1);

	spin_lock(&test_lock);
	dispatch_disabled_in_spin = sns_dsp() && in_atomic() && preempt_count() == 1;
	EXPECT_REPORT(mutex_lock(&test_mutex));
	spin_unlock(&test_lock);
	dispatch_enabled_after = !sns_dsp() && !in_atomic();
	mutex_unlock(&test_mutex);

	local_irq_save(flags);
	task_flags[2] = irqs_disabled() && in_atomic();
	EXPECT_REPORT(usleep_range(100, 200));
	local_irq_restore(flags);
	task_flags[3] = !irqs_disabled();

	spin_lock_irqsave(&test_lock, flags);
	EXPECT_REPORT(schedule_timeout_uninterruptible(1));
	spin_unlock_irqrestore(&test_lock, flags);
}

int main(void)
{
	static const struct rtos_task_cfg tasks[] = { LXC_TASK(1, main_task, 5, true) };
	static const struct rtos_int_cfg ints[] = { { IRQ_TEST, TA_ENAINT | TA_EDGE, -3 } };
	static const struct rtos_isr_cfg isrs[] = { { TA_NULL, 0, IRQ_TEST, test_isr, 1 } };

	tap_plan(19);
	if (!lxc_boot(tasks, 1, ints, 1, isrs, 1))
		return tap_done();
	rtos_host_run_for(20 * NSEC_PER_MSEC);
	rtos_host_shutdown();

	ok(task_flags[0], "task context: not in interrupt, not atomic, irqs enabled");
	ok(task_flags[1], "might_sleep and msleep in a task report nothing");
	ok(timer_flags[0] && timer_flags[1], "hrtimer callback: in_interrupt, in_atomic, not preemptible");
	ok(isr_flags[0], "ISR: in_interrupt and in_irq, not in_task");
	ok(isr_flags[1], "lx_irq_exit leaves no IRQ recorded");
	ok(dispatch_disabled_in_spin, "spin_lock in a task disables dispatching and counts one atomic level");
	ok(dispatch_enabled_after, "spin_unlock re-enables dispatching");
	ok(task_flags[2] && task_flags[3], "local_irq_save/restore: irqs_disabled follows");
	is_int(nreports, 6, "six reports collected");

#define CHECK_REPORT(i, ctxword, what) do {						\
	ok(strncmp(reports[i], "1|", 2) == 0 &&						\
	   strstr(reports[i], "sleeping function called from invalid context") != NULL,	\
	   "report %d is one might_sleep bug", i);					\
	ok(strstr(reports[i], ctxword) != NULL && strstr(reports[i], what) != NULL &&	\
	   strstr(reports[i], "test_might_sleep.c:") != NULL,				\
	   "report %d names %s, %s and the call site: %s", i, what, ctxword, reports[i]); \
} while (0)
	CHECK_REPORT(0, "hrtimer callback", "msleep()");
	CHECK_REPORT(1, "interrupt context (isr 90)", "might_sleep()");
	ok(strstr(reports[2], "hard IRQ 47") != NULL && strstr(reports[2], "down()") != NULL,
	   "down() in a Linux IRQ handler names hard IRQ 47: %s", reports[2]);
	CHECK_REPORT(3, "spinlock held", "mutex_lock()");
	CHECK_REPORT(4, "interrupts disabled", "usleep_range()");
	ok(strstr(reports[5], "spinlock held, interrupts disabled") != NULL &&
	   strstr(reports[5], "schedule_timeout()") != NULL,
	   "schedule_timeout under spin_lock_irqsave names both: %s", reports[5]);
	return tap_done();
}
