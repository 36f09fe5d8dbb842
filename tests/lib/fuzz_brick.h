/*
 * fuzz_brick.h — the simulated brick for fuzz harnesses (docs/reliability.md).
 *
 * The brick boots once per process with linux_compat and the EV3 drivers
 * (ev3_drivers_cfg) and one kernel-domain worker task.  Each input is handed
 * to the worker, which runs the harness's work function on it in task
 * context (service calls, blocking driver calls), while fz_run drives
 * virtual time; or the harness injects bytes from the hardware's side and
 * lets time run.  After every input the stack must not have reported a bug
 * (a sleeping call in atomic context, a lock misuse, a bad service call):
 * any report aborts, which the fuzzer and the replay test see as a crash.
 *
 * The same harness file builds two ways: with EV3LX_LIBFUZZER (mk/fuzz.mk,
 * clang's libFuzzer supplies main) and as a TAP test that replays the
 * committed corpus in every test configuration (fuzz_replay.h).
 */
#ifndef EV3LX_TESTS_FUZZ_BRICK_H
#define EV3LX_TESTS_FUZZ_BRICK_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include "rtos_host.h"
#include "host_sim/scenario.h"
#include "host_sim/devices/ev3_brick.h"
#include "ev3_drivers_cfg.h"

#define FZ_TASK_ID	1
#define FZ_STACK	(64 * 1024)
#define FZ_MS		1000000ULL
#ifndef FZ_WORK_LIMIT_MS
#define FZ_WORK_LIMIT_MS 2000	/* a work item that takes longer is a hang */
#endif

typedef void (*fz_work_fn)(const uint8_t *data, size_t size);

static struct {
	bool booted;
	unsigned bugs;		/* bug reports before the current input */
	fz_work_fn work;
	const uint8_t *data;
	size_t size;
	volatile bool pending;
	void (*at_boot)(void);	/* run once by the worker task after the boot */
	volatile bool ready;
} fz;

static void fz_task(intptr_t exinf)
{
	(void)exinf;
	if (fz.at_boot)
		fz.at_boot();
	fz.ready = true;
	for (;;) {
		while (!fz.pending)
			dly_tsk(1);
		fz.work(fz.data, fz.size);
		fz.pending = false;
	}
}

/* Aborts if the stack reported a bug since the last check (names the input's size). */
static inline void fz_check(const char *what, size_t size)
{
	if (rtos_host_bug_count() != fz.bugs) {
		fprintf(stderr, "fuzz: %s: the stack reported a bug on a %zu-byte input\n", what, size);
		abort();
	}
}

/* Boots the brick at the first call, with the configurations includes (NULL
 * ended) and the worker in protection domain domid; at_boot (may be NULL)
 * runs in the worker task once. */
static inline void fz_boot_with(const struct rtos_cfg *const *includes, ID domid, void (*at_boot)(void))
{
	static struct rtos_task_cfg task = {
		FZ_TASK_ID, TA_ACT, 0, fz_task, 8, FZ_STACK, TDOM_KERNEL, "fuzz",
	};
	static struct rtos_cfg cfg = { .name = "fuzz", .tasks = &task, .ntasks = 1 };
	static const struct hs_board_cfg board = { .devices = ev3_board_devices };
	struct hs_scenario scn = { .rtos = &cfg, .board = &board, .seed = 1 };

	if (fz.booted)
		return;
	task.domid = domid;
	cfg.includes = includes;
	fz.at_boot = at_boot;
	if (hs_sim_boot(&scn) != E_OK) {
		fprintf(stderr, "fuzz: boot failed: %s\n", rtos_host_boot_error());
		abort();
	}
	for (unsigned ms = 0; !fz.ready && ms < 10000; ms++)
		hs_sim_run_for(FZ_MS);
	if (!fz.ready) {
		fprintf(stderr, "fuzz: the worker did not start\n");
		abort();
	}
	fz.booted = true;
	fz.bugs = rtos_host_bug_count();
}

/* Boots the brick with linux_compat and the drivers, the worker in the kernel domain. */
static inline void fz_boot(void (*at_boot)(void))
{
	static const struct rtos_cfg *const includes[] = { &ev3_drivers_cfg, NULL };

	fz_boot_with(includes, TDOM_KERNEL, at_boot);
}

/* Runs work(data, size) in the worker task; aborts on a hang or a bug report. */
static inline void fz_run(fz_work_fn work, const uint8_t *data, size_t size)
{
	unsigned ms;

	fz.work = work;
	fz.data = data;
	fz.size = size;
	fz.pending = true;
	for (ms = 0; fz.pending && ms < FZ_WORK_LIMIT_MS; ms++)
		hs_sim_run_for(FZ_MS);
	if (fz.pending) {
		fprintf(stderr, "fuzz: a %zu-byte input hung the worker\n", size);
		abort();
	}
	fz_check("work", size);
}

/* Lets virtual time run, then checks for bug reports. */
static inline void fz_settle(unsigned ms, size_t size)
{
	hs_sim_run_for(ms * FZ_MS);
	fz_check("settle", size);
}

/* Ends the process's brick (the replay test; libFuzzer just exits). */
static inline void fz_shutdown(void)
{
	if (fz.booted)
		hs_sim_shutdown();
	fz.booted = false;
}

#endif /* EV3LX_TESTS_FUZZ_BRICK_H */
