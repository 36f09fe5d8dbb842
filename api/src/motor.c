/*
 * motor.c — the EV3 motor API over d_pwm's extended service calls.
 *
 * Commands go to d_pwm through pwm_hack's service calls (one call per API
 * call: the hot path of ev3lx_motor_set_speed is one cal_svc, PWM_FN_RUN,
 * whose values travel in registers; the hack runs OUTPUT_SPEED and
 * OUTPUT_START through the driver's handlers).  Counts and speed are read from
 * the MOTORDATA array d_pwm publishes (its /dev/lms_motor mapping), which the
 * driver refreshes every 2 ms.
 */
#include <string.h>
#include "ev3api_motor.h"
#include "ev3api_sensor.h"
#include "api_internal.h"
#include "pwm_hack.h"

/* What each output port was configured as (NONE_MOTOR until ev3lx_motor_config). */
static motor_type_t motor_type[TNUM_MOTOR_PORT];
/* d_pwm's MOTORDATA[4], mapped at the first configuration. */
static const volatile struct lms_motor_data *motor_data;

/* Polling period of a blocking rotate, in ms (d_pwm's control period is 2 ms). */
#define ROTATE_POLL_MS 2U

static inline uint8_t port_bit(motor_port_t port)
{
	return (uint8_t)(1U << (unsigned)port);
}

/* E_OK if port is valid and configured as one of the types in mask. */
static ER check_motor(motor_port_t port, unsigned type_mask)
{
	if ((unsigned)port >= TNUM_MOTOR_PORT)
		return E_ID;
	if (!(type_mask & (1U << motor_type[port])))
		return E_OBJ;
	return E_OK;
}

#define ANY_MOTOR       ((1U << MEDIUM_MOTOR) | (1U << LARGE_MOTOR) | (1U << UNREGULATED_MOTOR))
#define REGULATED_MOTOR ((1U << MEDIUM_MOTOR) | (1U << LARGE_MOTOR))

/* A command is a service call that may wait in the driver. */
static ER check_command(motor_port_t port, unsigned type_mask)
{
	ER ercd = api_may_wait();

	return ercd != E_OK ? ercd : check_motor(port, type_mask);
}

/* A reading of the shared memory (the out-pointer is checked after this). */
static ER check_reading(motor_port_t port, unsigned type_mask)
{
	ER ercd = api_may_read();

	return ercd != E_OK ? ercd : check_motor(port, type_mask);
}

/* d_pwm's device type for an API motor type. */
static uint8_t lms_type_of(motor_type_t type)
{
	switch (type) {
	case MEDIUM_MOTOR:
		return LMS_PWM_TYPE_MINITACHO;
	case LARGE_MOTOR:
	case UNREGULATED_MOTOR:
		return LMS_PWM_TYPE_TACHO;
	default:
		return LMS_PWM_TYPE_NONE;
	}
}

void api_motor_boot(void)
{
	memset(motor_type, 0, sizeof(motor_type));
	motor_data = NULL;
}

ER ev3lx_motor_config(motor_port_t port, motor_type_t type)
{
	uint8_t cmd[5];
	motor_type_t old;
	ER ercd;

	ercd = api_may_wait();
	if (ercd != E_OK)
		return ercd;
	if ((unsigned)port >= TNUM_MOTOR_PORT)
		return E_ID;
	if ((unsigned)type >= TNUM_MOTOR_TYPE)
		return E_PAR;
	if (motor_data == NULL) {
		const struct lms_motor_data *map = NULL;

		ercd = pwm_motor_map(&map);
		if (ercd != E_OK)
			return ercd;
		motor_data = map;
	}
	old = motor_type[port];
	motor_type[port] = type;
	cmd[0] = LMS_PWM_OUTPUT_SET_TYPE;
	for (unsigned i = 0; i < TNUM_MOTOR_PORT; i++)
		cmd[1 + i] = lms_type_of(motor_type[i]);
	ercd = pwm_command(cmd, sizeof(cmd));
	if (ercd != E_OK) {
		motor_type[port] = old;
		return ercd;
	}
	/* SET_TYPE only resets a port whose type changed; a reconfiguration resets too. */
	cmd[0] = LMS_PWM_OUTPUT_CLR_COUNT;
	cmd[1] = port_bit(port);
	return pwm_command(cmd, 2);
}

ER ev3lx_motor_get_type(motor_port_t port, motor_type_t *p_type)
{
	ER ercd = api_may_read();

	if (ercd != E_OK)
		return ercd;
	if ((unsigned)port >= TNUM_MOTOR_PORT)
		return E_ID;
	ercd = API_CHECK_OUT(p_type);
	if (ercd != E_OK)
		return ercd;
	*p_type = motor_type[port];
	return E_OK;
}

/* Sends OUTPUT_POWER or OUTPUT_SPEED with the value, then OUTPUT_START, in one call. */
static ER run_motor(motor_port_t port, uint8_t opcode, int value, unsigned type_mask)
{
	ER ercd;

	ercd = check_command(port, type_mask);
	if (ercd != E_OK)
		return ercd;
	if (value < -100 || value > 100)
		return E_PAR;
	return pwm_run(opcode, (uint_t)port, value);
}

ER ev3lx_motor_set_speed(motor_port_t port, int speed)
{
	return run_motor(port, LMS_PWM_OUTPUT_SPEED, speed, REGULATED_MOTOR);
}

ER ev3lx_motor_set_power(motor_port_t port, int power)
{
	return run_motor(port, LMS_PWM_OUTPUT_POWER, power, ANY_MOTOR);
}

ER ev3lx_motor_get_speed(motor_port_t port, int *p_speed)
{
	ER ercd = check_reading(port, ANY_MOTOR);

	if (ercd == E_OK)
		ercd = API_CHECK_OUT(p_speed);
	if (ercd != E_OK)
		return ercd;
	*p_speed = (int)motor_data[port].speed;	/* signed: -100..100 */
	return E_OK;
}

ER ev3lx_motor_stop(motor_port_t port, bool brake)
{
	uint8_t cmd[3];
	ER ercd;

	ercd = check_command(port, ANY_MOTOR);
	if (ercd != E_OK)
		return ercd;
	cmd[0] = LMS_PWM_OUTPUT_STOP;
	cmd[1] = port_bit(port);
	cmd[2] = brake ? 1U : 0U;
	return pwm_command(cmd, sizeof(cmd));
}

ER ev3lx_motor_get_counts(motor_port_t port, int32_t *p_counts)
{
	ER ercd = check_reading(port, ANY_MOTOR);

	if (ercd == E_OK)
		ercd = API_CHECK_OUT(p_counts);
	if (ercd != E_OK)
		return ercd;
	*p_counts = motor_data[port].tacho_sensor;
	return E_OK;
}

ER ev3lx_motor_reset_counts(motor_port_t port)
{
	uint8_t cmd[2];
	ER ercd;

	ercd = check_command(port, ANY_MOTOR);
	if (ercd != E_OK)
		return ercd;
	cmd[0] = LMS_PWM_OUTPUT_CLR_COUNT;
	cmd[1] = port_bit(port);
	return pwm_command(cmd, sizeof(cmd));
}

static void put_s32(uint8_t *p, int32_t v)
{
	uint32_t u = (uint32_t)v;

	p[0] = (uint8_t)u;
	p[1] = (uint8_t)(u >> 8);
	p[2] = (uint8_t)(u >> 16);
	p[3] = (uint8_t)(u >> 24);
}

ER ev3lx_motor_is_busy(motor_port_t port, bool *p_busy)
{
	ER_UINT busy;
	ER ercd = check_command(port, ANY_MOTOR);	/* a read() of d_pwm: a service call */

	if (ercd == E_OK)
		ercd = API_CHECK_OUT(p_busy);
	if (ercd != E_OK)
		return ercd;
	busy = pwm_busy();
	if (busy < 0)
		return (ER)busy;
	*p_busy = ((unsigned)busy & port_bit(port)) != 0;
	return E_OK;
}

/* Waits until none of the ports in mask is busy, at most timeout_ms. */
static ER wait_not_busy(uint8_t mask, RELTIM timeout_ms)
{
	for (RELTIM waited = 0;; waited += ROTATE_POLL_MS) {
		ER_UINT busy = pwm_busy();

		if (busy < 0)
			return (ER)busy;
		if (!((unsigned)busy & mask))
			return E_OK;
		if (waited >= timeout_ms)
			return E_TMOUT;
		dly_tsk(ROTATE_POLL_MS);
	}
}

/* A generous bound for turning degrees at speed: the time at a quarter of the
 * nominal speed (speed 100 ~ 1000 deg/s) plus a second for the ramps. */
static RELTIM rotate_timeout_ms(int degrees, int speed)
{
	uint32_t deg = (uint32_t)(degrees < 0 ? -degrees : degrees);
	uint32_t spd = (uint32_t)(speed < 0 ? -speed : speed);

	/* cppcheck-suppress zerodivcond ; speed is never 0: ev3lx_motor_rotate answers E_PAR first */
	return (RELTIM)(1000U + deg * 400U / spd);
}

ER ev3lx_motor_rotate(motor_port_t port, int degrees, int speed, bool blocking)
{
	uint8_t cmd[LMS_PWM_STEP_LEN];
	ER ercd;

	ercd = check_command(port, REGULATED_MOTOR);
	if (ercd != E_OK)
		return ercd;
	if (speed < -100 || speed > 100 || speed == 0 || degrees == 0 ||
	    degrees < -10000000 || degrees > 10000000)
		return E_PAR;
	if (degrees < 0) {
		degrees = -degrees;
		speed = -speed;
	}
	memset(cmd, 0, sizeof(cmd));
	cmd[0] = LMS_PWM_OUTPUT_STEP_SPEED;
	cmd[LMS_PWM_STEP_OFF_NOS] = port_bit(port);
	cmd[LMS_PWM_STEP_OFF_VALUE] = (uint8_t)(int8_t)speed;
	put_s32(&cmd[LMS_PWM_STEP_OFF_STEP2], degrees);
	cmd[LMS_PWM_STEP_OFF_BRAKE] = 1;
	ercd = pwm_command(cmd, sizeof(cmd));
	if (ercd != E_OK || !blocking)
		return ercd;
	return wait_not_busy(port_bit(port), rotate_timeout_ms(degrees, speed));
}

/* STEP_SYNC for a pair; d_pwm orders the pair by port number, so the turn's
 * sign is flipped when the left motor has the higher port number. */
static ER sync_pair(motor_port_t left, motor_port_t right, int speed, int turn, int degrees)
{
	uint8_t cmd[LMS_PWM_SYNC_LEN];
	ER ercd;

	ercd = check_command(left, REGULATED_MOTOR);
	if (ercd == E_OK)
		ercd = check_command(right, REGULATED_MOTOR);
	if (ercd != E_OK)
		return ercd;
	if (left == right || speed < -100 || speed > 100 || turn < -200 || turn > 200)
		return E_PAR;
	if (left > right)
		turn = -turn;
	memset(cmd, 0, sizeof(cmd));
	cmd[0] = LMS_PWM_OUTPUT_STEP_SYNC;
	cmd[LMS_PWM_SYNC_OFF_NOS] = (uint8_t)(port_bit(left) | port_bit(right));
	cmd[LMS_PWM_SYNC_OFF_SPEED] = (uint8_t)(int8_t)speed;
	cmd[LMS_PWM_SYNC_OFF_TURN] = (uint8_t)(uint16_t)(int16_t)turn;
	cmd[LMS_PWM_SYNC_OFF_TURN + 1] = (uint8_t)((uint16_t)(int16_t)turn >> 8);
	put_s32(&cmd[LMS_PWM_SYNC_OFF_STEP], degrees);
	/* a limited run ends braked; an endless one runs until the next command */
	cmd[LMS_PWM_SYNC_OFF_BRAKE] = degrees != 0 ? 1U : 0U;
	return pwm_command(cmd, sizeof(cmd));
}

ER ev3lx_motor_steer(motor_port_t left, motor_port_t right, int speed, int turn)
{
	return sync_pair(left, right, speed, turn, 0);
}

ER ev3lx_motor_sync(motor_port_t left, motor_port_t right, int speed, int turn, int degrees)
{
	/* at speed 0 the pair would never cover the distance: the call could never finish */
	if (degrees <= 0 || degrees > 10000000 || speed == 0)
		return E_PAR;
	return sync_pair(left, right, speed, turn, degrees);
}
