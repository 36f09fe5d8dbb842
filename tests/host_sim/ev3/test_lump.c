/*
 * test_lump.c — LEGO UART protocol framing (LEGO's d_uart_mod.c, pybricks' port_lump.c): size codes, check
 * bytes, padding, frame lengths, the parser and its framing errors.
 */
#include <stdlib.h>
#include "tap.h"
#include "host_sim/devices/lump.h"

/* Headers announcing more than the longest frame (size codes 6, 7) are framing
 * errors: counted, dropped, and the parser takes the next byte as a header. */
static void oversized_headers(void)
{
	static const uint8_t classes[] = { LUMP_CLASS_CMD, LUMP_CLASS_INFO, LUMP_CLASS_DATA };
	struct lump_parser p = { 0 };
	struct lump_msg m;
	uint8_t f[LUMP_MAX_FRAME];
	unsigned rejected = 0, parsed = 0;
	size_t n;

	for (unsigned c = 0; c < sizeof(classes); c++) {
		for (unsigned code = 0; code < 8; code++) {
			uint8_t hdr = (uint8_t)(classes[c] | code << 3);
			size_t len = lump_frame_len(hdr);

			lump_parser_reset(&p);
			if (len > LUMP_MAX_FRAME) {
				rejected += !lump_parser_push(&p, hdr, &m) && p.have == 0;
				continue;
			}
			for (size_t i = 0; i < len; i++)
				parsed += lump_parser_push(&p, i ? (uint8_t)i : hdr, &m);
		}
	}
	is_int(rejected, 6, "size codes 6 and 7 of CMD, INFO and DATA rejected");
	is_int(p.framing_errors, 6, "each counted as a framing error");
	is_int(parsed, 18, "size codes 0..5 frame (at most 35 bytes)");
	n = lump_encode_data(f, sizeof(f), 1, "\x2a\0", 2);
	lump_parser_reset(&p);
	(void)lump_parser_push(&p, 0xF8, &m);	/* DATA, 128 bytes: impossible */
	parsed = 0;
	for (size_t i = 0; i < n; i++)
		parsed += lump_parser_push(&p, f[i], &m);
	ok(parsed == 1 && m.check_ok && m.payload[0] == 0x2a, "resynchronised on the next valid header");
}

/* Random streams: whatever arrives, the parser stays inside its buffer. */
static void random_streams(void)
{
	struct lump_parser p = { 0 };
	struct lump_msg m;
	unsigned frames = 0, overflows = 0;

	srand(15);
	for (unsigned i = 0; i < 200000; i++) {
		frames += lump_parser_push(&p, (uint8_t)rand(), &m);
		overflows += p.have > LUMP_MAX_FRAME || (frames && m.len > LUMP_MAX_PAYLOAD);
	}
	is_int(overflows, 0, "200 000 random bytes: never beyond the frame buffer");
	ok(frames > 1000 && p.framing_errors > 1000, "%u frames, %u framing errors", frames,
	   (unsigned)p.framing_errors);
}

int main(void)
{
	uint8_t f[LUMP_MAX_FRAME], type = 29;
	uint8_t speed[4] = { 0x00, 0xE1, 0x00, 0x00 };
	struct lump_parser p = { 0 };
	struct lump_msg m = { 0 };
	size_t n;
	int got = 0;

	tap_plan(20);
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
	oversized_headers();
	random_streams();
	return tap_done();
}
