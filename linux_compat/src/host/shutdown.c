/*
 * shutdown.c (host) — the termination routine runs in the harness with the
 * system intact (rtos_host_shutdown), so it lets the system run until the
 * worker has unloaded the modules.
 */
#include <linux_compat/report.h>
#include <linux_compat/shutdown.h>
#include <linux_compat/workqueue.h>
#include <rtos_host.h>

#define STEP_NS		(100ULL * 1000)   /* the unload ends at most this much before the run stops */

/* Runs the system until the worker has unloaded the modules; a bug report if it takes too long.
 * After ext_ker (or a stalled task, a stack overrun) nothing runs and time stands still: the
 * modules stay loaded, as on a brick whose kernel has stopped, and false comes back at once. */
bool lx_compat_finish_unload(void)
{
	uint64_t end = rtos_host_now() + LX_UNLOAD_TIMEOUT_MS * 1000000ULL;

	while (!lx_worker_unloaded() && rtos_host_now() < end && !rtos_host_exited())
		rtos_host_run_for(STEP_NS);
	if (lx_worker_unloaded())
		return true;
	if (rtos_host_exited())
		return false;
	lx_report("module unload did not finish", NULL, 0,
		  "the worker has not run every module_exit after %d ms (an exit or a work item blocks it)",
		  LX_UNLOAD_TIMEOUT_MS);
	return false;
}
