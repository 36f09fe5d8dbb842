/*
 * kernel_hrp3.h — the names TOPPERS/HRP3's kernel.h adds to HRP2's, for an
 * app built in the HRP3 profile (EV3LX_KERNEL_HRP3; kernel.h includes it
 * then).  Names and values are HRP3's (public source: ev3rt-git/ev3rt-hrp3,
 * include/kernel.h, include/t_stddef.h); the calls are served by the host
 * kernel (rtos_stub/src/host/hrp3.c, docs/ev3rt-apps.md, "Two kernel profiles").
 */
#ifndef TOPPERS_KERNEL_HRP3_H
#define TOPPERS_KERNEL_HRP3_H

/* Included by name, it makes the including file an HRP3 one; after kernel.h
 * of the HRP2 profile it could only contradict it. */
#if defined(TOPPERS_KERNEL_H) && !defined(EV3LX_KERNEL_HRP3)
#error "kernel_hrp3.h after kernel.h of the HRP2 profile: an app is built for one profile (docs/ev3rt-apps.md)"
#endif
#ifndef EV3LX_KERNEL_HRP3
#define EV3LX_KERNEL_HRP3 1
#endif
#include "kernel.h"

#ifdef __cplusplus
extern "C" {
#endif

/* ---- The kernel's identification (HRP3 3.x) ---- */
#define TKERNEL_MAKER   0x0118U    /* TOPPERS Project */
#define TKERNEL_PRID    0x0006U    /* HRP3 */
#define TKERNEL_SPVER   0xf633U    /* the third-generation kernel specification */

/* ---- Notification modes of CRE_CYC and CRE_ALM (nfymode) ---- */
#define TNFY_HANDLER    0x00U      /* call a time-event handler (exinf, handler) */
#define TNFY_SETVAR     0x01U      /* set a variable (p_var, value) */
#define TNFY_INCVAR     0x02U      /* increment a variable (p_var) */
#define TNFY_ACTTSK     0x03U      /* activate a task (tskid) */
#define TNFY_WUPTSK     0x04U      /* wake up a task (tskid) */
#define TNFY_SIGSEM     0x05U      /* signal a semaphore (semid) */
#define TNFY_SETFLG     0x06U      /* set an eventflag (flgid, flgptn) */
#define TNFY_SNDDTQ     0x07U      /* send to a data queue (dtqid, data) */
/* What is done when the notification fails (ORed into nfymode) */
#define TENFY_SETVAR    0x10U      /* set a variable to the error code (p_var) */
#define TENFY_INCVAR    0x20U      /* increment a variable (p_var) */
#define TENFY_ACTTSK    0x30U      /* activate a task (tskid) */
#define TENFY_WUPTSK    0x40U      /* wake up a task (tskid) */
#define TENFY_SIGSEM    0x50U      /* signal a semaphore (semid) */
#define TENFY_SETFLG    0x60U      /* set an eventflag (flgid, flgptn) */
#define TENFY_SNDDTQ    0x70U      /* send the error code to a data queue (dtqid) */

#ifndef TOPPERS_MACRO_ONLY

/* A time-event handler (TNFY_HANDLER). */
typedef void (*TMEHDR)(intptr_t exinf);
/* A notification handler: what the configurator makes of a notification. */
typedef void (*NFYHDR)(intptr_t exinf);

/* The notification information of HRP3's T_CCYC and T_CALM. */
typedef struct { intptr_t exinf; TMEHDR tmehdr; } T_NFY_HDR;
typedef struct { intptr_t *p_var; intptr_t value; } T_NFY_VAR;
typedef struct { intptr_t *p_var; } T_NFY_IVAR;
typedef struct { ID tskid; } T_NFY_TSK;
typedef struct { ID semid; } T_NFY_SEM;
typedef struct { ID flgid; FLGPTN flgptn; } T_NFY_FLG;
typedef struct { ID dtqid; intptr_t data; } T_NFY_DTQ;
typedef struct { intptr_t *p_var; } T_ENFY_VAR;
typedef struct { ID dtqid; } T_ENFY_DTQ;

typedef struct {
	MODE nfymode;
	union {
		T_NFY_HDR  handler;
		T_NFY_VAR  setvar;
		T_NFY_IVAR incvar;
		T_NFY_TSK  acttsk;
		T_NFY_TSK  wuptsk;
		T_NFY_SEM  sigsem;
		T_NFY_FLG  setflg;
		T_NFY_DTQ  snddtq;
	} nfy;
	union {
		T_ENFY_VAR setvar;
		T_NFY_IVAR incvar;
		T_NFY_TSK  acttsk;
		T_NFY_TSK  wuptsk;
		T_NFY_SEM  sigsem;
		T_NFY_FLG  setflg;
		T_ENFY_DTQ snddtq;
	} enfy;
} T_NFYINFO;

typedef struct t_ccyc {
	ATR       cycatr;
	T_NFYINFO nfyinfo;
	RELTIM    cyctim;
	RELTIM    cycphs;
} T_CCYC;

typedef struct t_calm {
	ATR       almatr;
	T_NFYINFO nfyinfo;
} T_CALM;

/* The high-resolution timer: us since boot, modulo 2^32 (any context). */
HRTCNT  fch_hrt(void) EV3LX_HRP3_SVC(fch_hrt);

/* HRP3 calls ev3lx does not provide: an app using one compiles, and its link
 * fails naming it (undefined reference to `ev3lx_not_yet_supported__hrp3__ras_ter'). */
#define EV3LX_HRP3_NOT_YET(name) __asm__("ev3lx_not_yet_supported__hrp3__" #name)
ER      get_tst(ID tskid, STAT *p_tskstat) EV3LX_HRP3_NOT_YET(get_tst);
ER      ras_ter(ID tskid) EV3LX_HRP3_NOT_YET(ras_ter);
ER      dis_ter(void) EV3LX_HRP3_NOT_YET(dis_ter);
ER      ena_ter(void) EV3LX_HRP3_NOT_YET(ena_ter);
bool_t  sns_ter(void) EV3LX_HRP3_NOT_YET(sns_ter);
ER      set_tim(SYSTIM systim) EV3LX_HRP3_NOT_YET(set_tim);
ER      adj_tim(int32_t adjtim) EV3LX_HRP3_NOT_YET(adj_tim);
ER      get_did(ID *p_domid) EV3LX_HRP3_NOT_YET(get_did);
ER      get_lod(PRI tskpri, uint_t *p_load) EV3LX_HRP3_NOT_YET(get_lod);
ER      get_nth(PRI tskpri, uint_t nth, ID *p_tskid) EV3LX_HRP3_NOT_YET(get_nth);
bool_t  sns_ker(void) EV3LX_HRP3_NOT_YET(sns_ker);
ER      chg_ipm(PRI intpri) EV3LX_HRP3_NOT_YET(chg_ipm);
ER      get_ipm(PRI *p_intpri) EV3LX_HRP3_NOT_YET(get_ipm);
ER      sta_ovr(ID tskid, PRCTIM ovrtim) EV3LX_HRP3_NOT_YET(sta_ovr);
ER      stp_ovr(ID tskid) EV3LX_HRP3_NOT_YET(stp_ovr);
ER      snd_mbf(ID mbfid, const void *msg, uint_t msgsz) EV3LX_HRP3_NOT_YET(snd_mbf);
ER_UINT rcv_mbf(ID mbfid, void *msg) EV3LX_HRP3_NOT_YET(rcv_mbf);
ER      get_mpf(ID mpfid, void **p_blk) EV3LX_HRP3_NOT_YET(get_mpf);
ER      rel_mpf(ID mpfid, void *blk) EV3LX_HRP3_NOT_YET(rel_mpf);

#endif /* TOPPERS_MACRO_ONLY */

/* HRP3 has no i-calls: the i-names are the calls themselves, which work in
 * task and non-task context alike. */
#define iact_tsk(tskid)                 act_tsk(tskid)
#define iwup_tsk(tskid)                 wup_tsk(tskid)
#define irel_wai(tskid)                 rel_wai(tskid)
#define isig_sem(semid)                 sig_sem(semid)
#define iset_flg(flgid, setptn)         set_flg(flgid, setptn)
#define ipsnd_dtq(dtqid, data)          psnd_dtq(dtqid, data)
#define ifsnd_dtq(dtqid, data)          fsnd_dtq(dtqid, data)
#define ipsnd_pdq(pdqid, data, datapri) psnd_pdq(pdqid, data, datapri)
#define ifch_hrt()                      fch_hrt()
#define ista_alm(almid, almtim)         sta_alm(almid, almtim)
#define istp_alm(almid)                 stp_alm(almid)
#define irot_rdq(tskpri)                rot_rdq(tskpri)
#define iget_tid(p_tskid)               get_tid(p_tskid)
#define iloc_cpu()                      loc_cpu()
#define iunl_cpu()                      unl_cpu()
#define isns_ctx()                      sns_ctx()
#define isns_loc()                      sns_loc()
#define isns_dsp()                      sns_dsp()
#define isns_dpn()                      sns_dpn()

#ifdef __cplusplus
}
#endif

#endif /* TOPPERS_KERNEL_HRP3_H */
