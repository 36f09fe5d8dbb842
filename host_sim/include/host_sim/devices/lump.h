/*
 * lump.h — the LEGO UART sensor message protocol, as both ends frame it
 * (LEGO's d_uart_mod.c, pybricks' port_lump.c): header bits 7-6 message class, bits 5-3 payload size code,
 * bits 2-0 command or mode; check byte = 0xFF XOR every preceding byte.
 * Used by the sensor models (device side) and by tests (host side).
 */
#ifndef HOST_SIM_DEVICES_LUMP_H
#define HOST_SIM_DEVICES_LUMP_H

#include <stdbool.h>
#include <stddef.h>
#include <stdint.h>

/* Message classes (header bits 7-6). */
#define LUMP_CLASS_SYS   0x00U
#define LUMP_CLASS_CMD   0x40U
#define LUMP_CLASS_INFO  0x80U
#define LUMP_CLASS_DATA  0xC0U
#define LUMP_CLASS_MASK  0xC0U

/* SYS messages are one byte. */
#define LUMP_SYS_SYNC    0x00U
#define LUMP_SYS_NACK    0x02U
#define LUMP_SYS_ACK     0x04U

/* CMD commands (header bits 2-0). */
#define LUMP_CMD_TYPE    0U
#define LUMP_CMD_MODES   1U
#define LUMP_CMD_SPEED   2U
#define LUMP_CMD_SELECT  3U
#define LUMP_CMD_WRITE   4U

/* INFO sub-types (the byte after the header). */
#define LUMP_INFO_NAME   0x00U
#define LUMP_INFO_RAW    0x01U
#define LUMP_INFO_PCT    0x02U
#define LUMP_INFO_SI     0x03U
#define LUMP_INFO_SYMBOL 0x04U
#define LUMP_INFO_FORMAT 0x80U

/* FORMAT data types. */
#define LUMP_DATA8       0U
#define LUMP_DATA16      1U
#define LUMP_DATA32      2U
#define LUMP_DATAF       3U

#define LUMP_MAX_PAYLOAD 32U
#define LUMP_MAX_FRAME   (LUMP_MAX_PAYLOAD + 3U)   /* header, info, payload, check */

/* 0xFF XOR the n bytes: the check byte of a frame whose first n bytes these are. */
uint8_t lump_check(const uint8_t *bytes, size_t n);

/* The size code (LLL) of the smallest payload >= len, or -1 if len > 32. */
int lump_size_code(size_t len);

/* Payload bytes a header announces: 1 << LLL for CMD, INFO and DATA, 0 for SYS. */
size_t lump_payload_len(uint8_t header);

/* Total frame bytes a header announces: 1 (SYS), 2 + payload (CMD, DATA), 3 + payload (INFO). */
size_t lump_frame_len(uint8_t header);

/* Encodes a CMD message (payload zero-padded to its power of two) into out;
 * returns the frame length, or 0 if cmd > 7, len > 32 or cap is too small. */
size_t lump_encode_cmd(uint8_t *out, size_t cap, unsigned cmd, const void *payload, size_t len);

/* Encodes an INFO message for mode (0..7) and sub-type info; returns the length or 0. */
size_t lump_encode_info(uint8_t *out, size_t cap, unsigned mode, uint8_t info,
			const void *payload, size_t len);

/* Encodes a DATA message for mode (0..7); returns the length or 0. */
size_t lump_encode_data(uint8_t *out, size_t cap, unsigned mode, const void *payload, size_t len);

/* One decoded message. */
struct lump_msg {
	uint8_t header;
	uint8_t info;               /* INFO sub-type (INFO only) */
	uint8_t payload[LUMP_MAX_PAYLOAD];
	uint8_t len;                /* payload bytes (a power of two), 0 for SYS */
	bool check_ok;              /* the check byte matched (always true for SYS) */
};

/* A byte-wise frame assembler: feed bytes, get whole messages.  A header
 * announcing more than the longest valid frame (size codes 6 and 7: 64 and
 * 128 payload bytes) is a framing error: it is counted and dropped, and the
 * next byte is taken as a header again, so the parser resynchronises on the
 * next valid header and never writes past buf. */
struct lump_parser {
	uint8_t buf[LUMP_MAX_FRAME];
	size_t have;
	size_t need;
	uint32_t framing_errors;    /* headers dropped for an impossible length */
};

/* Empties the parser (keeps its error count). */
void lump_parser_reset(struct lump_parser *p);

/* Adds one byte; returns true and fills *msg when it completes a message. */
bool lump_parser_push(struct lump_parser *p, uint8_t byte, struct lump_msg *msg);

#endif /* HOST_SIM_DEVICES_LUMP_H */
