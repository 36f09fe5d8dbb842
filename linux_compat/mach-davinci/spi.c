/*
 * spi.c — the AM1808's SPI0 and SPI1 as SPI controllers for the SPI core
 * (AM1808 TRM, "Serial Peripheral Interface (SPI)" chapter), the part of
 * Linux's spi-davinci the EV3 needs: master mode, 2..16-bit words, the
 * four SPI modes and LSB-first through SPIFMT0, the chip-select delays from
 * davinci_spi_config, chip selects by GPIO or by the SCSn pins.  Transfers
 * are programmed I/O: each word is written to SPIDAT1 and its answer read
 * from SPIBUF once RXEMPTY clears (a byte at the EV3 display's 9.4 MHz is
 * about 1 us, so the caller's thread polls rather than sleeps).
 */
#include <linux/bits.h>
#include <linux/io.h>
#include <linux/kernel.h>
#include <linux/sizes.h>
#include <linux/slab.h>
#include <linux/spi/spi.h>
#include <linux/platform_data/spi-davinci.h>
#include <mach/da8xx.h>
#include <mach/spi.h>
#include <linux_compat/machine.h>

/* Registers (TRM SPI chapter, "SPI Registers"). */
#define SPIGCR0		0x00
#define SPIGCR1		0x04
#define SPIINT0		0x08
#define SPIFLG		0x10
#define SPIPC0		0x14
#define SPIDAT1		0x3c
#define SPIBUF		0x40
#define SPIDELAY	0x48
#define SPIDEF		0x4c
#define SPIFMT0		0x50

#define SPIGCR0_RESET		BIT(0)
#define SPIGCR1_CLKMOD		BIT(1)
#define SPIGCR1_MASTER		BIT(0)
#define SPIGCR1_ENABLE		BIT(24)
#define SPIPC0_SOMIFUN		BIT(11)
#define SPIPC0_SIMOFUN		BIT(10)
#define SPIPC0_CLKFUN		BIT(9)
#define SPIBUF_RXEMPTY		BIT(31)
#define SPIFMT_SHIFTDIR		BIT(20)
#define SPIFMT_POLARITY		BIT(17)
#define SPIFMT_PHASE		BIT(16)
#define SPIFMT_PRESCALE_SHIFT	8
#define SPIDAT1_CSNR_SHIFT	16
#define SPIDELAY_C2T_SHIFT	24
#define SPIDELAY_T2C_SHIFT	16
#define SPI_PRESCALE_MIN	2       /* prescale 0 and 1 are reserved (TRM, SPIFMTn.PRESCALE) */
#define SPI_RX_POLL_LIMIT	1000000U

struct davinci_spi {
	void __iomem *base;
	u32 clk_hz;
	int cs_gpios[8];
	u32 fmt_cache;          /* SPIFMT0 last written, 0: none */
	u32 delay_cache;
};

/* The two instances: registers and module clock.  SPI0 runs on PLL0_SYSCLK2
 * (150 MHz); SPI1 on the ASYNC3 domain, which LEGO's kernel moves to
 * PLL1_SYSCLK2 (CFGCHIP3.ASYNC3_CLKSRC), 132 MHz on the EV3. */
static const struct {
	phys_addr_t base;
	u32 clk_hz;
} davinci_spi_hw[2] = {
	{ DA8XX_SPI0_BASE, 150000000 },
	{ DA8XX_SPI1_BASE, 132000000 },
};

static struct spi_controller *davinci_spi_buses[2];

/* Programs SPIFMT0 and SPIDELAY for a transfer: 0 or -EINVAL (speed out of reach). */
static int davinci_spi_format(struct davinci_spi *dspi, struct spi_device *spi, struct spi_transfer *t)
{
	const struct davinci_spi_config *cfg = spi->controller_data;
	u32 prescale, fmt, delay = 0;

	if (!t->speed_hz)
		return -EINVAL;
	prescale = DIV_ROUND_UP(dspi->clk_hz, t->speed_hz) - 1;
	if (prescale < SPI_PRESCALE_MIN || prescale > 255) {
		dev_err(&spi->dev, "%u Hz is beyond the controller's %u..%u Hz\n", t->speed_hz,
			dspi->clk_hz / 256, dspi->clk_hz / (SPI_PRESCALE_MIN + 1));
		return -EINVAL;
	}
	fmt = (prescale << SPIFMT_PRESCALE_SHIFT) | t->bits_per_word;
	if (spi->mode & SPI_CPOL)
		fmt |= SPIFMT_POLARITY;
	if (!(spi->mode & SPI_CPHA))
		fmt |= SPIFMT_PHASE;    /* the DaVinci's PHASE is the inverse of CPHA */
	if (spi->mode & SPI_LSB_FIRST)
		fmt |= SPIFMT_SHIFTDIR;
	if (cfg)
		delay = ((u32)cfg->c2tdelay << SPIDELAY_C2T_SHIFT) | ((u32)cfg->t2cdelay << SPIDELAY_T2C_SHIFT);
	if (fmt != dspi->fmt_cache) {
		writel(fmt, dspi->base + SPIFMT0);
		dspi->fmt_cache = fmt;
	}
	if (delay != dspi->delay_cache) {
		writel(delay, dspi->base + SPIDELAY);
		dspi->delay_cache = delay;
	}
	return 0;
}

static int davinci_spi_transfer_one(struct spi_controller *ctlr, struct spi_device *spi, struct spi_transfer *t)
{
	struct davinci_spi *dspi = spi_controller_get_devdata(ctlr);
	unsigned int bytes = t->bits_per_word > 8 ? 2 : 1;
	u32 csnr = (spi->cs_gpio >= 0 || (spi->mode & SPI_NO_CS)) ? 0 : BIT(spi->chip_select);
	/* SPIDAT1's CSNR selects the pins driven active (0) during the word: all others stay inactive */
	u32 dat1 = (0xffU & ~csnr) << SPIDAT1_CSNR_SHIFT;
	unsigned int i;
	int ret;

	ret = davinci_spi_format(dspi, spi, t);
	if (ret)
		return ret;
	for (i = 0; i < t->len; i += bytes) {
		const u8 *tx = t->tx_buf;
		u32 word = 0, buf, polls = 0;

		if (tx)
			word = bytes == 2 ? (u32)tx[i] | ((u32)tx[i + 1] << 8) : tx[i];
		writel(dat1 | word, dspi->base + SPIDAT1);
		do {
			buf = readl(dspi->base + SPIBUF);
		} while ((buf & SPIBUF_RXEMPTY) && ++polls < SPI_RX_POLL_LIMIT);
		if (buf & SPIBUF_RXEMPTY) {
			dev_err(&spi->dev, "no answer from the SPI controller\n");
			return -ETIMEDOUT;
		}
		if (t->rx_buf) {
			u8 *rx = t->rx_buf;

			rx[i] = (u8)buf;
			if (bytes == 2)
				rx[i + 1] = (u8)(buf >> 8);
		}
	}
	return 0;
}

static void davinci_spi_set_cs(struct spi_device *spi, bool level)
{
	struct davinci_spi *dspi = spi_controller_get_devdata(spi->controller);
	u32 def = readl(dspi->base + SPIDEF);

	/* SPIDEF gives each SCSn pin's level between words */
	if (level)
		def |= BIT(spi->chip_select);
	else
		def &= ~BIT(spi->chip_select);
	writel(def, dspi->base + SPIDEF);
}

int da8xx_register_spi_bus(int instance, unsigned int num_chipselect, const int *cs_gpios)
{
	struct spi_controller *ctlr;
	struct davinci_spi *dspi;
	unsigned int i;
	int ret;

	if (instance < 0 || instance > 1 || num_chipselect == 0 || num_chipselect > ARRAY_SIZE(dspi->cs_gpios))
		return -EINVAL;
	if (davinci_spi_buses[instance])
		return -EBUSY;
	ctlr = spi_alloc_master(NULL, sizeof(*dspi));
	if (!ctlr)
		return -ENOMEM;
	dspi = spi_controller_get_devdata(ctlr);
	dspi->base = ioremap(davinci_spi_hw[instance].base, SZ_4K);
	if (!dspi->base) {
		spi_controller_put(ctlr);
		return -ENXIO;
	}
	dspi->clk_hz = davinci_spi_hw[instance].clk_hz;
	for (i = 0; i < num_chipselect; i++)
		dspi->cs_gpios[i] = cs_gpios ? cs_gpios[i] : -1;
	ctlr->bus_num = (s16)instance;
	ctlr->num_chipselect = (u16)num_chipselect;
	ctlr->cs_gpios = dspi->cs_gpios;
	ctlr->mode_bits = SPI_CPOL | SPI_CPHA | SPI_CS_HIGH | SPI_LSB_FIRST | SPI_NO_CS;
	ctlr->bits_per_word_mask = GENMASK(15, 1);      /* 2..16 bits */
	ctlr->max_speed_hz = dspi->clk_hz / (SPI_PRESCALE_MIN + 1);
	ctlr->min_speed_hz = dspi->clk_hz / 256;
	ctlr->transfer_one = davinci_spi_transfer_one;
	ctlr->set_cs = davinci_spi_set_cs;

	/* reset, then master with the internal clock, SIMO/SOMI/CLK as SPI pins, no interrupts */
	writel(0, dspi->base + SPIGCR0);
	writel(SPIGCR0_RESET, dspi->base + SPIGCR0);
	writel(SPIGCR1_MASTER | SPIGCR1_CLKMOD, dspi->base + SPIGCR1);
	writel(SPIPC0_SOMIFUN | SPIPC0_SIMOFUN | SPIPC0_CLKFUN, dspi->base + SPIPC0);
	writel(0, dspi->base + SPIINT0);
	writel(0xff, dspi->base + SPIDEF);
	writel(SPIGCR1_MASTER | SPIGCR1_CLKMOD | SPIGCR1_ENABLE, dspi->base + SPIGCR1);

	ret = spi_register_controller(ctlr);
	if (ret) {
		writel(0, dspi->base + SPIGCR1);
		iounmap(dspi->base);
		spi_controller_put(ctlr);
		return ret;
	}
	davinci_spi_buses[instance] = ctlr;
	return 0;
}

void da8xx_unregister_spi_bus(int instance)
{
	struct spi_controller *ctlr;
	struct davinci_spi *dspi;
	void __iomem *base;

	if (instance < 0 || instance > 1 || !davinci_spi_buses[instance])
		return;
	ctlr = davinci_spi_buses[instance];
	dspi = spi_controller_get_devdata(ctlr);
	base = dspi->base;
	davinci_spi_buses[instance] = NULL;
	/* the devices' remove() may still transfer: unregister first, then disable and unmap */
	spi_unregister_controller(ctlr);
	writel(0, base + SPIGCR1);
	iounmap(base);
}

/* Forgets the buses of a previous boot (their memory went with the heap). */
void lx_davinci_spi_boot(void)
{
	davinci_spi_buses[0] = davinci_spi_buses[1] = NULL;
}
