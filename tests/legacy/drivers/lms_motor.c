/*
 * lms_motor.c — the second conformance module in the 2.6-era idiom.  It
 * defines the same global names as lms_gpio (Hw, HwId, InitGpio, PinTable,
 * GpioBase) — private to each module on Linux — and drives eHRPWM1 through
 * one ioremap window of 0x2854 bytes (several 4 KiB pages) as 16-bit
 * registers, with compound read-modify-write statements.
 *
 * eHRPWM registers (AM1808 TRM, eHRPWM chapter), 16-bit: TBCTL 0x00,
 * TBPRD 0x0A, CMPCTL 0x0E, CMPA 0x12, CMPB 0x14, AQCTLA 0x16.
 */
#include <linux/kernel.h>
#include <linux/module.h>
#include <linux/moduleparam.h>
#include <linux/init.h>
#include <linux/io.h>

#define   TRUE    1
#define   FALSE   0

typedef   unsigned char   UBYTE;
typedef   unsigned short  UWORD;
typedef   unsigned int    ULONG;
typedef   signed char     DATA8;
typedef   ULONG           SIZE;
typedef   UBYTE           BOOL;

#define   GPIO_BASE       0x01E26000
#define   PWM1_BASE       0x01F02000
#define   PWM1_SIZE       0x2854

enum { TBCTL = 0x00 / 2, TBPRD = 0x0A / 2, CMPCTL = 0x0E / 2, CMPA = 0x12 / 2, CMPB = 0x14 / 2, AQCTLA = 0x16 / 2 };

enum { FINAL = 0, EP2 = 1, HWIDS = 2 };

/* Per board revision: the motor-enable pin (bank * 16 + bit). */
UWORD PinTable[HWIDS] = { [FINAL] = 2 * 16 + 1, [EP2] = 2 * 16 + 0 };

int HwId = FINAL;
module_param(HwId, int, 0);

int Hw;
volatile ULONG *GpioBase;
volatile UWORD *Pwm;
SIZE PwmWindow;

void InitGpio(void)
{
	ULONG Mask = 1UL << (PinTable[Hw] & 31);

	GpioBase[4 + 10 * (PinTable[Hw] >> 5) + 2] = Mask;   /* SET_DATA */
	GpioBase[4 + 10 * (PinTable[Hw] >> 5)] &= ~Mask;     /* DIR: output */
}

void SetDuty(UWORD Duty)
{
	Pwm[CMPA] = Duty;
	Pwm[AQCTLA] = (Pwm[AQCTLA] & ~0x0FFF) | 0x0021;       /* low at zero, high at CMPA */
}

static int __init ModuleInit(void)
{
	if (HwId < FINAL || HwId >= HWIDS)
		return -EINVAL;
	Hw = HwId;
	GpioBase = (volatile ULONG *)ioremap(GPIO_BASE, 0xD8);
	Pwm = (volatile UWORD *)ioremap(PWM1_BASE, PWM1_SIZE);
	if (GpioBase == NULL || Pwm == NULL)
		return -ENOMEM;
	PwmWindow = PWM1_SIZE;
	InitGpio();
	Pwm[TBPRD] = 9999;
	Pwm[CMPCTL] = 0;
	Pwm[TBCTL] &= ~0x0003;                                /* up-count */
	Pwm[TBCTL] |= 0x0030;                                 /* free run */
	SetDuty(0);
	return 0;
}

static void __exit ModuleExit(void)
{
	SetDuty(0);
	iounmap((void __iomem *)Pwm);
	iounmap((void __iomem *)GpioBase);
}

module_init(ModuleInit);
module_exit(ModuleExit);
MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("lms2012-style eHRPWM conformance module");
