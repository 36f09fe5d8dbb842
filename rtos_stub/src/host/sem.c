/*
 * sem.c — counting semaphores (CRE_SEM): wait queues in FIFO or priority
 * order (TA_TPRI), E_QOVR when a release would exceed maxsem.
 */
#include <stdlib.h>

#include "kernel_impl.h"

struct semcb *sem_table[TNUM_SEMID + 1];

/* Resolves a semaphore ID; NULL and *ercd (E_ID/E_NOEXS) on failure. */
static struct semcb *sem_lookup(ID semid, ER *ercd)
{
	if (semid < 1 || semid > TNUM_SEMID) {
		*ercd = E_ID;
		return NULL;
	}
	if (sem_table[semid] == NULL) {
		*ercd = E_NOEXS;
		return NULL;
	}
	return sem_table[semid];
}

/* Gives the resource to the first waiter, or counts it (E_QOVR at maxsem). */
static ER sem_signal(struct semcb *s)
{
	if (!queue_empty(&s->wq)) {
		wait_release(container_of_kernel(s->wq.next, struct tcb, node), E_OK);
		return E_OK;
	}
	if (s->cnt >= s->cfg->maxsem)
		return E_QOVR;
	s->cnt++;
	return E_OK;
}

/* Releases one resource; a waiter of higher priority runs at once. */
ER sig_sem(ID semid)
{
	struct semcb *s;
	ER ercd = E_OK;

	svc_charge();
	if (!ctx_task_unlocked())
		return svc_result("sig_sem", E_CTX);
	if ((s = sem_lookup(semid, &ercd)) == NULL)
		return svc_result("sig_sem", ercd);
	ercd = sem_signal(s);
	dispatch_if_needed();
	return svc_result("sig_sem", ercd);
}

/* sig_sem from non-task context; the dispatch happens on return from the interrupt. */
ER isig_sem(ID semid)
{
	struct semcb *s;
	ER ercd = E_OK;

	svc_charge();
	if (!ctx_nontask_unlocked())
		return svc_result("isig_sem", E_CTX);
	if ((s = sem_lookup(semid, &ercd)) == NULL)
		return svc_result("isig_sem", ercd);
	return svc_result("isig_sem", sem_signal(s));
}

/* Common body; polling: pol_sem (needs no dispatching), else a blocking call. */
static ER sem_wait(const char *svc, ID semid, TMO tmout, bool polling)
{
	struct semcb *s;
	ER ercd = E_OK;

	if (polling ? !ctx_task_unlocked() : !ctx_may_block())
		return svc_result(svc, E_CTX);
	if ((s = sem_lookup(semid, &ercd)) == NULL)
		return svc_result(svc, ercd);
	if (!tmout_valid(tmout))
		return svc_result(svc, E_PAR);
	if (s->cnt > 0) {
		s->cnt--;
		return E_OK;
	}
	if (tmout == TMO_POL)
		return svc_result(svc, E_TMOUT);
	return svc_result(svc, wait_block(WAIT_SEM, semid, &s->wq,
					  (s->cfg->sematr & TA_TPRI) != 0, tmout));
}

/* Acquires one resource, waiting as long as needed. */
ER wai_sem(ID semid)
{
	svc_charge();
	return sem_wait("wai_sem", semid, TMO_FEVR, false);
}

/* Acquires one resource if available, else E_TMOUT. */
ER pol_sem(ID semid)
{
	svc_charge();
	return sem_wait("pol_sem", semid, TMO_POL, true);
}

/* Acquires one resource, waiting at most tmout ms (E_TMOUT). */
ER twai_sem(ID semid, TMO tmout)
{
	svc_charge();
	return sem_wait("twai_sem", semid, tmout, false);
}

/* Returns the semaphore to its initial count; its waiters get E_DLT. */
ER ini_sem(ID semid)
{
	struct semcb *s;
	ER ercd = E_OK;

	svc_charge();
	if (!ctx_task_unlocked())
		return svc_result("ini_sem", E_CTX);
	if ((s = sem_lookup(semid, &ercd)) == NULL)
		return svc_result("ini_sem", ercd);
	s->cnt = s->cfg->isemcnt;
	while (!queue_empty(&s->wq))
		wait_release(container_of_kernel(s->wq.next, struct tcb, node), E_DLT);
	dispatch_if_needed();
	return E_OK;
}

/* Reports the first waiting task and the count. */
ER ref_sem(ID semid, T_RSEM *pk_rsem)
{
	struct semcb *s;
	ER ercd = E_OK;

	svc_charge();
	if (!ctx_task_unlocked())
		return svc_result("ref_sem", E_CTX);
	if ((s = sem_lookup(semid, &ercd)) == NULL)
		return svc_result("ref_sem", ercd);
	if (check_out_ptr(pk_rsem, sizeof(*pk_rsem)) != E_OK)
		return svc_result("ref_sem", E_MACV);
	pk_rsem->wtskid = queue_empty(&s->wq) ? TSK_NONE :
		container_of_kernel(s->wq.next, struct tcb, node)->id;
	pk_rsem->semcnt = s->cnt;
	return E_OK;
}
