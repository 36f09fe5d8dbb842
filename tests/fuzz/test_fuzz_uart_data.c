/*
 * test_fuzz_uart_data.c — fuzz harness: d_uart's DATA parser.  A hand-made
 * sensor on input port 1 (framed with host_sim's LUMP encoder, injected into
 * the port's UART) completes the handshake whenever the port is not in DATA;
 * then the input arrives at the sensor's 57600 baud in FIFO-sized bursts, as
 * frames of any class, size code and check byte would.  After it a valid frame
 * sent every 10 ms must be served within 400 ms (a stalled message costs its
 * wire time and one byte; the longest is 35 bytes), unless the driver
 * restarted the handshake (repeated errors), which is also allowed.
 */
#define _POSIX_C_SOURCE 200809L
#define _FILE_OFFSET_BITS 64	/* readdir of a 64-bit host directory from a 32-bit guest (qemu-arm) */
#include "fuzz_brick.h"
#include "uart_hack.h"
#include "host_sim/devices/ev3_ports.h"
#include "host_sim/devices/lump.h"
#include "host_sim/devices/uart16550.h"

#define FUZZ_NAME "uart_data"
#define PORT 0
#define DATA_BAUD 57600U
#define RESYNC_FRAMES 40U	/* the longest message's 35 bytes, each a stall, and some */

static const struct lms_uart_shm *shm;

static void start_port(void)
{
	const struct lms_uart_shm *map = NULL;

	if (uart_svc_map(&map) != E_OK || uart_svc_set_mode(PORT, 0) != E_OK)
		abort();
	shm = map;
}

static void send(const uint8_t *b, size_t n, uint32_t baud, size_t size)
{
	struct hs_uart *u = ev3_input_uart(PORT);

	for (size_t i = 0; i < n; i++) {
		hs_uart_rx_byte(u, b[i], baud);
		if (i % 8 == 7)
			fz_settle(1, size);
	}
	fz_settle(1, size);
}

static void send_frame(size_t n, const uint8_t *f, size_t size)
{
	send(f, n, 2400, size);
}

/* In the worker task: accept the new description, so that samples are stored. */
static void accept(const uint8_t *data, size_t size)
{
	(void)data;
	(void)size;
	(void)uart_svc_clear_changed(PORT);
}

static uint8_t port_state(void)
{
	return *(const volatile uint8_t *)&shm->ext.port[PORT].state;
}

/* The sensor side of a handshake: one mode, one DATA8 value, 57600 baud. */
static void handshake(size_t size)
{
	static const uint8_t type = 50, modes = 0, format[4] = { 1, LUMP_DATA8, 3, 0 };
	static const uint8_t speed[4] = { DATA_BAUD & 0xff, DATA_BAUD >> 8 & 0xff, DATA_BAUD >> 16, 0 };
	static const uint8_t ack = LUMP_SYS_ACK;
	uint8_t f[LUMP_MAX_FRAME];

	if (port_state() != LMS_UART_STATE_SYNC)
		fz_settle(300, size);	/* a reconnection's break first */
	send_frame(lump_encode_cmd(f, sizeof(f), LUMP_CMD_TYPE, &type, 1), f, size);
	send_frame(lump_encode_cmd(f, sizeof(f), LUMP_CMD_MODES, &modes, 1), f, size);
	send_frame(lump_encode_cmd(f, sizeof(f), LUMP_CMD_SPEED, speed, 4), f, size);
	send_frame(lump_encode_info(f, sizeof(f), 0, LUMP_INFO_NAME, "FUZZ", 4), f, size);
	send_frame(lump_encode_info(f, sizeof(f), 0, LUMP_INFO_FORMAT, format, 4), f, size);
	send(&ack, 1, 2400, size);
	fz_settle(30, size);
	fz_run(accept, NULL, 0);
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	uint8_t f[LUMP_MAX_FRAME], v = 0x5a;
	size_t n;

	fz_boot(start_port);
	if (port_state() != LMS_UART_STATE_DATA)
		handshake(size);
	if (port_state() != LMS_UART_STATE_DATA)
		return 0;	/* the driver is still resetting the sensor: next input */
	send(data, size, DATA_BAUD, size);
	fz_settle(12, size);	/* longer than the longest frame takes: 35 bytes, 9 ms */
	n = lump_encode_data(f, sizeof(f), 0, &v, 1);
	/* a valid frame every 10 ms until one is served: each stalled message in the garbage
	 * costs its wire time (9 ms) and one byte, so the bound is RESYNC_FRAMES of them */
	for (unsigned k = 0; k < RESYNC_FRAMES; k++) {
		send(f, n, DATA_BAUD, size);
		if (port_state() != LMS_UART_STATE_DATA || lms_uart_sample(shm, PORT, 0))
			return 0;	/* served, or the driver restarted the handshake */
		fz_settle(9, size);
	}
	{
		const struct lms_uart_port_ext *x = &shm->ext.port[PORT];

		fprintf(stderr, "fuzz: no valid frame served within %u ms of a %zu-byte input "
			"(state %u, flags %#x, mode %d, data mode %d, frames %u)\n", RESYNC_FRAMES * 10,
			size, x->state, x->flags, x->mode, x->data_mode, (unsigned)x->frames);
		abort();
	}
	return 0;
}

#define FUZZ_FINISH fz_shutdown
#include "fuzz_replay.h"
