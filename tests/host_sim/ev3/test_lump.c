/*
 * test_lump.c — LEGO UART protocol framing (LEGO's d_uart_mod.c, pybricks' port_lump.c): size codes, check
 * bytes, padding, frame lengths, the parser.
 */
#include "tap.h"
#include "host_sim/devices/lump.h"

int main(void)
{
	uint8_t f[LUMP_MAX_FRAME], type = 29;
	uint8_t speed[4] = { 0x00, 0xE1, 0x00, 0x00 };
	struct lump_parser p;
	struct lump_msg m = { 0 };
	size_t n;
	int got = 0;

	tap_plan(14);
	n = lump_encode_cmd(f, sizeof(f), LUMP_CMD_TYPE, &type, 1);
	ok(n == 3 && f[0] == 0x40 && f[1] == 29 && f[2] == (0xFF ^ 0x40 ^ 29), "TYPE 29: 40 1D A2");
	n = lump_encode_cmd(f, sizeof(f), LUMP_CMD_SPEED, speed, 4);
	ok(n == 6 && f[0] == 0x52, "SPEED: header 0x52, 4 bytes");
	n = lump_encode_info(f, sizeof(f), 2, LUMP_INFO_NAME, "COL-COLOR", 9);
	ok(n == 19 && f[0] == 0xA2 && f[1] == 0 && f[11] == 0 && f[17] == 0, "9-char NAME padded to 16 (0xA2)");
	is_int(f[18], lump_check(f, 18), "check byte = 0xFF ^ all before");
	n = lump_encode_data(f, sizeof(f), 4, "\1\0\2\0\3\0\4\0", 8);
	ok(n == 10 && f[0] == 0xDC, "8-byte DATA of mode 4: header 0xDC");
	is_int(lump_size_code(3), 2, "3 bytes need a 4-byte payload");
	is_int(lump_size_code(33), -1, "33 bytes cannot be framed");
	is_int(lump_encode_cmd(f, sizeof(f), 8, NULL, 0), 0, "command 8 refused");
	is_int(lump_encode_cmd(f, 4, LUMP_CMD_SPEED, speed, 4), 0, "too small a buffer refused");
	is_int(lump_frame_len(0x04), 1, "SYS is one byte");
	is_int(lump_frame_len(0x98), 11, "INFO with 8 bytes: header, info, payload, check");
	lump_parser_reset(&p);
	n = lump_encode_cmd(f, sizeof(f), LUMP_CMD_SELECT, "\3", 1);
	for (size_t i = 0; i < n; i++)
		got += lump_parser_push(&p, f[i], &m);
	ok(got == 1 && m.header == 0x43 && m.payload[0] == 3 && m.check_ok, "parser: SELECT 3");
	if (n > 0)
		f[n - 1] ^= 1;
	got = 0;
	for (size_t i = 0; i < n; i++)
		got += lump_parser_push(&p, f[i], &m);
	ok(got == 1 && !m.check_ok, "parser flags a bad check byte");
	ok(lump_parser_push(&p, 0x02, &m) && m.header == 0x02 && m.len == 0, "parser: NACK");
	return tap_done();
}
