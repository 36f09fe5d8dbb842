/*
 * test_uart16550_state.c — the port UART's status seen through the state its
 * byte path keeps between reads: LSR's FIFO error summary (RXFIFOE) with
 * errors behind the head, reported once, and forgotten when the byte leaves
 * unreported; the character timeout while the FIFO is at its trigger level,
 * exposed by raising the trigger (long after, or before it is due); THRE
 * raised when a divisor write lets a waiting byte start.
 */
#include "devtest.h"
#include "host_sim/intc.h"
#include "host_sim/devices/uart16550.h"

#define U0 HS_UART0_BASE
#define LSR (U0 + HS_UART_LSR)
#define IIR (U0 + HS_UART_IIR)
#define US 1000ULL

#define LSR_DR      0x01U
#define LSR_FE      0x08U
#define LSR_RXFIFOE 0x80U
#define FCR_FIFO_TRIGGER_1  0x01U
#define FCR_FIFO_TRIGGER_4  0x41U

/* 115200 baud at the UART0 clock (a 10-bit byte ~86.8 us, timeout ~347 us),
 * 8N1, FIFOs on and cleared, trigger 1, interrupts off. */
static uint32_t setup(void)
{
	wr32(U0 + 0x30, 0x6001);
	wr32(U0 + HS_UART_LCR, 0x03);
	wr32(U0 + 0x20, 81);
	wr32(U0 + 0x24, 0);
	wr32(IIR, 0x07);
	wr32(U0 + HS_UART_IER, 0);
	return hs_uart_baud(ev3_input_uart(1));
}

static unsigned iir_id(void)
{
	return rd32(IIR) & HS_UART_IIR_ID_MASK;
}

int main(void)
{
	struct hs_uart *u;
	uint32_t baud, lsr;

	tap_plan(16);
	devtest_boot(2, NULL);
	u = ev3_input_uart(1);
	baud = setup();

	/* a framing error behind a good byte: RXFIFOE at once, FE when it reaches the head */
	hs_uart_rx_byte(u, 0x11, baud);
	hs_uart_rx_byte(u, 0x40, 2400);
	lsr = rd32(LSR);
	ok((lsr & (LSR_DR | LSR_FE | LSR_RXFIFOE)) == (LSR_DR | LSR_RXFIFOE),
	   "error behind the head: DR and RXFIFOE, no FE (LSR 0x%02x)", lsr);
	is_int(rd32(U0 + HS_UART_RBR), 0x11, "the good byte first");
	lsr = rd32(LSR);
	ok((lsr & (LSR_DR | LSR_FE | LSR_RXFIFOE)) == (LSR_DR | LSR_FE | LSR_RXFIFOE),
	   "error at the head: DR, FE and RXFIFOE (LSR 0x%02x)", lsr);
	lsr = rd32(LSR);
	ok((lsr & (LSR_FE | LSR_RXFIFOE)) == 0, "reported: the next read has neither FE nor RXFIFOE (0x%02x)", lsr);
	(void)rd32(U0 + HS_UART_RBR);

	/* an error byte read out of RBR before LSR reported it leaves no RXFIFOE behind */
	hs_uart_rx_byte(u, 0x40, 2400);
	(void)rd32(U0 + HS_UART_RBR);
	hs_uart_rx_byte(u, 0x22, baud);
	lsr = rd32(LSR);
	ok((lsr & (LSR_DR | LSR_FE | LSR_RXFIFOE)) == LSR_DR, "unreported error gone with its byte (LSR 0x%02x)", lsr);
	(void)rd32(U0 + HS_UART_RBR);

	/* at the trigger level the data interrupt shows; raising the trigger long after
	 * the bytes came reveals the character timeout that has run meanwhile */
	wr32(U0 + HS_UART_IER, 0x01);       /* ERBI */
	hs_uart_rx_byte(u, 0x31, baud);
	hs_uart_rx_byte(u, 0x32, baud);
	is_int(iir_id(), HS_UART_IIR_RX_DATA, "two bytes at trigger 1: received data");
	hs_sim_run_for(MS);
	is_int(iir_id(), HS_UART_IIR_RX_DATA, "idle 1 ms: still received data (it outranks the timeout)");
	wr32(IIR, FCR_FIFO_TRIGGER_4);
	is_int(iir_id(), HS_UART_IIR_RX_TIMEOUT, "trigger raised to 4: the timeout is already there");
	ok(hs_intc_pending(EV3_UART0_INTNO), "and keeps the line asserted");
	(void)rd32(U0 + HS_UART_RBR);
	(void)rd32(U0 + HS_UART_RBR);
	is_int(iir_id(), HS_UART_IIR_NONE, "drained: nothing pending");

	/* raised before the timeout is due: it comes 4 characters after the last byte */
	wr32(IIR, FCR_FIFO_TRIGGER_1);
	hs_uart_rx_byte(u, 0x33, baud);
	hs_uart_rx_byte(u, 0x34, baud);
	hs_sim_run_for(100 * US);
	wr32(IIR, FCR_FIFO_TRIGGER_4);
	is_int(iir_id(), HS_UART_IIR_NONE, "trigger raised 100 us after: below it, no timeout yet");
	hs_sim_run_for(200 * US);
	is_int(iir_id(), HS_UART_IIR_NONE, "300 us idle: still none");
	hs_sim_run_for(100 * US);
	is_int(iir_id(), HS_UART_IIR_RX_TIMEOUT, "400 us idle: character timeout");
	wr32(IIR, 0x07);
	wr32(U0 + HS_UART_IER, 0);

	/* a byte waiting for a baud clock starts when the divisor is written: THR empty */
	wr32(U0 + 0x20, 0);
	wr32(U0 + HS_UART_IER, 0x02);       /* ETBEI, THR empty: THRE */
	is_int(iir_id(), HS_UART_IIR_THR_EMPTY, "ETBEI with THR empty: THRE");
	wr32(U0 + HS_UART_RBR, 0x55);
	is_int(iir_id(), HS_UART_IIR_NONE, "a byte waits in THR without a baud clock");
	wr32(U0 + 0x20, 81);
	is_int(iir_id(), HS_UART_IIR_THR_EMPTY, "divisor written: the byte shifts out, THRE");
	wr32(U0 + HS_UART_IER, 0);
	hs_sim_shutdown();
	return tap_done();
}
