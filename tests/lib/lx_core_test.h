/*
 * lx_core_test.h — booting linux_compat's full configuration (worker task,
 * tick ISR, Linux lines) with a test's own tasks and ISRs, and small helpers.
 */
#ifndef EV3LX_TESTS_LX_CORE_TEST_H
#define EV3LX_TESTS_LX_CORE_TEST_H

#include "tap.h"
#include "rtos_host.h"
#include <linux_compat/config.h>

#define LXC_STACK	(64 * 1024)
/* A test task row: id, body, priority, activated at boot. */
#define LXC_TASK(id, fn, pri, act) \
	{ (id), (act) ? TA_ACT : TA_NULL, 0, (fn), (pri), LXC_STACK, TDOM_KERNEL, #fn }

/* Boots the test's tasks/ints/isrs together with linux_compat_cfg. */
static inline bool lxc_boot(const struct rtos_task_cfg *tasks, uint_t ntasks,
			    const struct rtos_int_cfg *ints, uint_t nints,
			    const struct rtos_isr_cfg *isrs, uint_t nisrs)
{
	static const struct rtos_cfg *const includes[] = { &linux_compat_cfg, NULL };
	static struct rtos_cfg cfg;
	ER ercd;

	cfg.name = "lx_core_test";
	cfg.tasks = tasks;
	cfg.ntasks = ntasks;
	cfg.ints = ints;
	cfg.nints = nints;
	cfg.isrs = isrs;
	cfg.nisrs = nisrs;
	cfg.includes = includes;
	ercd = rtos_host_boot(&cfg);
	if (ercd != E_OK)
		tap_diag("boot failed: %d", (int)ercd);
	return ercd == E_OK;
}

/* A deterministic pseudo-random sequence (xorshift32). */
static inline uint32_t lxc_rand(uint32_t *state)
{
	uint32_t x = *state;

	x ^= x << 13;
	x ^= x >> 17;
	x ^= x << 5;
	*state = x;
	return x;
}

#endif /* EV3LX_TESTS_LX_CORE_TEST_H */
