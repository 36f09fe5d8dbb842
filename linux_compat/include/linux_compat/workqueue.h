/* linux_compat/workqueue.h — the worker's internals other parts of linux_compat call. */
#ifndef _LINUX_COMPAT_WORKQUEUE_H
#define _LINUX_COMPAT_WORKQUEUE_H

#include <stdbool.h>

/* Forgets all queued work and workqueues (boot). */
void lx_workqueue_reset(void);
/* True if the calling code runs in the worker task. */
bool lx_in_worker(void);
/* True once the worker has run the module inits and serves work. */
bool lx_worker_ready(void);

#endif /* _LINUX_COMPAT_WORKQUEUE_H */
