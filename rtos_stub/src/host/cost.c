/*
 * cost.c — the CPU time service calls cost (rtos_host.h): the defaults are
 * make bench's ARMv5 instruction counts at 300 MHz; the harness may change
 * them, per extended service call too.  svc_charge, the first step of every
 * service call, charges them.  This is simulation, not kernel: make bench's
 * counter excludes this file (it is not one of the service-call files).
 */
#include "kernel_impl.h"

/* One initializer for both: a const object is no constant expression in ISO C. */
#define DEFAULT_COST { \
	.svc_ns = RTOS_HOST_INSN_NS(RTOS_HOST_SVC_INSN), \
	.ext_svc_ns = RTOS_HOST_INSN_NS(RTOS_HOST_EXT_SVC_INSN), \
	.kernel_domain = false, \
	.app_block_ns = RTOS_HOST_INSN_NS(RTOS_HOST_APP_BLOCK_INSN), \
}

/* Blocks of app code charged at once: a 272 ns grain at the default cost. */
#define APP_BLOCK_BATCH 16U

static const struct rtos_host_cpu_cost default_cost = DEFAULT_COST;
struct rtos_host_cpu_cost cpu_cost = DEFAULT_COST;
static int64_t fncd_cost[TNUM_FNCD + 1];   /* ns + 1; 0: the default */

/* Sets the costs (NULL: the defaults); they stay across boots. */
void rtos_host_set_cpu_cost(const struct rtos_host_cpu_cost *cost)
{
	cpu_cost = cost != NULL ? *cost : default_cost;
}

void rtos_host_get_cpu_cost(struct rtos_host_cpu_cost *cost)
{
	if (cost != NULL)
		*cost = cpu_cost;
}

/* Sets the cost of one extended service call; ns < 0 returns it to the default. */
ER rtos_host_set_svc_cost(FN fncd, int32_t ns)
{
	if (fncd < 1 || fncd > TNUM_FNCD)
		return E_PAR;
	fncd_cost[fncd] = ns < 0 ? 0 : (int64_t)ns + 1;
	return E_OK;
}

/* True if a service call made now costs CPU time: a task at task level, not
 * inside an extended service (whose measured cost includes its calls). */
static bool charge_applies(void)
{
	return cpu.kind == EXEC_TASK && cpu.isr_depth == 0 && cpu.irq_defer == 0 &&
	       runtsk->nocharge_depth == 0 && (cpu_cost.kernel_domain || runtsk->cfg->domid != TDOM_KERNEL);
}

/* The first step of every service call: the calling task's stack use, its CPU time. */
void svc_charge(void)
{
	if (cpu.kind != EXEC_TASK || cpu.isr_depth != 0 || cpu.irq_defer != 0 || runtsk->nocharge_depth != 0)
		return;
	stack_use_sample(runtsk, __builtin_frame_address(0));
	if (cpu_cost.svc_ns != 0 && (cpu_cost.kernel_domain || runtsk->cfg->domid != TDOM_KERNEL))
		task_consume(cpu_cost.svc_ns);
}

/* cal_svc: charges the measured total of extended service fncd; the calls it makes are covered. */
struct tcb *svc_ext_enter(FN fncd)
{
	uint32_t ns = fncd_cost[fncd] != 0 ? (uint32_t)(fncd_cost[fncd] - 1) : cpu_cost.ext_svc_ns;
	struct tcb *caller;

	if (cpu.kind != EXEC_TASK)
		return NULL;
	if (cpu.isr_depth == 0 && cpu.irq_defer == 0 && runtsk->nocharge_depth == 0)
		stack_use_sample(runtsk, __builtin_frame_address(0));
	if (ns != 0 && charge_applies())
		task_consume(ns);
	/* the task that called, even if another ran meanwhile */
	caller = runtsk;
	caller->nocharge_depth++;
	return caller;
}

void svc_ext_exit(struct tcb *caller)
{
	if (caller != NULL)
		caller->nocharge_depth--;
}

/*
 * Called by the compiler at every basic block of an app's code (built with
 * -fsanitize-coverage=trace-pc): every APP_BLOCK_BATCH blocks, their CPU
 * time, where a service call would be charged.  Code that runs before boot,
 * in the kernel domain or in a handler costs nothing, as before.
 */
void __sanitizer_cov_trace_pc(void)
{
	static uint32_t blocks;

	if (++blocks < APP_BLOCK_BATCH)
		return;
	blocks = 0;
	if (kernel_booted && !kernel_exited && cpu_cost.app_block_ns != 0 && charge_applies())
		task_consume((uint64_t)cpu_cost.app_block_ns * APP_BLOCK_BATCH);
}
