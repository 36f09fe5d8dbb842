/*
 * brick_test.h — a linux_compat test body on the whole simulated EV3:
 * host_sim's board with its devices (the ADC, the buttons, the PWM and eCAP
 * outputs...), linux_compat_cfg, and one kernel-domain task running the
 * body in process context, as lx_test.h does without the board.  The two
 * assertions it makes (the boot, the body's end) count in the test's plan.
 */
#ifndef EV3LX_TESTS_BRICK_TEST_H
#define EV3LX_TESTS_BRICK_TEST_H

#include "lx_test.h"
#include "host_sim/scenario.h"
#include "host_sim/devices/ev3_brick.h"

/* Boots the brick (asserting it: what names what is simulated), runs body
 * to its end or LX_TEST_MAX_NS of virtual time (asserted), shuts down. */
static inline void lx_test_on_brick(void (*body)(void), const char *what)
{
	static const struct rtos_task_cfg task = {
		LX_TEST_TASK_ID, TA_ACT, 0, lx_test_task, 8, LX_TEST_STACK, TDOM_KERNEL, "lx_test",
	};
	static const struct rtos_cfg *const includes[] = { &linux_compat_cfg, NULL };
	static const struct rtos_cfg cfg = { .name = "lx_test", .tasks = &task, .ntasks = 1,
					     .includes = includes };
	static const struct hs_board_cfg board = { .devices = ev3_board_devices };
	const struct hs_scenario scn = { .rtos = &cfg, .board = &board, .seed = 1 };

	lx_test_body = body;
	lx_test_body_done = false;
	is_int(hs_sim_boot(&scn), E_OK, "%s", what);
	while (!lx_test_body_done && hs_now() < LX_TEST_MAX_NS)
		hs_sim_run_for(1000 * 1000);
	ok(lx_test_body_done, "test task ran to completion");
	hs_sim_shutdown();
}

#endif /* EV3LX_TESTS_BRICK_TEST_H */
