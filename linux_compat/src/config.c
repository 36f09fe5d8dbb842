/*
 * config.c — linux_compat_cfg, linux_compat's RTOS configuration fragment
 * (linux_compat/config.h lists what it brings and which IDs it reserves).
 * The same objects, with the same IDs, are cfg/ev3lx.cfg's static APIs
 * (tests/cfg/test_ev3lx_fragment.c compares them); an HRP2 firmware's
 * configuration INCLUDEs that fragment.
 */
#include <rtos_cfg.h>
#include <linux_compat/config.h>
#include <linux_compat/clock.h>

static const struct rtos_task_cfg lx_tasks[] = {
	{ LX_WORKER_TSKID, TA_ACT, 0, lx_worker_task, LX_WORKER_PRIORITY, LX_WORKER_STACK,
	  TDOM_KERNEL, "lx_worker" },
#if LX_NR_POOL_WORKERS >= 1
	{ LX_POOL_WORKER1_TSKID, TA_ACT, 1, lx_pool_worker_task, LX_WORKER_PRIORITY, LX_WORKER_STACK,
	  TDOM_KERNEL, "lx_pool_worker1" },
#endif
#if LX_NR_POOL_WORKERS >= 2
	{ LX_POOL_WORKER2_TSKID, TA_ACT, 2, lx_pool_worker_task, LX_WORKER_PRIORITY, LX_WORKER_STACK,
	  TDOM_KERNEL, "lx_pool_worker2" },
#endif
#if LX_NR_POOL_WORKERS >= 3
	{ LX_POOL_WORKER3_TSKID, TA_ACT, 3, lx_pool_worker_task, LX_WORKER_PRIORITY, LX_WORKER_STACK,
	  TDOM_KERNEL, "lx_pool_worker3" },
#endif
#if LX_NR_POOL_WORKERS >= 4
	{ LX_POOL_WORKER4_TSKID, TA_ACT, 4, lx_pool_worker_task, LX_WORKER_PRIORITY, LX_WORKER_STACK,
	  TDOM_KERNEL, "lx_pool_worker4" },
#endif
#if LX_NR_IRQ_THREADS >= 1
	{ LX_IRQ_THREAD1_TSKID, TA_ACT, 0, lx_irq_thread_task, LX_IRQ_THREAD_PRIORITY, LX_IRQ_THREAD_STACK,
	  TDOM_KERNEL, "lx_irq_thread1" },
#endif
#if LX_NR_IRQ_THREADS >= 2
	{ LX_IRQ_THREAD2_TSKID, TA_ACT, 1, lx_irq_thread_task, LX_IRQ_THREAD_PRIORITY, LX_IRQ_THREAD_STACK,
	  TDOM_KERNEL, "lx_irq_thread2" },
#endif
#if LX_NR_IRQ_THREADS >= 3
	{ LX_IRQ_THREAD3_TSKID, TA_ACT, 2, lx_irq_thread_task, LX_IRQ_THREAD_PRIORITY, LX_IRQ_THREAD_STACK,
	  TDOM_KERNEL, "lx_irq_thread3" },
#endif
#if LX_NR_IRQ_THREADS >= 4
	{ LX_IRQ_THREAD4_TSKID, TA_ACT, 3, lx_irq_thread_task, LX_IRQ_THREAD_PRIORITY, LX_IRQ_THREAD_STACK,
	  TDOM_KERNEL, "lx_irq_thread4" },
#endif
};
#if LX_NR_POOL_WORKERS > 4
#error "config.c configures at most 4 pool workers"
#endif

static const struct rtos_isr_cfg lx_isrs[] = {
	{ TA_NULL, 0, LX_TICK_INTNO, lx_tick_isr, LX_TICK_ISRPRI },
};

static const struct rtos_ini_cfg lx_inis[] = {
	{ lx_compat_boot, 0 },
};

static const struct rtos_ter_cfg lx_ters[] = {
	{ lx_compat_terminate, 0 },
};

static const struct rtos_cfg *const lx_includes[] = {
	&linux_irq_cfg,
	NULL,
};

const struct rtos_cfg linux_compat_cfg = {
	.name = "linux_compat",
	.tasks = RTOS_TABLE(lx_tasks),
	.isrs = RTOS_TABLE(lx_isrs),
	.inis = RTOS_TABLE(lx_inis),
	.ters = RTOS_TABLE(lx_ters),
	.includes = lx_includes,
};
