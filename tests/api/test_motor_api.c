/*
 * test_motor_api.c — the motor API end to end: application task -> ev3api ->
 * pwm_hack service calls -> d_pwm -> linux_compat -> simulated eHRPWM/eCAP,
 * GPIO and motors.  Values are checked against the motor models.
 */
#include <stdlib.h>
#include "api_test.h"

static int32_t global_counts;   /* outside the application's domain */
static ER ctx_result;

static void attach(void)
{
	ev3_attach_motor(0, HS_MOTOR_LARGE, NULL);
	ev3_attach_motor(1, HS_MOTOR_LARGE, NULL);
	ev3_attach_motor(3, HS_MOTOR_MEDIUM, NULL);
}

static double model_angle(unsigned port)
{
	return hs_motor_angle_deg(ev3_output_motor(port));
}

static void call_from_interrupt(void *arg)
{
	(void)arg;
	ctx_result = ev3lx_motor_set_speed(EV3_PORT_A, 10);
}

static void body(void)
{
	int32_t counts = 0;
	int speed = 0;
	bool busy = true;
	motor_type_t type = NONE_MOTOR;

	/* configuration and its errors */
	is_int(ev3lx_motor_set_speed(EV3_PORT_A, 50), E_OBJ, "set_speed before config: E_OBJ");
	is_int(ev3lx_motor_config(EV3_PORT_A, LARGE_MOTOR), E_OK, "config A large");
	is_int(ev3lx_motor_config(EV3_PORT_B, LARGE_MOTOR), E_OK, "config B large");
	is_int(ev3lx_motor_config(EV3_PORT_D, MEDIUM_MOTOR), E_OK, "config D medium");
	is_int(ev3lx_motor_config(TNUM_MOTOR_PORT, LARGE_MOTOR), E_ID, "config bad port: E_ID");
	is_int(ev3lx_motor_config(EV3_PORT_C, (motor_type_t)9), E_PAR, "config bad type: E_PAR");
	is_int(ev3lx_motor_get_type(EV3_PORT_D, &type), E_OK, "get_type");
	is_int(type, MEDIUM_MOTOR, "D is medium");

	/* regulated speed reaches the model's speed */
	is_int(ev3lx_motor_set_speed(EV3_PORT_A, 50), E_OK, "set_speed A 50");
	dly_tsk(600);
	is_int(ev3lx_motor_get_speed(EV3_PORT_A, &speed), E_OK, "get_speed");
	in_range(speed, 45, 55, "measured speed about 50");
	is_int(ev3lx_motor_get_counts(EV3_PORT_A, &counts), E_OK, "get_counts");
	in_range(counts - model_angle(0), -3, 3, "counts follow the shaft angle (%d)", (int)counts);
	ok(counts > 200, "the motor turned forwards (%d deg)", (int)counts);

	/* braking holds the position */
	is_int(ev3lx_motor_stop(EV3_PORT_A, true), E_OK, "stop with brake");
	dly_tsk(300);
	double held = model_angle(0);
	dly_tsk(300);
	in_range(model_angle(0) - held, -2, 2, "braked motor holds its position");

	/* counts reset */
	is_int(ev3lx_motor_reset_counts(EV3_PORT_A), E_OK, "reset_counts");
	dly_tsk(4);
	ev3lx_motor_get_counts(EV3_PORT_A, &counts);
	in_range(counts, -1, 1, "counts are zero after reset");

	/* rotate, blocking and not */
	double start = model_angle(0);
	is_int(ev3lx_motor_rotate(EV3_PORT_A, 360, 50, true), E_OK, "rotate 360 blocking");
	dly_tsk(800);
	in_range(model_angle(0) - start, 355, 365, "turned by 360 degrees (+-5)");
	start = model_angle(0);
	is_int(ev3lx_motor_rotate(EV3_PORT_A, -180, 30, false), E_OK, "rotate -180 non-blocking");
	dly_tsk(10);
	is_int(ev3lx_motor_is_busy(EV3_PORT_A, &busy), E_OK, "is_busy");
	ok(busy, "busy while rotating");
	for (int i = 0; i < 300 && busy; i++) {
		dly_tsk(10);
		ev3lx_motor_is_busy(EV3_PORT_A, &busy);
	}
	ok(!busy, "not busy when done");
	dly_tsk(800);       /* the brake's hold pulls the overshoot back */
	in_range(model_angle(0) - start, -185, -175, "turned back by 180 degrees (+-5)");

	/* unregulated power, reverse */
	start = model_angle(3);
	is_int(ev3lx_motor_set_power(EV3_PORT_D, -60), E_OK, "set_power D -60");
	dly_tsk(300);
	ok(model_angle(3) < start - 30, "medium motor runs backwards on negative power");
	is_int(ev3lx_motor_stop(EV3_PORT_D, false), E_OK, "coast D");

	/* synchronised pair keeps the turn ratio */
	double a0 = model_angle(0), b0 = model_angle(1);
	is_int(ev3lx_motor_steer(EV3_PORT_A, EV3_PORT_B, 40, 50), E_OK, "steer A/B 40, turn 50");
	dly_tsk(1000);
	double da = model_angle(0) - a0, db = model_angle(1) - b0;
	ok(da > 100, "left wheel turns (%.0f deg)", da);
	in_range(db / da, 0.4, 0.6, "right wheel at half the left's speed (ratio %.2f)", db / da);
	ev3lx_motor_stop(EV3_PORT_A, true);
	ev3lx_motor_stop(EV3_PORT_B, true);
	is_int(ev3lx_motor_steer(EV3_PORT_A, EV3_PORT_A, 40, 0), E_PAR, "steer a motor with itself: E_PAR");
	is_int(ev3lx_motor_steer(EV3_PORT_A, EV3_PORT_B, 40, 201), E_PAR, "turn 201: E_PAR");
	is_int(ev3lx_motor_sync(EV3_PORT_A, EV3_PORT_B, 40, 0, 0), E_PAR, "sync 0 degrees: E_PAR");

	/* the other error paths */
	is_int(ev3lx_motor_set_speed(EV3_PORT_A, 101), E_PAR, "speed 101: E_PAR");
	is_int(ev3lx_motor_set_speed(EV3_PORT_A, -101), E_PAR, "speed -101: E_PAR");
	is_int(ev3lx_motor_set_power((motor_port_t)-1, 10), E_ID, "port -1: E_ID");
	is_int(ev3lx_motor_set_speed(EV3_PORT_C, 10), E_OBJ, "unconfigured port: E_OBJ");
	ev3lx_motor_config(EV3_PORT_C, UNREGULATED_MOTOR);
	is_int(ev3lx_motor_set_speed(EV3_PORT_C, 10), E_OBJ, "speed on an unregulated motor: E_OBJ");
	is_int(ev3lx_motor_rotate(EV3_PORT_A, 90, 0, false), E_PAR, "rotate at speed 0: E_PAR");
	is_int(ev3lx_motor_get_counts(EV3_PORT_A, NULL), E_MACV, "NULL counts: E_MACV");
	is_int(ev3lx_motor_get_counts(EV3_PORT_A, &global_counts), E_MACV,
	       "counts into memory outside the domain: E_MACV");
	is_int(ev3lx_motor_get_type(EV3_PORT_A, (motor_type_t *)&global_counts), E_MACV,
	       "get_type into memory outside the domain: E_MACV");

	/* non-task context */
	ctx_result = E_OK;
	hs_sim_at(rtos_host_now() + 1000, call_from_interrupt, NULL);
	dly_tsk(1);
	is_int(ctx_result, E_CTX, "set_speed from interrupt context: E_CTX");
}

int main(void)
{
	tap_plan(45);
	ok(at_run(attach, body, 1, 30), "the application finished");
	return tap_done();
}
