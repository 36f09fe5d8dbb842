/*
 * linux/platform_data/spi-davinci.h — per-device settings of the DaVinci
 * SPI controller, given by board code as spi_board_info.controller_data
 * (Linux's layout; this controller uses the chip-select delays).
 */
#ifndef __LINUX_PLATFORM_DATA_SPI_DAVINCI_H
#define __LINUX_PLATFORM_DATA_SPI_DAVINCI_H

#include <linux/types.h>

#define SPI_INTERN_CS	0xFF

struct davinci_spi_config {
	u8 wdelay;
	u8 odd_parity;
	u8 parity_enable;
#define SPI_IO_TYPE_INTR	0
#define SPI_IO_TYPE_POLL	1
#define SPI_IO_TYPE_DMA		2
	u8 io_type;
	u8 timer_disable;
	u8 c2tdelay;            /* chip select to transmit start, module clocks (SPIDELAY C2TDELAY) */
	u8 t2cdelay;            /* transmit end to chip select release (SPIDELAY T2CDELAY) */
	u8 t2edelay;
	u8 c2edelay;
};

#endif /* __LINUX_PLATFORM_DATA_SPI_DAVINCI_H */
