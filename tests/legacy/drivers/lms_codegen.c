/*
 * lms_codegen.c — a conformance module in the 2.6-era idiom for what gcc's
 * code generation does to it at -O2:
 *
 * - registers through plain, non-volatile `UWORD *` and `ULONG *` pointers,
 *   one statement per register, so that gcc merges adjacent stores (eHRPWM1's
 *   AQCTLA/AQCTLB at 0x16/0x18 into one 4-byte store at a 2-aligned address,
 *   TBPHS/TBCNT, eCAP0's CAP1/CAP2 pair into one 8-byte store) — the ARM926
 *   performs one access per register;
 * - eCAP0's 32-bit TSCTR and CTRPHS cleared through a `UWORD *`: a 16-bit
 *   write to their low halves;
 * - SPI0 set up with SPIDAT1 written while SPIGCR1.ENABLE is still 0 (the data
 *   format selected before the module is enabled), then enabled;
 * - a tone command in a `char` buffer whose frequency bytes are above 127
 *   (440 Hz is 0xB8 0x01): kbuild compiles with -funsigned-char, so
 *   `Cmd[2] + (Cmd[3] << 8)` is 440 on every architecture, not 184.
 *
 * Registers (AM1808 TRM): eHRPWM TBCTL 0x00, TBPHS 0x06, TBCNT 0x08, TBPRD
 * 0x0A, CMPCTL 0x0E, AQCTLA 0x16, AQCTLB 0x18 (16-bit); eCAP TSCTR 0x00,
 * CTRPHS 0x04, CAP1 0x08, CAP2 0x0C (32-bit), ECCTL2 0x2A (16-bit); SPI
 * SPIGCR0 0x00, SPIGCR1 0x04, SPIINT0 0x08, SPIPC0 0x14, SPIDAT1 0x3C,
 * SPIDELAY 0x48, SPIDEF 0x4C, SPIFMT0 0x50 (32-bit).
 */
#include <linux/kernel.h>
#include <linux/module.h>
#include <linux/init.h>
#include <linux/io.h>
#include <linux/string.h>

typedef   unsigned char   UBYTE;
typedef   unsigned short  UWORD;
typedef   unsigned int    ULONG;

#define   PWM0_BASE       0x01F00000
#define   PWM1_BASE       0x01F02000
#define   ECAP0_BASE      0x01F06000
#define   SPI0_BASE       0x01C41000

enum { TBCTL = 0x00, TBPHS = 0x03, TBCNT = 0x04, TBPRD = 0x05, CMPCTL = 0x07, AQCTLA = 0x0B, AQCTLB = 0x0C };
enum { TSCTR = 0x00, CTRPHS = 0x02, CAP1 = 0x04, CAP2 = 0x06, ECCTL2 = 0x15 };
enum { SPIGCR0 = 0x00, SPIGCR1 = 0x01, SPIINT0 = 0x02, SPIPC0 = 0x05, SPIDAT1 = 0x0F, SPIDELAY = 0x12,
       SPIDEF = 0x13, SPIFMT0 = 0x14 };

enum { TONE = 1, BREAK = 2 };

#define   TONE_CLOCK      132000000UL    /* eHRPWM0's time base: PLL1_SYSCLK2 */
#define   MIN_FRQ         250
#define   MAX_FRQ         10000

UWORD *Pwm0;
UWORD *Pwm1;
UWORD *Ecap0;
ULONG *Ecap0L;
ULONG *Spi0;
UWORD Frequency;

/* eHRPWM1 as LEGO's SETUPPwmModules leaves it: adjacent stores gcc merges. */
void SetupPwm(void)
{
	Pwm1[TBPHS] = 0;
	Pwm1[TBCNT] = 0;
	Pwm1[CMPCTL] = 0;
	Pwm1[AQCTLA] = 0x0021;
	Pwm1[AQCTLB] = 0x0201;
	Ecap0[TSCTR] = 0;
	Ecap0[CTRPHS] = 0;
	Ecap0L[CAP1] = 0x1000;
	Ecap0L[CAP1 + 1] = 0x0400;
	Ecap0[ECCTL2] = 0x0690;
}

/* SPI0 as LEGO's SPIInit: SPIDAT1's format select before the enable bit. */
void SetupSpi(void)
{
	Spi0[SPIGCR0] = 0x00000001;
	Spi0[SPIGCR1] = 0x00000003;
	Spi0[SPIPC0] = 0x00000E08;
	Spi0[SPIDAT1] = 0x00000000;
	Spi0[SPIFMT0] = 0x00010810;
	Spi0[SPIDELAY] = 0x0A0A0A0A;
	Spi0[SPIINT0] = 0x00000000;
	Spi0[SPIDEF] = 0x00000008;
	Spi0[SPIGCR1] = 0x01000003;
}

/* One command as d_sound's write(): the bytes in a `char` buffer. */
int Command(const char *Buffer, int Count)
{
	char CommandBuffer[8];
	UWORD Period;

	if (Count < 4 || Count > (int)sizeof(CommandBuffer))
		return -EINVAL;
	memcpy(CommandBuffer, Buffer, Count);
	switch (CommandBuffer[0]) {
	case TONE:
		Frequency = (UWORD)(CommandBuffer[2] + (CommandBuffer[3] << 8));
		if (Frequency < MIN_FRQ)
			Frequency = MIN_FRQ;
		else if (Frequency > MAX_FRQ)
			Frequency = MAX_FRQ;
		Period = (UWORD)((TONE_CLOCK / 32 / Frequency) - 1);
		Pwm0[TBPRD] = Period;
		break;
	case BREAK:
		Pwm0[TBPRD] = 0;
		break;
	default:
		return -EINVAL;
	}
	return Count;
}

static int __init ModuleInit(void)
{
	Pwm0 = (UWORD *)ioremap(PWM0_BASE, 0x2000);
	Pwm1 = (UWORD *)ioremap(PWM1_BASE, 0x2000);
	Ecap0 = (UWORD *)ioremap(ECAP0_BASE, 0x1000);
	Spi0 = (ULONG *)ioremap(SPI0_BASE, 0x1000);
	if (Pwm0 == NULL || Pwm1 == NULL || Ecap0 == NULL || Spi0 == NULL)
		return -ENOMEM;
	Ecap0L = (ULONG *)Ecap0;
	SetupPwm();
	SetupSpi();
	return 0;
}

static void __exit ModuleExit(void)
{
	iounmap((void __iomem *)Spi0);
	iounmap((void __iomem *)Ecap0);
	iounmap((void __iomem *)Pwm1);
	iounmap((void __iomem *)Pwm0);
}

module_init(ModuleInit);
module_exit(ModuleExit);

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("conformance module: merged register stores, 16-bit eCAP halves, SPIDAT1 before enable, char command bytes");
