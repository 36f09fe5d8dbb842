/*
 * mtx.c — mutexes (CRE_MTX) as TOPPERS/HRP2 specifies them: TA_CEILING
 * raises the holder to the ceiling priority while it holds the mutex
 * (locking with a base priority above the ceiling is E_ILUSE); TA_INHERIT
 * (uITRON 4.0's priority inheritance, beyond HRP2) raises the holder to its
 * highest waiter's priority, along chains of holders.  A task unlocks its
 * mutexes in the reverse order of locking (E_OBJ otherwise), and a task that
 * ends (ext_tsk, ter_tsk) unlocks the ones it still holds.  A priority
 * changed by a mutex operation puts a ready task first among its new peers
 * (the holder keeps the CPU when its priority rises).
 */
#include <stdlib.h>

#include "kernel_impl.h"

struct mtxcb *mtx_table[TNUM_MTXID + 1];

/* Resolves a mutex ID; NULL and *ercd (E_ID/E_NOEXS) on failure. */
static struct mtxcb *mtx_lookup(ID mtxid, ER *ercd)
{
	if (mtxid < 1 || mtxid > TNUM_MTXID) {
		*ercd = E_ID;
		return NULL;
	}
	if (mtx_table[mtxid] == NULL) {
		*ercd = E_NOEXS;
		return NULL;
	}
	return mtx_table[mtxid];
}

/* The priority t runs at: base, raised by ceilings and inherited waiters. */
PRI mtx_effective_priority(const struct tcb *t)
{
	PRI pri = t->base_pri;

	for (const struct mtxcb *m = t->mtx_last; m != NULL; m = m->prev_locked) {
		if (m->cfg->mtxatr == TA_CEILING && m->cfg->ceilpri < pri)
			pri = m->cfg->ceilpri;
		if (m->cfg->mtxatr == TA_INHERIT && !queue_empty(&m->wq)) {
			const struct tcb *w = container_of_kernel(m->wq.next, struct tcb, node);

			if (w->bpri < pri)
				pri = w->bpri;
		}
	}
	return pri;
}

/* Recomputes t's current priority; follows the chain while t waits for an inheriting mutex. */
void mtx_update_priority(struct tcb *t)
{
	for (int depth = 0; t != NULL && t->state != TTS_DMT && depth <= TNUM_TSKID; depth++) {
		PRI pri = mtx_effective_priority(t);
		struct mtxcb *waited;

		if (pri == t->bpri)
			return;
		task_set_priority(t, pri, true);
		if (t->state != TTS_WAI || t->wait != WAIT_MTX)
			return;
		waited = mtx_table[t->wobjid];
		if (waited->cfg->mtxatr != TA_INHERIT)
			return;
		t = waited->owner;
	}
}

/* A waiter left mutex mtxid's queue: its owner's inherited priority may drop. */
void mtx_waiter_left(ID mtxid)
{
	struct mtxcb *m = mtx_table[mtxid];

	if (m->owner != NULL && m->cfg->mtxatr == TA_INHERIT)
		mtx_update_priority(m->owner);
}

/* Makes t the owner of m (last in its locking order). */
static void mtx_acquire(struct mtxcb *m, struct tcb *t)
{
	m->owner = t;
	m->prev_locked = t->mtx_last;
	t->mtx_last = m;
}

/* Removes m from its owner's locking order (usually the top). */
static void mtx_unlink(struct mtxcb *m)
{
	struct mtxcb **pp = &m->owner->mtx_last;

	while (*pp != NULL && *pp != m)
		pp = &(*pp)->prev_locked;
	if (*pp == m)
		*pp = m->prev_locked;
	m->prev_locked = NULL;
	m->owner = NULL;
}

/* Gives m to its first waiter, if any (the caller recomputes the old owner). */
static void mtx_hand_over(struct mtxcb *m)
{
	struct tcb *w;

	if (queue_empty(&m->wq))
		return;
	w = container_of_kernel(m->wq.next, struct tcb, node);
	mtx_acquire(m, w);
	wait_release(w, E_OK);
	mtx_update_priority(w);
}

/* Unlocks every mutex t holds, newest first, handing each to its first waiter. */
void mtx_release_all(struct tcb *t)
{
	while (t->mtx_last != NULL) {
		struct mtxcb *m = t->mtx_last;

		mtx_unlink(m);
		mtx_hand_over(m);
	}
	t->bpri = t->base_pri;
}

/* Common body of loc_mtx, ploc_mtx and tloc_mtx. */
static ER mtx_lock(const char *svc, ID mtxid, TMO tmout, bool polling)
{
	struct mtxcb *m;
	ER ercd = E_OK;

	if (polling ? !ctx_task_unlocked() : !ctx_may_block())
		return svc_result(svc, E_CTX);
	if ((m = mtx_lookup(mtxid, &ercd)) == NULL)
		return svc_result(svc, ercd);
	if (!tmout_valid(tmout))
		return svc_result(svc, E_PAR);
	if (m->cfg->mtxatr == TA_CEILING && runtsk->base_pri < m->cfg->ceilpri)
		return svc_result(svc, E_ILUSE);
	if (m->owner == runtsk)
		return svc_result(svc, E_OBJ);
	if (m->owner == NULL) {
		mtx_acquire(m, runtsk);
		mtx_update_priority(runtsk);
		return E_OK;
	}
	if (tmout == TMO_POL)
		return svc_result(svc, E_TMOUT);
	wait_enter(WAIT_MTX, mtxid, &m->wq, m->cfg->mtxatr != TA_NULL, tmout);
	/* queued first, so that an inheriting owner sees this waiter */
	if (m->cfg->mtxatr == TA_INHERIT)
		mtx_update_priority(m->owner);
	task_switch();
	return svc_result(svc, runtsk->wercd);
}

/* Locks a mutex, waiting while another task holds it. */
ER loc_mtx(ID mtxid)
{
	svc_charge();
	return mtx_lock("loc_mtx", mtxid, TMO_FEVR, false);
}

/* Locks a mutex if it is free, else E_TMOUT. */
ER ploc_mtx(ID mtxid)
{
	svc_charge();
	return mtx_lock("ploc_mtx", mtxid, TMO_POL, true);
}

/* Locks a mutex, waiting at most tmout ms. */
ER tloc_mtx(ID mtxid, TMO tmout)
{
	svc_charge();
	return mtx_lock("tloc_mtx", mtxid, tmout, false);
}

/* Unlocks the mutex the caller locked last; its first waiter gets it. */
ER unl_mtx(ID mtxid)
{
	struct mtxcb *m;
	ER ercd = E_OK;
	struct tcb *t;

	svc_charge();
	if (!ctx_task_unlocked())
		return svc_result("unl_mtx", E_CTX);
	if ((m = mtx_lookup(mtxid, &ercd)) == NULL)
		return svc_result("unl_mtx", ercd);
	t = runtsk;
	if (m->owner != t || t->mtx_last != m)
		return svc_result("unl_mtx", E_OBJ);
	mtx_unlink(m);
	mtx_update_priority(t);
	mtx_hand_over(m);
	dispatch_if_needed();
	return E_OK;
}

/* Re-initialises a mutex: the holder loses it, waiters get E_DLT. */
ER ini_mtx(ID mtxid)
{
	struct mtxcb *m;
	ER ercd = E_OK;

	svc_charge();
	if (!ctx_task_unlocked())
		return svc_result("ini_mtx", E_CTX);
	if ((m = mtx_lookup(mtxid, &ercd)) == NULL)
		return svc_result("ini_mtx", ercd);
	if (m->owner != NULL) {
		struct tcb *owner = m->owner;

		mtx_unlink(m);
		mtx_update_priority(owner);
	}
	while (!queue_empty(&m->wq))
		wait_release(container_of_kernel(m->wq.next, struct tcb, node), E_DLT);
	dispatch_if_needed();
	return E_OK;
}

/* Reports the holder and the first waiter. */
ER ref_mtx(ID mtxid, T_RMTX *pk_rmtx)
{
	struct mtxcb *m;
	ER ercd = E_OK;

	svc_charge();
	if (!ctx_task_unlocked())
		return svc_result("ref_mtx", E_CTX);
	if ((m = mtx_lookup(mtxid, &ercd)) == NULL)
		return svc_result("ref_mtx", ercd);
	if (check_out_ptr(pk_rmtx, sizeof(*pk_rmtx)) != E_OK)
		return svc_result("ref_mtx", E_MACV);
	pk_rmtx->htskid = m->owner != NULL ? m->owner->id : TSK_NONE;
	pk_rmtx->wtskid = queue_empty(&m->wq) ? TSK_NONE : container_of_kernel(m->wq.next, struct tcb, node)->id;
	return E_OK;
}

/* Creates a mutex from its (checked) row. */
ER mtx_create(const struct rtos_mtx_cfg *cfg)
{
	struct mtxcb *m = calloc(1, sizeof(*m));

	if (m == NULL)
		return E_NOMEM;
	m->cfg = cfg;
	queue_init(&m->wq);
	mtx_table[cfg->mtxid] = m;
	return E_OK;
}
