/*
 * test_unload.c — modules across boots: at shutdown linux_compat's ATT_TER
 * has the worker run every module_exit, newest first, in task context (an
 * exit may sleep), before the kernel stops; each boot runs every
 * module_init again; lx_compat_unload unloads from a task (E_CTX from
 * non-task context and from the worker itself); memory a module leaves in
 * the kmalloc pool is logged; an exit that never returns is reported after
 * LX_UNLOAD_TIMEOUT_MS and the next boot starts clean anyway.
 */
#define KBUILD_MODNAME "unload_a"
#include "tap.h"
#include "lx_core_test.h"
#include "rtos_test.h"
#include <linux/module.h>
#include <linux/completion.h>
#include <linux/delay.h>
#include <linux/errno.h>
#include <linux/slab.h>
#include <linux/workqueue.h>
#include <linux_compat/heap.h>
#include <linux_compat/sched.h>
#include <linux_compat/shutdown.h>
#include <kernel.h>

#define MS 1000000ULL

static bool exits_in_worker = true;
static uint64_t exit_started_ns, exit_ended_ns;
static bool leak;            /* module b keeps its allocation */
static bool hang;            /* module b's exit waits for ever */
static void *b_mem;
static DECLARE_COMPLETION(never);

static void note_context(void)
{
	if (sns_ctx() || lx_current_tskid() != LX_WORKER_TSKID)
		exits_in_worker = false;
}

static int __init a_init(void)
{
	rt_log("init:a");
	return 0;
}

/* Sleeps: exits run in task context. */
static void __exit a_exit(void)
{
	note_context();
	exit_started_ns = rtos_host_now();
	msleep(5);
	exit_ended_ns = rtos_host_now();
	rt_log("exit:a");
}

module_init(a_init);
module_exit(a_exit);
MODULE_LICENSE("GPL");

/* A second module, initialised after unload_a (same level, later name). */
static struct module b_mod = { .name = "unload_b" };

static int b_init(void)
{
	rt_log("init:b");
	b_mem = kmalloc(100, GFP_KERNEL);
	return b_mem ? 0 : -ENOMEM;
}

static void b_exit(void)
{
	note_context();
	if (hang)
		wait_for_completion(&never);
	if (!leak)
		kfree(b_mem);
	rt_log("exit:b");
}

static const struct lx_initcall b_init_call = { &b_mod, b_init, NULL, LX_INITCALL_DEVICE };
static const struct lx_initcall b_exit_call = { &b_mod, NULL, b_exit, LX_INITCALL_DEVICE };
static const struct lx_initcall *const b_calls[2] __used __section(LX_INITCALL_SECTION) = {
	&b_init_call, &b_exit_call,
};

/* ---- task bodies ---- */

static ER unload_ercd, harness_ercd, worker_ercd;
static char log_after_unload[64];
static struct work_struct unload_work;

static void idle_task(intptr_t exinf)
{
	(void)exinf;
}

static void unloading_task(intptr_t exinf)
{
	(void)exinf;
	unload_ercd = lx_compat_unload();
	snprintf(log_after_unload, sizeof(log_after_unload), "%.60s", rt_log_text());
}

static void unload_from_worker(struct work_struct *w)
{
	(void)w;
	worker_ercd = lx_compat_unload();
}

static void queueing_task(intptr_t exinf)
{
	(void)exinf;
	INIT_WORK(&unload_work, unload_from_worker);
	schedule_work(&unload_work);
}

/* ---- the syslog warning about leftover memory, seen through the trace ---- */

static bool saw_leak_warning;

static void trace_sink(const char *line, void *ctx)
{
	(void)ctx;
	if (strstr(line, "kmalloc memory in use after every module_exit"))
		saw_leak_warning = true;
}

static bool boot_with(void (*fn)(intptr_t))
{
	static struct rtos_task_cfg task = LXC_TASK(1, idle_task, 8, true);

	task.task = fn;
	return lxc_boot(&task, 1, NULL, 0, NULL, 0);
}

int main(void)
{
	struct lx_heap_stats stats;

	tap_plan(19);

	/* Boot 1: load, run, shut down. */
	rt_log_reset();
	if (!boot_with(idle_task))
		return tap_done();
	rtos_host_run_for(10 * MS);
	is_str(rt_log_text(), "init:a init:b", "boot 1: both modules initialised");
	is_int(lx_module_find("unload_a")->state, MODULE_STATE_LIVE, "unload_a is live");
	rt_log_reset();
	rtos_host_shutdown();
	is_str(rt_log_text(), "exit:b exit:a", "shutdown: every module_exit, newest first");
	ok(exits_in_worker, "exits run in the worker task (task context)");
	is_u64(exit_ended_ns - exit_started_ns, 5 * MS, "an exit may sleep (msleep(5) took 5 ms)");
	ok(lx_module_find("unload_a")->state == MODULE_STATE_UNFORMED &&
	   b_mod.state == MODULE_STATE_UNFORMED, "both modules unloaded");
	lx_heap_get_stats(&stats);
	is_int(stats.in_use, 0, "the kmalloc pool is empty again");

	/* Boot 2: inits run again; a task unloads; shutdown has nothing left to do. */
	rt_log_reset();
	if (!boot_with(unloading_task))
		return tap_done();
	rtos_host_run_for(20 * MS);
	is_int(unload_ercd, E_OK, "lx_compat_unload from a task");
	is_str(log_after_unload, "init:a init:b exit:b exit:a",
	       "boot 2: inits ran again; lx_compat_unload returned after the exits");
	harness_ercd = lx_compat_unload();
	is_int(harness_ercd, E_CTX, "lx_compat_unload from non-task context: E_CTX");
	rt_log_reset();
	rtos_host_shutdown();
	is_str(rt_log_text(), "", "no module_exit runs twice");

	/* Boot 3: from the worker itself it would wait for itself. */
	rt_log_reset();
	if (!boot_with(queueing_task))
		return tap_done();
	rtos_host_run_for(10 * MS);
	is_int(worker_ercd, E_CTX, "lx_compat_unload from a work item: E_CTX");
	rtos_host_shutdown();

	/* Boot 4: a module leaks; the shutdown says so. */
	leak = true;
	saw_leak_warning = false;
	rtos_host_trace_set_sink(trace_sink, NULL);
	if (!boot_with(idle_task))
		return tap_done();
	rtos_host_run_for(10 * MS);
	rtos_host_shutdown();
	rtos_host_trace_set_sink(NULL, NULL);
	ok(saw_leak_warning, "memory left by a module_exit is logged at shutdown");
	lx_heap_get_stats(&stats);
	ok(stats.in_use > 0, "(it is still allocated: %zu bytes)", stats.in_use);
	leak = false;

	/* Boot 5: an exit that never returns is reported; the next boot starts clean. */
	hang = true;
	rtos_host_expect_bugs(true);
	rt_log_reset();
	if (!boot_with(idle_task))
		return tap_done();
	rtos_host_run_for(10 * MS);
	rtos_host_shutdown();
	is_int(rtos_host_bug_count(), 1, "an exit blocking the worker is reported");
	ok(strstr(rtos_host_last_bug(), "module unload did not finish") != NULL, "as: %s",
	   rtos_host_last_bug());
	is_str(rt_log_text(), "init:a init:b", "(the blocked exit never finished)");
	rtos_host_expect_bugs(false);
	hang = false;

	rt_log_reset();
	if (!boot_with(idle_task))
		return tap_done();
	rtos_host_run_for(10 * MS);
	is_str(rt_log_text(), "init:a init:b", "the next boot initialises every module again");
	rt_log_reset();
	rtos_host_shutdown();
	is_str(rt_log_text(), "exit:b exit:a", "and unloads them at its shutdown");
	return tap_done();
}
