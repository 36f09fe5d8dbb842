/*
 * svc.c — extended service calls (DEF_SVC / cal_svc) and memory access
 * probing per protection domain (prb_mem), as in TOPPERS/HRP2.
 */
#include <stdlib.h>

#include "kernel_impl.h"

struct mem_region {
	uintptr_t lo;
	uintptr_t hi;      /* exclusive */
	MODE      access;
};

static EXTSVC svc_table[TNUM_FNCD + 1];
static struct mem_region *regions[TNUM_DOMID + 1];
static uint_t nregions[TNUM_DOMID + 1];

/* Calls extended service routine fncd in the caller's context with the caller's domain. */
ER_UINT rtos_host_cal_svc(FN fncd, intptr_t par1, intptr_t par2, intptr_t par3, intptr_t par4, intptr_t par5)
{
	EXTSVC fn;
	struct tcb *caller;
	ER_UINT ercd;

	if ((uint_t)fncd - 1U >= (uint_t)TNUM_FNCD || (fn = svc_table[fncd]) == NULL) {
		svc_charge();
		return svc_result("cal_svc", E_RSFN);
	}
	caller = svc_ext_enter(fncd);
	ercd = fn(par1, par2, par3, par4, par5, caller != NULL ? caller->cfg->domid : TDOM_KERNEL);
	svc_ext_exit(caller);
	return ercd;
}

/* The domain of the calling task (TDOM_KERNEL in non-task context). */
ID rtos_host_current_domain(void)
{
	return cpu.kind == EXEC_TASK ? runtsk->cfg->domid : TDOM_KERNEL;
}

/* Finds a region covering addr with all of pmmode: the domain's, or the task's own stack. */
static const struct mem_region *region_at(const struct tcb *t, uintptr_t addr, MODE pmmode,
					  struct mem_region *stack)
{
	ID dom = t->cfg->domid;

	stack->lo = (uintptr_t)t->co.stack_lo;
	stack->hi = stack->lo + t->co.stack_size;
	stack->access = TPM_READ | TPM_WRITE;
	if (addr >= stack->lo && addr < stack->hi && (stack->access & pmmode) == pmmode)
		return stack;
	for (uint_t i = 0; i < nregions[dom]; i++) {
		const struct mem_region *r = &regions[dom][i];

		if (addr >= r->lo && addr < r->hi && (r->access & pmmode) == pmmode)
			return r;
	}
	return NULL;
}

/* prb_mem after its fast path: every rule, for any task and range (kept out of
 * line so that the fast path saves no registers for it). */
static __attribute__((noinline)) ER probe_memory(const void *base, SIZE size, ID tskid, MODE pmmode)
{
	struct tcb *t;
	ER ercd = E_OK;
	uintptr_t lo = (uintptr_t)base, hi;
	struct mem_region stack;

	if (tskid == TSK_SELF) {		/* no lookup */
		if (cpu.kind != EXEC_TASK)
			return svc_result("prb_mem", E_ID);
		t = runtsk;
	} else if ((t = task_lookup(tskid, true, &ercd)) == NULL) {
		return svc_result("prb_mem", ercd);
	}
	if (pmmode == 0 || (pmmode & ~(MODE)(TPM_READ | TPM_WRITE | TPM_EXEC)) != 0 || size == 0)
		return svc_result("prb_mem", E_PAR);
	if (base == NULL || size > UINTPTR_MAX - lo)
		return svc_result("prb_mem", E_MACV);
	if (t->cfg->domid == TDOM_KERNEL)
		return E_OK;
	hi = lo + size;
	while (lo < hi) {
		const struct mem_region *r = region_at(t, lo, pmmode, &stack);

		if (r == NULL)
			return svc_result("prb_mem", E_MACV);
		lo = r->hi;
	}
	return E_OK;
}

/*
 * E_OK if task tskid's domain may access [base, base+size) with pmmode, else
 * E_MACV.  The usual probe, the caller's own stack read or written, is decided
 * here without a lookup or a region search; everything else by probe_memory.
 */
ER prb_mem(const void *base, SIZE size, ID tskid, MODE pmmode)
{
	svc_charge();
	if (tskid == TSK_SELF && cpu.kind == EXEC_TASK) {
		uintptr_t offset = (uintptr_t)base - (uintptr_t)runtsk->co.stack_lo;
		size_t stack_size = runtsk->co.stack_size;

		if (offset < stack_size && size - 1U < stack_size - offset &&
		    pmmode != 0 && (pmmode & ~(MODE)(TPM_READ | TPM_WRITE)) == 0)
			return E_OK;
	}
	return probe_memory(base, size, tskid, pmmode);
}

/* Defines extended service fncd (DEF_SVC row already checked). */
ER svc_define(FN fncd, EXTSVC extsvc)
{
	svc_table[fncd] = extsvc;
	return E_OK;
}

/* True if fncd is defined (boot duplicate check). */
bool svc_defined(FN fncd)
{
	return svc_table[fncd] != NULL;
}

/* Forgets all service definitions. */
void svc_reset(void)
{
	for (FN f = 0; f <= TNUM_FNCD; f++)
		svc_table[f] = NULL;
}

/* Adds a memory region to its domain (row already checked). */
ER mem_add_region(const struct rtos_mem_cfg *mem)
{
	struct mem_region *n = realloc(regions[mem->domid], (nregions[mem->domid] + 1) * sizeof(*n));

	if (n == NULL)
		return E_NOMEM;
	regions[mem->domid] = n;
	n[nregions[mem->domid]].lo = (uintptr_t)mem->base;
	n[nregions[mem->domid]].hi = (uintptr_t)mem->base + mem->size;
	n[nregions[mem->domid]].access = mem->access;
	nregions[mem->domid]++;
	return E_OK;
}

/* Forgets all memory regions. */
void mem_reset(void)
{
	for (ID d = 0; d <= TNUM_DOMID; d++) {
		free(regions[d]);
		regions[d] = NULL;
		nregions[d] = 0;
	}
}
