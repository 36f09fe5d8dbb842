/*
 * linux_compat/workqueue.h — the work FIFO (workqueue.c) and the worker
 * task that serves it and runs the modules' life cycle (worker.c), as the
 * rest of linux_compat calls them.
 */
#ifndef _LINUX_COMPAT_WORKQUEUE_H
#define _LINUX_COMPAT_WORKQUEUE_H

#include <stdbool.h>
#include <kernel.h>
#include <linux_compat/config.h>

/* Forgets all queued work, workqueues and the worker's state (boot). */
void lx_workqueue_reset(void);
/* Runs the oldest queued work the calling worker may run; false if there is none. */
bool lx_workqueue_run_one(void);
/* Marks the calling worker idle (true: about to sleep; false if runnable work is queued) or busy. */
bool lx_workqueue_set_idle(bool idle);
/* Forgets the worker's module life cycle state (lx_workqueue_reset). */
void lx_worker_reset(void);
/* True if the calling code runs in a worker task (the main one or a pool worker). */
bool lx_in_worker(void);
/* The calling worker's index (0 = the main worker, 1..LX_NR_POOL_WORKERS), or -1. */
int lx_worker_index(void);
/* The task ID of worker index. */
ID lx_worker_tskid(unsigned int index);
/* True once the worker has run the module inits and serves work. */
bool lx_worker_ready(void);
/* In the worker while the module inits run, runs one queued work (a sleep
 * calls it first, so an init may wait for work it queued); false if none. */
bool lx_worker_serve_before_init_sleep(void);
/* Asks the worker to run every module_exit (lx_modules_exit) when it next
 * runs; any context.  The request lasts until the next boot. */
void lx_worker_request_unload(void);
/* True once the worker has done so. */
bool lx_worker_unloaded(void);
/* Sleeps the calling task (not the worker) until lx_worker_unloaded(). */
void lx_worker_wait_unloaded(void);

#endif /* _LINUX_COMPAT_WORKQUEUE_H */
