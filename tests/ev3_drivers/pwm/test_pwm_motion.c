/*
 * test_pwm_motion.c — d_pwm's limited commands and counters on simulated
 * motors: STEP_SPEED stops within +-2 degrees of its target, TIME_SPEED runs
 * for its time +-1 control tick (2 ms), a braked motor holds its position
 * under load, tacho counts follow the shaft both ways, CLR_COUNT resets.
 */
#include "pwm_test.h"

#define TICK_MS 2.0

/* Waits until the busy mask clears the port bits or limit_ms passes; the time waited. */
static double wait_idle(uint8_t mask, double limit_ms)
{
	double t0 = now_ms();

	while ((pwm_busy() & mask) && now_ms() - t0 < limit_ms)
		dly_tsk(1);
	return now_ms() - t0;
}

static void test_step_speed(unsigned port, int speed, int32_t s1, int32_t s2, int32_t s3)
{
	double a0 = motor_angle(port), moved, want = (speed < 0 ? -1 : 1) * (double)(s1 + s2 + s3);

	ok(pwm_cmd_step(LMS_PWM_OUTPUT_STEP_SPEED, 1U << port, speed, s1, s2, s3, 1) == E_OK,
	   "STEP_SPEED %d: %d/%d/%d counts, brake", speed, s1, s2, s3);
	ok(pwm_busy() & (1U << port), "port busy while stepping");
	wait_idle(1U << port, 10000);
	ok(!(pwm_busy() & (1U << port)), "busy bit cleared at the end");
	dly_tsk(800);       /* the hold pulls the overshoot back */
	moved = motor_angle(port) - a0;
	ok(fabs(moved - want) <= 2.0, "stopped at %.2f deg for a target of %.0f (+-2)", moved, want);
}

static void test_step_power(unsigned port, int power, int32_t s1, int32_t s2, int32_t s3)
{
	double a0 = motor_angle(port), moved, want = (power < 0 ? -1 : 1) * (double)(s1 + s2 + s3);

	ok(pwm_cmd_step(LMS_PWM_OUTPUT_STEP_POWER, 1U << port, power, s1, s2, s3, 1) == E_OK,
	   "STEP_POWER %d: %d/%d/%d counts, brake", power, s1, s2, s3);
	wait_idle(1U << port, 10000);
	ok(!(pwm_busy() & (1U << port)), "busy bit cleared at the end");
	dly_tsk(800);
	moved = motor_angle(port) - a0;
	ok(fabs(moved - want) <= 2.0, "unregulated step stopped at %.2f deg for %.0f (+-2)", moved, want);
}

static void test_time_speed(unsigned port, int speed, int32_t ms)
{
	double t0, took, dps_mid;

	ok(pwm_cmd_step(LMS_PWM_OUTPUT_TIME_SPEED, 1U << port, speed, 0, ms, 0, 0) == E_OK,
	   "TIME_SPEED %d for %d ms", speed, ms);
	t0 = now_ms();
	dly_tsk((RELTIM)(ms / 2));
	dps_mid = motor_dps(port);
	wait_idle(1U << port, ms + 1000);
	took = now_ms() - t0;
	ok(fabs(took - ms) <= TICK_MS, "busy for %.1f ms of %d (+-1 tick)", took, ms);
	ok(fabs(dps_mid - PWM_LARGE_DPS(speed)) < 0.1 * fabs(PWM_LARGE_DPS(speed)),
	   "running at speed midway (%.0f deg/s)", dps_mid);
	dly_tsk(1000);
	ok(fabs(motor_dps(port)) < 1.0, "coasted to a stop afterwards");
}

/* Counts between the port's count now and held (the driver holds its count to +-1). */
static int32_t count_off(unsigned port, int32_t held)
{
	return motor_data_of(port).tacho_sensor - held;
}

static void test_brake_under_load(unsigned port)
{
	struct hs_motor *m = ev3_output_motor(port);
	double held, worst = 0;
	int32_t held_count;

	ok(pwm_cmd_value(LMS_PWM_OUTPUT_SPEED, 1U << port, 40) == E_OK &&
	   pwm_cmd(LMS_PWM_OUTPUT_START, 1U << port) == E_OK, "runs at 40");
	dly_tsk(300);
	ok(pwm_cmd_value(LMS_PWM_OUTPUT_STOP, 1U << port, 1) == E_OK, "STOP with brake");
	dly_tsk(800);       /* pulled back from the overshoot and settled */
	held = motor_angle(port);
	held_count = motor_data_of(port).tacho_sensor;
	hs_motor_set_load(m, 0.10, 0);       /* a quarter of the stall torque pushing back */
	for (int i = 0; i < 500; i++) {
		dly_tsk(1);
		if (fabs(motor_angle(port) - held) > worst)
			worst = fabs(motor_angle(port) - held);
	}
	ok(worst <= 8.0, "gives at most %.2f deg to a 0.1 N m load (<= 8)", worst);
	ok(abs(count_off(port, held_count)) <= 2 && fabs(motor_angle(port) - held) <= 3.0,
	   "and is back at its count while loaded (%d counts, %.2f deg)", count_off(port, held_count),
	   motor_angle(port) - held);
	hs_motor_set_load(m, -0.10, 0);
	dly_tsk(800);
	ok(abs(count_off(port, held_count)) <= 2 && fabs(motor_angle(port) - held) <= 3.0,
	   "holds against the reverse load (%d counts, %.2f deg)", count_off(port, held_count),
	   motor_angle(port) - held);
	hs_motor_set_load(m, 0, 0);
	dly_tsk(800);
	ok(abs(count_off(port, held_count)) <= 2 && fabs(motor_angle(port) - held) <= 3.0,
	   "at the braked position without load (%d counts, %.2f deg)", count_off(port, held_count),
	   motor_angle(port) - held);
	ok(pwm_cmd_value(LMS_PWM_OUTPUT_STOP, 1U << port, 0) == E_OK, "STOP coast releases it");
}

static void test_tacho(unsigned port)
{
	struct hs_motor *m = ev3_output_motor(port);
	struct lms_motor_data md;

	pwm_cmd_value(LMS_PWM_OUTPUT_SPEED, 1U << port, 60);
	pwm_cmd(LMS_PWM_OUTPUT_START, 1U << port);
	dly_tsk(700);
	md = motor_data_of(port);
	ok(llabs(md.tacho_sensor - hs_motor_tacho_counts(m)) <= 1 &&
	   fabs(md.tacho_sensor - motor_angle(port)) <= 2.0,
	   "forward: counts %d follow the shaft (%.1f deg)", md.tacho_sensor, motor_angle(port));
	pwm_cmd_value(LMS_PWM_OUTPUT_SPEED, 1U << port, -60);
	dly_tsk(1500);
	md = motor_data_of(port);
	ok(llabs(md.tacho_sensor - hs_motor_tacho_counts(m)) <= 1 &&
	   fabs(md.tacho_sensor - motor_angle(port)) <= 2.0,
	   "reverse: counts %d follow the shaft (%.1f deg)", md.tacho_sensor, motor_angle(port));
	ok(md.speed < -50, "speed reported negative (%d)", md.speed);
	for (int i = 0; i < 6; i++) {      /* quick reversals */
		pwm_cmd_value(LMS_PWM_OUTPUT_SPEED, 1U << port, i & 1 ? 80 : -80);
		dly_tsk(150);
	}
	pwm_cmd_value(LMS_PWM_OUTPUT_STOP, 1U << port, 1);
	dly_tsk(800);
	md = motor_data_of(port);
	ok(md.tacho_sensor == hs_motor_tacho_counts(m),
	   "at rest after reversals: counts %d equal the pins' %lld", md.tacho_sensor,
	   (long long)hs_motor_tacho_counts(m));
	ok(fabs(md.tacho_sensor - motor_angle(port)) <= 1.0,
	   "at rest: counts %d equal the shaft angle %.2f to a count", md.tacho_sensor,
	   motor_angle(port));
	ok(md.speed == 0, "speed 0 at rest");

	ok(pwm_cmd(LMS_PWM_OUTPUT_CLR_COUNT, 1U << port) == E_OK, "CLR_COUNT");
	dly_tsk(4);
	ok(motor_data_of(port).tacho_sensor == 0, "sensor count reset to 0");
	pwm_cmd_step(LMS_PWM_OUTPUT_STEP_SPEED, 1U << port, 30, 0, 90, 0, 1);
	wait_idle(1U << port, 5000);
	dly_tsk(800);
	md = motor_data_of(port);
	ok(md.tacho_sensor >= 88 && md.tacho_sensor <= 92, "counts from 0 again after CLR_COUNT (%d)",
	   md.tacho_sensor);
	ok(abs(md.tacho_counts) <= 2,
	   "TachoCounts back to 0 when the step command ended (%d)", md.tacho_counts);
}

/* A sync pair (master = first port for turn >= 0): the slave keeps its share of the travel. */
static void test_sync(unsigned mport, unsigned sport, int speed, int turn, double ratio)
{
	uint8_t nos = (uint8_t)((1U << mport) | (1U << sport));
	double m0 = motor_angle(mport), s0 = motor_angle(sport), dm, ds;

	ok(pwm_cmd_sync(LMS_PWM_OUTPUT_TIME_SYNC, nos, speed, turn, 1500, 1) == E_OK,
	   "TIME_SYNC speed %d turn %d for 1.5 s", speed, turn);
	ok((pwm_busy() & nos) == nos, "both ports busy");
	for (int i = 0; i < 5; i++) {
		dly_tsk(250);
		dm = motor_angle(mport) - m0;
		ds = motor_angle(sport) - s0;
		if (fabs(ds - ratio * dm) > 4.0 + 0.02 * fabs(dm))
			break;
	}
	ok(fabs(ds - ratio * dm) <= 4.0 + 0.02 * fabs(dm),
	   "slave %.1f deg for master %.1f deg: ratio %.3f (want %.2f) throughout", ds, dm,
	   dm != 0 ? ds / dm : 0.0, ratio);
	ok(fabs(dm) > 300, "the master moved (%.0f deg)", dm);
	wait_idle(nos, 2000);
	ok((pwm_busy() & nos) == 0, "both busy bits cleared at the end");
	dly_tsk(800);
	dm = motor_angle(mport) - m0;
	ds = motor_angle(sport) - s0;
	ok(fabs(ds - ratio * dm) <= 4.0 + 0.02 * fabs(dm), "braked pair keeps the ratio (%.1f / %.1f)",
	   ds, dm);
}

static void test_step_sync(void)
{
	double a0 = motor_angle(0), d0 = motor_angle(3);

	ok(pwm_cmd_sync(LMS_PWM_OUTPUT_STEP_SYNC, 0x09, 40, 0, 720, 1) == E_OK,
	   "STEP_SYNC A+D speed 40 straight for 720 counts");
	wait_idle(0x09, 5000);
	dly_tsk(800);
	ok(fabs(motor_angle(0) - a0 - 720) <= 3.0 && fabs(motor_angle(3) - d0 - 720) <= 6.0,
	   "both near 720 (%.1f, %.1f)", motor_angle(0) - a0, motor_angle(3) - d0);
	ok(pwm_cmd_sync(LMS_PWM_OUTPUT_TIME_SYNC, 0x09, 40, 0, 0, 0) == E_OK, "TIME_SYNC forever");
	dly_tsk(300);
	ok(pwm_cmd_value(LMS_PWM_OUTPUT_SPEED, 0x01, 20) == E_OK, "a new command on one motor of the pair");
	dly_tsk(2);
	ok((pwm_busy() & 0x09) == 0, "dissolves the pair: both not busy");
	dly_tsk(1000);
	ok(fabs(motor_dps(3)) < 1.0, "the partner floats to a stop");
	pwm_cmd_value(LMS_PWM_OUTPUT_STOP, 0x09, 0);
}

static void body(void)
{
	ok(pwm_set_types(LMS_PWM_TYPE_TACHO, LMS_PWM_TYPE_MINITACHO, LMS_PWM_TYPE_TACHO,
			 LMS_PWM_TYPE_TACHO) == E_OK, "SET_TYPE");
	test_step_speed(0, 50, 0, 360, 0);
	test_step_speed(0, -50, 0, 360, 0);
	test_step_speed(1, 75, 90, 540, 90);
	test_step_speed(2, 20, 30, 60, 30);
	test_step_power(3, 60, 45, 180, 45);
	test_step_power(1, -40, 0, 270, 0);
	test_time_speed(3, 40, 500);
	test_time_speed(3, -60, 1001);
	test_brake_under_load(0);
	test_tacho(2);
	test_sync(0, 3, 50, 0, 1.0);
	test_sync(0, 3, 50, 50, 0.5);
	test_sync(3, 0, -40, -150, -0.5);   /* turn < 0: the second port leads */
	test_sync(0, 2, 30, 200, -1.0);
	test_step_sync();
}

int main(void)
{
	const int motors[4] = { HS_MOTOR_LARGE, HS_MOTOR_MEDIUM, HS_MOTOR_LARGE, HS_MOTOR_LARGE };

	tap_plan(79);
	ok(pwm_test_run(body, motors), "test body ran to its end");
	return tap_done();
}
