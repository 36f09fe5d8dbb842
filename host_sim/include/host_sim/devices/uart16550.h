/*
 * uart16550.h — the AM1808 UART (16550-compatible) as used behind the EV3
 * input ports.  The model is one 16550 at an address, on an interrupt line,
 * with a module clock (struct hs_uart_cfg); which UARTs a board has and
 * what sits on their lines is the board's business (the EV3: UART1 behind
 * port 1, UART0 behind port 2 and two stand-ins for the PRU soft UARTs of
 * ports 3 and 4, ev3_ports.h: ev3_port_uart).  Host only.
 *
 * Registers are 32-bit words (AM1808 TRM): RBR/THR 0x00, IER 0x04, IIR/FCR
 * 0x08, LCR 0x0C, MCR 0x10, LSR 0x14, MSR 0x18, SCR 0x1C, DLL 0x20, DLH
 * 0x24, REVID1/2 0x28/0x2C, PWREMU_MGMT 0x30, MDR 0x34; byte accesses are
 * accepted too.  DLL/DLH also appear at 0x00/0x04 while LCR.DLAB is set.
 * Baud = module clock / (16 or 13 (MDR.OSM_SEL) x divisor).  Each byte
 * takes (1 + data + parity + stop) bit times on the wire; 16-byte FIFOs
 * with the FCR trigger level and the 4-character timeout; LSR error bits
 * clear on read; reading IIR clears a THRE interrupt; PWREMU_MGMT URRST /
 * UTRST at 0 hold receiver / transmitter in reset; LCR.BC sends a break.
 * A received byte whose baud differs from the UART's by more than 4 % is
 * garbled (framing error), as a real receiver samples the wrong bits.
 */
#ifndef HOST_SIM_DEVICES_UART16550_H
#define HOST_SIM_DEVICES_UART16550_H

#include <stdbool.h>
#include <stdint.h>
#include "host_sim/board.h"

struct hs_uart;

/* Register offsets (32-bit words, AM1808 TRM, UART chapter). */
#define HS_UART_RBR	0x00U   /* THR on writes, DLL while LCR.DLAB */
#define HS_UART_IER	0x04U
#define HS_UART_IIR	0x08U   /* FCR on writes */
#define HS_UART_LCR	0x0CU
#define HS_UART_LSR	0x14U

/* IIR bits 3-0, the interrupt identification, highest priority first
 * (AM1808 TRM, UART chapter, table "Interrupt Identification and Interrupt
 * Clearing Information"); bits 7-6 are set while the FIFOs are enabled. */
#define HS_UART_IIR_LINE_STATUS	0x6U    /* overrun, parity, framing error or break */
#define HS_UART_IIR_RX_DATA	0x4U    /* receiver data at the trigger level */
#define HS_UART_IIR_RX_TIMEOUT	0xCU    /* character timeout with data in the FIFO */
#define HS_UART_IIR_THR_EMPTY	0x2U
#define HS_UART_IIR_NONE	0x1U    /* no interrupt pending */
#define HS_UART_IIR_ID_MASK	0x0FU
#define HS_UART_IIR_FIFOS_ON	0xC0U

/* One UART instance: register base, AINTC line, module clock, power domain. */
struct hs_uart_cfg {
	const char *name;           /* region name */
	uintptr_t base;
	unsigned intno;
	uint32_t clock_hz;          /* module clock: baud = clock / (16 or 13 * divisor) */
	unsigned power;             /* HS_PSCx_MODULE(n), or HS_NO_PSC */
};

/* Creates a UART (cfg must stay valid while it exists) in the state Linux
 * leaves it, or at TRM reset with the board's cold_reset.  Returns E_OK
 * and *out, E_NOMEM, or E_PAR if its registers cannot be placed. */
ER hs_uart_create(const struct hs_uart_cfg *cfg, struct hs_uart **out);
/* Stops its events and frees it. */
void hs_uart_destroy(struct hs_uart *u);

/* The far end: called when a byte the UART sent has left the wire, and
 * when the UART starts/stops sending a break (LCR.BC). */
struct hs_uart_peer {
	void (*tx_byte)(void *ctx, uint8_t byte, uint32_t baud);
	void (*tx_break)(void *ctx, bool active);
	void *ctx;
};
void hs_uart_set_peer(struct hs_uart *u, const struct hs_uart_peer *peer);

/* A byte finished arriving on the RX line, sent at baud. */
void hs_uart_rx_byte(struct hs_uart *u, uint8_t byte, uint32_t baud);
/* The RX line level: held low for a character time or more is a break. */
void hs_uart_rx_line(struct hs_uart *u, bool high);

/* Current baud (0 if the divisor is 0 or the UART is in reset). */
uint32_t hs_uart_baud(const struct hs_uart *u);

struct hs_uart_stats {
	uint32_t rx_bytes, tx_bytes;
	uint32_t overruns;          /* bytes lost because the RX FIFO was full */
	uint32_t framing_errors;    /* garbled bytes (speed mismatch, break) */
	uint32_t breaks;
	uint32_t rx_in_reset;       /* bytes that arrived while the receiver was in reset */
};
const struct hs_uart_stats *hs_uart_get_stats(const struct hs_uart *u);

#endif /* HOST_SIM_DEVICES_UART16550_H */
