/*
 * test_semaphore.c — native semaphores through the RTOS: down blocks and up
 * wakes waiters in FIFO order (whatever their priority), down_timeout,
 * down_interruptible released by rel_wai, down_trylock/up with the CPU
 * locked and in an ISR, and the 2.6-era initialisers.
 */
#include "tap.h"
#include "lx_core_test.h"
#include "rtos_test.h"
#include <linux/semaphore.h>
#include <linux/delay.h>
#include <linux/ktime.h>
#include <linux/errno.h>
#include <kernel.h>

#define IRQ_TEST	90U

static struct semaphore sem;
static DEFINE_SEMAPHORE(binary_sem);
static DEFINE_SEMAPHORE(counting_sem, 3);
static s64 timeout_elapsed;
static int timeout_ret = 1, intr_ret = 1;
static int locked_try[3], isr_try[2];
static bool isr_woke_waiter;

static void waiter(intptr_t exinf)
{
	down(&sem);
	rt_log("W%d", (int)exinf);
}

static void sem_isr(intptr_t exinf)
{
	(void)exinf;
	isr_try[0] = down_trylock(&sem);   /* count 0: not acquired */
	up(&sem);                           /* wakes the waiting task with iwup_tsk */
	isr_try[1] = 0;
}

static void isr_waiter(intptr_t exinf)
{
	(void)exinf;
	down(&sem);
	isr_woke_waiter = true;
}

static void interrupted(intptr_t exinf)
{
	(void)exinf;
	intr_ret = down_interruptible(&sem);
}

static void main_task(intptr_t exinf)
{
	s64 t0;

	(void)exinf;
	sema_init(&sem, 0);
	/* Three waiters block lowest priority first; FIFO hands out W2 W4 W3
	 * (priority order would be W3 W4 W2). */
	act_tsk(2);
	msleep(1);
	act_tsk(4);
	msleep(1);
	act_tsk(3);
	msleep(1);
	rt_log("up");
	up(&sem);
	msleep(1);
	up(&sem);
	msleep(1);
	up(&sem);
	msleep(1);

	t0 = ktime_get();
	timeout_ret = down_timeout(&sem, 5);
	timeout_elapsed = ktime_get() - t0;

	act_tsk(5);
	msleep(1);
	rel_wai(5);
	msleep(1);

	/* CPU locked: trylock and up are legal; a waiter's wakeup waits for the unlock. */
	sema_init(&sem, 1);
	loc_cpu();
	locked_try[0] = down_trylock(&sem);
	locked_try[1] = down_trylock(&sem);
	up(&sem);
	locked_try[2] = down_trylock(&sem);
	unl_cpu();

	/* ISR: trylock fails, up hands the semaphore to a sleeping task. */
	act_tsk(6);
	msleep(1);
	rtos_host_irq_raise(IRQ_TEST);
	msleep(1);
}

int main(void)
{
	static const struct rtos_task_cfg tasks[] = {
		LXC_TASK(1, main_task, 8, true),
		LXC_TASK(2, waiter, 9, false),
		LXC_TASK(3, waiter, 3, false),
		LXC_TASK(4, waiter, 6, false),
		LXC_TASK(5, interrupted, 6, false),
		LXC_TASK(6, isr_waiter, 6, false),
	};
	static const struct rtos_int_cfg ints[] = { { IRQ_TEST, TA_ENAINT | TA_EDGE, -3 } };
	static const struct rtos_isr_cfg isrs[] = { { TA_NULL, 0, IRQ_TEST, sem_isr, 1 } };
	struct rtos_task_cfg rows[6];
	int i;

	for (i = 0; i < 6; i++) {
		rows[i] = tasks[i];
		rows[i].exinf = rows[i].tskid;
	}
	tap_plan(13);
	rt_log_reset();
	if (!lxc_boot(rows, 6, ints, 1, isrs, 1))
		return tap_done();
	rtos_host_run_for(50 * NSEC_PER_MSEC);
	rtos_host_shutdown();

	is_str(rt_log_text(), "up W2 W4 W3", "up wakes the waiters in the order they blocked, not by priority");
	is_int(timeout_ret, -ETIME, "down_timeout on an empty semaphore returns -ETIME");
	ok(timeout_elapsed >= 5 * NSEC_PER_MSEC && timeout_elapsed < 6 * NSEC_PER_MSEC,
	   "...after 5 jiffies = 5 ms (%lld ns)", (long long)timeout_elapsed);
	is_int(intr_ret, -EINTR, "down_interruptible released by rel_wai returns -EINTR");
	is_int(locked_try[0], 0, "down_trylock with the CPU locked acquires (0)");
	is_int(locked_try[1], 1, "...and then fails (1)");
	is_int(locked_try[2], 0, "up with the CPU locked releases it again");
	is_int(isr_try[0], 1, "down_trylock in an ISR on an empty semaphore returns 1");
	ok(isr_woke_waiter, "up in an ISR wakes the task blocked in down");
	is_int(sem.count, 0, "the semaphore went to the waiter, not back to the count");
	is_int(binary_sem.count, 1, "DEFINE_SEMAPHORE(name) is a binary semaphore (count 1)");
	is_int(counting_sem.count, 3, "DEFINE_SEMAPHORE(name, 3) has count 3");
	{
		struct semaphore a, b;

		init_MUTEX(&a);
		init_MUTEX_LOCKED(&b);
		ok(a.count == 1 && b.count == 0, "init_MUTEX / init_MUTEX_LOCKED");
	}
	return tap_done();
}
