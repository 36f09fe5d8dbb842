/*
 * test_spin_quiet.c — rtos_host_spin_until with nothing due before its time
 * (no event, no interrupt, no task to switch to) takes a short cut; at its
 * edges it must end exactly as the busy loop does: a spin ending at the run's
 * deadline is not paused, one that crosses it is; an event due exactly at the
 * spin's time runs inside it; a task woken under dis_dsp waits through the
 * spin; a device event (not task level) spins too.
 */
#include "tap.h"
#include "kernel.h"
#include "rtos_test.h"

#define US 1000ULL

static uint64_t quiet_spun, at_deadline, past_spun, past_end, event_ran_at, event_spin_end, high_start;
static uint64_t in_event_spun, in_event_end;

static void mark_event(void *arg)
{
	event_ran_at = rtos_host_now();
}

/* A device event that spins 30 us (not at task level: nothing to deliver or switch to). */
static void spinning_event(void *arg)
{
	in_event_spun = rtos_host_spin_until(rtos_host_now() + 30 * US);
	in_event_end = rtos_host_now();
}

static void low_task(intptr_t x)
{
	quiet_spun = rtos_host_spin_until(40 * US);
	at_deadline = rtos_host_spin_until(100 * US);
	past_spun = rtos_host_spin_until(110 * US);
	past_end = rtos_host_now();

	rtos_host_event_at(120 * US, mark_event, NULL);
	(void)rtos_host_spin_until(120 * US);
	event_spin_end = rtos_host_now();

	dis_dsp();
	wup_tsk(2);
	(void)rtos_host_spin_until(125 * US);
	ena_dsp();

	rtos_host_event_at(150 * US, spinning_event, NULL);
	slp_tsk();
}

static void high_task(intptr_t x)
{
	slp_tsk();
	high_start = rtos_host_now();
	slp_tsk();
}

static const struct rtos_task_cfg tasks[] = {
	{ 1, TA_ACT, 0, low_task, 8, 1024, TDOM_KERNEL, "low" },
	{ 2, TA_ACT, 0, high_task, 2, 1024, TDOM_KERNEL, "high" },
};
static const struct rtos_cfg cfg = { .name = "spin_quiet", .tasks = RTOS_TABLE(tasks) };

int main(void)
{
	tap_plan(10);
	is_int(rtos_host_boot(&cfg), E_OK, "boot");
	rtos_host_run_for(100 * US);
	is_u64(quiet_spun, 40 * US, "a quiet spin from 0 to 40 us spins 40 us");
	is_u64(at_deadline, 60 * US, "a spin that ends at the run's deadline is not paused there");
	is_u64(past_end, 0, "the next spin crosses the deadline: the task is paused in it");
	rtos_host_run_for(100 * US);
	ok(past_spun == 10 * US && past_end == 110 * US, "resumed, it spins on to its time (%llu at %llu)",
	   (unsigned long long)past_spun, (unsigned long long)past_end);
	ok(event_ran_at == 120 * US && event_spin_end == 120 * US,
	   "an event due at the spin's time runs inside it (at %llu, spin ended %llu)",
	   (unsigned long long)event_ran_at, (unsigned long long)event_spin_end);
	is_u64(high_start, 125 * US, "a task woken under dis_dsp runs at ena_dsp, after the spin");
	is_u64(rtos_host_now(), 200 * US, "the run ends at its deadline");
	ok(in_event_spun == 30 * US && in_event_end == 180 * US,
	   "a device event spins 30 us from 150 us (spun %llu, ended %llu)",
	   (unsigned long long)in_event_spun, (unsigned long long)in_event_end);
	is_u64(rtos_host_spin_until(190 * US), 0, "from the harness, a time that has passed spins for nothing");
	rtos_host_shutdown();
	return tap_done();
}
