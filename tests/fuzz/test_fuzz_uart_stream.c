/*
 * test_fuzz_uart_stream.c — fuzz harness: any byte stream a sensor cable can
 * deliver, into d_uart through host_sim's UART (the receiver of input port 1),
 * in whatever state the port is in (SYNC, the handshake, DATA, TERMINAL).
 * The first byte picks the line speed the bytes arrive at (2400, 9600, 57600
 * or 115200 baud: right or wrong for the port's state); the rest arrive in
 * FIFO-sized bursts with 1 ms between them, then 20 ms run.  The port was
 * handed to d_uart at boot and stays so; its state carries from input to
 * input, as on a cable.  See docs/reliability.md.
 */
#define _POSIX_C_SOURCE 200809L
#define _FILE_OFFSET_BITS 64	/* readdir of a 64-bit host directory from a 32-bit guest (qemu-arm) */
#include "fuzz_brick.h"
#include "uart_hack.h"
#include "host_sim/devices/ev3_ports.h"
#include "host_sim/devices/uart16550.h"

#define FUZZ_NAME "uart_stream"
#define PORT 0

static void start_port(void)
{
	if (uart_svc_set_mode(PORT, 0) != E_OK)
		abort();
}

int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size);
int LLVMFuzzerTestOneInput(const uint8_t *data, size_t size)
{
	static const uint32_t bauds[] = { 2400, 9600, 57600, 115200 };
	struct hs_uart *u;
	uint32_t baud;

	fz_boot(start_port);
	if (size == 0)
		return 0;
	u = ev3_input_uart(PORT);
	baud = bauds[data[0] & 3U];
	for (size_t i = 1; i < size; i++) {
		hs_uart_rx_byte(u, data[i], baud);
		if (i % 8 == 0)
			fz_settle(1, size);
	}
	fz_settle(20, size);
	return 0;
}

#define FUZZ_FINISH fz_shutdown
#include "fuzz_replay.h"
