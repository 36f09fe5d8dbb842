/*
 * test_tick_order.c — the kernel's tick interrupt is raised exactly where an
 * event scheduled when the tick was armed would run: after the device events
 * due at the same time that were scheduled before that, before those
 * scheduled after it, and a deferred event's place (rtos_host_deferred_due)
 * is judged against it the same way.  With an ISR on INTNO_TICK the tick for
 * a boundary is armed at the previous one; without, when a time event needs
 * it (dly_tsk), and an earlier need replaces a later one.
 */
#include "tap.h"
#include "kernel.h"
#include "rtos_test.h"

#define US 1000ULL

static struct rtos_host_deferred early_deferred, late_deferred;
static bool early_due, late_due;

/* A device event: logs its name. */
static void log_event(void *arg)
{
	rt_log("%s", (const char *)arg);
}

/* A deferred event's settle: nothing to complete (the test disarms them). */
static void settle_nothing(void *arg)
{
	(void)arg;
}

/* The ISR on the tick line: at 400 us it logs and looks at the deferred events due then. */
static void isr_tick(intptr_t x)
{
	if (rtos_host_now() != 400 * US)
		return;
	rt_log("T");
	early_due = rtos_host_deferred_due(&early_deferred);
	late_due = rtos_host_deferred_due(&late_deferred);
}

/* At 300 us, after the tick for 400 us was armed at 200 us: an event and a deferred one at 400 us. */
static void schedule_late(void *arg)
{
	(void)arg;
	rtos_host_event_at(400 * US, log_event, "late");
	rtos_host_defer_at(&late_deferred, 400 * US, log_event, settle_nothing, NULL);
}

static const struct rtos_isr_cfg tick_isrs[] = { { TA_NULL, 0, INTNO_TICK, isr_tick, 1 } };
static const struct rtos_cfg every_cfg = { .name = "tick_every", .isrs = RTOS_TABLE(tick_isrs) };

/* Sleeps 1 ms twice: woken by the ticks at 1000 us and 2000 us. */
static void sleeper(intptr_t x)
{
	dly_tsk(1);
	rt_log("W1");
	dly_tsk(1);
	rt_log("W2");
	slp_tsk();
}

/* At 500 us: an event due at the 1000 us tick, scheduled after the tick was armed. */
static void schedule_after_need(void *arg)
{
	(void)arg;
	rtos_host_event_at(1000 * US, log_event, "after");
}

/* At 1500 us, while the sleeper waits for the 2000 us tick: an alarm needs
 * the tick at 1600 us, which replaces it, between two device events at 1600 us;
 * the tick at 2000 us, armed again at 1600 us, then comes after e2000. */
static void need_earlier(void *arg)
{
	(void)arg;
	rtos_host_event_at(1600 * US, log_event, "e1600");
	ista_alm(1, 0);
	rtos_host_event_at(1600 * US, log_event, "f1600");
	rtos_host_event_at(2000 * US, log_event, "e2000");
}

/* The alarm: logs at the tick it was started for. */
static void alarm(intptr_t x)
{
	rt_log("A");
}

static const struct rtos_task_cfg sleeper_tasks[] = { RT_TASK(1, sleeper, 5, true) };
static const struct rtos_alm_cfg alarms[] = { { 1, TA_NULL, 0, alarm, "alarm" } };
static const struct rtos_cfg need_cfg = {
	.name = "tick_need", .tasks = RTOS_TABLE(sleeper_tasks), .alms = RTOS_TABLE(alarms),
};

int main(void)
{
	tap_plan(8);

	is_int(rtos_host_boot(&every_cfg), E_OK, "boot with an ISR on the tick line");
	rtos_host_event_at(400 * US, log_event, "early");
	rtos_host_defer_at(&early_deferred, 400 * US, log_event, settle_nothing, NULL);
	rtos_host_event_at(300 * US, schedule_late, NULL);
	rtos_host_run_for(500 * US);
	is_str(rt_log_text(), "early T late",
	       "at a boundary, events scheduled before the tick was armed run before its ISR, later ones after");
	ok(early_due && !late_due,
	   "in the tick's ISR a deferred event armed before the tick is due, one armed after it is not");
	rtos_host_deferred_disarm(&early_deferred);
	rtos_host_deferred_disarm(&late_deferred);
	rtos_host_shutdown();

	rt_log_reset();
	is_int(rtos_host_boot(&need_cfg), E_OK, "boot with a sleeping task and no ISR on the tick line");
	rtos_host_event_at(1000 * US, log_event, "before");
	rtos_host_event_at(500 * US, schedule_after_need, NULL);
	rtos_host_run_for(1100 * US);
	is_str(rt_log_text(), "before W1 after",
	       "the tick a dly_tsk needs runs after the events scheduled before the need, before later ones");
	rt_log_reset();
	rtos_host_event_at(1500 * US, need_earlier, NULL);
	rtos_host_run_for(1000 * US);
	is_str(rt_log_text(), "e1600 A f1600 e2000 W2",
	       "an earlier need re-arms the tick in the order of its own time; the later tick is re-armed after it");
	is_u64(rtos_host_now(), 2100 * US, "the run ends at its deadline");
	ok(rtos_host_run_until_idle(10000 * US), "idle once only the sleeping task is left");
	rtos_host_shutdown();
	return tap_done();
}
