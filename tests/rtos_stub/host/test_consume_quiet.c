/*
 * test_consume_quiet.c — a task's rtos_host_consume with nothing due before
 * its end (no event, no interrupt, no task to switch to) takes a short cut;
 * at its edges it must end exactly as the busy loop does: a consume ending at
 * the run's deadline is not paused, one that crosses it is; a woken task waits
 * while dispatching is disabled and a masked interrupt while the CPU is
 * locked, and both run at the moment they are allowed to.
 */
#include "tap.h"
#include "kernel.h"
#include "rtos_test.h"

#define US 1000ULL
#define IRQ_DEV 120U

static uint64_t at_deadline, past_deadline, high_start, isr_at, unlocked_at;

static void isr_dev(intptr_t x)
{
	isr_at = rtos_host_now();
}

static void raise_event(void *arg)
{
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

int main(void)
{
	tap_plan(6);
	is_int(rtos_host_boot(&cfg), E_OK, "boot");
	rtos_host_run_for(100 * US);
	is_u64(at_deadline, 100 * US, "a consume that ends at the run's deadline is not paused there");
	is_u64(past_deadline, 0, "the next consume crosses the deadline: the task is paused in it");
	rtos_host_run_for(100 * US);
	is_u64(high_start, 106 * US, "a task woken under dis_dsp runs at ena_dsp, after the 5 us consumed");
	ok(unlocked_at == 109 * US && isr_at == 109 * US,
	   "an interrupt raised under loc_cpu waits through the consume and is taken at unl_cpu");
	is_u64(rtos_host_now(), 200 * US, "the run ends at its deadline with the tasks asleep");
	rtos_host_shutdown();
	return tap_done();
}
