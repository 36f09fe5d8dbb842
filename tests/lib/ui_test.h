/*
 * ui_test.h — d_ui on the simulated brick: boots host_sim's EV3 with
 * linux_compat and d_ui (through ui_hack), one test task that runs the test
 * body in process context and a helper task (higher priority, kernel
 * domain) the body can start for a second waiter; small helpers for the
 * shared page and virtual time.
 */
#ifndef EV3LX_TESTS_UI_TEST_H
#define EV3LX_TESTS_UI_TEST_H

#include "tap.h"
#include "rtos_host.h"
#include "host_sim/scenario.h"
#include "host_sim/trace.h"
#include "host_sim/devices/ev3_brick.h"
#include "host_sim/devices/ev3_ui.h"
#include <linux_compat/config.h>
#include "ui_hack.h"

#define UIT_TASK_ID	1
#define UIT_HELPER_ID	2
#define UIT_STACK	(64 * 1024)
#define UIT_MS		1000000ULL
#define UIT_DEBOUNCE_MS	20	/* d_ui's default */

static void (*uit_body)(void);
static void (*uit_at_power_on)(void);	/* optional: runs after boot, before any task */
static void (*uit_helper_fn)(void);
static bool uit_done;
static ID uit_domain = TDOM_KERNEL;	/* the test task's protection domain */
static const struct lms_ui *uit_shm;

static void uit_task(intptr_t exinf)
{
	const struct lms_ui *shm;	/* on the task's stack: writable in any domain */

	(void)exinf;
	if (ui_svc_map(&shm) != E_OK) {
		tap_diag("ui_svc_map failed: d_ui is not up");
	} else {
		uit_shm = shm;
		uit_body();
	}
	uit_done = true;
}

static void uit_helper_task(intptr_t exinf)
{
	(void)exinf;
	if (uit_helper_fn)
		uit_helper_fn();
}

/* Boots the brick with seed, runs body in a task of uit_domain, shuts down. */
static inline bool uit_run(void (*body)(void), uint64_t seed)
{
	const struct rtos_task_cfg tasks[] = {
		{ UIT_TASK_ID, TA_ACT, 0, uit_task, 8, UIT_STACK, uit_domain, "ui_test" },
		{ UIT_HELPER_ID, TA_NULL, 0, uit_helper_task, 6, UIT_STACK, TDOM_KERNEL, "ui_helper" },
	};
	static const struct rtos_cfg *const includes[] = { &linux_compat_cfg, &ui_hack_cfg, NULL };
	const struct rtos_cfg cfg = {
		.name = "ui_test", .tasks = tasks, .ntasks = 2, .includes = includes,
	};
	static const struct hs_board_cfg board = { .devices = ev3_board_devices };
	struct hs_scenario scn = { .rtos = &cfg, .board = &board, .seed = seed };
	uint64_t limit;

	uit_body = body;
	uit_done = false;
	if (hs_sim_boot(&scn) != E_OK) {
		tap_diag("boot failed: %s", rtos_host_boot_error());
		return false;
	}
	if (uit_at_power_on)
		uit_at_power_on();
	for (limit = 0; !uit_done && limit < 600; limit++)
		hs_sim_run_for(100 * UIT_MS);
	hs_sim_shutdown();
	return uit_done;
}

/* Runs fn in the helper task (which must be dormant). */
static inline ER uit_start_helper(void (*fn)(void))
{
	uit_helper_fn = fn;
	return act_tsk(UIT_HELPER_ID);
}

static inline uint64_t uit_now_ms(void)
{
	return rtos_host_now() / UIT_MS;
}

static inline uint8_t uit_pressed(unsigned button)
{
	return *(volatile const uint8_t *)&uit_shm->pressed[button];
}

static inline uint32_t uit_u32(const uint32_t *p)
{
	return *(volatile const uint32_t *)p;
}

#endif /* EV3LX_TESTS_UI_TEST_H */
