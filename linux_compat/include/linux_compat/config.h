/*
 * linux_compat/config.h — linux_compat's RTOS configuration.
 *
 * An application INCLUDEs linux_compat_cfg in its rtos_cfg (.includes).  It
 * brings:
 *   - the kernel worker task LX_WORKER_TSKID at priority LX_WORKER_PRIORITY: it runs every module_init
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
 * The tasks' IDs are the configurator's (cfg/ev3lx.cfg, kernel_cfg.h).  No
 * semaphores, eventflags, cyclics or alarms are used (linux_compat's
 * primitives are native).
 *
 * LX_WORKER_PRIORITY and LX_WORKER_STACK may be overridden at build time
 * (-D); the priority can also be changed at run time with chg_pri.
 */
#ifndef _LINUX_COMPAT_CONFIG_H
#define _LINUX_COMPAT_CONFIG_H

#include <rtos_cfg.h>

/*
 * The tasks' IDs are the configurator's (kernel_cfg.h): cfg/ev3lx.cfg declares
 * the worker LX_WORKER_TSKID, the pool workers LX_POOL_WORKER1_TSKID.. and the
 * IRQ threads LX_IRQ_THREAD1_TSKID..; a firmware's configurator (HRP2's)
 * numbers them with the rest of the firmware, ev3cfg --library on the host at
 * the top of the range.  Not while a configurator reads the fragment
 * (TOPPERS_CFG1_OUT): kernel_cfg.h is what it writes.
 */
#ifndef TOPPERS_CFG1_OUT
#include <kernel_cfg.h>
#endif

/*
 * The pool workers: LX_NR_POOL_WORKERS more worker tasks at
 * LX_WORKER_PRIORITY.  They run work while the other workers sleep inside
 * theirs; with all of them asleep in work items, further work waits.
 */
#ifndef LX_NR_POOL_WORKERS
#define LX_NR_POOL_WORKERS	2
#endif
#define LX_NR_WORKERS		(1 + LX_NR_POOL_WORKERS)
#if LX_NR_POOL_WORKERS < 0 || LX_NR_POOL_WORKERS > 4
#error "cfg/ev3lx.cfg declares 0 to 4 pool workers"
#endif

/*
 * The IRQ threads: LX_NR_IRQ_THREADS tasks at LX_IRQ_THREAD_PRIORITY, above
 * the workers as Linux runs IRQ threads SCHED_FIFO.  Each
 * request_threaded_irq with a thread function takes one until its free_irq.
 */
#ifndef LX_NR_IRQ_THREADS
#define LX_NR_IRQ_THREADS	2
#endif
#if LX_NR_IRQ_THREADS < 0 || LX_NR_IRQ_THREADS > 4
#error "cfg/ev3lx.cfg declares 0 to 4 IRQ threads"
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

/* The line of the kernel's tick, where linux_compat attaches lx_tick_isr
 * beside the kernel's own timer ISR: HRP2's INTNO_TIMER (TIMER64P0 TINT12 on
 * the AM1808, arch/arm_gcc/am1808/chip_timer.h) where the kernel names it,
 * the host kernel's INTNO_TICK otherwise.  The line is the kernel's: its
 * CFG_INT is the kernel's too. */
#ifdef INTNO_TIMER
#define LX_TICK_INTNO	INTNO_TIMER
#else
#define LX_TICK_INTNO	INTNO_TICK
#endif
/* After the kernel's timer ISR on the line (HRP2 calls a line's ISRs in isrpri order). */
#define LX_TICK_ISRPRI	(TMIN_ISRPRI + 1)

/* linux_compat's configuration fragment (includes linux_irq_cfg). */
extern const struct rtos_cfg linux_compat_cfg;
/* The Linux interrupt lines (linux_compat/mach-davinci/irq_cfg.c). */
extern const struct rtos_cfg linux_irq_cfg;

/* ATT_INI of linux_compat_cfg: clears all linux_compat state (a fresh boot). */
void lx_compat_boot(intptr_t exinf);
/* ATT_TER of linux_compat_cfg: the worker unloads every module before the kernel stops. */
void lx_compat_terminate(intptr_t exinf);
/* The ISR linux_compat attaches to the RTOS tick (LX_TICK_INTNO): jiffies,
 * deferred wakeups, due hrtimers, then due timer_list timers. */
void lx_tick_isr(intptr_t exinf);
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
