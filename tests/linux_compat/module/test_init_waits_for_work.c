/*
 * test_init_waits_for_work.c — a module_init may schedule_work() and wait for
 * it, with wait_for_completion_timeout or without a timeout: module inits run
 * in the worker, which serves the queued work in place while an init sleeps,
 * so the wait neither times out nor hangs the inits after it.
 */
#define KBUILD_MODNAME "initwait"
#include "tap.h"
#include "lx_core_test.h"
#include <linux/module.h>
#include <linux/init.h>
#include <linux/workqueue.h>
#include <linux/completion.h>
#include <linux/jiffies.h>
#include <linux/delay.h>
#include <linux_compat/workqueue.h>
#include <kernel.h>

static struct work_struct probe_work;
static DECLARE_COMPLETION(probe_done);
static unsigned long timeout_left;
static bool waited_untimed, init_returned, work_ran_in_worker;
static bool ready_seen_by_task;

static void probe_fn(struct work_struct *w)
{
	(void)w;
	work_ran_in_worker = lx_in_worker();
	complete(&probe_done);
}

static int __init initwait_init(void)
{
	INIT_WORK(&probe_work, probe_fn);
	schedule_work(&probe_work);
	timeout_left = wait_for_completion_timeout(&probe_done, msecs_to_jiffies(100));
	reinit_completion(&probe_done);
	schedule_work(&probe_work);
	wait_for_completion(&probe_done);
	waited_untimed = true;
	init_returned = true;
	return 0;
}

static void __exit initwait_exit(void)
{
	cancel_work_sync(&probe_work);
}

module_init(initwait_init);
module_exit(initwait_exit);
MODULE_LICENSE("GPL");

static void main_task(intptr_t exinf)
{
	(void)exinf;
	msleep(5);
	ready_seen_by_task = lx_worker_ready();
}

int main(void)
{
	static const struct rtos_task_cfg tasks[] = { LXC_TASK(1, main_task, 8, true) };

	tap_plan(4);
	if (!lxc_boot(tasks, 1, NULL, 0, NULL, 0))
		return tap_done();
	rtos_host_run_for(20 * NSEC_PER_MSEC);
	rtos_host_shutdown();
	ok(timeout_left > 0, "wait_for_completion_timeout in module_init: completed, %lu jiffies left",
	   timeout_left);
	ok(waited_untimed && init_returned, "wait_for_completion without a timeout in module_init returns");
	ok(work_ran_in_worker, "the work ran in the worker");
	ok(ready_seen_by_task, "the inits finished: the worker serves the workqueues");
	return tap_done();
}
