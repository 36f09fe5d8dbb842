/*
 * test_workqueue_might_sleep.c — flush_work, cancel_work_sync,
 * cancel_delayed_work_sync and flush_workqueue may sleep, so Linux announces
 * might_sleep() in them: called under a spinlock they are reported even when
 * the work is idle and they would not have waited.
 */
#include "tap.h"
#include "lx_core_test.h"
#include <linux/workqueue.h>
#include <linux/spinlock.h>
#include <linux/delay.h>
#include <kernel.h>

static struct work_struct idle_work;
static struct delayed_work idle_dwork;
static DEFINE_SPINLOCK(lock);
static uint_t counts[4];
static char texts[4][256];
static bool task_silent;

static void nothing(struct work_struct *w)
{
	(void)w;
}

/* Runs stmt under the spinlock, keeping the number of reports and the last one. */
#define UNDER_LOCK(i, stmt) do {					\
	uint_t before_ = rtos_host_bug_count();				\
	rtos_host_expect_bugs(true);					\
	spin_lock(&lock);						\
	stmt;								\
	spin_unlock(&lock);						\
	rtos_host_expect_bugs(false);					\
	counts[i] = rtos_host_bug_count() - before_;			\
	snprintf(texts[i], sizeof(texts[i]), "%s", rtos_host_last_bug()); \
} while (0)

static void main_task(intptr_t exinf)
{
	uint_t before;

	(void)exinf;
	INIT_WORK(&idle_work, nothing);
	INIT_DELAYED_WORK(&idle_dwork, nothing);
	UNDER_LOCK(0, (void)flush_work(&idle_work));
	UNDER_LOCK(1, (void)cancel_work_sync(&idle_work));
	UNDER_LOCK(2, (void)cancel_delayed_work_sync(&idle_dwork));
	UNDER_LOCK(3, flush_workqueue(system_wq));
	before = rtos_host_bug_count();
	(void)flush_work(&idle_work);
	(void)cancel_work_sync(&idle_work);
	(void)cancel_delayed_work_sync(&idle_dwork);
	flush_workqueue(system_wq);
	task_silent = rtos_host_bug_count() == before;
}

int main(void)
{
	static const struct rtos_task_cfg tasks[] = { LXC_TASK(1, main_task, 8, true) };
	static const char *const names[] = {
		"flush_work()", "cancel_work_sync()", "cancel_delayed_work_sync()", "flush_workqueue()",
	};
	unsigned int i;

	tap_plan(9);
	if (!lxc_boot(tasks, 1, NULL, 0, NULL, 0))
		return tap_done();
	rtos_host_run_for(10 * NSEC_PER_MSEC);
	rtos_host_shutdown();
	for (i = 0; i < 4; i++) {
		is_int((int)counts[i], 1, "%s on an idle work under a spinlock: one report", names[i]);
		ok(strstr(texts[i], "sleeping function called from invalid context") != NULL &&
		   strstr(texts[i], names[i]) != NULL && strstr(texts[i], "spinlock held") != NULL,
		   "...naming it and the spinlock: %s", texts[i]);
	}
	ok(task_silent, "the same calls in a task report nothing");
	return tap_done();
}
