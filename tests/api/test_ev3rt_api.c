/*
 * test_ev3rt_api.c — EV3RT's interface as EV3RT apps use it: the types and
 * values they compile against, getters that return values (0 and a logged
 * warning on error), set_power regulated on large/medium motors and clamped,
 * steer's turn scale, get_power, and the sensor calls EV3RT has beyond
 * ev3lx's checked forms (ultrasonic listen, infrared seek and remote).
 * The bodies are written in EV3RT's idiom: no error codes read from getters.
 */
#include <string.h>
#include "api_test.h"
#include "host_sim/devices/ev3_ui.h"

/* ---- what EV3RT apps compile against ---- */

_Static_assert(TNUM_MOTOR_PORT == 4 && EV3_PORT_D == 3, "motor ports");
_Static_assert(NONE_MOTOR == 0 && MEDIUM_MOTOR == 1 && LARGE_MOTOR == 2 &&
	       UNREGULATED_MOTOR == 3 && TNUM_MOTOR_TYPE == 4, "motor types");
_Static_assert(TNUM_SENSOR_PORT == 4 && EV3_PORT_4 == 3, "sensor ports");
_Static_assert(NONE_SENSOR == 0 && ULTRASONIC_SENSOR == 1 && GYRO_SENSOR == 2 && TOUCH_SENSOR == 3 &&
	       COLOR_SENSOR == 4 && INFRARED_SENSOR == 5 && HT_NXT_ACCEL_SENSOR == 6 &&
	       HT_NXT_COLOR_SENSOR == 7 && NXT_TEMP_SENSOR == 8 && TNUM_SENSOR_TYPE == 9,
	       "sensor types in EV3RT's order");
_Static_assert(COLOR_NONE == 0 && COLOR_BLACK == 1 && COLOR_BROWN == 7 && TNUM_COLOR == 8, "colours");
_Static_assert(sizeof(rgb_raw_t) == 6, "rgb_raw_t is three uint16_t");
_Static_assert(sizeof(ir_seek_t) == 8 && sizeof(ir_remote_t) == 4, "infrared structures");
_Static_assert(IR_RED_UP_BUTTON == 1 && IR_RED_DOWN_BUTTON == 2 && IR_BLUE_UP_BUTTON == 4 &&
	       IR_BLUE_DOWN_BUTTON == 8 && IR_BEACON_BUTTON == 16, "remote button bits");
_Static_assert(LEFT_BUTTON == 0 && RIGHT_BUTTON == 1 && UP_BUTTON == 2 && DOWN_BUTTON == 3 &&
	       ENTER_BUTTON == 4 && BACK_BUTTON == 5 && TNUM_BUTTON == 6, "buttons");
_Static_assert(LED_OFF == 0 && LED_RED == 1 && LED_GREEN == 2 && LED_ORANGE == 3, "LED colours");
_Static_assert(sizeof(motor_port_t) == sizeof(int) && sizeof(sensor_type_t) == sizeof(int) &&
	       sizeof(colorid_t) == sizeof(int) && sizeof(button_t) == sizeof(int), "enums are int-sized");
_Static_assert(EV3_LCD_WIDTH == 178 && EV3_LCD_HEIGHT == 128 && EV3_FONT_MEDIUM == 1 &&
	       EV3_LCD_BLACK == 1 && EV3_SERIAL_BT == 2 && TMAX_FILENAME_LEN == 255, "LCD, files, serial");
_Static_assert(NOTE_A4 == 440.00 && SOUND_MANUAL_STOP == -1, "sound");

/* ---- the warnings EV3RT's getters log ---- */

static char last_warning[256];
static unsigned warnings;

static void trace_sink(const char *line, void *ctx)
{
	const char *w = strstr(line, " syslog WARNING: ");

	(void)ctx;
	if (w == NULL)
		return;
	warnings++;
	snprintf(last_warning, sizeof(last_warning), "%s", w + strlen(" syslog WARNING: "));
}

/* Whether the last warning logged since the previous call contains what. */
static bool warned(const char *what)
{
	bool seen = warnings > 0 && strstr(last_warning, what) != NULL;

	if (!seen)
		tap_diag("  last warning (%u): %s", warnings, warnings ? last_warning : "none");
	warnings = 0;
	last_warning[0] = '\0';
	return seen;
}

/* ---- motors: A, B large, C a large motor run unregulated, D medium ---- */

#define LOAD_NM 0.12

static void attach_motors(void)
{
	rtos_host_trace_set_sink(trace_sink, NULL);
	ev3_attach_motor(0, HS_MOTOR_LARGE, NULL);
	ev3_attach_motor(1, HS_MOTOR_LARGE, NULL);
	ev3_attach_motor(2, HS_MOTOR_LARGE, NULL);
	ev3_attach_motor(3, HS_MOTOR_MEDIUM, NULL);
}

static double model_angle(unsigned port)
{
	return hs_motor_angle_deg(ev3_output_motor(port));
}

/*
 * ev3_motor_steer with one port as both motors is refused by the API itself,
 * before any service call: nothing reaches d_pwm.  (EV3RT's ev3api_motor.c
 * does not check it and sends d_pwm a sync of one motor.)  Seen by the cost
 * of an extended service call, made 1 ms here: the refusal takes none.
 */
static void steer_one_motor_twice(void)
{
	struct rtos_host_cpu_cost cost, ext_only = { .svc_ns = 0, .ext_svc_ns = 1000000, .kernel_domain = false };
	uint64_t t0, took;
	ER ercd;

	rtos_host_get_cpu_cost(&cost);
	rtos_host_set_cpu_cost(&ext_only);
	t0 = rtos_host_now();
	ercd = ev3_motor_steer(EV3_PORT_B, EV3_PORT_B, 30, 10);
	took = rtos_host_now() - t0;
	rtos_host_set_cpu_cost(&cost);
	is_int(ercd, E_PAR, "left and right both B: E_PAR");
	is_int(took, 0, "refused without a service call to the motor driver");
}

static void motor_body(void)
{
	double a0, b0;

	is_int(ev3_motor_config(EV3_PORT_A, LARGE_MOTOR), E_OK, "config A large");
	is_int(ev3_motor_config(EV3_PORT_B, LARGE_MOTOR), E_OK, "config B large");
	is_int(ev3_motor_config(EV3_PORT_C, UNREGULATED_MOTOR), E_OK, "config C unregulated");
	is_int(ev3_motor_config(EV3_PORT_D, MEDIUM_MOTOR), E_OK, "config D medium");
	is_int(ev3_motor_get_type(EV3_PORT_C), UNREGULATED_MOTOR, "get_type returns the type");
	is_int(ev3_motor_get_type((motor_port_t)4), E_ID, "get_type of a bad port: E_ID");

	/* set_power: a regulated speed on a large motor, a power on an unregulated one */
	hs_motor_set_load(ev3_output_motor(0), LOAD_NM, 0);
	hs_motor_set_load(ev3_output_motor(2), LOAD_NM, 0);
	is_int(ev3_motor_set_power(EV3_PORT_A, 50), E_OK, "set_power A 50");
	is_int(ev3_motor_set_power(EV3_PORT_C, 50), E_OK, "set_power C 50");
	dly_tsk(800);
	in_range(ev3_motor_get_power(EV3_PORT_A), 46, 54,
		 "large motor under load: the regulator holds speed 50");
	ok(ev3_motor_get_power(EV3_PORT_C) < ev3_motor_get_power(EV3_PORT_A) - 8,
	   "unregulated motor under the same load runs slower (%d)", ev3_motor_get_power(EV3_PORT_C));
	is_int(ev3_motor_set_power(EV3_PORT_D, -40), E_OK, "set_power D -40 (medium)");
	dly_tsk(500);
	in_range(ev3_motor_get_power(EV3_PORT_D), -44, -36, "medium motor regulated to -40");

	/* clamping */
	warnings = 0;
	is_int(ev3_motor_set_power(EV3_PORT_B, 250), E_OK, "set_power 250: clamped, E_OK");
	ok(warned("power 250 clamped to 100"), "the clamp is logged");
	dly_tsk(800);
	ok(ev3_motor_get_power(EV3_PORT_B) > 80, "B runs at full regulated speed (%d)",
	   ev3_motor_get_power(EV3_PORT_B));
	is_int(ev3_motor_set_power(EV3_PORT_B, -101), E_OK, "set_power -101: clamped");
	ok(warned("clamped to -100"), "logged");
	is_int(ev3_motor_set_power((motor_port_t)7, 10), E_ID, "set_power bad port: E_ID");

	/* getters on errors: 0 and a warning naming the call */
	is_int(ev3_motor_get_counts((motor_port_t)9), 0, "get_counts bad port: 0");
	ok(warned("ev3_motor_get_counts(9): E_ID"), "and a warning naming the call and the error");
	is_int(ev3_motor_get_power((motor_port_t)-1), 0, "get_power bad port: 0");
	ok(warned("ev3_motor_get_power(-1): E_ID"), "logged");

	/* counts, stop, rotate */
	is_int(ev3_motor_stop(EV3_PORT_A, true), E_OK, "stop A braked");
	is_int(ev3_motor_stop(EV3_PORT_B, false), E_OK, "stop B coasting");
	is_int(ev3_motor_stop(EV3_PORT_C, true), E_OK, "stop C");
	is_int(ev3_motor_stop(EV3_PORT_D, true), E_OK, "stop D");
	hs_motor_set_load(ev3_output_motor(0), 0, 0);
	dly_tsk(600);
	is_int(ev3_motor_reset_counts(EV3_PORT_A), E_OK, "reset_counts");
	dly_tsk(4);
	in_range(ev3_motor_get_counts(EV3_PORT_A), -1, 1, "counts 0 after reset");
	a0 = model_angle(0);
	is_int(ev3_motor_rotate(EV3_PORT_A, -180, 40, true), E_OK, "rotate -180 at 40, blocking");
	in_range(model_angle(0) - a0, -185, -175, "turned back by 180 degrees");
	in_range(ev3_motor_get_counts(EV3_PORT_A), -185, -175, "counts follow");
	is_int(ev3_motor_rotate(EV3_PORT_A, 90, 0, false), E_PAR, "rotate at speed 0: E_PAR");
	/* a negative speed passed as speed_abs (an unsigned parameter) turns the other way,
	 * as EV3RT's signed byte of the command makes it */
	a0 = model_angle(0);
	is_int(ev3_motor_rotate(EV3_PORT_A, 90, (uint32_t)-40, true), E_OK, "rotate 90 at speed_abs -40, blocking");
	in_range(model_angle(0) - a0, -95, -85, "turned back by 90 degrees");
	ok(warned("ev3_motor_rotate(0): speed_abs -40 is negative"), "with a warning naming the call");
	a0 = model_angle(0);
	is_int(ev3_motor_rotate(EV3_PORT_A, -90, (uint32_t)-40, true), E_OK, "rotate -90 at speed_abs -40");
	in_range(model_angle(0) - a0, 85, 95, "turned forwards by 90 degrees");

	/* steer: turn_ratio 50 is LEGO's turn 100, one wheel stopped; positive turns right */
	a0 = model_angle(0);
	b0 = model_angle(1);
	is_int(ev3_motor_steer(EV3_PORT_A, EV3_PORT_B, 40, 50), E_OK, "steer A/B 40, turn_ratio 50");
	dly_tsk(1000);
	ok(model_angle(0) - a0 > 250, "the left motor runs (%.0f deg)", model_angle(0) - a0);
	in_range(model_angle(1) - b0, -15, 15, "the right motor stands");
	a0 = model_angle(0);
	b0 = model_angle(1);
	is_int(ev3_motor_steer(EV3_PORT_B, EV3_PORT_A, 40, 50), E_OK, "steer with left B, right A");
	dly_tsk(1000);
	ok(model_angle(1) - b0 > 250, "now B (left) runs (%.0f deg)", model_angle(1) - b0);
	in_range(model_angle(0) - a0, -25, 25, "and A (right) stands");
	a0 = model_angle(0);
	b0 = model_angle(1);
	is_int(ev3_motor_steer(EV3_PORT_A, EV3_PORT_B, 30, -100), E_OK, "steer turn_ratio -100");
	dly_tsk(1000);
	ok(model_angle(0) - a0 < -150 && model_angle(1) - b0 > 150,
	   "spins on the spot (A %.0f, B %.0f)", model_angle(0) - a0, model_angle(1) - b0);
	is_int(ev3_motor_steer(EV3_PORT_A, EV3_PORT_B, 30, 101), E_PAR, "turn_ratio 101: E_PAR");
	is_int(ev3_motor_steer(EV3_PORT_A, EV3_PORT_A, 30, 0), E_PAR, "one motor twice: E_PAR");
	steer_one_motor_twice();
	ev3_motor_stop(EV3_PORT_A, true);
	ev3_motor_stop(EV3_PORT_B, true);
}

/* ---- sensors: touch 1, gyro 2, colour 3, infrared 4; then an ultrasonic ---- */

static const struct uart_sensor_scene gyro_scene = { .rate_dps = -45.0 };
static const struct uart_sensor_scene color_scene = {
	.reflect_pct = 63, .ambient_pct = 9, .color = 3, .rgb = { 120, 340, 56 },
};
static const struct uart_sensor_scene ir_scene = {
	.distance_mm = 420,
	.beacon_heading = { 0, -12, 0, 7 }, .beacon_distance = { -128, 40, -128, 88 },
	.remote_buttons = { 1, 0, 8, 9 },
};
static const struct uart_sensor_scene us_scene = { .distance_mm = 734, .other_ultrasonic = true };

static void attach_sensors(void)
{
	rtos_host_trace_set_sink(trace_sink, NULL);
	ev3_attach_analog(0, EV3_INPUT_EV3_TOUCH, NULL);
	ev3_attach_uart_sensor(1, 32, NULL);
	ev3_attach_uart_sensor(2, 29, NULL);
	ev3_attach_uart_sensor(3, 33, NULL);
	ev3_set_scene(1, &gyro_scene);
	ev3_set_scene(2, &color_scene);
	ev3_set_scene(3, &ir_scene);
}

static void sensor_body(void)
{
	rgb_raw_t rgb = { 0, 0, 0 };
	ir_seek_t seek;
	ir_remote_t remote;
	int16_t angle;

	is_int(ev3_sensor_config(EV3_PORT_1, TOUCH_SENSOR), E_OK, "config touch on 1");
	is_int(ev3_sensor_config(EV3_PORT_2, GYRO_SENSOR), E_OK, "config gyro on 2");
	is_int(ev3_sensor_config(EV3_PORT_3, COLOR_SENSOR), E_OK, "config colour on 3");
	is_int(ev3_sensor_config(EV3_PORT_4, INFRARED_SENSOR), E_OK, "config IR on 4");
	is_int(ev3_sensor_get_type(EV3_PORT_3), COLOR_SENSOR, "get_type returns the type");
	is_int(ev3_sensor_get_type((sensor_port_t)4), E_ID, "get_type bad port: E_ID");
	is_int(ev3_sensor_config(EV3_PORT_1, TNUM_SENSOR_TYPE), E_PAR,
	       "an unknown sensor type: E_PAR");
	is_int(ev3_sensor_get_type(EV3_PORT_1), TOUCH_SENSOR, "and the port keeps its type");

	/* gyro: the first read waits for the handshake */
	in_range(ev3_gyro_sensor_get_rate(EV3_PORT_2), -46, -44, "gyro rate -45 deg/s");
	is_int(ev3_gyro_sensor_reset(EV3_PORT_2), E_OK, "gyro reset (GYRO-CAL)");
	angle = ev3_gyro_sensor_get_angle(EV3_PORT_2);
	in_range(angle, -3, 0, "angle restarts at 0 (%d)", angle);
	dly_tsk(1000);
	in_range(ev3_gyro_sensor_get_angle(EV3_PORT_2), -48, -42, "and integrates -45 deg/s over 1 s");

	/* colour */
	is_int(ev3_color_sensor_get_reflect(EV3_PORT_3), 63, "reflect");
	is_int(ev3_color_sensor_get_ambient(EV3_PORT_3), 9, "ambient");
	is_int(ev3_color_sensor_get_color(EV3_PORT_3), COLOR_GREEN, "color");
	ev3_color_sensor_get_rgb_raw(EV3_PORT_3, &rgb);
	ok(rgb.r == 120 && rgb.g == 340 && rgb.b == 56, "rgb_raw %u/%u/%u", rgb.r, rgb.g, rgb.b);

	/* infrared */
	is_int(ev3_infrared_sensor_get_distance(EV3_PORT_4), 60, "IR proximity 60 %%");
	seek = ev3_infrared_sensor_seek(EV3_PORT_4);
	ok(seek.heading[1] == -12 && seek.distance[1] == 40 && seek.heading[3] == 7 &&
	   seek.distance[3] == 88 && seek.distance[0] == -128, "seek: the beacons on channels 2 and 4");
	remote = ev3_infrared_sensor_get_remote(EV3_PORT_4);
	is_int(remote.channel[0], IR_RED_UP_BUTTON, "remote channel 1: red up");
	is_int(remote.channel[1], 0, "channel 2: nothing");
	is_int(remote.channel[2], IR_RED_DOWN_BUTTON | IR_BLUE_DOWN_BUTTON, "channel 3: both down");
	is_int(remote.channel[3], IR_BEACON_BUTTON, "channel 4: beacon");

	/* touch */
	ok(!ev3_touch_sensor_is_pressed(EV3_PORT_1), "touch released");
	ev3_set_touch(0, true);
	dly_tsk(20);
	ok(ev3_touch_sensor_is_pressed(EV3_PORT_1), "touch pressed");

	/* wrong type or port: 0 / false and a warning naming the call */
	warnings = 0;
	is_int(ev3_gyro_sensor_get_rate(EV3_PORT_3), 0, "gyro rate from the colour port: 0");
	ok(warned("ev3_gyro_sensor_get_rate(2): E_OBJ"), "logged with E_OBJ");
	is_int(ev3_color_sensor_get_reflect((sensor_port_t)4), 0, "reflect from a bad port: 0");
	ok(warned("ev3_color_sensor_get_reflect(4): E_ID"), "logged with E_ID");
	ok(!ev3_touch_sensor_is_pressed(EV3_PORT_2), "touch on the gyro port: false");
	ok(warned("ev3_touch_sensor_is_pressed(1): E_OBJ"), "logged");
	seek = ev3_infrared_sensor_seek(EV3_PORT_1);
	ok(seek.heading[0] == 0 && seek.distance[3] == 0, "seek on the touch port: zeros");
	ok(warned("ev3_infrared_sensor_seek(0): E_OBJ"), "logged");
	ev3_color_sensor_get_rgb_raw(EV3_PORT_2, &rgb);
	ok(warned("ev3_color_sensor_get_rgb_raw(1): E_OBJ"), "rgb_raw on the gyro port: logged");
}

static void attach_ultrasonic(void)
{
	rtos_host_trace_set_sink(trace_sink, NULL);
	ev3_attach_uart_sensor(3, 30, NULL);
	ev3_set_scene(3, &us_scene);
}

static void ultrasonic_body(void)
{
	is_int(ev3_sensor_config(EV3_PORT_4, ULTRASONIC_SENSOR), E_OK, "config ultrasonic on 4");
	is_int(ev3_ultrasonic_sensor_get_distance(EV3_PORT_4), 73, "distance 73 cm (734 mm)");
	ok(ev3_ultrasonic_sensor_listen(EV3_PORT_4), "listen: another ultrasonic sensor is heard");
	is_int(ev3_ultrasonic_sensor_get_distance(EV3_PORT_4), 73, "distance again after listening");
	ok(!ev3_ultrasonic_sensor_listen(EV3_PORT_1), "listen on an unconfigured port: false");
	ok(warned("ev3_ultrasonic_sensor_listen(0): E_OBJ"), "logged");
}

/* ---- buttons, LEDs, EV3 cyclic handlers ---- */

static volatile int clicks;
static volatile intptr_t click_exinf;

static void on_click(intptr_t exinf)
{
	clicks++;
	click_exinf = exinf;
}

static void attach_none(void)
{
	rtos_host_trace_set_sink(trace_sink, NULL);
}

static void brick_body(void)
{
	is_int(ev3_led_set_color(LED_ORANGE), E_OK, "LED orange");
	is_int(ev3_led_set_color((ledcolor_t)4), E_PAR, "LED colour 4: E_PAR");
	ok(!ev3_button_is_pressed(ENTER_BUTTON), "ENTER released");
	ev3_ui_button_set(EV3_UI_BUTTON_ENTER, true);
	dly_tsk(100);
	ok(ev3_button_is_pressed(ENTER_BUTTON), "ENTER pressed");
	warnings = 0;
	ok(!ev3_button_is_pressed((button_t)6), "a bad button: false");
	ok(warned("ev3_button_is_pressed(6): E_ID"), "logged");
	is_int(ev3_button_set_on_clicked(BACK_BUTTON, on_click, 7), E_OK, "set_on_clicked BACK");
	ev3_ui_button_set(EV3_UI_BUTTON_ENTER, false);
	ev3_ui_button_set(EV3_UI_BUTTON_BACK, true);
	dly_tsk(100);
	ev3_ui_button_set(EV3_UI_BUTTON_BACK, false);
	dly_tsk(100);
	ok(clicks == 1 && click_exinf == 7, "the click handler ran once with its exinf");
	is_int(ev3_sta_cyc(TNUM_CYCID + 1), E_ID, "ev3_sta_cyc of a bad ID: E_ID");
	is_int(ev3_stp_cyc(0), E_ID, "ev3_stp_cyc(0): E_ID");
}

int main(void)
{
	ok(at_run(attach_motors, motor_body, 1, 60), "motors: the body finished");
	ok(at_run(attach_sensors, sensor_body, 2, 60), "sensors: the body finished");
	ok(at_run(attach_ultrasonic, ultrasonic_body, 3, 30), "ultrasonic: the body finished");
	ok(at_run(attach_none, brick_body, 4, 30), "brick: the body finished");
	rtos_host_trace_set_sink(NULL, NULL);
	return tap_done();
}
