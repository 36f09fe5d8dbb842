// SPDX-License-Identifier: GPL-2.0
/*
 * lms_names — a conformance module in the 2.6-era idiom whose own names are
 * the ones an RTOS spends: TRUE, FALSE, ID, ER, MODE, STAT, ... as its
 * enumerators, SIZE, BOOL, ATR, PRI, ... as its types, and functions called
 * like the RTOS's service calls.  It is a small command device: a write of
 * one byte selects a MODE, a read returns the state machine's STAT and the
 * result (ER) of the last command.  Any of these names leaking in from the
 * headers it includes breaks its build.
 */
#define pr_fmt(fmt) KBUILD_MODNAME ": " fmt

#include <linux/kernel.h>
#include <linux/module.h>
#include <linux/init.h>
#include <linux/fs.h>
#include <linux/miscdevice.h>
#include <linux/uaccess.h>
#include <linux/slab.h>
#include <linux/io.h>
#include <linux/interrupt.h>
#include <linux/gpio.h>
#include <linux/hrtimer.h>
#include <linux/workqueue.h>
#include <linux/spinlock.h>
#include <linux/semaphore.h>
#include <linux/mutex.h>
#include <linux/delay.h>
#include <linux/poll.h>
#include <linux/wait.h>
#include <linux/sched.h>

/* The module's vocabulary (TOPPERS's t_stddef.h and kernel.h spend the same names). */
enum { FALSE, TRUE };
typedef enum { E_OK = 0, E_SYS = 5, E_NOSPT = 9, E_PAR = 17, E_ID = 18, E_OBJ = 41, E_TMOUT = 50 } ER;
enum { ID, MODE, ATR, STAT, PRI, TMO, RELTIM, SYSTIM, SYSUTM, FN, INTNO, INHNO, EXCNO, FP, ACPTN,
	ER_UINT, ER_ID, ER_BOOL, TMO_POL, TMO_FEVR, TMO_NBLK, TA_NULL, TA_ACT, TSK_SELF, TPRI_INI,
	TDOM_KERNEL, TDOM_SELF, TNUM_TSKID, TMIN_TPRI, TMAX_TPRI, TCYC_STA, TTS_RUN, TTS_DMT,
	NAMES };
typedef unsigned char   UBYTE;
typedef unsigned int    ULONG;
typedef ULONG           SIZE;
typedef UBYTE           BOOL;
typedef unsigned short  ATTR;
typedef signed char     PRIO;
typedef int             int_t;
typedef unsigned int    uint_t;
typedef int             bool_t;
typedef long            long_t;
typedef unsigned long   ulong_t;
typedef struct { ULONG acptn1, acptn2, acptn3, acptn4; } ACVCT;

#define NAMES_DEVICE_NAME "lms_names"
#define MODES 4

static UBYTE State = TTS_DMT;
static ER LastResult = E_OK;
static SIZE Commands;
static BOOL Opened = FALSE;
static ACVCT Rights = { 1, 2, 3, 4 };
static DEFINE_SPINLOCK(Lock);

/* Service-call-shaped helpers of the module's own. */
static ER act_tsk(int_t Mode)
{
	if (Mode < 0 || Mode >= MODES)
		return E_PAR;
	State = Mode == 0 ? TTS_DMT : TTS_RUN;
	return E_OK;
}

static bool_t sns_ctx(void)
{
	return in_interrupt() ? TRUE : FALSE;
}

static ulong_t get_tim(void)
{
	return Commands + Rights.acptn4 - Rights.acptn1 - 3;
}

static int NamesOpen(struct inode *pInode, struct file *pFile)
{
	Opened = TRUE;
	return 0;
}

static int NamesClose(struct inode *pInode, struct file *pFile)
{
	Opened = FALSE;
	return 0;
}

static ssize_t NamesWrite(struct file *File, const char __user *Buffer, size_t Count, loff_t *Data)
{
	UBYTE Mode;
	unsigned long Flags;

	if (Count != 1)
		return -EINVAL;
	if (copy_from_user(&Mode, Buffer, 1))
		return -EFAULT;
	spin_lock_irqsave(&Lock, Flags);
	LastResult = sns_ctx() ? E_SYS : act_tsk(Mode);
	Commands++;
	spin_unlock_irqrestore(&Lock, Flags);
	return 1;
}

static ssize_t NamesRead(struct file *File, char __user *Buffer, size_t Count, loff_t *Offset)
{
	UBYTE Reply[3];
	unsigned long Flags;

	if (Count < sizeof(Reply))
		return -EINVAL;
	spin_lock_irqsave(&Lock, Flags);
	Reply[0] = State;
	Reply[1] = (UBYTE)LastResult;
	Reply[2] = (UBYTE)get_tim();
	spin_unlock_irqrestore(&Lock, Flags);
	if (copy_to_user(Buffer, Reply, sizeof(Reply)))
		return -EFAULT;
	return sizeof(Reply);
}

static const struct file_operations NamesFops = {
	.owner   = THIS_MODULE,
	.open    = NamesOpen,
	.release = NamesClose,
	.read    = NamesRead,
	.write   = NamesWrite,
};

static struct miscdevice Names = {
	MISC_DYNAMIC_MINOR,
	NAMES_DEVICE_NAME,
	&NamesFops
};

static int __init ModuleInit(void)
{
	int Result = misc_register(&Names);

	if (Result)
		pr_err("cannot register /dev/%s\n", NAMES_DEVICE_NAME);
	else
		pr_info("%d names of its own\n", NAMES);
	return Result;
}

static void __exit ModuleExit(void)
{
	misc_deregister(&Names);
}

module_init(ModuleInit);
module_exit(ModuleExit);

MODULE_LICENSE("GPL");
MODULE_DESCRIPTION("conformance module: the RTOS's names as a driver's own");
