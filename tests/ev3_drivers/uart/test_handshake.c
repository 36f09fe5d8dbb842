/*
 * test_handshake.c — d_uart brings each of the four EV3 UART sensors
 * (colour, gyro, ultrasonic, IR; one per input port, so both real UARTs and
 * both stand-ins are used) from power-up to DATA: 2400 baud handshake, the
 * mode descriptions in LEGO's TYPES layout, ACK and CHANGED, 57600 baud,
 * then values from the scene once user space has accepted the description.
 */
#include "uart_test.h"

struct expect {
	uint8_t type, modes;
	const char *name0, *name_last;
	const char *symbol0;
	int8_t data_sets0, format0, figures0, decimals0;
	float raw_max0, si_max0;
};

static const struct expect expected[LMS_UART_PORTS] = {
	{ 29, 6, "COL-REFLECT", "COL-CAL", "pct", 1, LMS_UART_DATA8, 3, 0, 100.0f, 100.0f },
	{ 32, 5, "GYRO-ANG", "GYRO-CAL", "deg", 1, LMS_UART_DATA16, 4, 0, 180.0f, 180.0f },
	{ 30, 7, "US-DIST-CM", "US-DC-IN", "cm", 1, LMS_UART_DATA16, 5, 1, 2550.0f, 255.0f },
	{ 33, 6, "IR-PROX", "IR-CAL", "pct", 1, LMS_UART_DATA8, 3, 0, 100.0f, 100.0f },
};

static void body(void)
{
	struct uart_sensor_scene scene = { .reflect_pct = 42, .distance_mm = 1234 };
	struct lms_uart_types t;
	const int8_t *s;
	unsigned port;

	ev3_attach_uart_sensor(0, UART_SENSOR_TYPE_COLOR, NULL);
	ev3_attach_uart_sensor(1, UART_SENSOR_TYPE_GYRO, NULL);
	ev3_attach_uart_sensor(2, UART_SENSOR_TYPE_ULTRASONIC, NULL);
	ev3_attach_uart_sensor(3, UART_SENSOR_TYPE_IR, NULL);
	ev3_set_scene(0, &scene);
	scene.distance_mm = 500;
	ev3_set_scene(2, &scene);
	scene.distance_mm = 700;
	ev3_set_scene(3, &scene);

	is_int(uart_svc_mode_info(0, 0, &t), E_OBJ, "no description before the handshake");
	for (port = 0; port < LMS_UART_PORTS; port++)
		is_int(uart_svc_set_mode(port, 0), E_OK, "port %u handed to d_uart", port + 1);
	ok(ut_ext(0)->state == LMS_UART_STATE_SYNC && ut_ext(0)->speed == 2400,
	   "SYNC at 2400 baud right after SET_CONN");

	for (port = 0; port < LMS_UART_PORTS; port++) {
		const struct expect *e = &expected[port];

		ok(ut_wait_state(port, LMS_UART_STATE_DATA, 3000), "port %u: DATA within 3 s", port + 1);
		is_int(ut_ext(port)->speed, 57600, "port %u: sensor's SPEED in use", port + 1);
		is_int(ut_ext(port)->modes, e->modes, "port %u: %u modes", port + 1, e->modes);
		ok(ut_status(port) & LMS_UART_PORT_CHANGED, "port %u: CHANGED set", port + 1);
		ok(!lms_uart_sample(ut_shm, port, 0), "port %u: no data before CLEAR_CHANGED", port + 1);

		is_int(uart_svc_mode_info(port, 0, &t), E_OK, "port %u: mode 0 info", port + 1);
		ok(!strcmp(t.name, e->name0), "port %u: mode 0 is %s (%s)", port + 1, e->name0, t.name);
		is_int(t.type, e->type, "port %u: type", port + 1);
		is_int(t.connection, LMS_CONN_INPUT_UART, "port %u: connection", port + 1);
		ok(t.data_sets == e->data_sets0 && t.format == e->format0 &&
		   t.figures == e->figures0 && t.decimals == e->decimals0,
		   "port %u: FORMAT %d %d %d %d", port + 1, t.data_sets, t.format, t.figures, t.decimals);
		ok(!strcmp(t.symbol, e->symbol0), "port %u: symbol %s", port + 1, t.symbol);
		is_int(t.raw_max, ut_float_bits(e->raw_max0), "port %u: RAW max bits", port + 1);
		is_int(t.si_max, ut_float_bits(e->si_max0), "port %u: SI max bits", port + 1);
		is_int(t.pct_max, ut_float_bits(100.0f), "port %u: PCT defaults to 100", port + 1);
		is_int(uart_svc_mode_info(port, e->modes - 1, &t), E_OK, "port %u: last mode", port + 1);
		ok(!strcmp(t.name, e->name_last), "port %u: last mode is %s (%s)", port + 1,
		   e->name_last, t.name);
		is_int(uart_svc_mode_info(port, e->modes, &t), E_PAR, "port %u: no mode %u", port + 1,
		       e->modes);
		is_int(uart_svc_clear_changed(port), E_OK, "port %u: description accepted", port + 1);
	}

	s = ut_wait_sample(0, 0, 300);
	ok(s && s[0] == 42, "colour: reflected light %d", s ? s[0] : -1);
	s = ut_wait_sample(1, 0, 300);
	ok(s && ut_s16(s, 0) == 0, "gyro: angle %d at rest", s ? ut_s16(s, 0) : -1);
	s = ut_wait_sample(2, 0, 300);
	ok(s && ut_s16(s, 0) == 500, "ultrasonic: %d mm (0.1 cm units)", s ? ut_s16(s, 0) : -1);
	s = ut_wait_sample(3, 0, 1500);
	ok(s && s[0] > 0 && s[0] <= 100, "IR: proximity %d", s ? s[0] : -1);
	for (port = 0; port < LMS_UART_PORTS; port++) {
		ok(ut_status(port) & LMS_UART_DATA_READY, "port %u: DATA_READY", port + 1);
		is_int(ut_ext(port)->data_mode, 0, "port %u: data of mode 0", port + 1);
		is_int(ut_ext(port)->check_errors + ut_ext(port)->reconnects, 0,
		       "port %u: no errors, no reconnects", port + 1);
	}
	dly_tsk(2000);
	for (port = 0; port < LMS_UART_PORTS; port++) {
		ok(ut_ext(port)->state == LMS_UART_STATE_DATA && !(ut_ext(port)->flags & LMS_UART_FLAG_STALE),
		   "port %u: still streaming 2 s later (keep-alive works)", port + 1);
		is_int(uart_sensor_get_stats(ev3_input_uart_sensor(port))->resets, 1,
		       "port %u: the sensor never reset", port + 1);
	}
}

int main(void)
{
	tap_plan(4 * 18 + 4 + 3 + 4 + 4 * 3 + 4 * 2);
	ok(ut_run(body, 1, NULL), "scenario ran to its end");
	return tap_done();
}
