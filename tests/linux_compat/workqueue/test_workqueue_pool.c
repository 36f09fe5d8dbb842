/*
 * test_workqueue_pool.c — the workers serve the workqueues as one CPU's
 * kworker pool: a work item that sleeps does not hold up another
 * workqueue's (or system_wq's) items, an ordered workqueue runs one item at
 * a time, an item never runs on two workers at once, a flush from a work
 * item waits for an item running on another worker, destroy_workqueue
 * drains, and with every worker asleep in an item further work waits.
 */
#include "tap.h"
#include "lx_core_test.h"
#include "rtos_test.h"
#include <linux/workqueue.h>
#include <linux/completion.h>
#include <linux/delay.h>
#include <linux/jiffies.h>
#include <linux_compat/clock.h>
#include <linux_compat/sched.h>
#include <linux_compat/workqueue.h>
#include <kernel.h>

static struct workqueue_struct *wq_a, *wq_b, *ordered;
static struct work_struct sleeper, quick, o1, o2, again, waiters[LX_NR_WORKERS + 1], runs_long, flusher;
static struct work_struct same_o1, same_o2;
static DECLARE_COMPLETION(go);
static uint64_t sleeper_done_ns, quick_ran_ns;
static int sleeper_worker = -1, quick_worker = -1;
static int again_running, again_max, again_runs;
static int waiters_started, waiters_done, started_before_go;
static bool runs_long_done_seen_by_flusher, flush_result, quick_b_ran;
static unsigned int bugs_before_flush, bugs_after_flush;

static void sleeper_fn(struct work_struct *w)
{
	(void)w;
	if (sleeper_worker < 0)
		sleeper_worker = lx_worker_index();
	msleep(20);
	sleeper_done_ns = lx_clock_now_ns();
}

static void quick_fn(struct work_struct *w)
{
	(void)w;
	quick_worker = lx_worker_index();
	quick_ran_ns = lx_clock_now_ns();
}

static void ordered_fn(struct work_struct *w)
{
	const char *name = w == &o1 ? "o1" : "o2";

	rt_log("%s-start", name);
	msleep(3);
	rt_log("%s-end", name);
}

static void again_fn(struct work_struct *w)
{
	(void)w;
	if (++again_running > again_max)
		again_max = again_running;
	msleep(3);
	again_running--;
	again_runs++;
}

static void waiter_fn(struct work_struct *w)
{
	(void)w;
	waiters_started++;
	wait_for_completion(&go);
	waiters_done++;
}

static void runs_long_fn(struct work_struct *w)
{
	(void)w;
	msleep(5);
}

static void flusher_fn(struct work_struct *w)
{
	(void)w;
	flush_result = flush_work(&runs_long);   /* runs on another worker: sleep until it is done */
	runs_long_done_seen_by_flusher = !work_pending(&runs_long);
}

static void same_o1_fn(struct work_struct *w)
{
	(void)w;
	queue_work(ordered, &same_o2);
	flush_work(&same_o2);    /* same ordered workqueue: only this item could make way */
}

static void same_o2_fn(struct work_struct *w)
{
	(void)w;
}

static void main_task(intptr_t exinf)
{
	unsigned int i;

	(void)exinf;
	wq_a = alloc_workqueue("a", 0, 0);
	wq_b = alloc_workqueue("b", 0, 0);
	ordered = alloc_ordered_workqueue("o", 0);

	INIT_WORK(&sleeper, sleeper_fn);
	INIT_WORK(&quick, quick_fn);
	queue_work(wq_a, &sleeper);
	msleep(1);
	queue_work(wq_b, &quick);
	msleep(1);
	quick_b_ran = quick_ran_ns != 0;
	flush_workqueue(wq_a);

	INIT_WORK(&o1, ordered_fn);
	INIT_WORK(&o2, ordered_fn);
	queue_work(ordered, &o1);
	queue_work(ordered, &o2);
	flush_workqueue(ordered);

	INIT_WORK(&again, again_fn);
	schedule_work(&again);
	msleep(1);                  /* running, asleep in msleep */
	schedule_work(&again);      /* pending again while it runs */
	msleep(10);

	for (i = 0; i < LX_NR_WORKERS + 1; i++) {
		INIT_WORK(&waiters[i], waiter_fn);
		schedule_work(&waiters[i]);
	}
	msleep(2);
	started_before_go = waiters_started;
	complete_all(&go);
	msleep(2);

	INIT_WORK(&runs_long, runs_long_fn);
	INIT_WORK(&flusher, flusher_fn);
	bugs_before_flush = rtos_host_bug_count();
	schedule_work(&runs_long);
	msleep(1);
	schedule_work(&flusher);
	msleep(10);
	bugs_after_flush = rtos_host_bug_count();

	INIT_WORK(&sleeper, sleeper_fn);
	sleeper_done_ns = 0;
	queue_work(wq_a, &sleeper);
	destroy_workqueue(wq_a);
	rt_log(" destroyed-after-sleeper=%d", sleeper_done_ns != 0);

	INIT_WORK(&same_o1, same_o1_fn);
	INIT_WORK(&same_o2, same_o2_fn);
	rtos_host_expect_bugs(true);
	queue_work(ordered, &same_o1);
	msleep(2);
	rtos_host_expect_bugs(false);
}

int main(void)
{
	static const struct rtos_task_cfg tasks[] = { LXC_TASK(1, main_task, 2, true) };  /* above the workers */

	tap_plan(12);
	rt_log_reset();
	if (!lxc_boot(tasks, 1, NULL, 0, NULL, 0))
		return tap_done();
	rtos_host_run_for(200 * NSEC_PER_MSEC);

	ok(LX_NR_POOL_WORKERS >= 1, "%d pool workers besides the main worker", LX_NR_POOL_WORKERS);
	ok(quick_b_ran && quick_ran_ns < sleeper_done_ns,
	   "wq b's item ran while wq a's slept (%llu < %llu ns)", (unsigned long long)quick_ran_ns,
	   (unsigned long long)sleeper_done_ns);
	ok(quick_worker >= 0 && quick_worker != sleeper_worker, "on another worker (%d, %d)", sleeper_worker,
	   quick_worker);
	ok(strstr(rt_log_text(), "o1-start o1-end o2-start o2-end") != NULL,
	   "the ordered workqueue ran one item at a time: %s", rt_log_text());
	is_int(again_runs, 2, "a work queued again while it ran ran twice");
	is_int(again_max, 1, "never on two workers at once");
	is_int(started_before_go, LX_NR_WORKERS, "with every worker asleep in an item, the next one waits");
	is_int(waiters_done, LX_NR_WORKERS + 1, "and runs when one is free");
	ok(flush_result && runs_long_done_seen_by_flusher,
	   "flush_work from a work item sleeps until the item running on another worker is done");
	is_int((int)(bugs_after_flush - bugs_before_flush), 0, "with no deadlock report");
	ok(strstr(rt_log_text(), "destroyed-after-sleeper=1") != NULL, "destroy_workqueue drained its sleeping item");
	ok(strstr(rtos_host_last_bug(), "workqueue deadlock") != NULL,
	   "flush_work of an item of its own ordered workqueue is the reported deadlock: %s", rtos_host_last_bug());
	rtos_host_shutdown();
	return tap_done();
}
