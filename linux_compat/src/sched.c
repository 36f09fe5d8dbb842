/*
 * sched.c — blocking and waking tasks for linux_compat's sleeping primitives,
 * deferred wakeups, bottom-half disabling, and Linux's task API (current,
 * schedule_timeout, wake_up_process) on RTOS tasks.
 */
#include <linux/kernel.h>
#include <linux/errno.h>
#include <linux/string.h>
#include <linux/sched.h>
#include <linux_compat/sched.h>
#include <linux_compat/clock.h>
#include <linux_compat/context.h>
#include <linux_compat/report.h>
#include <linux_compat/workqueue.h>
#include <kernel.h>
#include <rtos_cfg.h>
#include <sil.h>

/* Tasks whose wakeup is waiting for the interrupt lock to be released. */
static uint32_t deferred_wake[(TNUM_TSKID + 32) / 32];
/* A wakeup is deferred (read inline by the production spin_unlock_irqrestore). */
bool lx_deferred_wake_pending;
static unsigned int bh_disable_depth;
static struct task_struct tasks[TNUM_TSKID + 1];

/* Forgets deferred wakeups, bottom-half state and task states. */
void lx_sched_reset(void)
{
	memset(deferred_wake, 0, sizeof(deferred_wake));
	lx_deferred_wake_pending = false;
	bh_disable_depth = 0;
	memset(tasks, 0, sizeof(tasks));
}

/* The running task's ID, or TSK_NONE outside task context. */
ID lx_current_tskid(void)
{
	ID tskid = TSK_NONE;

	if (sns_ctx() || get_tid(&tskid) != E_OK)
		return TSK_NONE;
	return tskid;
}

/* Records a wakeup for later delivery. */
static void defer_wake(ID tskid)
{
	SIL_PRE_LOC;

	SIL_LOC_INT();
	deferred_wake[(tskid - 1) / 32] |= 1U << ((tskid - 1) % 32);
	lx_deferred_wake_pending = true;
	SIL_UNL_INT();
}

/* Wakes tskid now, or at the next tick if service calls are not allowed now. */
void lx_wake_task(ID tskid)
{
	ER er;

	if (tskid <= 0 || tskid > TNUM_TSKID)
		return;
	if (lx_irqs_masked()) {
		defer_wake(tskid);
		return;
	}
	er = sns_ctx() ? iwup_tsk(tskid) : wup_tsk(tskid);
	if (er == E_CTX)
		defer_wake(tskid);
}

/* Delivers the deferred wakeups (the tick ISR, or whoever just unmasked interrupts). */
void lx_deferred_wakeups_run(void)
{
	uint32_t pending;
	unsigned int word, bit;
	bool in_isr;
	SIL_PRE_LOC;

	if (!lx_deferred_wake_pending || lx_irqs_masked())
		return;
	in_isr = sns_ctx();
	for (word = 0; word < sizeof(deferred_wake) / sizeof(deferred_wake[0]); word++) {
		SIL_LOC_INT();
		pending = deferred_wake[word];
		deferred_wake[word] = 0;
		SIL_UNL_INT();
		for (bit = 0; bit < 32; bit++)
			if (pending & (1U << bit))
				(void)(in_isr ? iwup_tsk((ID)(word * 32 + bit + 1))
					      : wup_tsk((ID)(word * 32 + bit + 1)));
	}
	SIL_LOC_INT();
	lx_deferred_wake_pending = false;
	for (word = 0; word < sizeof(deferred_wake) / sizeof(deferred_wake[0]); word++)
		if (deferred_wake[word])
			lx_deferred_wake_pending = true;
	SIL_UNL_INT();
}

/* Appends w to wl. */
void lx_waitlist_add_locked(struct lx_waitlist *wl, struct lx_waiter *w)
{
	w->next = NULL;
	if (wl->tail != NULL)
		wl->tail->next = w;
	else
		wl->head = w;
	wl->tail = w;
}

/* Removes w from wl if present; true if it was. */
bool lx_waitlist_remove_locked(struct lx_waitlist *wl, struct lx_waiter *w)
{
	struct lx_waiter *prev = NULL, *cur;

	for (cur = wl->head; cur != NULL; prev = cur, cur = cur->next) {
		if (cur != w)
			continue;
		if (prev != NULL)
			prev->next = cur->next;
		else
			wl->head = cur->next;
		if (wl->tail == cur)
			wl->tail = prev;
		cur->next = NULL;
		return true;
	}
	return false;
}

/* Removes and returns the first waiter, or NULL. */
struct lx_waiter *lx_waitlist_pop_locked(struct lx_waitlist *wl)
{
	struct lx_waiter *w = wl->head;

	if (w != NULL) {
		wl->head = w->next;
		if (wl->head == NULL)
			wl->tail = NULL;
		w->next = NULL;
	}
	return w;
}

/* Prepares a waiter record for the calling task. */
void lx_waiter_init(struct lx_waiter *w)
{
	w->next = NULL;
	w->tskid = lx_current_tskid();
	w->woken = false;
	w->exclusive = false;
}

/* The deadline ms from now; none for negative ms. */
uint64_t lx_deadline_after_ms(long ms)
{
	if (ms < 0)
		return U64_MAX;
	return lx_clock_now_ns() + (uint64_t)ms * 1000000U;
}

/* Sleeps until woken, the deadline, or rel_wai: 0, -ETIME or -EINTR. */
int lx_waiter_sleep(struct lx_waiter *w, uint64_t deadline_ns)
{
	uint64_t now;
	ER er;

	while (!w->woken && lx_worker_serve_before_init_sleep())
		;
	for (;;) {
		if (w->woken)
			return 0;
		if (deadline_ns == U64_MAX) {
			er = slp_tsk();
		} else {
			now = lx_clock_now_ns();
			if (now >= deadline_ns)
				return -ETIME;
			/* TOPPERS timeouts are whole ms: round up, never wake early. */
			er = tslp_tsk((TMO)((deadline_ns - now + 999999U) / 1000000U));
		}
		if (w->woken)
			return 0;
		if (er == E_TMOUT)
			continue;        /* the loop head checks the deadline */
		if (er == E_RLWAI)
			return -EINTR;
		if (er != E_OK) {
			lx_report("sleep failed", NULL, 0, "slp_tsk/tslp_tsk returned %d", (int)er);
			return -EINTR;
		}
	}
}

/* Disables timer_list callbacks until the matching lx_bh_enable. */
void lx_bh_disable(void)
{
	bh_disable_depth++;
}

/* Re-enables timer_list callbacks (they run at the next tick). */
void lx_bh_enable(void)
{
	if (bh_disable_depth > 0)
		bh_disable_depth--;
}

/* True while bottom halves are disabled. */
bool lx_bh_disabled(void)
{
	return bh_disable_depth > 0;
}

/* The task_struct of the calling task (index 0 stands for non-task context). */
struct task_struct *lx_get_current(void)
{
	ID tskid = lx_current_tskid();
	struct task_struct *t = &tasks[tskid > 0 && tskid <= TNUM_TSKID ? tskid : 0];

	t->pid = tskid;
	return t;
}

/* Sleeps until wake_up_process or timeout jiffies; returns the jiffies left (0 on timeout). */
long schedule_timeout(long timeout)
{
	struct task_struct *t = lx_get_current();
	uint64_t start, deadline;
	long left;
	ER er;

	if (!lx_might_sleep_check("schedule_timeout()", NULL, 0))
		return 0;
	if (t->__state == TASK_RUNNING) {
		(void)rot_rdq(TPRI_SELF);
		return timeout < 0 ? 0 : timeout;
	}
	start = lx_clock_now_ns();
	if (timeout == MAX_SCHEDULE_TIMEOUT || timeout < 0) {
		er = slp_tsk();
		t->__state = TASK_RUNNING;
		return er == E_OK ? MAX_SCHEDULE_TIMEOUT : 0;
	}
	deadline = start + jiffies_to_nsecs((unsigned long)timeout);
	er = tslp_tsk((TMO)jiffies_to_msecs((unsigned long)timeout));
	t->__state = TASK_RUNNING;
	if (er == E_TMOUT)
		return 0;
	left = (long)nsecs_to_jiffies(deadline > lx_clock_now_ns() ? deadline - lx_clock_now_ns() : 0);
	return left > 0 ? left : 1;
}

/* schedule_timeout in TASK_INTERRUPTIBLE state. */
long schedule_timeout_interruptible(long timeout)
{
	set_current_state(TASK_INTERRUPTIBLE);
	return schedule_timeout(timeout);
}

/* schedule_timeout in TASK_UNINTERRUPTIBLE state. */
long schedule_timeout_uninterruptible(long timeout)
{
	set_current_state(TASK_UNINTERRUPTIBLE);
	return schedule_timeout(timeout);
}

/* Sleeps until wake_up_process (if the state was set to a sleeping state). */
void schedule(void)
{
	(void)schedule_timeout(MAX_SCHEDULE_TIMEOUT);
}

/* Wakes task p; 1 if it was sleeping in schedule*, 0 if it was running. */
int wake_up_process(struct task_struct *p)
{
	int was_sleeping;

	if (p == NULL || p->pid <= 0)
		return 0;
	was_sleeping = p->__state != TASK_RUNNING;
	p->__state = TASK_RUNNING;
	/* A task still running would keep a queued wakeup it never asked for. */
	if (was_sleeping)
		lx_wake_task((ID)p->pid);
	return was_sleeping;
}

/* Gives the CPU to other ready tasks of the same priority. */
void yield(void)
{
	if (!sns_ctx())
		(void)rot_rdq(TPRI_SELF);
}
