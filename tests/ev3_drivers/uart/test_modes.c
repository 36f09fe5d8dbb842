/*
 * test_modes.c — SELECT through d_uart: after a mode change no value of the
 * old mode is ever served, even from sensors whose first frame after SELECT
 * still carries the old reading (ev3dev #1401, host_sim's stale_first_frame);
 * the colour sensor's RGB-RAW frames with their wrong check byte are
 * accepted; modes beyond the sensor's are refused.
 */
#include "uart_test.h"

static unsigned switch_ms;	/* how long the last switch_and_check waited for its value */

/* Switches port to mode and watches every millisecond until its first value:
 * true if the first value served is want (read by get) and nothing of another
 * mode was served meanwhile. */
static bool switch_and_check(unsigned port, unsigned mode, int (*get)(const int8_t *), int want,
			     int *first)
{
	const int8_t *s;
	unsigned ms, other;

	*first = -1;
	if (uart_svc_set_mode(port, mode) != E_OK)
		return false;
	for (ms = 0; ms < 500; ms++) {
		for (other = 0; other < LMS_UART_MODES; other++)
			if (other != mode && lms_uart_sample(ut_shm, port, (int)other))
				return false;
		s = lms_uart_sample(ut_shm, port, (int)mode);
		if (s) {
			switch_ms = ms;
			*first = get(s);
			return *first == want;
		}
		dly_tsk(1);
	}
	return false;
}

static int get_u8(const int8_t *s)
{
	return (uint8_t)s[0];
}

static int get_s16(const int8_t *s)
{
	return ut_s16(s, 0);
}

static void body(void)
{
	const struct uart_sensor_options stale = { .stale_first_frame = true };
	struct uart_sensor_scene scene = {
		.reflect_pct = 42, .ambient_pct = 17, .color = 5, .rgb = { 300, 500, 700 },
	};
	const int8_t *s;
	uint32_t selects;
	int first;
	bool sw;

	ev3_attach_uart_sensor(0, UART_SENSOR_TYPE_COLOR, &stale);
	ev3_set_scene(0, &scene);
	ev3_attach_uart_sensor(1, UART_SENSOR_TYPE_GYRO, &stale);
	ok(ut_start(0, 0, 3000) && ut_start(1, 0, 3000), "colour and gyro in DATA");
	s = ut_wait_sample(0, 0, 300);
	ok(s && s[0] == 42, "colour reflect 42");
	selects = ut_ext(0)->selects;

	ok(uart_svc_set_mode(0, 1) == E_OK && !lms_uart_sample(ut_shm, 0, 0) &&
	   !(ut_status(0) & LMS_UART_DATA_READY) && ut_ext(0)->data_mode == -1,
	   "mode change withdraws the old data at once");
	ok(ut_ext(0)->flags & LMS_UART_FLAG_SELECTING, "SELECTING flagged");
	sw = switch_and_check(0, 1, get_u8, 17, &first);
	ok(sw, "first value after SELECT is ambient 17 (%d)", first);
	ok(!(ut_ext(0)->flags & LMS_UART_FLAG_SELECTING), "SELECTING cleared");
	sw = switch_and_check(0, 2, get_u8, 5, &first);
	ok(sw, "then COL-COLOR red 5 (%d)", first);
	sw = switch_and_check(0, 4, get_s16, 300, &first);
	ok(sw, "then RGB-RAW red 300 (%d)", first);
	s = lms_uart_sample(ut_shm, 0, 4);
	ok(s && ut_s16(s, 1) == 500 && ut_s16(s, 2) == 700, "RGB-RAW green 500, blue 700");
	dly_tsk(500);
	ok(lms_uart_sample(ut_shm, 0, 4) != NULL, "RGB-RAW keeps flowing");
	is_int(ut_ext(0)->check_errors, 0, "RGB-RAW's wrong check byte is not an error");
	sw = switch_and_check(0, 0, get_u8, 42, &first);
	ok(sw, "back to reflect 42 (%d)", first);
	is_int(ut_ext(0)->selects - selects, 4, "one SELECT per change");
	is_int(uart_svc_set_mode(0, 0), E_OK, "selecting the current mode again");
	is_int(ut_ext(0)->selects - selects, 4, "sends no SELECT");
	ok(lms_uart_sample(ut_shm, 0, 0) != NULL, "and keeps the data");

	is_int(uart_svc_set_mode(0, 6), E_PAR, "colour has no mode 6");
	is_int(uart_svc_set_mode(0, 8), E_PAR, "no mode 8 at all");
	is_int(ut_ext(0)->mode, 0, "mode unchanged by refused requests");

	scene.rate_dps = 30.0;
	ev3_set_scene(1, &scene);
	dly_tsk(2000);
	s = lms_uart_sample(ut_shm, 1, 0);
	ok(s && ut_s16(s, 0) >= 55 && ut_s16(s, 0) <= 65, "gyro angle ~60 after 2 s at 30 d/s (%d)",
	   s ? ut_s16(s, 0) : -1);
	sw = switch_and_check(1, 1, get_s16, 30, &first);
	ok(sw, "gyro rate: first value 30 d/s, not an angle (%d)", first);
	/* LEGO's shows the stale angle as the rate from 5 to 8 ms, then 30 */
	ok(switch_ms <= 8, "after %u ms (LEGO's right value after 8)", switch_ms);
	is_int(ut_ext(0)->reconnects + ut_ext(1)->reconnects, 0, "no reconnects");
}

int main(void)
{
	tap_plan(24);
	ok(ut_run(body, 2, NULL), "scenario ran to its end");
	return tap_done();
}
