/*
 * test_workqueue.c — deferred work runs in the kernel worker tasks: FIFO
 * order, queueing from an ISR, flush_work / cancel_work_sync, delayed work,
 * alloc/destroy_workqueue, and a flush from inside a work item.
 */
#include "tap.h"
#include "lx_core_test.h"
#include "rtos_test.h"
#include <linux/workqueue.h>
#include <linux/delay.h>
#include <linux/jiffies.h>
#include <linux_compat/sched.h>
#include <linux_compat/workqueue.h>
#include <kernel.h>

#define IRQ_TEST	90U

static struct work_struct w1, w2, w3, isr_work, slow_work, cancel_me, outer, inner;
static struct delayed_work dw, dw_cancel, dw_flush;
static bool ran_in_task = true, ran_in_worker = true;
static unsigned long dw_queued_at, dw_ran_at;
static bool r_flush, r_cancel_pending, r_cancel_ran, r_queue_again, r_dw_cancel, r_dw_flush_ran;
static bool r_inner_done_in_outer, r_custom_ran, r_isr_ran, r_flushed_waited;
static struct workqueue_struct *custom;

static void check_context(void)
{
	if (sns_ctx())
		ran_in_task = false;
	if (!lx_in_worker())
		ran_in_worker = false;
}

static void log_fn(struct work_struct *w)
{
	check_context();
	rt_log("%s", w == &w1 ? "w1" : w == &w2 ? "w2" : "w3");
}

static void isr_fn(struct work_struct *w)
{
	(void)w;
	check_context();
	r_isr_ran = true;
}

static void slow_fn(struct work_struct *w)
{
	(void)w;
	check_context();
	msleep(5);
	rt_log("slow-done");
}

static void cancelled_fn(struct work_struct *w)
{
	(void)w;
	r_cancel_ran = true;
}

static void dw_fn(struct work_struct *w)
{
	(void)w;
	check_context();
	dw_ran_at = jiffies;
}

static void flushed_dw_fn(struct work_struct *w)
{
	(void)w;
	r_dw_flush_ran = true;
}

static void inner_fn(struct work_struct *w)
{
	(void)w;
	rt_log("inner");
}

static void outer_fn(struct work_struct *w)
{
	(void)w;
	schedule_work(&inner);
	flush_work(&inner);           /* from the worker: runs inner in place */
	r_inner_done_in_outer = !work_pending(&inner);
	rt_log("outer");
}

static void custom_fn(struct work_struct *w)
{
	(void)w;
	r_custom_ran = true;
}

static void work_isr(intptr_t exinf)
{
	(void)exinf;
	schedule_work(&isr_work);
}

static void main_task(intptr_t exinf)
{
	(void)exinf;
	INIT_WORK(&w1, log_fn);
	INIT_WORK(&w2, log_fn);
	INIT_WORK(&w3, log_fn);
	schedule_work(&w1);
	schedule_work(&w2);
	r_queue_again = !schedule_work(&w1);    /* already pending */
	schedule_work(&w3);
	msleep(1);

	INIT_WORK(&isr_work, isr_fn);
	rtos_host_irq_raise(IRQ_TEST);
	msleep(1);

	INIT_WORK(&slow_work, slow_fn);
	schedule_work(&slow_work);
	r_flush = flush_work(&slow_work);       /* sleeps until slow_fn returned */
	r_flushed_waited = strstr(rt_log_text(), "slow-done") != NULL;

	INIT_WORK(&cancel_me, cancelled_fn);
	INIT_WORK(&outer, outer_fn);
	INIT_WORK(&inner, inner_fn);
	schedule_work(&slow_work);
	schedule_work(&cancel_me);
	r_cancel_pending = cancel_work_sync(&cancel_me);
	flush_scheduled_work();
	schedule_work(&outer);
	flush_work(&outer);

	INIT_DELAYED_WORK(&dw, dw_fn);
	dw_queued_at = jiffies;
	schedule_delayed_work(&dw, msecs_to_jiffies(4));
	INIT_DELAYED_WORK(&dw_cancel, cancelled_fn);
	schedule_delayed_work(&dw_cancel, 2);
	r_dw_cancel = cancel_delayed_work(&dw_cancel);
	INIT_DELAYED_WORK(&dw_flush, flushed_dw_fn);
	schedule_delayed_work(&dw_flush, 1000);
	flush_delayed_work(&dw_flush);
	msleep(10);

	custom = alloc_workqueue("custom-%d", 0, 1, 7);
	if (custom != NULL) {
		INIT_WORK(&w1, custom_fn);
		queue_work(custom, &w1);
		destroy_workqueue(custom);
	}
}

int main(void)
{
	static const struct rtos_task_cfg tasks[] = { LXC_TASK(1, main_task, 2, true) };  /* above the worker */
	static const struct rtos_int_cfg ints[] = { { IRQ_TEST, TA_ENAINT | TA_EDGE, -3 } };
	static const struct rtos_isr_cfg isrs[] = { { TA_NULL, 0, IRQ_TEST, work_isr, 1 } };

	tap_plan(14);
	rt_log_reset();
	if (!lxc_boot(tasks, 1, ints, 1, isrs, 1))
		return tap_done();
	rtos_host_run_for(60 * NSEC_PER_MSEC);
	rtos_host_shutdown();

	ok(strncmp(rt_log_text(), "w1 w2 w3", 8) == 0, "work runs in queueing order: %s", rt_log_text());
	ok(r_queue_again, "queueing a pending work returns false");
	ok(ran_in_task && ran_in_worker, "every work ran in task context, in a worker task");
	ok(r_isr_ran, "work queued from an ISR ran");
	ok(r_flush && r_flushed_waited, "flush_work sleeps until the work has finished");
	ok(r_cancel_pending && !r_cancel_ran, "cancel_work_sync of a pending work: true, and it never runs");
	ok(strstr(rt_log_text(), "inner outer") != NULL && r_inner_done_in_outer,
	   "flush_work from a work item runs the flushed work in place");
	ok(dw_ran_at - dw_queued_at >= 4 && dw_ran_at - dw_queued_at <= 5,
	   "delayed work runs after its delay (%lu jiffies)", dw_ran_at - dw_queued_at);
	ok(r_dw_cancel, "cancel_delayed_work during the delay returns true (and it never runs)");
	ok(r_dw_flush_ran, "flush_delayed_work runs a 1 s delayed work at once");
	ok(custom != NULL && strcmp(custom->name, "custom-7") == 0, "alloc_workqueue formats the name");
	ok(r_custom_ran, "destroy_workqueue waits for its work");
	ok(!r_cancel_ran, "cancelled work (plain and delayed) never ran");
	ok(lx_worker_ready(), "the worker finished module init and serves work");
	return tap_done();
}
