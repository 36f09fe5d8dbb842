/*
 * rtos_cfg.h — the static configuration, as TOPPERS .cfg files declare it.
 *
 * Each table row is one static API of the TOPPERS configurator:
 * CRE_TSK, CRE_SEM, CRE_FLG, CRE_DTQ, CRE_PDQ, CRE_MTX, CRE_CYC, CRE_ALM, CFG_INT, ATT_ISR, ATT_INI,
 * ATT_TER, DEF_SVC, and HRP2's memory regions per protection domain.  On the host the
 * tables are checked at rtos_boot (a bad row is a clear boot error naming the
 * row); on the AM1808 the same objects are written into the HRP2 .cfg
 * (docs/porting-to-hrp2.md).
 *
 * IDs are explicit, as the configurator's kernel_cfg.h makes them: every
 * object kind has IDs 1..TNUM_xxx, each used at most once across all the
 * included configurations.  By convention applications use IDs from 1 and
 * libraries (linux_compat) take theirs from the top of the range.
 */
#ifndef RTOS_CFG_H
#define RTOS_CFG_H

#ifdef __cplusplus
extern "C" {
#endif

/* The kernel's own header, wherever the build finds it (angle brackets: not
 * this directory's first), so that against a real HRP2 tree its kernel.h is
 * the one, and nothing here redefines a name the kernel supplies. */
#include <kernel.h>

/* Against a real kernel (EV3LX_HRP2_KERNEL: make am1808 HRP2_DIR=...) the
 * object counts are its configurator's: the firmware's kernel_cfg.h
 * (EV3LX_CFG_DIR) defines TNUM_TSKID and the others.  Not while a
 * configurator reads a configuration (TOPPERS_CFG1_OUT): it writes that file. */
#if defined(EV3LX_HRP2_KERNEL) && !defined(TOPPERS_CFG1_OUT)
#include <kernel_cfg.h>
#endif

/* The object counts: the configurator's (kernel_cfg.h) when a firmware's
 * configuration came first, the host kernel's table sizes otherwise. */
#ifndef TNUM_TSKID
#define TNUM_TSKID   32
#endif
#ifndef TNUM_SEMID
#define TNUM_SEMID   32
#endif
#ifndef TNUM_FLGID
#define TNUM_FLGID   16
#endif
#ifndef TNUM_CYCID
#define TNUM_CYCID   16
#endif
#ifndef TNUM_ALMID
#define TNUM_ALMID   16
#endif
#ifndef TNUM_DTQID
#define TNUM_DTQID   16
#endif
#ifndef TNUM_PDQID
#define TNUM_PDQID   16
#endif
#ifndef TNUM_MTXID
#define TNUM_MTXID   16
#endif
/* Extended service calls: function codes 1..TNUM_FNCD.  A build setting
 * (make TNUM_FNCD=n passes -DTNUM_FNCD=n to every unit, library and
 * configurations alike), as the TOPPERS configurator sets it for HRP2. */
#ifndef TNUM_FNCD
#define TNUM_FNCD    256
#endif
#ifndef TNUM_DOMID
#define TNUM_DOMID   4      /* user protection domains 1..TNUM_DOMID */
#endif
/* Interrupt numbers 0..TMAX_INTNO.  The AM1808's AINTC has 0..100, HRP2's
 * value (arch/arm_gcc/am1808/am1808.h), which wins against a real kernel;
 * the host model keeps 101..127 as spare lines for tests. */
#ifndef TMAX_INTNO
#define TMAX_INTNO   127U
#endif

/* The host tick is an interrupt line too, as on the AM1808 (TIMER64P0 TINT12).
 * Its priority is a build setting (make INTPRI_TICK=n), EV3RT's by default:
 * INTPRI_TIMER, TMIN_INTPRI + 3 = -28 (ev3rt-git/ev3rt-hrp2, target/ev3_gcc/ev3.h);
 * every Linux line takes it too (LX_IRQ_PRIORITY), so Linux handlers and the
 * tick's hrtimer callbacks never nest. */
#define INTNO_TICK   21U
#ifndef INTPRI_TICK
#define INTPRI_TICK  (-28)
#endif

/* The sections of the library's memory that user domains may access
 * (ATA_SEC in cfg/ev3lx.cfg): the drivers' shared areas (lx_heap_area, read),
 * and the API's LCD frame and app heap (read and write).  Only where the
 * memory configuration places them (EV3LX_MEM_SECTIONS: the AM1808's); on the
 * host the tables of rtos_cfg.h grant the same access. */
#if defined(EV3LX_MEM_SECTIONS) && EV3LX_MEM_SECTIONS
#define EV3LX_SHARED_RO	__attribute__((section("ev3lx_shared_ro")))
#define EV3LX_SHARED_RW	__attribute__((section("ev3lx_shared_rw")))
#else
#define EV3LX_SHARED_RO
#define EV3LX_SHARED_RW
#endif

struct rtos_task_cfg {      /* CRE_TSK */
	ID       tskid;
	ATR      tskatr;         /* TA_ACT or TA_NULL */
	intptr_t exinf;
	TASK     task;
	PRI      itskpri;
	SIZE     stksz;
	ID       domid;          /* TDOM_KERNEL or a user domain 1..TNUM_DOMID */
	const char *name;
};

struct rtos_sem_cfg {       /* CRE_SEM */
	ID     semid;
	ATR    sematr;           /* TA_TPRI or TA_NULL (FIFO) */
	uint_t isemcnt;
	uint_t maxsem;
	const char *name;
};

struct rtos_flg_cfg {       /* CRE_FLG */
	ID     flgid;
	ATR    flgatr;           /* TA_TPRI | TA_WMUL | TA_CLR */
	FLGPTN iflgptn;
	const char *name;
};

struct rtos_dtq_cfg {       /* CRE_DTQ: the buffer is allocated by the kernel (dtqmb NULL) */
	ID     dtqid;
	ATR    dtqatr;           /* TA_TPRI (senders' queue in priority order) or TA_NULL */
	uint_t dtqcnt;           /* capacity in data elements; 0: sender and receiver meet */
	const char *name;
};

struct rtos_pdq_cfg {       /* CRE_PDQ */
	ID     pdqid;
	ATR    pdqatr;           /* TA_TPRI or TA_NULL */
	uint_t pdqcnt;           /* capacity; 0: sender and receiver meet */
	PRI    maxdpri;          /* data priorities 1..maxdpri (<= TMAX_DPRI) */
	const char *name;
};

struct rtos_mtx_cfg {       /* CRE_MTX */
	ID     mtxid;
	ATR    mtxatr;           /* TA_NULL, TA_TPRI, TA_CEILING or TA_INHERIT */
	PRI    ceilpri;          /* TA_CEILING only: TMIN_TPRI..TMAX_TPRI */
	const char *name;
};

struct rtos_cyc_cfg {       /* CRE_CYC: period and phase in ms (HRP2), in us (the HRP3 profile) */
	ID       cycid;
	ATR      cycatr;         /* TA_STA | TA_PHS (HRP2); TA_STA (HRP3) */
	intptr_t exinf;
	CYCHDR   cychdr;
	RELTIM   cyctim;
	RELTIM   cycphs;
	const char *name;
};

struct rtos_alm_cfg {       /* CRE_ALM */
	ID       almid;
	ATR      almatr;
	intptr_t exinf;
	ALMHDR   almhdr;
	const char *name;
};

struct rtos_int_cfg {       /* CFG_INT */
	INTNO intno;
	ATR   intatr;            /* TA_ENAINT | TA_EDGE */
	PRI   intpri;            /* TMIN_INTPRI..TMAX_INTPRI */
};

struct rtos_isr_cfg {       /* ATT_ISR: several ISRs may share a line, called in isrpri order */
	ATR      isratr;
	intptr_t exinf;
	INTNO    intno;
	ISR      isr;
	PRI      isrpri;         /* order among the line's ISRs, 1 first */
};

struct rtos_ini_cfg {       /* ATT_INI: runs at boot in non-task context, in table order */
	INIRTN   inirtn;
	intptr_t exinf;
};

struct rtos_ter_cfg {       /* ATT_TER: runs at kernel termination, in reverse order of registration */
	TERRTN   terrtn;
	intptr_t exinf;
};

struct rtos_svc_cfg {       /* DEF_SVC */
	FN     fncd;             /* 1..TNUM_FNCD */
	EXTSVC extsvc;
	SIZE   stksz;
};

struct rtos_mem_cfg {       /* a memory region a user domain may access */
	ID         domid;        /* 1..TNUM_DOMID */
	const void *base;
	SIZE       size;
	MODE       access;       /* TPM_READ | TPM_WRITE | TPM_EXEC */
	const char *name;
};

#define RTOS_TABLE(arr) (arr), (uint_t)(sizeof(arr) / sizeof((arr)[0]))

struct rtos_cfg {
	const char *name;
	const struct rtos_task_cfg *tasks;   uint_t ntasks;
	const struct rtos_sem_cfg  *sems;    uint_t nsems;
	const struct rtos_flg_cfg  *flgs;    uint_t nflgs;
	const struct rtos_cyc_cfg  *cycs;    uint_t ncycs;
	const struct rtos_alm_cfg  *alms;    uint_t nalms;
	const struct rtos_int_cfg  *ints;    uint_t nints;
	const struct rtos_isr_cfg  *isrs;    uint_t nisrs;
	const struct rtos_ini_cfg  *inis;    uint_t ninis;
	const struct rtos_ter_cfg  *ters;    uint_t nters;
	const struct rtos_svc_cfg  *svcs;    uint_t nsvcs;
	const struct rtos_mem_cfg  *mems;    uint_t nmems;
	const struct rtos_dtq_cfg  *dtqs;    uint_t ndtqs;
	const struct rtos_pdq_cfg  *pdqs;    uint_t npdqs;
	const struct rtos_mtx_cfg  *mtxs;    uint_t nmtxs;
	/* The function codes this configuration owns: svc_first..svc_first+svc_count-1
	 * (svc_count 0: none declared).  Boot rejects ranges that overlap another
	 * configuration's, naming both, and DEF_SVC rows outside the range. */
	FN     svc_first;
	uint_t svc_count;
	/* INCLUDE(): other configurations merged in, e.g. linux_compat's. NULL-terminated. */
	const struct rtos_cfg *const *includes;
	/* The kernel profile the configuration is written for: its CRE_CYC times are
	 * ms (RTOS_PROFILE_HRP2, the default) or us (RTOS_PROFILE_HRP3). */
	uint_t profile;
};

#define RTOS_PROFILE_HRP2 0U
#define RTOS_PROFILE_HRP3 1U

#ifdef __cplusplus
}
#endif

#endif /* RTOS_CFG_H */
