/*
 * test_consume_quiet.c — a task's rtos_host_consume with nothing due before
 * its end (no event, no interrupt, no task to switch to) takes a short cut;
 * at its edges it must end exactly as the busy loop does: a consume ending at
 * the run's deadline is not paused, one that crosses it is; a woken task waits
 * while dispatching is disabled and a masked interrupt while the CPU is
 * locked, and both run at the moment they are allowed to.  A service call's
 * charge (svc_charge) takes the same short cut inline, with the same edges;
 * an event falling due inside a charge runs at its time.
 */
#include "tap.h"
#include "kernel.h"
#include "rtos_test.h"

#define US 1000ULL
#define IRQ_DEV 120U
#define APP_DOM 1

static uint64_t at_deadline, past_deadline, high_start, isr_at, unlocked_at, event_at;

static void isr_dev(intptr_t x)
{
	isr_at = rtos_host_now();
}

static void raise_event(void *arg)
{
	event_at = rtos_host_now();
	rtos_host_irq_raise(IRQ_DEV);
}

static void low_task(intptr_t x)
{
	rtos_host_consume(100 * US);
	at_deadline = rtos_host_now();
	rtos_host_consume(1 * US);
	past_deadline = rtos_host_now();

	dis_dsp();
	wup_tsk(2);
	rtos_host_consume(5 * US);
	ena_dsp();

	loc_cpu();
	rtos_host_event_at(rtos_host_now() + 1 * US, raise_event, NULL);
	rtos_host_consume(3 * US);
	unlocked_at = rtos_host_now();
	unl_cpu();
	rtos_host_consume(4 * US);
	slp_tsk();
}

/* The same steps in service calls, each charged 1 us (a user-domain task). */
static void charging_task(intptr_t x)
{
	for (int i = 0; i < 10; i++)
		(void)sns_ctx();
	at_deadline = rtos_host_now();
	(void)sns_ctx();
	past_deadline = rtos_host_now();

	dis_dsp();
	wup_tsk(2);
	for (int i = 0; i < 5; i++)
		(void)sns_ctx();
	ena_dsp();

	loc_cpu();
	rtos_host_event_at(rtos_host_now() + 1 * US, raise_event, NULL);
	for (int i = 0; i < 3; i++)
		(void)sns_ctx();
	unlocked_at = rtos_host_now();
	unl_cpu();
	slp_tsk();
}

/* Kernel domain: its own calls are free, so only the first task's charges count. */
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
static const struct rtos_int_cfg ints[] = { { IRQ_DEV, TA_ENAINT, -2 } };
static const struct rtos_isr_cfg isrs[] = { { TA_NULL, 0, IRQ_DEV, isr_dev, 1 } };
static const struct rtos_cfg cfg = {
	.name = "consume_quiet", .tasks = RTOS_TABLE(tasks), .ints = RTOS_TABLE(ints), .isrs = RTOS_TABLE(isrs),
};
static const struct rtos_task_cfg charging_tasks[] = {
	{ 1, TA_ACT, 0, charging_task, 8, 1024, APP_DOM, "app" },
	{ 2, TA_ACT, 0, high_task, 2, 1024, TDOM_KERNEL, "high" },
};
static const struct rtos_cfg charging_cfg = {
	.name = "charge_quiet", .tasks = RTOS_TABLE(charging_tasks), .ints = RTOS_TABLE(ints),
	.isrs = RTOS_TABLE(isrs),
};

/* Boots c and runs it to first_ns, where the task's what ends exactly at the
 * run's deadline and the next one crosses it; then second_ns more. */
static void run_past_edges(const struct rtos_cfg *c, const char *what, uint64_t first_ns, uint64_t second_ns)
{
	at_deadline = past_deadline = high_start = isr_at = unlocked_at = event_at = 0;
	is_int(rtos_host_boot(c), E_OK, "boot %s", c->name);
	rtos_host_run_for(first_ns);
	is_u64(at_deadline, first_ns, "a %s that ends at the run's deadline is not paused there", what);
	is_u64(past_deadline, 0, "the next %s crosses the deadline: the task is paused in it", what);
	rtos_host_run_for(second_ns);
}

/* The charges' run: 10 us, then 100 us more. */
static void check_charges(void)
{
	static const struct rtos_host_cpu_cost one_us = { 1000, 1000, false, 0 };

	rtos_host_set_cpu_cost(&one_us);
	run_past_edges(&charging_cfg, "service call's charge", 10 * US, 100 * US);
	is_u64(past_deadline, 11 * US, "the paused charge ends in the next run");
	/* dis_dsp 12, wup_tsk 13, five calls 18, ena_dsp's charge 19, then the dispatch */
	is_u64(high_start, 19 * US, "a task woken under dis_dsp runs at ena_dsp, after the calls' charges");
	/* loc_cpu 20; the event at 21 falls inside the second call's charge */
	is_u64(event_at, 21 * US, "an event due inside a charge runs at its time");
	ok(unlocked_at == 23 * US && isr_at == 24 * US,
	   "its interrupt, raised under loc_cpu, waits through the charges and is taken after unl_cpu's");
	is_u64(rtos_host_now(), 110 * US, "the charged run ends at its deadline with the tasks asleep");
	rtos_host_shutdown();
	rtos_host_set_cpu_cost(NULL);
}

int main(void)
{
	tap_plan(14);
	run_past_edges(&cfg, "consume", 100 * US, 100 * US);
	is_u64(high_start, 106 * US, "a task woken under dis_dsp runs at ena_dsp, after the 5 us consumed");
	ok(unlocked_at == 109 * US && isr_at == 109 * US,
	   "an interrupt raised under loc_cpu waits through the consume and is taken at unl_cpu");
	is_u64(rtos_host_now(), 200 * US, "the run ends at its deadline with the tasks asleep");
	rtos_host_shutdown();
	check_charges();
	return tap_done();
}
