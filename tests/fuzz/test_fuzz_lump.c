/*
 * test_fuzz_lump.c — fuzz harness: host_sim's sensor-side LUMP frame parser
 * (what a sensor model makes of the bytes the host sends).  Any byte stream:
 * the parser never holds more than the longest frame, every message it
 * completes has a payload within the protocol's 32 bytes and a length its
 * header announces, and framing errors are counted, not ignored.
 */
#define _POSIX_C_SOURCE 200809L
#define _FILE_OFFSET_BITS 64	/* readdir of a 64-bit host directory from a 32-bit guest (qemu-arm) */
#include <stdbool.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include "host_sim/devices/lump.h"

#define FUZZ_NAME "lump"

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	struct lump_parser p = { 0 };
	struct lump_msg m;
	uint32_t oversized = 0;

	for (size_t i = 0; i < size; i++) {
		if (p.have == 0 && lump_frame_len(data[i]) > LUMP_MAX_FRAME)
			oversized++;
		if (lump_parser_push(&p, data[i], &m) &&
		    (m.len > LUMP_MAX_PAYLOAD || lump_frame_len(m.header) > LUMP_MAX_FRAME ||
		     (m.len && m.len != lump_payload_len(m.header)))) {
			fprintf(stderr, "fuzz: lump parser completed a malformed message\n");
			abort();
		}
		if (p.have > LUMP_MAX_FRAME)
			abort();
	}
	if (p.framing_errors != oversized) {
		fprintf(stderr, "fuzz: %u oversized headers, %u framing errors counted\n", oversized,
			(unsigned)p.framing_errors);
		abort();
	}
	return 0;
}

#include "fuzz_replay.h"
