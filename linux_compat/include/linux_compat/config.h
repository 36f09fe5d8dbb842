/*
 * linux_compat/config.h — linux_compat's RTOS configuration.
 *
 * An application INCLUDEs linux_compat_cfg in its rtos_cfg (.includes).  It
 * brings:
 *   - the kernel worker task LX_WORKER_TSKID (TNUM_TSKID, the top of the
 *     task range) at priority LX_WORKER_PRIORITY: it runs every module_init
 *     at boot (linux/module.h), then serves the workqueues;
 *   - the ISR lx_tick_isr on the tick line INTNO_TICK (hrtimers, jiffies,
 *     timer_list, deferred wakeups);
 *   - the ATT_INI lx_compat_boot, which resets linux_compat's state: no
 *     module is loaded, so every boot runs every module_init again;
 *   - the ATT_TER lx_compat_terminate: at shutdown the worker runs every
 *     module_exit, newest module first, in task context (they may sleep),
 *     before the kernel stops (linux_compat/shutdown.h: on the host the
 *     routine runs the system until the worker is done; on HRP2, where
 *     ext_ker has stopped dispatching, a task calls lx_compat_unload first);
 *   - linux_irq_cfg: the Linux interrupt lines (CFG_INT + ATT_ISR rows, see
 *     linux_compat/irq.h) - do not include it a second time.
 *   - LX_NR_POOL_WORKERS pool workers (below), which serve the workqueues
 *     with it, so a work item that sleeps does not hold up the others;
 *   - LX_NR_IRQ_THREADS IRQ threads (below) for threaded interrupt handlers;
 * Reserved IDs: task TNUM_TSKID, the pool workers' and the IRQ threads' IDs.  No semaphores, eventflags, cyclics or
 * alarms are used (linux_compat's primitives are native).
 *
 * LX_WORKER_PRIORITY and LX_WORKER_STACK may be overridden at build time
 * (-D); the priority can also be changed at run time with chg_pri.
 */
#ifndef _LINUX_COMPAT_CONFIG_H
#define _LINUX_COMPAT_CONFIG_H

#include <rtos_cfg.h>

#define LX_WORKER_TSKID		TNUM_TSKID

/*
 * The pool workers: LX_NR_POOL_WORKERS more worker tasks at
 * LX_WORKER_PRIORITY with IDs LX_POOL_WORKER_TSKID_BASE.. (default just
 * below the IDs the platform layers take under TNUM_TSKID).  They run work
 * while the other workers sleep inside theirs; with all of them asleep in
 * work items, further work waits.
 */
#ifndef LX_NR_POOL_WORKERS
#define LX_NR_POOL_WORKERS	2
#endif
#ifndef LX_POOL_WORKER_TSKID_BASE
#define LX_POOL_WORKER_TSKID_BASE	(TNUM_TSKID - 8)
#endif
#define LX_NR_WORKERS		(1 + LX_NR_POOL_WORKERS)
#if LX_NR_POOL_WORKERS < 0 || LX_POOL_WORKER_TSKID_BASE < 1 || \
    LX_POOL_WORKER_TSKID_BASE + LX_NR_POOL_WORKERS > TNUM_TSKID
#error "the pool workers' task IDs must lie in 1..TNUM_TSKID-1"
#endif

/*
 * The IRQ threads: LX_NR_IRQ_THREADS tasks with IDs LX_IRQ_THREAD_TSKID_BASE..
 * (default just below the pool workers' range) at LX_IRQ_THREAD_PRIORITY,
 * above the workers as Linux runs IRQ threads SCHED_FIFO.  Each
 * request_threaded_irq with a thread function takes one until its free_irq.
 */
#ifndef LX_NR_IRQ_THREADS
#define LX_NR_IRQ_THREADS	2
#endif
#ifndef LX_IRQ_THREAD_TSKID_BASE
#define LX_IRQ_THREAD_TSKID_BASE	(LX_POOL_WORKER_TSKID_BASE - LX_NR_IRQ_THREADS)
#endif
#if LX_NR_IRQ_THREADS < 0 || LX_NR_IRQ_THREADS > 4 || LX_IRQ_THREAD_TSKID_BASE < 1 || \
    LX_IRQ_THREAD_TSKID_BASE + LX_NR_IRQ_THREADS > LX_POOL_WORKER_TSKID_BASE
#error "the IRQ threads (at most 4) need task IDs in 1..LX_POOL_WORKER_TSKID_BASE-1"
#endif
#ifndef LX_IRQ_THREAD_PRIORITY
#define LX_IRQ_THREAD_PRIORITY	3
#endif
#ifndef LX_IRQ_THREAD_STACK
#define LX_IRQ_THREAD_STACK	(16 * 1024)
#endif

#ifndef LX_WORKER_PRIORITY
#define LX_WORKER_PRIORITY	4
#endif

#ifndef LX_WORKER_STACK
#define LX_WORKER_STACK		(32 * 1024)
#endif

/* linux_compat's configuration fragment (includes linux_irq_cfg). */
extern const struct rtos_cfg linux_compat_cfg;
/* The Linux interrupt lines (linux_compat/mach-davinci/irq_cfg.c). */
extern const struct rtos_cfg linux_irq_cfg;

/* ATT_INI of linux_compat_cfg: clears all linux_compat state (a fresh boot). */
void lx_compat_boot(intptr_t exinf);
/* ATT_TER of linux_compat_cfg: the worker unloads every module before the kernel stops. */
void lx_compat_terminate(intptr_t exinf);
/* The worker task's body: module inits, then the workqueues (and the unload at shutdown). */
void lx_worker_task(intptr_t exinf);
/* A pool worker's body: the workqueues. */
void lx_pool_worker_task(intptr_t exinf);
/* IRQ thread exinf's body: runs its threaded handler each time it is woken. */
void lx_irq_thread_task(intptr_t exinf);

/* The boot command line, passed before the kernel starts as a boot loader
 * passes Linux's (the string must stay valid): its "module.param=value" words
 * set module parameters before the modules' init (e.g.
 * "d_uart.port3_base=0x01d0c000").  AM1808: the firmware's start-up calls it;
 * host: the simulated board sets it (this is rtos_host_set_boot_args). */
void lx_compat_set_boot_args(const char *args);

#endif /* _LINUX_COMPAT_CONFIG_H */
