/*
 * mach/spi.h — the AM1808's SPI controllers as SPI buses (board code calls
 * this, as Linux's da8xx board files call da8xx_register_spi_bus).
 */
#ifndef __ASM_ARCH_DAVINCI_SPI_H
#define __ASM_ARCH_DAVINCI_SPI_H

/* Registers SPI0 or SPI1 (instance) as SPI bus number instance with
 * num_chipselect chip selects; cs_gpios[i] is the GPIO driving chip select
 * i, or -1 for the controller's own SCSn pin (NULL: all the controller's).
 * Process context: 0, -EINVAL (bad instance or count), -EBUSY (already
 * registered), -ENOMEM, -ENXIO (no registers at the controller's address). */
int da8xx_register_spi_bus(int instance, unsigned int num_chipselect, const int *cs_gpios);
/* Unregisters the bus (its devices are unbound and freed). */
void da8xx_unregister_spi_bus(int instance);

#endif /* __ASM_ARCH_DAVINCI_SPI_H */
