/*
 * linux/irqflags.h — local interrupt masking with the SIL lock.
 *
 * local_irq_save(flags) stores the previous interrupt state in flags and
 * masks all interrupts (SIL_LOC_INT); local_irq_restore(flags) returns to
 * exactly that state, so nested sections restore correctly.
 * local_irq_disable/enable do not nest (as in Linux): enable returns to the
 * state before the outermost disable.
 */
#ifndef _LINUX_IRQFLAGS_H
#define _LINUX_IRQFLAGS_H

#include <linux/typecheck.h>
#include <linux_compat/context.h>

/* Masks interrupts; returns the state to restore. */
unsigned long arch_local_irq_save(void);
/* Returns to a state arch_local_irq_save returned. */
void arch_local_irq_restore(unsigned long flags);
/* Masks interrupts (non-nesting). */
void arch_local_irq_disable(void);
/* Undoes arch_local_irq_disable. */
void arch_local_irq_enable(void);

#define local_irq_save(flags) \
	do { typecheck(unsigned long, flags); (flags) = arch_local_irq_save(); } while (0)
#define local_irq_restore(flags) \
	do { typecheck(unsigned long, flags); arch_local_irq_restore(flags); } while (0)
#define local_irq_disable()	arch_local_irq_disable()
#define local_irq_enable()	arch_local_irq_enable()
#define irqs_disabled()		lx_irqs_disabled()
#define raw_local_irq_save(flags)	local_irq_save(flags)
#define raw_local_irq_restore(flags)	local_irq_restore(flags)

/* The ARM's FIQ mask (the CPSR F bit; asm/fiq.h): a FIQ that comes while it
 * is masked runs when it is unmasked.  Non-nesting, as in Linux. */
void lx_local_fiq_disable(void);
void lx_local_fiq_enable(void);
#define local_fiq_disable()	lx_local_fiq_disable()
#define local_fiq_enable()	lx_local_fiq_enable()

#endif /* _LINUX_IRQFLAGS_H */
