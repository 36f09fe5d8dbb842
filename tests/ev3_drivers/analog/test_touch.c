/*
 * test_touch.c — touch sensors as d_analog's values show them: EV3 touch
 * presses and releases with contact bounce appear in InPin6 and in the 1 ms
 * Pin6 log (bounce included, final level right), the connection does not
 * flicker meanwhile; an NXT touch press pulls pin 1 to ~900 mV; Updated is
 * set on every new sample.
 */
#include "analog_test.h"

#define HIGH_MV	2500U

/* Pin 6 of port `back` samples before the newest one, in mV. */
static unsigned pin6_back(const volatile struct lms_analog *shm, unsigned port, unsigned back)
{
	unsigned idx = (shm->actual[port] + LMS_ANALOG_LOG_SIZE - back) % LMS_ANALOG_LOG_SIZE;

	return lms_analog_raw_to_mv(shm->pin6[port][idx]);
}

/* Level changes in the last n pin 6 samples of a port, oldest first. */
static unsigned pin6_edges(const volatile struct lms_analog *shm, unsigned port, unsigned n)
{
	unsigned edges = 0, back;
	bool prev = pin6_back(shm, port, n - 1) > HIGH_MV;

	for (back = n - 1; back-- > 0;) {
		bool now = pin6_back(shm, port, back) > HIGH_MV;

		edges += now != prev;
		prev = now;
	}
	return edges;
}

static void touch_body(void)
{
	const struct ev3_analog_options bouncy = { .bounce_us = 20000 };
	const volatile struct lms_analog *shm = analog_shm();
	struct analog_input_state st;
	unsigned i, edges = 0, high_after = 0, low_after = 0, conn_ok = 0;
	double t0;

	ev3_attach_analog(0, EV3_INPUT_EV3_TOUCH, &bouncy);
	ev3_attach_analog(1, EV3_INPUT_NXT_TOUCH, &bouncy);
	ok(wait_in_conn(0, LMS_CONN_INPUT_DUMB, 3000) > 0, "EV3 touch detected");
	ok(wait_in_conn(1, LMS_CONN_NXT_DUMB, 500) > 0, "NXT touch detected");
	ok(pin6_back(shm, 0, 0) < 500, "released EV3 touch: pin 6 low");

	for (i = 0; i < 5; i++) {
		ev3_set_touch(0, true);
		dly_tsk(60);
		edges += pin6_edges(shm, 0, 64);
		high_after += pin6_back(shm, 0, 0) > 4000;
		conn_ok += shm->in_conn[0] == LMS_CONN_INPUT_DUMB;
		ev3_set_touch(0, false);
		dly_tsk(60);
		edges += pin6_edges(shm, 0, 64);
		low_after += pin6_back(shm, 0, 0) < 500;
		conn_ok += shm->in_conn[0] == LMS_CONN_INPUT_DUMB;
	}
	is_int(high_after, 5, "every press ends with pin 6 high in the log");
	is_int(low_after, 5, "every release ends with pin 6 low in the log");
	ok(edges > 10, "the 1 ms log shows contact bounce (%u level changes for 10 transitions)", edges);
	ok(edges % 2 == 0, "bounce always settles to the pressed or released level");
	is_int(conn_ok, 10, "the connection stays INPUT_DUMB through presses and bounce");

	ev3_set_touch(0, true);
	t0 = now_ms();
	while (shm->in_pin6[0] < 4000 * LMS_ADC_MAX / LMS_ADC_FULL_SCALE_MV && now_ms() < t0 + 50)
		dly_tsk(1);
	ok(now_ms() - t0 <= 2.5, "a press is visible in InPin6 within 2 ms (%.1f ms)", now_ms() - t0);
	is_int(analog_input(0, &st), E_OK, "port 1 state");
	ok(st.pin6_mv > 4000, "analog_input reports the press (%u mV)", st.pin6_mv);

	ev3_set_touch(1, true);
	dly_tsk(50);
	is_int(analog_input(1, &st), E_OK, "port 2 state");
	in_range(st.pin1_mv, 850, 950, "pressed NXT touch pulls pin 1 to ~900 mV (%u)", st.pin1_mv);
	ev3_set_touch(1, false);
	dly_tsk(50);
	is_int(analog_input(1, &st), E_OK, "port 2 state again");
	ok(st.pin1_mv > 4800, "released NXT touch: pin 1 back above 4.8 V (%u)", st.pin1_mv);
	is_int(shm->in_conn[1], LMS_CONN_NXT_DUMB, "NXT touch stays connected");

	((volatile struct lms_analog *)shm)->updated[0] = 0;
	dly_tsk(2);
	is_int(shm->updated[0], 1, "Updated is set again by the next sample");
}

int main(void)
{
	tap_plan(18);
	ok(analog_test_run(touch_body, 3, 6000), "the test body ran to its end");
	return tap_done();
}
