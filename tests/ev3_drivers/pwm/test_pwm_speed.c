/*
 * test_pwm_speed.c — d_pwm speed regulation on the simulated large and medium
 * motors: OUTPUT_SPEED + OUTPUT_START reach the speed the protocol defines
 * (speed 100 = CountsPerPulse over the stamp clock) within 5 % in under
 * 300 ms and hold it; MOTORDATA reports the speed and the counts.
 */
#include "pwm_test.h"

/* Runs port at speed; returns the first time (ms after START) from which the
 * model stays within 5 % of want_dps until 600 ms, or -1. */
static double settle_time(unsigned port, int speed, double want_dps)
{
	double t0, settled = -1;

	ok(pwm_cmd_value(LMS_PWM_OUTPUT_SPEED, 1U << port, speed) == E_OK, "OUTPUT_SPEED %d", speed);
	ok(pwm_cmd(LMS_PWM_OUTPUT_START, 1U << port) == E_OK, "OUTPUT_START");
	t0 = now_ms();
	while (now_ms() - t0 < 600) {
		double err = fabs(motor_dps(port) - want_dps) / fabs(want_dps);

		if (err > 0.05)
			settled = -1;
		else if (settled < 0)
			settled = now_ms() - t0;
		dly_tsk(2);
	}
	return settled;
}

static void body(void)
{
	double t;
	struct lms_motor_data md;

	ok(pwm_set_types(LMS_PWM_TYPE_TACHO, LMS_PWM_TYPE_MINITACHO, LMS_PWM_TYPE_TACHO,
			 LMS_PWM_TYPE_TACHO) == E_OK, "SET_TYPE large, medium, large, large");

	t = settle_time(0, 50, PWM_LARGE_DPS(50));
	tap_diag("large: settled after %.1f ms at %.1f deg/s (want %.1f)", t, motor_dps(0),
		 PWM_LARGE_DPS(50));
	ok(t >= 0 && t < 300, "large motor at SPEED 50 within 5%% in under 300 ms");
	md = motor_data_of(0);
	ok(md.speed >= 48 && md.speed <= 52, "MOTORDATA speed %d near 50", md.speed);

	t = settle_time(1, 50, PWM_MEDIUM_DPS(50));
	tap_diag("medium: settled after %.1f ms at %.1f deg/s (want %.1f)", t, motor_dps(1),
		 PWM_MEDIUM_DPS(50));
	ok(t >= 0 && t < 300, "medium motor at SPEED 50 within 5%% in under 300 ms");

	t = settle_time(2, -30, PWM_LARGE_DPS(-30));
	ok(t >= 0 && t < 300, "large motor at SPEED -30 within 5%% in under 300 ms (%.1f ms)", t);
	md = motor_data_of(2);
	ok(md.speed <= -28 && md.speed >= -32, "MOTORDATA speed %d near -30", md.speed);

	t = settle_time(3, 90, PWM_LARGE_DPS(90));
	ok(t >= 0 && t < 300, "large motor at SPEED 90 within 5%% in under 300 ms (%.1f ms)", t);
}

int main(void)
{
	const int motors[4] = { HS_MOTOR_LARGE, HS_MOTOR_MEDIUM, HS_MOTOR_LARGE, HS_MOTOR_LARGE };

	tap_plan(16);
	ok(pwm_test_run(body, motors), "test body ran to its end");
	return tap_done();
}
