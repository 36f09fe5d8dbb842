/*
 * hrp2_link_provider.c — link-only definitions of the symbols a TOPPERS/HRP2
 * firmware for the EV3 defines and the library may use, under the names the
 * real image gives them: the kernel's service calls as _kernel_<call>
 * (include/svc_call.h: kernel-domain code calls them so; user-domain code
 * traps, and cal_svc is always a trap), the system log's syslog and
 * _syslog_msk_log (library/vasyslog.c, syssvc/syslog.c), the ARM core's
 * _sil_dly_nse (arch/arm_gcc/common/core_support.S) and EV3RT's svc_perror
 * (ev3rt-git/ev3rt-hrp2).
 *
 * Nothing here runs: each call answers E_NOSPT.  The link check
 * (am1808/check_link.sh) proves with it that libev3lx.a has no unresolved
 * symbol once these are present, that this file defines exactly what
 * rtos_stub's target headers declare, and that each of those is a symbol of
 * the real image (am1808/hrp2_symbols.txt) — so the library asks the kernel
 * for nothing HRP2 lacks, and nothing host-only leaks into it.
 */
#include "kernel.h"
#include "sil.h"
#include "syssvc/syslog.h"

ER _kernel_act_tsk(ID tskid) { (void)tskid; return E_NOSPT; }
ER _kernel_iact_tsk(ID tskid) { (void)tskid; return E_NOSPT; }
ER_UINT _kernel_can_act(ID tskid) { (void)tskid; return E_NOSPT; }
ER _kernel_ext_tsk(void) { return E_NOSPT; }
ER _kernel_chg_pri(ID tskid, PRI tskpri) { (void)tskid; (void)tskpri; return E_NOSPT; }
ER _kernel_get_pri(ID tskid, PRI *p_tskpri) { (void)tskid; (void)p_tskpri; return E_NOSPT; }
ER _kernel_get_tid(ID *p_tskid) { (void)p_tskid; return E_NOSPT; }
ER _kernel_iget_tid(ID *p_tskid) { (void)p_tskid; return E_NOSPT; }

ER _kernel_slp_tsk(void) { return E_NOSPT; }
ER _kernel_tslp_tsk(TMO tmout) { (void)tmout; return E_NOSPT; }
ER _kernel_wup_tsk(ID tskid) { (void)tskid; return E_NOSPT; }
ER _kernel_iwup_tsk(ID tskid) { (void)tskid; return E_NOSPT; }
ER_UINT _kernel_can_wup(ID tskid) { (void)tskid; return E_NOSPT; }
ER _kernel_rel_wai(ID tskid) { (void)tskid; return E_NOSPT; }
ER _kernel_irel_wai(ID tskid) { (void)tskid; return E_NOSPT; }
ER _kernel_dly_tsk(RELTIM dlytim) { (void)dlytim; return E_NOSPT; }
ER _kernel_sus_tsk(ID tskid) { (void)tskid; return E_NOSPT; }
ER _kernel_rsm_tsk(ID tskid) { (void)tskid; return E_NOSPT; }
ER _kernel_ter_tsk(ID tskid) { (void)tskid; return E_NOSPT; }

ER _kernel_sig_sem(ID semid) { (void)semid; return E_NOSPT; }
ER _kernel_isig_sem(ID semid) { (void)semid; return E_NOSPT; }
ER _kernel_wai_sem(ID semid) { (void)semid; return E_NOSPT; }
ER _kernel_pol_sem(ID semid) { (void)semid; return E_NOSPT; }
ER _kernel_twai_sem(ID semid, TMO tmout) { (void)semid; (void)tmout; return E_NOSPT; }

ER _kernel_set_flg(ID flgid, FLGPTN setptn) { (void)flgid; (void)setptn; return E_NOSPT; }
ER _kernel_iset_flg(ID flgid, FLGPTN setptn) { (void)flgid; (void)setptn; return E_NOSPT; }
ER _kernel_clr_flg(ID flgid, FLGPTN clrptn) { (void)flgid; (void)clrptn; return E_NOSPT; }
ER _kernel_wai_flg(ID flgid, FLGPTN waiptn, MODE wfmode, FLGPTN *p_flgptn)
{ (void)flgid; (void)waiptn; (void)wfmode; (void)p_flgptn; return E_NOSPT; }
ER _kernel_pol_flg(ID flgid, FLGPTN waiptn, MODE wfmode, FLGPTN *p_flgptn)
{ (void)flgid; (void)waiptn; (void)wfmode; (void)p_flgptn; return E_NOSPT; }
ER _kernel_twai_flg(ID flgid, FLGPTN waiptn, MODE wfmode, FLGPTN *p_flgptn, TMO tmout)
{ (void)flgid; (void)waiptn; (void)wfmode; (void)p_flgptn; (void)tmout; return E_NOSPT; }

ER _kernel_snd_dtq(ID dtqid, intptr_t data) { (void)dtqid; (void)data; return E_NOSPT; }
ER _kernel_psnd_dtq(ID dtqid, intptr_t data) { (void)dtqid; (void)data; return E_NOSPT; }
ER _kernel_ipsnd_dtq(ID dtqid, intptr_t data) { (void)dtqid; (void)data; return E_NOSPT; }
ER _kernel_tsnd_dtq(ID dtqid, intptr_t data, TMO tmout) { (void)dtqid; (void)data; (void)tmout; return E_NOSPT; }
ER _kernel_fsnd_dtq(ID dtqid, intptr_t data) { (void)dtqid; (void)data; return E_NOSPT; }
ER _kernel_ifsnd_dtq(ID dtqid, intptr_t data) { (void)dtqid; (void)data; return E_NOSPT; }
ER _kernel_rcv_dtq(ID dtqid, intptr_t *p_data) { (void)dtqid; (void)p_data; return E_NOSPT; }
ER _kernel_prcv_dtq(ID dtqid, intptr_t *p_data) { (void)dtqid; (void)p_data; return E_NOSPT; }
ER _kernel_trcv_dtq(ID dtqid, intptr_t *p_data, TMO tmout) { (void)dtqid; (void)p_data; (void)tmout; return E_NOSPT; }
ER _kernel_ini_dtq(ID dtqid) { (void)dtqid; return E_NOSPT; }
ER _kernel_ref_dtq(ID dtqid, T_RDTQ *pk_rdtq) { (void)dtqid; (void)pk_rdtq; return E_NOSPT; }

ER _kernel_snd_pdq(ID pdqid, intptr_t data, PRI datapri) { (void)pdqid; (void)data; (void)datapri; return E_NOSPT; }
ER _kernel_psnd_pdq(ID pdqid, intptr_t data, PRI datapri) { (void)pdqid; (void)data; (void)datapri; return E_NOSPT; }
ER _kernel_ipsnd_pdq(ID pdqid, intptr_t data, PRI datapri) { (void)pdqid; (void)data; (void)datapri; return E_NOSPT; }
ER _kernel_tsnd_pdq(ID pdqid, intptr_t data, PRI datapri, TMO tmout)
{ (void)pdqid; (void)data; (void)datapri; (void)tmout; return E_NOSPT; }
ER _kernel_rcv_pdq(ID pdqid, intptr_t *p_data, PRI *p_datapri) { (void)pdqid; (void)p_data; (void)p_datapri; return E_NOSPT; }
ER _kernel_prcv_pdq(ID pdqid, intptr_t *p_data, PRI *p_datapri) { (void)pdqid; (void)p_data; (void)p_datapri; return E_NOSPT; }
ER _kernel_trcv_pdq(ID pdqid, intptr_t *p_data, PRI *p_datapri, TMO tmout)
{ (void)pdqid; (void)p_data; (void)p_datapri; (void)tmout; return E_NOSPT; }
ER _kernel_ini_pdq(ID pdqid) { (void)pdqid; return E_NOSPT; }
ER _kernel_ref_pdq(ID pdqid, T_RPDQ *pk_rpdq) { (void)pdqid; (void)pk_rpdq; return E_NOSPT; }

ER _kernel_loc_mtx(ID mtxid) { (void)mtxid; return E_NOSPT; }
ER _kernel_ploc_mtx(ID mtxid) { (void)mtxid; return E_NOSPT; }
ER _kernel_tloc_mtx(ID mtxid, TMO tmout) { (void)mtxid; (void)tmout; return E_NOSPT; }
ER _kernel_unl_mtx(ID mtxid) { (void)mtxid; return E_NOSPT; }
ER _kernel_ini_mtx(ID mtxid) { (void)mtxid; return E_NOSPT; }
ER _kernel_ref_mtx(ID mtxid, T_RMTX *pk_rmtx) { (void)mtxid; (void)pk_rmtx; return E_NOSPT; }

ER _kernel_ini_sem(ID semid) { (void)semid; return E_NOSPT; }
ER _kernel_ref_sem(ID semid, T_RSEM *pk_rsem) { (void)semid; (void)pk_rsem; return E_NOSPT; }
ER _kernel_ini_flg(ID flgid) { (void)flgid; return E_NOSPT; }
ER _kernel_ref_flg(ID flgid, T_RFLG *pk_rflg) { (void)flgid; (void)pk_rflg; return E_NOSPT; }
ER _kernel_ref_cyc(ID cycid, T_RCYC *pk_rcyc) { (void)cycid; (void)pk_rcyc; return E_NOSPT; }
ER _kernel_ref_alm(ID almid, T_RALM *pk_ralm) { (void)almid; (void)pk_ralm; return E_NOSPT; }
ER _kernel_get_inf(intptr_t *p_exinf) { (void)p_exinf; return E_NOSPT; }

ER _kernel_get_tim(SYSTIM *p_systim) { (void)p_systim; return E_NOSPT; }
ER _kernel_get_utm(SYSUTM *p_sysutm) { (void)p_sysutm; return E_NOSPT; }
ER _kernel_sta_cyc(ID cycid) { (void)cycid; return E_NOSPT; }
ER _kernel_stp_cyc(ID cycid) { (void)cycid; return E_NOSPT; }
ER _kernel_sta_alm(ID almid, RELTIM almtim) { (void)almid; (void)almtim; return E_NOSPT; }
ER _kernel_ista_alm(ID almid, RELTIM almtim) { (void)almid; (void)almtim; return E_NOSPT; }
ER _kernel_stp_alm(ID almid) { (void)almid; return E_NOSPT; }
ER _kernel_istp_alm(ID almid) { (void)almid; return E_NOSPT; }

ER _kernel_rot_rdq(PRI tskpri) { (void)tskpri; return E_NOSPT; }
ER _kernel_irot_rdq(PRI tskpri) { (void)tskpri; return E_NOSPT; }
ER _kernel_loc_cpu(void) { return E_NOSPT; }
ER _kernel_iloc_cpu(void) { return E_NOSPT; }
ER _kernel_unl_cpu(void) { return E_NOSPT; }
ER _kernel_iunl_cpu(void) { return E_NOSPT; }
ER _kernel_dis_dsp(void) { return E_NOSPT; }
ER _kernel_ena_dsp(void) { return E_NOSPT; }
bool_t _kernel_sns_ctx(void) { return FALSE; }
bool_t _kernel_sns_loc(void) { return FALSE; }
bool_t _kernel_sns_dsp(void) { return FALSE; }
bool_t _kernel_sns_dpn(void) { return FALSE; }
ER _kernel_ext_ker(void) { return E_NOSPT; }

ER _kernel_dis_int(INTNO intno) { (void)intno; return E_NOSPT; }
ER _kernel_ena_int(INTNO intno) { (void)intno; return E_NOSPT; }

/* HRP2's ARM core (core_support.S): the calibrated loop sil_dly_nse calls. */
void _sil_dly_nse(ulong_t dlytim) { (void)dlytim; }

ER _kernel_prb_mem(const void *base, SIZE size, ID tskid, MODE pmmode)
{ (void)base; (void)size; (void)tskid; (void)pmmode; return E_NOSPT; }

void syslog(uint_t prio, const char *format, ...) { (void)prio; (void)format; }
ER _syslog_msk_log(uint_t logmask, uint_t lowmask, ID cdmid)
{ (void)logmask; (void)lowmask; (void)cdmid; return E_NOSPT; }

/* EV3RT's platform (target/ev3_gcc/platform/src/ev3main.c), which ev3.h declares. */
void svc_perror(const char *file, int_t line, const char *expr, ER ercd)
{
	(void)file; (void)line; (void)expr; (void)ercd;
}
