/*
 * dtq.c — data queues (CRE_DTQ) and priority data queues (CRE_PDQ) of
 * intptr_t elements, as TOPPERS/HRP2 specifies them.
 *
 * A sender hands its element straight to a waiting receiver, else queues it,
 * else (full) waits in the send queue (FIFO, or by task priority with
 * TA_TPRI).  A receiver takes the oldest element (the highest-priority one in
 * a priority data queue), and the first waiting sender's element takes the
 * freed place; with capacity 0 sender and receiver meet directly.  Receivers
 * always wait in FIFO order.  fsnd_dtq drops the oldest element instead of
 * waiting (E_ILUSE with capacity 0).  ini_* empties the queue and releases
 * every waiting task with E_DLT.
 */
#include <stdlib.h>

#include "kernel_impl.h"

struct dtqcb *dtq_table[TNUM_DTQID + 1];
struct pdqcb *pdq_table[TNUM_PDQID + 1];

/* The first task of a wait queue, NULL if none. */
static struct tcb *first_waiter(struct queue *wq)
{
	return queue_empty(wq) ? NULL : container_of_kernel(wq->next, struct tcb, node);
}

/* Releases every task of a wait queue with ercd. */
static void release_all(struct queue *wq, ER ercd)
{
	while (!queue_empty(wq))
		wait_release(container_of_kernel(wq->next, struct tcb, node), ercd);
}

/* ---- Data queues ---- */

static struct dtqcb *dtq_lookup(ID dtqid, ER *ercd)
{
	if (dtqid < 1 || dtqid > TNUM_DTQID) {
		*ercd = E_ID;
		return NULL;
	}
	if (dtq_table[dtqid] == NULL) {
		*ercd = E_NOEXS;
		return NULL;
	}
	return dtq_table[dtqid];
}

static void dtq_push(struct dtqcb *d, intptr_t data)
{
	d->buf[(d->head + d->count) % d->cfg->dtqcnt] = data;
	d->count++;
}

static intptr_t dtq_pop(struct dtqcb *d)
{
	intptr_t data = d->buf[d->head];

	d->head = (d->head + 1) % d->cfg->dtqcnt;
	d->count--;
	return data;
}

/* Delivers data to a waiting receiver or the queue; false if the caller must wait. */
static bool dtq_deliver(struct dtqcb *d, intptr_t data)
{
	struct tcb *r = first_waiter(&d->rwq);

	if (r != NULL) {
		r->wdata = data;
		wait_release(r, E_OK);
		return true;
	}
	if (d->count < d->cfg->dtqcnt) {
		dtq_push(d, data);
		return true;
	}
	return false;
}

/* Common body of the sending calls; nontask: the i-call (no waiting). */
static ER dtq_send(const char *svc, ID dtqid, intptr_t data, TMO tmout, bool nontask)
{
	struct dtqcb *d;
	ER ercd = E_OK;

	if (nontask ? !ctx_nontask_unlocked() : (tmout == TMO_POL ? !ctx_task_unlocked() : !ctx_may_block()))
		return svc_result(svc, E_CTX);
	if ((d = dtq_lookup(dtqid, &ercd)) == NULL)
		return svc_result(svc, ercd);
	if (!tmout_valid(tmout))
		return svc_result(svc, E_PAR);
	if (dtq_deliver(d, data)) {
		if (!nontask)
			dispatch_if_needed();
		return E_OK;
	}
	if (tmout == TMO_POL)
		return svc_result(svc, E_TMOUT);
	runtsk->wdata = data;
	return svc_result(svc, wait_block(WAIT_SDTQ, dtqid, &d->swq, (d->cfg->dtqatr & TA_TPRI) != 0, tmout));
}

ER snd_dtq(ID dtqid, intptr_t data)
{
	svc_charge();
	return dtq_send("snd_dtq", dtqid, data, TMO_FEVR, false);
}

ER psnd_dtq(ID dtqid, intptr_t data)
{
	svc_charge();
	return dtq_send("psnd_dtq", dtqid, data, TMO_POL, false);
}

ER ipsnd_dtq(ID dtqid, intptr_t data)
{
	svc_charge();
	return dtq_send("ipsnd_dtq", dtqid, data, TMO_POL, true);
}

ER tsnd_dtq(ID dtqid, intptr_t data, TMO tmout)
{
	svc_charge();
	return dtq_send("tsnd_dtq", dtqid, data, tmout, false);
}

/* Forced send: a full queue loses its oldest element. */
static ER dtq_force(const char *svc, ID dtqid, intptr_t data, bool nontask)
{
	struct dtqcb *d;
	ER ercd = E_OK;

	if (nontask ? !ctx_nontask_unlocked() : !ctx_task_unlocked())
		return svc_result(svc, E_CTX);
	if ((d = dtq_lookup(dtqid, &ercd)) == NULL)
		return svc_result(svc, ercd);
	if (d->cfg->dtqcnt == 0)
		return svc_result(svc, E_ILUSE);
	if (!dtq_deliver(d, data)) {
		(void)dtq_pop(d);
		dtq_push(d, data);
	}
	if (!nontask)
		dispatch_if_needed();
	return E_OK;
}

ER fsnd_dtq(ID dtqid, intptr_t data)
{
	svc_charge();
	return dtq_force("fsnd_dtq", dtqid, data, false);
}

ER ifsnd_dtq(ID dtqid, intptr_t data)
{
	svc_charge();
	return dtq_force("ifsnd_dtq", dtqid, data, true);
}

/* Common body of the receiving calls. */
static ER dtq_receive(const char *svc, ID dtqid, intptr_t *p_data, TMO tmout)
{
	struct dtqcb *d;
	struct tcb *s;
	ER ercd = E_OK;

	if (tmout == TMO_POL ? !ctx_task_unlocked() : !ctx_may_block())
		return svc_result(svc, E_CTX);
	if ((d = dtq_lookup(dtqid, &ercd)) == NULL)
		return svc_result(svc, ercd);
	if (!tmout_valid(tmout))
		return svc_result(svc, E_PAR);
	if (check_out_ptr(p_data, sizeof(*p_data)) != E_OK)
		return svc_result(svc, E_MACV);
	s = first_waiter(&d->swq);
	if (d->count > 0) {
		*p_data = dtq_pop(d);
		if (s != NULL) {
			dtq_push(d, s->wdata);
			wait_release(s, E_OK);
		}
	} else if (s != NULL) {
		*p_data = s->wdata;
		wait_release(s, E_OK);
	} else if (tmout == TMO_POL) {
		return svc_result(svc, E_TMOUT);
	} else {
		ercd = wait_block(WAIT_RDTQ, dtqid, &d->rwq, false, tmout);
		if (ercd == E_OK)
			*p_data = runtsk->wdata;
		return svc_result(svc, ercd);
	}
	dispatch_if_needed();
	return E_OK;
}

ER rcv_dtq(ID dtqid, intptr_t *p_data)
{
	svc_charge();
	return dtq_receive("rcv_dtq", dtqid, p_data, TMO_FEVR);
}

ER prcv_dtq(ID dtqid, intptr_t *p_data)
{
	svc_charge();
	return dtq_receive("prcv_dtq", dtqid, p_data, TMO_POL);
}

ER trcv_dtq(ID dtqid, intptr_t *p_data, TMO tmout)
{
	svc_charge();
	return dtq_receive("trcv_dtq", dtqid, p_data, tmout);
}

/* Empties the queue; waiting senders and receivers get E_DLT. */
ER ini_dtq(ID dtqid)
{
	struct dtqcb *d;
	ER ercd = E_OK;

	svc_charge();
	if (!ctx_task_unlocked())
		return svc_result("ini_dtq", E_CTX);
	if ((d = dtq_lookup(dtqid, &ercd)) == NULL)
		return svc_result("ini_dtq", ercd);
	d->head = 0;
	d->count = 0;
	release_all(&d->swq, E_DLT);
	release_all(&d->rwq, E_DLT);
	dispatch_if_needed();
	return E_OK;
}

/* Reports the first waiting sender and receiver and the element count. */
ER ref_dtq(ID dtqid, T_RDTQ *pk_rdtq)
{
	struct dtqcb *d;
	ER ercd = E_OK;

	svc_charge();
	if (!ctx_task_unlocked())
		return svc_result("ref_dtq", E_CTX);
	if ((d = dtq_lookup(dtqid, &ercd)) == NULL)
		return svc_result("ref_dtq", ercd);
	if (check_out_ptr(pk_rdtq, sizeof(*pk_rdtq)) != E_OK)
		return svc_result("ref_dtq", E_MACV);
	pk_rdtq->stskid = queue_empty(&d->swq) ? TSK_NONE : first_waiter(&d->swq)->id;
	pk_rdtq->rtskid = queue_empty(&d->rwq) ? TSK_NONE : first_waiter(&d->rwq)->id;
	pk_rdtq->sdtqcnt = d->count;
	return E_OK;
}

/* ---- Priority data queues ---- */

static struct pdqcb *pdq_lookup(ID pdqid, ER *ercd)
{
	if (pdqid < 1 || pdqid > TNUM_PDQID) {
		*ercd = E_ID;
		return NULL;
	}
	if (pdq_table[pdqid] == NULL) {
		*ercd = E_NOEXS;
		return NULL;
	}
	return pdq_table[pdqid];
}

/* Inserts after every element of the same or higher priority (FIFO within one). */
static void pdq_push(struct pdqcb *p, intptr_t data, PRI pri)
{
	uint_t pos = p->count;

	while (pos > 0 && p->buf[pos - 1].pri > pri) {
		p->buf[pos] = p->buf[pos - 1];
		pos--;
	}
	p->buf[pos].data = data;
	p->buf[pos].pri = pri;
	p->count++;
}

static struct pdq_elem pdq_pop(struct pdqcb *p)
{
	struct pdq_elem e = p->buf[0];

	p->count--;
	for (uint_t i = 0; i < p->count; i++)
		p->buf[i] = p->buf[i + 1];
	return e;
}

/* Common body of the sending calls. */
static ER pdq_send(const char *svc, ID pdqid, intptr_t data, PRI datapri, TMO tmout, bool nontask)
{
	struct pdqcb *p;
	struct tcb *r;
	ER ercd = E_OK;

	if (nontask ? !ctx_nontask_unlocked() : (tmout == TMO_POL ? !ctx_task_unlocked() : !ctx_may_block()))
		return svc_result(svc, E_CTX);
	if ((p = pdq_lookup(pdqid, &ercd)) == NULL)
		return svc_result(svc, ercd);
	if (datapri < TMIN_DPRI || datapri > p->cfg->maxdpri || !tmout_valid(tmout))
		return svc_result(svc, E_PAR);
	if ((r = first_waiter(&p->rwq)) != NULL) {
		r->wdata = data;
		r->wdpri = datapri;
		wait_release(r, E_OK);
	} else if (p->count < p->cfg->pdqcnt) {
		pdq_push(p, data, datapri);
	} else if (tmout == TMO_POL) {
		return svc_result(svc, E_TMOUT);
	} else {
		runtsk->wdata = data;
		runtsk->wdpri = datapri;
		return svc_result(svc, wait_block(WAIT_SPDQ, pdqid, &p->swq, (p->cfg->pdqatr & TA_TPRI) != 0, tmout));
	}
	if (!nontask)
		dispatch_if_needed();
	return E_OK;
}

ER snd_pdq(ID pdqid, intptr_t data, PRI datapri)
{
	svc_charge();
	return pdq_send("snd_pdq", pdqid, data, datapri, TMO_FEVR, false);
}

ER psnd_pdq(ID pdqid, intptr_t data, PRI datapri)
{
	svc_charge();
	return pdq_send("psnd_pdq", pdqid, data, datapri, TMO_POL, false);
}

ER ipsnd_pdq(ID pdqid, intptr_t data, PRI datapri)
{
	svc_charge();
	return pdq_send("ipsnd_pdq", pdqid, data, datapri, TMO_POL, true);
}

ER tsnd_pdq(ID pdqid, intptr_t data, PRI datapri, TMO tmout)
{
	svc_charge();
	return pdq_send("tsnd_pdq", pdqid, data, datapri, tmout, false);
}

/* Common body of the receiving calls. */
static ER pdq_receive(const char *svc, ID pdqid, intptr_t *p_data, PRI *p_datapri, TMO tmout)
{
	struct pdqcb *p;
	struct tcb *s;
	ER ercd = E_OK;

	if (tmout == TMO_POL ? !ctx_task_unlocked() : !ctx_may_block())
		return svc_result(svc, E_CTX);
	if ((p = pdq_lookup(pdqid, &ercd)) == NULL)
		return svc_result(svc, ercd);
	if (!tmout_valid(tmout))
		return svc_result(svc, E_PAR);
	if (check_out_ptr(p_data, sizeof(*p_data)) != E_OK || check_out_ptr(p_datapri, sizeof(*p_datapri)) != E_OK)
		return svc_result(svc, E_MACV);
	s = first_waiter(&p->swq);
	if (p->count > 0) {
		struct pdq_elem e = pdq_pop(p);

		*p_data = e.data;
		*p_datapri = e.pri;
		if (s != NULL) {
			pdq_push(p, s->wdata, s->wdpri);
			wait_release(s, E_OK);
		}
	} else if (s != NULL) {
		*p_data = s->wdata;
		*p_datapri = s->wdpri;
		wait_release(s, E_OK);
	} else if (tmout == TMO_POL) {
		return svc_result(svc, E_TMOUT);
	} else {
		ercd = wait_block(WAIT_RPDQ, pdqid, &p->rwq, false, tmout);
		if (ercd == E_OK) {
			*p_data = runtsk->wdata;
			*p_datapri = runtsk->wdpri;
		}
		return svc_result(svc, ercd);
	}
	dispatch_if_needed();
	return E_OK;
}

ER rcv_pdq(ID pdqid, intptr_t *p_data, PRI *p_datapri)
{
	svc_charge();
	return pdq_receive("rcv_pdq", pdqid, p_data, p_datapri, TMO_FEVR);
}

ER prcv_pdq(ID pdqid, intptr_t *p_data, PRI *p_datapri)
{
	svc_charge();
	return pdq_receive("prcv_pdq", pdqid, p_data, p_datapri, TMO_POL);
}

ER trcv_pdq(ID pdqid, intptr_t *p_data, PRI *p_datapri, TMO tmout)
{
	svc_charge();
	return pdq_receive("trcv_pdq", pdqid, p_data, p_datapri, tmout);
}

ER ini_pdq(ID pdqid)
{
	struct pdqcb *p;
	ER ercd = E_OK;

	svc_charge();
	if (!ctx_task_unlocked())
		return svc_result("ini_pdq", E_CTX);
	if ((p = pdq_lookup(pdqid, &ercd)) == NULL)
		return svc_result("ini_pdq", ercd);
	p->count = 0;
	release_all(&p->swq, E_DLT);
	release_all(&p->rwq, E_DLT);
	dispatch_if_needed();
	return E_OK;
}

ER ref_pdq(ID pdqid, T_RPDQ *pk_rpdq)
{
	struct pdqcb *p;
	ER ercd = E_OK;

	svc_charge();
	if (!ctx_task_unlocked())
		return svc_result("ref_pdq", E_CTX);
	if ((p = pdq_lookup(pdqid, &ercd)) == NULL)
		return svc_result("ref_pdq", ercd);
	if (check_out_ptr(pk_rpdq, sizeof(*pk_rpdq)) != E_OK)
		return svc_result("ref_pdq", E_MACV);
	pk_rpdq->stskid = queue_empty(&p->swq) ? TSK_NONE : first_waiter(&p->swq)->id;
	pk_rpdq->rtskid = queue_empty(&p->rwq) ? TSK_NONE : first_waiter(&p->rwq)->id;
	pk_rpdq->spdqcnt = p->count;
	return E_OK;
}

/* ---- Creation at boot, reset at shutdown ---- */

ER dtq_create(const struct rtos_dtq_cfg *cfg)
{
	struct dtqcb *d = calloc(1, sizeof(*d));

	if (d == NULL || (cfg->dtqcnt > 0 && (d->buf = calloc(cfg->dtqcnt, sizeof(*d->buf))) == NULL)) {
		free(d);
		return E_NOMEM;
	}
	d->cfg = cfg;
	queue_init(&d->swq);
	queue_init(&d->rwq);
	dtq_table[cfg->dtqid] = d;
	return E_OK;
}

ER pdq_create(const struct rtos_pdq_cfg *cfg)
{
	struct pdqcb *p = calloc(1, sizeof(*p));

	if (p == NULL || (cfg->pdqcnt > 0 && (p->buf = calloc(cfg->pdqcnt, sizeof(*p->buf))) == NULL)) {
		free(p);
		return E_NOMEM;
	}
	p->cfg = cfg;
	queue_init(&p->swq);
	queue_init(&p->rwq);
	pdq_table[cfg->pdqid] = p;
	return E_OK;
}

/* Frees every data queue, priority data queue and mutex. */
void dtq_pdq_mtx_reset(void)
{
	for (ID id = 0; id <= TNUM_DTQID; id++) {
		if (dtq_table[id] != NULL)
			free(dtq_table[id]->buf);
		free(dtq_table[id]);
		dtq_table[id] = NULL;
	}
	for (ID id = 0; id <= TNUM_PDQID; id++) {
		if (pdq_table[id] != NULL)
			free(pdq_table[id]->buf);
		free(pdq_table[id]);
		pdq_table[id] = NULL;
	}
	for (ID id = 0; id <= TNUM_MTXID; id++) {
		free(mtx_table[id]);
		mtx_table[id] = NULL;
	}
}
