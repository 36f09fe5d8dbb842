/*
 * test_api_context.c — the API checks its context before it does anything
 * (docs/api.md, "Context"): with the CPU locked every call is E_CTX; with
 * dispatching disabled the commands (service calls that may wait) are E_CTX
 * and readings of the shared memory work; no call reaches a driver, so the
 * kernel reports no sleeping call in atomic context and no motor moves.
 * Misaligned out-pointers are E_PAR, never a misaligned store; a synchronised
 * run that could never end (speed 0) is E_PAR.
 */
#include <string.h>
#include "api_test.h"

static void attach(void)
{
	ev3_attach_motor(0, HS_MOTOR_LARGE, NULL);
	ev3_attach_motor(1, HS_MOTOR_LARGE, NULL);
	ev3_attach_uart_sensor(1, UART_SENSOR_TYPE_GYRO, NULL);
}

/* Every command (a service call that may wait: is_busy is a read() of d_pwm); the count of those not E_CTX. */
static unsigned commands_not_refused(void)
{
	bool busy;
	unsigned bad = 0;

	bad += ev3lx_motor_config(EV3_PORT_A, LARGE_MOTOR) != E_CTX;
	bad += ev3lx_motor_set_speed(EV3_PORT_A, 50) != E_CTX;
	bad += ev3lx_motor_set_power(EV3_PORT_A, 50) != E_CTX;
	bad += ev3lx_motor_stop(EV3_PORT_A, true) != E_CTX;
	bad += ev3lx_motor_reset_counts(EV3_PORT_A) != E_CTX;
	bad += ev3lx_motor_rotate(EV3_PORT_A, 90, 50, false) != E_CTX;
	bad += ev3lx_motor_steer(EV3_PORT_A, EV3_PORT_B, 50, 0) != E_CTX;
	bad += ev3lx_motor_sync(EV3_PORT_A, EV3_PORT_B, 50, 0, 90) != E_CTX;
	bad += ev3lx_sensor_config(EV3_PORT_2, GYRO_SENSOR) != E_CTX;
	bad += ev3lx_gyro_sensor_reset(EV3_PORT_2) != E_CTX;
	bad += ev3lx_led_set_color(LED_RED) != E_CTX;
	bad += ev3lx_button_set_on_clicked(ENTER_BUTTON, NULL, 0) != E_CTX;
	bad += ev3lx_motor_is_busy(EV3_PORT_A, &busy) != E_CTX;
	return bad;
}

/* Every reading; the count of those that did not return want. */
static unsigned readings_not(ER want)
{
	int32_t counts;
	int speed;
	bool pressed;
	int16_t rate;
	motor_type_t mtype;
	sensor_type_t stype;
	uint8_t raw[2];
	unsigned bad = 0;

	bad += ev3lx_motor_get_counts(EV3_PORT_A, &counts) != want;
	bad += ev3lx_motor_get_speed(EV3_PORT_A, &speed) != want;
	bad += ev3lx_motor_get_type(EV3_PORT_A, &mtype) != want;
	bad += ev3lx_sensor_get_type(EV3_PORT_2, &stype) != want;
	bad += ev3lx_gyro_sensor_get_rate(EV3_PORT_2, &rate) != want;	/* data is there: no wait */
	bad += ev3lx_uart_sensor_get_raw(EV3_PORT_2, raw, sizeof(raw)) != want;
	bad += ev3lx_button_is_pressed(ENTER_BUTTON, &pressed) != want;
	return bad;
}

static void body(void)
{
	int32_t before, after, counts;
	int16_t rate;
	bool pressed;
	unsigned bugs = rtos_host_bug_count();
	union {
		int32_t align;
		uint8_t bytes[16];
	} buf;

	ok(ev3lx_motor_config(EV3_PORT_A, LARGE_MOTOR) == E_OK &&
	   ev3lx_motor_config(EV3_PORT_B, LARGE_MOTOR) == E_OK &&
	   ev3lx_sensor_config(EV3_PORT_2, GYRO_SENSOR) == E_OK, "motors on A, B and the gyro on 2");
	ok(ev3lx_gyro_sensor_get_rate(EV3_PORT_2, &rate) == E_OK, "the gyro answers");
	ok(ev3lx_button_is_pressed(ENTER_BUTTON, &pressed) == E_OK, "the buttons' memory is mapped");
	is_int(ev3lx_motor_get_counts(EV3_PORT_A, &before), E_OK, "counts read");

	loc_cpu();
	is_int(commands_not_refused(), 0, "CPU locked: every command is E_CTX");
	is_int(readings_not(E_CTX), 0, "CPU locked: every reading is E_CTX");
	unl_cpu();

	dis_dsp();
	is_int(commands_not_refused(), 0, "dispatching disabled: every command is E_CTX");
	is_int(readings_not(E_OK), 0, "dispatching disabled: readings of the shared memory work");
	ena_dsp();

	dly_tsk(300);
	is_int(ev3lx_motor_get_counts(EV3_PORT_A, &after), E_OK, "counts read again");
	ok(after - before >= -1 && after - before <= 1, "no refused command reached the motor (%d -> %d)",
	   (int)before, (int)after);
	is_int(rtos_host_bug_count() - bugs, 0, "no sleeping call in atomic context reached the kernel");

	is_int(ev3lx_motor_get_counts(EV3_PORT_A, (int32_t *)(void *)&buf.bytes[1]), E_PAR,
	       "a misaligned int32_t out-pointer is E_PAR");
	is_int(ev3lx_gyro_sensor_get_rate(EV3_PORT_2, (int16_t *)(void *)&buf.bytes[3]), E_PAR,
	       "a misaligned int16_t out-pointer is E_PAR");
	is_int(ev3lx_color_sensor_get_rgb_raw(EV3_PORT_2, (rgb_raw_t *)(void *)&buf.bytes[1]), E_OBJ,
	       "a gyro port is no colour sensor: E_OBJ before the pointer");
	is_int(ev3lx_uart_sensor_get_raw(EV3_PORT_2, &buf.bytes[1], 2), E_OK,
	       "a byte buffer has no alignment");
	is_int(ev3lx_motor_get_counts(EV3_PORT_A, &counts), E_OK, "an aligned one works");

	is_int(ev3lx_motor_sync(EV3_PORT_A, EV3_PORT_B, 0, 0, 360), E_PAR,
	       "sync at speed 0 could never finish: E_PAR");
	is_int(ev3lx_motor_steer(EV3_PORT_A, EV3_PORT_B, 0, 0), E_OK, "steer at speed 0 holds still");
}

int main(void)
{
	tap_plan(19);
	ok(at_run(attach, body, 15, 20), "the application finished");
	return tap_done();
}
