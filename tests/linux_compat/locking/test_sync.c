/*
 * test_sync.c — mutexes (hand-over, trylock, misuse reports), completions
 * (complete from an ISR, complete_all, timeouts), wait queues (wake_up from
 * an ISR, timeouts, rel_wai), nested irqsave, spinlock recursion, atomics.
 */
#include "tap.h"
#include "lx_core_test.h"
#include "rtos_test.h"
#include <linux/mutex.h>
#include <linux/completion.h>
#include <linux/wait.h>
#include <linux/spinlock.h>
#include <linux/atomic.h>
#include <linux/delay.h>
#include <linux/errno.h>
#include <kernel.h>

#define IRQ_TEST	90U

static DEFINE_MUTEX(mtx);
static DECLARE_COMPLETION(done);
static DECLARE_WAIT_QUEUE_HEAD(wq);
static DEFINE_SPINLOCK(lock);
static volatile int flag;
static int isr_mode;
static int r_trylock[2], r_misuse_bugs, r_recursive;
static bool r_locked_seen;
static unsigned long r_cto_timeout, r_cto_ok;
static int r_wait_intr;
static long r_wet_timeout, r_wet_ok;
static bool r_irq_nesting[4];
static int r_spin_bugs;
static int completion_waiters_done;

static void irq_isr(intptr_t exinf)
{
	(void)exinf;
	if (isr_mode == 1) {
		complete(&done);
	} else if (isr_mode == 2) {
		flag = 1;
		wake_up(&wq);
	}
}

static void mutex_contender(intptr_t exinf)
{
	(void)exinf;
	mutex_lock(&mtx);
	rt_log("C-locked");
	mutex_unlock(&mtx);
}

static void completion_waiter(intptr_t exinf)
{
	(void)exinf;
	wait_for_completion(&done);
	completion_waiters_done++;
}

static void wq_waiter(intptr_t exinf)
{
	(void)exinf;
	r_wait_intr = wait_event_interruptible(wq, flag == 2);
}

static void main_task(intptr_t exinf)
{
	unsigned long f1, f2;
	uint_t before;

	(void)exinf;
	/* Mutex: hand-over to a waiting task. */
	mutex_lock(&mtx);
	act_tsk(2);                  /* higher priority: blocks on the mutex */
	r_locked_seen = mutex_is_locked(&mtx);
	r_trylock[0] = mutex_trylock(&mtx) == 0 ? 0 : 1;
	rt_log("M-unlock");
	mutex_unlock(&mtx);
	msleep(1);
	r_trylock[1] = mutex_trylock(&mtx);
	mutex_unlock(&mtx);

	before = rtos_host_bug_count();
	rtos_host_expect_bugs(true);
	mutex_unlock(&mtx);                          /* unlocked: reported */
	mutex_lock(&mtx);
	mutex_lock(&mtx);                            /* recursive: reported, not hung */
	r_recursive = strstr(rtos_host_last_bug(), "mutex deadlock") != NULL;
	mutex_unlock(&mtx);
	rtos_host_expect_bugs(false);
	r_misuse_bugs = (int)(rtos_host_bug_count() - before);

	/* Completion from an ISR, before and while a task waits. */
	isr_mode = 1;
	rtos_host_irq_raise(IRQ_TEST);
	msleep(1);
	wait_for_completion(&done);              /* already completed: no sleep */
	act_tsk(3);
	msleep(1);
	rtos_host_irq_raise(IRQ_TEST);
	msleep(1);
	r_cto_timeout = wait_for_completion_timeout(&done, 3);
	complete(&done);
	r_cto_ok = wait_for_completion_timeout(&done, 3);
	act_tsk(3);
	act_tsk(4);
	msleep(1);
	complete_all(&done);
	msleep(1);
	ok(try_wait_for_completion(&done) && completion_done(&done), "after complete_all every wait succeeds");
	reinit_completion(&done);
	ok(!try_wait_for_completion(&done), "reinit_completion: not done again");

	/* Wait queue: wake_up from an ISR, timeouts, rel_wai. */
	isr_mode = 2;
	flag = 0;
	rtos_host_irq_raise(IRQ_TEST);
	wait_event(wq, flag == 1);
	r_wet_timeout = wait_event_timeout(wq, flag == 5, 4);
	flag = 5;
	r_wet_ok = wait_event_timeout(wq, flag == 5, 4);
	act_tsk(5);
	msleep(1);
	rel_wai(5);
	msleep(1);

	/* Nested irqsave restores each level. */
	spin_lock_irqsave(&lock, f1);
	r_irq_nesting[0] = irqs_disabled();
	local_irq_save(f2);
	local_irq_restore(f2);
	r_irq_nesting[1] = irqs_disabled();
	spin_unlock_irqrestore(&lock, f1);
	r_irq_nesting[2] = !irqs_disabled() && !in_atomic();
	local_irq_disable();
	local_irq_disable();
	local_irq_enable();
	r_irq_nesting[3] = !irqs_disabled();

	before = rtos_host_bug_count();
	rtos_host_expect_bugs(true);
	spin_lock(&lock);
	spin_lock(&lock);            /* recursion: the deadlock SMP would hit */
	spin_unlock(&lock);
	spin_unlock(&lock);          /* unlock of a free lock */
	rtos_host_expect_bugs(false);
	r_spin_bugs = (int)(rtos_host_bug_count() - before);
}

int main(void)
{
	static const struct rtos_task_cfg tasks[] = {
		LXC_TASK(1, main_task, 8, true),
		LXC_TASK(2, mutex_contender, 5, false),
		LXC_TASK(3, completion_waiter, 6, false),
		LXC_TASK(4, completion_waiter, 7, false),
		LXC_TASK(5, wq_waiter, 6, false),
	};
	static const struct rtos_int_cfg ints[] = { { IRQ_TEST, TA_ENAINT | TA_EDGE, -3 } };
	static const struct rtos_isr_cfg isrs[] = { { TA_NULL, 0, IRQ_TEST, irq_isr, 1 } };
	atomic_t a = ATOMIC_INIT(5);

	tap_plan(26);
	rt_log_reset();
	if (!lxc_boot(tasks, 5, ints, 1, isrs, 1))
		return tap_done();
	rtos_host_run_for(50 * NSEC_PER_MSEC);
	rtos_host_shutdown();

	is_str(rt_log_text(), "M-unlock C-locked", "mutex_unlock hands the mutex to the waiting task");
	ok(r_locked_seen && r_trylock[0] == 0, "mutex_is_locked; mutex_trylock on a held mutex returns 0");
	is_int(r_trylock[1], 1, "mutex_trylock on a free mutex returns 1");
	is_int(r_misuse_bugs, 2, "unlocking an unlocked mutex and locking it recursively are reported");
	ok(r_recursive, "the recursive lock is reported as a deadlock");
	is_int(completion_waiters_done, 3, "complete from an ISR and complete_all released every waiter");
	is_int(r_cto_timeout, 0, "wait_for_completion_timeout returns 0 on timeout");
	ok(r_cto_ok >= 1 && r_cto_ok <= 3, "...and the jiffies left when completed (%lu)", r_cto_ok);
	is_int(r_wet_timeout, 0, "wait_event_timeout returns 0 when the condition stays false");
	ok(r_wet_ok >= 1, "...and >= 1 when it is true");
	is_int(r_wait_intr, -ERESTARTSYS, "wait_event_interruptible released by rel_wai returns -ERESTARTSYS");
	ok(r_irq_nesting[0] && r_irq_nesting[1], "an inner irqsave/restore keeps the outer level disabled");
	ok(r_irq_nesting[2], "the outer restore enables interrupts and leaves the atomic section");
	ok(r_irq_nesting[3], "local_irq_disable twice, enable once: enabled (no nesting, as Linux)");
	is_int(r_spin_bugs, 2, "spinlock recursion and unlocking a free lock are reported");

	is_int(atomic_read(&a), 5, "ATOMIC_INIT / atomic_read");
	atomic_inc(&a);
	atomic_add(4, &a);
	is_int(atomic_read(&a), 10, "atomic_inc / atomic_add");
	ok(!atomic_dec_and_test(&a) && atomic_sub_return(9, &a) == 0, "atomic_dec_and_test / atomic_sub_return");
	is_int(atomic_cmpxchg(&a, 0, 7), 0, "atomic_cmpxchg returns the old value");
	is_int(atomic_read(&a), 7, "...and swapped");
	is_int(atomic_cmpxchg(&a, 1, 9), 7, "atomic_cmpxchg with a wrong old value");
	is_int(atomic_xchg(&a, 2), 7, "atomic_xchg");
	ok(atomic_inc_return(&a) == 3 && atomic_dec_return(&a) == 2, "atomic_inc_return / atomic_dec_return");
	ok(atomic_add_unless(&a, 1, 2) == false && atomic_inc_not_zero(&a) && atomic_read(&a) == 3,
	   "atomic_add_unless / atomic_inc_not_zero");
	return tap_done();
}
