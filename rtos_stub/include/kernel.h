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
#define TMIN_INTPRI  (-31)  /* highest interrupt priority: the AM1808 AINTC's channel 2
			    * (ev3rt-git/ev3rt-hrp2, arch/arm_gcc/am1808/am1808.h) */
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
 * In the HRP3 profile (EV3LX_KERNEL_HRP3, host only) a service call whose
 * HRP3 form differs from HRP2's (time in us, or callable from non-task
 * context too) reaches the host kernel's HRP3 entry point ev3lx_hrp3_NAME
 * (rtos_stub/src/host/hrp3.c) instead of _kernel_NAME (target_svc.h); an API
 * call whose EV3RT 1.x form differs is bound to its HRP3 entry by name.
 */
#ifdef EV3LX_KERNEL_HRP3
#define EV3LX_HRP3_SVC(name) __asm__("ev3lx_hrp3_" #name)
#else
#define EV3LX_HRP3_SVC(name)
#endif
/* ---- Service calls ---- */
/* Their function codes, their kernel-domain names (_kernel_*, TOPPERS_SVC_CALL)
 * and their user-domain traps with cal_svc, in HRP2's three headers. */
#include "kernel_fncode.h"
#include "svc_call.h"
#include "target_svc.h"

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
