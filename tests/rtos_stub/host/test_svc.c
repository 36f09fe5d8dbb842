/*
 * test_svc.c — extended service calls (cal_svc: E_RSFN for undefined and
 * non-positive codes, parameters and the caller's domain passed through)
 * and prb_mem (in/out/straddling/adjacent ranges, own stack, modes, IDs).
 */
#include "tap.h"
#include "kernel.h"
#include "rtos_test.h"

#define IRQ_DEV 95U

static uint8_t region_a[256];      /* domain 1: read/write */
static uint8_t region_b[256];      /* domain 1: read only */
static uint8_t outside[64];

static ID seen_dom[4];
static int nseen;

static ER_UINT svc_sum(intptr_t a, intptr_t b, intptr_t c, intptr_t d, intptr_t e, ID cdmid)
{
	if (nseen < 4)
		seen_dom[nseen++] = cdmid;
	return (ER_UINT)(a + b + c + d + e);
}

static ER r_rsfn[4], r_sum_user, r_sum_kernel, r_isr_sum;
static ER r_prb[20], r_stack[5];
static ID user_dom_seen;

static void isr_dev(intptr_t x)
{
	r_isr_sum = cal_svc(1, 1, 1, 1, 1, 1);
	r_prb[19] = prb_mem(region_a, 4, TSK_SELF, TPM_READ);   /* TSK_SELF in non-task: E_ID */
}

static void user_task(intptr_t x)
{
	uint32_t local = 0;

	user_dom_seen = rtos_host_current_domain();
	r_sum_user = cal_svc(1, 1, 2, 3, 4, 5);
	r_prb[0] = prb_mem(region_a, sizeof(region_a), TSK_SELF, TPM_READ | TPM_WRITE);
	r_prb[1] = prb_mem(region_a + 10, 16, TSK_SELF, TPM_WRITE);
	r_prb[2] = prb_mem(outside, 4, TSK_SELF, TPM_READ);
	r_prb[3] = prb_mem(region_a + 250, 16, TSK_SELF, TPM_READ);       /* straddles the end */
	r_prb[4] = prb_mem(region_b, 16, TSK_SELF, TPM_READ);
	r_prb[5] = prb_mem(region_b, 16, TSK_SELF, TPM_WRITE);             /* read-only region */
	r_prb[6] = prb_mem(region_a, 4, TSK_SELF, TPM_EXEC);
	r_prb[7] = prb_mem(&local, sizeof(local), TSK_SELF, TPM_READ | TPM_WRITE);   /* own stack */
	r_prb[8] = prb_mem(NULL, 4, TSK_SELF, TPM_READ);
	r_prb[9] = prb_mem(region_a, 0, TSK_SELF, TPM_READ);
	r_prb[10] = prb_mem(region_a, 4, TSK_SELF, 0);
	r_prb[11] = prb_mem(region_a, 4, TSK_SELF, 0x80);
	r_prb[12] = prb_mem(region_a, 4, 0 - 1, TPM_READ);
	r_prb[13] = prb_mem(region_a, 4, 7, TPM_READ);                     /* unconfigured */
	r_prb[14] = prb_mem(region_a, 4, 2, TPM_READ);                     /* kernel task: anything */
	r_prb[15] = prb_mem(outside, 4, 2, TPM_READ | TPM_WRITE);
	r_prb[16] = prb_mem((const void *)(UINTPTR_MAX - 2), 16, 2, TPM_READ);   /* wraps */
	r_prb[17] = prb_mem(&local, 4, 2, TPM_READ);                       /* our stack, kernel task: ok */
	r_prb[18] = prb_mem(region_a + 200, 100, 1, TPM_READ);             /* adjacent A|B read: ok if adjacent */
	/* The own-stack fast path keeps the general rules. */
	r_stack[0] = prb_mem(&local, sizeof(local), TSK_SELF, TPM_EXEC);   /* a stack is data */
	r_stack[1] = prb_mem(&local, 0, TSK_SELF, TPM_READ);
	r_stack[2] = prb_mem(&local, sizeof(local), TSK_SELF, 0);
	r_stack[3] = prb_mem(&local, 4096, TSK_SELF, TPM_READ);            /* runs past the 1 KiB stack */
	r_stack[4] = prb_mem(&local, sizeof(local), 1, TPM_WRITE);          /* by ID: the same answer */
}

static void kernel_task(intptr_t x)
{
	r_sum_kernel = cal_svc(1, 10, 20, 30, 40, 50);
	r_rsfn[0] = cal_svc(0, 0, 0, 0, 0, 0);
	r_rsfn[1] = cal_svc(-3, 0, 0, 0, 0, 0);
	r_rsfn[2] = cal_svc(2, 0, 0, 0, 0, 0);               /* in range, undefined */
	r_rsfn[3] = cal_svc(TNUM_FNCD + 1, 0, 0, 0, 0, 0);
	rtos_host_irq_raise(IRQ_DEV);
}

static const struct rtos_task_cfg tasks[] = {
	{ 1, TA_ACT, 0, user_task, 5, 1024, 1, "user" },
	{ 2, TA_ACT, 0, kernel_task, 6, 1024, TDOM_KERNEL, "kernel" },
};
static const struct rtos_svc_cfg svcs[] = { { 1, svc_sum, 1024 } };
static struct rtos_mem_cfg mems[] = {
	{ 1, region_a, sizeof(region_a), TPM_READ | TPM_WRITE, "a" },
	{ 1, region_b, sizeof(region_b), TPM_READ, "b" },
};
static const struct rtos_int_cfg ints[] = { { IRQ_DEV, TA_ENAINT, -2 } };
static const struct rtos_isr_cfg isrs[] = { { TA_NULL, 0, IRQ_DEV, isr_dev, 1 } };
static const struct rtos_cfg cfg = {
	.name = "svc", .tasks = RTOS_TABLE(tasks), .svcs = RTOS_TABLE(svcs), .mems = RTOS_TABLE(mems),
	.ints = RTOS_TABLE(ints), .isrs = RTOS_TABLE(isrs),
};

int main(void)
{
	bool adjacent = region_a + sizeof(region_a) == region_b;

	tap_plan(21);
	is_int(rtos_host_boot(&cfg), E_OK, "boot");
	rtos_host_run_for(1000000);
	is_int(user_dom_seen, 1, "rtos_host_current_domain: the task's domain");
	is_int(r_sum_user, 15, "cal_svc passes five parameters and returns the routine's value");
	is_int(r_sum_kernel, 150, "cal_svc from a kernel task");
	ok(nseen == 3 && seen_dom[0] == 1 && seen_dom[1] == TDOM_KERNEL && seen_dom[2] == TDOM_KERNEL,
	   "the routine gets the caller's domain (user 1, kernel, and TDOM_KERNEL from an ISR)");
	is_int(r_isr_sum, 5, "cal_svc from an ISR runs in the ISR");
	ok(r_rsfn[0] == E_RSFN && r_rsfn[1] == E_RSFN && r_rsfn[2] == E_RSFN && r_rsfn[3] == E_RSFN,
	   "cal_svc: zero, negative, undefined and too large codes give E_RSFN");
	ok(r_prb[0] == E_OK && r_prb[1] == E_OK, "prb_mem: ranges inside a read/write region");
	ok(r_prb[2] == E_MACV && r_prb[3] == E_MACV, "prb_mem: outside and straddling ranges give E_MACV");
	ok(r_prb[4] == E_OK && r_prb[5] == E_MACV && r_prb[6] == E_MACV,
	   "prb_mem: the region's access modes are respected");
	is_int(r_prb[7], E_OK, "prb_mem: a task may always access its own stack");
	is_int(r_prb[8], E_MACV, "prb_mem: NULL is E_MACV");
	ok(r_stack[0] == E_MACV && r_stack[3] == E_MACV,
	   "prb_mem: own stack for execution, or past the stack's end: E_MACV");
	ok(r_stack[1] == E_PAR && r_stack[2] == E_PAR, "prb_mem: own stack with size 0 or no mode: E_PAR");
	is_int(r_stack[4], E_OK, "prb_mem: the task's stack probed by its ID");
	ok(r_prb[9] == E_PAR && r_prb[10] == E_PAR && r_prb[11] == E_PAR, "prb_mem: size 0 and bad modes are E_PAR");
	ok(r_prb[12] == E_ID && r_prb[13] == E_NOEXS, "prb_mem: bad task IDs E_ID / E_NOEXS");
	ok(r_prb[14] == E_OK && r_prb[15] == E_OK && r_prb[17] == E_OK,
	   "prb_mem: a kernel-domain task may access everything");
	is_int(r_prb[16], E_MACV, "prb_mem: a wrapping range is E_MACV");
	if (adjacent)
		is_int(r_prb[18], E_OK, "prb_mem: a range covered by two adjacent regions is allowed");
	else
		is_int(r_prb[18], E_MACV, "prb_mem: a range crossing into unmapped memory is E_MACV");
	is_int(r_prb[19], E_ID, "prb_mem(TSK_SELF) in non-task context is E_ID");
	rtos_host_shutdown();
	return tap_done();
}
