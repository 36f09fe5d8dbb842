/*
 * spi.h — the AM1808's SPI0 and SPI1 masters (AM1808 TRM, "Serial Peripheral
 * Interface (SPI)" chapter).  Host only.
 *
 * One model, two instances: SPI0 at 0x01C41000 (PSC0 LPSC 4, AINTC 20,
 * clocked by PLL0_SYSCLK2) and SPI1 at 0x01F0E000 (PSC1 LPSC 10, AINTC 56,
 * clocked by the ASYNC3 domain, PLL1_SYSCLK2 as LEGO's kernel sets it).
 * Registers: SPIGCR0/1, SPIINT0, SPILVL, SPIFLG, SPIPC0-5, SPIDAT0/1, SPIBUF
 * (RXEMPTY bit 31, RXOVR 30, TXFULL 29), SPIEMU, SPIDELAY, SPIDEF,
 * SPIFMT0-3, INTVEC0/1.  A master transfer starts when SPIDAT0 or SPIDAT1
 * is written with the module out of reset and enabled, and lasts CHARLEN bit
 * times at the module clock / (PRESCALE + 1) plus the chip-select delays
 * (C2TDELAY, T2CDELAY); a second word waits in the TX buffer (TXFULL).  A
 * SPIBUF read while the answer is still on its way stalls the reading CPU
 * until it arrives (hs_access_stall_until), so a polling loop costs one
 * access.
 */
#ifndef HOST_SIM_DEVICES_SPI_H
#define HOST_SIM_DEVICES_SPI_H

#include <stdbool.h>
#include <stdint.h>
#include "host_sim/board.h"

#define HS_SPI_BUSES   2U
#define HS_SPI1_BASE   0x01F0E000U
#define EV3_SPI0_INTNO 20U
#define HS_SPI1_INTNO  56U

/* The SoC peripherals. */
extern const struct hs_device hs_spi0_device;
extern const struct hs_device hs_spi1_device;

/* The slave on a bus: frame(ctx, word) is called as a frame starts with the
 * word the master shifts out and returns the word the slave shifts back
 * during it; frame_done(ctx, word), if set, as the frame's last bit is
 * clocked (when a write-only slave latches the word). */
struct hs_spi_peer {
	uint16_t (*frame)(void *ctx, uint16_t word);
	void (*frame_done)(void *ctx, uint16_t word);
	void *ctx;
};
/* Connects peer as bus's slave (copied; NULL: none, the master reads 0). */
void hs_spi_connect(unsigned bus, const struct hs_spi_peer *peer);
/* The SPIFMTn register the frame in progress on bus uses (0 without the module). */
uint32_t hs_spi_format(unsigned bus);

struct ev3_spi_stats {
	uint32_t transfers;
	uint32_t rx_overruns;
	uint32_t stalls;            /* SPIBUF reads that waited for a transfer */
	uint32_t deferred_ends;     /* frames whose end was completed when observed, not as an event */
};
/* Counters of bus (zeros without the module). */
const struct ev3_spi_stats *hs_spi_stats(unsigned bus);
/* SPI0's counters. */
const struct ev3_spi_stats *ev3_spi_get_stats(void);
/* Frames whose end only the module's own registers show (no interrupt
 * enabled, no word waiting, no slave hook) are completed when next observed
 * instead of by an event, with the same observable results (on by default);
 * off makes every frame end an event, for comparing the two. */
void hs_spi_defer_private_ends(bool on);

#endif /* HOST_SIM_DEVICES_SPI_H */
