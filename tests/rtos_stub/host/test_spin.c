/*
 * test_spin.c — rtos_host_spin_until against rtos_host_consume: a
 * low-priority task busy-waits while a higher-priority task preempts it.
 * Spinning to an absolute time counts the preemption toward it (the poll
 * finds the time passed when it resumes, and never spins past it); consuming
 * the same CPU time ends later by the preemption.  The spun CPU time is what
 * the spinner itself ran.
 */
#include "tap.h"
#include "kernel.h"
#include "rtos_test.h"

#define US 1000ULL

static uint64_t spin_end, spin_cpu, late_end, late_cpu, consume_end, past_cpu;

/* Low priority: three busy waits, each preempted by the high task. */
static void spinner(intptr_t x)
{
	spin_cpu = rtos_host_spin_until(1000 * US);     /* preempted 200..500 us */
	spin_end = rtos_host_now();
	late_cpu = rtos_host_spin_until(2100 * US);     /* preempted 2000..2300 us: past it */
	late_end = rtos_host_now();
	rtos_host_consume(1000 * US);                   /* 2300..3300, preempted 3000..3300 us */
	consume_end = rtos_host_now();
	past_cpu = rtos_host_spin_until(consume_end - 1);
	ext_tsk();
}

/* Sleeps until virtual time t, a multiple of the 200 us tick (dly_tsk(0) waits for the next tick). */
static void sleep_until(uint64_t t)
{
	while (rtos_host_now() < t)
		dly_tsk(0);
}

/* High priority: three bursts of 300 us of CPU. */
static void preempter(intptr_t x)
{
	static const uint64_t at[] = { 200 * US, 2000 * US, 3000 * US };

	for (unsigned i = 0; i < 3; i++) {
		sleep_until(at[i]);
		rtos_host_consume(300 * US);
	}
	ext_tsk();
}

static const struct rtos_task_cfg tasks[] = {
	{ 1, TA_ACT, 0, spinner, 10, 4096, TDOM_KERNEL, "spinner" },
	{ 2, TA_ACT, 0, preempter, 5, 4096, TDOM_KERNEL, "preempter" },
};
static const struct rtos_cfg cfg = { .name = "spin", .tasks = RTOS_TABLE(tasks) };

int main(void)
{
	tap_plan(7);
	is_int(rtos_host_boot(&cfg), E_OK, "boot");
	rtos_host_run_for(10000 * US);
	ok(spin_end == 1000 * US, "spin_until 1000 us preempted for 300 us ends at 1000 us (%llu)",
	   (unsigned long long)spin_end);
	ok(spin_cpu == 700 * US, "and spun 700 us of its own CPU time (%llu)", (unsigned long long)spin_cpu);
	ok(late_end == 2300 * US, "preempted past its time, it returns when it resumes (%llu)",
	   (unsigned long long)late_end);
	ok(late_cpu == 1000 * US, "having spun only until the preemption (%llu)",
	   (unsigned long long)late_cpu);
	ok(consume_end == 3600 * US, "consume of 1000 us from 2300 us ends 300 us late: 3600 us (%llu)",
	   (unsigned long long)consume_end);
	is_int((int)past_cpu, 0, "spin_until a time that has passed spins for nothing");
	rtos_host_shutdown();
	return tap_done();
}
