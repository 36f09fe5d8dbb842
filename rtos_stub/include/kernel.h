/*
 * kernel.h — the TOPPERS/HRP2 service-call subset ev3lx stands on, and for
 * an app built in the HRP3 profile (EV3LX_KERNEL_HRP3) TOPPERS/HRP3's forms
 * of them (kernel_hrp3.h, docs/ev3rt-apps.md "Two kernel profiles").
 *
 * Signatures, constants and error codes are those of TOPPERS/HRP2, so that
 * everything above rtos_stub links unchanged against the real kernel on the
 * AM1808.  On the host the same calls are served by a deterministic
 * single-CPU kernel in virtual time (rtos_stub/src/host, see rtos_host.h).
 *
 * Service-call shape (every call): check arguments and context, lock, act,
 * unlock, return an ER code.  Task-only calls from non-task context, i-calls
 * from task context, and blocking calls with the CPU locked or dispatching
 * disabled return E_CTX.
 */
#ifndef TOPPERS_KERNEL_H
#define TOPPERS_KERNEL_H

#ifdef __cplusplus
extern "C" {
#endif

#include "t_stddef.h"
#include "t_syslog.h"

/* ---- Tick: TIC_NUME/TIC_DENO ms per tick (default 1/5 ms = 200 us). ---- */
#ifndef TIC_NUME
#define TIC_NUME 1U
#endif
#ifndef TIC_DENO
#define TIC_DENO 5U
#endif

/* ---- Object types ---- */
typedef uint_t   FLGPTN;  /* eventflag bit pattern */
typedef uint_t   INTNO;   /* interrupt number */
typedef uint_t   INHNO;   /* interrupt handler number */
typedef uint_t   EXCNO;   /* CPU exception handler number */
typedef uint_t   TEXPTN;  /* task exception pattern (HRP2's type; ev3lx has no task exceptions) */

typedef void (*TASK)(intptr_t exinf);
typedef void (*ISR)(intptr_t exinf);
typedef void (*CYCHDR)(intptr_t exinf);
typedef void (*ALMHDR)(intptr_t exinf);
typedef void (*INIRTN)(intptr_t exinf);
typedef void (*TERRTN)(intptr_t exinf);
typedef void (*TEXRTN)(TEXPTN texptn, intptr_t exinf);  /* task exception routine */
/* An extended service routine (HRP2 DEF_SVC): five parameters and the caller's domain. */
typedef ER_UINT (*EXTSVC)(intptr_t par1, intptr_t par2, intptr_t par3,
			  intptr_t par4, intptr_t par5, ID cdmid);

/* ---- Priorities ---- */
#define TMIN_TPRI    1      /* highest task priority */
#define TMAX_TPRI    16     /* lowest task priority */
#define TMIN_INTPRI  (-7)   /* highest interrupt priority */
#define TMAX_INTPRI  (-1)   /* lowest interrupt priority */
#define TIPM_ENAALL  0      /* interrupt priority mask: all enabled */
#define TMIN_DPRI    1      /* highest data priority (priority data queues) */
#define TMAX_DPRI    16     /* lowest data priority */
#define TMIN_ISRPRI  1      /* first ISR on a line */
#define TMAX_ISRPRI  16     /* last ISR on a line */

/* ---- Limits ---- */
#define TMAX_ACTCNT  1U           /* queued activations per task */
#define TMAX_WUPCNT  1U           /* queued wakeups per task */
#ifndef EV3LX_KERNEL_HRP3
#define TMAX_RELTIM  0x7fffffffU  /* largest relative time (ms); HRP3's is in t_stddef.h */
#endif
#define TBIT_FLGPTN  ((uint_t)(sizeof(FLGPTN) * 8U))

/* ---- Special IDs and values ---- */
#define TSK_SELF     0
#define TSK_NONE     0
#define TPRI_SELF    0
#define TPRI_INI     0
#define TDOM_SELF    0
#define TDOM_KERNEL  (-1)
#define TDOM_NONE    (-2)

/* ---- Attributes ---- */
#define TA_ACT       0x02U  /* task: activate at boot */
#define TA_TPRI      0x01U  /* wait queue in priority order */
#define TA_WMUL      0x02U  /* eventflag: several waiters */
#define TA_CLR       0x04U  /* eventflag: clear on release */
#define TA_INHERIT   0x02U  /* mutex: priority inheritance (uITRON 4.0) */
#define TA_CEILING   0x03U  /* mutex: priority ceiling protocol */
#define TA_STA       0x02U  /* cyclic: started at boot */
#ifndef EV3LX_KERNEL_HRP3
#define TA_PHS       0x04U  /* cyclic: keep phase (HRP2; HRP3 has no TA_PHS) */
#endif
#define TA_ENAINT    0x01U  /* interrupt: enabled at boot */
#define TA_EDGE      0x02U  /* interrupt: edge triggered */

/* ---- Modes ---- */
#define TWF_ORW      0x01U
#define TWF_ANDW     0x02U
/* memory access modes (prb_mem, ATT_MEM), HRP2's values: write 0x01, read 0x02 */
#define TPM_WRITE    0x01U
#define TPM_READ     0x02U
#define TPM_EXEC     0x04U

/* ---- Task states (ref_tsk) ---- */
#define TTS_RUN      0x01U
#define TTS_RDY      0x02U
#define TTS_WAI      0x04U
#define TTS_SUS      0x08U
#define TTS_WAS      0x0cU
#define TTS_DMT      0x10U

/* ---- Reference packets ---- */
typedef struct t_rdtq {    /* ref_dtq */
	ID     stskid;         /* first task waiting to send, TSK_NONE if none */
	ID     rtskid;         /* first task waiting to receive, TSK_NONE if none */
	uint_t sdtqcnt;        /* data elements in the queue */
} T_RDTQ;

typedef struct t_rpdq {    /* ref_pdq */
	ID     stskid;
	ID     rtskid;
	uint_t spdqcnt;
} T_RPDQ;

typedef struct t_rmtx {    /* ref_mtx */
	ID     htskid;         /* the task holding the mutex, TSK_NONE if unlocked */
	ID     wtskid;         /* first task waiting for it, TSK_NONE if none */
} T_RMTX;

typedef struct t_rsem {    /* ref_sem */
	ID     wtskid;         /* first task waiting, TSK_NONE if none */
	uint_t semcnt;         /* resources available */
} T_RSEM;

typedef struct t_rflg {    /* ref_flg */
	ID     wtskid;         /* first task waiting, TSK_NONE if none */
	FLGPTN flgptn;         /* the current pattern */
} T_RFLG;

typedef struct t_rcyc {    /* ref_cyc */
	STAT   cycstat;        /* TCYC_STA or TCYC_STP */
	RELTIM lefttim;        /* time to the next activation (ms; HRP3: us) */
} T_RCYC;

typedef struct t_ralm {    /* ref_alm */
	STAT   almstat;        /* TALM_STA or TALM_STP */
	RELTIM lefttim;        /* time until the handler runs (ms; HRP3: us) */
} T_RALM;

/* ---- Object states (ref_cyc, ref_alm) ---- */
#define TCYC_STP     0x01U
#define TCYC_STA     0x02U
#define TALM_STP     0x01U
#define TALM_STA     0x02U

/*
 * A service call whose HRP3 form differs from HRP2's (time in us, or callable
 * from non-task context too) is bound, in the HRP3 profile, to the host
 * kernel's HRP3 entry point ev3lx_hrp3_NAME (rtos_stub/src/host/hrp3.c);
 * in the HRP2 profile the declaration is HRP2's.
 */
#ifdef EV3LX_KERNEL_HRP3
#define EV3LX_HRP3_SVC(name) __asm__("ev3lx_hrp3_" #name)
#else
#define EV3LX_HRP3_SVC(name)
#endif

/* ---- Task management ---- */
ER      act_tsk(ID tskid) EV3LX_HRP3_SVC(act_tsk); /* activate (queue one activation if not dormant) */
ER      iact_tsk(ID tskid);                /* act_tsk from non-task context */
ER_UINT can_act(ID tskid);                 /* cancel queued activations, return their count */
ER      ext_tsk(void);                     /* end the calling task; returns only on error (E_CTX: not a task) */
ER      chg_pri(ID tskid, PRI tskpri);     /* change base priority */
ER      get_pri(ID tskid, PRI *p_tskpri);  /* read current priority */
ER      get_tid(ID *p_tskid) EV3LX_HRP3_SVC(get_tid); /* ID of the running task */
ER      iget_tid(ID *p_tskid);             /* ID of the task interrupted (TSK_NONE if idle) */

/* ---- Task-dependent synchronisation ---- */
ER      slp_tsk(void);                     /* sleep until woken */
ER      tslp_tsk(TMO tmout) EV3LX_HRP3_SVC(tslp_tsk); /* sleep with timeout (E_TMOUT) */
ER      wup_tsk(ID tskid) EV3LX_HRP3_SVC(wup_tsk); /* wake, or queue one wakeup */
ER      iwup_tsk(ID tskid);
ER_UINT can_wup(ID tskid);
ER      rel_wai(ID tskid) EV3LX_HRP3_SVC(rel_wai); /* force a waiting task out with E_RLWAI */
ER      irel_wai(ID tskid);
ER      dly_tsk(RELTIM dlytim) EV3LX_HRP3_SVC(dly_tsk); /* delay for at least dlytim ms (HRP3: us) */
ER      sus_tsk(ID tskid);                 /* suspend (a waiting task becomes waiting-suspended) */
ER      rsm_tsk(ID tskid);                 /* resume a suspended task */
ER      ter_tsk(ID tskid);                 /* terminate another task (releases its mutexes) */

/* ---- Semaphores ---- */
ER      sig_sem(ID semid) EV3LX_HRP3_SVC(sig_sem); /* release one resource (E_QOVR at maximum) */
ER      isig_sem(ID semid);
ER      wai_sem(ID semid);                 /* acquire, waiting */
ER      pol_sem(ID semid);                 /* acquire, E_TMOUT if none */
ER      twai_sem(ID semid, TMO tmout) EV3LX_HRP3_SVC(twai_sem); /* acquire with timeout */

/* ---- Eventflags ---- */
ER      set_flg(ID flgid, FLGPTN setptn) EV3LX_HRP3_SVC(set_flg);
ER      iset_flg(ID flgid, FLGPTN setptn);
ER      clr_flg(ID flgid, FLGPTN clrptn);  /* AND the pattern with clrptn */
ER      wai_flg(ID flgid, FLGPTN waiptn, MODE wfmode, FLGPTN *p_flgptn);
ER      pol_flg(ID flgid, FLGPTN waiptn, MODE wfmode, FLGPTN *p_flgptn);
ER      twai_flg(ID flgid, FLGPTN waiptn, MODE wfmode, FLGPTN *p_flgptn, TMO tmout) EV3LX_HRP3_SVC(twai_flg);

/* ---- Data queues (intptr_t elements, FIFO) ---- */
ER      snd_dtq(ID dtqid, intptr_t data);  /* send, waiting while full */
ER      psnd_dtq(ID dtqid, intptr_t data) EV3LX_HRP3_SVC(psnd_dtq); /* send, E_TMOUT if full */
ER      ipsnd_dtq(ID dtqid, intptr_t data);
ER      tsnd_dtq(ID dtqid, intptr_t data, TMO tmout) EV3LX_HRP3_SVC(tsnd_dtq);
ER      fsnd_dtq(ID dtqid, intptr_t data) EV3LX_HRP3_SVC(fsnd_dtq); /* send, dropping the oldest element if full */
ER      ifsnd_dtq(ID dtqid, intptr_t data);
ER      rcv_dtq(ID dtqid, intptr_t *p_data);   /* receive, waiting while empty */
ER      prcv_dtq(ID dtqid, intptr_t *p_data);  /* receive, E_TMOUT if empty */
ER      trcv_dtq(ID dtqid, intptr_t *p_data, TMO tmout) EV3LX_HRP3_SVC(trcv_dtq);
ER      ini_dtq(ID dtqid);                 /* empty it; waiting tasks get E_DLT */
ER      ref_dtq(ID dtqid, T_RDTQ *pk_rdtq);

/* ---- Priority data queues (ordered by data priority, FIFO within one) ---- */
ER      snd_pdq(ID pdqid, intptr_t data, PRI datapri);
ER      psnd_pdq(ID pdqid, intptr_t data, PRI datapri) EV3LX_HRP3_SVC(psnd_pdq);
ER      ipsnd_pdq(ID pdqid, intptr_t data, PRI datapri);
ER      tsnd_pdq(ID pdqid, intptr_t data, PRI datapri, TMO tmout) EV3LX_HRP3_SVC(tsnd_pdq);
ER      rcv_pdq(ID pdqid, intptr_t *p_data, PRI *p_datapri);
ER      prcv_pdq(ID pdqid, intptr_t *p_data, PRI *p_datapri);
ER      trcv_pdq(ID pdqid, intptr_t *p_data, PRI *p_datapri, TMO tmout) EV3LX_HRP3_SVC(trcv_pdq);
ER      ini_pdq(ID pdqid);
ER      ref_pdq(ID pdqid, T_RPDQ *pk_rpdq);

/* ---- Mutexes (TA_CEILING: priority ceiling; TA_INHERIT: priority inheritance) ---- */
ER      loc_mtx(ID mtxid);                 /* lock, waiting while another task holds it */
ER      ploc_mtx(ID mtxid);                /* lock, E_TMOUT if held */
ER      tloc_mtx(ID mtxid, TMO tmout) EV3LX_HRP3_SVC(tloc_mtx);
ER      unl_mtx(ID mtxid);                 /* unlock; mutexes unlock in reverse order of locking */
ER      ini_mtx(ID mtxid);                 /* unlock; waiting tasks get E_DLT */
ER      ref_mtx(ID mtxid, T_RMTX *pk_rmtx);

/* ---- Initialisation and reference (HRP2 and HRP3) ---- */
ER      ini_sem(ID semid);                 /* back to isemcnt; waiting tasks get E_DLT */
ER      ref_sem(ID semid, T_RSEM *pk_rsem);
ER      ini_flg(ID flgid);                 /* back to iflgptn; waiting tasks get E_DLT */
ER      ref_flg(ID flgid, T_RFLG *pk_rflg);
ER      ref_cyc(ID cycid, T_RCYC *pk_rcyc) EV3LX_HRP3_SVC(ref_cyc);
ER      ref_alm(ID almid, T_RALM *pk_ralm) EV3LX_HRP3_SVC(ref_alm);
ER      get_inf(intptr_t *p_exinf);        /* the calling task's exinf */

/* ---- Time management ---- */
ER      get_tim(SYSTIM *p_systim) EV3LX_HRP3_SVC(get_tim); /* system time in ms since boot (HRP3: us, 64 bits) */
ER      get_utm(SYSUTM *p_sysutm);         /* performance time in us since boot */
ER      sta_cyc(ID cycid);                 /* start a cyclic handler */
ER      stp_cyc(ID cycid);
ER      sta_alm(ID almid, RELTIM almtim) EV3LX_HRP3_SVC(sta_alm); /* start an alarm, almtim ms (HRP3: us) from now */
ER      ista_alm(ID almid, RELTIM almtim);
ER      stp_alm(ID almid) EV3LX_HRP3_SVC(stp_alm);
ER      istp_alm(ID almid);

/* ---- System state ---- */
ER      rot_rdq(PRI tskpri) EV3LX_HRP3_SVC(rot_rdq); /* rotate the ready queue of a priority */
ER      irot_rdq(PRI tskpri);
ER      loc_cpu(void) EV3LX_HRP3_SVC(loc_cpu); /* CPU lock: mask all interrupts and dispatch */
ER      iloc_cpu(void);
ER      unl_cpu(void) EV3LX_HRP3_SVC(unl_cpu);
ER      iunl_cpu(void);
ER      dis_dsp(void);                     /* disable dispatching */
ER      ena_dsp(void);
bool_t  sns_ctx(void);                     /* TRUE in non-task context */
bool_t  sns_loc(void);                     /* TRUE with the CPU locked */
bool_t  sns_dsp(void);                     /* TRUE with dispatching disabled */
bool_t  sns_dpn(void);                     /* TRUE when dispatching is pending/not possible */
ER      ext_ker(void);                     /* end the kernel: ATT_TER routines, then stop */

/* ---- Interrupts ---- */
ER      dis_int(INTNO intno);              /* mask one interrupt line */
ER      ena_int(INTNO intno);              /* unmask one interrupt line */

/* ---- Extended service calls and memory protection (HRP2) ---- */
ER_UINT cal_svc(FN fncd, intptr_t par1, intptr_t par2, intptr_t par3,
		intptr_t par4, intptr_t par5);
/* E_OK if the task's protection domain may access [base, base+size) with pmmode, else E_MACV. */
ER      prb_mem(const void *base, SIZE size, ID tskid, MODE pmmode);

#ifdef __cplusplus
}
#endif

#ifdef EV3LX_KERNEL_HRP3
/* HRP3's own names: notification, the high-resolution timer, the i-names. */
#include "kernel_hrp3.h"
#endif

/* The target's part of the interface (the EV3), as HRP2's kernel.h includes it. */
#include "target_kernel.h"

#endif /* TOPPERS_KERNEL_H */
