/*
 * uart_test.h — d_uart on the simulated brick: boots host_sim's EV3 with
 * linux_compat, d_uart (through uart_hack) and one test task that runs the
 * test body in process context, and gives the body small helpers to plug
 * sensors in, wait in virtual time and look at the driver's shared memory.
 */
#ifndef EV3LX_TESTS_UART_TEST_H
#define EV3LX_TESTS_UART_TEST_H

#include "tap.h"
#include "rtos_host.h"
#include "host_sim/scenario.h"
#include "host_sim/devices/ev3_brick.h"
#include "host_sim/devices/uart16550.h"
#include <linux_compat/config.h>
#include "uart_hack.h"

#define UT_TASK_ID	1
#define UT_STACK	(64 * 1024)
#define UT_MS		1000000ULL

static void (*ut_body)(void);
static bool ut_done;
static ID ut_domain = TDOM_KERNEL;	/* the test task's protection domain */
static const struct lms_uart_shm *ut_shm;

static void ut_task(intptr_t exinf)
{
	const struct lms_uart_shm *shm;	/* on the task's stack: writable in any domain */

	(void)exinf;
	if (uart_svc_map(&shm) != E_OK) {
		tap_diag("uart_svc_map failed: d_uart is not up");
	} else {
		ut_shm = shm;
		ut_body();
	}
	ut_done = true;
}

/* Boots the brick with seed and reglog filter (may be NULL), runs body in a task of
 * ut_domain, shuts down. */
static inline bool ut_run(void (*body)(void), uint64_t seed, const char *reglog)
{
	const struct rtos_task_cfg task = {
		UT_TASK_ID, TA_ACT, 0, ut_task, 8, UT_STACK, ut_domain, "uart_test",
	};
	static const struct rtos_cfg *const includes[] = { &linux_compat_cfg, &uart_hack_cfg, NULL };
	const struct rtos_cfg cfg = {
		.name = "uart_test", .tasks = &task, .ntasks = 1, .includes = includes,
	};
	static const struct hs_board_cfg board = { .devices = ev3_board_devices };
	struct hs_scenario scn = { .rtos = &cfg, .board = &board, .seed = seed,
				   .reglog_filter = reglog };
	uint64_t limit;

	ut_body = body;
	ut_done = false;
	if (hs_sim_boot(&scn) != E_OK) {
		tap_diag("boot failed: %s", rtos_host_boot_error());
		return false;
	}
	for (limit = 0; !ut_done && limit < 600; limit++)
		hs_sim_run_for(100 * UT_MS);
	hs_sim_shutdown();
	return ut_done;
}

static inline const struct lms_uart_port_ext *ut_ext(unsigned port)
{
	return &ut_shm->ext.port[port];
}

static inline int8_t ut_status(unsigned port)
{
	return *(volatile const int8_t *)&ut_shm->lms.status[port];
}

/* Waits (1 ms steps) until the port reaches state, at most ms; true if it did. */
static inline bool ut_wait_state(unsigned port, uint8_t state, unsigned ms)
{
	while (*(volatile const uint8_t *)&ut_ext(port)->state != state) {
		if (!ms--)
			return false;
		dly_tsk(1);
	}
	return true;
}

/* Waits until a valid sample of mode is there, at most ms; the sample or NULL. */
static inline const int8_t *ut_wait_sample(unsigned port, int mode, unsigned ms)
{
	const int8_t *s;

	while (!(s = lms_uart_sample(ut_shm, port, mode))) {
		if (!ms--)
			return NULL;
		dly_tsk(1);
	}
	return s;
}

/* Starts port in mode, waits for DATA and accepts the description; true on success. */
static inline bool ut_start(unsigned port, unsigned mode, unsigned ms)
{
	if (uart_svc_set_mode(port, mode) != E_OK || !ut_wait_state(port, LMS_UART_STATE_DATA, ms))
		return false;
	return uart_svc_clear_changed(port) == E_OK;
}

static inline int16_t ut_s16(const int8_t *sample, unsigned i)
{
	return (int16_t)((uint8_t)sample[2 * i] | (uint8_t)sample[2 * i + 1] << 8);
}

static inline uint32_t ut_float_bits(float f)
{
	uint32_t u;

	memcpy(&u, &f, sizeof(u));
	return u;
}

#endif /* EV3LX_TESTS_UART_TEST_H */
