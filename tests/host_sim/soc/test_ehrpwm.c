/*
 * test_ehrpwm.c — eHRPWM1's outputs as a motor sees them: the low fraction
 * of each period for the action qualifiers a driver sets (up and up-down
 * counting, set/clear and toggle actions, shadowed and immediate compare
 * loads), that a compare value reaches only the output whose actions
 * use it, also when a setting is left and taken again, and that a moving
 * compare value changes the order of the actions right; that a shadowed
 * compare value loads at the instant its CMPCTL load mode names (zero,
 * period, either, never), also with an action-qualifier write between the
 * period and the zero instant, and a shadowed period at zero.
 */
#include <math.h>
#include "devtest.h"
#include "host_sim/devices/pwm.h"

#define PWM1     HS_EHRPWM1_BASE
#define TBCTL    (PWM1 + 0x00)
#define TBSTS    (PWM1 + 0x02)
#define TBCNT    (PWM1 + 0x08)
#define TBPRD    (PWM1 + 0x0A)
#define CMPCTL   (PWM1 + 0x0E)
#define CMPA     (PWM1 + 0x12)
#define CMPB     (PWM1 + 0x14)
#define AQCTLA   (PWM1 + 0x16)
#define AQCTLB   (PWM1 + 0x18)
#define PRD      9999U          /* devtest_pwm_setup's period: 10 000 counts up */
#define TBCLK_HZ 132000000ULL   /* TBCLK = the module clock, HS_PLL1_SYSCLK2_HZ (dividers /1 /1) */
#define MARGIN   50U            /* counts kept from an instant when checking before or after it */

/* CMPCTL LOADAMODE (bits 1:0): the counter instant a shadowed CMPA loads at. */
#define LOAD_ZERO   0U
#define LOAD_PRD    1U
#define LOAD_EITHER 2U
#define LOAD_FREEZE 3U

/* AQCTL actions (AM1808 TRM, eHRPWM action-qualifier control): 1 clear, 2 set, 3 toggle. */
#define ZRO(a)   ((a) << 0)
#define CAU(a)   ((a) << 4)
#define CAD(a)   ((a) << 6)
#define CBU(a)   ((a) << 8)

/* A fraction computed exactly as expected (within rounding). */
#define is_near(got, expected, ...) in_range(got, (expected) - 1e-12, (expected) + 1e-12, __VA_ARGS__)

static bool is_close(double got, double expected)
{
	return fabs(got - expected) < 1e-12;
}

static double low_a(void)
{
	return hs_pwm_low_fraction(HS_PWM_EHRPWM1_A);
}

static double low_b(void)
{
	return hs_pwm_low_fraction(HS_PWM_EHRPWM1_B);
}

/* Writes CMPA and lets a shadow load (at counter zero) pass. */
static void set_cmpa(uint16_t v)
{
	wr16(CMPA, v);
	hs_sim_run_for(MS);
}

/* Runs until the up counter is at count, at most one period ahead (register
 * accesses take virtual time: it may be some counts later). */
static void run_to_count(uint32_t count)
{
	uint32_t now = rd16(TBCNT), ahead = count >= now ? count - now : PRD + 1U - now + count;

	hs_sim_run_for((uint64_t)ahead * 1000000000ULL / TBCLK_HZ + 1U);
}

/* Runs until the up-down counter counts in direction up (TBSTS CTRDIR) within [lo, hi]. */
static void run_to_updown(bool up, uint32_t lo, uint32_t hi)
{
	for (;;) {
		uint32_t cnt = rd16(TBCNT);

		if (((rd16(TBSTS) & 1U) != 0) == up && cnt >= lo && cnt <= hi)
			return;
		hs_sim_run_for(MS / 1000U);
	}
}

/* CMPA = 2500 loaded, then CMPA = 7500 written early in a period with CMPCTL load
 * mode mode; the low fraction just before and after the period instant and the
 * next zero. */
static void load_around(unsigned mode, double low[3])
{
	wr16(CMPCTL, 0);
	set_cmpa(2500);
	wr16(CMPCTL, (uint16_t)mode);
	run_to_count(1000);
	wr16(CMPA, 7500);
	run_to_count(PRD - MARGIN);
	low[0] = low_a();
	run_to_count(2U * MARGIN);
	low[1] = low_a();
	hs_sim_run_for(MS);
	low[2] = low_a();
}

/* Shadowed loads at the instants the load modes name (AM1808 TRM, eHRPWM
 * counter-compare submodule: shadow-to-active load at CTR = 0, CTR = PRD, either,
 * or frozen). */
static void check_load_modes(void)
{
	double low[3];

	load_around(LOAD_ZERO, low);
	ok(is_close(low[0], 0.25) && is_close(low[1], 0.75) && is_close(low[2], 0.75),
	   "load at zero: CMPA moves after the zero instant (%.3f %.3f %.3f)", low[0], low[1], low[2]);
	load_around(LOAD_PRD, low);
	ok(is_close(low[0], 0.25) && is_close(low[1], 0.75) && is_close(low[2], 0.75),
	   "load at period: CMPA moves at the period instant (%.3f %.3f %.3f)", low[0], low[1], low[2]);
	load_around(LOAD_EITHER, low);
	ok(is_close(low[0], 0.25) && is_close(low[1], 0.75),
	   "load at zero or period: at the first of them (%.3f %.3f)", low[0], low[1]);
	load_around(LOAD_FREEZE, low);
	ok(is_close(low[0], 0.25) && is_close(low[1], 0.25) && is_close(low[2], 0.25),
	   "load frozen: CMPA never moves (%.3f %.3f %.3f)", low[0], low[1], low[2]);
	wr16(CMPCTL, LOAD_ZERO);
	hs_sim_run_for(MS);
	is_near(low_a(), 0.75, "the frozen shadow loads once the mode is zero again");

	/* load at period: the write just before the period instant loads there, one just after waits a period */
	wr16(CMPCTL, LOAD_PRD);
	run_to_count(PRD - MARGIN);
	wr16(CMPA, 5000);
	run_to_count(MARGIN);
	is_near(low_a(), 0.5, "load at period: a write just before the instant loads at it");
	wr16(CMPA, 2000);
	run_to_count(PRD - MARGIN);
	is_near(low_a(), 0.5, "... one just after waits for the next period instant");
	run_to_count(MARGIN);
	is_near(low_a(), 0.2, "... and loads there");

	/* load at zero in up-down counting, with an action-qualifier write between the
	 * period and the zero instant (counting down) */
	wr16(CMPCTL, LOAD_ZERO);
	wr16(TBCTL, 0x0032);
	wr16(AQCTLA, CAU(1) | CAD(2));
	wr16(CMPA, 2500);
	hs_sim_run_for(MS);
	run_to_updown(true, 0, PRD / 2U);
	wr16(CMPA, 5000);
	run_to_updown(false, PRD / 4U, 3U * PRD / 4U);
	is_near(low_a(), (PRD - 2500.0) / PRD, "up-down, load at zero: counting down, not yet loaded");
	wr16(AQCTLA, CAU(2) | CAD(1));
	is_near(low_a(), 2500.0 / PRD, "an AQCTLA write there acts at once on the active CMPA");
	run_to_updown(true, 0, PRD / 2U);
	is_near(low_a(), 5000.0 / PRD, "... and the shadow loads at zero under the new actions");
	wr16(TBCTL, 0x0030);
	wr16(AQCTLA, ZRO(1) | CAU(2));
	wr16(CMPA, 4000);
	hs_sim_run_for(MS);

	/* a shadowed period (TBCTL PRDLD = 0) loads at zero */
	run_to_count(1000);
	wr16(TBPRD, 7999);
	ok(fabs(hs_pwm_frequency(HS_PWM_EHRPWM1_A) - TBCLK_HZ / 10000.0) < 1e-6,
	   "shadowed TBPRD: the period holds until zero");
	hs_sim_run_for(MS);
	ok(fabs(hs_pwm_frequency(HS_PWM_EHRPWM1_A) - TBCLK_HZ / 8000.0) < 1e-6,
	   "... and is the new one after it");
	is_near(low_a(), 0.5, "CMPA = 4000 of a period of 8000");
	wr16(TBPRD, PRD);
	hs_sim_run_for(MS);
}

int main(void)
{
	double l;

	tap_plan(31);
	devtest_boot(1, NULL);
	devtest_pwm_setup();
	hs_sim_run_for(MS);

	/* up counting, low from zero to CMPA (AQCTLA) and from zero to CMPB (AQCTLB) */
	check_load_modes();
	set_cmpa(0);
	set_cmpa(2500);
	is_near(low_a(), 0.25, "A: low from zero to CMPA = 2500 of 10 000");
	is_near(low_b(), 0.0, "B: CMPB = 0 sets it high at zero");
	set_cmpa(7500);
	is_near(low_a(), 0.75, "A follows a new CMPA at the next zero");
	set_cmpa(2500);
	is_near(low_a(), 0.25, "A follows CMPA back to a setting it had");
	wr16(CMPB, 5000);
	hs_sim_run_for(MS);
	set_cmpa(1000);
	is_near(low_b(), 0.5, "B does not depend on CMPA while its actions do not use it");
	wr16(AQCTLB, ZRO(1) | CAU(2));
	hs_sim_run_for(MS);
	is_near(low_b(), 0.1, "B follows CMPA once its actions use it");
	set_cmpa(3000);
	is_near(low_b(), 0.3, "... and a change of CMPA");

	/* both compare values act on A: CMPA moves past CMPB, onto it (CMPB wins, applied
	 * last), beyond the period (no action) and back, the order of the actions changing */
	wr16(AQCTLA, ZRO(2) | CAU(1) | CBU(2));
	set_cmpa(2000);
	is_near(low_a(), 0.3, "A: high at zero, low from CMPA = 2000 to CMPB = 5000");
	set_cmpa(8000);
	is_near(low_a(), 0.2, "A: CMPA after CMPB, low from 8000 to the period's end");
	set_cmpa(5000);
	is_near(low_a(), 0.0, "A: CMPA on CMPB, CMPB's set wins");
	set_cmpa(10000);
	is_near(low_a(), 0.0, "A: CMPA beyond the period never clears");
	set_cmpa(1000);
	is_near(low_a(), 0.4, "A: CMPA back inside, before CMPB");
	wr16(AQCTLA, ZRO(1) | CAU(2));

	/* immediate compare load (CMPCTL SHDWAMODE) */
	wr16(CMPCTL, 1U << 4);
	wr16(CMPA, 4000);
	is_near(low_a(), 0.4, "immediate CMPA acts without waiting for zero");

	/* toggles: the fraction depends on the level the output had */
	wr16(AQCTLA, ZRO(3) | CAU(3));
	hs_sim_run_for(MS);
	l = low_a();
	ok(fabs(l - 0.4) < 1e-12 || fabs(l - 0.6) < 1e-12, "toggle at zero and CMPA: low 40 %% or 60 %% (%.3f)", l);
	wr16(AQCTLA, ZRO(3));
	hs_sim_run_for(MS);
	is_near(low_a(), 0.5, "toggle at zero only: low every other period");

	/* up-down counting: set at CMPA going up, clear at CMPA going down */
	wr16(TBCTL, 0x0032);
	wr16(AQCTLA, CAU(1) | CAD(2));
	wr16(CMPA, 2500);
	hs_sim_run_for(MS);
	is_near(low_a(), 2.0 * (PRD - 2500) / (2.0 * PRD),
		"up-down: low between CMPA up and CMPA down");
	wr16(AQCTLA, CAU(2) | CAD(1));
	hs_sim_run_for(MS);
	is_near(low_a(), 2.0 * 2500 / (2.0 * PRD), "up-down, inverted actions: the complement");

	hs_sim_shutdown();
	return tap_done();
}
