/*
 * test_poll_deadline.c — a task that does nothing but poll a device register
 * (each access costs virtual time, as host_sim charges it) still stops where
 * rtos_host_run_for ends, and goes on polling in the next run.
 */
#include "tap.h"
#include "rtos_test.h"
#include "kernel.h"
#include "sil.h"

#define ACCESS_NS 50U

static uint32_t device_register;   /* claimed by the fake device below */
static uint64_t polls;

static bool claims(const volatile void *addr, void *ctx)
{
	(void)ctx;
	return addr == &device_register;
}

/* A status read that never becomes ready, costing bus time like a real access. */
static uint32_t read_status(const volatile void *addr, uint_t width, void *ctx)
{
	(void)addr; (void)width; (void)ctx;
	rtos_host_consume(ACCESS_NS);
	polls++;
	return 0;
}

static void write_ignored(volatile void *addr, uint_t width, uint32_t data, void *ctx)
{
	(void)addr; (void)width; (void)data; (void)ctx;
}

static const struct rtos_host_mmio_ops fake_device = {
	.claims = claims, .read = read_status, .write = write_ignored, .map = NULL, .ctx = NULL,
};

static void poller(intptr_t exinf)
{
	(void)exinf;
	while ((sil_rew_mem(&device_register) & 1U) == 0)
		;
}

static const struct rtos_task_cfg tasks[] = { RT_TASK(1, poller, 5, true) };
static const struct rtos_cfg cfg = { .name = "poll", .tasks = tasks, .ntasks = 1 };

int main(void)
{
	uint64_t first;

	tap_plan(5);
	rtos_host_set_mmio_handler(&fake_device);
	is_int(rtos_host_boot(&cfg), E_OK, "boot");
	rtos_host_run_for(1000000);
	in_range(rtos_host_now(), 1000000, 1000000 + ACCESS_NS, "run_for(1 ms) returned at its deadline");
	first = polls;
	in_range(first, 1000000 / ACCESS_NS - 1, 1000000 / ACCESS_NS + 1, "the task polled all along (%llu)",
		 (unsigned long long)first);
	rtos_host_run_for(1000000);
	ok(polls > first, "and goes on polling in the next run");
	in_range(rtos_host_now(), 2000000, 2000000 + ACCESS_NS, "which also ends at its deadline");
	rtos_host_shutdown();
	rtos_host_set_mmio_handler(NULL);
	return tap_done();
}
