/*
 * linux_compat/workqueue.h — the work FIFO (workqueue.c) and the worker
 * task that serves it and runs the modules' life cycle (worker.c), as the
 * rest of linux_compat calls them.
 */
#ifndef _LINUX_COMPAT_WORKQUEUE_H
#define _LINUX_COMPAT_WORKQUEUE_H

#include <stdbool.h>

/* Forgets all queued work, workqueues and the worker's state (boot). */
void lx_workqueue_reset(void);
/* Runs the first queued work in the calling (worker) task; false if none is queued. */
bool lx_workqueue_run_one(void);
/* Forgets the worker's module life cycle state (lx_workqueue_reset). */
void lx_worker_reset(void);
/* True if the calling code runs in the worker task. */
bool lx_in_worker(void);
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
