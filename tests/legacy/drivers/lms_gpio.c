/*
 * lms_gpio.c — a conformance module written the way 2.6-era AM1808 drivers
 * (LEGO's lms2012 modules among them) are: its own basic types and
 * TRUE/FALSE, board tables selected by a HwId module parameter, common
 * global names (Hw, HwId, InitGpio), GPIO registers through a plain
 * `volatile unsigned long *` from ioremap and a struct of ULONG, compound
 * read-modify-write statements, and a GPIO edge interrupt.
 *
 * GPIO registers (AM1808 TRM, GPIO chapter): the banks are paired, pair n at
 * 0x10 + 0x28 * n from the base: DIR, OUT_DATA, SET_DATA, CLR_DATA, IN_DATA,
 * SET_RIS_TRIG, CLR_RIS_TRIG, SET_FAL_TRIG, CLR_FAL_TRIG, INTSTAT.
 * Pin multiplexing (AM1808 TRM, SYSCFG chapter): PINMUXn at SYSCFG0 +
 * 0x120 + 4 * n, 4 bits per pin; writable after KICK0R/KICK1R (0x38/0x3C)
 * are unlocked with 0x83E70B13/0x95A4F1E0.
 */
#define pr_fmt(fmt) KBUILD_MODNAME ": " fmt

#include <linux/kernel.h>
#include <linux/module.h>
#include <linux/moduleparam.h>
#include <linux/init.h>
#include <linux/io.h>
#include <linux/gpio.h>
#include <linux/interrupt.h>
#include <linux/export.h>

#define   TRUE    1
#define   FALSE   0

typedef   unsigned char   UBYTE;
typedef   unsigned short  UWORD;
typedef   unsigned int    ULONG;
typedef   signed char     DATA8;
typedef   signed short    DATA16;
typedef   signed int      DATA32;
typedef   ULONG           SIZE;
typedef   UBYTE           BOOL;
typedef   UBYTE           MODE;
typedef   UWORD           ATR;
typedef   UBYTE           STAT;
typedef   DATA16          PRI;
typedef   DATA32          TMO;
typedef   ULONG           RELTIM;
typedef   ULONG           SYSTIM;
typedef   UBYTE           FN;
typedef   UWORD           INTNO;

enum { OK = 0, BUSY = 1, FAIL = 2, STOP = 4, ID = 8, ER = 16, E_OK = 0, E_PAR = 32, TA_NULL = 0 };

#define   GPIO_BASE       0x01E26000
#define   GPIO_SIZE       0xD8
#define   SYSCFG0_BASE    0x01C14000
#define   KICK0R          (0x38 / 4)
#define   KICK1R          (0x3C / 4)
#define   PINMUX(n)       ((0x120 / 4) + (n))

enum { FINAL = 0, EP2 = 1, EP3 = 2, HWIDS = 3 };

typedef struct {
	ULONG Dir, OutData, SetData, ClrData, InData;
	ULONG SetRisTrig, ClrRisTrig, SetFalTrig, ClrFalTrig, IntStat;
} GPIOPAIR;

typedef struct {
	UWORD Pin;        /* bank * 16 + bit */
	MODE  Output;
	UBYTE MuxReg;     /* PINMUXn selecting the pin's GPIO function */
	UBYTE MuxShift;
	UBYTE MuxMode;
} PINDEF;

/* Per board revision: [0] the output pin, [1] the edge-counting input. */
PINDEF PinTable[HWIDS][2] = {
	[FINAL] = { { 3 * 16 + 14, TRUE, 7, 4, 8 },  { 0 * 16 + 2, FALSE, 1, 20, 8 } },
	[EP2]   = { { 3 * 16 + 13, TRUE, 7, 8, 8 },  { 0 * 16 + 3, FALSE, 1, 16, 8 } },
	[EP3]   = { { 3 * 16 + 12, TRUE, 7, 12, 8 }, { 0 * 16 + 4, FALSE, 1, 12, 8 } },
};

int HwId = FINAL;
module_param(HwId, int, 0);

int Hw;
volatile ULONG *GpioBase;
ULONG EdgeCount;
DATA8 LastLevel;
EXPORT_SYMBOL(EdgeCount);

static GPIOPAIR *PairOf(UWORD Pin)
{
	return (GPIOPAIR *)&GpioBase[4 + 10 * (Pin >> 5)];
}

void SetPinMux(PINDEF *pPin)
{
	volatile ULONG *Syscfg = (volatile ULONG *)ioremap(SYSCFG0_BASE, 0x200);

	if (Syscfg == NULL)
		return;
	Syscfg[KICK0R] = 0x83E70B13;
	Syscfg[KICK1R] = 0x95A4F1E0;
	Syscfg[PINMUX(pPin->MuxReg)] = (Syscfg[PINMUX(pPin->MuxReg)] & ~(0xFUL << pPin->MuxShift)) |
		((ULONG)pPin->MuxMode << pPin->MuxShift);
	Syscfg[KICK0R] = 0;
	Syscfg[KICK1R] = 0;
	iounmap((void __iomem *)Syscfg);
}

void InitGpio(void)
{
	volatile GPIOPAIR *pOut = PairOf(PinTable[Hw][0].Pin);
	volatile GPIOPAIR *pIn = PairOf(PinTable[Hw][1].Pin);
	ULONG OutMask = 1UL << (PinTable[Hw][0].Pin & 31);
	ULONG InMask = 1UL << (PinTable[Hw][1].Pin & 31);
	UBYTE Raw[4];

	SetPinMux(&PinTable[Hw][0]);
	SetPinMux(&PinTable[Hw][1]);
	pOut->ClrData = OutMask;
	pOut->Dir &= ~OutMask;                     /* output */
	pIn->Dir |= InMask;                        /* input */
	*(ULONG *)Raw = pIn->InData;               /* type punning, as kbuild allows */
	LastLevel = (Raw[(PinTable[Hw][1].Pin & 31) >> 3] >> (PinTable[Hw][1].Pin & 7)) & 1;
}

void SetOutput(BOOL On)
{
	volatile GPIOPAIR *pOut = PairOf(PinTable[Hw][0].Pin);
	ULONG OutMask = 1UL << (PinTable[Hw][0].Pin & 31);

	if (On == TRUE)
		pOut->OutData |= OutMask;
	else
		GpioBase[4 + 10 * (PinTable[Hw][0].Pin >> 5) + 1] =
			(GpioBase[4 + 10 * (PinTable[Hw][0].Pin >> 5) + 1] & ~OutMask) | 0;
}

static irqreturn_t EdgeIrq(int irq, void *dev_id)
{
	EdgeCount++;
	SetOutput((EdgeCount & 1) ? TRUE : FALSE);
	return IRQ_HANDLED;
}

static int __init ModuleInit(void)
{
	int Result;

	if (HwId < FINAL || HwId >= HWIDS)
		return -EINVAL;
	Hw = HwId;
	GpioBase = (volatile ULONG *)ioremap(GPIO_BASE, GPIO_SIZE);
	if (GpioBase == NULL)
		return -ENOMEM;
	InitGpio();
	EdgeCount = 0;
	Result = request_irq(gpio_to_irq(PinTable[Hw][1].Pin), EdgeIrq, IRQF_TRIGGER_RISING, "lms_gpio", NULL);
	if (Result) {
		iounmap((void __iomem *)GpioBase);
		return Result;
	}
	pr_info("board %d, output pin %u, input pin %u\n", Hw, PinTable[Hw][0].Pin, PinTable[Hw][1].Pin);
	return 0;
}

static void __exit ModuleExit(void)
{
	free_irq(gpio_to_irq(PinTable[Hw][1].Pin), NULL);
	iounmap((void __iomem *)GpioBase);
}

module_init(ModuleInit);
module_exit(ModuleExit);
MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("lms2012-style GPIO conformance module");
