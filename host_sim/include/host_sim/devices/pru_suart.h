/*
 * pru_suart.h — the AM1808's PRU subsystem running TI's soft-UART firmware,
 * with McASP0 as its serial pins and the shared RAM its buffers live in,
 * as the ARM sees them.  Host only.
 *
 * Regions (AM1808 TRM, memory map): PRUSS at 0x01C30000 (PSC0 LPSC 13):
 * data RAM 0/1 (0x0000/0x2000: the TRM gives 512 bytes each and reserves
 * the rest of each 8 KiB; the model answers all of it as RAM, since TI's
 * HAL clears data RAM 0 with word stores up to byte 514), the PRU
 * interrupt controller (0x4000), PRU0/PRU1 control (0x7000/0x7800),
 * instruction RAM 0/1 (0x8000/0xC000, 4 KiB each); McASP0 at 0x01D00000
 * (PSC1 LPSC 7), its control registers; the shared RAM at 0x80000000 (the
 * first 8 KiB, where TI's driver keeps its FIFOs).
 *
 * The PRU's instructions are not executed.  While PRU0 is enabled (CONTROL
 * ENABLE) with code in its instruction RAM, the model does what TI's soft
 * UART firmware (PRU_SUART_Emulation.p, in LEGO's d_uart sources) does with
 * the channel registers in data RAM 0, per character instead of per McASP
 * sample:
 *   - a write of system event 32 (ARM to PRU0) to the INTC's SISR makes it
 *     serve the lowest channel whose control word has SR (bit 2) set: clear
 *     SR and the channel's bit in the global ISR (0x82), set READY and the
 *     channel-active bit (status bit 7); for a TX channel clear the bytes
 *     counter and send Config2.DATALEN + 1 bytes from the buffer address in
 *     the channel's data word (a shared RAM address), one character time each;
 *   - TX done: COMPLETE set, READY cleared, and if the channel's bit is set
 *     in the global IMR (0x80), its ISR bit and system event 34 + channel;
 *   - an RX request also re-activates the channel's serializer as a receiver
 *     (SRCTL 0x000E) if the ARM deactivated it;
 *   - RX (active channel, its McASP serializer in receive mode): each byte is
 *     stored at buffer + bytes counter; at DATALEN + 1 bytes the status FIFO
 *     index bit (1) is cleared, at twice that set and the counter zeroed, and
 *     each time, if READY, the channel's ISR bit and event 34 + channel;
 *     a line held low a character time is a break (BI, ERR, global bit 9);
 *     MAX_RX_TIMEOUT_TRIES (0x88) McASP receive frames without a start bit
 *     after a byte, with Config1 bit 14 set and the counter neither 0 nor
 *     DATALEN + 1, set TIMEOUT, clear Config1 bit 14 and interrupt;
 *   - an event the PRU raises also enables it (EISR), as the firmware does.
 * Bit times come from the McASP clock dividers the driver programmed, from
 * the 24 MHz AUXCLK: transmit (AHCLKXDIV + 1)(CLKXDIV + 1) per bit times the
 * channel's prescaler (Config1 bits 9:0); receive (AHCLKRDIV + 1)(CLKRDIV + 1)
 * per sample, 8 samples a bit (RFMT slot size) times the prescaler.
 * The INTC maps events to channels (CMR) and channels to host interrupts
 * (HMR); host interrupts 2..9 are PRU_EVTOUT0..7, AINTC lines 3..10.
 */
#ifndef HOST_SIM_DEVICES_PRU_SUART_H
#define HOST_SIM_DEVICES_PRU_SUART_H

#include <stdbool.h>
#include <stdint.h>
#include "host_sim/board.h"

#define HS_PRUSS_BASE		0x01C30000U
#define HS_MCASP0_BASE		0x01D00000U
#define HS_SHARED_RAM_BASE	0x80000000U
#define HS_SHARED_RAM_MODELLED	0x2000U
#define HS_MCASP_SERIALIZERS	16U
#define HS_PRU_AUXCLK_HZ	24000000U

struct hs_pru_suart;

/* What a McASP serial pin of the soft UART is wired to: called when a byte
 * sent on transmit serializer ser has left the wire. */
struct hs_pru_suart_peer {
	void (*tx_byte)(void *ctx, unsigned ser, uint8_t byte, uint32_t baud);
	void *ctx;
};

extern const struct hs_device hs_pru_suart_device;

/* The model the board created, or NULL. */
struct hs_pru_suart *hs_pru_suart(void);
/* Wires the transmit serializers (NULL: none). */
void hs_pru_suart_set_peer(struct hs_pru_suart *s, const struct hs_pru_suart_peer *peer);
/* A byte sent at baud finished arriving on receive serializer ser. */
void hs_pru_suart_rx_byte(struct hs_pru_suart *s, unsigned ser, uint8_t byte, uint32_t baud);
/* The level of receive serializer ser's line (low a character time: a break). */
void hs_pru_suart_rx_line(struct hs_pru_suart *s, unsigned ser, bool high);

/* Counters for tests. */
struct hs_pru_suart_stats {
	unsigned tx_bytes, rx_bytes, rx_dropped, rx_garbled, breaks, timeouts, events;
};
const struct hs_pru_suart_stats *hs_pru_suart_get_stats(const struct hs_pru_suart *s);

#endif
