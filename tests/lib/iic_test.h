/*
 * iic_test.h — d_iic on the simulated brick: boots host_sim's EV3 with
 * linux_compat, d_analog and d_iic (through their hacks) and one test task
 * that runs the test body, and gives the body helpers to wait for port
 * states and samples in virtual time.
 */
#ifndef EV3LX_TESTS_IIC_TEST_H
#define EV3LX_TESTS_IIC_TEST_H

#include <string.h>
#include "tap.h"
#include "rtos_host.h"
#include "host_sim/scenario.h"
#include "host_sim/devices/ev3_brick.h"
#include "host_sim/devices/nxt_iic.h"
#include <linux_compat/config.h>
#include "analog_hack.h"
#include "iic_hack.h"

#define IT_TASK_ID	1
#define IT_STACK	(64 * 1024)
#define IT_MS		1000000ULL

static void (*it_body)(void);
static bool it_done;
static const struct lms_iic *it_shm;
static const struct lms_analog *it_analog;
static ID it_domain = TDOM_KERNEL;	/* the test task's protection domain */

static void it_task(intptr_t exinf)
{
	const struct lms_iic *shm;
	const struct lms_analog *analog;

	(void)exinf;
	if (iic_svc_map(&shm) != E_OK || analog_map(&analog) != E_OK) {
		tap_diag("iic_svc_map/analog_map failed: a driver is not up");
	} else {
		it_shm = shm;
		it_analog = analog;
		it_body();
	}
	it_done = true;
}

/* Boots the brick with seed, runs body in a task of it_domain, shuts down. */
static inline bool it_run(void (*body)(void), uint64_t seed)
{
	const struct rtos_task_cfg task = {
		IT_TASK_ID, TA_ACT, 0, it_task, 8, IT_STACK, it_domain, "iic_test",
	};
	static const struct rtos_cfg *const includes[] = {
		&linux_compat_cfg, &analog_hack_cfg, &iic_hack_cfg, NULL,
	};
	const struct rtos_cfg cfg = {
		.name = "iic_test", .tasks = &task, .ntasks = 1, .includes = includes,
	};
	static const struct hs_board_cfg board = { .devices = ev3_board_devices };
	struct hs_scenario scn = { .rtos = &cfg, .board = &board, .seed = seed };
	uint64_t limit;

	it_body = body;
	it_done = false;
	if (hs_sim_boot(&scn) != E_OK) {
		tap_diag("boot failed: %s", rtos_host_boot_error());
		return false;
	}
	for (limit = 0; !it_done && limit < 600; limit++)
		hs_sim_run_for(100 * IT_MS);
	hs_sim_shutdown();
	return it_done;
}

/* Waits (1 ms steps) until the port's state is state, at most ms; true if it was. */
static inline bool it_wait_state(unsigned port, unsigned state, unsigned ms)
{
	while (iic_svc_state(port) != (ER_UINT)state) {
		if (!ms--)
			return false;
		dly_tsk(1);
	}
	return true;
}

/* Waits until d_analog reports conn on the input port, at most ms. */
static inline bool it_wait_conn(unsigned port, int conn, unsigned ms)
{
	while (*(const volatile int8_t *)&it_analog->in_conn[port] != conn) {
		if (!ms--)
			return false;
		dly_tsk(1);
	}
	return true;
}

/* Waits until a polled sample is there, at most ms. */
static inline const int8_t *it_wait_sample(unsigned port, unsigned ms)
{
	const int8_t *s;

	while (!(s = lms_iic_sample(it_shm, port))) {
		if (!ms--)
			return NULL;
		dly_tsk(1);
	}
	return s;
}

/* An IICSTR for port with an MSB-first poll string of lng bytes. */
static inline struct lms_iic_str it_poll(unsigned port, uint32_t setup, int setup_lng, uint32_t poll,
					 int poll_lng, int read_lng, int time_ms)
{
	struct lms_iic_str s;

	memset(&s, 0, sizeof(s));
	s.port = (int8_t)port;
	s.time = (int16_t)time_ms;
	s.setup_string = setup;
	s.setup_lng = (int8_t)setup_lng;
	s.poll_string = poll;
	s.poll_lng = (int8_t)poll_lng;
	s.read_lng = (int8_t)read_lng;
	return s;
}

/* Runs one IIC_SETUP transaction to completion (at most ms); the final result code. */
static inline int it_setup(struct lms_iic_dat *d, unsigned ms)
{
	do {
		if (iic_svc_setup(d) != E_OK)
			return -1;
		if (d->result != LMS_IIC_BUSY)
			return d->result;
		dly_tsk(1);
	} while (ms--);
	return LMS_IIC_BUSY;
}

#endif /* EV3LX_TESTS_IIC_TEST_H */
