/*
 * flg.c — eventflags (CRE_FLG): OR/AND waits, TA_WMUL for several waiters,
 * TA_CLR to clear the whole pattern when a waiter is released.
 */
#include <stdlib.h>

#include "kernel_impl.h"

struct flgcb *flg_table[TNUM_FLGID + 1];

/* Resolves an eventflag ID; NULL and *ercd (E_ID/E_NOEXS) on failure. */
static struct flgcb *flg_lookup(ID flgid, ER *ercd)
{
	if (flgid < 1 || flgid > TNUM_FLGID) {
		*ercd = E_ID;
		return NULL;
	}
	if (flg_table[flgid] == NULL) {
		*ercd = E_NOEXS;
		return NULL;
	}
	return flg_table[flgid];
}

/* True if ptn satisfies waiptn in mode wfmode. */
static bool flg_match(FLGPTN ptn, FLGPTN waiptn, MODE wfmode)
{
	return wfmode == TWF_ORW ? (ptn & waiptn) != 0 : (ptn & waiptn) == waiptn;
}

/* Sets bits and releases the waiters now satisfied, in queue order. */
static void flg_set(struct flgcb *f, FLGPTN setptn)
{
	struct queue *pos, *next;

	f->ptn |= setptn;
	for (pos = f->wq.next; pos != &f->wq; pos = next) {
		struct tcb *t = container_of_kernel(pos, struct tcb, node);

		next = pos->next;
		if (!flg_match(f->ptn, t->waiptn, t->wfmode))
			continue;
		t->flgptn = f->ptn;
		wait_release(t, E_OK);
		if (f->cfg->flgatr & TA_CLR) {
			f->ptn = 0;
			break;
		}
	}
}

/* ORs setptn into the eventflag; released waiters of higher priority run at once. */
ER set_flg(ID flgid, FLGPTN setptn)
{
	struct flgcb *f;
	ER ercd = E_OK;

	svc_charge();
	if (!ctx_task_unlocked())
		return svc_result("set_flg", E_CTX);
	if ((f = flg_lookup(flgid, &ercd)) == NULL)
		return svc_result("set_flg", ercd);
	flg_set(f, setptn);
	dispatch_if_needed();
	return E_OK;
}

/* set_flg from non-task context. */
ER iset_flg(ID flgid, FLGPTN setptn)
{
	struct flgcb *f;
	ER ercd = E_OK;

	svc_charge();
	if (!ctx_nontask_unlocked())
		return svc_result("iset_flg", E_CTX);
	if ((f = flg_lookup(flgid, &ercd)) == NULL)
		return svc_result("iset_flg", ercd);
	flg_set(f, setptn);
	return E_OK;
}

/* ANDs the pattern with clrptn. */
ER clr_flg(ID flgid, FLGPTN clrptn)
{
	struct flgcb *f;
	ER ercd = E_OK;

	svc_charge();
	if (!ctx_task_unlocked())
		return svc_result("clr_flg", E_CTX);
	if ((f = flg_lookup(flgid, &ercd)) == NULL)
		return svc_result("clr_flg", ercd);
	f->ptn &= clrptn;
	return E_OK;
}

/* Common body; polling: pol_flg (needs no dispatching), else a blocking call. */
static ER flg_wait(const char *svc, ID flgid, FLGPTN waiptn, MODE wfmode, FLGPTN *p_flgptn,
		   TMO tmout, bool polling)
{
	struct flgcb *f;
	ER ercd = E_OK;

	if (polling ? !ctx_task_unlocked() : !ctx_may_block())
		return svc_result(svc, E_CTX);
	if ((f = flg_lookup(flgid, &ercd)) == NULL)
		return svc_result(svc, ercd);
	if (waiptn == 0 || (wfmode != TWF_ORW && wfmode != TWF_ANDW) || !tmout_valid(tmout))
		return svc_result(svc, E_PAR);
	if (check_out_ptr(p_flgptn, sizeof(*p_flgptn)) != E_OK)
		return svc_result(svc, E_MACV);
	if (!(f->cfg->flgatr & TA_WMUL) && !queue_empty(&f->wq))
		return svc_result(svc, E_ILUSE);
	if (flg_match(f->ptn, waiptn, wfmode)) {
		*p_flgptn = f->ptn;
		if (f->cfg->flgatr & TA_CLR)
			f->ptn = 0;
		return E_OK;
	}
	if (tmout == TMO_POL)
		return svc_result(svc, E_TMOUT);
	runtsk->waiptn = waiptn;
	runtsk->wfmode = wfmode;
	ercd = wait_block(WAIT_FLG, flgid, &f->wq, (f->cfg->flgatr & TA_TPRI) != 0, tmout);
	if (ercd == E_OK)
		*p_flgptn = runtsk->flgptn;
	return svc_result(svc, ercd);
}

/* Waits until the pattern satisfies waiptn/wfmode; *p_flgptn gets the pattern at release. */
ER wai_flg(ID flgid, FLGPTN waiptn, MODE wfmode, FLGPTN *p_flgptn)
{
	svc_charge();
	return flg_wait("wai_flg", flgid, waiptn, wfmode, p_flgptn, TMO_FEVR, false);
}

/* wai_flg without waiting (E_TMOUT). */
ER pol_flg(ID flgid, FLGPTN waiptn, MODE wfmode, FLGPTN *p_flgptn)
{
	svc_charge();
	return flg_wait("pol_flg", flgid, waiptn, wfmode, p_flgptn, TMO_POL, true);
}

/* wai_flg with a timeout in ms (E_TMOUT). */
ER twai_flg(ID flgid, FLGPTN waiptn, MODE wfmode, FLGPTN *p_flgptn, TMO tmout)
{
	svc_charge();
	return flg_wait("twai_flg", flgid, waiptn, wfmode, p_flgptn, tmout, false);
}

/* Returns the eventflag to its initial pattern; its waiters get E_DLT. */
ER ini_flg(ID flgid)
{
	struct flgcb *f;
	ER ercd = E_OK;

	svc_charge();
	if (!ctx_task_unlocked())
		return svc_result("ini_flg", E_CTX);
	if ((f = flg_lookup(flgid, &ercd)) == NULL)
		return svc_result("ini_flg", ercd);
	f->ptn = f->cfg->iflgptn;
	while (!queue_empty(&f->wq))
		wait_release(container_of_kernel(f->wq.next, struct tcb, node), E_DLT);
	dispatch_if_needed();
	return E_OK;
}

/* Reports the first waiting task and the pattern. */
ER ref_flg(ID flgid, T_RFLG *pk_rflg)
{
	struct flgcb *f;
	ER ercd = E_OK;

	svc_charge();
	if (!ctx_task_unlocked())
		return svc_result("ref_flg", E_CTX);
	if ((f = flg_lookup(flgid, &ercd)) == NULL)
		return svc_result("ref_flg", ercd);
	if (check_out_ptr(pk_rflg, sizeof(*pk_rflg)) != E_OK)
		return svc_result("ref_flg", E_MACV);
	pk_rflg->wtskid = queue_empty(&f->wq) ? TSK_NONE :
		container_of_kernel(f->wq.next, struct tcb, node)->id;
	pk_rflg->flgptn = f->ptn;
	return E_OK;
}
