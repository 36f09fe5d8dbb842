/*
 * test_pwm_lego_behaviour.c — what applications see of d_pwm, held to the
 * behaviour of LEGO's lms2012 motor driver on the same byte streams (two
 * large motors on A and B, watched every 10 ms as an application would):
 *
 *  1. a command re-issued every 1, 4 or 10 ms keeps the speed a single one
 *     gives (the regulator keeps its accumulated power) — deliberately also a
 *     STEP_/TIME_SPEED without ramps, which LEGO's runs ~25 % fast re-issued
 *     every 1-4 ms, and a ramped TIME_SPEED, which LEGO's runs at 315-920 deg/s;
 *  2. braking steps close in on their end as LEGO's do and stop on it (a
 *     large motor less than a degree past, as LEGO's up to 0.6, a medium
 *     one up to LEGO's 0.6 / 2.4 degrees past); a 90-count STEP_SPEED at
 *     speed 30 is busy 570-676 ms; TIME_SYNC overshoots by at most 3
 *     degrees; 2b. steps from rest take, and braking TIME_SPEEDs travel,
 *     within 5 % of LEGO's figures; 2c. SPEED 50 and 100 run at LEGO's
 *     speeds, and reversed without a stop they reach 90 % of the speed the
 *     other way in LEGO's time, MOTORDATA Speed showing what LEGO's shows;
 *  3. MOTORDATA TachoCounts counts from the start of the current command
 *     (0 while unlimited, 0 again when a step ends, from the stop after a
 *     STOP); TachoSensor is cumulative; a step counts from where
 *     TachoCounts is 0: from the stop after a coast STOP (the motor still
 *     coasting, or at rest past it), from the first of two steps re-issued;
 *  4. a brake hold settles within 250 ms and then stays put;
 *  5. MOTORDATA Speed after STOP: 0 at the first sample, then the measured
 *     speed of the coasting (or settling) motor from 50 ms on;
 *  6. and what already matched stays: regulated speed within its unit, POWER 30
 *     at 323 deg/s, reversal, polarity, CLR_COUNT, TIME_SPEED's end time.
 */
#define PWM_TEST_LIMIT_NS (400ULL * 1000 * 1000 * 1000)
#include "pwm_test.h"

#define PORT_A      0U
#define PORT_B      1U
#define PORT_C      2U      /* a medium motor */
#define PAIR        0x03U
#define SAMPLE_MS   10

/* Waits until the busy mask clears the port bits or limit_ms passes; the time waited. */
static double wait_idle(uint8_t mask, double limit_ms)
{
	double t0 = now_ms();

	while ((pwm_busy() & mask) && now_ms() - t0 < limit_ms)
		dly_tsk(1);
	return now_ms() - t0;
}

/* Coasts both motors, lets them come to rest and zeroes TachoCounts there
 * (OUTPUT_RESET), so that the next step counts from where they rest, not
 * from where STOP found them. */
static void rest(void)
{
	pwm_cmd_value(LMS_PWM_OUTPUT_STOP, PAIR, 0);
	dly_tsk(1500);
	pwm_cmd(LMS_PWM_OUTPUT_RESET, PAIR);
}

/* Mean speeds (deg/s) of A and B over ms, while send() is called every period ms. */
static void speeds_while(void (*send)(void), RELTIM period, RELTIM ms, double dps[2])
{
	double a0 = motor_angle(PORT_A), b0 = motor_angle(PORT_B), t0 = now_ms(), dt;

	while (now_ms() - t0 < ms) {
		if (send)
			send();
		dly_tsk(period);
	}
	dt = (now_ms() - t0) / 1000.0;
	dps[0] = (motor_angle(PORT_A) - a0) / dt;
	dps[1] = (motor_angle(PORT_B) - b0) / dt;
}

/* Runs a command once (period 0) or every period ms for 2 s; the mean speeds of its last second. */
static void steady_speeds(void (*send)(void), RELTIM period, double dps[2])
{
	send();
	if (period == 0) {
		speeds_while(NULL, SAMPLE_MS, 1000, dps);
		speeds_while(NULL, SAMPLE_MS, 1000, dps);
	} else {
		speeds_while(send, period, 1000, dps);
		speeds_while(send, period, 1000, dps);
	}
	rest();
}

static int sync_turn;
static int sync_speed = 40;

static void send_sync(void)
{
	pwm_cmd_sync(LMS_PWM_OUTPUT_STEP_SYNC, PAIR, sync_speed, sync_turn, 0, 0);
}

static void send_speed(void)
{
	pwm_cmd_value(LMS_PWM_OUTPUT_SPEED, PAIR, 40);
	pwm_cmd(LMS_PWM_OUTPUT_START, PAIR);
}

static void send_power(void)
{
	pwm_cmd_value(LMS_PWM_OUTPUT_POWER, PAIR, 30);
	pwm_cmd(LMS_PWM_OUTPUT_START, PAIR);
}

static void send_step_speed(void)
{
	pwm_cmd_step(LMS_PWM_OUTPUT_STEP_SPEED, PAIR, 40, 30, 100000, 30, 0);
}

static void send_time_speed(void)
{
	pwm_cmd_step(LMS_PWM_OUTPUT_TIME_SPEED, PAIR, 40, 100, 100000, 100, 0);
}

static void send_step_speed_flat(void)
{
	pwm_cmd_step(LMS_PWM_OUTPUT_STEP_SPEED, PAIR, 40, 0, 100000, 0, 0);
}

static void send_time_speed_flat(void)
{
	pwm_cmd_step(LMS_PWM_OUTPUT_TIME_SPEED, PAIR, 40, 0, 100000, 0, 0);
}

static bool near(double got, double want, double tolerance)
{
	return fabs(got - want) <= tolerance * fabs(want);
}

/* 1. The same command every period ms runs at the speed one command gives. */
static void test_reissued(const char *what, void (*send)(void))
{
	static const RELTIM periods[] = { 1, 4, 10 };
	double once[2], again[2];

	steady_speeds(send, 0, once);
	tap_diag("%s once: A %.0f, B %.0f deg/s", what, once[0], once[1]);
	for (unsigned i = 0; i < sizeof(periods) / sizeof(periods[0]); i++) {
		steady_speeds(send, periods[i], again);
		ok(near(again[0], once[0], 0.03) && near(again[1], once[1], 0.03),
		   "%s every %u ms: A %.0f, B %.0f deg/s (once: %.0f, %.0f; +-3%%)", what,
		   (unsigned)periods[i], again[0], again[1], once[0], once[1]);
	}
}

static void test_reissue(void)
{
	double dps[2];

	sync_turn = 0;
	test_reissued("STEP_SYNC 40 turn 0", send_sync);
	steady_speeds(send_sync, 0, dps);
	ok(near(dps[0], 405, 0.03) && near(dps[1], 405, 0.03),
	   "STEP_SYNC 40 turn 0 runs at 400-410 deg/s (%.0f, %.0f)", dps[0], dps[1]);
	sync_turn = 50;
	test_reissued("STEP_SYNC 40 turn 50", send_sync);
	steady_speeds(send_sync, 4, dps);
	ok(near(dps[1], dps[0] / 2, 0.05), "turn 50 re-issued: the slave at half the master (%.0f of %.0f)",
	   dps[1], dps[0]);
	sync_turn = 200;
	test_reissued("STEP_SYNC 40 turn 200", send_sync);
	sync_turn = 0;
	test_reissued("SPEED 40 + START", send_speed);
	test_reissued("POWER 30 + START", send_power);
	test_reissued("STEP_SPEED 40", send_step_speed);
	test_reissued("TIME_SPEED 40", send_time_speed);
	/* LEGO's runs these at ~510 deg/s re-issued every 1-4 ms (it clears its regulator each time) */
	test_reissued("STEP_SPEED 40 without ramps", send_step_speed_flat);
	test_reissued("TIME_SPEED 40 without ramps", send_time_speed_flat);

	/* A changed value changes the target, smoothly: 40 then 60, re-issued every 4 ms. */
	sync_speed = 40;
	speeds_while(send_sync, 4, 1000, dps);
	sync_speed = 60;
	speeds_while(send_sync, 4, 1000, dps);
	speeds_while(send_sync, 4, 1000, dps);
	sync_speed = 40;
	ok(near(dps[0], PWM_LARGE_DPS(60), 0.03) && near(dps[1], PWM_LARGE_DPS(60), 0.03),
	   "STEP_SYNC re-issued 40 then 60: at %.0f, %.0f deg/s (want %.0f)", dps[0], dps[1],
	   PWM_LARGE_DPS(60));
	rest();
}

/* Largest travel beyond the end position in the direction of travel, after busy clears. */
static double overshoot_after(unsigned port, double end, int sign, RELTIM ms)
{
	double worst = 0;

	for (RELTIM t = 0; t < ms; t++) {
		double beyond = (motor_angle(port) - end) * sign;

		if (beyond > worst)
			worst = beyond;
		dly_tsk(1);
	}
	return worst;
}

/* 2. Steps approach their target and stop on it. */
static void test_step_end(int speed, int32_t counts)
{
	double a0 = motor_angle(PORT_A), took, over, end;
	int sign = speed < 0 ? -1 : 1;

	pwm_cmd_step(LMS_PWM_OUTPUT_STEP_SPEED, 1U << PORT_A, speed, 0, counts, 0, 1);
	took = wait_idle(1U << PORT_A, 5000);
	end = a0 + sign * counts;
	over = overshoot_after(PORT_A, end, sign, 800);
	ok(over <= 1.0 && fabs(motor_angle(PORT_A) - end) <= 1.0,
	   "STEP_SPEED %d for %d counts: overshoot %.2f deg (LEGO's 0-0.6, <= 1), ends %.2f off (<= 1), busy %.0f ms",
	   speed, counts, over, motor_angle(PORT_A) - end, took);
	rest();
}

/* The same on the medium motor, whose regulator has other gains and which
 * closes in over a third of its speed in counts: it runs past its end by up
 * to max_over degrees before the hold pulls it back (LEGO's: 0.6 at speed 30,
 * 2.4 at speed 90). */
static void test_step_end_medium(int speed, int32_t counts, double max_over)
{
	double c0 = motor_angle(PORT_C), took, over, end;

	pwm_cmd_step(LMS_PWM_OUTPUT_STEP_SPEED, 1U << PORT_C, speed, 0, counts, 0, 1);
	took = wait_idle(1U << PORT_C, 5000);
	end = c0 + counts;
	over = overshoot_after(PORT_C, end, 1, 800);
	ok(over <= max_over && fabs(motor_angle(PORT_C) - end) <= 1.0,
	   "medium STEP_SPEED %d for %d counts: overshoot %.2f deg (<= %.1f), ends %.2f off, busy %.0f ms",
	   speed, counts, over, max_over, motor_angle(PORT_C) - end, took);
	pwm_cmd_value(LMS_PWM_OUTPUT_STOP, 1U << PORT_C, 0);
	dly_tsk(1000);
}

static void test_approach(void)
{
	double a0 = motor_angle(PORT_A), b0 = motor_angle(PORT_B), took, over_a, over_b, end_a, end_b;

	pwm_cmd_step(LMS_PWM_OUTPUT_STEP_SPEED, 1U << PORT_A, 30, 0, 90, 0, 1);
	took = wait_idle(1U << PORT_A, 5000);
	ok(took >= 560 && took <= 700, "STEP_SPEED 30 for 90 counts busy %.0f ms (LEGO's 570-676)", took);
	rest();
	test_step_end(30, 90);
	test_step_end(50, 360);
	test_step_end(-50, 360);
	test_step_end(80, 720);
	test_step_end_medium(30, 90, 1.0);
	test_step_end_medium(90, 360, 3.0);

	a0 = motor_angle(PORT_A);
	b0 = motor_angle(PORT_B);
	pwm_cmd_sync(LMS_PWM_OUTPUT_STEP_SYNC, PAIR, 40, 0, 720, 1);
	took = wait_idle(PAIR, 5000);
	over_a = overshoot_after(PORT_A, a0 + 720, 1, 400);
	over_b = overshoot_after(PORT_B, b0 + 720, 1, 400);
	end_a = motor_angle(PORT_A) - a0 - 720;
	end_b = motor_angle(PORT_B) - b0 - 720;
	ok(over_a <= 0.5 && over_b <= 1.0 && fabs(end_a) <= 1.0 && fabs(end_b) <= 2.0,
	   "STEP_SYNC 40 for 720: overshoot %.2f, %.2f deg, ends %.2f, %.2f off, busy %.0f ms",
	   over_a, over_b, end_a, end_b, took);
	rest();

	pwm_cmd_sync(LMS_PWM_OUTPUT_TIME_SYNC, PAIR, 40, 0, 1000, 1);
	took = wait_idle(PAIR, 5000);
	a0 = motor_angle(PORT_A);
	b0 = motor_angle(PORT_B);
	over_a = overshoot_after(PORT_A, a0, 1, 400);
	over_b = overshoot_after(PORT_B, b0, 1, 400);
	ok(over_a <= 3.0 && over_b <= 3.0 && fabs(took - 1000) <= 10,
	   "TIME_SYNC 40 for 1000 ms: overshoot %.2f, %.2f deg (<= 3), busy %.0f ms", over_a, over_b,
	   took);
	rest();
}

/* 3. TachoCounts per command, TachoSensor cumulative. */
static void test_counters(void)
{
	struct lms_motor_data md;
	int32_t sensor0 = motor_data_of(PORT_A).tacho_sensor, worst = 0, after;
	int64_t pins0 = hs_motor_tacho_counts(ev3_output_motor(PORT_A)), pins;

	pwm_cmd_value(LMS_PWM_OUTPUT_SPEED, 1U << PORT_A, 40);
	pwm_cmd(LMS_PWM_OUTPUT_START, 1U << PORT_A);
	for (int i = 0; i < 100; i++) {
		dly_tsk(SAMPLE_MS);
		md = motor_data_of(PORT_A);
		if (abs(md.tacho_counts) > abs(worst))
			worst = md.tacho_counts;
	}
	ok(worst == 0, "TachoCounts 0 throughout an unlimited run (worst %d)", worst);
	md = motor_data_of(PORT_A);
	pins = hs_motor_tacho_counts(ev3_output_motor(PORT_A)) - pins0;
	ok(llabs(md.tacho_sensor - sensor0 - pins) <= 1,
	   "TachoSensor cumulative: %d counts for the encoder's %lld", md.tacho_sensor - sensor0,
	   (long long)pins);

	pwm_cmd_value(LMS_PWM_OUTPUT_STOP, 1U << PORT_A, 1);
	dly_tsk(SAMPLE_MS);
	md = motor_data_of(PORT_A);
	after = md.tacho_counts;
	dly_tsk(500);
	md = motor_data_of(PORT_A);
	ok(abs(after) <= 8 && abs(md.tacho_counts) <= 8,
	   "after STOP with brake TachoCounts counts from the stop (%d, then %d)", after,
	   md.tacho_counts);
	rest();

	sensor0 = motor_data_of(PORT_A).tacho_sensor;
	pwm_cmd_step(LMS_PWM_OUTPUT_STEP_SPEED, 1U << PORT_A, 40, 0, 180, 0, 1);
	dly_tsk(200);
	md = motor_data_of(PORT_A);
	ok(md.tacho_counts > 20 && md.tacho_counts < 180, "during a step TachoCounts counts it (%d)",
	   md.tacho_counts);
	while (pwm_busy() & (1U << PORT_A))
		dly_tsk(1);
	dly_tsk(SAMPLE_MS);
	md = motor_data_of(PORT_A);
	ok(abs(md.tacho_counts) <= 1, "reset to 0 when the step ends (%d)", md.tacho_counts);
	ok(abs(md.tacho_sensor - sensor0 - 180) <= 1, "while TachoSensor went on to %d",
	   md.tacho_sensor - sensor0);
	rest();
}

/* Runs A at speed 50 for a second and coasts it (OUTPUT_STOP); where it stopped. */
static double coast_stop(void)
{
	pwm_cmd_value(LMS_PWM_OUTPUT_SPEED, 1U << PORT_A, 50);
	pwm_cmd(LMS_PWM_OUTPUT_START, 1U << PORT_A);
	dly_tsk(1000);
	pwm_cmd_value(LMS_PWM_OUTPUT_STOP, 1U << PORT_A, 0);
	return motor_angle(PORT_A);
}

/* A braking STEP_SPEED 30 for 90 counts on A; where A is 300 ms after it ends. */
static double step_90_end(void)
{
	pwm_cmd_step(LMS_PWM_OUTPUT_STEP_SPEED, 1U << PORT_A, 30, 0, 90, 0, 1);
	wait_idle(1U << PORT_A, 5000);
	dly_tsk(300);
	return motor_angle(PORT_A);
}

/* Busy time of a braking STEP_SPEED on A from rest; *travel: where A ends, 300 ms later. */
static double step_busy(int speed, int32_t up, int32_t flat, int32_t down, double *travel)
{
	double a0 = motor_angle(PORT_A), took;

	pwm_cmd_step(LMS_PWM_OUTPUT_STEP_SPEED, 1U << PORT_A, speed, up, flat, down, 1);
	took = wait_idle(1U << PORT_A, 5000);
	dly_tsk(300);
	*travel = motor_angle(PORT_A) - a0;
	rest();
	return took;
}

/* A braking TIME_SPEED on A from rest: how far A went when it ended, and past that 500 ms later. */
static double timed_travel(int speed, int32_t ms, double *overshoot)
{
	double a0 = motor_angle(PORT_A), at_end;

	pwm_cmd_step(LMS_PWM_OUTPUT_TIME_SPEED, 1U << PORT_A, speed, 0, ms, 0, 1);
	wait_idle(1U << PORT_A, 5000);
	at_end = motor_angle(PORT_A) - a0;
	dly_tsk(500);
	*overshoot = motor_angle(PORT_A) - a0 - at_end;
	rest();
	return at_end;
}

/*
 * 2b. How long steps take and how far timed commands go, within 5 % of LEGO's
 * driver on the same motor: a braking step closes in on its end over half
 * its speed in counts (a large motor), asking for what is left, or for 1
 * while the motor is faster than that; a timed one over its speed in ms.
 */
static void test_lego_timings(void)
{
	double travel, took, over;

	took = step_busy(50, 0, 360, 0, &travel);
	ok(took >= 912 && took <= 1069 && fabs(travel - 360) <= 1,
	   "STEP_SPEED 50 for 360 from rest: busy %.0f ms (LEGO's 960-1018, +-5%%), ends at %.1f", took,
	   travel);
	took = step_busy(75, 0, 720, 0, &travel);
	ok(took >= 1177 && took <= 1346 && fabs(travel - 720) <= 1,
	   "STEP_SPEED 75 for 720 from rest: busy %.0f ms (LEGO's 1239-1282, +-5%%), ends at %.1f", took,
	   travel);
	took = step_busy(50, 90, 180, 90, &travel);
	ok(took >= 1413 && took <= 1577 && fabs(travel - 360) <= 1.5,
	   "STEP_SPEED 50 ramped 90/180/90: busy %.0f ms (LEGO's 1487-1502, +-5%%), ends at %.1f", took,
	   travel);
	travel = timed_travel(50, 1000, &over);
	ok(fabs(travel - 486) <= 0.05 * 486 && fabs(over) <= 2,
	   "TIME_SPEED 50 for 1 s: %.1f deg when it ends (LEGO's 486-488, +-5%%), %.1f after (LEGO's -0.2..0.9)",
	   travel, over);
	travel = timed_travel(30, 500, &over);
	ok(fabs(travel - 139) <= 0.05 * 139 && fabs(over) <= 2,
	   "TIME_SPEED 30 for 0.5 s: %.1f deg when it ends (LEGO's 139-140, +-5%%), %.1f after (LEGO's -0.2..0.7)",
	   travel, over);
}

/*
 * 2c. Reversal without a stop, SPEED +v then -v, watched as an application
 * watches it: MOTORDATA Speed at 75, 100, 150, 200 and 300 ms, and when the
 * motor reaches 90 % of its speed the other way, against LEGO's driver on
 * the same motor (twenty runs, host and arm926).  The measured speed keeps
 * its last value across the turn until a full window of the new direction is
 * in, and the window follows the newest edge interval, as LEGO's does.  From
 * +100, 7 of LEGO's 20 runs notice the turn late and show +15 until ~135 ms
 * (their 90 % point 116-119 ms); the MOTORDATA figures here are the other
 * 13, which ev3lx follows in every run.
 */
struct reversal_lego {
	int speed;                      /* +v, then -v */
	double steady_lo, steady_hi;    /* deg/s at +v before the turn */
	double took_lo, took_hi;        /* ms to 90 % of it the other way */
	int shown_lo[5], shown_hi[5];   /* MOTORDATA Speed at reversal_look_ms */
};

static const RELTIM reversal_look_ms[5] = { 75, 100, 150, 200, 300 };

static const struct reversal_lego reversals[] = {
	{ 50, 513, 514, 76, 88, { -39, -47, -56, -54, -52 }, { -36, -42, -54, -54, -52 } },
	{ 100, 1011, 1018, 116, 132, { -33, -47, -79, -96, -100 }, { -26, -38, -76, -94, -100 } },
};

static void test_reversal(const struct reversal_lego *lego)
{
	double steady, t0, took = -1;
	int shown[5];
	unsigned k = 0;
	bool shown_ok = true;

	pwm_cmd_value(LMS_PWM_OUTPUT_SPEED, 1U << PORT_A, lego->speed);
	pwm_cmd(LMS_PWM_OUTPUT_START, 1U << PORT_A);
	dly_tsk(1500);
	steady = motor_dps(PORT_A);
	ok(steady >= 0.99 * lego->steady_lo && steady <= 1.01 * lego->steady_hi,
	   "SPEED %d runs at %.0f deg/s (LEGO's %.0f-%.0f, +-1%%)", lego->speed, steady, lego->steady_lo,
	   lego->steady_hi);
	pwm_cmd_value(LMS_PWM_OUTPUT_SPEED, 1U << PORT_A, -lego->speed);
	pwm_cmd(LMS_PWM_OUTPUT_START, 1U << PORT_A);
	t0 = now_ms();
	while (now_ms() - t0 < 400) {
		if (took < 0 && motor_dps(PORT_A) <= -0.9 * steady)
			took = now_ms() - t0;
		if (k < 5 && now_ms() - t0 >= reversal_look_ms[k]) {
			shown[k] = motor_data_of(PORT_A).speed;
			/* 5 units either side: 5 % of the speed scale. */
			shown_ok &= shown[k] >= lego->shown_lo[k] - 5 && shown[k] <= lego->shown_hi[k] + 5;
			k++;
		}
		dly_tsk(1);
	}
	ok(took >= 0.95 * lego->took_lo && took <= 1.05 * lego->took_hi,
	   "SPEED %+d to %+d: 90 %% of %.0f deg/s the other way after %.0f ms (LEGO's %.0f-%.0f, +-5%%)",
	   lego->speed, -lego->speed, steady, took, lego->took_lo, lego->took_hi);
	ok(shown_ok, "SPEED %+d to %+d: MOTORDATA Speed %d / %d / %d / %d / %d at 75 / 100 / 150 / 200 / 300 ms "
	   "(LEGO's %d..%d / %d..%d / %d..%d / %d..%d / %d..%d, +-5)", lego->speed, -lego->speed,
	   shown[0], shown[1], shown[2], shown[3], shown[4], lego->shown_lo[0], lego->shown_hi[0],
	   lego->shown_lo[1], lego->shown_hi[1], lego->shown_lo[2], lego->shown_hi[2], lego->shown_lo[3],
	   lego->shown_hi[3], lego->shown_lo[4], lego->shown_hi[4]);
	rest();
}

static void test_reversal_time(void)
{
	for (unsigned i = 0; i < sizeof(reversals) / sizeof(reversals[0]); i++)
		test_reversal(&reversals[i]);
}

/* 3b. A step counts from where TachoCounts is 0 (LEGO's driver counts it in the
 * same count it zeroes at STOP, at the end of a step and while unlimited). */
static void test_step_origin(void)
{
	double stop_at, cmd_at, end;

	stop_at = coast_stop();
	dly_tsk(100);
	cmd_at = motor_angle(PORT_A);
	end = step_90_end();
	ok(cmd_at - stop_at > 30 && fabs(end - stop_at - 90) <= 1.5,
	   "a step 100 ms after a coast STOP ends 90 from the stop (%.1f; %.1f from the command, coasted %.1f)",
	   end - stop_at, end - cmd_at, cmd_at - stop_at);
	pwm_cmd_value(LMS_PWM_OUTPUT_STOP, 1U << PORT_A, 0);
	dly_tsk(1500);

	stop_at = coast_stop();
	dly_tsk(1500);
	cmd_at = motor_angle(PORT_A);
	end = step_90_end();
	ok(cmd_at - stop_at > 90 && fabs(end - stop_at - 90) <= 1.5,
	   "a step after the motor coasted %.1f past the stop to rest goes back to 90 from the stop (%.1f)",
	   cmd_at - stop_at, end - stop_at);
	rest();

	pwm_cmd_value(LMS_PWM_OUTPUT_SPEED, 1U << PORT_A, 50);
	pwm_cmd(LMS_PWM_OUTPUT_START, 1U << PORT_A);
	dly_tsk(500);
	cmd_at = motor_angle(PORT_A);
	end = step_90_end();
	ok(fabs(end - cmd_at - 90) <= 3, "a step while running unlimited counts from the command (%.1f)",
	   end - cmd_at);
	rest();

	cmd_at = motor_angle(PORT_A);
	pwm_cmd_step(LMS_PWM_OUTPUT_STEP_SPEED, 1U << PORT_A, 30, 0, 90, 0, 1);
	dly_tsk(200);
	end = step_90_end();
	ok(fabs(end - cmd_at - 90) <= 1.5, "a step re-issued 200 ms into the same step ends 90 from the first (%.1f)",
	   end - cmd_at);
	rest();
}

/* 4. Brake hold: settled within 250 ms of STOP, and still there a second later
 * (stopped at four different points within a count: the pull-back differs). */
static void test_brake_hold(void)
{
	double worst_settle = 0, worst_drift = 0, worst_off = 0;

	for (int k = 0; k < 4; k++) {
		double stop_at, angle[100], settled_ms = 0, drift;

		pwm_cmd_value(LMS_PWM_OUTPUT_SPEED, 1U << PORT_A, 40);
		pwm_cmd(LMS_PWM_OUTPUT_START, 1U << PORT_A);
		dly_tsk(1000 + 3 * k);
		stop_at = motor_angle(PORT_A);
		pwm_cmd_value(LMS_PWM_OUTPUT_STOP, 1U << PORT_A, 1);
		for (int i = 0; i < 100; i++) {
			dly_tsk(SAMPLE_MS);
			angle[i] = motor_angle(PORT_A);
		}
		for (int i = 0; i < 100; i++)
			if (fabs(angle[i] - angle[99]) > 0.5)
				settled_ms = (i + 1) * SAMPLE_MS;
		drift = angle[99] - angle[24];
		worst_settle = fmax(worst_settle, settled_ms);
		worst_drift = fmax(worst_drift, fabs(drift));
		worst_off = fmax(worst_off, fabs(angle[99] - stop_at));
		tap_diag("stop %d: settled after %.0f ms, %.2f deg from the stop point, drift %.2f", k,
			 settled_ms, angle[99] - stop_at, drift);
		rest();
	}
	ok(worst_settle <= 250, "brake hold settled %.0f ms after STOP at worst (<= 250)", worst_settle);
	ok(worst_drift <= 0.5, "then stays put: %.2f deg from 250 ms to 1 s at worst", worst_drift);
	ok(worst_off <= 3.0, "held %.2f deg from the stop point at worst (<= 3)", worst_off);
}

/*
 * 5. MOTORDATA Speed after STOP: 0 at the first sample (the speed history is
 * cleared, as LEGO's driver clears its samples), then what the motor does:
 * coasting, the motor's speed within 4 from 50 ms on (LEGO's: 47, 40, 34, 29);
 * braked, the speed of the slowing motor or 0 (the window fills within
 * 10-14 ms), then the brake's swing back (LEGO's: 25 at 50 ms, -16 at 100 ms).
 */
static void test_speed_after_stop(int brake)
{
	static const int at_ms[] = { 50, 100, 150, 200 };
	struct lms_motor_data md;
	double t0, worst = 0, model;
	int at_50 = 0, at_100 = 0;

	pwm_cmd_value(LMS_PWM_OUTPUT_SPEED, 1U << PORT_A, 50);
	pwm_cmd(LMS_PWM_OUTPUT_START, 1U << PORT_A);
	dly_tsk(1000);
	md = motor_data_of(PORT_A);
	ok(md.speed >= 48 && md.speed <= 52, "running: MOTORDATA Speed %d", md.speed);
	pwm_cmd_value(LMS_PWM_OUTPUT_STOP, 1U << PORT_A, brake);
	t0 = now_ms();
	dly_tsk(SAMPLE_MS);
	md = motor_data_of(PORT_A);
	if (brake)
		ok(md.speed >= 0 && md.speed <= 50,
		   "STOP brake: Speed %d at the first sample, 0 or the slowing motor's (%.0f deg/s)",
		   md.speed, motor_dps(PORT_A));
	else
		ok(md.speed == 0, "STOP coast: Speed %d at the first sample (motor still at %.0f deg/s)",
		   md.speed, motor_dps(PORT_A));
	for (unsigned i = 0; i < sizeof(at_ms) / sizeof(at_ms[0]); i++) {
		while (now_ms() - t0 < at_ms[i])
			dly_tsk(1);
		md = motor_data_of(PORT_A);
		model = motor_dps(PORT_A) / PWM_LARGE_DPS(1);
		worst = fmax(worst, fabs(md.speed - model));
		if (at_ms[i] == 50)
			at_50 = md.speed;
		if (at_ms[i] == 100)
			at_100 = md.speed;
	}
	if (brake)
		ok(at_50 >= 0 && at_50 <= 35 && at_100 >= -22 && at_100 <= -10,
		   "STOP brake: Speed %d at 50 ms, %d at 100 ms, the swing back (LEGO's: 25, -16)",
		   at_50, at_100);
	else
		ok(worst <= 4 && at_100 >= 36 && at_100 <= 44,
		   "STOP coast: from 50 ms on Speed is the motor's (%d at 100 ms, LEGO's 40; worst %.1f off)",
		   at_100, worst);
	rest();
}

/* Mean speed (deg/s) of A over its second second at an unlimited command. */
static double unlimited_dps(uint8_t op, int value)
{
	double dps[2];

	pwm_cmd_value(op, 1U << PORT_A, value);
	pwm_cmd(LMS_PWM_OUTPUT_START, 1U << PORT_A);
	speeds_while(NULL, SAMPLE_MS, 1000, dps);
	speeds_while(NULL, SAMPLE_MS, 1000, dps);
	return dps[0];
}

/* 6. What matched LEGO's driver before stays as it was. */
static void test_unchanged(void)
{
	double dps, took;

	dps = unlimited_dps(LMS_PWM_OUTPUT_SPEED, 50);
	ok(pwm_large_regulated_to(dps, 50), "SPEED 50 regulated to %.0f deg/s (%.0f..%.0f)", dps,
	   PWM_LARGE_DPS(50), PWM_LARGE_DPS(51));
	dps = unlimited_dps(LMS_PWM_OUTPUT_SPEED, -50);
	ok(pwm_large_regulated_to(dps, -50), "reversed without a stop: %.0f deg/s", dps);
	rest();
	dps = unlimited_dps(LMS_PWM_OUTPUT_POWER, 30);
	ok(near(dps, 323, 0.02), "POWER 30 runs at %.0f deg/s (323 +-2%%)", dps);
	rest();
	pwm_cmd_value(LMS_PWM_OUTPUT_POLARITY, 1U << PORT_A, -1);
	dps = unlimited_dps(LMS_PWM_OUTPUT_SPEED, 40);
	pwm_cmd_value(LMS_PWM_OUTPUT_POLARITY, 1U << PORT_A, 1);
	ok(pwm_large_regulated_to(dps, -40), "polarity -1: SPEED 40 runs at %.0f deg/s", dps);
	rest();
	pwm_cmd(LMS_PWM_OUTPUT_CLR_COUNT, 1U << PORT_A);
	dly_tsk(SAMPLE_MS);
	ok(motor_data_of(PORT_A).tacho_sensor == 0, "CLR_COUNT: TachoSensor 0");
	pwm_cmd_step(LMS_PWM_OUTPUT_TIME_SPEED, 1U << PORT_A, 40, 0, 500, 0, 0);
	took = wait_idle(1U << PORT_A, 2000);
	ok(fabs(took - 500) <= 5, "TIME_SPEED 500 ms: busy %.0f ms (+-1%%)", took);
	rest();
}

static void body(void)
{
	ok(pwm_set_types(LMS_PWM_TYPE_TACHO, LMS_PWM_TYPE_TACHO, LMS_PWM_TYPE_MINITACHO,
			 LMS_PWM_TYPE_TACHO) == E_OK, "SET_TYPE large on A and B, medium on C");
	test_reissue();
	test_approach();
	test_lego_timings();
	test_reversal_time();
	test_counters();
	test_step_origin();
	test_brake_hold();
	test_speed_after_stop(1);
	test_speed_after_stop(0);
	test_unchanged();
}

int main(void)
{
	const int motors[4] = { HS_MOTOR_LARGE, HS_MOTOR_LARGE, HS_MOTOR_MEDIUM,
				PWM_TEST_NO_MOTOR };

	tap_plan(77);
	ok(pwm_test_run(body, motors), "test body ran to its end");
	return tap_done();
}
