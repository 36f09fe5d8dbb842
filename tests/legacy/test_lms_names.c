/*
 * test_lms_names.c — lms_names, a module whose enumerators and types are the
 * RTOS's own names (TRUE, FALSE, ID, ER, MODE, STAT, SIZE, BOOL, ...), built
 * -nostdinc as kbuild builds it, linked with its private namespace beside the
 * other conformance modules, loads and works: its device's commands run its
 * state machine and report its own result codes.
 */
#include "tap.h"
#include "rtos_host.h"
#include "host_sim/board.h"
#include "host_sim/scenario.h"
#include "host_sim/devices/ev3_brick.h"
#include <linux_compat/config.h>

#include "lms_names_hack.h"

#define MS 1000000ULL

/* The module's own values (tests/legacy/drivers/lms_names.c). */
#define NAMES_TTS_RUN   31
#define NAMES_TTS_DMT   32
#define NAMES_E_PAR     17

static volatile bool done;

static void test_task(intptr_t exinf)
{
	unsigned char reply[3] = { 0, 0, 0 };

	(void)exinf;
	is_int(lms_names_load(), 0, "lms_names' init registers /dev/lms_names");
	is_int(lms_names_command(2, reply), 0, "a command through its device file");
	is_int(reply[0], NAMES_TTS_RUN, "its state is its own TTS_RUN enumerator (%d)", NAMES_TTS_RUN);
	is_int(reply[1], 0, "its result is its own E_OK");
	is_int(reply[2], 1, "one command counted (its get_tim() of its own)");
	is_int(lms_names_command(9, reply), 0, "a bad mode is still a command");
	is_int(reply[1], NAMES_E_PAR, "its result is its own E_PAR (17)");
	is_int(reply[0], NAMES_TTS_RUN, "and the state is unchanged");
	is_int(lms_names_command(0, reply), 0, "mode 0");
	is_int(reply[0], NAMES_TTS_DMT, "its state is its own TTS_DMT");
	lms_names_unload();
	ok(lms_names_command(1, reply) < 0, "after unload its device is gone");
	done = true;
}

int main(void)
{
	const struct rtos_task_cfg tasks[] = {
		{ 1, TA_ACT, 0, test_task, 8, 64 * 1024, TDOM_KERNEL, "lms_names_test" },
	};
	static const struct rtos_cfg *const includes[] = { &linux_compat_cfg, NULL };
	const struct rtos_cfg cfg = { .name = "lms_names", .tasks = tasks, .ntasks = 1, .includes = includes };
	static const struct hs_board_cfg board = { .devices = ev3_board_devices };
	struct hs_scenario scn = { .rtos = &cfg, .board = &board, .seed = 1 };

	tap_plan(12);
	if (hs_sim_boot(&scn) != E_OK)
		tap_bail_out(rtos_host_boot_error());
	for (int i = 0; i < 100 && !done; i++)
		hs_sim_run_for(10 * MS);
	ok(done, "the test body ran to its end");
	hs_sim_shutdown();
	return tap_done();
}
