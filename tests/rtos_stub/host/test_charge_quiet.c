/*
 * test_charge_quiet.c — a service call's charge (svc_charge) takes the task's
 * quiet short cut inline when nothing is due before its end; at its edges it
 * must end exactly as the busy loop does: a charge ending at the run's
 * deadline is not paused, one that crosses it is; a task woken under dis_dsp
 * runs at ena_dsp after the calls made meanwhile; an event falling due inside
 * a charge runs at its time, and the interrupt it raises under loc_cpu waits
 * through later charges (pending but masked: still quiet) until unl_cpu.
 */
#include "tap.h"
#include "kernel.h"
#include "rtos_test.h"

#define US 1000ULL
#define APP_DOM 1
#define IRQ_DEV 120U

static uint64_t at_deadline, past_deadline, high_start, event_at, unlocked_at, isr_at;

static void isr_dev(intptr_t x)
{
	isr_at = rtos_host_now();
}

static void raise_event(void *arg)
{
	event_at = rtos_host_now();
	rtos_host_irq_raise(IRQ_DEV);
}

static void app_task(intptr_t x)
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

/* Kernel domain: its own calls are free, so only the application's charges count. */
static void high_task(intptr_t x)
{
	slp_tsk();
	high_start = rtos_host_now();
	slp_tsk();
}

static const struct rtos_task_cfg tasks[] = {
	{ 1, TA_ACT, 0, app_task, 8, 1024, APP_DOM, "app" },
	{ 2, TA_ACT, 0, high_task, 2, 1024, TDOM_KERNEL, "high" },
};
static const struct rtos_int_cfg ints[] = { { IRQ_DEV, TA_ENAINT, -2 } };
static const struct rtos_isr_cfg isrs[] = { { TA_NULL, 0, IRQ_DEV, isr_dev, 1 } };
static const struct rtos_cfg cfg = {
	.name = "charge_quiet", .tasks = RTOS_TABLE(tasks), .ints = RTOS_TABLE(ints), .isrs = RTOS_TABLE(isrs),
};

int main(void)
{
	static const struct rtos_host_cpu_cost one_us = { 1000, 1000, false };

	tap_plan(8);
	rtos_host_set_cpu_cost(&one_us);
	is_int(rtos_host_boot(&cfg), E_OK, "boot");
	rtos_host_run_for(10 * US);
	is_u64(at_deadline, 10 * US, "ten charges end at the run's deadline and are not paused there");
	is_u64(past_deadline, 0, "the next charge crosses the deadline: the task is paused in it");
	rtos_host_run_for(100 * US);
	is_u64(past_deadline, 11 * US, "the paused charge ends in the next run");
	/* dis_dsp 12, wup_tsk 13, five calls 18, ena_dsp's charge 19, then the dispatch */
	is_u64(high_start, 19 * US, "a task woken under dis_dsp runs at ena_dsp, after the calls' charges");
	/* loc_cpu 20; the event at 21 falls inside the second call's charge */
	is_u64(event_at, 21 * US, "an event due inside a charge runs at its time");
	ok(unlocked_at == 23 * US && isr_at == 24 * US,
	   "its interrupt, raised under loc_cpu, waits through the charges and is taken after unl_cpu's");
	is_u64(rtos_host_now(), 110 * US, "the run ends at its deadline with the tasks asleep");
	rtos_host_shutdown();
	rtos_host_set_cpu_cost(NULL);
	return tap_done();
}
