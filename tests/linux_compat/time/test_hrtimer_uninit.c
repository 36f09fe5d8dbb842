/*
 * test_hrtimer_uninit.c — cancelling an hrtimer that was never initialised,
 * as LEGO's exit code does after its init's misc_register failed (the init
 * returns 0 anyway, so the exit runs): Linux reads the timer's NULL base and
 * crashes (6.1) or spins for ever (2.6.33); here each cancel form is
 * reported once, naming the call and why, and returns 0.
 */
#define KBUILD_MODNAME "hrtimer_uninit"
#include "tap.h"
#include "lx_core_test.h"
#include "rtos_test.h"
#include <linux/hrtimer.h>
#include <linux/string.h>
#include <linux/time64.h>

static struct hrtimer never_set_up;
static int cancel_ret = -7, try_ret = -7;
static unsigned bugs_after_cancel, bugs_after_try;
static char first_report[256];

static void task(intptr_t exinf)
{
	(void)exinf;
	rtos_host_expect_bugs(true);
	cancel_ret = hrtimer_cancel(&never_set_up);
	bugs_after_cancel = rtos_host_bug_count();
	strscpy(first_report, rtos_host_last_bug(), sizeof(first_report));
	try_ret = hrtimer_try_to_cancel(&never_set_up);
	bugs_after_try = rtos_host_bug_count();
	rtos_host_expect_bugs(false);
}

int main(void)
{
	static const struct rtos_task_cfg tasks[] = { LXC_TASK(1, task, 5, true) };

	tap_plan(5);
	if (!lxc_boot(tasks, 1, NULL, 0, NULL, 0))
		return tap_done();
	rtos_host_run_for(5 * NSEC_PER_MSEC);
	rtos_host_shutdown();
	is_int(cancel_ret, 0, "hrtimer_cancel of a timer never initialised returns 0");
	is_int((int)bugs_after_cancel, 1, "and is reported");
	ok(strstr(first_report, "hrtimer_cancel") && strstr(first_report, "never initialised") &&
	   strstr(first_report, "crashes"), "the report names the call and what Linux does: %s", first_report);
	is_int(try_ret, 0, "hrtimer_try_to_cancel of it returns 0");
	is_int((int)bugs_after_try, 2, "and is reported too");
	return tap_done();
}
