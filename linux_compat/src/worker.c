/*
 * worker.c — the kernel worker tasks and the modules' life cycle: at boot the
 * main worker runs every module_init, then serves the work FIFO
 * (workqueue.c) with the pool workers; when an unload is requested
 * (linux_compat's termination, lx_compat_unload) it runs every module_exit
 * and goes on serving work.
 */
#include <linux/kernel.h>
#include <linux/module.h>
#include <linux/wait.h>
#include <linux_compat/config.h>
#include <linux_compat/sched.h>
#include <linux_compat/workqueue.h>
#include <kernel.h>

static struct {
	bool ready;                  /* module inits done */
	bool unload_requested;       /* lx_worker_request_unload was called */
	bool unloaded;               /* ...and the worker has run every module_exit */
} worker;

static DECLARE_WAIT_QUEUE_HEAD(unload_waiters);

/* Forgets the previous boot's life cycle state. */
void lx_worker_reset(void)
{
	worker.ready = false;
	worker.unload_requested = false;
	worker.unloaded = false;
	lx_init_waitqueue_head(&unload_waiters, "unload_waiters");
}

/* The workers' IDs as the configurator gave them (cfg/ev3lx.cfg): the worker, then the pool workers. */
static const ID worker_tskids[LX_NR_WORKERS] = {
	LX_WORKER_TSKID,
#if LX_NR_POOL_WORKERS >= 1
	LX_POOL_WORKER1_TSKID,
#endif
#if LX_NR_POOL_WORKERS >= 2
	LX_POOL_WORKER2_TSKID,
#endif
#if LX_NR_POOL_WORKERS >= 3
	LX_POOL_WORKER3_TSKID,
#endif
#if LX_NR_POOL_WORKERS >= 4
	LX_POOL_WORKER4_TSKID,
#endif
};

/* The task ID of worker index (0 = the main worker). */
ID lx_worker_tskid(unsigned int index)
{
	return worker_tskids[index];
}

/* The calling worker's index, or -1. */
int lx_worker_index(void)
{
	ID tid = lx_current_tskid();

	for (int i = 0; i < LX_NR_WORKERS; i++)
		if (tid == worker_tskids[i])
			return i;
	return -1;
}

/* True in a worker task. */
bool lx_in_worker(void)
{
	return lx_worker_index() >= 0;
}

/* True once module inits are done. */
bool lx_worker_ready(void)
{
	return worker.ready;
}

/*
 * Module inits run in the worker: one that queues work and sleeps until it is
 * done would wait for itself.  While the inits run, a sleep in the worker
 * first serves the queued work in place; true if it ran one.
 */
bool lx_worker_serve_before_init_sleep(void)
{
	if (READ_ONCE(worker.ready) || !lx_in_worker())
		return false;
	return lx_workqueue_run_one();
}

/* Asks the worker to unload every module (any context; the worker does it when it next runs). */
void lx_worker_request_unload(void)
{
	WRITE_ONCE(worker.unload_requested, true);
	lx_wake_task(LX_WORKER_TSKID);
}

/* True once the worker has run every module_exit after a request. */
bool lx_worker_unloaded(void)
{
	return READ_ONCE(worker.unloaded);
}

/* Sleeps the calling task until the worker has unloaded the modules. */
void lx_worker_wait_unloaded(void)
{
	wait_event(unload_waiters, lx_worker_unloaded());
}

/*
 * In the worker: every module_exit, newest first.  The worker runs at the
 * highest task priority meanwhile, so application tasks still running
 * cannot call into a driver half-way through its unload unless the exit
 * sleeps.  Work queued by the exits is served afterwards, as before.
 */
static void unload_modules(void)
{
	PRI pri = LX_WORKER_PRIORITY;

	(void)get_pri(TSK_SELF, &pri);
	(void)chg_pri(TSK_SELF, TMIN_TPRI);
	lx_modules_exit();
	WRITE_ONCE(worker.unloaded, true);
	wake_up_all(&unload_waiters);
	(void)chg_pri(TSK_SELF, pri);
}

/* Sleeps the calling worker until queue_work (or an unload request) wakes it. */
static void wait_for_work(void)
{
	if (lx_workqueue_set_idle(true))
		(void)slp_tsk();
	(void)lx_workqueue_set_idle(false);
}

/* The main worker task: every module_init, then work until the modules are unloaded, then work. */
void lx_worker_task(intptr_t exinf)
{
	(void)exinf;
	(void)lx_modules_init();
	worker.ready = true;
	for (;;) {
		if (READ_ONCE(worker.unload_requested) && !worker.unloaded)
			unload_modules();
		else if (!lx_workqueue_run_one())
			wait_for_work();
	}
}

/* A pool worker: runs work while the others sleep in theirs. */
void lx_pool_worker_task(intptr_t exinf)
{
	(void)exinf;
	for (;;) {
		if (!lx_workqueue_run_one())
			wait_for_work();
	}
}
