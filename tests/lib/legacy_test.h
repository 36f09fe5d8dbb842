/*
 * legacy_test.h — running a 2.6-era conformance module's test on the
 * simulated EV3: the EV3 boots with linux_compat, the boot loader's part is
 * done (power_on: PSC power, pin mux, as on the brick before Linux starts),
 * and then the body runs in a kernel-domain task, as a module's init would,
 * for at most a second of virtual time (or the test's run_ms).
 */
#ifndef EV3LX_TESTS_LEGACY_TEST_H
#define EV3LX_TESTS_LEGACY_TEST_H

#include <stdbool.h>
#include <stdio.h>
#include "tap.h"
#include "rtos_host.h"
#include "host_sim/board.h"
#include "host_sim/scenario.h"
#include "host_sim/devices/ev3_brick.h"
#include <linux_compat/config.h>

#define LT_MS 1000000ULL

/* What lt_run runs. */
struct lt_test {
	const char *name;           /* the configuration's and the task's name */
	void (*power_on)(void);     /* the boot loader's part, NULL: none */
	void (*body)(void);         /* the test body, in a kernel-domain task */
	unsigned after_boot;        /* the tests left once booted, for the skip */
	bool plain_pointers;        /* the module uses plain pointers: skipped where the board cannot trap them */
	unsigned run_ms;            /* virtual time the body may take (0: 1000 ms) */
};

static const struct lt_test *lt_current;
static volatile bool lt_started, lt_done;

static void lt_task(intptr_t exinf)
{
	(void)exinf;
	while (!lt_started)
		dly_tsk(1);
	lt_current->body();
	lt_done = true;
}

/* Boots, powers on and runs the body: true, with lt_done telling whether
 * the body ran to its end; false, with after_boot tests skipped (the reason
 * given), where the board cannot trap the module's plain pointers. */
static inline bool lt_run(const struct lt_test *t)
{
	const struct rtos_task_cfg tasks[] = {
		{ 1, TA_ACT, 0, lt_task, 8, 64 * 1024, TDOM_KERNEL, t->name },
	};
	static const struct rtos_cfg *const includes[] = { &linux_compat_cfg, NULL };
	const struct rtos_cfg cfg = { .name = t->name, .tasks = tasks, .ntasks = 1, .includes = includes };
	static const struct hs_board_cfg board = { .devices = ev3_board_devices };
	struct hs_scenario scn = { .rtos = &cfg, .board = &board, .seed = 1 };

	lt_current = t;
	if (hs_sim_boot(&scn) != E_OK)
		tap_bail_out(rtos_host_boot_error());
	if (t->plain_pointers && !hs_board_traps_pointers()) {
		char why[200];

		snprintf(why, sizeof(why), "%s", hs_board_trap_unavailable_reason());
		hs_sim_shutdown();
		tap_skip(t->after_boot, why);
		return false;
	}
	if (t->power_on != NULL)
		t->power_on();
	lt_started = true;
	for (unsigned i = 0; i < (t->run_ms ? t->run_ms : 1000U) / 10U && !lt_done; i++)
		hs_sim_run_for(10 * LT_MS);
	hs_sim_shutdown();
	return true;
}

#endif /* EV3LX_TESTS_LEGACY_TEST_H */
