/*
 * test_dtq.c — data queues and priority data queues: FIFO order, a full
 * queue blocks the sender and the receiver's take admits it, capacity 0
 * (sender and receiver meet), psnd/prcv E_TMOUT, tsnd/trcv timeouts at
 * exact virtual times, fsnd drops the oldest (E_ILUSE at capacity 0),
 * ipsnd from a handler, TA_TPRI senders, data priorities (FIFO within one,
 * E_PAR outside 1..maxdpri), ini_* releasing waiters with E_DLT, ref_*,
 * bad IDs, E_CTX from non-task context and E_MACV for a bad pointer.
 */
#define _POSIX_C_SOURCE 200809L
#include "tap.h"
#include "kernel.h"
#include "rtos_test.h"
#include "boot_refusal_test.h"

#define MS 1000000ULL

enum { DTQ_FIFO = 1, DTQ_SYNC, DTQ_TPRI, DTQ_ISR };
enum { PDQ_MAIN = 1 };
enum { T_MAIN = 1, T_SND_A, T_SND_B, T_RCV, T_SYNC_SND, T_INI_WAIT, T_PDQ_SND };

static ER r_fifo[6], r_pol[4], r_fsnd[3], r_bad[4], r_ref, r_tmo, r_ini, r_pdq[6];
static intptr_t got[8], pgot[6];
static PRI gotpri[6];
static uint64_t t_tmo;
static T_RDTQ ref;
static ER ini_waiter_result, isr_sent, cyc_ctx;

/* Senders waiting on the TA_TPRI queue (priorities 6 and 4). */
static void sender(intptr_t x)
{
	snd_dtq(DTQ_TPRI, x);
}

static void sync_sender(intptr_t x)
{
	rt_log("s%d", (int)snd_dtq(DTQ_SYNC, 77));
}

static void ini_waiter(intptr_t x)
{
	intptr_t d;

	ini_waiter_result = rcv_dtq(DTQ_FIFO, &d);
}

static void pdq_sender(intptr_t x)
{
	/* the queue (capacity 2) is full: waits, then enters by priority */
	rt_log("p%d", (int)snd_pdq(PDQ_MAIN, 500, 1));
}

/* A kernel cyclic handler: ipsnd_dtq from non-task context. */
static void cyc(intptr_t x)
{
	static bool sent;
	intptr_t d;

	if (sent)
		return;
	sent = true;
	isr_sent = ipsnd_dtq(DTQ_ISR, 99);
	cyc_ctx = prcv_dtq(DTQ_ISR, &d);	/* task-only call: E_CTX */
}

static void main_task(intptr_t x)
{
	intptr_t d = 0;
	PRI p = 0;

	/* FIFO, capacity 3 */
	r_fifo[0] = snd_dtq(DTQ_FIFO, 1);
	r_fifo[1] = psnd_dtq(DTQ_FIFO, 2);
	r_fifo[2] = tsnd_dtq(DTQ_FIFO, 3, 5);
	r_fifo[3] = psnd_dtq(DTQ_FIFO, 4);      /* full: E_TMOUT */
	r_ref = ref_dtq(DTQ_FIFO, &ref);
	for (int i = 0; i < 3; i++)
		prcv_dtq(DTQ_FIFO, &got[i]);
	r_pol[0] = prcv_dtq(DTQ_FIFO, &d);      /* empty: E_TMOUT */
	/* fsnd: a full queue loses its oldest */
	for (intptr_t i = 10; i < 14; i++)
		r_fsnd[0] = fsnd_dtq(DTQ_FIFO, i);
	r_fsnd[1] = fsnd_dtq(DTQ_SYNC, 1);      /* capacity 0: E_ILUSE */
	prcv_dtq(DTQ_FIFO, &got[3]);            /* 11: 10 was dropped */
	prcv_dtq(DTQ_FIFO, &got[4]);
	prcv_dtq(DTQ_FIFO, &got[5]);
	/* trcv times out at exactly +2 ms from a tick boundary */
	dly_tsk(1);
	r_tmo = trcv_dtq(DTQ_FIFO, &d, 2);
	t_tmo = rtos_host_now();

	/* capacity 0: the receiver takes from the waiting sender */
	act_tsk(T_SYNC_SND);
	dly_tsk(1);
	r_pol[1] = prcv_dtq(DTQ_SYNC, &got[6]);
	r_pol[2] = psnd_dtq(DTQ_SYNC, 5);       /* nobody receiving: E_TMOUT */

	/* TA_TPRI senders: capacity 1, filled; priority 6 then 4 start waiting */
	snd_dtq(DTQ_TPRI, 100);
	act_tsk(T_SND_A);
	act_tsk(T_SND_B);
	dly_tsk(1);
	for (int i = 0; i < 3; i++) {
		rcv_dtq(DTQ_TPRI, &d);
		rt_log("t%d", (int)d);
	}

	/* ini_dtq releases a waiting receiver with E_DLT */
	act_tsk(T_INI_WAIT);
	dly_tsk(1);
	r_ini = ini_dtq(DTQ_FIFO);
	dly_tsk(1);

	/* ipsnd from the cyclic handler */
	sta_cyc(1);
	r_pol[3] = trcv_dtq(DTQ_ISR, &got[7], 10);

	/* bad IDs, bad pointer */
	r_bad[0] = snd_dtq(0, 1);
	r_bad[1] = snd_dtq(TNUM_DTQID + 1, 1);
	r_bad[2] = snd_dtq(9, 1);
	r_bad[3] = rcv_dtq(DTQ_FIFO, NULL);

	/* priority data queue: maxdpri 4, capacity 2 */
	r_pdq[0] = snd_pdq(PDQ_MAIN, 300, 3);
	r_pdq[1] = snd_pdq(PDQ_MAIN, 200, 2);
	r_pdq[2] = psnd_pdq(PDQ_MAIN, 1, 1);    /* full: E_TMOUT */
	r_pdq[3] = snd_pdq(PDQ_MAIN, 1, 5);     /* beyond maxdpri: E_PAR */
	r_pdq[4] = psnd_pdq(PDQ_MAIN, 1, 0);    /* E_PAR */
	act_tsk(T_PDQ_SND);                     /* waits with (500, 1) */
	dly_tsk(1);
	for (int i = 0; i < 3; i++) {
		rcv_pdq(PDQ_MAIN, &pgot[i], &gotpri[i]);
		rt_log("q%d/%d", (int)pgot[i], gotpri[i]);
	}
	snd_pdq(PDQ_MAIN, 41, 2);
	snd_pdq(PDQ_MAIN, 42, 2);               /* same priority: FIFO */
	for (int i = 3; i < 5; i++)
		prcv_pdq(PDQ_MAIN, &pgot[i], &gotpri[i]);
	r_pdq[5] = prcv_pdq(PDQ_MAIN, &d, &p);
	rt_log("q%d q%d", (int)pgot[3], (int)pgot[4]);
}

static const struct rtos_task_cfg tasks[] = {
	{ T_MAIN, TA_ACT, 0, main_task, 5, 1024, TDOM_KERNEL, "main" },
	{ T_SND_A, TA_NULL, 106, sender, 6, 1024, TDOM_KERNEL, "snd6" },
	{ T_SND_B, TA_NULL, 104, sender, 4, 1024, TDOM_KERNEL, "snd4" },
	{ T_SYNC_SND, TA_NULL, 0, sync_sender, 6, 1024, TDOM_KERNEL, "sync" },
	{ T_INI_WAIT, TA_NULL, 0, ini_waiter, 6, 1024, TDOM_KERNEL, "iniw" },
	{ T_PDQ_SND, TA_NULL, 0, pdq_sender, 6, 1024, TDOM_KERNEL, "pdqs" },
};
static const struct rtos_dtq_cfg dtqs[] = {
	{ DTQ_FIFO, TA_NULL, 3, "fifo" },
	{ DTQ_SYNC, TA_NULL, 0, "sync" },
	{ DTQ_TPRI, TA_TPRI, 1, "tpri" },
	{ DTQ_ISR, TA_NULL, 1, "isr" },
};
static const struct rtos_pdq_cfg pdqs[] = { { PDQ_MAIN, TA_NULL, 2, 4, "pdq" } };
static const struct rtos_cyc_cfg cycs[] = { { 1, TA_NULL, 0, cyc, 2, 0, "cyc" } };
static const struct rtos_cfg cfg = {
	.name = "dtq", .tasks = RTOS_TABLE(tasks), .dtqs = RTOS_TABLE(dtqs), .pdqs = RTOS_TABLE(pdqs),
	.cycs = RTOS_TABLE(cycs),
};

static const struct rtos_dtq_cfg bad_dtqs[] = { { 3, 0x80U, 1, "badattr" } };
static const struct rtos_cfg bad_cfg = { .name = "bad", .dtqs = RTOS_TABLE(bad_dtqs) };
static const struct rtos_pdq_cfg bad_pdqs[] = { { 2, TA_NULL, 1, TMAX_DPRI + 1, "badpri" } };
static const struct rtos_cfg bad_pdq_cfg = { .name = "bad", .pdqs = RTOS_TABLE(bad_pdqs) };

int main(void)
{
	intptr_t d;
	bool said_so = true;

	tap_plan(27);
	rt_log_reset();
	rtos_host_expect_bugs(true);
	is_int(rtos_host_boot(&cfg), E_OK, "boot");
	rtos_host_run_for(100 * MS);
	ok(r_fifo[0] == E_OK && r_fifo[1] == E_OK && r_fifo[2] == E_OK, "snd/psnd/tsnd into free places");
	is_int(r_fifo[3], E_TMOUT, "psnd_dtq on a full queue: E_TMOUT");
	ok(r_ref == E_OK && ref.sdtqcnt == 3 && ref.stskid == TSK_NONE && ref.rtskid == TSK_NONE, "ref_dtq: 3 elements, no waiters");
	ok(got[0] == 1 && got[1] == 2 && got[2] == 3, "received in FIFO order");
	is_int(r_pol[0], E_TMOUT, "prcv_dtq on an empty queue: E_TMOUT");
	ok(r_fsnd[0] == E_OK && got[3] == 11 && got[4] == 12 && got[5] == 13, "fsnd_dtq on a full queue drops the oldest");
	is_int(r_fsnd[1], E_ILUSE, "fsnd_dtq with capacity 0: E_ILUSE");
	is_int(r_tmo, E_TMOUT, "trcv_dtq times out");
	ok(t_tmo >= 3 * MS && t_tmo <= 4 * MS, "no earlier than 2 ms after the call (at %llu ns)", (unsigned long long)t_tmo);
	ok(r_pol[1] == E_OK && got[6] == 77, "capacity 0: prcv_dtq takes the waiting sender's element");
	is_int(r_pol[2], E_TMOUT, "capacity 0: psnd_dtq without a receiver is E_TMOUT");
	ok(strstr(rt_log_text(), "s0 t100 t104 t106") != NULL, "the sender is released; TA_TPRI senders enter by priority (%s)",
	   rt_log_text());
	ok(r_ini == E_OK && ini_waiter_result == E_DLT, "ini_dtq releases a waiting receiver with E_DLT");
	ok(isr_sent == E_OK && r_pol[3] == E_OK && got[7] == 99, "ipsnd_dtq from a cyclic handler reaches a waiting task (%d %d %d)",
	   isr_sent, r_pol[3], (int)got[7]);
	is_int(cyc_ctx, E_CTX, "prcv_dtq from a handler: E_CTX");
	ok(r_bad[0] == E_ID && r_bad[1] == E_ID && r_bad[2] == E_NOEXS, "bad IDs: E_ID, unconfigured: E_NOEXS");
	is_int(r_bad[3], E_MACV, "rcv_dtq into NULL: E_MACV");
	ok(r_pdq[0] == E_OK && r_pdq[1] == E_OK && r_pdq[2] == E_TMOUT, "snd_pdq fills, psnd_pdq on full: E_TMOUT");
	ok(r_pdq[3] == E_PAR && r_pdq[4] == E_PAR, "data priority outside 1..maxdpri: E_PAR");
	ok(strstr(rt_log_text(), "q200/2 q500/1 q300/3") != NULL && strstr(rt_log_text(), "p0") != NULL,
	   "highest data priority first; the waiting sender enters by its priority (%s)", rt_log_text());
	ok(strstr(rt_log_text(), "q41 q42") != NULL, "FIFO within one data priority");
	is_int(r_pdq[5], E_TMOUT, "prcv_pdq on empty: E_TMOUT");
	is_int(rtos_host_bug_count(), 0, "no bug reports");
	is_int(snd_dtq(DTQ_FIFO, 1), E_CTX, "snd_dtq from the harness: E_CTX");
	(void)d;
	rtos_host_shutdown();
	ok(rt_boot_refused(&bad_cfg, &said_so) == E_RSATR && rt_boot_refused(&bad_pdq_cfg, &said_so) == E_PAR,
	   "boot refuses unknown dtqatr (E_RSATR) and maxdpri beyond TMAX_DPRI (E_PAR)");
	ok(said_so, "each refusal printed its boot error on stderr");
	rtos_host_shutdown();
	return tap_done();
}
