/* lms_spi_hack.h — the lms_spi conformance module's interface (C types only). */
#ifndef LMS_SPI_HACK_H
#define LMS_SPI_HACK_H

#define LMS_SPI_API __attribute__((visibility("default")))

/* Runs the module's init (0 or -errno) / exit. */
LMS_SPI_API int lms_spi_load(void);
LMS_SPI_API void lms_spi_unload(void);
/* The converter's answer to frame 0..2 of the init (SPIBUF's data half). */
LMS_SPI_API unsigned lms_spi_adc_answer(int frame);
/* What the init read back through Spi0[] after its set-up: 0 SPIGCR1, 1 SPIFMT0, 2 SPIDELAY, 3 SPIDEF. */
LMS_SPI_API unsigned lms_spi_setup(int reg);
/* The module's register pointer (ioremap's address) as an integer. */
LMS_SPI_API unsigned long lms_spi_base(void);

#endif
