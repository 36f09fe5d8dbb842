/*
 * pwm_test.h — running d_pwm tests on the simulated brick.
 *
 * pwm_test_run boots host_sim with every EV3 peripheral model, the motors
 * the test asks for on ports A..D, linux_compat (whose worker runs d_pwm's
 * module_init first) and pwm_hack_cfg, then runs the test body in a task of
 * the given domain until it returns.  The body talks to the driver the way
 * applications do: through pwm_hack.h's service calls.
 */
#ifndef EV3LX_TESTS_PWM_TEST_H
#define EV3LX_TESTS_PWM_TEST_H

#include <math.h>

#include "tap.h"
#include "kernel.h"
#include "rtos_host.h"
#include <linux_compat/config.h>
#include "host_sim/scenario.h"
#include "host_sim/devices/ev3_brick.h"
#include "pwm_hack.h"

#define PWM_TEST_TASK_ID     1
#define PWM_TEST_STACK       (64 * 1024)
#define PWM_TEST_NO_MOTOR    (-1)
#ifndef PWM_TEST_LIMIT_NS        /* virtual time a test body may take */
#define PWM_TEST_LIMIT_NS    (120ULL * 1000 * 1000 * 1000)
#endif

/* Speed 100 in counts (degrees) per second: CountsPerPulse over the 7.76 us stamp. */
#define PWM_STAMP_HZ         (132000000.0 / 4.0 / 256.0)
#define PWM_LARGE_DPS(speed) ((speed) * PWM_STAMP_HZ / 12800.0)
#define PWM_MEDIUM_DPS(speed) ((speed) * PWM_STAMP_HZ / 8100.0)

/*
 * True if a large motor at dps deg/s runs at what SPEED speed gives: the
 * regulator (LEGO's integer one, and d_pwm's) stops adding power once the
 * measured whole speed is the target, so the shaft settles anywhere within
 * that unit (SPEED 40: 403..413 deg/s); 1 % either side for the averaging.
 */
static inline bool pwm_large_regulated_to(double dps, int speed)
{
	double lo = PWM_LARGE_DPS(speed < 0 ? -speed : speed);
	double hi = PWM_LARGE_DPS((speed < 0 ? -speed : speed) + 1);
	double mag = speed < 0 ? -dps : dps;

	return mag >= 0.99 * lo && mag <= 1.01 * hi;
}

static void (*pwm_test_body)(void);
static bool pwm_test_done;

static void pwm_test_task(intptr_t exinf)
{
	(void)exinf;
	pwm_test_body();
	pwm_test_done = true;
}

/* Boots the brick with motors[port] (an hs_motor_kind or PWM_TEST_NO_MOTOR),
 * runs body in a task of domain domid with extra merged in; true if the body
 * finished within the time limit. */
static inline bool pwm_test_run_in(void (*body)(void), const int motors[4], ID domid,
				   const struct rtos_cfg *extra)
{
	const struct rtos_task_cfg task = {
		PWM_TEST_TASK_ID, TA_ACT, 0, pwm_test_task, 8, PWM_TEST_STACK, domid, "pwm_test",
	};
	const struct rtos_cfg *includes[4] = { &linux_compat_cfg, &pwm_hack_cfg, extra, NULL };
	const struct rtos_cfg cfg = {
		.name = "pwm_test", .tasks = &task, .ntasks = 1, .includes = includes,
	};
	const struct hs_board_cfg board = { .devices = ev3_board_devices };
	const struct hs_scenario scn = { .rtos = &cfg, .board = &board, .seed = 1 };
	uint64_t end;

	pwm_test_body = body;
	pwm_test_done = false;
	if (hs_sim_boot(&scn) != E_OK) {
		tap_diag("boot failed");
		return false;
	}
	for (unsigned port = 0; port < 4; port++)
		if (motors[port] != PWM_TEST_NO_MOTOR &&
		    ev3_attach_motor(port, (enum hs_motor_kind)motors[port], NULL) != E_OK)
			tap_diag("could not attach a motor to port %c", 'A' + port);
	end = hs_now() + PWM_TEST_LIMIT_NS;
	while (!pwm_test_done && hs_now() < end)
		hs_sim_run_for(10ULL * 1000 * 1000);
	hs_sim_shutdown();
	return pwm_test_done;
}

static inline bool pwm_test_run(void (*body)(void), const int motors[4])
{
	return pwm_test_run_in(body, motors, TDOM_KERNEL, NULL);
}

/* ---- command builders ---- */

/* A two- or three-byte command: [op, nos] or [op, nos, value]. */
static inline ER pwm_cmd(uint8_t op, uint8_t nos)
{
	uint8_t b[2] = { op, nos };

	return pwm_command(b, sizeof(b));
}

static inline ER pwm_cmd_value(uint8_t op, uint8_t nos, int value)
{
	uint8_t b[3] = { op, nos, (uint8_t)(int8_t)value };

	return pwm_command(b, sizeof(b));
}

static inline void pwm_put_s32(uint8_t *b, int32_t v)
{
	b[0] = (uint8_t)v;
	b[1] = (uint8_t)(v >> 8);
	b[2] = (uint8_t)(v >> 16);
	b[3] = (uint8_t)(v >> 24);
}

/* STEP_/TIME_POWER/SPEED: 20 bytes. */
static inline ER pwm_cmd_step(uint8_t op, uint8_t nos, int value, int32_t s1, int32_t s2,
			      int32_t s3, int brake)
{
	uint8_t b[LMS_PWM_STEP_LEN] = { op, nos, (uint8_t)(int8_t)value };

	pwm_put_s32(b + LMS_PWM_STEP_OFF_STEP1, s1);
	pwm_put_s32(b + LMS_PWM_STEP_OFF_STEP2, s2);
	pwm_put_s32(b + LMS_PWM_STEP_OFF_STEP3, s3);
	b[LMS_PWM_STEP_OFF_BRAKE] = (uint8_t)brake;
	return pwm_command(b, sizeof(b));
}

/* STEP_/TIME_SYNC: 16 bytes. */
static inline ER pwm_cmd_sync(uint8_t op, uint8_t nos, int speed, int turn, int32_t step, int brake)
{
	uint8_t b[LMS_PWM_SYNC_LEN] = { op, nos, (uint8_t)(int8_t)speed };

	b[LMS_PWM_SYNC_OFF_TURN] = (uint8_t)turn;
	b[LMS_PWM_SYNC_OFF_TURN + 1] = (uint8_t)((uint16_t)(int16_t)turn >> 8);
	pwm_put_s32(b + LMS_PWM_SYNC_OFF_STEP, step);
	b[LMS_PWM_SYNC_OFF_BRAKE] = (uint8_t)brake;
	return pwm_command(b, sizeof(b));
}

/* OUTPUT_SET_TYPE for all four ports. */
static inline ER pwm_set_types(uint8_t a, uint8_t b, uint8_t c, uint8_t d)
{
	uint8_t cmd[5] = { LMS_PWM_OUTPUT_SET_TYPE, a, b, c, d };

	return pwm_command(cmd, sizeof(cmd));
}

/* ---- observations ---- */

static inline double motor_angle(unsigned port)
{
	return hs_motor_angle_deg(ev3_output_motor(port));
}

static inline double motor_dps(unsigned port)
{
	return hs_motor_speed_dps(ev3_output_motor(port));
}

static inline struct lms_motor_data motor_data_of(unsigned port)
{
	struct lms_motor_data md = { 0 };

	if (pwm_motor_data(port, &md) != E_OK)
		tap_diag("pwm_motor_data(%u) failed", port);
	return md;
}

/* Virtual time in ms (as a double, for timing assertions). */
static inline double now_ms(void)
{
	return (double)rtos_host_now() / 1e6;
}

#endif /* EV3LX_TESTS_PWM_TEST_H */
