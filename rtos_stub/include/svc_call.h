/*
 * svc_call.h — HRP2's service calls by function call: the kernel's own
 * entry points, named _kernel_<call> (ev3rt-git/ev3rt-hrp2, include/svc_call.h).
 * Kernel-domain code (the kernel, system services, drivers: compiled with
 * TOPPERS_SVC_CALL) calls them under the plain names, which this header
 * renames; a user domain reaches the same calls through target_svc.h's
 * software interrupts.  Signatures are HRP2's; the set is the subset ev3lx uses.
 */
/* Included alone, the kernel's types come first: kernel.h defines them and
 * then includes this header. */
#ifndef TOPPERS_SVC_CALL_H
#include "kernel.h"
#endif

#ifndef TOPPERS_SVC_CALL_H
#define TOPPERS_SVC_CALL_H

#ifndef TOPPERS_MACRO_ONLY

/* ---- Task management ---- */
ER      _kernel_act_tsk(ID tskid);              /* activate (queue one activation if not dormant) */
ER      _kernel_iact_tsk(ID tskid);             /* act_tsk from non-task context */
ER_UINT _kernel_can_act(ID tskid);              /* cancel queued activations, return their count */
ER      _kernel_ext_tsk(void);                  /* end the calling task; returns only on error (E_CTX: not a task) */
ER      _kernel_chg_pri(ID tskid, PRI tskpri);  /* change base priority */
ER      _kernel_get_pri(ID tskid, PRI *p_tskpri); /* read current priority */
ER      _kernel_get_tid(ID *p_tskid);           /* ID of the running task */
ER      _kernel_iget_tid(ID *p_tskid);          /* ID of the task interrupted (TSK_NONE if idle) */

/* ---- Task-dependent synchronisation ---- */
ER      _kernel_slp_tsk(void);                  /* sleep until woken */
ER      _kernel_tslp_tsk(TMO tmout);            /* sleep with timeout (E_TMOUT) */
ER      _kernel_wup_tsk(ID tskid);              /* wake, or queue one wakeup */
ER      _kernel_iwup_tsk(ID tskid);
ER_UINT _kernel_can_wup(ID tskid);
ER      _kernel_rel_wai(ID tskid);              /* force a waiting task out with E_RLWAI */
ER      _kernel_irel_wai(ID tskid);
ER      _kernel_dly_tsk(RELTIM dlytim);         /* delay for at least dlytim ms */
ER      _kernel_sus_tsk(ID tskid);              /* suspend (a waiting task becomes waiting-suspended) */
ER      _kernel_rsm_tsk(ID tskid);              /* resume a suspended task */
ER      _kernel_ter_tsk(ID tskid);              /* terminate another task (releases its mutexes) */

/* ---- Semaphores ---- */
ER      _kernel_sig_sem(ID semid);              /* release one resource (E_QOVR at maximum) */
ER      _kernel_isig_sem(ID semid);
ER      _kernel_wai_sem(ID semid);              /* acquire, waiting */
ER      _kernel_pol_sem(ID semid);              /* acquire, E_TMOUT if none */
ER      _kernel_twai_sem(ID semid, TMO tmout);  /* acquire with timeout */

/* ---- Eventflags ---- */
ER      _kernel_set_flg(ID flgid, FLGPTN setptn);
ER      _kernel_iset_flg(ID flgid, FLGPTN setptn);
ER      _kernel_clr_flg(ID flgid, FLGPTN clrptn); /* AND the pattern with clrptn */
ER      _kernel_wai_flg(ID flgid, FLGPTN waiptn, MODE wfmode, FLGPTN *p_flgptn);
ER      _kernel_pol_flg(ID flgid, FLGPTN waiptn, MODE wfmode, FLGPTN *p_flgptn);
ER      _kernel_twai_flg(ID flgid, FLGPTN waiptn, MODE wfmode, FLGPTN *p_flgptn, TMO tmout);

/* ---- Data queues (intptr_t elements, FIFO) ---- */
ER      _kernel_snd_dtq(ID dtqid, intptr_t data); /* send, waiting while full */
ER      _kernel_psnd_dtq(ID dtqid, intptr_t data); /* send, E_TMOUT if full */
ER      _kernel_ipsnd_dtq(ID dtqid, intptr_t data);
ER      _kernel_tsnd_dtq(ID dtqid, intptr_t data, TMO tmout);
ER      _kernel_fsnd_dtq(ID dtqid, intptr_t data); /* send, dropping the oldest element if full */
ER      _kernel_ifsnd_dtq(ID dtqid, intptr_t data);
ER      _kernel_rcv_dtq(ID dtqid, intptr_t *p_data); /* receive, waiting while empty */
ER      _kernel_prcv_dtq(ID dtqid, intptr_t *p_data); /* receive, E_TMOUT if empty */
ER      _kernel_trcv_dtq(ID dtqid, intptr_t *p_data, TMO tmout);
ER      _kernel_ini_dtq(ID dtqid);              /* empty it; waiting tasks get E_DLT */
ER      _kernel_ref_dtq(ID dtqid, T_RDTQ *pk_rdtq);

/* ---- Priority data queues (ordered by data priority, FIFO within one) ---- */
ER      _kernel_snd_pdq(ID pdqid, intptr_t data, PRI datapri);
ER      _kernel_psnd_pdq(ID pdqid, intptr_t data, PRI datapri);
ER      _kernel_ipsnd_pdq(ID pdqid, intptr_t data, PRI datapri);
ER      _kernel_tsnd_pdq(ID pdqid, intptr_t data, PRI datapri, TMO tmout);
ER      _kernel_rcv_pdq(ID pdqid, intptr_t *p_data, PRI *p_datapri);
ER      _kernel_prcv_pdq(ID pdqid, intptr_t *p_data, PRI *p_datapri);
ER      _kernel_trcv_pdq(ID pdqid, intptr_t *p_data, PRI *p_datapri, TMO tmout);
ER      _kernel_ini_pdq(ID pdqid);
ER      _kernel_ref_pdq(ID pdqid, T_RPDQ *pk_rpdq);

/* ---- Mutexes (TA_CEILING: priority ceiling; TA_INHERIT: priority inheritance) ---- */
ER      _kernel_loc_mtx(ID mtxid);              /* lock, waiting while another task holds it */
ER      _kernel_ploc_mtx(ID mtxid);             /* lock, E_TMOUT if held */
ER      _kernel_tloc_mtx(ID mtxid, TMO tmout);
ER      _kernel_unl_mtx(ID mtxid);              /* unlock; mutexes unlock in reverse order of locking */
ER      _kernel_ini_mtx(ID mtxid);              /* unlock; waiting tasks get E_DLT */
ER      _kernel_ref_mtx(ID mtxid, T_RMTX *pk_rmtx);

/* ---- Initialisation and reference ---- */
ER      _kernel_ini_sem(ID semid);              /* back to isemcnt; waiting tasks get E_DLT */
ER      _kernel_ref_sem(ID semid, T_RSEM *pk_rsem);
ER      _kernel_ini_flg(ID flgid);              /* back to iflgptn; waiting tasks get E_DLT */
ER      _kernel_ref_flg(ID flgid, T_RFLG *pk_rflg);
ER      _kernel_ref_cyc(ID cycid, T_RCYC *pk_rcyc);
ER      _kernel_ref_alm(ID almid, T_RALM *pk_ralm);
ER      _kernel_get_inf(intptr_t *p_exinf);     /* the calling task's exinf */

/* ---- Time management ---- */
ER      _kernel_get_tim(SYSTIM *p_systim);      /* system time in ms since boot */
ER      _kernel_get_utm(SYSUTM *p_sysutm);      /* performance time in us since boot */
ER      _kernel_sta_cyc(ID cycid);              /* start a cyclic handler */
ER      _kernel_stp_cyc(ID cycid);
ER      _kernel_sta_alm(ID almid, RELTIM almtim); /* start an alarm, almtim ms from now */
ER      _kernel_ista_alm(ID almid, RELTIM almtim);
ER      _kernel_stp_alm(ID almid);
ER      _kernel_istp_alm(ID almid);

/* ---- System state ---- */
ER      _kernel_rot_rdq(PRI tskpri);            /* rotate the ready queue of a priority */
ER      _kernel_irot_rdq(PRI tskpri);
ER      _kernel_loc_cpu(void);                  /* CPU lock: mask all interrupts and dispatch */
ER      _kernel_iloc_cpu(void);
ER      _kernel_unl_cpu(void);
ER      _kernel_iunl_cpu(void);
ER      _kernel_dis_dsp(void);                  /* disable dispatching */
ER      _kernel_ena_dsp(void);
bool_t  _kernel_sns_ctx(void);                  /* TRUE in non-task context */
bool_t  _kernel_sns_loc(void);                  /* TRUE with the CPU locked */
bool_t  _kernel_sns_dsp(void);                  /* TRUE with dispatching disabled */
bool_t  _kernel_sns_dpn(void);                  /* TRUE when dispatching is pending/not possible */
ER      _kernel_ext_ker(void);                  /* end the kernel: ATT_TER routines, then stop */

/* ---- Interrupts ---- */
ER      _kernel_dis_int(INTNO intno);           /* mask one interrupt line */
ER      _kernel_ena_int(INTNO intno);           /* unmask one interrupt line */

/* ---- Memory protection (HRP2; cal_svc is target_svc.h's trap) ---- */
/* E_OK if the task's protection domain may access [base, base+size) with pmmode, else E_MACV. */
ER      _kernel_prb_mem(const void *base, SIZE size, ID tskid, MODE pmmode);

#endif /* TOPPERS_MACRO_ONLY */

#ifdef TOPPERS_SVC_CALL
#define act_tsk   _kernel_act_tsk
#define iact_tsk  _kernel_iact_tsk
#define can_act   _kernel_can_act
#define ext_tsk   _kernel_ext_tsk
#define chg_pri   _kernel_chg_pri
#define get_pri   _kernel_get_pri
#define get_tid   _kernel_get_tid
#define iget_tid  _kernel_iget_tid
#define slp_tsk   _kernel_slp_tsk
#define tslp_tsk  _kernel_tslp_tsk
#define wup_tsk   _kernel_wup_tsk
#define iwup_tsk  _kernel_iwup_tsk
#define can_wup   _kernel_can_wup
#define rel_wai   _kernel_rel_wai
#define irel_wai  _kernel_irel_wai
#define dly_tsk   _kernel_dly_tsk
#define sus_tsk   _kernel_sus_tsk
#define rsm_tsk   _kernel_rsm_tsk
#define ter_tsk   _kernel_ter_tsk
#define sig_sem   _kernel_sig_sem
#define isig_sem  _kernel_isig_sem
#define wai_sem   _kernel_wai_sem
#define pol_sem   _kernel_pol_sem
#define twai_sem  _kernel_twai_sem
#define set_flg   _kernel_set_flg
#define iset_flg  _kernel_iset_flg
#define clr_flg   _kernel_clr_flg
#define wai_flg   _kernel_wai_flg
#define pol_flg   _kernel_pol_flg
#define twai_flg  _kernel_twai_flg
#define snd_dtq   _kernel_snd_dtq
#define psnd_dtq  _kernel_psnd_dtq
#define ipsnd_dtq _kernel_ipsnd_dtq
#define tsnd_dtq  _kernel_tsnd_dtq
#define fsnd_dtq  _kernel_fsnd_dtq
#define ifsnd_dtq _kernel_ifsnd_dtq
#define rcv_dtq   _kernel_rcv_dtq
#define prcv_dtq  _kernel_prcv_dtq
#define trcv_dtq  _kernel_trcv_dtq
#define ini_dtq   _kernel_ini_dtq
#define ref_dtq   _kernel_ref_dtq
#define snd_pdq   _kernel_snd_pdq
#define psnd_pdq  _kernel_psnd_pdq
#define ipsnd_pdq _kernel_ipsnd_pdq
#define tsnd_pdq  _kernel_tsnd_pdq
#define rcv_pdq   _kernel_rcv_pdq
#define prcv_pdq  _kernel_prcv_pdq
#define trcv_pdq  _kernel_trcv_pdq
#define ini_pdq   _kernel_ini_pdq
#define ref_pdq   _kernel_ref_pdq
#define loc_mtx   _kernel_loc_mtx
#define ploc_mtx  _kernel_ploc_mtx
#define tloc_mtx  _kernel_tloc_mtx
#define unl_mtx   _kernel_unl_mtx
#define ini_mtx   _kernel_ini_mtx
#define ref_mtx   _kernel_ref_mtx
#define ini_sem   _kernel_ini_sem
#define ref_sem   _kernel_ref_sem
#define ini_flg   _kernel_ini_flg
#define ref_flg   _kernel_ref_flg
#define ref_cyc   _kernel_ref_cyc
#define ref_alm   _kernel_ref_alm
#define get_inf   _kernel_get_inf
#define get_tim   _kernel_get_tim
#define get_utm   _kernel_get_utm
#define sta_cyc   _kernel_sta_cyc
#define stp_cyc   _kernel_stp_cyc
#define sta_alm   _kernel_sta_alm
#define ista_alm  _kernel_ista_alm
#define stp_alm   _kernel_stp_alm
#define istp_alm  _kernel_istp_alm
#define rot_rdq   _kernel_rot_rdq
#define irot_rdq  _kernel_irot_rdq
#define loc_cpu   _kernel_loc_cpu
#define iloc_cpu  _kernel_iloc_cpu
#define unl_cpu   _kernel_unl_cpu
#define iunl_cpu  _kernel_iunl_cpu
#define dis_dsp   _kernel_dis_dsp
#define ena_dsp   _kernel_ena_dsp
#define sns_ctx   _kernel_sns_ctx
#define sns_loc   _kernel_sns_loc
#define sns_dsp   _kernel_sns_dsp
#define sns_dpn   _kernel_sns_dpn
#define ext_ker   _kernel_ext_ker
#define dis_int   _kernel_dis_int
#define ena_int   _kernel_ena_int
#define prb_mem   _kernel_prb_mem
#endif /* TOPPERS_SVC_CALL */

#endif /* TOPPERS_SVC_CALL_H */
