/*
 * spi_adc.h — SPI0 of the AM1808 with the EV3's analog-to-digital converter
 * on it (AM1808 TRM; LEGO's d_analog.c).  Host only.
 *
 * SPI0 (0x01C41000): SPIGCR0/1, SPIINT0, SPILVL, SPIFLG, SPIPC0-5,
 * SPIDAT0/1, SPIBUF (RXEMPTY bit 31, RXOVR 30, TXFULL 29), SPIEMU,
 * SPIDELAY, SPIDEF, SPIFMT0-3, INTVEC0/1.  A master transfer starts when
 * SPIDAT0 or SPIDAT1 is written with the module out of reset and enabled,
 * and lasts CHARLEN bit times at 150 MHz / (PRESCALE + 1) plus the chip-
 * select delays (16 bits at 2 MHz: 8 us + setup/hold); a second word waits
 * in the TX buffer (TXFULL).  A SPIBUF read while the answer is still on
 * its way stalls the reading CPU until it arrives (hs_access_stall_until),
 * so a polling loop costs one access.
 *
 * The board connects the converter as SPI0's slave (hs_spi0_connect): it
 * behaves as a TI ADS7957 in manual mode: command word
 * 0x1840 | ch << 7 selects channel ch (bit 6: 0-5 V range), the channel is
 * sampled during the next frame and its result is shifted out in the frame
 * after that (two frames late), as bits 15-12 channel and bits 11-2 a
 * 10-bit value (LEGO reads 12 bits as 4095 = 5000 mV).  The voltage of
 * each channel comes from ev3_adc_channel_mv (ev3_brick.h).
 */
#ifndef HOST_SIM_DEVICES_SPI_ADC_H
#define HOST_SIM_DEVICES_SPI_ADC_H

#include <stdint.h>
#include "host_sim/board.h"

/* SPI0 (SoC peripheral). */
extern const struct hs_device hs_spi0_device;

#define EV3_SPI0_INTNO 20U

/* The slave on SPI0's chip select: frame(ctx, word) is called as a frame
 * starts with the word the master shifts out and returns the word the
 * slave shifts back during it. */
struct hs_spi_peer {
	uint16_t (*frame)(void *ctx, uint16_t word);
	void *ctx;
};
/* Connects peer as the slave (copied; NULL: none, the master reads 0). */
void hs_spi0_connect(const struct hs_spi_peer *peer);

/* The EV3's converter on SPI0 (board model). */
extern const struct hs_device ev3_adc_device;

/* The ADC's answer word for a channel at a voltage (ADS7957 layout, 0-5 V range). */
uint16_t ads7957_word(unsigned ch, uint32_t mv);

struct ev3_spi_stats {
	uint32_t transfers;
	uint32_t rx_overruns;
	uint32_t stalls;            /* SPIBUF reads that waited for a transfer */
};
const struct ev3_spi_stats *ev3_spi_get_stats(void);

#endif /* HOST_SIM_DEVICES_SPI_ADC_H */
