// SPDX-License-Identifier: GPL-2.0
/*
 * lms_serial — a conformance module in the 2.6-era AM1808 idiom for the
 * serial blocks: SPI0 talking to the EV3's converter, UART0 in loopback, and
 * eCAP0 as a PWM, all through plain pointers into ioremap()ed windows
 * declared as structs of 32-bit ULONG fields, with 8-bit reads of the status
 * bytes (the UART's LSR), 16-bit reads of SPIBUF's data half and 16-bit
 * writes into the halves of eCAP's 32-bit CAPx registers, as the bus allows.
 * It defines `Hw` and `HwId` like its siblings.  Register layouts: AM1808
 * TRM, SPI, UART and eCAP chapters; the converter's command word: TI ADS7957
 * data sheet, manual mode (0x1840 | channel << 7, its answer two frames on).
 */
#define pr_fmt(fmt) KBUILD_MODNAME ": " fmt

#include <linux/kernel.h>
#include <linux/module.h>
#include <linux/moduleparam.h>
#include <linux/init.h>
#include <linux/io.h>
#include <linux/delay.h>
#include <linux/export.h>

#define   TRUE    1
#define   FALSE   0

typedef   unsigned char   UBYTE;
typedef   unsigned short  UWORD;
typedef   unsigned int    ULONG;
typedef   signed int      DATA32;
typedef   UBYTE           BOOL;

#define   SPI0_BASE       0x01C41000
#define   UART0_BASE      0x01C42000
#define   ECAP0_BASE      0x01F06000

typedef struct {
	ULONG SPIGCR0, SPIGCR1, SPIINT0, SPILVL, SPIFLG;
	ULONG SPIPC[6];
	ULONG Reserved[3];
	ULONG SPIDAT0, SPIDAT1, SPIBUF, SPIEMU, SPIDELAY, SPIDEF;
	ULONG SPIFMT[4];
} SPIREGS;

typedef struct {
	ULONG RBR, IER, IIR, LCR, MCR, LSR, MSR, SCR, DLL, DLH, REVID1, REVID2, PWREMU_MGMT, MDR;
} UARTREGS;

/* eCAP: 32-bit counters and captures, 16-bit controls (word indexes for a UWORD pointer). */
enum { CAP1_LO = 0x08 / 2, CAP1_HI = 0x0A / 2, CAP2_LO = 0x0C / 2, CAP2_HI = 0x0E / 2, ECCTL2 = 0x2A / 2 };

#define   SPIBUF_RXEMPTY  0x80000000
#define   LSR_DR          0x01
#define   LSR_TEMT        0x40
#define   ECCTL2_APWM     0x0200
#define   ECCTL2_RUN      0x0010
#define   ADC_COMMAND(c)  (0x1840 | ((c) << 7))
#define   TIMEOUT         1000

int HwId;
module_param(HwId, int, 0);

int Hw;
SPIREGS *pSpi;
UARTREGS *pUart;
UWORD *pCap;

UWORD AdcAnswer[3];
UBYTE Echo[8];
int EchoCount;
ULONG PwmPeriod;
EXPORT_SYMBOL(AdcAnswer);

static UWORD SpiFrame(UWORD Command)
{
	volatile SPIREGS *pRegs = pSpi;
	int Timeout = TIMEOUT;

	pRegs->SPIDAT1 = (pRegs->SPIDAT1 & 0xFFFF0000) | Command;
	while ((pRegs->SPIBUF & SPIBUF_RXEMPTY) && --Timeout)
		udelay(1);
	return *(volatile UWORD *)&pRegs->SPIBUF;           /* the data half */
}

static void SpiInit(void)
{
	volatile SPIREGS *pRegs = pSpi;

	pRegs->SPIGCR0 = 0;                                 /* reset */
	pRegs->SPIGCR0 = 1;
	pRegs->SPIGCR1 |= 0x03;                             /* master, internal clock */
	pRegs->SPIPC[0] = 0x0E01;                           /* SOMI, SIMO, CLK, SCS0 */
	pRegs->SPIFMT[0] = (74 << 8) | 16;                  /* 2 MHz, 16-bit characters */
	pRegs->SPIGCR1 |= 0x01000000;                       /* enable */
}

static void UartLoopback(const char *pText)
{
	volatile UARTREGS *pRegs = pUart;
	volatile UBYTE *pLsr = (volatile UBYTE *)&pRegs->LSR;
	int Timeout;

	pRegs->PWREMU_MGMT = 0x6001;                        /* receiver and transmitter out of reset */
	pRegs->LCR = 0x83;                                  /* DLAB, 8N1 */
	pRegs->DLL = 81;                                    /* 150 MHz / 16 / 81: 115200 baud */
	pRegs->DLH = 0;
	pRegs->LCR &= ~0x80;
	pRegs->IIR = 0x07;                                  /* FCR: FIFOs on and cleared */
	pRegs->MCR |= 0x10;                                 /* loopback */
	for (EchoCount = 0; pText[EchoCount] && EchoCount < (int)sizeof(Echo); EchoCount++)
		pRegs->RBR = (UBYTE)pText[EchoCount];       /* THR */
	for (int i = 0; i < EchoCount; i++) {
		Timeout = TIMEOUT;
		while (!(*pLsr & LSR_DR) && --Timeout)
			udelay(10);
		Echo[i] = *(volatile UBYTE *)&pRegs->RBR;
	}
}

static void PwmInit(ULONG Period, ULONG Duty)
{
	volatile UWORD *pRegs = pCap;

	pRegs[ECCTL2] = ECCTL2_APWM;
	pRegs[CAP1_LO] = Period & 0xFFFF;                   /* 16-bit halves of 32-bit registers */
	pRegs[CAP1_HI] = Period >> 16;
	pRegs[CAP2_LO] = Duty & 0xFFFF;
	pRegs[CAP2_HI] = Duty >> 16;
	pRegs[ECCTL2] |= ECCTL2_RUN;
	PwmPeriod = *(volatile ULONG *)&pRegs[CAP1_LO];
}

static int __init ModuleInit(void)
{
	Hw = HwId;
	pSpi = (SPIREGS *)ioremap(SPI0_BASE, sizeof(SPIREGS));
	pUart = (UARTREGS *)ioremap(UART0_BASE, sizeof(UARTREGS));
	pCap = (UWORD *)ioremap(ECAP0_BASE, 0x60);
	if (pSpi == NULL || pUart == NULL || pCap == NULL) {
		pr_err("cannot map the serial blocks\n");
		return -ENOMEM;
	}
	SpiInit();
	for (int i = 0; i < 3; i++)
		AdcAnswer[i] = SpiFrame(ADC_COMMAND(5));
	UartLoopback("EV3");
	PwmInit(0x12345, 0x9ABC);
	pr_info("adc %04x, %d bytes echoed, pwm period %u\n", AdcAnswer[2], EchoCount, PwmPeriod);
	return 0;
}

static void __exit ModuleExit(void)
{
	iounmap((void __iomem *)pCap);
	iounmap((void __iomem *)pUart);
	iounmap((void __iomem *)pSpi);
}

module_init(ModuleInit);
module_exit(ModuleExit);

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("conformance module: SPI0, UART0 and eCAP0 through plain pointers");
