/*
 * lump.c — framing of the LEGO UART sensor protocol (LEGO's d_uart_mod.c, pybricks' port_lump.c).
 */
#include <string.h>
#include "host_sim/devices/lump.h"

/* 0xFF XOR the n bytes. */
uint8_t lump_check(const uint8_t *bytes, size_t n)
{
	uint8_t c = 0xFFU;

	for (size_t i = 0; i < n; i++)
		c ^= bytes[i];
	return c;
}

/* Smallest LLL with 1 << LLL >= len, or -1 beyond 32 bytes. */
int lump_size_code(size_t len)
{
	int lll = 0;

	if (len > LUMP_MAX_PAYLOAD)
		return -1;
	while ((1U << lll) < len)
		lll++;
	return lll;
}

/* Payload length announced by a header. */
size_t lump_payload_len(uint8_t header)
{
	if ((header & LUMP_CLASS_MASK) == LUMP_CLASS_SYS)
		return 0;
	return (size_t)1U << ((header >> 3) & 7U);
}

/* Frame length announced by a header. */
size_t lump_frame_len(uint8_t header)
{
	switch (header & LUMP_CLASS_MASK) {
	case LUMP_CLASS_SYS:
		return 1;
	case LUMP_CLASS_INFO:
		return 3 + lump_payload_len(header);
	default:
		return 2 + lump_payload_len(header);
	}
}

/* Common encoder: header, optional info byte, padded payload, check. */
static size_t lump_encode(uint8_t *out, size_t cap, uint8_t cls, unsigned low3, int info,
			  const void *payload, size_t len)
{
	int lll = lump_size_code(len);
	size_t plen, n = 0;

	if (lll < 0 || low3 > 7U || (len && !payload) || !out)
		return 0;
	plen = (size_t)1U << lll;
	if (cap < plen + (info >= 0 ? 3U : 2U))
		return 0;
	out[n++] = (uint8_t)(cls | ((unsigned)lll << 3) | low3);
	if (info >= 0)
		out[n++] = (uint8_t)info;
	if (len)
		memcpy(out + n, payload, len);
	memset(out + n + len, 0, plen - len);
	n += plen;
	out[n] = lump_check(out, n);
	return n + 1;
}

/* CMD message. */
size_t lump_encode_cmd(uint8_t *out, size_t cap, unsigned cmd, const void *payload, size_t len)
{
	return lump_encode(out, cap, LUMP_CLASS_CMD, cmd, -1, payload, len);
}

/* INFO message. */
size_t lump_encode_info(uint8_t *out, size_t cap, unsigned mode, uint8_t info,
			const void *payload, size_t len)
{
	return lump_encode(out, cap, LUMP_CLASS_INFO, mode, info, payload, len);
}

/* DATA message. */
size_t lump_encode_data(uint8_t *out, size_t cap, unsigned mode, const void *payload, size_t len)
{
	return lump_encode(out, cap, LUMP_CLASS_DATA, mode, -1, payload, len);
}

/* Empties the parser (keeps its error count). */
void lump_parser_reset(struct lump_parser *p)
{
	p->have = 0;
	p->need = 0;
}

/* Adds one byte; completes a message when the announced length is reached. */
bool lump_parser_push(struct lump_parser *p, uint8_t byte, struct lump_msg *msg)
{
	size_t hdr_extra;

	if (p->have == 0) {
		p->need = lump_frame_len(byte);
		if (p->need > sizeof(p->buf)) {
			p->framing_errors++;
			p->need = 0;
			return false;
		}
	}
	p->buf[p->have++] = byte;
	if (p->have < p->need)
		return false;

	memset(msg, 0, sizeof(*msg));
	msg->header = p->buf[0];
	if (p->need == 1) {
		msg->check_ok = true;
	} else {
		hdr_extra = (msg->header & LUMP_CLASS_MASK) == LUMP_CLASS_INFO ? 2U : 1U;
		msg->info = hdr_extra == 2U ? p->buf[1] : 0U;
		msg->len = (uint8_t)(p->need - hdr_extra - 1U);
		memcpy(msg->payload, p->buf + hdr_extra, msg->len);
		msg->check_ok = lump_check(p->buf, p->need - 1U) == p->buf[p->need - 1U];
	}
	p->have = 0;
	p->need = 0;
	return true;
}
