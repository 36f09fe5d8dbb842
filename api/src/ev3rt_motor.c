/*
 * ev3rt_motor.c — EV3RT's motor calls (ev3api_motor.h) as thin wrappers over
 * ev3lx's checked forms: values are returned (0 and a warning on error),
 * power is clamped, and set_power means a regulated speed on large and
 * medium motors as it does in EV3RT.
 */
#include "ev3api_motor.h"
#include "ev3api_sensor.h"
#include "api_internal.h"

#define POWER_MAX 100

/* power limited to -100..100, with a warning when it was outside. */
static int clamp_power(const char *call, motor_port_t port, int power)
{
	int clamped = power > POWER_MAX ? POWER_MAX : power < -POWER_MAX ? -POWER_MAX : power;

	if (clamped != power)
		syslog(LOG_WARNING, "%s(%d): power %d clamped to %d", call, (int)port, power, clamped);
	return clamped;
}

ER ev3_motor_config(motor_port_t port, motor_type_t type)
{
	return ev3lx_motor_config(port, type);
}

ER_UINT ev3_motor_get_type(motor_port_t port)
{
	motor_type_t type = NONE_MOTOR;
	ER ercd = ev3lx_motor_get_type(port, &type);

	return ercd == E_OK ? (ER_UINT)type : ercd;
}

int32_t ev3_motor_get_counts(motor_port_t port)
{
	int32_t counts = 0;
	ER ercd = ev3lx_motor_get_counts(port, &counts);

	if (ercd != E_OK) {
		api_warn(__func__, (int)port, ercd);
		return 0;
	}
	return counts;
}

ER ev3_motor_reset_counts(motor_port_t port)
{
	return ev3lx_motor_reset_counts(port);
}

ER ev3_motor_set_power(motor_port_t port, int power)
{
	motor_type_t type = NONE_MOTOR;
	ER ercd = ev3lx_motor_get_type(port, &type);

	if (ercd != E_OK)
		return ercd;
	power = clamp_power(__func__, port, power);
	if (type == UNREGULATED_MOTOR)
		return ev3lx_motor_set_power(port, power);
	return ev3lx_motor_set_speed(port, power);	/* E_OBJ for a port without a motor */
}

int ev3_motor_get_power(motor_port_t port)
{
	int speed = 0;
	ER ercd = ev3lx_motor_get_speed(port, &speed);

	if (ercd != E_OK) {
		api_warn(__func__, (int)port, ercd);
		return 0;
	}
	return speed;
}

ER ev3_motor_stop(motor_port_t port, bool_t brake)
{
	return ev3lx_motor_stop(port, brake != 0);
}

ER ev3_motor_rotate(motor_port_t port, int degrees, uint32_t speed_abs, bool_t blocking)
{
	int32_t as_signed = (int32_t)speed_abs;
	int speed = (int)(speed_abs > POWER_MAX ? POWER_MAX : speed_abs);

	if (as_signed < 0 && as_signed >= -POWER_MAX) {
		/* EV3RT multiplies speed_abs into the command's signed byte, so a
		 * negative speed turns the other way there (ev3rt-git/ev3rt-hrp2-sdk,
		 * common/ev3api/src/ev3api_motor.c): apps rely on it. */
		speed = (int)as_signed;
		syslog(LOG_WARNING, "%s(%d): speed_abs %ld is negative: turning the other way, as EV3RT does",
		       __func__, (int)port, (long)as_signed);
	} else if (speed_abs > POWER_MAX) {
		syslog(LOG_WARNING, "%s(%d): speed %lu clamped to %d", __func__, (int)port,
		       (unsigned long)speed_abs, speed);
	}
	return ev3lx_motor_rotate(port, degrees, speed, blocking != 0);
}

ER ev3_motor_steer(motor_port_t left_motor, motor_port_t right_motor, int power, int turn_ratio)
{
	if (turn_ratio < -100 || turn_ratio > 100)
		return E_PAR;
	power = clamp_power(__func__, left_motor, power);
	return ev3lx_motor_steer(left_motor, right_motor, power, 2 * turn_ratio);
}
