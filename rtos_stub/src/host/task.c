/*
 * task.c — tasks: ready queues, dispatch, waiting, and the task management
 * and task-dependent synchronisation service calls.
 *
 * As in TOPPERS, the running task stays in the ready queue (at the head of
 * its priority); a preempted task therefore resumes before its peers.
 */
#include <stdlib.h>
#include <string.h>

#include "kernel_impl.h"

/* Host frames (libc, sanitizers) are larger than the target's: never less than this. */
#define HOST_MIN_STACK (256U * 1024U)

struct tcb *tcb_table[TNUM_TSKID + 1];
struct tcb *runtsk;
struct tcb *schedtsk;

static struct queue ready_queue[TMAX_TPRI + 1];   /* indexed by priority */
static uint32_t ready_map;                        /* bit pri-1 set: queue not empty */

static void wait_timeout(struct tmevt *ev);

/* Traces a task event (the observer sees the task's state after it). */
static void trace_task(const char *what, const struct tcb *t)
{
	observe_task_state(t);
	if (trace_on())
		rtos_host_trace("kernel", "%s %s", what, t->cfg->name ? t->cfg->name : "?");
}

/* Recomputes schedtsk from the ready queues. */
void update_schedtsk(void)
{
	if (ready_map == 0) {
		schedtsk = NULL;
		return;
	}
	schedtsk = container_of_kernel(ready_queue[__builtin_ctz(ready_map) + 1].next, struct tcb, node);
}

/* Marks t ready at the tail of its priority queue. */
void ready_insert_tail(struct tcb *t)
{
	queue_insert_before(&ready_queue[t->bpri], &t->node);
	ready_map |= 1U << (t->bpri - 1);
	if (schedtsk == NULL || t->bpri < schedtsk->bpri)
		schedtsk = t;
}

/* Marks t ready at the head of its priority queue. */
void ready_insert_head(struct tcb *t)
{
	queue_insert_before(ready_queue[t->bpri].next, &t->node);
	ready_map |= 1U << (t->bpri - 1);
	update_schedtsk();
}

/* Removes t from the ready queue. */
void ready_remove(struct tcb *t)
{
	queue_remove(&t->node);
	if (queue_empty(&ready_queue[t->bpri]))
		ready_map &= ~(1U << (t->bpri - 1));
	if (t == schedtsk)
		update_schedtsk();
}

/* Moves the first ready task of pri to the tail of its priority. */
void ready_rotate(PRI pri)
{
	struct queue *q = &ready_queue[pri];
	struct queue *first = q->next;

	if (queue_empty(q) || first->next == q)
		return;
	queue_remove(first);
	queue_insert_before(q, first);
	update_schedtsk();
}

/* Leaves the running task for schedtsk (or idle); returns when it runs again. */
static void switch_from_task(bool dying)
{
	struct tcb *from = runtsk;
	/* after ext_ker from a handler, the CPU goes back to the harness for good */
	struct tcb *to = kernel_exited ? NULL : schedtsk;
	struct coroutine *to_co;

	if (to == from && !dying)
		return;
	if (to != NULL) {
		runtsk = to;
		cpu.kind = EXEC_TASK;
		cpu.exec_id = to->id;
		to_co = &to->co;
		trace_task("dispatch", to);
		observe_running(to);
	} else {
		runtsk = NULL;
		cpu.kind = EXEC_IDLE;
		cpu.exec_id = 0;
		to_co = &harness_co;
		observe_running(NULL);
		if (trace_on())
			rtos_host_trace("kernel", "idle");
	}
	co_switch(&from->co, to_co, dying);
	/* Running again: whoever switched here set runtsk and cpu.kind. */
	irq_dispatch_pending();
}

/* From a task: switch to schedtsk (or to idle); returns when this task runs again. */
void task_switch(void)
{
	switch_from_task(false);
}

/* Switches tasks if the current task context may and should be preempted. */
void dispatch_if_needed(void)
{
	if ((schedtsk != runtsk || kernel_exited) && cpu.kind == EXEC_TASK && cpu.isr_depth == 0 && !cpu.locked &&
	    !cpu.dsp_disabled && cpu.sil_lock == 0 && cpu.irq_defer == 0)
		switch_from_task(false);
}

/* Ends the running task (ext_tsk or return from the task function). */
__attribute__((noreturn)) static void task_exit_running(void)
{
	struct tcb *t = runtsk;

	/* TOPPERS: ext_tsk releases the CPU lock and re-enables dispatching. */
	cpu.locked = false;
	cpu.dsp_disabled = false;
	mtx_release_all(t);
	ready_remove(t);
	t->state = TTS_DMT;
	trace_task("exit", t);
	if (t->actcnt > 0) {
		t->actcnt--;
		task_activate(t);
	}
	switch_from_task(true);
	abort();
}

/* Coroutine entry of every task: runs the task function; returning = ext_tsk. */
static void task_entry(void)
{
	struct tcb *t = runtsk;

	t->stack_entry = (uintptr_t)__builtin_frame_address(0);
	irq_dispatch_pending();
	t->cfg->task(t->cfg->exinf);
	task_exit_running();
}

/* Makes a dormant task ready from its start (activation). */
void task_activate(struct tcb *t)
{
	t->state = TTS_RDY;
	t->bpri = t->cfg->itskpri;
	t->base_pri = t->cfg->itskpri;
	t->suspended = false;
	t->mtx_last = NULL;
	t->nocharge_depth = 0;
	t->wupcnt = 0;
	t->wait = WAIT_NONE;
	t->co.restart = true;
	t->call_us = false;
	trace_task("activate", t);
	ready_insert_tail(t);
}

/* Puts runtsk to wait; returns the release code (E_OK, E_TMOUT, E_RLWAI...). */
ER wait_block(enum wait_kind kind, ID objid, struct queue *wq, bool tpri, TMO tmout)
{
	wait_enter(kind, objid, wq, tpri, tmout);
	task_switch();
	return runtsk->wercd;
}

/* Puts runtsk into the waiting state and its queue, without switching yet. */
void wait_enter(enum wait_kind kind, ID objid, struct queue *wq, bool tpri, TMO tmout)
{
	struct tcb *t = runtsk;

	ready_remove(t);
	t->state = TTS_WAI;
	t->wait = kind;
	t->wobjid = objid;
	t->wercd = E_OK;
	t->wait_queue = wq;
	if (wq != NULL)
		wait_requeue(t, tpri);
	if (tmout != TMO_FEVR)
		tmevt_enqueue(&t->tmevt, tick_after_ns(svc_reltim_ns((uint32_t)tmout)));
	trace_task("wait", t);
}

/* Inserts a waiting task into its wait queue (FIFO, or by priority after its peers). */
void wait_requeue(struct tcb *t, bool tpri)
{
	struct queue *wq = t->wait_queue;
	struct queue *pos = wq;

	if (wq == NULL)
		return;
	if (t->node.next != &t->node)
		queue_remove(&t->node);
	if (tpri) {
		for (pos = wq->next; pos != wq; pos = pos->next)
			if (container_of_kernel(pos, struct tcb, node)->bpri > t->bpri)
				break;
	}
	queue_insert_before(pos, &t->node);
}

/* Takes t out of its wait (queue, timeout) without making it ready. */
static void wait_cancel(struct tcb *t)
{
	enum wait_kind kind = t->wait;

	if (t->wait_queue != NULL) {
		queue_remove(&t->node);
		t->wait_queue = NULL;
	}
	if (tmevt_queued(&t->tmevt))
		tmevt_dequeue(&t->tmevt);
	t->wait = WAIT_NONE;
	/* leaving a mutex's queue other than by getting it may lower the owner's priority */
	if (kind == WAIT_MTX && mtx_table[t->wobjid]->owner != t)
		mtx_waiter_left(t->wobjid);
}

/* Releases a waiting task with ercd; it becomes ready, or suspended after sus_tsk (the caller dispatches). */
void wait_release(struct tcb *t, ER ercd)
{
	wait_cancel(t);
	t->wercd = ercd;
	if (trace_on())
		rtos_host_trace("kernel", "release %s %s", t->cfg->name ? t->cfg->name : "?",
				ercd_name(ercd));
	if (t->suspended) {
		t->state = TTS_SUS;
		observe_task_state(t);
		return;
	}
	t->state = TTS_RDY;
	observe_task_state(t);
	ready_insert_tail(t);
}

/* True if the queue t waits in is in priority order. */
bool wait_queue_tpri(const struct tcb *t)
{
	switch (t->wait) {
	case WAIT_SEM:
		return (sem_table[t->wobjid]->cfg->sematr & TA_TPRI) != 0;
	case WAIT_FLG:
		return (flg_table[t->wobjid]->cfg->flgatr & TA_TPRI) != 0;
	case WAIT_SDTQ:
		return (dtq_table[t->wobjid]->cfg->dtqatr & TA_TPRI) != 0;
	case WAIT_SPDQ:
		return (pdq_table[t->wobjid]->cfg->pdqatr & TA_TPRI) != 0;
	case WAIT_MTX:
		return mtx_table[t->wobjid]->cfg->mtxatr != TA_NULL;
	default:
		return false;
	}
}

/* Sets t's current priority; head: a ready task goes first among its new peers. */
void task_set_priority(struct tcb *t, PRI pri, bool head)
{
	if (t->state == TTS_RDY) {
		ready_remove(t);
		t->bpri = pri;
		if (head)
			ready_insert_head(t);
		else
			ready_insert_tail(t);
	} else {
		t->bpri = pri;
		if (t->state == TTS_WAI && wait_queue_tpri(t))
			wait_requeue(t, true);
	}
}

/* Time event of a waiting task: E_TMOUT (E_OK for dly_tsk). */
static void wait_timeout(struct tmevt *ev)
{
	struct tcb *t = container_of_kernel(ev, struct tcb, tmevt);

	wait_release(t, t->wait == WAIT_DLY ? E_OK : E_TMOUT);
}

/* Resolves a task ID (TSK_SELF allowed if self_ok, in task context); NULL and *ercd on failure. */
struct tcb *task_lookup(ID tskid, bool self_ok, ER *ercd)
{
	if (tskid == TSK_SELF && self_ok && cpu.kind == EXEC_TASK)
		return runtsk;
	if (tskid < 1 || tskid > TNUM_TSKID) {
		*ercd = E_ID;
		return NULL;
	}
	if (tcb_table[tskid] == NULL) {
		*ercd = E_NOEXS;
		return NULL;
	}
	return tcb_table[tskid];
}

/* Checks an output pointer from the caller: E_OK, or E_MACV (NULL, or outside its domain). */
ER check_out_ptr(const void *p, SIZE size)
{
	ER ercd;

	if (p == NULL)
		return E_MACV;
	if (cpu.kind != EXEC_TASK || runtsk->cfg->domid == TDOM_KERNEL)
		return E_OK;
	/* part of the calling service call, which has paid for it */
	runtsk->nocharge_depth++;
	ercd = prb_mem(p, size, TSK_SELF, TPM_WRITE);
	runtsk->nocharge_depth--;
	return ercd != E_OK ? E_MACV : E_OK;
}

/* Creates the control blocks and stacks of the configured tasks (rows already checked). */
ER task_create_all(void)
{
	for (uint_t pri = 1; pri <= TMAX_TPRI; pri++)
		queue_init(&ready_queue[pri]);
	ready_map = 0;
	runtsk = NULL;
	schedtsk = NULL;
	for (ID id = 1; id <= TNUM_TSKID; id++) {
		struct tcb *t = tcb_table[id];
		size_t size;

		if (t == NULL)
			continue;
		size = t->cfg->stksz > HOST_MIN_STACK ? t->cfg->stksz : HOST_MIN_STACK;
		queue_init(&t->node);
		t->state = TTS_DMT;
		t->bpri = t->cfg->itskpri;
		t->base_pri = t->cfg->itskpri;
		t->tmevt.heap_index = UINT32_MAX;
		t->tmevt.callback = wait_timeout;
		if (!co_create(&t->co, size, task_entry))
			return E_NOMEM;
	}
	return E_OK;
}

/* Frees every task control block and stack. */
void task_destroy_all(void)
{
	for (ID id = 1; id <= TNUM_TSKID; id++) {
		if (tcb_table[id] != NULL) {
			co_destroy(&tcb_table[id]->co);
			free(tcb_table[id]);
			tcb_table[id] = NULL;
		}
	}
	runtsk = NULL;
	schedtsk = NULL;
	ready_map = 0;
}

/* ---- Task management ---- */

/* Activates a dormant task or queues one activation (E_QOVR beyond). */
static ER activate_or_queue(struct tcb *t)
{
	if (t->state == TTS_DMT) {
		task_activate(t);
		return E_OK;
	}
	if (t->actcnt >= TMAX_ACTCNT)
		return E_QOVR;
	t->actcnt++;
	return E_OK;
}

/* Activates a task, or queues one activation if it is not dormant. */
ER act_tsk(ID tskid)
{
	struct tcb *t;
	ER ercd = E_OK;

	svc_charge();
	if (!ctx_task_unlocked())
		return svc_result("act_tsk", E_CTX);
	if ((t = task_lookup(tskid, true, &ercd)) == NULL)
		return svc_result("act_tsk", ercd);
	ercd = activate_or_queue(t);
	dispatch_if_needed();
	return svc_result("act_tsk", ercd);
}

/* act_tsk from non-task context; the dispatch happens on return from the interrupt. */
ER iact_tsk(ID tskid)
{
	struct tcb *t;
	ER ercd = E_OK;

	svc_charge();
	if (!ctx_nontask_unlocked())
		return svc_result("iact_tsk", E_CTX);
	if ((t = task_lookup(tskid, false, &ercd)) == NULL)
		return svc_result("iact_tsk", ercd);
	return svc_result("iact_tsk", activate_or_queue(t));
}

/* Cancels queued activations; returns how many there were. */
ER_UINT can_act(ID tskid)
{
	struct tcb *t;
	ER ercd = E_OK;
	uint_t n;

	svc_charge();
	if (!ctx_task_unlocked())
		return svc_result("can_act", E_CTX);
	if ((t = task_lookup(tskid, true, &ercd)) == NULL)
		return svc_result("can_act", ercd);
	n = t->actcnt;
	t->actcnt = 0;
	return (ER_UINT)n;
}

/* Ends the calling task; from non-task context it is a reported bug and returns E_CTX. */
ER ext_tsk(void)
{
	svc_charge();
	if (cpu.kind != EXEC_TASK || cpu.isr_depth != 0) {
		svc_result("ext_tsk", E_CTX);
		rtos_host_bug("ext_tsk", "called from non-task context (E_CTX)");
		return E_CTX;
	}
	task_exit_running();
	return E_SYS;           /* not reached: the task has ended */
}

/* Changes a task's base priority; a ready task goes to the tail of its new priority. */
ER chg_pri(ID tskid, PRI tskpri)
{
	struct tcb *t;
	ER ercd = E_OK;
	PRI newpri;

	svc_charge();
	if (!ctx_task_unlocked())
		return svc_result("chg_pri", E_CTX);
	if ((t = task_lookup(tskid, true, &ercd)) == NULL)
		return svc_result("chg_pri", ercd);
	if (tskpri != TPRI_INI && (tskpri < TMIN_TPRI || tskpri > TMAX_TPRI))
		return svc_result("chg_pri", E_PAR);
	if (t->state == TTS_DMT)
		return svc_result("chg_pri", E_OBJ);
	newpri = tskpri == TPRI_INI ? t->cfg->itskpri : tskpri;
	/* HRP2: a base priority above the ceiling of a mutex the task holds or waits for */
	for (const struct mtxcb *m = t->mtx_last; m != NULL; m = m->prev_locked)
		if (m->cfg->mtxatr == TA_CEILING && newpri < m->cfg->ceilpri)
			return svc_result("chg_pri", E_ILUSE);
	if (t->state == TTS_WAI && t->wait == WAIT_MTX && mtx_table[t->wobjid]->cfg->mtxatr == TA_CEILING &&
	    newpri < mtx_table[t->wobjid]->cfg->ceilpri)
		return svc_result("chg_pri", E_ILUSE);
	t->base_pri = newpri;
	task_set_priority(t, mtx_effective_priority(t), false);
	if (t->state == TTS_WAI && t->wait == WAIT_MTX)
		mtx_waiter_left(t->wobjid);	/* the owner inherits the waiter's new priority */
	dispatch_if_needed();
	return E_OK;
}

/* Reads a task's current priority. */
ER get_pri(ID tskid, PRI *p_tskpri)
{
	struct tcb *t;
	ER ercd = E_OK;

	svc_charge();
	if (!ctx_task_unlocked())
		return svc_result("get_pri", E_CTX);
	if ((t = task_lookup(tskid, true, &ercd)) == NULL)
		return svc_result("get_pri", ercd);
	if (check_out_ptr(p_tskpri, sizeof(*p_tskpri)) != E_OK)
		return svc_result("get_pri", E_MACV);
	if (t->state == TTS_DMT)
		return svc_result("get_pri", E_OBJ);
	*p_tskpri = t->bpri;
	return E_OK;
}

/* ID of the running task (task context). */
ER get_tid(ID *p_tskid)
{
	svc_charge();
	if (cpu.kind != EXEC_TASK)
		return svc_result("get_tid", E_CTX);
	if (check_out_ptr(p_tskid, sizeof(*p_tskid)) != E_OK)
		return svc_result("get_tid", E_MACV);
	*p_tskid = runtsk->id;
	return E_OK;
}

/* The calling task's extended information (its CRE_TSK exinf). */
ER get_inf(intptr_t *p_exinf)
{
	svc_charge();
	if (!ctx_task_unlocked())
		return svc_result("get_inf", E_CTX);
	if (check_out_ptr(p_exinf, sizeof(*p_exinf)) != E_OK)
		return svc_result("get_inf", E_MACV);
	*p_exinf = runtsk->cfg->exinf;
	return E_OK;
}

/* ID of the task the interrupt came on top of, TSK_NONE if the CPU was idle. */
ER iget_tid(ID *p_tskid)
{
	svc_charge();
	if (cpu.kind == EXEC_TASK)
		return svc_result("iget_tid", E_CTX);
	if (p_tskid == NULL)
		return svc_result("iget_tid", E_MACV);
	*p_tskid = runtsk != NULL ? runtsk->id : TSK_NONE;
	return E_OK;
}

/* ---- Task-dependent synchronisation ---- */

/* Sleeps until woken (a queued wakeup is consumed at once). */
ER slp_tsk(void)
{
	svc_charge();
	if (!ctx_may_block())
		return svc_result("slp_tsk", E_CTX);
	if (runtsk->wupcnt > 0) {
		runtsk->wupcnt--;
		return E_OK;
	}
	return svc_result("slp_tsk", wait_block(WAIT_SLP, 0, NULL, false, TMO_FEVR));
}

/* Sleeps until woken or tmout ms (E_TMOUT). */
ER tslp_tsk(TMO tmout)
{
	struct tcb *t;

	svc_charge();
	if (!ctx_may_block())
		return svc_result("tslp_tsk", E_CTX);
	if (!tmout_valid(tmout))
		return svc_result("tslp_tsk", E_PAR);
	t = runtsk;
	if (t->wupcnt > 0) {
		t->wupcnt--;
		return E_OK;
	}
	if (tmout == TMO_POL)
		return svc_result("tslp_tsk", E_TMOUT);
	return svc_result("tslp_tsk", wait_block(WAIT_SLP, 0, NULL, false, tmout));
}

/* Wakes a sleeping task or queues one wakeup (E_OBJ dormant, E_QOVR beyond). */
static ER wakeup(struct tcb *t)
{
	if (t->state == TTS_DMT)
		return E_OBJ;
	if (t->state == TTS_WAI && t->wait == WAIT_SLP) {
		wait_release(t, E_OK);
		return E_OK;
	}
	if (t->wupcnt >= TMAX_WUPCNT)
		return E_QOVR;
	t->wupcnt++;
	return E_OK;
}

/* Wakes a sleeping task, or queues one wakeup. */
ER wup_tsk(ID tskid)
{
	struct tcb *t;
	ER ercd = E_OK;

	svc_charge();
	if (!ctx_task_unlocked())
		return svc_result("wup_tsk", E_CTX);
	if ((t = task_lookup(tskid, true, &ercd)) == NULL)
		return svc_result("wup_tsk", ercd);
	ercd = wakeup(t);
	dispatch_if_needed();
	return svc_result("wup_tsk", ercd);
}

/* wup_tsk from non-task context. */
ER iwup_tsk(ID tskid)
{
	struct tcb *t;
	ER ercd = E_OK;

	svc_charge();
	if (!ctx_nontask_unlocked())
		return svc_result("iwup_tsk", E_CTX);
	if ((t = task_lookup(tskid, false, &ercd)) == NULL)
		return svc_result("iwup_tsk", ercd);
	return svc_result("iwup_tsk", wakeup(t));
}

/* Cancels queued wakeups; returns how many there were. */
ER_UINT can_wup(ID tskid)
{
	struct tcb *t;
	ER ercd = E_OK;
	uint_t n;

	svc_charge();
	if (!ctx_task_unlocked())
		return svc_result("can_wup", E_CTX);
	if ((t = task_lookup(tskid, true, &ercd)) == NULL)
		return svc_result("can_wup", ercd);
	if (t->state == TTS_DMT)
		return svc_result("can_wup", E_OBJ);
	n = t->wupcnt;
	t->wupcnt = 0;
	return (ER_UINT)n;
}

/* Forces a waiting task out with E_RLWAI (E_OBJ if not waiting). */
static ER release_wait(struct tcb *t)
{
	if (t->state != TTS_WAI)
		return E_OBJ;
	wait_release(t, E_RLWAI);
	return E_OK;
}

/* Forces a waiting task out of its wait with E_RLWAI. */
ER rel_wai(ID tskid)
{
	struct tcb *t;
	ER ercd = E_OK;

	svc_charge();
	if (!ctx_task_unlocked())
		return svc_result("rel_wai", E_CTX);
	if ((t = task_lookup(tskid, false, &ercd)) == NULL)
		return svc_result("rel_wai", ercd);
	ercd = release_wait(t);
	dispatch_if_needed();
	return svc_result("rel_wai", ercd);
}

/* rel_wai from non-task context. */
ER irel_wai(ID tskid)
{
	struct tcb *t;
	ER ercd = E_OK;

	svc_charge();
	if (!ctx_nontask_unlocked())
		return svc_result("irel_wai", E_CTX);
	if ((t = task_lookup(tskid, false, &ercd)) == NULL)
		return svc_result("irel_wai", ercd);
	return svc_result("irel_wai", release_wait(t));
}

/* Delays the calling task for at least dlytim ms (rel_wai ends it early with E_RLWAI). */
ER dly_tsk(RELTIM dlytim)
{
	svc_charge();
	if (!ctx_may_block())
		return svc_result("dly_tsk", E_CTX);
	if (dlytim > svc_reltim_max())
		return svc_result("dly_tsk", E_PAR);
	return svc_result("dly_tsk", wait_block(WAIT_DLY, 0, NULL, false, (TMO)dlytim));
}

/* ---- Suspension and termination ---- */

/* Suspends a task: a ready one leaves the ready queue, a waiting one keeps waiting (TTS_WAS). */
ER sus_tsk(ID tskid)
{
	struct tcb *t;
	ER ercd = E_OK;

	svc_charge();
	if (!ctx_task_unlocked())
		return svc_result("sus_tsk", E_CTX);
	if ((t = task_lookup(tskid, true, &ercd)) == NULL)
		return svc_result("sus_tsk", ercd);
	if (t == runtsk && cpu.dsp_disabled)
		return svc_result("sus_tsk", E_CTX);
	if (t->state == TTS_DMT)
		return svc_result("sus_tsk", E_OBJ);
	if (t->suspended)
		return svc_result("sus_tsk", E_QOVR);
	t->suspended = true;
	if (t->state == TTS_RDY) {
		ready_remove(t);
		t->state = TTS_SUS;
	}
	trace_task("suspend", t);
	dispatch_if_needed();
	return E_OK;
}

/* Resumes a suspended task (E_OBJ if it is not suspended). */
ER rsm_tsk(ID tskid)
{
	struct tcb *t;
	ER ercd = E_OK;

	svc_charge();
	if (!ctx_task_unlocked())
		return svc_result("rsm_tsk", E_CTX);
	if ((t = task_lookup(tskid, false, &ercd)) == NULL)
		return svc_result("rsm_tsk", ercd);
	if (!t->suspended)
		return svc_result("rsm_tsk", E_OBJ);
	t->suspended = false;
	if (t->state == TTS_SUS) {
		t->state = TTS_RDY;
		ready_insert_tail(t);
	}
	trace_task("resume", t);
	dispatch_if_needed();
	return E_OK;
}

/* Terminates another task: out of its queues, its mutexes unlocked; a queued activation restarts it. */
ER ter_tsk(ID tskid)
{
	struct tcb *t;
	ER ercd = E_OK;

	svc_charge();
	if (!ctx_task_unlocked())
		return svc_result("ter_tsk", E_CTX);
	if ((t = task_lookup(tskid, true, &ercd)) == NULL)
		return svc_result("ter_tsk", ercd);
	if (t == runtsk)
		return svc_result("ter_tsk", E_ILUSE);
	if (t->state == TTS_DMT)
		return svc_result("ter_tsk", E_OBJ);
	if (t->state == TTS_RDY)
		ready_remove(t);
	else if (t->state == TTS_WAI)
		wait_cancel(t);
	if (t == paused_task)
		paused_task = NULL;
	t->state = TTS_DMT;
	t->suspended = false;
	mtx_release_all(t);
	trace_task("terminate", t);
	if (t->actcnt > 0) {
		t->actcnt--;
		task_activate(t);
	}
	dispatch_if_needed();
	return E_OK;
}
