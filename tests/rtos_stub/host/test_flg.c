/*
 * test_flg.c — eventflags: OR and AND waits, TA_CLR, TA_WMUL (E_ILUSE
 * without it), the pattern returned at release, timeouts, parameter errors.
 */
#include "tap.h"
#include "kernel.h"
#include "rtos_test.h"

enum { FLG_MUL = 1, FLG_CLR, FLG_ONE };

static FLGPTN got_or, got_and, got_clr;
static ER r_ilu, r_par[3], r_pol, r_tw, r_ok_pol;
static uint64_t t_tw;
static FLGPTN ptn_after_clr;

static void or_waiter(intptr_t x)
{
	wai_flg(FLG_MUL, 0x0c, TWF_ORW, &got_or);
	rt_log("or");
}

static void and_waiter(intptr_t x)
{
	wai_flg(FLG_MUL, 0x03, TWF_ANDW, &got_and);
	rt_log("and");
}

static void clr_waiter(intptr_t x)
{
	wai_flg(FLG_CLR, 0x01, TWF_ORW, &got_clr);
	rt_log("clr");
}

static void one_waiter(intptr_t x)
{
	FLGPTN p;

	wai_flg(FLG_ONE, 1, TWF_ORW, &p);
}

static void main_task(intptr_t x)
{
	FLGPTN p;

	act_tsk(2);
	act_tsk(3);
	act_tsk(4);
	act_tsk(5);
	dly_tsk(1);                              /* all four wait */
	set_flg(FLG_MUL, 0x01);                  /* nobody satisfied */
	rt_log("s1");
	set_flg(FLG_MUL, 0x06);                  /* 0x07: OR(0x0c) and AND(0x03) both */
	rt_log("s2");
	dly_tsk(1);
	set_flg(FLG_CLR, 0x81);
	dly_tsk(1);
	pol_flg(FLG_CLR, 0xff, TWF_ORW, &p) == E_TMOUT ? (void)(ptn_after_clr = 0) : (void)(ptn_after_clr = p);
	r_ilu = wai_flg(FLG_ONE, 1, TWF_ORW, &p);          /* one waiter already: E_ILUSE */
	r_par[0] = wai_flg(FLG_MUL, 0, TWF_ORW, &p);
	r_par[1] = wai_flg(FLG_MUL, 1, 3, &p);
	r_par[2] = twai_flg(FLG_MUL, 1, TWF_ORW, &p, -5);
	clr_flg(FLG_MUL, 0);
	r_pol = pol_flg(FLG_MUL, 1, TWF_ORW, &p);
	set_flg(FLG_MUL, 0x10);
	r_ok_pol = pol_flg(FLG_MUL, 0x30, TWF_ORW, &p);
	r_tw = twai_flg(FLG_MUL, 0x20, TWF_ANDW, &p, 2);
	t_tw = rtos_host_now();
}

static const struct rtos_task_cfg tasks[] = {
	{ 1, TA_ACT, 0, main_task, 1, 1024, TDOM_KERNEL, "main" },
	{ 2, TA_NULL, 0, or_waiter, 5, 1024, TDOM_KERNEL, "or" },
	{ 3, TA_NULL, 0, and_waiter, 4, 1024, TDOM_KERNEL, "and" },
	{ 4, TA_NULL, 0, clr_waiter, 4, 1024, TDOM_KERNEL, "clr" },
	{ 5, TA_NULL, 0, one_waiter, 4, 1024, TDOM_KERNEL, "one" },
};
static const struct rtos_flg_cfg flgs[] = {
	{ FLG_MUL, TA_WMUL, 0, "mul" },
	{ FLG_CLR, TA_CLR, 0, "clr" },
	{ FLG_ONE, TA_NULL, 0, "one" },
};
static const struct rtos_cfg cfg = { .name = "flg", .tasks = RTOS_TABLE(tasks), .flgs = RTOS_TABLE(flgs) };

int main(void)
{
	tap_plan(10);
	rt_log_reset();
	is_int(rtos_host_boot(&cfg), E_OK, "boot");
	rtos_host_run_for(20000000);
	is_str(rt_log_text(), "s1 s2 and or clr", "set_flg releases OR and AND waiters once satisfied (then by priority)");
	ok(got_or == 0x07 && got_and == 0x07, "waiters get the pattern at release");
	is_int(got_clr, 0x81, "TA_CLR waiter gets the pattern before the clear");
	is_int(ptn_after_clr, 0, "TA_CLR cleared the whole pattern");
	is_int(r_ilu, E_ILUSE, "second waiter without TA_WMUL: E_ILUSE");
	ok(r_par[0] == E_PAR && r_par[1] == E_PAR && r_par[2] == E_PAR, "waiptn 0, bad mode, bad timeout: E_PAR");
	ok(r_pol == E_TMOUT && r_ok_pol == E_OK, "clr_flg clears; pol_flg polls");
	is_int(r_tw, E_TMOUT, "twai_flg times out");
	is_u64(t_tw, 5000000, "twai_flg(2 ms) at 3 ms times out at 5 ms");
	rtos_host_shutdown();
	return tap_done();
}
