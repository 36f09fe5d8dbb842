/*
 * hrp2_link_provider.c — link-only definitions of the TOPPERS/HRP2 service
 * calls that the real kernel supplies on the brick.
 *
 * Nothing here runs: each call answers E_NOSPT.  The link check
 * (mk/am1808.mk) proves two things with it: libev3lx.a has no unresolved
 * symbol once these are present, and this file defines exactly the service
 * calls declared by rtos_stub's target headers — so nothing host-only
 * (rtos_host.h, the virtual clock, host_sim) leaks into the target library.
 */
#include "kernel.h"
#include "sil.h"

ER act_tsk(ID tskid) { (void)tskid; return E_NOSPT; }
ER iact_tsk(ID tskid) { (void)tskid; return E_NOSPT; }
ER_UINT can_act(ID tskid) { (void)tskid; return E_NOSPT; }
ER ext_tsk(void) { for (;;) { } }
ER chg_pri(ID tskid, PRI tskpri) { (void)tskid; (void)tskpri; return E_NOSPT; }
ER get_pri(ID tskid, PRI *p_tskpri) { (void)tskid; (void)p_tskpri; return E_NOSPT; }
ER get_tid(ID *p_tskid) { (void)p_tskid; return E_NOSPT; }
ER iget_tid(ID *p_tskid) { (void)p_tskid; return E_NOSPT; }

ER slp_tsk(void) { return E_NOSPT; }
ER tslp_tsk(TMO tmout) { (void)tmout; return E_NOSPT; }
ER wup_tsk(ID tskid) { (void)tskid; return E_NOSPT; }
ER iwup_tsk(ID tskid) { (void)tskid; return E_NOSPT; }
ER_UINT can_wup(ID tskid) { (void)tskid; return E_NOSPT; }
ER rel_wai(ID tskid) { (void)tskid; return E_NOSPT; }
ER irel_wai(ID tskid) { (void)tskid; return E_NOSPT; }
ER dly_tsk(RELTIM dlytim) { (void)dlytim; return E_NOSPT; }
ER sus_tsk(ID tskid) { (void)tskid; return E_NOSPT; }
ER rsm_tsk(ID tskid) { (void)tskid; return E_NOSPT; }
ER ter_tsk(ID tskid) { (void)tskid; return E_NOSPT; }

ER sig_sem(ID semid) { (void)semid; return E_NOSPT; }
ER isig_sem(ID semid) { (void)semid; return E_NOSPT; }
ER wai_sem(ID semid) { (void)semid; return E_NOSPT; }
ER pol_sem(ID semid) { (void)semid; return E_NOSPT; }
ER twai_sem(ID semid, TMO tmout) { (void)semid; (void)tmout; return E_NOSPT; }

ER set_flg(ID flgid, FLGPTN setptn) { (void)flgid; (void)setptn; return E_NOSPT; }
ER iset_flg(ID flgid, FLGPTN setptn) { (void)flgid; (void)setptn; return E_NOSPT; }
ER clr_flg(ID flgid, FLGPTN clrptn) { (void)flgid; (void)clrptn; return E_NOSPT; }
ER wai_flg(ID flgid, FLGPTN waiptn, MODE wfmode, FLGPTN *p_flgptn)
{ (void)flgid; (void)waiptn; (void)wfmode; (void)p_flgptn; return E_NOSPT; }
ER pol_flg(ID flgid, FLGPTN waiptn, MODE wfmode, FLGPTN *p_flgptn)
{ (void)flgid; (void)waiptn; (void)wfmode; (void)p_flgptn; return E_NOSPT; }
ER twai_flg(ID flgid, FLGPTN waiptn, MODE wfmode, FLGPTN *p_flgptn, TMO tmout)
{ (void)flgid; (void)waiptn; (void)wfmode; (void)p_flgptn; (void)tmout; return E_NOSPT; }

ER snd_dtq(ID dtqid, intptr_t data) { (void)dtqid; (void)data; return E_NOSPT; }
ER psnd_dtq(ID dtqid, intptr_t data) { (void)dtqid; (void)data; return E_NOSPT; }
ER ipsnd_dtq(ID dtqid, intptr_t data) { (void)dtqid; (void)data; return E_NOSPT; }
ER tsnd_dtq(ID dtqid, intptr_t data, TMO tmout) { (void)dtqid; (void)data; (void)tmout; return E_NOSPT; }
ER fsnd_dtq(ID dtqid, intptr_t data) { (void)dtqid; (void)data; return E_NOSPT; }
ER ifsnd_dtq(ID dtqid, intptr_t data) { (void)dtqid; (void)data; return E_NOSPT; }
ER rcv_dtq(ID dtqid, intptr_t *p_data) { (void)dtqid; (void)p_data; return E_NOSPT; }
ER prcv_dtq(ID dtqid, intptr_t *p_data) { (void)dtqid; (void)p_data; return E_NOSPT; }
ER trcv_dtq(ID dtqid, intptr_t *p_data, TMO tmout) { (void)dtqid; (void)p_data; (void)tmout; return E_NOSPT; }
ER ini_dtq(ID dtqid) { (void)dtqid; return E_NOSPT; }
ER ref_dtq(ID dtqid, T_RDTQ *pk_rdtq) { (void)dtqid; (void)pk_rdtq; return E_NOSPT; }

ER snd_pdq(ID pdqid, intptr_t data, PRI datapri) { (void)pdqid; (void)data; (void)datapri; return E_NOSPT; }
ER psnd_pdq(ID pdqid, intptr_t data, PRI datapri) { (void)pdqid; (void)data; (void)datapri; return E_NOSPT; }
ER ipsnd_pdq(ID pdqid, intptr_t data, PRI datapri) { (void)pdqid; (void)data; (void)datapri; return E_NOSPT; }
ER tsnd_pdq(ID pdqid, intptr_t data, PRI datapri, TMO tmout)
{ (void)pdqid; (void)data; (void)datapri; (void)tmout; return E_NOSPT; }
ER rcv_pdq(ID pdqid, intptr_t *p_data, PRI *p_datapri) { (void)pdqid; (void)p_data; (void)p_datapri; return E_NOSPT; }
ER prcv_pdq(ID pdqid, intptr_t *p_data, PRI *p_datapri) { (void)pdqid; (void)p_data; (void)p_datapri; return E_NOSPT; }
ER trcv_pdq(ID pdqid, intptr_t *p_data, PRI *p_datapri, TMO tmout)
{ (void)pdqid; (void)p_data; (void)p_datapri; (void)tmout; return E_NOSPT; }
ER ini_pdq(ID pdqid) { (void)pdqid; return E_NOSPT; }
ER ref_pdq(ID pdqid, T_RPDQ *pk_rpdq) { (void)pdqid; (void)pk_rpdq; return E_NOSPT; }

ER loc_mtx(ID mtxid) { (void)mtxid; return E_NOSPT; }
ER ploc_mtx(ID mtxid) { (void)mtxid; return E_NOSPT; }
ER tloc_mtx(ID mtxid, TMO tmout) { (void)mtxid; (void)tmout; return E_NOSPT; }
ER unl_mtx(ID mtxid) { (void)mtxid; return E_NOSPT; }
ER ini_mtx(ID mtxid) { (void)mtxid; return E_NOSPT; }
ER ref_mtx(ID mtxid, T_RMTX *pk_rmtx) { (void)mtxid; (void)pk_rmtx; return E_NOSPT; }

ER ini_sem(ID semid) { (void)semid; return E_NOSPT; }
ER ref_sem(ID semid, T_RSEM *pk_rsem) { (void)semid; (void)pk_rsem; return E_NOSPT; }
ER ini_flg(ID flgid) { (void)flgid; return E_NOSPT; }
ER ref_flg(ID flgid, T_RFLG *pk_rflg) { (void)flgid; (void)pk_rflg; return E_NOSPT; }
ER ref_cyc(ID cycid, T_RCYC *pk_rcyc) { (void)cycid; (void)pk_rcyc; return E_NOSPT; }
ER ref_alm(ID almid, T_RALM *pk_ralm) { (void)almid; (void)pk_ralm; return E_NOSPT; }
ER get_inf(intptr_t *p_exinf) { (void)p_exinf; return E_NOSPT; }

ER get_tim(SYSTIM *p_systim) { (void)p_systim; return E_NOSPT; }
ER get_utm(SYSUTM *p_sysutm) { (void)p_sysutm; return E_NOSPT; }
ER sta_cyc(ID cycid) { (void)cycid; return E_NOSPT; }
ER stp_cyc(ID cycid) { (void)cycid; return E_NOSPT; }
ER sta_alm(ID almid, RELTIM almtim) { (void)almid; (void)almtim; return E_NOSPT; }
ER ista_alm(ID almid, RELTIM almtim) { (void)almid; (void)almtim; return E_NOSPT; }
ER stp_alm(ID almid) { (void)almid; return E_NOSPT; }
ER istp_alm(ID almid) { (void)almid; return E_NOSPT; }

ER rot_rdq(PRI tskpri) { (void)tskpri; return E_NOSPT; }
ER irot_rdq(PRI tskpri) { (void)tskpri; return E_NOSPT; }
ER loc_cpu(void) { return E_NOSPT; }
ER iloc_cpu(void) { return E_NOSPT; }
ER unl_cpu(void) { return E_NOSPT; }
ER iunl_cpu(void) { return E_NOSPT; }
ER dis_dsp(void) { return E_NOSPT; }
ER ena_dsp(void) { return E_NOSPT; }
bool_t sns_ctx(void) { return FALSE; }
bool_t sns_loc(void) { return FALSE; }
bool_t sns_dsp(void) { return FALSE; }
bool_t sns_dpn(void) { return FALSE; }
ER ext_ker(void) { for (;;) { } }

ER dis_int(INTNO intno) { (void)intno; return E_NOSPT; }
ER ena_int(INTNO intno) { (void)intno; return E_NOSPT; }

/* The real target code supplies sil_dly_nse; weak so a library-side calibration loop may replace it. */
void __attribute__((weak)) sil_dly_nse(ulong_t dlytim) { (void)dlytim; }

ER_UINT cal_svc(FN fncd, intptr_t par1, intptr_t par2, intptr_t par3, intptr_t par4, intptr_t par5)
{ (void)fncd; (void)par1; (void)par2; (void)par3; (void)par4; (void)par5; return E_NOSPT; }
ER prb_mem(const void *base, SIZE size, ID tskid, MODE pmmode)
{ (void)base; (void)size; (void)tskid; (void)pmmode; return E_NOSPT; }

void syslog(uint_t prio, const char *format, ...) { (void)prio; (void)format; }
ER syslog_msk_log(uint_t logmask, uint_t lowmask) { (void)logmask; (void)lowmask; return E_NOSPT; }

/* EV3RT's platform (target/ev3_gcc/platform/src/ev3main.c), which ev3.h declares. */
void svc_perror(const char *file, int_t line, const char *expr, ER ercd)
{
	(void)file; (void)line; (void)expr; (void)ercd;
}
