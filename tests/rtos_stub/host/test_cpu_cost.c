/*
 * test_cpu_cost.c — service calls cost virtual CPU time: a user-domain task
 * that busy-polls a flag with a service call per round lets time pass and
 * sees the device event that ends its loop; the costs are make bench's
 * instruction counts at 300 MHz; cal_svc costs its measured total (the calls
 * inside it are not charged again), per function code if set; kernel-domain
 * tasks are free unless asked; zero costs make calls free; time spent in a
 * call lets a higher-priority task preempt.
 */
#include "tap.h"
#include "kernel.h"
#include "rtos_test.h"

#define MS 1000000ULL
#define APP_DOM 1

static volatile bool flag;
static unsigned long rounds;
static uint64_t t_seen, t_cal, t_cal_fncd, t_kernel, t_kernel_charged, t_free, t_get_tim;
static SYSTIM tim;
static int hi_runs_during_poll;

static void raise_flag(void *arg)
{
	flag = true;
}

static ER_UINT ext_svc(intptr_t p1, intptr_t p2, intptr_t p3, intptr_t p4, intptr_t p5, ID cdmid)
{
	int local = 0;

	/* service calls inside an extended service call: covered by its own cost */
	(void)prb_mem(&local, sizeof(local), TSK_SELF, TPM_WRITE);
	(void)sns_ctx();
	return E_OK;
}

static void app_task(intptr_t x)
{
	uint64_t t0;
	struct rtos_host_cpu_cost cost, none = { 0, 0, false, 0 };

	rtos_host_event_at(5 * MS, raise_flag, NULL);
	while (!flag) {
		(void)sns_ctx();
		rounds++;
	}
	t_seen = rtos_host_now();

	do
		get_tim(&tim);
	while (tim < 10);
	t_get_tim = rtos_host_now();

	t0 = rtos_host_now();
	cal_svc(1, 0, 0, 0, 0, 0);
	t_cal = rtos_host_now() - t0;
	rtos_host_set_svc_cost(1, 5000);
	t0 = rtos_host_now();
	cal_svc(1, 0, 0, 0, 0, 0);
	t_cal_fncd = rtos_host_now() - t0;
	rtos_host_set_svc_cost(1, -1);

	rtos_host_get_cpu_cost(&cost);
	rtos_host_set_cpu_cost(&none);
	t0 = rtos_host_now();
	for (int i = 0; i < 1000; i++)
		(void)sns_ctx();
	t_free = rtos_host_now() - t0;
	rtos_host_set_cpu_cost(&cost);
}

static void kernel_task(intptr_t x)
{
	uint64_t t0 = rtos_host_now();
	struct rtos_host_cpu_cost cost;

	for (int i = 0; i < 1000; i++)
		(void)sns_ctx();
	t_kernel = rtos_host_now() - t0;
	rtos_host_get_cpu_cost(&cost);
	cost.kernel_domain = true;
	rtos_host_set_cpu_cost(&cost);
	t0 = rtos_host_now();
	for (int i = 0; i < 1000; i++)
		(void)sns_ctx();
	t_kernel_charged = rtos_host_now() - t0;
	rtos_host_set_cpu_cost(NULL);
}

/* Higher priority, every ms: runs while the app polls (preemption inside a call's time). */
static void hi_task(intptr_t x)
{
	for (;;) {
		dly_tsk(1);
		if (!flag)
			hi_runs_during_poll++;
	}
}

static const struct rtos_task_cfg tasks[] = {
	{ 1, TA_ACT, 0, app_task, 8, 4096, APP_DOM, "app" },
	{ 2, TA_NULL, 0, kernel_task, 8, 4096, TDOM_KERNEL, "kernel" },
	{ 3, TA_ACT, 0, hi_task, 4, 4096, TDOM_KERNEL, "hi" },
};
static const struct rtos_svc_cfg svcs[] = { { 1, ext_svc, 1024 } };
static SYSTIM *const tim_ptr = &tim;
static const struct rtos_mem_cfg mems[] = {
	{ APP_DOM, &tim, sizeof(tim), TPM_READ | TPM_WRITE, "tim" },
};
static const struct rtos_cfg cfg = {
	.name = "cost", .tasks = RTOS_TABLE(tasks), .svcs = RTOS_TABLE(svcs), .mems = RTOS_TABLE(mems),
};

int main(void)
{
	tap_plan(12);
	(void)tim_ptr;
	is_int(RTOS_HOST_INSN_NS(RTOS_HOST_SVC_INSN), 200, "a kernel service call: 60 instructions at 300 MHz = 200 ns");
	is_int(RTOS_HOST_INSN_NS(RTOS_HOST_EXT_SVC_INSN), 1873, "cal_svc: 562 instructions at 300 MHz = 1873 ns");
	is_int(rtos_host_boot(&cfg), E_OK, "boot");
	rtos_host_run_for(50 * MS);
	ok(flag && t_seen >= 5 * MS && t_seen < 5 * MS + 1000, "a busy-polling task sees the event (at %llu ns)",
	   (unsigned long long)t_seen);
	ok(rounds > 20000 && rounds <= 25000, "each round costs 200 ns of virtual time (%lu rounds in 5 ms)", rounds);
	ok(hi_runs_during_poll >= 4, "a higher-priority task preempts the polling loop (%d times)", hi_runs_during_poll);
	ok(tim >= 10 && t_get_tim >= 10 * MS, "polling get_tim lets the system time reach 10 ms");
	is_int(t_cal, 1873, "cal_svc costs its measured total; calls inside it are not charged again");
	is_int(t_cal_fncd, 5000, "a cost set per function code");
	is_int(t_free, 0, "zero costs: calls are free");
	rtos_host_shutdown();

	static const struct rtos_task_cfg ktasks[] = { { 2, TA_ACT, 0, kernel_task, 8, 4096, TDOM_KERNEL, "kernel" } };
	static const struct rtos_cfg kcfg = { .name = "cost-kernel", .tasks = RTOS_TABLE(ktasks) };

	rtos_host_boot(&kcfg);
	rtos_host_run_for(10 * MS);
	is_int(t_kernel, 0, "kernel-domain tasks are not charged by default");
	is_int(t_kernel_charged, 1000 * 200, "unless kernel_domain is set");
	rtos_host_shutdown();
	return tap_done();
}
