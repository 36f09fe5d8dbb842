/*
 * test_terminal.c — a port handed to d_uart where no sensor protocol shows up
 * within 2 s becomes LEGO's TERMINAL (type 124) at 115200 baud: whatever
 * arrives is served as raw mode-0 samples, and write() sends raw bytes.
 */
#include "uart_test.h"

static void body(void)
{
	struct hs_uart *u = ev3_input_uart(1);
	struct lms_uart_types t;
	static const uint8_t hello[] = { 'h', 'i', 0xC0, 0x00 };
	const int8_t *s;
	unsigned i;

	is_int(uart_svc_set_mode(1, 0), E_OK, "port 2 handed to d_uart, nothing plugged in");
	dly_tsk(1900);
	is_int(ut_ext(1)->state, LMS_UART_STATE_SYNC, "still searching after 1.9 s");
	ok(ut_wait_state(1, LMS_UART_STATE_TERMINAL, 200), "TERMINAL after 2 s");
	is_int(ut_ext(1)->speed, 115200, "at 115200 baud");
	ok(hs_uart_baud(u) > 114048 && hs_uart_baud(u) < 116352, "the UART runs at 115200 +-1 %% (%u)",
	   hs_uart_baud(u));
	is_int(uart_svc_mode_info(1, 0, &t), E_OK, "mode info");
	ok(t.type == LMS_TYPE_TERMINAL && !strcmp(t.name, "TERMINAL") && t.data_sets == 32,
	   "type 124 \"TERMINAL\", 32 bytes");
	ok(ut_status(1) & LMS_UART_PORT_CHANGED, "CHANGED");
	is_int(uart_svc_clear_changed(1), E_OK, "accepted");

	for (i = 0; i < sizeof(hello); i++)
		hs_uart_rx_byte(u, hello[i], 115200);
	s = ut_wait_sample(1, 0, 10);
	ok(s && !memcmp(s, hello, sizeof(hello)), "received bytes served as a raw sample");
	is_int(uart_svc_write(1, "AT", 2), E_OK, "raw write accepted");
	dly_tsk(5);
	is_int(hs_uart_get_stats(u)->tx_bytes, 2, "sent unframed: 2 bytes");
	is_int(uart_svc_set_mode(1, 1), E_PAR, "TERMINAL has only mode 0");
}

int main(void)
{
	tap_plan(14);
	ok(ut_run(body, 9, NULL), "scenario ran to its end");
	return tap_done();
}
