/*
 * test_framing.c — d_uart's receive parser against every byte a sensor cable
 * can deliver.  A hand-made sensor on port 1 (bytes injected into UART1's
 * receiver, framed with host_sim's LUMP encoder) completes the handshake, then
 * sends every message class with every size code, valid frames of every
 * command, truncated frames and random streams.  A header announcing more
 * than the longest valid message (size codes 6 and 7: 64 and 128 bytes) is a
 * framing error: counted in size_errors, the parser resynchronises on the
 * next valid frame and never copies past its 35-byte message buffer (the
 * ASan build checks that).  Repeated errors restart the handshake.
 */
#include <stdlib.h>
#include "uart_test.h"
#include "host_sim/devices/lump.h"

#define PORT		0
#define TEST_TYPE	50		/* a sensor type the driver has no special case for */
#define DATA_BAUD	57600U
#define FILLER		0x00		/* SYS SYNC: skipped singly by the parser */

static uint32_t baud = 2400;

/* The sensor sends n bytes (in FIFO-sized bursts the driver drains between). */
static void send(const uint8_t *b, size_t n)
{
	struct hs_uart *u = ev3_input_uart(PORT);

	for (size_t i = 0; i < n; i++) {
		hs_uart_rx_byte(u, b[i], baud);
		if (i % 8 == 7)
			dly_tsk(1);
	}
	dly_tsk(1);
}

static void send_frame(size_t (*enc)(uint8_t *, size_t, unsigned, const void *, size_t),
		       unsigned code, const void *payload, size_t len)
{
	uint8_t f[LUMP_MAX_FRAME];

	send(f, enc(f, sizeof(f), code, payload, len));
}

static void send_info(uint8_t info, const void *payload, size_t len)
{
	uint8_t f[LUMP_MAX_FRAME];

	send(f, lump_encode_info(f, sizeof(f), 0, info, payload, len));
}

/* The sensor side of the handshake: one mode, one DATA8 value, 57600 baud. */
static bool handshake(void)
{
	static const uint8_t type = TEST_TYPE, modes = 0, format[4] = { 1, LUMP_DATA8, 3, 0 };
	static const uint8_t speed[4] = { DATA_BAUD & 0xff, DATA_BAUD >> 8 & 0xff, DATA_BAUD >> 16, 0 };
	static const uint8_t ack = LUMP_SYS_ACK;

	baud = 2400;
	send_frame(lump_encode_cmd, LUMP_CMD_TYPE, &type, 1);
	send_frame(lump_encode_cmd, LUMP_CMD_MODES, &modes, 1);
	send_frame(lump_encode_cmd, LUMP_CMD_SPEED, speed, 4);
	send_info(LUMP_INFO_NAME, "FRAMING", 7);
	send_info(LUMP_INFO_FORMAT, format, 4);
	send(&ack, 1);
	if (!ut_wait_state(PORT, LMS_UART_STATE_DATA, 200))
		return false;
	baud = DATA_BAUD;
	return uart_svc_clear_changed(PORT) == E_OK;
}

/* One valid DATA frame of mode 0 with value v; true when the driver serves it. */
static bool value_served(int8_t v)
{
	const int8_t *s;

	send_frame(lump_encode_data, 0, &v, 1);
	s = lms_uart_sample(ut_shm, PORT, 0);
	return s && s[0] == v;
}

/* Every class and size code in DATA: codes 6 and 7 are size errors, and the next valid frame
 * is served at once. */
static void size_codes(void)
{
	static const uint8_t classes[] = { LUMP_CLASS_CMD, LUMP_CLASS_INFO, LUMP_CLASS_DATA };
	uint32_t size0 = ut_ext(PORT)->size_errors, resync0 = ut_ext(PORT)->resyncs;
	unsigned served = 0, tried = 0;

	for (unsigned c = 0; c < sizeof(classes); c++) {
		for (unsigned code = 0; code < 8; code++) {
			uint8_t junk[6] = { (uint8_t)(classes[c] | code << 3), FILLER, FILLER, FILLER,
					    FILLER, FILLER };

			send(junk, sizeof(junk));
			dly_tsk(12);	/* a long message waits for its rest (35 bytes at 57600: 9 ms) */
			served += value_served((int8_t)(c * 8 + code + 1));
			tried++;
		}
	}
	is_int(served, tried, "the valid frame after each bad header is served (%u headers)", tried);
	is_int(ut_ext(PORT)->size_errors - size0, 6, "size codes 6, 7 of CMD, INFO, DATA: 6 size errors");
	ok(ut_ext(PORT)->resyncs - resync0 >= 6, "every bad header lost sync (%u resyncs)",
	   ut_ext(PORT)->resyncs - resync0);
	is_int(ut_ext(PORT)->state, LMS_UART_STATE_DATA, "still in DATA: errors decay with good frames");
}

/* Valid CMD frames of every command and SYS bytes in DATA are ignored without an error. */
static void commands(void)
{
	uint32_t check0 = ut_ext(PORT)->check_errors, size0 = ut_ext(PORT)->size_errors;
	static const uint8_t sys[] = { LUMP_SYS_SYNC, LUMP_SYS_NACK, LUMP_SYS_ACK };
	uint8_t payload[32] = { 0 };
	unsigned served = 0;

	for (unsigned cmd = 0; cmd < 8; cmd++) {
		send_frame(lump_encode_cmd, cmd, payload, (size_t)1 << (cmd % 6));
		served += value_served((int8_t)(100 + cmd));
	}
	send(sys, sizeof(sys));
	served += value_served(111);
	is_int(served, 9, "data served between CMD frames of every command and SYS bytes");
	is_int(ut_ext(PORT)->check_errors - check0 + ut_ext(PORT)->size_errors - size0, 0,
	       "no error counted for valid frames");
}

/* A frame cut short: the rest never comes; it times out as garbage and data resumes. */
static void truncated(void)
{
	uint32_t check0 = ut_ext(PORT)->check_errors;
	static const uint8_t cut[] = { LUMP_CLASS_DATA | 2U << 3, 1, 2 };

	send(cut, sizeof(cut));
	dly_tsk(10);
	ok(ut_ext(PORT)->check_errors > check0, "the incomplete frame timed out as an error");
	ok(value_served(42), "the next frame is served");
}

/* Random bytes: many errors, a restarted handshake, never a crash. */
static void random_stream(void)
{
	uint32_t reconnects = ut_ext(PORT)->reconnects;
	uint8_t b[64];

	srand(1);
	for (unsigned burst = 0; burst < 200; burst++) {
		for (unsigned i = 0; i < sizeof(b); i++)
			b[i] = (uint8_t)rand();
		send(b, sizeof(b));
	}
	ok(ut_ext(PORT)->reconnects > reconnects, "repeated errors restarted the handshake (%u)",
	   ut_ext(PORT)->reconnects - reconnects);
	ok(ut_wait_state(PORT, LMS_UART_STATE_SYNC, 300), "waiting in SYNC for the sensor");
	dly_tsk(150);		/* the break d_uart sends to reset the sensor */
	ok(handshake(), "a new handshake after the random stream");
	ok(value_served(-7), "data served again");
	is_int(rtos_host_bug_count(), 0, "no kernel bug reported");
}

/* An oversized INFO header in the handshake fails it; the next handshake succeeds. */
static void oversized_info(void)
{
	static const uint8_t type = TEST_TYPE, modes = 0;
	uint32_t size0 = ut_ext(PORT)->size_errors, failed0 = ut_ext(PORT)->handshake_errors;
	uint8_t junk[8] = { LUMP_CLASS_INFO | 7U << 3, LUMP_INFO_NAME, 'X', 'X', 'X' };

	ok(uart_svc_stop(PORT) == E_OK && uart_svc_set_mode(PORT, 0) == E_OK, "port restarted");
	baud = 2400;
	send_frame(lump_encode_cmd, LUMP_CMD_TYPE, &type, 1);
	send_frame(lump_encode_cmd, LUMP_CMD_MODES, &modes, 1);
	send(junk, sizeof(junk));
	is_int(ut_ext(PORT)->size_errors - size0, 1, "INFO with 128 bytes: a size error");
	is_int(ut_ext(PORT)->handshake_errors - failed0, 1, "the handshake abandoned");
	ok(handshake(), "the next handshake succeeds");
	ok(value_served(9), "data served");
}

static void body(void)
{
	is_int(uart_svc_set_mode(PORT, 0), E_OK, "port 1 handed to d_uart");
	ok(handshake(), "hand-made sensor: handshake done, DATA at 57600");
	ok(value_served(7), "a valid frame is served");
	size_codes();
	commands();
	truncated();
	random_stream();
	oversized_info();
}

int main(void)
{
	tap_plan(22);
	ok(ut_run(body, 3, NULL), "scenario ran to its end");
	return tap_done();
}
