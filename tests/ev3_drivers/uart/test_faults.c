/*
 * test_faults.c — d_uart under the failures EV3 users report: the NACK
 * keep-alive every 100 ms (checked on the register trace), a sensor that is
 * unplugged (reported stale, not frozen; the port goes back to SYNC) and
 * plugged in again (DATA again), 5 % of the bytes lost (every untouched frame
 * delivered), bit errors (counted, data keeps flowing, no reconnect), and a receive overrun while the CPU is blocked (counted and
 * recovered), and a write request forged in the shared page (dropped).
 */
#include <stdlib.h>
#include "uart_test.h"

#define MAX_NACKS 64

static uint64_t nack_ns[MAX_NACKS];
static unsigned nacks;
static bool tracing;

/* Trace sink: records the times of NACK bytes d_uart writes to UART0 (port 2). */
static void sink(const char *line, void *ctx)
{
	(void)ctx;
	if (tracing && strstr(line, "W4 UART0.THR") && strstr(line, "= 0x00000002") &&
	    nacks < MAX_NACKS)
		nack_ns[nacks++] = strtoull(line, NULL, 10);
}

static void keepalive(void)
{
	unsigned i, good = 0;

	ev3_attach_uart_sensor(1, UART_SENSOR_TYPE_GYRO, NULL);
	ok(ut_start(1, 0, 3000), "gyro in DATA");
	rtos_host_trace_set_sink(sink, NULL);
	tracing = true;
	dly_tsk(1000);
	tracing = false;
	ok(nacks >= 9 && nacks <= 11, "%u NACKs in 1 s", nacks);
	for (i = 1; i < nacks; i++)
		good += llabs((long long)(nack_ns[i] - nack_ns[i - 1]) - (long long)(100 * UT_MS)) < 100000;
	is_int(good, nacks - 1, "every NACK 100 ms (+-0.1 ms) after the previous one");
}

static void unplug(void)
{
	struct uart_sensor_scene scene = { .reflect_pct = 33 };
	uint32_t reconnects;
	unsigned ms;
	const int8_t *s;

	ev3_attach_uart_sensor(0, UART_SENSOR_TYPE_COLOR, NULL);
	ev3_set_scene(0, &scene);
	ok(ut_start(0, 0, 3000) && ut_wait_sample(0, 0, 300), "colour streaming");
	reconnects = ut_ext(0)->reconnects;

	ev3_detach_input(0);
	for (ms = 0; ms < 1000 && lms_uart_sample(ut_shm, 0, 0); ms++)
		dly_tsk(1);
	ok(ms <= 300, "data withdrawn %u ms after the unplug (not frozen)", ms);
	ok(ut_ext(0)->flags & LMS_UART_FLAG_STALE, "flagged stale");
	ok(!(ut_status(0) & LMS_UART_DATA_READY), "DATA_READY cleared");
	ok(ut_wait_state(0, LMS_UART_STATE_SYNC, 1000), "back to SYNC for the next handshake");
	ok(ut_shm->lms.actual[0] == 0 && ut_shm->lms.log_in[0] == 0,
	   "its samples start again in slot 0 (Actual %u, LogIn %u; LEGO's 0, 0)", ut_shm->lms.actual[0],
	   ut_shm->lms.log_in[0]);
	is_int(ut_ext(0)->speed, 2400, "at 2400 baud");
	is_int(ut_ext(0)->reconnects - reconnects, 1, "one reconnect counted");

	dly_tsk(3000);
	ok(ut_ext(0)->state == LMS_UART_STATE_SYNC, "an empty port waits in SYNC (no TERMINAL)");
	scene.reflect_pct = 71;
	ev3_attach_uart_sensor(0, UART_SENSOR_TYPE_COLOR, NULL);
	ev3_set_scene(0, &scene);
	ok(ut_wait_state(0, LMS_UART_STATE_DATA, 3000), "replugged: DATA again");
	ok(ut_status(0) & LMS_UART_PORT_CHANGED, "new description flagged");
	is_int(uart_svc_clear_changed(0), E_OK, "accepted");
	s = ut_wait_sample(0, 0, 300);
	ok(s && s[0] == 71 && ut_shm->lms.actual[0] == 0, "fresh value %d in slot %u", s ? s[0] : -1,
	   ut_shm->lms.actual[0]);
}

static void bit_errors(void)
{
	struct ev3_fault f = { EV3_FAULT_UART_BIT_ERRORS, 2, 0.003, 3000 * UT_MS };
	uint32_t flipped, dropped, dup;
	const int8_t *s;

	ev3_attach_uart_sensor(2, UART_SENSOR_TYPE_GYRO, NULL);
	ok(ut_start(2, 0, 3000) && ut_wait_sample(2, 0, 100), "gyro streaming");
	is_int(ev3_fault_at(rtos_host_now(), &f), E_OK, "bit errors for 3 s");
	dly_tsk(3500);
	ev3_fault_uart_counts(2, &flipped, &dropped, &dup);
	ok(flipped >= 5, "%u bytes flipped", flipped);
	ok(ut_ext(2)->check_errors + ut_ext(2)->line_errors >= flipped / 2,
	   "errors counted: %u check, %u line", ut_ext(2)->check_errors, ut_ext(2)->line_errors);
	is_int(ut_ext(2)->reconnects, 0, "no reconnect");
	s = lms_uart_sample(ut_shm, 2, 0);
	ok(s && ut_s16(s, 0) == 0, "valid data afterwards (angle %d)", s ? ut_s16(s, 0) : -1);
}

static void overrun(void)
{
	uint32_t seq;

	ev3_attach_uart_sensor(3, UART_SENSOR_TYPE_GYRO, NULL);
	ok(ut_start(3, 0, 3000) && ut_wait_sample(3, 0, 100), "gyro streaming");
	loc_cpu();
	rtos_host_consume(20 * UT_MS);	/* interrupts and the driver's timer held off */
	unl_cpu();
	dly_tsk(2);
	ok(ut_ext(3)->fifo_overruns > 0, "%u receive overruns (LSR.OE) counted", ut_ext(3)->fifo_overruns);
	seq = ut_ext(3)->seq;
	dly_tsk(50);
	ok(ut_ext(3)->seq - seq >= 10 && lms_uart_sample(ut_shm, 3, 0), "recovered: %u samples in 50 ms",
	   ut_ext(3)->seq - seq);
	is_int(ut_ext(3)->reconnects, 0, "without a reconnect");
}

/* The shared page is mapped writable (lms2012 maps it read/write), so a process can
 * raise WRITE_REQUEST with a length write() never set: d_uart drops that request
 * instead of copying past its 35-byte message and the 32-byte output row. */
static void forged_write(void)
{
	struct lms_uart *lms = (struct lms_uart *)&ut_shm->lms;	/* the process's writable view */
	const struct hs_uart_stats *st = hs_uart_get_stats(ev3_input_uart(3));
	static const int8_t forged[] = { -1, 33, 127 };
	uint32_t sent;
	unsigned i;

	for (i = 0; i < sizeof(forged); i++) {
		sent = st->tx_bytes;
		lms->output_length[3] = forged[i];
		lms->status[3] |= LMS_UART_WRITE_REQUEST;
		dly_tsk(5);
		ok(!(ut_status(3) & LMS_UART_WRITE_REQUEST) && st->tx_bytes - sent <= 1,
		   "forged length %d: request dropped, %u bytes sent (a NACK at most)", forged[i],
		   st->tx_bytes - sent);
	}
	is_int(uart_svc_write(3, "\x01\x02", 2), E_OK, "a real write afterwards is accepted");
	for (i = 0; i < 10 && (ut_status(3) & LMS_UART_WRITE_REQUEST); i++)
		dly_tsk(1);
	ok(!(ut_status(3) & LMS_UART_WRITE_REQUEST), "and sent");
	ok(lms_uart_sample(ut_shm, 3, 0) != NULL, "the gyro still streams");
}

/*
 * 5 % of a colour sensor's bytes lost for 10 s: while the port is in DATA every frame no loss
 * touched arrives as a sample (a bad check byte costs one byte of resync, not the frames
 * behind it); when errors outrun good frames (six, as LEGO's driver allows) the port starts
 * the handshake again and, the line clean again, serves values within the handshake's time.
 * LEGO's driver, on the same line, loses 4-8 untouched frames in 100 and in 3 of 10 runs
 * falls into its error state and stays there.
 */
static void dropped_bytes(void)
{
	struct ev3_fault f = { EV3_FAULT_UART_DROP, 0, 0.05, 10000 * UT_MS };
	const struct uart_sensor_stats *st = uart_sensor_get_stats(ev3_input_uart_sensor(0));
	uint32_t frames = 0, last = st->data_frames, seq = ut_ext(0)->seq, flipped, dropped, dup;
	unsigned ms;

	is_int(ev3_fault_at(rtos_host_now(), &f), E_OK, "5 %% of port 1's bytes dropped for 10 s");
	for (ms = 0; ms < 10000; ms++) {
		dly_tsk(1);
		if (ut_ext(0)->state == LMS_UART_STATE_DATA)
			frames += st->data_frames - last;
		last = st->data_frames;
	}
	ev3_fault_uart_counts(0, &flipped, &dropped, &dup);
	ok(ut_ext(0)->seq - seq + dropped >= frames,
	   "%u samples of the %u frames sent in DATA, %u bytes dropped: every untouched frame delivered",
	   ut_ext(0)->seq - seq, frames, dropped);
	ok(ut_wait_state(0, LMS_UART_STATE_DATA, 3000), "DATA again within 3 s of the clean line");
	if (ut_status(0) & LMS_UART_PORT_CHANGED)
		uart_svc_clear_changed(0);
	ok(ut_wait_sample(0, 0, 300) != NULL, "and a value served (%u reconnects)", ut_ext(0)->reconnects);
}

/* One boot: linux_compat initialises modules once per process. */
static void body(void)
{
	keepalive();
	unplug();
	dropped_bytes();
	bit_errors();
	overrun();
	forged_write();
}

int main(void)
{
	tap_plan(37);
	ok(ut_run(body, 3, "UART0"), "scenario ran to its end");
	return tap_done();
}
