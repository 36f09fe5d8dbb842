/*
 * target_svc.h — HRP2's service calls from a user domain, and cal_svc.
 *
 * In a user domain (code compiled without TOPPERS_SVC_CALL) every service
 * call is an inline function that enters the kernel by software interrupt,
 * as HRP2's tool_svc.h and the ARM core's core_svc.h make it
 * (ev3rt-git/ev3rt-hrp2, arch/gcc/tool_svc.h, arch/arm_gcc/common/core_svc.h):
 * the function code in r7 (kernel_fncode.h: negative for the kernel's calls),
 * the parameters in r0..r4, `svc 1`, the result in r0.  cal_svc is that trap
 * with a positive code in every domain, the kernel's included
 * (target/ev3_gcc/target_svc.h); a code <= 0 is E_RSFN without a trap.
 *
 * On the host the same inline functions call the host kernel's _kernel_
 * entries directly, and cal_svc with a positive code enters the host kernel's
 * extended service dispatcher (rtos_host_cal_svc): no trap, the same names
 * and results.
 */
/* Included alone, the kernel's types come first: kernel.h defines them and
 * then includes this header. */
#ifndef TOPPERS_TARGET_SVC_H
#include "kernel.h"
#endif

#ifndef TOPPERS_TARGET_SVC_H
#define TOPPERS_TARGET_SVC_H

#ifndef TOPPERS_MACRO_ONLY

#if defined(EV3LX_AM1808)
/* Enters the kernel with function code fncd and five parameters; returns r0. */
Inline intptr_t TOPPERS_svc_trap(FN fncd, intptr_t par1, intptr_t par2, intptr_t par3,
				 intptr_t par4, intptr_t par5)
{
	register intptr_t r0 __asm__("r0") = par1;
	register intptr_t r1 __asm__("r1") = par2;
	register intptr_t r2 __asm__("r2") = par3;
	register intptr_t r3 __asm__("r3") = par4;
	register intptr_t r4 __asm__("r4") = par5;
	register FN r7 __asm__("r7") = fncd;

	__asm__ volatile("svc 1"
			 : "+r"(r0), "+r"(r1), "+r"(r2), "+r"(r3)
			 : "r"(r4), "r"(r7)
			 : "ip", "lr", "memory", "cc");
	return r0;
}

/* Calls extended service routine fncd (DEF_SVC) with five parameters. */
Inline ER_UINT cal_svc(FN fncd, intptr_t par1, intptr_t par2, intptr_t par3,
		       intptr_t par4, intptr_t par5)
{
	return fncd > 0 ? (ER_UINT)TOPPERS_svc_trap(fncd, par1, par2, par3, par4, par5) : E_RSFN;
}
#else
/* The host kernel's extended service dispatcher: routine fncd in the caller's context and domain. */
ER_UINT rtos_host_cal_svc(FN fncd, intptr_t par1, intptr_t par2, intptr_t par3,
			  intptr_t par4, intptr_t par5);

/* Calls extended service routine fncd (DEF_SVC) with five parameters. */
Inline ER_UINT cal_svc(FN fncd, intptr_t par1, intptr_t par2, intptr_t par3,
		       intptr_t par4, intptr_t par5)
{
	return fncd > 0 ? rtos_host_cal_svc(fncd, par1, par2, par3, par4, par5) : E_RSFN;
}
#endif

#ifndef TOPPERS_SVC_CALL
/* The user domain's service calls (one line each: the trap on the brick, the
 * host kernel's entry on the host). */
#if defined(EV3LX_AM1808)
Inline ER act_tsk(ID tskid) { return (ER)TOPPERS_svc_trap(TFN_ACT_TSK, (intptr_t)tskid, 0, 0, 0, 0); }
Inline ER iact_tsk(ID tskid) { return (ER)TOPPERS_svc_trap(TFN_IACT_TSK, (intptr_t)tskid, 0, 0, 0, 0); }
Inline ER_UINT can_act(ID tskid) { return (ER_UINT)TOPPERS_svc_trap(TFN_CAN_ACT, (intptr_t)tskid, 0, 0, 0, 0); }
Inline ER ext_tsk(void) { return (ER)TOPPERS_svc_trap(TFN_EXT_TSK, 0, 0, 0, 0, 0); }
Inline ER chg_pri(ID tskid, PRI tskpri) { return (ER)TOPPERS_svc_trap(TFN_CHG_PRI, (intptr_t)tskid, (intptr_t)tskpri, 0, 0, 0); }
Inline ER get_pri(ID tskid, PRI *p_tskpri) { return (ER)TOPPERS_svc_trap(TFN_GET_PRI, (intptr_t)tskid, (intptr_t)p_tskpri, 0, 0, 0); }
Inline ER get_tid(ID *p_tskid) { return (ER)TOPPERS_svc_trap(TFN_GET_TID, (intptr_t)p_tskid, 0, 0, 0, 0); }
Inline ER iget_tid(ID *p_tskid) { return (ER)TOPPERS_svc_trap(TFN_IGET_TID, (intptr_t)p_tskid, 0, 0, 0, 0); }
Inline ER slp_tsk(void) { return (ER)TOPPERS_svc_trap(TFN_SLP_TSK, 0, 0, 0, 0, 0); }
Inline ER tslp_tsk(TMO tmout) { return (ER)TOPPERS_svc_trap(TFN_TSLP_TSK, (intptr_t)tmout, 0, 0, 0, 0); }
Inline ER wup_tsk(ID tskid) { return (ER)TOPPERS_svc_trap(TFN_WUP_TSK, (intptr_t)tskid, 0, 0, 0, 0); }
Inline ER iwup_tsk(ID tskid) { return (ER)TOPPERS_svc_trap(TFN_IWUP_TSK, (intptr_t)tskid, 0, 0, 0, 0); }
Inline ER_UINT can_wup(ID tskid) { return (ER_UINT)TOPPERS_svc_trap(TFN_CAN_WUP, (intptr_t)tskid, 0, 0, 0, 0); }
Inline ER rel_wai(ID tskid) { return (ER)TOPPERS_svc_trap(TFN_REL_WAI, (intptr_t)tskid, 0, 0, 0, 0); }
Inline ER irel_wai(ID tskid) { return (ER)TOPPERS_svc_trap(TFN_IREL_WAI, (intptr_t)tskid, 0, 0, 0, 0); }
Inline ER dly_tsk(RELTIM dlytim) { return (ER)TOPPERS_svc_trap(TFN_DLY_TSK, (intptr_t)dlytim, 0, 0, 0, 0); }
Inline ER sus_tsk(ID tskid) { return (ER)TOPPERS_svc_trap(TFN_SUS_TSK, (intptr_t)tskid, 0, 0, 0, 0); }
Inline ER rsm_tsk(ID tskid) { return (ER)TOPPERS_svc_trap(TFN_RSM_TSK, (intptr_t)tskid, 0, 0, 0, 0); }
Inline ER ter_tsk(ID tskid) { return (ER)TOPPERS_svc_trap(TFN_TER_TSK, (intptr_t)tskid, 0, 0, 0, 0); }
Inline ER sig_sem(ID semid) { return (ER)TOPPERS_svc_trap(TFN_SIG_SEM, (intptr_t)semid, 0, 0, 0, 0); }
Inline ER isig_sem(ID semid) { return (ER)TOPPERS_svc_trap(TFN_ISIG_SEM, (intptr_t)semid, 0, 0, 0, 0); }
Inline ER wai_sem(ID semid) { return (ER)TOPPERS_svc_trap(TFN_WAI_SEM, (intptr_t)semid, 0, 0, 0, 0); }
Inline ER pol_sem(ID semid) { return (ER)TOPPERS_svc_trap(TFN_POL_SEM, (intptr_t)semid, 0, 0, 0, 0); }
Inline ER twai_sem(ID semid, TMO tmout) { return (ER)TOPPERS_svc_trap(TFN_TWAI_SEM, (intptr_t)semid, (intptr_t)tmout, 0, 0, 0); }
Inline ER set_flg(ID flgid, FLGPTN setptn) { return (ER)TOPPERS_svc_trap(TFN_SET_FLG, (intptr_t)flgid, (intptr_t)setptn, 0, 0, 0); }
Inline ER iset_flg(ID flgid, FLGPTN setptn) { return (ER)TOPPERS_svc_trap(TFN_ISET_FLG, (intptr_t)flgid, (intptr_t)setptn, 0, 0, 0); }
Inline ER clr_flg(ID flgid, FLGPTN clrptn) { return (ER)TOPPERS_svc_trap(TFN_CLR_FLG, (intptr_t)flgid, (intptr_t)clrptn, 0, 0, 0); }
Inline ER wai_flg(ID flgid, FLGPTN waiptn, MODE wfmode, FLGPTN *p_flgptn) { return (ER)TOPPERS_svc_trap(TFN_WAI_FLG, (intptr_t)flgid, (intptr_t)waiptn, (intptr_t)wfmode, (intptr_t)p_flgptn, 0); }
Inline ER pol_flg(ID flgid, FLGPTN waiptn, MODE wfmode, FLGPTN *p_flgptn) { return (ER)TOPPERS_svc_trap(TFN_POL_FLG, (intptr_t)flgid, (intptr_t)waiptn, (intptr_t)wfmode, (intptr_t)p_flgptn, 0); }
Inline ER twai_flg(ID flgid, FLGPTN waiptn, MODE wfmode, FLGPTN *p_flgptn, TMO tmout) { return (ER)TOPPERS_svc_trap(TFN_TWAI_FLG, (intptr_t)flgid, (intptr_t)waiptn, (intptr_t)wfmode, (intptr_t)p_flgptn, (intptr_t)tmout); }
Inline ER snd_dtq(ID dtqid, intptr_t data) { return (ER)TOPPERS_svc_trap(TFN_SND_DTQ, (intptr_t)dtqid, (intptr_t)data, 0, 0, 0); }
Inline ER psnd_dtq(ID dtqid, intptr_t data) { return (ER)TOPPERS_svc_trap(TFN_PSND_DTQ, (intptr_t)dtqid, (intptr_t)data, 0, 0, 0); }
Inline ER ipsnd_dtq(ID dtqid, intptr_t data) { return (ER)TOPPERS_svc_trap(TFN_IPSND_DTQ, (intptr_t)dtqid, (intptr_t)data, 0, 0, 0); }
Inline ER tsnd_dtq(ID dtqid, intptr_t data, TMO tmout) { return (ER)TOPPERS_svc_trap(TFN_TSND_DTQ, (intptr_t)dtqid, (intptr_t)data, (intptr_t)tmout, 0, 0); }
Inline ER fsnd_dtq(ID dtqid, intptr_t data) { return (ER)TOPPERS_svc_trap(TFN_FSND_DTQ, (intptr_t)dtqid, (intptr_t)data, 0, 0, 0); }
Inline ER ifsnd_dtq(ID dtqid, intptr_t data) { return (ER)TOPPERS_svc_trap(TFN_IFSND_DTQ, (intptr_t)dtqid, (intptr_t)data, 0, 0, 0); }
Inline ER rcv_dtq(ID dtqid, intptr_t *p_data) { return (ER)TOPPERS_svc_trap(TFN_RCV_DTQ, (intptr_t)dtqid, (intptr_t)p_data, 0, 0, 0); }
Inline ER prcv_dtq(ID dtqid, intptr_t *p_data) { return (ER)TOPPERS_svc_trap(TFN_PRCV_DTQ, (intptr_t)dtqid, (intptr_t)p_data, 0, 0, 0); }
Inline ER trcv_dtq(ID dtqid, intptr_t *p_data, TMO tmout) { return (ER)TOPPERS_svc_trap(TFN_TRCV_DTQ, (intptr_t)dtqid, (intptr_t)p_data, (intptr_t)tmout, 0, 0); }
Inline ER ini_dtq(ID dtqid) { return (ER)TOPPERS_svc_trap(TFN_INI_DTQ, (intptr_t)dtqid, 0, 0, 0, 0); }
Inline ER ref_dtq(ID dtqid, T_RDTQ *pk_rdtq) { return (ER)TOPPERS_svc_trap(TFN_REF_DTQ, (intptr_t)dtqid, (intptr_t)pk_rdtq, 0, 0, 0); }
Inline ER snd_pdq(ID pdqid, intptr_t data, PRI datapri) { return (ER)TOPPERS_svc_trap(TFN_SND_PDQ, (intptr_t)pdqid, (intptr_t)data, (intptr_t)datapri, 0, 0); }
Inline ER psnd_pdq(ID pdqid, intptr_t data, PRI datapri) { return (ER)TOPPERS_svc_trap(TFN_PSND_PDQ, (intptr_t)pdqid, (intptr_t)data, (intptr_t)datapri, 0, 0); }
Inline ER ipsnd_pdq(ID pdqid, intptr_t data, PRI datapri) { return (ER)TOPPERS_svc_trap(TFN_IPSND_PDQ, (intptr_t)pdqid, (intptr_t)data, (intptr_t)datapri, 0, 0); }
Inline ER tsnd_pdq(ID pdqid, intptr_t data, PRI datapri, TMO tmout) { return (ER)TOPPERS_svc_trap(TFN_TSND_PDQ, (intptr_t)pdqid, (intptr_t)data, (intptr_t)datapri, (intptr_t)tmout, 0); }
Inline ER rcv_pdq(ID pdqid, intptr_t *p_data, PRI *p_datapri) { return (ER)TOPPERS_svc_trap(TFN_RCV_PDQ, (intptr_t)pdqid, (intptr_t)p_data, (intptr_t)p_datapri, 0, 0); }
Inline ER prcv_pdq(ID pdqid, intptr_t *p_data, PRI *p_datapri) { return (ER)TOPPERS_svc_trap(TFN_PRCV_PDQ, (intptr_t)pdqid, (intptr_t)p_data, (intptr_t)p_datapri, 0, 0); }
Inline ER trcv_pdq(ID pdqid, intptr_t *p_data, PRI *p_datapri, TMO tmout) { return (ER)TOPPERS_svc_trap(TFN_TRCV_PDQ, (intptr_t)pdqid, (intptr_t)p_data, (intptr_t)p_datapri, (intptr_t)tmout, 0); }
Inline ER ini_pdq(ID pdqid) { return (ER)TOPPERS_svc_trap(TFN_INI_PDQ, (intptr_t)pdqid, 0, 0, 0, 0); }
Inline ER ref_pdq(ID pdqid, T_RPDQ *pk_rpdq) { return (ER)TOPPERS_svc_trap(TFN_REF_PDQ, (intptr_t)pdqid, (intptr_t)pk_rpdq, 0, 0, 0); }
Inline ER loc_mtx(ID mtxid) { return (ER)TOPPERS_svc_trap(TFN_LOC_MTX, (intptr_t)mtxid, 0, 0, 0, 0); }
Inline ER ploc_mtx(ID mtxid) { return (ER)TOPPERS_svc_trap(TFN_PLOC_MTX, (intptr_t)mtxid, 0, 0, 0, 0); }
Inline ER tloc_mtx(ID mtxid, TMO tmout) { return (ER)TOPPERS_svc_trap(TFN_TLOC_MTX, (intptr_t)mtxid, (intptr_t)tmout, 0, 0, 0); }
Inline ER unl_mtx(ID mtxid) { return (ER)TOPPERS_svc_trap(TFN_UNL_MTX, (intptr_t)mtxid, 0, 0, 0, 0); }
Inline ER ini_mtx(ID mtxid) { return (ER)TOPPERS_svc_trap(TFN_INI_MTX, (intptr_t)mtxid, 0, 0, 0, 0); }
Inline ER ref_mtx(ID mtxid, T_RMTX *pk_rmtx) { return (ER)TOPPERS_svc_trap(TFN_REF_MTX, (intptr_t)mtxid, (intptr_t)pk_rmtx, 0, 0, 0); }
Inline ER ini_sem(ID semid) { return (ER)TOPPERS_svc_trap(TFN_INI_SEM, (intptr_t)semid, 0, 0, 0, 0); }
Inline ER ref_sem(ID semid, T_RSEM *pk_rsem) { return (ER)TOPPERS_svc_trap(TFN_REF_SEM, (intptr_t)semid, (intptr_t)pk_rsem, 0, 0, 0); }
Inline ER ini_flg(ID flgid) { return (ER)TOPPERS_svc_trap(TFN_INI_FLG, (intptr_t)flgid, 0, 0, 0, 0); }
Inline ER ref_flg(ID flgid, T_RFLG *pk_rflg) { return (ER)TOPPERS_svc_trap(TFN_REF_FLG, (intptr_t)flgid, (intptr_t)pk_rflg, 0, 0, 0); }
Inline ER ref_cyc(ID cycid, T_RCYC *pk_rcyc) { return (ER)TOPPERS_svc_trap(TFN_REF_CYC, (intptr_t)cycid, (intptr_t)pk_rcyc, 0, 0, 0); }
Inline ER ref_alm(ID almid, T_RALM *pk_ralm) { return (ER)TOPPERS_svc_trap(TFN_REF_ALM, (intptr_t)almid, (intptr_t)pk_ralm, 0, 0, 0); }
Inline ER get_inf(intptr_t *p_exinf) { return (ER)TOPPERS_svc_trap(TFN_GET_INF, (intptr_t)p_exinf, 0, 0, 0, 0); }
Inline ER get_tim(SYSTIM *p_systim) { return (ER)TOPPERS_svc_trap(TFN_GET_TIM, (intptr_t)p_systim, 0, 0, 0, 0); }
Inline ER get_utm(SYSUTM *p_sysutm) { return (ER)TOPPERS_svc_trap(TFN_GET_UTM, (intptr_t)p_sysutm, 0, 0, 0, 0); }
Inline ER sta_cyc(ID cycid) { return (ER)TOPPERS_svc_trap(TFN_STA_CYC, (intptr_t)cycid, 0, 0, 0, 0); }
Inline ER stp_cyc(ID cycid) { return (ER)TOPPERS_svc_trap(TFN_STP_CYC, (intptr_t)cycid, 0, 0, 0, 0); }
Inline ER sta_alm(ID almid, RELTIM almtim) { return (ER)TOPPERS_svc_trap(TFN_STA_ALM, (intptr_t)almid, (intptr_t)almtim, 0, 0, 0); }
Inline ER ista_alm(ID almid, RELTIM almtim) { return (ER)TOPPERS_svc_trap(TFN_ISTA_ALM, (intptr_t)almid, (intptr_t)almtim, 0, 0, 0); }
Inline ER stp_alm(ID almid) { return (ER)TOPPERS_svc_trap(TFN_STP_ALM, (intptr_t)almid, 0, 0, 0, 0); }
Inline ER istp_alm(ID almid) { return (ER)TOPPERS_svc_trap(TFN_ISTP_ALM, (intptr_t)almid, 0, 0, 0, 0); }
Inline ER rot_rdq(PRI tskpri) { return (ER)TOPPERS_svc_trap(TFN_ROT_RDQ, (intptr_t)tskpri, 0, 0, 0, 0); }
Inline ER irot_rdq(PRI tskpri) { return (ER)TOPPERS_svc_trap(TFN_IROT_RDQ, (intptr_t)tskpri, 0, 0, 0, 0); }
Inline ER loc_cpu(void) { return (ER)TOPPERS_svc_trap(TFN_LOC_CPU, 0, 0, 0, 0, 0); }
Inline ER iloc_cpu(void) { return (ER)TOPPERS_svc_trap(TFN_ILOC_CPU, 0, 0, 0, 0, 0); }
Inline ER unl_cpu(void) { return (ER)TOPPERS_svc_trap(TFN_UNL_CPU, 0, 0, 0, 0, 0); }
Inline ER iunl_cpu(void) { return (ER)TOPPERS_svc_trap(TFN_IUNL_CPU, 0, 0, 0, 0, 0); }
Inline ER dis_dsp(void) { return (ER)TOPPERS_svc_trap(TFN_DIS_DSP, 0, 0, 0, 0, 0); }
Inline ER ena_dsp(void) { return (ER)TOPPERS_svc_trap(TFN_ENA_DSP, 0, 0, 0, 0, 0); }
Inline bool_t sns_ctx(void) { return (bool_t)TOPPERS_svc_trap(TFN_SNS_CTX, 0, 0, 0, 0, 0); }
Inline bool_t sns_loc(void) { return (bool_t)TOPPERS_svc_trap(TFN_SNS_LOC, 0, 0, 0, 0, 0); }
Inline bool_t sns_dsp(void) { return (bool_t)TOPPERS_svc_trap(TFN_SNS_DSP, 0, 0, 0, 0, 0); }
Inline bool_t sns_dpn(void) { return (bool_t)TOPPERS_svc_trap(TFN_SNS_DPN, 0, 0, 0, 0, 0); }
Inline ER ext_ker(void) { return (ER)TOPPERS_svc_trap(TFN_EXT_KER, 0, 0, 0, 0, 0); }
Inline ER dis_int(INTNO intno) { return (ER)TOPPERS_svc_trap(TFN_DIS_INT, (intptr_t)intno, 0, 0, 0, 0); }
Inline ER ena_int(INTNO intno) { return (ER)TOPPERS_svc_trap(TFN_ENA_INT, (intptr_t)intno, 0, 0, 0, 0); }
Inline ER prb_mem(const void *base, SIZE size, ID tskid, MODE pmmode) { return (ER)TOPPERS_svc_trap(TFN_PRB_MEM, (intptr_t)base, (intptr_t)size, (intptr_t)tskid, (intptr_t)pmmode, 0); }
#else
/*
 * The host: a user domain's call is the kernel's entry itself.  In the HRP3
 * profile (EV3LX_KERNEL_HRP3) a call whose HRP3 form differs from HRP2's
 * (time in us, or callable from non-task context too) enters the host
 * kernel's HRP3 entry point ev3lx_hrp3_NAME instead (rtos_stub/src/host/hrp3.c).
 */
#ifdef EV3LX_KERNEL_HRP3
#define EV3LX_ENTRY(name) ev3lx_hrp3_##name
ER ev3lx_hrp3_act_tsk(ID tskid);
ER ev3lx_hrp3_get_tid(ID *p_tskid);
ER ev3lx_hrp3_tslp_tsk(TMO tmout);
ER ev3lx_hrp3_wup_tsk(ID tskid);
ER ev3lx_hrp3_rel_wai(ID tskid);
ER ev3lx_hrp3_dly_tsk(RELTIM dlytim);
ER ev3lx_hrp3_sig_sem(ID semid);
ER ev3lx_hrp3_twai_sem(ID semid, TMO tmout);
ER ev3lx_hrp3_set_flg(ID flgid, FLGPTN setptn);
ER ev3lx_hrp3_twai_flg(ID flgid, FLGPTN waiptn, MODE wfmode, FLGPTN *p_flgptn, TMO tmout);
ER ev3lx_hrp3_psnd_dtq(ID dtqid, intptr_t data);
ER ev3lx_hrp3_tsnd_dtq(ID dtqid, intptr_t data, TMO tmout);
ER ev3lx_hrp3_fsnd_dtq(ID dtqid, intptr_t data);
ER ev3lx_hrp3_trcv_dtq(ID dtqid, intptr_t *p_data, TMO tmout);
ER ev3lx_hrp3_psnd_pdq(ID pdqid, intptr_t data, PRI datapri);
ER ev3lx_hrp3_tsnd_pdq(ID pdqid, intptr_t data, PRI datapri, TMO tmout);
ER ev3lx_hrp3_trcv_pdq(ID pdqid, intptr_t *p_data, PRI *p_datapri, TMO tmout);
ER ev3lx_hrp3_tloc_mtx(ID mtxid, TMO tmout);
ER ev3lx_hrp3_get_tim(SYSTIM *p_systim);
ER ev3lx_hrp3_sta_alm(ID almid, RELTIM almtim);
ER ev3lx_hrp3_stp_alm(ID almid);
ER ev3lx_hrp3_rot_rdq(PRI tskpri);
ER ev3lx_hrp3_loc_cpu(void);
ER ev3lx_hrp3_unl_cpu(void);
ER ev3lx_hrp3_ref_cyc(ID cycid, T_RCYC *pk_rcyc);
ER ev3lx_hrp3_ref_alm(ID almid, T_RALM *pk_ralm);
#else
#define EV3LX_ENTRY(name) _kernel_##name
#endif
Inline ER act_tsk(ID tskid) { return EV3LX_ENTRY(act_tsk)(tskid); }
Inline ER iact_tsk(ID tskid) { return _kernel_iact_tsk(tskid); }
Inline ER_UINT can_act(ID tskid) { return _kernel_can_act(tskid); }
Inline ER ext_tsk(void) { return _kernel_ext_tsk(); }
Inline ER chg_pri(ID tskid, PRI tskpri) { return _kernel_chg_pri(tskid, tskpri); }
Inline ER get_pri(ID tskid, PRI *p_tskpri) { return _kernel_get_pri(tskid, p_tskpri); }
Inline ER get_tid(ID *p_tskid) { return EV3LX_ENTRY(get_tid)(p_tskid); }
Inline ER iget_tid(ID *p_tskid) { return _kernel_iget_tid(p_tskid); }
Inline ER slp_tsk(void) { return _kernel_slp_tsk(); }
Inline ER tslp_tsk(TMO tmout) { return EV3LX_ENTRY(tslp_tsk)(tmout); }
Inline ER wup_tsk(ID tskid) { return EV3LX_ENTRY(wup_tsk)(tskid); }
Inline ER iwup_tsk(ID tskid) { return _kernel_iwup_tsk(tskid); }
Inline ER_UINT can_wup(ID tskid) { return _kernel_can_wup(tskid); }
Inline ER rel_wai(ID tskid) { return EV3LX_ENTRY(rel_wai)(tskid); }
Inline ER irel_wai(ID tskid) { return _kernel_irel_wai(tskid); }
Inline ER dly_tsk(RELTIM dlytim) { return EV3LX_ENTRY(dly_tsk)(dlytim); }
Inline ER sus_tsk(ID tskid) { return _kernel_sus_tsk(tskid); }
Inline ER rsm_tsk(ID tskid) { return _kernel_rsm_tsk(tskid); }
Inline ER ter_tsk(ID tskid) { return _kernel_ter_tsk(tskid); }
Inline ER sig_sem(ID semid) { return EV3LX_ENTRY(sig_sem)(semid); }
Inline ER isig_sem(ID semid) { return _kernel_isig_sem(semid); }
Inline ER wai_sem(ID semid) { return _kernel_wai_sem(semid); }
Inline ER pol_sem(ID semid) { return _kernel_pol_sem(semid); }
Inline ER twai_sem(ID semid, TMO tmout) { return EV3LX_ENTRY(twai_sem)(semid, tmout); }
Inline ER set_flg(ID flgid, FLGPTN setptn) { return EV3LX_ENTRY(set_flg)(flgid, setptn); }
Inline ER iset_flg(ID flgid, FLGPTN setptn) { return _kernel_iset_flg(flgid, setptn); }
Inline ER clr_flg(ID flgid, FLGPTN clrptn) { return _kernel_clr_flg(flgid, clrptn); }
Inline ER wai_flg(ID flgid, FLGPTN waiptn, MODE wfmode, FLGPTN *p_flgptn) { return _kernel_wai_flg(flgid, waiptn, wfmode, p_flgptn); }
Inline ER pol_flg(ID flgid, FLGPTN waiptn, MODE wfmode, FLGPTN *p_flgptn) { return _kernel_pol_flg(flgid, waiptn, wfmode, p_flgptn); }
Inline ER twai_flg(ID flgid, FLGPTN waiptn, MODE wfmode, FLGPTN *p_flgptn, TMO tmout) { return EV3LX_ENTRY(twai_flg)(flgid, waiptn, wfmode, p_flgptn, tmout); }
Inline ER snd_dtq(ID dtqid, intptr_t data) { return _kernel_snd_dtq(dtqid, data); }
Inline ER psnd_dtq(ID dtqid, intptr_t data) { return EV3LX_ENTRY(psnd_dtq)(dtqid, data); }
Inline ER ipsnd_dtq(ID dtqid, intptr_t data) { return _kernel_ipsnd_dtq(dtqid, data); }
Inline ER tsnd_dtq(ID dtqid, intptr_t data, TMO tmout) { return EV3LX_ENTRY(tsnd_dtq)(dtqid, data, tmout); }
Inline ER fsnd_dtq(ID dtqid, intptr_t data) { return EV3LX_ENTRY(fsnd_dtq)(dtqid, data); }
Inline ER ifsnd_dtq(ID dtqid, intptr_t data) { return _kernel_ifsnd_dtq(dtqid, data); }
Inline ER rcv_dtq(ID dtqid, intptr_t *p_data) { return _kernel_rcv_dtq(dtqid, p_data); }
Inline ER prcv_dtq(ID dtqid, intptr_t *p_data) { return _kernel_prcv_dtq(dtqid, p_data); }
Inline ER trcv_dtq(ID dtqid, intptr_t *p_data, TMO tmout) { return EV3LX_ENTRY(trcv_dtq)(dtqid, p_data, tmout); }
Inline ER ini_dtq(ID dtqid) { return _kernel_ini_dtq(dtqid); }
Inline ER ref_dtq(ID dtqid, T_RDTQ *pk_rdtq) { return _kernel_ref_dtq(dtqid, pk_rdtq); }
Inline ER snd_pdq(ID pdqid, intptr_t data, PRI datapri) { return _kernel_snd_pdq(pdqid, data, datapri); }
Inline ER psnd_pdq(ID pdqid, intptr_t data, PRI datapri) { return EV3LX_ENTRY(psnd_pdq)(pdqid, data, datapri); }
Inline ER ipsnd_pdq(ID pdqid, intptr_t data, PRI datapri) { return _kernel_ipsnd_pdq(pdqid, data, datapri); }
Inline ER tsnd_pdq(ID pdqid, intptr_t data, PRI datapri, TMO tmout) { return EV3LX_ENTRY(tsnd_pdq)(pdqid, data, datapri, tmout); }
Inline ER rcv_pdq(ID pdqid, intptr_t *p_data, PRI *p_datapri) { return _kernel_rcv_pdq(pdqid, p_data, p_datapri); }
Inline ER prcv_pdq(ID pdqid, intptr_t *p_data, PRI *p_datapri) { return _kernel_prcv_pdq(pdqid, p_data, p_datapri); }
Inline ER trcv_pdq(ID pdqid, intptr_t *p_data, PRI *p_datapri, TMO tmout) { return EV3LX_ENTRY(trcv_pdq)(pdqid, p_data, p_datapri, tmout); }
Inline ER ini_pdq(ID pdqid) { return _kernel_ini_pdq(pdqid); }
Inline ER ref_pdq(ID pdqid, T_RPDQ *pk_rpdq) { return _kernel_ref_pdq(pdqid, pk_rpdq); }
Inline ER loc_mtx(ID mtxid) { return _kernel_loc_mtx(mtxid); }
Inline ER ploc_mtx(ID mtxid) { return _kernel_ploc_mtx(mtxid); }
Inline ER tloc_mtx(ID mtxid, TMO tmout) { return EV3LX_ENTRY(tloc_mtx)(mtxid, tmout); }
Inline ER unl_mtx(ID mtxid) { return _kernel_unl_mtx(mtxid); }
Inline ER ini_mtx(ID mtxid) { return _kernel_ini_mtx(mtxid); }
Inline ER ref_mtx(ID mtxid, T_RMTX *pk_rmtx) { return _kernel_ref_mtx(mtxid, pk_rmtx); }
Inline ER ini_sem(ID semid) { return _kernel_ini_sem(semid); }
Inline ER ref_sem(ID semid, T_RSEM *pk_rsem) { return _kernel_ref_sem(semid, pk_rsem); }
Inline ER ini_flg(ID flgid) { return _kernel_ini_flg(flgid); }
Inline ER ref_flg(ID flgid, T_RFLG *pk_rflg) { return _kernel_ref_flg(flgid, pk_rflg); }
Inline ER ref_cyc(ID cycid, T_RCYC *pk_rcyc) { return EV3LX_ENTRY(ref_cyc)(cycid, pk_rcyc); }
Inline ER ref_alm(ID almid, T_RALM *pk_ralm) { return EV3LX_ENTRY(ref_alm)(almid, pk_ralm); }
Inline ER get_inf(intptr_t *p_exinf) { return _kernel_get_inf(p_exinf); }
Inline ER get_tim(SYSTIM *p_systim) { return EV3LX_ENTRY(get_tim)(p_systim); }
Inline ER get_utm(SYSUTM *p_sysutm) { return _kernel_get_utm(p_sysutm); }
Inline ER sta_cyc(ID cycid) { return _kernel_sta_cyc(cycid); }
Inline ER stp_cyc(ID cycid) { return _kernel_stp_cyc(cycid); }
Inline ER sta_alm(ID almid, RELTIM almtim) { return EV3LX_ENTRY(sta_alm)(almid, almtim); }
Inline ER ista_alm(ID almid, RELTIM almtim) { return _kernel_ista_alm(almid, almtim); }
Inline ER stp_alm(ID almid) { return EV3LX_ENTRY(stp_alm)(almid); }
Inline ER istp_alm(ID almid) { return _kernel_istp_alm(almid); }
Inline ER rot_rdq(PRI tskpri) { return EV3LX_ENTRY(rot_rdq)(tskpri); }
Inline ER irot_rdq(PRI tskpri) { return _kernel_irot_rdq(tskpri); }
Inline ER loc_cpu(void) { return EV3LX_ENTRY(loc_cpu)(); }
Inline ER iloc_cpu(void) { return _kernel_iloc_cpu(); }
Inline ER unl_cpu(void) { return EV3LX_ENTRY(unl_cpu)(); }
Inline ER iunl_cpu(void) { return _kernel_iunl_cpu(); }
Inline ER dis_dsp(void) { return _kernel_dis_dsp(); }
Inline ER ena_dsp(void) { return _kernel_ena_dsp(); }
Inline bool_t sns_ctx(void) { return _kernel_sns_ctx(); }
Inline bool_t sns_loc(void) { return _kernel_sns_loc(); }
Inline bool_t sns_dsp(void) { return _kernel_sns_dsp(); }
Inline bool_t sns_dpn(void) { return _kernel_sns_dpn(); }
Inline ER ext_ker(void) { return _kernel_ext_ker(); }
Inline ER dis_int(INTNO intno) { return _kernel_dis_int(intno); }
Inline ER ena_int(INTNO intno) { return _kernel_ena_int(intno); }
Inline ER prb_mem(const void *base, SIZE size, ID tskid, MODE pmmode) { return _kernel_prb_mem(base, size, tskid, pmmode); }
#endif
#endif /* TOPPERS_SVC_CALL */

#endif /* TOPPERS_MACRO_ONLY */

#endif /* TOPPERS_TARGET_SVC_H */
