// SPDX-License-Identifier: GPL-2.0
/*
 * lms_spi — a conformance module in LEGO's idiom for SPI0 (lms2012's d_analog
 * reads the EV3's converter this way): the registers as a `volatile unsigned
 * long *` array indexed by register number, macros for the status tests and
 * the set-up, the registers saved at init and restored at exit, and a frame
 * that polls SPIBUF's TXFULL and RXEMPTY flags around a write of SPIDAT0.
 * On the ARM926, an ILP32 target, `unsigned long` is 4 bytes and Spi0[n] is
 * the register at 4n; on an LP64 host it is 8 bytes and Spi0[n] is not a
 * register this module means.  Register numbers: AM1808 TRM, SPI chapter
 * (SPIGCR0 at 0x00 ... INTVEC1 at 0x64, one word each); the converter's
 * command word: TI ADS7957 data sheet, manual mode (0x1840 | channel << 7,
 * its answer two frames on).
 */
#include <linux/kernel.h>
#include <linux/module.h>
#include <linux/init.h>
#include <linux/io.h>
#include <linux/ioport.h>

#define   MODULE_NAME                   "lms_spi"

typedef   unsigned char                 UBYTE;
typedef   unsigned short                UWORD;
typedef   unsigned int                  ULONG;

#define   SPI0_CLOCK                    150000000
#define   ADC_CLOCK                     2000000
#define   CNVSPD                        (((ULONG)SPI0_CLOCK / (ULONG)ADC_CLOCK) - 1)

/* SPI register numbers (word index from SPI0's base) */
#define   SPIGCR0                       0
#define   SPIGCR1                       1
#define   SPIINT0                       2
#define   SPILVL                        3
#define   SPIFLG                        4
#define   SPIPC0                        5
#define   SPIDAT0                       14
#define   SPIDAT1                       15
#define   SPIBUF                        16
#define   SPIDELAY                      18
#define   SPIDEF                        19
#define   SPIFMT0                       20

static    volatile  unsigned long       *Spi0;

#define   SPIRxempty                    (Spi0[SPIBUF] & 0x80000000)
#define   SPITxfull                     (Spi0[SPIBUF] & 0x20000000)

#define   SPIInit                       {\
                                          Spi0[SPIGCR0]     = 0x00000001; /* Out of reset                 */\
                                          Spi0[SPIGCR1]     = 0x00000003; /* Master, internal clock       */\
                                          Spi0[SPIPC0]      = 0x00000E01; /* SOMI, SIMO, CLK, SCS0        */\
                                          Spi0[SPIFMT0]     = 0x00010010 | ((CNVSPD << 8) & 0xFF00);\
                                          Spi0[SPIDELAY]    = 0x0A0A0A0A; /* Delays = 10                  */\
                                          Spi0[SPIINT0]     = 0x00000000; /* Interrupts disabled          */\
                                          Spi0[SPIDEF]      = 0x00000001;\
                                          Spi0[SPIGCR1]    |= 0x01000000; /* Enable bit                   */\
                                        }

#define   TIMEOUT                       10000

ULONG     SpiSave[6];
UWORD     AdcAnswer[3];
ULONG     SpiSetup[4];

void      SpiSaveReg(void)
{
  SpiSave[0]  =  Spi0[SPIGCR1];
  SpiSave[1]  =  Spi0[SPIPC0];
  SpiSave[2]  =  Spi0[SPIFMT0];
  SpiSave[3]  =  Spi0[SPIDELAY];
  SpiSave[4]  =  Spi0[SPIINT0];
  SpiSave[5]  =  Spi0[SPIDEF];
}

void      SpiRestoreReg(void)
{
  Spi0[SPIGCR1]   =  SpiSave[0];
  Spi0[SPIPC0]    =  SpiSave[1];
  Spi0[SPIFMT0]   =  SpiSave[2];
  Spi0[SPIDELAY]  =  SpiSave[3];
  Spi0[SPIINT0]   =  SpiSave[4];
  Spi0[SPIDEF]    =  SpiSave[5];
}

UWORD     SpiUpdate(UWORD DataOut)
{
  int     Timeout = TIMEOUT;

  while (SPITxfull && --Timeout);

  Spi0[SPIDAT0]   = (ULONG)DataOut;

  while (SPIRxempty && --Timeout);

  return ((UWORD)(Spi0[SPIBUF] & 0x0000FFFF));
}

static int __init ModuleInit(void)
{
  int     Frame;

  if (request_mem_region(0x01C41000,0x68,MODULE_NAME) == NULL)
  {
    return (-EBUSY);
  }
  Spi0  =  (unsigned long*)ioremap(0x01C41000,0x68);
  if (Spi0 == NULL)
  {
    release_mem_region(0x01C41000,0x68);
    return (-ENOMEM);
  }
  SpiSaveReg();
  SPIInit;
  SpiSetup[0]  =  Spi0[SPIGCR1];
  SpiSetup[1]  =  Spi0[SPIFMT0];
  SpiSetup[2]  =  Spi0[SPIDELAY];
  SpiSetup[3]  =  Spi0[SPIDEF];
  for (Frame = 0;Frame < 3;Frame++)
  {
    AdcAnswer[Frame]  =  SpiUpdate(0x1840 | (5 << 7));
  }
  printk(KERN_INFO "%s: SPI0 mapped at 0x%08lX, answer 0x%04X\n",MODULE_NAME,(unsigned long)Spi0,AdcAnswer[2]);
  return (0);
}

static void __exit ModuleExit(void)
{
  SpiRestoreReg();
  iounmap((void __iomem *)Spi0);
  release_mem_region(0x01C41000,0x68);
}

module_init(ModuleInit);
module_exit(ModuleExit);

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("conformance module: SPI0 as a volatile unsigned long array indexed by register number");
