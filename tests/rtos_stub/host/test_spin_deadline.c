/*
 * test_spin_deadline.c — a task's spin across runs of the harness: events due
 * before the run's deadline and one due exactly at it run inside the spin
 * before the task is paused there; one due after it runs in the next run; the
 * spin spins its whole time, across the pauses.  A device event's spin (not
 * at task level) is never paused: it runs past the deadline, and the events
 * due meanwhile run inside it.
 */
#include "tap.h"
#include "kernel.h"
#include "rtos_test.h"

#define US 1000ULL

static uint64_t mark_at[4];
static uint64_t spun, spin_end, in_event_spun, in_event_end;

/* Records when it ran in mark_at[index]. */
static void mark(void *arg)
{
	mark_at[(uintptr_t)arg] = rtos_host_now();
}

/* A device event that spins 100 us across the run's deadline at 400 us. */
static void spinning_event(void *arg)
{
	in_event_spun = rtos_host_spin_until(rtos_host_now() + 100 * US);
	in_event_end = rtos_host_now();
}

static void spinner(intptr_t x)
{
	rtos_host_event_at(50 * US, mark, (void *)0);
	rtos_host_event_at(100 * US, mark, (void *)1);
	rtos_host_event_at(150 * US, mark, (void *)2);
	spun = rtos_host_spin_until(300 * US);
	spin_end = rtos_host_now();

	rtos_host_event_at(350 * US, spinning_event, NULL);
	rtos_host_event_at(420 * US, mark, (void *)3);
	slp_tsk();
}

static const struct rtos_task_cfg tasks[] = {
	{ 1, TA_ACT, 0, spinner, 8, 1024, TDOM_KERNEL, "spinner" },
};
static const struct rtos_cfg cfg = { .name = "spin_deadline", .tasks = RTOS_TABLE(tasks) };

int main(void)
{
	tap_plan(8);
	is_int(rtos_host_boot(&cfg), E_OK, "boot");
	rtos_host_run_for(100 * US);
	is_u64(mark_at[0], 50 * US, "an event before the run's deadline runs inside the spin");
	is_u64(mark_at[1], 100 * US, "an event due at the deadline runs before the spin is paused there");
	ok(mark_at[2] == 0 && spin_end == 0, "the later event waits, and so does the paused spin");
	rtos_host_run_for(100 * US);
	is_u64(mark_at[2], 150 * US, "the next run takes the spin on, and the event due in it");
	rtos_host_run_for(200 * US);
	ok(spun == 300 * US && spin_end == 300 * US, "the spin ends at its time, having spun it all (%llu at %llu)",
	   (unsigned long long)spun, (unsigned long long)spin_end);
	ok(in_event_spun == 100 * US && in_event_end == 450 * US && rtos_host_now() == 450 * US,
	   "a device event's spin runs past the deadline (spun %llu, ended %llu, run ended %llu)",
	   (unsigned long long)in_event_spun, (unsigned long long)in_event_end,
	   (unsigned long long)rtos_host_now());
	is_u64(mark_at[3], 420 * US, "an event due inside it runs at its time");
	rtos_host_shutdown();
	return tap_done();
}
