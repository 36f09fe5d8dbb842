/*
 * rtos_demo.c — a short tour of the host kernel in virtual time: three tasks
 * at different priorities, a cyclic handler, a semaphore, and a device event
 * that raises an interrupt whose ISR wakes the highest-priority task.
 */
#include <stdio.h>

#include "kernel.h"
#include "rtos_cfg.h"
#include "rtos_host.h"

enum { TSK_SENSOR = 1, TSK_CONTROL, TSK_LOGGER };
enum { SEM_SAMPLE = 1 };
enum { CYC_CONTROL = 1 };
#define INTNO_DEVICE 40U

static unsigned samples;

/* Prints one line stamped with the virtual time. */
static void say(const char *fmt, unsigned v)
{
	printf("[%8.3f ms] ", (double)rtos_host_now() / 1e6);
	printf(fmt, v);
	putchar('\n');
}

/* Highest priority: waits for the device interrupt, takes a sample, hands it on. */
static void sensor_task(intptr_t exinf)
{
	for (int i = 0; i < 3; i++) {
		slp_tsk();
		samples++;
		say("sensor  (pri 2): woken by the ISR, sample %u taken; 50 us of work", samples);
		rtos_host_consume(50000);
		sig_sem(SEM_SAMPLE);
	}
}

/* Middle priority: runs every 10 ms from the cyclic handler. */
static void control_task(intptr_t exinf)
{
	for (;;) {
		slp_tsk();
		say("control (pri 5): periodic step, %u samples so far", samples);
	}
}

/* Lowest priority: consumes samples from the semaphore. */
static void logger_task(intptr_t exinf)
{
	for (;;) {
		if (twai_sem(SEM_SAMPLE, 25) == E_TMOUT) {
			say("logger  (pri 9): no sample for %u ms", 25);
			continue;
		}
		say("logger  (pri 9): logged sample %u", samples);
	}
}

/* Cyclic handler: wakes the control task every 10 ms. */
static void control_cyclic(intptr_t exinf)
{
	iwup_tsk(TSK_CONTROL);
}

/* ISR of the device line: wakes the sensor task. */
static void device_isr(intptr_t exinf)
{
	say("isr %u: device interrupt, waking the sensor task", INTNO_DEVICE);
	iwup_tsk(TSK_SENSOR);
}

static const struct rtos_task_cfg tasks[] = {
	{ TSK_SENSOR, TA_ACT, 0, sensor_task, 2, 4096, TDOM_KERNEL, "sensor" },
	{ TSK_CONTROL, TA_ACT, 0, control_task, 5, 4096, TDOM_KERNEL, "control" },
	{ TSK_LOGGER, TA_ACT, 0, logger_task, 9, 4096, TDOM_KERNEL, "logger" },
};
static const struct rtos_sem_cfg sems[] = { { SEM_SAMPLE, TA_TPRI, 0, 8, "sample" } };
static const struct rtos_cyc_cfg cycs[] = {
	{ CYC_CONTROL, TA_STA, 0, control_cyclic, 10, 10, "control" },
};
static const struct rtos_int_cfg ints[] = { { INTNO_DEVICE, TA_ENAINT, -3 } };
static const struct rtos_isr_cfg isrs[] = { { TA_NULL, 0, INTNO_DEVICE, device_isr, 1 } };

static const struct rtos_cfg demo_cfg = {
	.name = "rtos_demo",
	.tasks = RTOS_TABLE(tasks),
	.sems = RTOS_TABLE(sems),
	.cycs = RTOS_TABLE(cycs),
	.ints = RTOS_TABLE(ints),
	.isrs = RTOS_TABLE(isrs),
};

/* Boots the demo, schedules three device interrupts, runs 60 ms of virtual time. */
int main(void)
{
	if (rtos_host_boot(&demo_cfg) != E_OK)
		return 1;
	puts("rtos_demo: the host kernel in virtual time (tick 200 us)");
	rtos_host_irq_raise_at(3500000, INTNO_DEVICE);
	rtos_host_irq_raise_at(12250000, INTNO_DEVICE);
	rtos_host_irq_raise_at(41000000, INTNO_DEVICE);
	rtos_host_run_for(60000000);
	printf("rtos_demo: %u samples at t=%.3f ms of virtual time\n", samples,
	       (double)rtos_host_now() / 1e6);
	rtos_host_shutdown();
	return samples == 3 ? 0 : 1;
}
