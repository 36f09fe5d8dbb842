/*
 * shutdown.c — linux_compat's termination: the modules are unloaded by the
 * worker task before the kernel stops (linux_compat/shutdown.h).
 */
#include <linux/kernel.h>
#include <linux/printk.h>
#include <linux_compat/config.h>
#include <linux_compat/heap.h>
#include <linux_compat/shutdown.h>
#include <linux_compat/workqueue.h>
#include <kernel.h>

/* ATT_TER: the worker runs every module_exit; what they leave in the kmalloc pool is logged. */
void lx_compat_terminate(intptr_t exinf)
{
	struct lx_heap_stats stats;

	(void)exinf;
	lx_worker_request_unload();
	if (!lx_compat_finish_unload())
		return;
	lx_heap_get_stats(&stats);
	if (stats.in_use != 0)
		pr_warn("linux_compat: %zu bytes of kmalloc memory in use after every module_exit\n",
			stats.in_use);
}

/* From a task: the worker unloads every module; returns when it is done. */
ER lx_compat_unload(void)
{
	if (sns_ctx() || lx_in_worker())
		return E_CTX;
	lx_worker_request_unload();
	lx_worker_wait_unloaded();
	return E_OK;
}
