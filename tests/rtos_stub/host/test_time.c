/*
 * test_time.c — timing rules at exact virtual times: tslp_tsk/dly_tsk on
 * and off tick boundaries, dly_tsk(0), get_tim/get_utm, alarms (start,
 * restart, stop, from an ISR), cyclic start/stop with and without TA_PHS.
 */
#include "tap.h"
#include "kernel.h"
#include "rtos_test.h"

#define MS 1000000ULL
#define INTNO_DEV 60U

static uint64_t t_slp_on, t_slp_off, t_dly0, t_dly5;
static ER r_slp, r_dly;
static SYSTIM systim;
static SYSUTM sysutm;
static uint64_t alm_times[8];
static int nalm;
static uint64_t cyc_times[16];
static int ncyc;
static uint64_t phs_times[16];
static int nphs;

static void alm_handler(intptr_t x)
{
	if (nalm < 8)
		alm_times[nalm++] = rtos_host_now();
}

static void cyc_handler(intptr_t x)
{
	if (ncyc < 16)
		cyc_times[ncyc++] = rtos_host_now();
}

static void phs_handler(intptr_t x)
{
	if (nphs < 16)
		phs_times[nphs++] = rtos_host_now();
}

static void dev_isr(intptr_t x)
{
	ista_alm(2, 1);
}

static void main_task(intptr_t x)
{
	/* at 0: tslp 2 ms on a boundary -> 2.0 ms */
	r_slp = tslp_tsk(2);
	t_slp_on = rtos_host_now();
	rtos_host_consume(10000);              /* 2.010 ms */
	tslp_tsk(2);                           /* 4.010 -> 4.2 */
	t_slp_off = rtos_host_now();
	r_dly = dly_tsk(0);                    /* at 4.2 (tick processed) -> next tick 4.4 */
	t_dly0 = rtos_host_now();
	dly_tsk(5);                            /* 4.4 + 5 = 9.4 */
	t_dly5 = rtos_host_now();
	rtos_host_consume(123456);             /* 9.523456 ms */
	get_tim(&systim);
	get_utm(&sysutm);

	/* alarms: start at 9.523456 for 2 ms -> 11.6; restart before expiry -> from now */
	sta_alm(1, 2);
	dly_tsk(1);                            /* -> 10.6 */
	sta_alm(1, 3);                         /* restart: 13.6 */
	sta_alm(3, 1);                         /* 11.6, then stopped */
	stp_alm(3);
	dly_tsk(5);                            /* -> 15.6 */
	rtos_host_irq_raise(INTNO_DEV);        /* ISR starts alarm 2: 1 ms -> 16.6 */
	dly_tsk(3);                            /* -> 18.6 */

	/* cyclic without TA_PHS: started at 18.6 with phase 1 ms, period 2 ms */
	sta_cyc(1);                            /* 19.6, 21.6, 23.6 ... */
	dly_tsk(5);                            /* -> 23.6 (boundary; cyclic runs first at the same tick) */
	stp_cyc(1);
	dly_tsk(4);                            /* 27.6 */
	sta_cyc(1);                            /* restart from now: 28.6, 30.6 */
	dly_tsk(3);                            /* 30.6 */
	stp_cyc(1);

	/* TA_PHS cyclic (not TA_STA): grid 5 + 10k ms from boot; start at 30.6 -> 35, 45 */
	sta_cyc(2);
	dly_tsk(20);                           /* 50.6 */
	stp_cyc(2);
	dly_tsk(20);                           /* 70.6: missed 55, 65 */
	sta_cyc(2);                            /* phase kept: 75, 85 */
	dly_tsk(20);                           /* 90.6 */
	stp_cyc(2);
}

static const struct rtos_task_cfg tasks[] = {
	{ 1, TA_ACT, 0, main_task, 1, 1024, TDOM_KERNEL, "main" },
};
static const struct rtos_alm_cfg alms[] = {
	{ 1, TA_NULL, 1, alm_handler, "a1" },
	{ 2, TA_NULL, 2, alm_handler, "a2" },
	{ 3, TA_NULL, 3, alm_handler, "a3" },
};
static const struct rtos_cyc_cfg cycs[] = {
	{ 1, TA_NULL, 0, cyc_handler, 2, 1, "c" },
	{ 2, TA_PHS, 0, phs_handler, 10, 5, "phs" },
};
static const struct rtos_int_cfg ints[] = { { INTNO_DEV, TA_ENAINT, -2 } };
static const struct rtos_isr_cfg isrs[] = { { TA_NULL, 0, INTNO_DEV, dev_isr, 1 } };
static const struct rtos_cfg cfg = {
	.name = "time", .tasks = RTOS_TABLE(tasks), .alms = RTOS_TABLE(alms), .cycs = RTOS_TABLE(cycs),
	.ints = RTOS_TABLE(ints), .isrs = RTOS_TABLE(isrs),
};

int main(void)
{
	tap_plan(14);
	is_int(rtos_host_boot(&cfg), E_OK, "boot");
	rtos_host_run_for(100 * MS);
	is_int(r_slp, E_TMOUT, "tslp_tsk times out with E_TMOUT");
	is_u64(t_slp_on, 2 * MS, "tslp_tsk(2) at 0 ms (a tick boundary) wakes at exactly 2.0 ms");
	is_u64(t_slp_off, 4200000, "tslp_tsk(2) at 2.010 ms wakes at the next boundary 4.2 ms");
	is_int(r_dly, E_OK, "dly_tsk returns E_OK");
	is_u64(t_dly0, 4400000, "dly_tsk(0) on a processed tick waits for the next tick");
	is_u64(t_dly5, 9400000, "dly_tsk(5) at 4.4 ms ends at 9.4 ms");
	is_int((int)systim, 9, "get_tim: ms since boot in whole ticks (9.523 ms -> 9)");
	is_int((int)sysutm, 9523, "get_utm: us since boot");
	ok(nalm == 2 && alm_times[0] == 13600000 && alm_times[1] == 16600000,
	   "alarms: restart counts from the restart (13.6 ms), a stopped one never fires, ista_alm from an ISR (16.6 ms)");
	if (nalm != 2)
		tap_diag("nalm=%d first=%llu", nalm, (unsigned long long)alm_times[0]);
	ok(ncyc == 5 && cyc_times[0] == 19600000 && cyc_times[1] == 21600000 &&
	   cyc_times[2] == 23600000 && cyc_times[3] == 28600000 && cyc_times[4] == 30600000,
	   "sta_cyc without TA_PHS: phase from the call; stp_cyc stops; restart re-phases");
	for (int i = 0; i < ncyc; i++)
		tap_diag("cyc %d at %llu", i, (unsigned long long)cyc_times[i]);
	ok(nphs == 4 && phs_times[0] == 35 * MS && phs_times[1] == 45 * MS && phs_times[2] == 75 * MS &&
	   phs_times[3] == 85 * MS, "TA_PHS keeps the boot-time phase grid across stop/start");
	for (int i = 0; i < nphs; i++)
		tap_diag("phs %d at %llu", i, (unsigned long long)phs_times[i]);
	is_u64(rtos_host_now(), 100 * MS, "virtual clock at the end of run_for");
	ok(rtos_host_run_until_idle(10 * MS), "run_until_idle: idle reached (task ended)");
	rtos_host_shutdown();
	return tap_done();
}
