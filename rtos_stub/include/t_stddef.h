/*
 * t_stddef.h — TOPPERS standard definitions: basic types, error codes,
 * timeout constants.  Names and numeric values follow the TOPPERS/HRP2
 * specification so that code built against this header links against the
 * real kernel unchanged.
 */
#ifndef TOPPERS_T_STDDEF_H
#define TOPPERS_T_STDDEF_H

#include <stddef.h>

#if __STDC_HOSTED__ && !defined(__KERNEL__)
#include <stdint.h>
#else
/*
 * Without a C library — a freestanding build, or Linux code, which is
 * compiled -nostdinc as kbuild compiles it and may reach this header only
 * after its driver (the service calls a hack defines) — the fixed-width types
 * come from the compiler's predefined ones, as TOPPERS's t_stddef.h defines
 * them where <stdint.h> is missing.  They are the C library's own types on
 * every build, so the definitions agree where both are seen.
 */
typedef __INT8_TYPE__		int8_t;
typedef __INT16_TYPE__		int16_t;
typedef __INT32_TYPE__		int32_t;
typedef __INT64_TYPE__		int64_t;
typedef __UINT8_TYPE__		uint8_t;
typedef __UINT16_TYPE__		uint16_t;
typedef __UINT32_TYPE__		uint32_t;
typedef __UINT64_TYPE__		uint64_t;
typedef __INTPTR_TYPE__		intptr_t;
typedef __UINTPTR_TYPE__	uintptr_t;
#endif

typedef int             bool_t;
typedef signed int      int_t;
typedef unsigned int    uint_t;
typedef signed long     long_t;
typedef unsigned long   ulong_t;

typedef int_t           FN;      /* function code */
typedef int_t           ER;      /* error code */
typedef int_t           ID;      /* object ID */
typedef uint_t          ATR;     /* object attribute */
typedef uint_t          STAT;    /* object state */
typedef uint_t          MODE;    /* service call mode */
typedef int_t           PRI;     /* priority */
typedef size_t          SIZE;    /* memory area size */
#ifdef EV3LX_KERNEL_HRP3
/* The HRP3 profile (an app written for TOPPERS/HRP3, EV3RT 1.x: the build
 * defines EV3LX_KERNEL_HRP3, docs/ev3rt-apps.md): time in microseconds, with
 * HRP3's types (public source: ev3rt-git/ev3rt-hrp3, include/t_stddef.h). */
typedef uint32_t        TMO;     /* timeout, in us */
typedef uint32_t        RELTIM;  /* relative time, in us */
typedef uint64_t        SYSTIM;  /* system time, in us */
typedef uint32_t        PRCTIM;  /* processor time, in us */
typedef uint32_t        HRTCNT;  /* high-resolution timer count, in us */
#else
typedef int_t           TMO;     /* timeout, in ms */
typedef uint_t          RELTIM;  /* relative time, in ms */
typedef ulong_t         SYSTIM;  /* system time, in ms */
#endif
typedef uint32_t        SYSUTM;  /* performance time, in us */
typedef uintptr_t       FP;      /* program start address */
typedef int_t           ER_BOOL; /* error code or boolean */
typedef int_t           ER_ID;   /* error code or ID */
typedef int_t           ER_UINT; /* error code or unsigned value */
typedef uint32_t        ACPTN;   /* access permission pattern */

#ifndef __KERNEL__
/* IEEE 754 single and double precision, as TOPPERS's GCC tool header gives
 * them (public source: ev3rt-git/ev3rt-hrp2 and ev3rt-hrp3,
 * arch/gcc/tool_stddef.h, TOPPERS_STDFLOAT_TYPE1); apps use them. */
typedef float           float32_t;
typedef double          double64_t;
#define FLOAT32_MIN     1.17549435e-38F
#define FLOAT32_MAX     3.40282347e+38F
#define DOUBLE64_MIN    2.2250738585072014e-308
#define DOUBLE64_MAX    1.7976931348623157e+308
#endif

typedef struct acvct {
	ACPTN acptn1;   /* normal operations */
	ACPTN acptn2;   /* management operations */
	ACPTN acptn3;   /* reference operations */
	ACPTN acptn4;   /* other operations */
} ACVCT;

#ifndef TRUE
#define TRUE    1
#endif
#ifndef FALSE
#define FALSE   0
#endif

#define E_OK     0

#define E_SYS    (-5)
#define E_NOSPT  (-9)
#define E_RSFN   (-10)
#define E_RSATR  (-11)
#define E_PAR    (-17)
#define E_ID     (-18)
#define E_CTX    (-25)
#define E_MACV   (-26)
#define E_OACV   (-27)
#define E_ILUSE  (-28)
#define E_NOMEM  (-33)
#define E_NOID   (-34)
#define E_NORES  (-35)
#define E_OBJ    (-41)
#define E_NOEXS  (-42)
#define E_QOVR   (-43)
#define E_RLWAI  (-49)
#define E_TMOUT  (-50)
#define E_DLT    (-51)
#define E_CLS    (-52)
#define E_WBLK   (-57)
#define E_BOVR   (-58)
#ifdef EV3LX_KERNEL_HRP3
#define E_RASTER (-53)  /* HRP3: the task's termination was requested */
#define E_COMM   (-65)  /* HRP3: communication error */
#endif

/* The main error code is the low byte, sign-extended; the sub code the rest. */
#define MERCD(ercd)        ((ER)((int8_t)(ercd)))
#define SERCD(ercd)        ((ER)((ercd) >> 8))
#define ERCD(mercd, sercd) ((ER)((((uint_t)(sercd)) << 8) | (((uint_t)(mercd)) & 0xffU)))

#define TA_NULL  0U

#ifdef EV3LX_KERNEL_HRP3
#define TMO_POL  0U
#define TMO_FEVR 0xffffffffU   /* HRP3: UINT32_MAX */
#define TMO_NBLK 0xfffffffeU   /* HRP3: UINT32_MAX - 1 */
/* HRP3's largest relative time: 4 000 000 000 us (66 min 40 s). */
#define TMAX_RELTIM 4000000000U
#else
#define TMO_POL  0
#define TMO_FEVR (-1)
#define TMO_NBLK (-2)
#endif

/* Access permission patterns of memory objects (ATA_SEC, ATA_MEM): one bit per
 * user domain; TACP_KERNEL the kernel domain only, TACP_SHARED every domain
 * (ev3rt-git/ev3rt-hrp2, include/t_stddef.h). */
#define TACP_KERNEL (0U)
#define TACP_SHARED (~0U)
#define TACP(domid) (1U << ((domid) - 1))

/* Integer constants of a TOPPERS type, as apps write them (ULONG_C(1000)). */
#ifndef INT_C
#define INT_C(val)   (val)
#endif
#ifndef UINT_C
#define UINT_C(val)  (val ## U)
#endif
#ifndef ULONG_C
#define ULONG_C(val) (val ## UL)
#endif

/* TOPPERS's inline functions (the GCC tool's tool_stddef.h: static inline). */
#ifndef Inline
#define Inline static __inline__
#endif

/* TOPPERS's headers declare their C functions `throw()` for C++ callers;
 * in C the specification is empty. */
#if !defined(__cplusplus) && !defined(__KERNEL__) && !defined(throw)
#define throw()
#endif

/*
 * assert as TOPPERS's t_stddef.h defines it: a failed assertion is logged
 * at LOG_EMERG with its expression, file and line (TOPPERS_assert_fail, a
 * macro of t_syslog.h, which every user of assert includes through kernel.h),
 * then TOPPERS_assert_abort runs, which on EV3RT's AM1808 target does
 * nothing, so the program goes on (public source: ev3rt-git/ev3rt-hrp2,
 * include/t_stddef.h, include/t_syslog.h, arch/arm_gcc/am1808/chip_stddef.h).
 * Without NDEBUG only; Linux code never sees it (kbuild has no assert).
 */
#ifndef __KERNEL__
/* What follows a failed assertion on the target: nothing on EV3RT's AM1808. */
static inline void TOPPERS_assert_abort(void)
{
}

#undef assert
#ifndef NDEBUG
#define assert(exp) ((void)((exp) ? 0 : (TOPPERS_assert_fail(#exp, __FILE__, __LINE__), \
	TOPPERS_assert_abort(), 0)))
#else
#define assert(exp) ((void)0)
#endif
#endif /* !__KERNEL__ */

#endif /* TOPPERS_T_STDDEF_H */
