/*
 * cost.c — the CPU time service calls cost (rtos_host.h): the defaults are
 * make bench's ARMv5 instruction counts at 300 MHz; the harness may change
 * them, per extended service call too.  The charge itself is svc_charge in
 * kernel_impl.h, the first step of every service call.
 */
#include "kernel_impl.h"

static const struct rtos_host_cpu_cost default_cost = {
	.svc_ns = RTOS_HOST_INSN_NS(RTOS_HOST_SVC_INSN),
	.ext_svc_ns = RTOS_HOST_INSN_NS(RTOS_HOST_EXT_SVC_INSN),
	.kernel_domain = false,
};

struct rtos_host_cpu_cost cpu_cost = default_cost;
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

/* The cost of extended service call fncd. */
uint32_t ext_svc_cost(FN fncd)
{
	return fncd_cost[fncd] != 0 ? (uint32_t)(fncd_cost[fncd] - 1) : cpu_cost.ext_svc_ns;
}
