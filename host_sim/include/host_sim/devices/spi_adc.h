/*
 * spi_adc.h — SPI0 of the AM1808 with the EV3's analog-to-digital converter
 * on it (AM1808 TRM; LEGO's d_analog.c).  Host only.
 *
 * SPI0 is modelled in spi.h.
 *
 * The board connects the converter as SPI0's slave (hs_spi_connect): it
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
#include "host_sim/devices/spi.h"

/* The EV3's converter on SPI0 (board model). */
extern const struct hs_device ev3_adc_device;

/* The ADC's answer word for a channel at a voltage (ADS7957 layout, 0-5 V range). */
uint16_t ads7957_word(unsigned ch, uint32_t mv);

#endif /* HOST_SIM_DEVICES_SPI_ADC_H */
