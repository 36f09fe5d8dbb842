/*
 * linux_compat/shutdown.h — unloading the modules before the kernel stops.
 *
 * linux_compat_cfg's ATT_TER, lx_compat_terminate, asks the worker task to
 * run every module_exit (lx_modules_exit, newest module first) in task
 * context - exits may sleep: misc_deregister, free_irq, hrtimer_cancel... -
 * as rmmod or a power-off would, and waits for it:
 *   - host: rtos_host_shutdown runs ATT_TER routines with the system still
 *     running, and lx_compat_finish_unload runs it until the worker is done
 *     (at most LX_UNLOAD_TIMEOUT_MS of virtual time, else a bug report);
 *   - AM1808: HRP2's ext_ker runs ATT_TER after dispatching has stopped, so
 *     the worker cannot run there.  A firmware that wants the drivers
 *     unloaded (motors coasting, lines released) calls lx_compat_unload()
 *     from a task before ext_ker; the ATT_TER logs if nobody did.
 * The next boot starts with every module uninitialised (lx_compat_boot).
 */
#ifndef _LINUX_COMPAT_SHUTDOWN_H
#define _LINUX_COMPAT_SHUTDOWN_H

#include <stdbool.h>
#include <t_stddef.h>

/* Virtual time the host shutdown gives the module exits. */
#define LX_UNLOAD_TIMEOUT_MS	10000

/* From a task other than the worker: has the worker run every module_exit
 * and sleeps until it is done.  E_OK, or E_CTX (non-task context, the
 * worker itself).  The modules stay unloaded until the next boot. */
ER lx_compat_unload(void);

/* Per target, in lx_compat_terminate after the unload request: true once the
 * worker has unloaded the modules (host: runs the system until then). */
bool lx_compat_finish_unload(void);

#endif /* _LINUX_COMPAT_SHUTDOWN_H */
