/*
 * shutdown.c (AM1808) — HRP2's ext_ker runs termination routines after
 * dispatching has stopped: the worker cannot unload anything any more.
 */
#include <linux/module.h>
#include <linux_compat/shutdown.h>
#include <linux_compat/workqueue.h>
#include <t_syslog.h>

/* True if a task had the modules unloaded (lx_compat_unload) before ext_ker; logs otherwise. */
bool lx_compat_finish_unload(void)
{
	if (lx_worker_unloaded())
		return true;
	syslog(LOG_NOTICE, "linux_compat: ext_ker with the modules loaded "
	       "(call lx_compat_unload() from a task first to run their module_exit)");
	return false;
}
