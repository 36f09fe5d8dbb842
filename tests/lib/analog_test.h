/*
 * analog_test.h — running a d_analog test on the simulated EV3: boots the
 * board with every device model, linux_compat (whose worker task runs
 * d_analog's module_init, and its module_exit at shutdown) and analog_hack's
 * service calls, then runs the test body in a kernel-domain task that
 * attaches devices, lets virtual time pass with dly_tsk and checks what the
 * driver publishes.
 */
#ifndef EV3LX_TESTS_ANALOG_TEST_H
#define EV3LX_TESTS_ANALOG_TEST_H

#include "tap.h"
#include "kernel.h"
#include "rtos_host.h"
#include "host_sim/scenario.h"
#include "host_sim/devices/ev3_brick.h"
#include <linux_compat/config.h>
#include <linux/module.h>
#include "analog_hack.h"

#define ANALOG_TEST_TASK_ID	1
#define ANALOG_TEST_STACK	(64 * 1024)
#define MS			1000000ULL

static void (*analog_test_body)(void);
static FILE *analog_test_log;           /* register log destination, or NULL */
static const char *analog_test_log_filter;
static volatile bool analog_test_done;

static void analog_test_task(intptr_t exinf)
{
	(void)exinf;
	analog_test_body();
	analog_test_done = true;
}

/* Boots the brick (seed), runs body in a task of domain domid until it returns (at most
 * limit_ms of virtual time) and shuts down; true if the body finished. */
static inline bool analog_test_run_in(void (*body)(void), uint64_t seed, uint64_t limit_ms,
				      ID domid)
{
	const struct rtos_task_cfg task = {
		ANALOG_TEST_TASK_ID, TA_ACT, 0, analog_test_task, 8, ANALOG_TEST_STACK,
		domid, "analog_test",
	};
	static const struct rtos_cfg *const includes[] = {
		&linux_compat_cfg, &analog_hack_cfg, NULL,
	};
	const struct rtos_cfg cfg = {
		.name = "analog_test", .tasks = &task, .ntasks = 1, .includes = includes,
	};
	static struct hs_board_cfg board;
	struct hs_scenario scn = {
		.rtos = &cfg, .board = &board, .seed = seed,
		.reglog_filter = analog_test_log_filter, .reglog = analog_test_log,
	};
	ER ercd;

	board.devices = ev3_board_devices;
	analog_test_body = body;
	analog_test_done = false;
	ercd = hs_sim_boot(&scn);
	if (ercd != E_OK) {
		tap_diag("boot failed: %d", ercd);
		return false;
	}
	while (!analog_test_done && rtos_host_now() < limit_ms * MS)
		hs_sim_run_for(10 * MS);
	hs_sim_shutdown();
	return analog_test_done;
}

/* analog_test_run_in for a kernel-domain task. */
static inline bool analog_test_run(void (*body)(void), uint64_t seed, uint64_t limit_ms)
{
	return analog_test_run_in(body, seed, limit_ms, TDOM_KERNEL);
}

/* Logs register accesses of the peripherals in filter (e.g. "SPI0") to out in the next run. */
static inline void analog_test_reglog(FILE *out, const char *filter)
{
	analog_test_log = out;
	analog_test_log_filter = filter;
}

/* Virtual time in ms (any context). */
static inline double now_ms(void)
{
	return (double)rtos_host_now() / (double)MS;
}

/* The driver's ANALOG area (the task is in the kernel domain). */
static inline const volatile struct lms_analog *analog_shm(void)
{
	const struct lms_analog *shm = NULL;

	ER ercd = analog_map(&shm);

	if (ercd != E_OK)
		tap_diag("analog_map failed: %d", ercd);

	return shm;
}

/* Waits in 1 ms steps until input port's InConn is conn (or timeout_ms passes);
 * returns the virtual time in ms at which it was seen, or -1. */
static inline double wait_in_conn(unsigned port, int conn, unsigned timeout_ms)
{
	const volatile struct lms_analog *shm = analog_shm();
	unsigned i;

	for (i = 0; i <= timeout_ms; i++) {
		if (shm->in_conn[port] == conn)
			return now_ms();
		dly_tsk(1);
	}
	return -1;
}

/* The same for output port's OutConn. */
static inline double wait_out_conn(unsigned port, int conn, unsigned timeout_ms)
{
	const volatile struct lms_analog *shm = analog_shm();
	unsigned i;

	for (i = 0; i <= timeout_ms; i++) {
		if (shm->out_conn[port] == conn)
			return now_ms();
		dly_tsk(1);
	}
	return -1;
}

#endif /* EV3LX_TESTS_ANALOG_TEST_H */
