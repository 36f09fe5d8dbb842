/*
 * test_ehrpwm.c — eHRPWM1's outputs as a motor sees them: the low fraction
 * of each period for the action qualifiers a driver sets (up and up-down
 * counting, set/clear and toggle actions, shadowed and immediate compare
 * loads), that a compare value reaches only the output whose actions
 * use it, also when a setting is left and taken again, and that a moving
 * compare value changes the order of the actions right.
 */
#include <math.h>
#include "devtest.h"
#include "host_sim/devices/pwm.h"

#define PWM1     HS_EHRPWM1_BASE
#define TBCTL    (PWM1 + 0x00)
#define TBPRD    (PWM1 + 0x0A)
#define CMPCTL   (PWM1 + 0x0E)
#define CMPA     (PWM1 + 0x12)
#define CMPB     (PWM1 + 0x14)
#define AQCTLA   (PWM1 + 0x16)
#define AQCTLB   (PWM1 + 0x18)
#define PRD      9999U          /* devtest_pwm_setup's period: 10 000 counts up */

/* AQCTL actions (AM1808 TRM, eHRPWM action-qualifier control): 1 clear, 2 set, 3 toggle. */
#define ZRO(a)   ((a) << 0)
#define CAU(a)   ((a) << 4)
#define CAD(a)   ((a) << 6)
#define CBU(a)   ((a) << 8)

/* A fraction computed exactly as expected (within rounding). */
#define is_near(got, expected, ...) in_range(got, (expected) - 1e-12, (expected) + 1e-12, __VA_ARGS__)

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

int main(void)
{
	double l;

	tap_plan(17);
	devtest_boot(1, NULL);
	devtest_pwm_setup();
	hs_sim_run_for(MS);

	/* up counting, low from zero to CMPA (AQCTLA) and from zero to CMPB (AQCTLB) */
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
