/*
 * lx_test.h — running a linux_compat test body in an RTOS task.
 *
 * lx_test_run boots a configuration with one kernel-domain task that runs
 * body (process context, as module init and file operations are),
 * linux_compat_cfg (worker task running module inits first, tick, Linux
 * interrupt lines) and whatever the test adds in
 * extra, runs the system until the body has returned (at most
 * LX_TEST_MAX_NS of virtual time), and shuts it down.
 */
#ifndef EV3LX_TESTS_LX_TEST_H
#define EV3LX_TESTS_LX_TEST_H

#include "tap.h"
#include "rtos_host.h"
#include <linux_compat/config.h>

#define LX_TEST_TASK_ID		1
#define LX_TEST_STACK		(64 * 1024)
#define LX_TEST_MAX_NS		(10ULL * 1000 * 1000 * 1000)   /* virtual time a body may take */

static void (*lx_test_body)(void);
static bool lx_test_body_done;

static void lx_test_task(intptr_t exinf)
{
	(void)exinf;
	lx_test_body();
	lx_test_body_done = true;
}

/* Runs body in a task of domain domid (TDOM_KERNEL or a user domain) with
 * extra (may be NULL) merged in; returns true if the body ran to its end. */
static inline bool lx_test_run_in(void (*body)(void), ID domid, const struct rtos_cfg *extra)
{
	const struct rtos_task_cfg task = {
		LX_TEST_TASK_ID, TA_ACT, 0, lx_test_task, 8, LX_TEST_STACK, domid, "lx_test",
	};
	const struct rtos_cfg *includes[3] = { &linux_compat_cfg, extra, NULL };
	const struct rtos_cfg cfg = {
		.name = "lx_test", .tasks = &task, .ntasks = 1, .includes = includes,
	};
	ER ercd;

	lx_test_body = body;
	lx_test_body_done = false;
	ercd = rtos_host_boot(&cfg);
	if (ercd != E_OK) {
		tap_diag("boot failed: %d", ercd);
		return false;
	}
	/* Not run_until_idle: a body waiting in dly_tsk leaves only ticks pending. */
	while (!lx_test_body_done && rtos_host_now() < LX_TEST_MAX_NS)
		rtos_host_run_for(1000 * 1000);
	rtos_host_shutdown();
	return lx_test_body_done;
}

static inline bool lx_test_run(void (*body)(void))
{
	return lx_test_run_in(body, TDOM_KERNEL, NULL);
}

#endif /* EV3LX_TESTS_LX_TEST_H */
