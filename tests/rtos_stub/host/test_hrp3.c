/*
 * test_hrp3.c — the HRP3 profile of the host kernel at exact virtual times:
 * this file is compiled as an HRP3 app is (EV3LX_KERNEL_HRP3), so kernel.h
 * gives HRP3's types and binds its calls to the kernel's HRP3 entry points.
 * Times in us (tslp_tsk, dly_tsk, twai_sem, get_tim, fch_hrt, sta_alm,
 * ref_cyc, ref_alm; a cyclic handler of an HRP3 configuration with a
 * sub-millisecond period beside an HRP2 one in ms), HRP3's limits (TMO_NBLK,
 * TMAX_RELTIM), the calls that work in non-task context too (act_tsk,
 * sig_sem from a cyclic handler), ini_sem/ini_flg/ref_sem/ref_flg, that an
 * HRP2 call of the same task keeps its milliseconds, and the boot checks of
 * an HRP3 configuration.
 */
#define EV3LX_KERNEL_HRP3 1
#include "tap.h"
#include "kernel.h"
#include "rtos_test.h"

#define US 1000ULL
#define MS 1000000ULL

/* HRP2's tslp_tsk (ms), the kernel's entry as the platform's code in the same task calls it. */
extern ER hrp2_tslp_tsk(int_t tmout) __asm__("_kernel_tslp_tsk");

static uint64_t t_slp, t_dly, t_twai, t_hrp2, t_alm;
static ER r_slp, r_nblk, r_big, r_par, r_twai, r_long, r_hrp2, r_ini_sem, r_ini_flg;
static SYSTIM systim;
static HRTCNT hrt;
static T_RCYC rcyc;
static T_RALM ralm;
static T_RSEM rsem;
static T_RFLG rflg;
static int fast_count, slow_count, worker_runs;
static ER r_nontask_act, r_nontask_sig;

/* An HRP3 cyclic handler every 700 us (from 0); its first run activates the worker. */
static void fast_cyc(intptr_t x)
{
	if (fast_count++ == 0) {
		r_nontask_act = act_tsk(2);
		r_nontask_sig = isig_sem(2);   /* HRP3's i-name: sig_sem itself */
	}
}

/* An HRP2 cyclic handler every 1 ms, in the same system. */
static void slow_cyc(intptr_t x)
{
	slow_count++;
}

static void alm_handler(intptr_t x)
{
	t_alm = rtos_host_now();
}

static void worker_task(intptr_t x)
{
	worker_runs++;
}

/* Waits on semaphore 1 until ini_sem releases it (E_DLT), then on flag 1 until ini_flg does. */
static void waiter_task(intptr_t x)
{
	r_ini_sem = wai_sem(1);
	r_ini_flg = wai_flg(1, 0x1, TWF_ORW, &(FLGPTN){ 0 });
}

/* Sleeps 3 000 000 000 us (valid in HRP3, beyond HRP2's int) until rel_wai. */
static void long_task(intptr_t x)
{
	r_long = tslp_tsk(3000000000U);
}

static void main_task(intptr_t x)
{
	r_slp = tslp_tsk(300);                 /* at 0: 300 us -> first boundary 400 us */
	t_slp = rtos_host_now();
	rtos_host_consume(10 * US);            /* 410 us */
	dly_tsk(1500);                         /* 1910 us -> 2000 us */
	t_dly = rtos_host_now();
	r_nblk = tslp_tsk(TMO_NBLK);
	r_big = dly_tsk(TMAX_RELTIM + 1U);
	r_par = sta_alm(1, TMAX_RELTIM + 1U);
	r_twai = twai_sem(3, 2500);            /* 2000 -> 4600 us (first boundary at or after 4500) */
	t_twai = rtos_host_now();
	r_hrp2 = hrp2_tslp_tsk(1);             /* HRP2's call in the same task: 1 ms -> 5600 us */
	t_hrp2 = rtos_host_now();
	rtos_host_consume(34 * US);            /* 5634 us */
	get_tim(&systim);
	hrt = fch_hrt();
	ref_cyc(1, &rcyc);                     /* next fast activation: 6300 us, tick 6400 */
	sta_alm(1, 1234);                      /* 5634 + 1234 = 6868 -> 7000 us */
	ref_alm(1, &ralm);
	dly_tsk(2000);                         /* 7634 -> 7800 */
	rel_wai(4);                            /* long_task: E_RLWAI */
	ini_sem(1);                            /* waiter: E_DLT */
	set_flg(1, 0x2);
	ref_flg(1, &rflg);
	ini_flg(1);
	ref_sem(1, &rsem);
	stp_cyc(1);
	stp_cyc(2);
}

static const struct rtos_task_cfg hrp3_tasks[] = {
	{ 1, TA_ACT, 0, main_task, 2, 1024, TDOM_KERNEL, "main" },
	{ 2, TA_NULL, 0, worker_task, 1, 1024, TDOM_KERNEL, "worker" },
	{ 3, TA_ACT, 0, waiter_task, 1, 1024, TDOM_KERNEL, "waiter" },
	{ 4, TA_ACT, 0, long_task, 1, 1024, TDOM_KERNEL, "long" },
};
static const struct rtos_sem_cfg hrp3_sems[] = {
	{ 1, TA_NULL, 0, 1, "s1" }, { 2, TA_NULL, 0, 1, "s2" }, { 3, TA_NULL, 0, 1, "s3" },
};
static const struct rtos_flg_cfg hrp3_flgs[] = { { 1, TA_NULL, 0x4, "f1" } };
static const struct rtos_alm_cfg hrp3_alms[] = { { 1, TA_NULL, 0, alm_handler, "a1" } };
static const struct rtos_cyc_cfg hrp3_cycs[] = { { 1, TA_STA, 0, fast_cyc, 700, 0, "fast" } };
static const struct rtos_cyc_cfg hrp2_cycs[] = { { 2, TA_STA, 0, slow_cyc, 1, 0, "slow" } };
static const struct rtos_cfg hrp2_cfg = { .name = "hrp2", .cycs = RTOS_TABLE(hrp2_cycs) };
static const struct rtos_cfg *const includes[] = { &hrp2_cfg, NULL };
static const struct rtos_cfg cfg = {
	.name = "hrp3", .tasks = RTOS_TABLE(hrp3_tasks), .sems = RTOS_TABLE(hrp3_sems),
	.flgs = RTOS_TABLE(hrp3_flgs), .alms = RTOS_TABLE(hrp3_alms), .cycs = RTOS_TABLE(hrp3_cycs),
	.includes = includes, .profile = RTOS_PROFILE_HRP3,
};

/* HRP3 has no TA_PHS (0x04), and its times end at TMAX_RELTIM us. */
static const struct rtos_cyc_cfg phs_cycs[] = { { 1, TA_STA | 0x04U, 0, slow_cyc, 700, 0, "phs" } };
static const struct rtos_cfg phs_cfg = { .name = "phs", .cycs = RTOS_TABLE(phs_cycs), .profile = RTOS_PROFILE_HRP3 };
static const struct rtos_cyc_cfg long_cycs[] = { { 1, TA_STA, 0, slow_cyc, 4000000001U, 0, "long" } };
static const struct rtos_cfg long_cfg = { .name = "long", .cycs = RTOS_TABLE(long_cycs), .profile = RTOS_PROFILE_HRP3 };
static const struct rtos_cyc_cfg max_cycs[] = { { 1, TA_STA, 0, slow_cyc, 4000000000U, 0, "max" } };
static const struct rtos_cfg max_cfg = { .name = "max", .cycs = RTOS_TABLE(max_cycs), .profile = RTOS_PROFILE_HRP3 };

int main(void)
{
	tap_plan(32);
	is_int(rtos_host_boot(&cfg), E_OK, "boot an HRP3 configuration that includes an HRP2 one");
	rtos_host_run_for(10 * MS);
	is_int(r_slp, E_TMOUT, "tslp_tsk(300) times out");
	is_u64(t_slp, 400 * US, "tslp_tsk(300) at 0 wakes at the first boundary at or after 300 us");
	is_u64(t_dly, 2000 * US, "dly_tsk(1500) at 410 us ends at 2000 us");
	is_int(r_nblk, E_PAR, "tslp_tsk(TMO_NBLK): E_PAR (no non-blocking calls)");
	is_int(r_big, E_PAR, "dly_tsk(TMAX_RELTIM + 1): E_PAR");
	is_int(r_par, E_PAR, "sta_alm(TMAX_RELTIM + 1): E_PAR");
	is_int(r_twai, E_TMOUT, "twai_sem(2500) times out");
	is_u64(t_twai, 4600 * US, "twai_sem(2500) at 2000 us times out at 4600 us");
	is_int(r_hrp2, E_TMOUT, "HRP2's tslp_tsk in the same task");
	is_u64(t_hrp2, 5600 * US, "keeps its milliseconds: tslp_tsk(1) at 4600 us wakes at 5600 us");
	ok(systim == 5634, "get_tim: us since boot (%llu)", (unsigned long long)systim);
	is_int((int)sizeof(systim), 8, "SYSTIM has 64 bits");
	is_int((int)hrt, 5634, "fch_hrt: us since boot");
	is_int((int)rcyc.cycstat, (int)TCYC_STA, "ref_cyc: running");
	is_int((int)rcyc.lefttim, 766, "ref_cyc: lefttim in us, to the tick of the next activation (6400 us)");
	is_int((int)ralm.almstat, (int)TALM_STA, "ref_alm: armed");
	is_int((int)ralm.lefttim, 1366, "ref_alm: lefttim in us (the alarm's tick, 7000 us)");
	is_u64(t_alm, 7000 * US, "sta_alm(1234) at 5634 us runs at 7000 us");
	is_int(r_nontask_act, E_OK, "act_tsk from a cyclic handler (non-task context) works in HRP3");
	is_int(worker_runs, 1, "the activated task ran");
	is_int(r_nontask_sig, E_OK, "isig_sem is sig_sem in HRP3, from non-task context");
	is_int(fast_count, 12, "the 700 us cyclic handler of the HRP3 configuration ran 12 times (0.2..7.8 ms)");
	is_int(slow_count, 8, "the 1 ms one of the HRP2 configuration 8 times (0..7 ms, stopped at 7.8 ms)");
	is_int(r_long, E_RLWAI, "tslp_tsk(3 000 000 000 us) is valid in HRP3 and waits (released by rel_wai)");
	is_int(r_ini_sem, E_DLT, "ini_sem releases its waiters with E_DLT");
	is_int(r_ini_flg, E_DLT, "ini_flg releases its waiters with E_DLT");
	ok(rflg.flgptn == 0x6 && rflg.wtskid == 3, "ref_flg: the pattern and the waiting task");
	ok(rsem.semcnt == 0 && rsem.wtskid == TSK_NONE, "ref_sem: the count ini_sem restored, no waiter");
	rtos_host_shutdown();

	is_int(rtos_host_boot(&phs_cfg), E_RSATR, "an HRP3 configuration has no TA_PHS (%s)", rtos_host_boot_error());
	is_int(rtos_host_boot(&long_cfg), E_PAR, "nor a cyctim beyond 4 000 000 000 us (%s)", rtos_host_boot_error());
	is_int(rtos_host_boot(&max_cfg), E_OK, "cyctim 4 000 000 000 us is HRP3's TMAX_RELTIM");
	rtos_host_shutdown();
	return tap_done();
}
