/*
 * hrp3.c — the service calls of the HRP3 profile: what an app compiled for
 * TOPPERS/HRP3 (EV3RT 1.x) calls, served by the same kernel.
 *
 * An app built in the HRP3 profile sees HRP3's kernel.h (rtos_stub/include/
 * kernel_hrp3.h), whose declarations bind each call that differs from HRP2's
 * to one of these entry points (ev3lx_hrp3_*).  The differences, from HRP3's
 * interface (public source: ev3rt-git/ev3rt-hrp3, include/kernel.h,
 * include/t_stddef.h, the kernel sources and the TOPPERS third-generation kernel
 * specification it implements):
 *
 *   - time is in microseconds: timeouts (TMO, TMO_FEVR = UINT32_MAX), relative
 *     times (RELTIM, up to TMAX_RELTIM = 4 000 000 000 us), get_tim's SYSTIM
 *     (64 bits), fch_hrt's HRTCNT, ref_cyc/ref_alm's lefttim;
 *   - the i-calls are gone: act_tsk, wup_tsk, rel_wai, sig_sem, set_flg,
 *     psnd_dtq, fsnd_dtq, psnd_pdq, sta_alm, stp_alm, rot_rdq, get_tid,
 *     loc_cpu and unl_cpu work in task and non-task context alike (kernel.h
 *     keeps the i-names as macros for them).
 *
 * A call with a time runs the HRP2 call with the task's call_us set, which
 * makes the kernel read its times in us (svc_reltim_ns, tmout_valid): the
 * conversion happens before the task can block, and the flag is the task's
 * own, so no other task or interrupt ever sees it.
 */
#include "kernel_impl.h"

/* Marks the running task's call as an HRP3 one (times in us); returns the
 * task to give end_us, NULL outside task context. */
static struct tcb *begin_us(void)
{
	struct tcb *self = cpu.kind == EXEC_TASK ? runtsk : NULL;

	if (self != NULL)
		self->call_us = true;
	return self;
}

/* Ends an HRP3 call begun by begin_us and returns its result. */
static ER end_us(struct tcb *self, ER ercd)
{
	if (self != NULL)
		self->call_us = false;
	return ercd;
}

/* True in task context (HRP3's unified calls choose the HRP2 call by it). */
static bool in_task(void)
{
	return cpu.kind == EXEC_TASK;
}

/* ---- Times in microseconds ---- */

/* tslp_tsk with tmout in us. */
ER ev3lx_hrp3_tslp_tsk(TMO tmout)
{
	struct tcb *self = begin_us();

	return end_us(self, tslp_tsk(tmout));
}

/* dly_tsk with dlytim in us. */
ER ev3lx_hrp3_dly_tsk(RELTIM dlytim)
{
	struct tcb *self = begin_us();

	return end_us(self, dly_tsk(dlytim));
}

/* twai_sem with tmout in us. */
ER ev3lx_hrp3_twai_sem(ID semid, TMO tmout)
{
	struct tcb *self = begin_us();

	return end_us(self, twai_sem(semid, tmout));
}

/* twai_flg with tmout in us. */
ER ev3lx_hrp3_twai_flg(ID flgid, FLGPTN waiptn, MODE wfmode, FLGPTN *p_flgptn, TMO tmout)
{
	struct tcb *self = begin_us();

	return end_us(self, twai_flg(flgid, waiptn, wfmode, p_flgptn, tmout));
}

/* tsnd_dtq with tmout in us. */
ER ev3lx_hrp3_tsnd_dtq(ID dtqid, intptr_t data, TMO tmout)
{
	struct tcb *self = begin_us();

	return end_us(self, tsnd_dtq(dtqid, data, tmout));
}

/* trcv_dtq with tmout in us. */
ER ev3lx_hrp3_trcv_dtq(ID dtqid, intptr_t *p_data, TMO tmout)
{
	struct tcb *self = begin_us();

	return end_us(self, trcv_dtq(dtqid, p_data, tmout));
}

/* tsnd_pdq with tmout in us. */
ER ev3lx_hrp3_tsnd_pdq(ID pdqid, intptr_t data, PRI datapri, TMO tmout)
{
	struct tcb *self = begin_us();

	return end_us(self, tsnd_pdq(pdqid, data, datapri, tmout));
}

/* trcv_pdq with tmout in us. */
ER ev3lx_hrp3_trcv_pdq(ID pdqid, intptr_t *p_data, PRI *p_datapri, TMO tmout)
{
	struct tcb *self = begin_us();

	return end_us(self, trcv_pdq(pdqid, p_data, p_datapri, tmout));
}

/* tloc_mtx with tmout in us. */
ER ev3lx_hrp3_tloc_mtx(ID mtxid, TMO tmout)
{
	struct tcb *self = begin_us();

	return end_us(self, tloc_mtx(mtxid, tmout));
}

/* ref_cyc with lefttim in us. */
ER ev3lx_hrp3_ref_cyc(ID cycid, T_RCYC *pk_rcyc)
{
	struct tcb *self = begin_us();

	return end_us(self, ref_cyc(cycid, pk_rcyc));
}

/* ref_alm with lefttim in us. */
ER ev3lx_hrp3_ref_alm(ID almid, T_RALM *pk_ralm)
{
	struct tcb *self = begin_us();

	return end_us(self, ref_alm(almid, pk_ralm));
}

/* HRP3's sta_alm: almtim in us, from task or non-task context, CPU unlocked
 * (E_CTX), almtim at most HRP3's TMAX_RELTIM (E_PAR). */
ER ev3lx_hrp3_sta_alm(ID almid, RELTIM almtim)
{
	svc_charge();
	if (cpu.locked)
		return svc_result("sta_alm", E_CTX);
	if (almtim > HRP3_TMAX_RELTIM)
		return svc_result("sta_alm", E_PAR);
	return alm_start_ns("sta_alm", almid, (uint64_t)almtim * 1000U);
}

/* HRP3's get_tim: the system time in us since boot, 64 bits (task context). */
ER ev3lx_hrp3_get_tim(uint64_t *p_systim)
{
	svc_charge();
	if (!ctx_task_unlocked())
		return svc_result("get_tim", E_CTX);
	if (check_out_ptr(p_systim, sizeof(*p_systim)) != E_OK)
		return svc_result("get_tim", E_MACV);
	*p_systim = rtos_host_now() / 1000U;
	return E_OK;
}

/* HRP3's fch_hrt: the high-resolution timer, us since boot modulo 2^32 (any context). */
uint32_t ev3lx_hrp3_fch_hrt(void)
{
	svc_charge();
	return (uint32_t)(rtos_host_now() / 1000U);
}

/* ---- Calls for both contexts ---- */

/* act_tsk or iact_tsk. */
ER ev3lx_hrp3_act_tsk(ID tskid)
{
	return in_task() ? act_tsk(tskid) : iact_tsk(tskid);
}

/* wup_tsk or iwup_tsk. */
ER ev3lx_hrp3_wup_tsk(ID tskid)
{
	return in_task() ? wup_tsk(tskid) : iwup_tsk(tskid);
}

/* rel_wai or irel_wai. */
ER ev3lx_hrp3_rel_wai(ID tskid)
{
	return in_task() ? rel_wai(tskid) : irel_wai(tskid);
}

/* sig_sem or isig_sem. */
ER ev3lx_hrp3_sig_sem(ID semid)
{
	return in_task() ? sig_sem(semid) : isig_sem(semid);
}

/* set_flg or iset_flg. */
ER ev3lx_hrp3_set_flg(ID flgid, FLGPTN setptn)
{
	return in_task() ? set_flg(flgid, setptn) : iset_flg(flgid, setptn);
}

/* psnd_dtq or ipsnd_dtq. */
ER ev3lx_hrp3_psnd_dtq(ID dtqid, intptr_t data)
{
	return in_task() ? psnd_dtq(dtqid, data) : ipsnd_dtq(dtqid, data);
}

/* fsnd_dtq or ifsnd_dtq. */
ER ev3lx_hrp3_fsnd_dtq(ID dtqid, intptr_t data)
{
	return in_task() ? fsnd_dtq(dtqid, data) : ifsnd_dtq(dtqid, data);
}

/* psnd_pdq or ipsnd_pdq. */
ER ev3lx_hrp3_psnd_pdq(ID pdqid, intptr_t data, PRI datapri)
{
	return in_task() ? psnd_pdq(pdqid, data, datapri) : ipsnd_pdq(pdqid, data, datapri);
}

/* stp_alm or istp_alm. */
ER ev3lx_hrp3_stp_alm(ID almid)
{
	return in_task() ? stp_alm(almid) : istp_alm(almid);
}

/* rot_rdq or irot_rdq. */
ER ev3lx_hrp3_rot_rdq(PRI tskpri)
{
	return in_task() ? rot_rdq(tskpri) : irot_rdq(tskpri);
}

/* get_tid or iget_tid (the task an interrupt came on top of). */
ER ev3lx_hrp3_get_tid(ID *p_tskid)
{
	return in_task() ? get_tid(p_tskid) : iget_tid(p_tskid);
}

/* loc_cpu or iloc_cpu. */
ER ev3lx_hrp3_loc_cpu(void)
{
	return in_task() ? loc_cpu() : iloc_cpu();
}

/* unl_cpu or iunl_cpu. */
ER ev3lx_hrp3_unl_cpu(void)
{
	return in_task() ? unl_cpu() : iunl_cpu();
}
