/*
 * test_notify.c — examples/notify, an EV3RT 1.x (TOPPERS/HRP3) app: its
 * times are microseconds (tslp_tsk, dly_tsk below a millisecond, get_tim's
 * 64-bit SYSTIM, fch_hrt, sta_alm, twai_sem), and its cyclic handlers and
 * alarm notify as HRP3 defines it (TNFY_ACTTSK, TNFY_SIGSEM, TNFY_SETFLG,
 * TNFY_SNDDTQ with TENFY_INCVAR, TNFY_INCVAR, TNFY_WUPTSK) — beside the HRP2
 * examples in the same suite.
 */
#include "example_test.h"

int main(void)
{
	struct ev3sim_run_opts o;
	struct ev3sim_run_result r;
	const char *line;
	unsigned long us = 0, ms = 0, at = 0;
	int n = 0, sample = -1, failed = -1, counts = -1, blinks = -1;
	unsigned size = 0, ptn = 0;
	char code[16] = "";

	ev3sim_run_defaults(&o, EV3SIM_ROBOT_BARE);
	o.app_name = "notify";
	o.seconds = 4;
	if (!ok(ex_run(&o, &r), "notify runs 4 s"))
		return tap_done();

	line = ex_logged("notify: SYSTIM");
	ok(line != NULL && sscanf(line, "notify: SYSTIM is %u bytes", &size) == 1 && size == 8 &&
	   strstr(line, "TMO_FEVR 0xffffffff, TMAX_RELTIM 4000000000") != NULL,
	   "HRP3's types and limits: 64-bit SYSTIM, TMO_FEVR UINT32_MAX, TMAX_RELTIM 4e9 us (%s)", line ? line : "none");

	line = ex_logged("notify: tslp_tsk");
	ok(line != NULL && sscanf(line, "notify: tslp_tsk(500 ms) %15s after %lu us", code, &us) == 2 &&
	   strcmp(code, "E_TMOUT") == 0, "tslp_tsk(500000) times out (%s)", line ? line : "none");
	in_range((long)us, 500000, 500400, "after 500000 us and at most two ticks more (%lu us)", us);

	line = ex_logged("notify: dly_tsk");
	ok(line != NULL && sscanf(line, "notify: dly_tsk(1500 us) took %lu us", &us) == 1, "dly_tsk(1500) ran");
	in_range((long)us, 1500, 1800, "a delay below a millisecond: 1500 us and the tick's rounding (%lu us)", us);

	line = ex_logged("notify: 10 ticks");
	ok(line != NULL && sscanf(line, "notify: %d ticks in %lu ms", &n, &ms) == 2, "TNFY_SIGSEM signalled");
	is_int(n, 10, "ten signals of the started cyclic handler");
	in_range((long)ms, 900, 901, "100 ms apart, the first at sta_cyc (%lu ms)", ms);

	line = ex_logged("notify: flag");
	ok(line != NULL && sscanf(line, "notify: flag %15s pattern 0x%x", code, &ptn) == 2 && ptn == 1,
	   "TNFY_SETFLG set the flag (%s)", line ? line : "none");

	line = ex_logged("notify: woken");
	ok(line != NULL && sscanf(line, "notify: woken by the alarm after %lu ms", &ms) == 1, "TNFY_WUPTSK woke it");
	is_int((long)ms, 200, "sta_alm(200000) is 200 ms");

	line = ex_logged("notify: twai_sem");
	ok(line != NULL && strstr(line, "E_TMOUT after 50 ms") != NULL, "twai_sem(50000) times out after 50 ms (%s)",
	   line ? line : "none");

	line = ex_logged("notify: at");
	ok(line != NULL && sscanf(line, "notify: at %lu ms: sample %d, %d sends failed, %d counts, %d blinks", &at,
				  &sample, &failed, &counts, &blinks) == 5, "the totals (%s)", line ? line : "none");
	is_int(sample, 7, "TNFY_SNDDTQ sent the sample");
	is_int(failed, (int)(at / 50), "TENFY_INCVAR counted every send to the full queue (one per 50 ms after the first)");
	in_range(counts, (long)at * 2 + 1, (long)at * 2 + 2, "TNFY_INCVAR counted every 500 us from 0 (%d)", counts);
	is_int(blinks, (int)(at / 500 + 1), "TNFY_ACTTSK activated the LED task every 500 ms from 0");
	is_int(r.warnings + r.errors + r.bugs, 0, "no warnings, errors or bugs");
	return tap_done();
}
