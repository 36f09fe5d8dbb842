/*
 * irq_cfg.c — linux_irq_cfg: the RTOS configuration fragment of the Linux
 * interrupt lines (linux_compat/irq.h explains the model).
 *
 * Generated from the one line table LX_IRQ_LINES: a CFG_INT row (initially
 * disabled, at LX_IRQ_PRIORITY) and an ATT_ISR row per line, plus the ATT_INI
 * lx_io_boot that clears the I/O layer's state at every boot.  On the AM1808
 * the same rows go into the HRP2 .cfg.
 */
#include <rtos_cfg.h>
#include <linux_compat/irq.h>
#include <linux_compat/machine.h>

/* NOLINTNEXTLINE(misc-redundant-expression): one value today, asserted so it stays one */
_Static_assert(LX_IRQ_PRIORITY == INTPRI_TICK,
	       "Linux lines share the tick's priority so handlers and hrtimer callbacks never nest");

#define LX_INT_ROW(intno, isr, exinf)	{ (intno), TA_NULL, LX_IRQ_PRIORITY },
#define LX_ISR_ROW(intno, isr, exinf)	{ TA_NULL, (exinf), (intno), (isr), 1 },

static const struct rtos_int_cfg lx_int_rows[] = {
	LX_IRQ_LINES(LX_INT_ROW)
};

static const struct rtos_isr_cfg lx_isr_rows[] = {
	LX_IRQ_LINES(LX_ISR_ROW)
};

static const struct rtos_ini_cfg lx_ini_rows[] = {
	{ lx_io_boot, 0 },
};

const struct rtos_cfg linux_irq_cfg = {
	.name = "linux_irq_cfg",
	.ints = RTOS_TABLE(lx_int_rows),
	.isrs = RTOS_TABLE(lx_isr_rows),
	.inis = RTOS_TABLE(lx_ini_rows),
};
