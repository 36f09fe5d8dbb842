/*
 * api_test.h — the EV3 API on the simulated brick: boots host_sim's EV3 with
 * ev3api_cfg (linux_compat, the three drivers through their hacks) and one
 * application task in user domain 1 that runs the test body, as a real
 * application would.  The body's out-parameters live on its stack, which its
 * domain may write; globals of the test are outside the domain (E_MACV).
 */
#ifndef EV3LX_TESTS_API_TEST_H
#define EV3LX_TESTS_API_TEST_H

#include "tap.h"
#include "rtos_host.h"
#include "ev3api_motor.h"
#include "ev3api_sensor.h"
#include "ev3api_brick.h"
#include "ev3api_cyc.h"
#include "ev3api_fs.h"
#include "ev3api_lcd.h"
#include "ev3api_speaker.h"
#include "ev3api_battery.h"
#include "ev3api_cfg.h"
#include "host_sim/scenario.h"
#include "host_sim/devices/ev3_brick.h"

#define AT_TASK_ID   1
#define AT_DOMAIN    1
#define AT_STACK     (64 * 1024)
#define AT_MS        1000000ULL

static void (*at_body)(void);
static bool at_done;
static const struct rtos_cfg *at_includes[3] = { &ev3api_cfg, NULL, NULL };

/* A configuration the next at_run includes besides the API's (a platform
 * service, e.g. ev3sim's SD card and serial port). */
static inline void at_include(const struct rtos_cfg *extra)
{
	at_includes[1] = extra;
}

static void at_task(intptr_t exinf)
{
	(void)exinf;
	at_body();
	at_done = true;
}

/* Attaches devices (at boot, as plugged in at power-on), runs body in the
 * application task, and shuts down; false if the body did not finish within
 * max_s virtual seconds. */
static inline bool at_run(void (*attach)(void), void (*body)(void), uint64_t seed, unsigned max_s)
{
	static const struct rtos_task_cfg task = {
		AT_TASK_ID, TA_ACT, 0, at_task, 8, AT_STACK, AT_DOMAIN, "app",
	};
	static const struct rtos_cfg cfg = {
		.name = "api_test", .tasks = &task, .ntasks = 1, .includes = at_includes,
	};
	static const struct hs_board_cfg board = { .devices = ev3_board_devices };
	struct hs_scenario scn = { .rtos = &cfg, .board = &board, .seed = seed };

	at_body = body;
	at_done = false;
	if (hs_sim_boot(&scn) != E_OK) {
		tap_diag("boot failed: %s", rtos_host_boot_error());
		return false;
	}
	if (attach)
		attach();
	for (unsigned i = 0; !at_done && i < max_s * 10U; i++)
		hs_sim_run_for(100 * AT_MS);
	hs_sim_shutdown();
	return at_done;
}

/* Virtual time in ms, for assertions in the body. */
static inline uint64_t at_now_ms(void)
{
	return rtos_host_now() / AT_MS;
}

#endif /* EV3LX_TESTS_API_TEST_H */
