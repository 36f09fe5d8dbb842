/*
 * test_deferred_wait.c — a deferred event bound once (rtos_host_deferred_bind)
 * and armed ns from now (rtos_host_deferred_arm_in) takes the time and place
 * rtos_host_defer_at gives it, and rtos_host_deferred_wait spends the time
 * to its end as rtos_host_consume does: only the clock moves when nothing is
 * due before it inside a device event, an event due meanwhile runs, the
 * harness (outside any event or access) takes the general path, and a time
 * that has come costs nothing.
 */
#include "tap.h"
#include "kernel.h"
#include "rtos_test.h"

#define US 1000ULL

static struct rtos_host_deferred d;
static uint64_t armed_for, waited_to;
static bool due_after_wait;

/* A device event: logs its name. */
static void log_event(void *arg)
{
	rt_log("%s", (const char *)arg);
}

/* The deferred event's settle: nothing to complete (the test disarms it). */
static void settle_nothing(void *arg)
{
	(void)arg;
}

/* Arms d 50 us from now and waits for it (with an event at arg us, 0: none, scheduled between). */
static void arm_and_wait(void *arg)
{
	uint64_t between = (uint64_t)(uintptr_t)arg;

	armed_for = rtos_host_deferred_arm_in(&d, 50 * US);
	if (between != 0)
		rtos_host_event_at(between * US, log_event, "between");
	rtos_host_deferred_wait(&d);
	waited_to = rtos_host_now();
	due_after_wait = rtos_host_deferred_due(&d);
	rt_log("waited");
	rtos_host_deferred_disarm(&d);
}

static const struct rtos_cfg cfg = { .name = "deferred_wait" };

int main(void)
{
	tap_plan(11);

	is_int(rtos_host_boot(&cfg), E_OK, "boot");
	rtos_host_deferred_bind(&d, log_event, settle_nothing, "d");

	rtos_host_event_at(100 * US, arm_and_wait, NULL);
	rtos_host_event_at(400 * US, log_event, "later");
	rtos_host_run_for(200 * US);
	is_u64(armed_for, 150 * US, "armed 50 us after the event's time");
	is_u64(waited_to, 150 * US, "the wait in a device event ends at the deferred event's time");
	ok(due_after_wait, "the deferred event is due then");
	is_str(rt_log_text(), "waited", "nothing else ran meanwhile (the quiet case)");

	rt_log_reset();
	rtos_host_event_at(250 * US, arm_and_wait, (void *)(uintptr_t)270);
	rtos_host_run_for(200 * US);
	is_u64(waited_to, 300 * US, "a wait with an event due before its end ends at its time");
	is_str(rt_log_text(), "between waited later", "the event due meanwhile ran during the wait");

	rt_log_reset();
	arm_and_wait(NULL);
	is_u64(waited_to, 450 * US, "the harness waits too (no event or access in progress)");
	ok(due_after_wait, "due after the harness's wait");

	rtos_host_defer_at(&d, rtos_host_now(), log_event, settle_nothing, "d");
	rtos_host_deferred_wait(&d);
	is_u64(rtos_host_now(), 450 * US, "a wait for a time that has come costs nothing");
	rtos_host_deferred_disarm(&d);
	is_str(rt_log_text(), "waited", "the deferred event itself never ran (its owner completes it)");
	rtos_host_shutdown();
	return tap_done();
}
