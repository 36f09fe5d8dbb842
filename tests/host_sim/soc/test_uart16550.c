/*
 * test_uart16550.c — the port UARTs' register semantics: baud from the
 * divisor and module clock, 10 bit-times per byte (11 and 12 with 2 stop
 * bits and parity, 7.5 with 5 data bits and 1.5 stop bits), FIFO and trigger level,
 * LSR bits and clear-on-read errors, overrun, IIR priorities and the THRE
 * clear on IIR read, the level on the AINTC line, DLAB, PWREMU_MGMT reset,
 * break, and the stand-in UARTs of ports 3 and 4.
 */
#include "devtest.h"
#include "host_sim/intc.h"
#include "host_sim/devices/uart16550.h"

#define U0 HS_UART0_BASE

/* Virtual ns from a THR write to the looped-back byte's arrival in RBR, with LCR lcr (1 us steps). */
static uint64_t loopback_char_ns(uint32_t lcr)
{
	uint64_t t0;

	wr32(U0 + 0x0C, lcr);
	t0 = hs_now();
	wr32(U0 + 0x00, 0x15);
	while (!(rd32(U0 + 0x14) & 0x01))
		hs_sim_run_for(1000);
	(void)rd32(U0 + 0x00);
	wr32(U0 + 0x0C, 0x03);
	return hs_now() - t0;
}

static void setup(uint32_t base, uint32_t clock, uint32_t baud, uint32_t fcr)
{
	uint32_t div = (clock + 8U * baud) / (16U * baud);

	wr32(base + 0x30, 0x6001);
	wr32(base + 0x0C, 0x03);
	wr32(base + 0x20, div & 0xFF);
	wr32(base + 0x24, div >> 8);
	wr32(base + HS_UART_IIR, fcr);    /* FCR */
}

int main(void)
{
	struct hs_uart *u = NULL;
	uint64_t t0;
	uint32_t lsr, iir;

	tap_plan(27);
	devtest_boot(2, NULL);
	u = ev3_input_uart(1);
	ok(u != NULL, "UART0 serves input port 2");
	ok(ev3_input_uart(2) && ev3_input_uart(3), "stand-in UARTs for ports 3 and 4");

	/* 115200 baud at 150 MHz: divisor 81, 10 bits = ~86.8 us; loopback */
	setup(U0, 150000000U, 115200, 0x07);
	wr32(U0 + HS_UART_IIR, 0x01);
	is_int(hs_uart_baud(u), 115741, "baud = 150 MHz / (16 x 81)");
	wr32(U0 + 0x10, 0x10);                      /* MCR.LOOP */
	t0 = hs_now();
	wr32(U0 + 0x00, 0x5A);
	ok(!(rd32(U0 + 0x14) & 0x40), "TEMT clear while the byte shifts");
	while (!(rd32(U0 + 0x14) & 0x01))
		hs_sim_run_for(1000);
	in_range(hs_now() - t0, 86000, 88500, "one byte = 10 bit times (%llu ns)", (unsigned long long)(hs_now() - t0));
	is_int(rd32(U0 + 0x00), 0x5A, "looped back into RBR");
	lsr = rd32(U0 + 0x14);
	ok((lsr & 0x61) == 0x60, "LSR: THRE and TEMT, no data");
	/* LCR.STB (AM1808 TRM, UART LCR): 2 stop bits, 1.5 with 5-bit words; one bit is 8.64 us */
	t0 = loopback_char_ns(0x07);
	in_range(t0, 95000, 96500, "8 data bits, 2 stop bits: 11 bit times (%llu ns)", (unsigned long long)t0);
	t0 = loopback_char_ns(0x0F);
	in_range(t0, 103600, 105100, "8 data bits, parity, 2 stop bits: 12 bit times (%llu ns)", (unsigned long long)t0);
	t0 = loopback_char_ns(0x04);
	in_range(t0, 64800, 66300, "5 data bits, STB: 1.5 stop bits, 7.5 bit times (%llu ns)", (unsigned long long)t0);

	/* 17 bytes into a 16-byte FIFO: overrun, OE cleared by reading LSR */
	for (int i = 0; i < 17; i++) {
		while (!(rd32(U0 + 0x14) & 0x20))
			hs_sim_run_for(1000);
		wr32(U0 + 0x00, (uint32_t)i);
	}
	hs_sim_run_for(3 * MS);
	lsr = rd32(U0 + 0x14);
	ok((lsr & 0x03) == 0x03, "17th byte: LSR.DR and OE");
	ok(!(rd32(U0 + 0x14) & 0x02), "OE cleared by the read");
	is_int(hs_uart_get_stats(u)->overruns, 1, "one byte lost");
	is_int(rd32(U0 + 0x00), 0, "the FIFO kept the first 16");
	wr32(U0 + HS_UART_IIR, 0x03);                      /* clear RX */
	ok(!(rd32(U0 + 0x14) & 0x01), "FCR RXCLR empties the FIFO");

	/* interrupts: IIR priorities, THRE cleared by reading IIR, level on line 25 */
	wr32(U0 + HS_UART_IIR, 0x41);                      /* FIFO, trigger 4 */
	wr32(U0 + 0x04, 0x03);                      /* ERBI, ETBEI */
	iir = rd32(U0 + HS_UART_IIR);
	ok((iir & HS_UART_IIR_ID_MASK) == HS_UART_IIR_THR_EMPTY &&
	   (iir & HS_UART_IIR_FIFOS_ON) == HS_UART_IIR_FIFOS_ON,
	   "enabling ETBEI with empty THR: IIR = THRE, FIFOs on");
	iir = rd32(U0 + HS_UART_IIR);
	is_int(iir & HS_UART_IIR_ID_MASK, HS_UART_IIR_NONE, "reading IIR cleared the THRE interrupt");
	for (int i = 0; i < 4; i++)
		wr32(U0 + 0x00, 0x30U + (uint32_t)i);
	hs_sim_run_for(500 * 1000);
	ok(hs_intc_pending(EV3_UART0_INTNO), "4 bytes reach the trigger: line 25 asserted");
	is_int(rd32(U0 + HS_UART_IIR) & HS_UART_IIR_ID_MASK, HS_UART_IIR_RX_DATA, "IIR: received data available");
	(void)rd32(U0 + 0x00);
	hs_sim_run_for(500 * 1000);
	is_int(rd32(U0 + HS_UART_IIR) & HS_UART_IIR_ID_MASK, HS_UART_IIR_RX_TIMEOUT, "below trigger, 4 characters idle: character timeout");
	while (rd32(U0 + 0x14) & 1U)
		(void)rd32(U0 + 0x00);
	iir = rd32(U0 + HS_UART_IIR) & HS_UART_IIR_ID_MASK;
	ok(iir == HS_UART_IIR_NONE || iir == HS_UART_IIR_THR_EMPTY, "drained: no receive interrupt left");
	wr32(U0 + 0x04, 0);

	/* DLAB maps the divisor at 0x00/0x04 */
	wr32(U0 + 0x0C, 0x83);
	is_int(rd32(U0 + 0x00), 81, "DLAB: offset 0 reads DLL");
	wr32(U0 + 0x0C, 0x03);

	/* PWREMU_MGMT: transmitter in reset ignores THR */
	wr32(U0 + 0x30, 0x2001);
	wr32(U0 + 0x00, 0x11);
	hs_sim_run_for(MS);
	ok(!(rd32(U0 + 0x14) & 0x01), "UTRST = 0: nothing sent");
	wr32(U0 + 0x30, 0x6001);
	wr32(U0 + 0x10, 0);

	/* a break from the line: one 0x00 with BI and FE */
	hs_uart_rx_line(u, false);
	hs_sim_run_for(MS);
	lsr = rd32(U0 + 0x14);
	ok((lsr & 0x19) == 0x19, "line low: break character (DR, FE, BI)");
	is_int(rd32(U0 + 0x00), 0, "break reads as 0x00");
	hs_uart_rx_line(u, true);

	/* wrong speed: garbled with FE */
	hs_uart_rx_byte(u, 0x40, 2400);
	ok((rd32(U0 + 0x14) & 0x09) == 0x09, "a 2400-baud byte at 115200: framing error");

	/* a line with no UART on it (a peer not yet attached): ignored, not dereferenced */
	hs_uart_rx_byte(NULL, 0x40, 115200);
	hs_uart_rx_line(NULL, false);
	ok(true, "bytes and line levels for no UART are ignored");
	hs_sim_shutdown();
	return tap_done();
}
