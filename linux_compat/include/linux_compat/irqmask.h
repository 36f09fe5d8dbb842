/*
 * linux_compat/irqmask.h — masking every interrupt of the one CPU and
 * restoring the state before, the primitive under local_irq_save and
 * spin_lock_irqsave.
 *
 * On the AM1808 it is inline: the CPSR saved and the I and F bits set with
 * mrs/orr/msr, as Linux's ARMv5 arch_local_irq_save does (ARM Architecture
 * Reference Manual, ARMv5: CPSR bit 7 = I, masks IRQ; bit 6 = F, masks FIQ;
 * FIQ is masked too, as SIL_LOC_INT masks every interrupt — SIL_LOC_INT's own
 * saved state is private to each TOPPERS target port, so it cannot be carried
 * in flags).  On the host it is the host kernel's interrupt mask, a call.
 */
#ifndef _LINUX_COMPAT_IRQMASK_H
#define _LINUX_COMPAT_IRQMASK_H

#if defined(EV3LX_AM1808)
#define LX_CPSR_IRQ_MASK	0x80U
#define LX_CPSR_FIQ_MASK	0x40U

/* Masks IRQ and FIQ; returns the CPSR before. */
static inline unsigned long lx_irq_mask_save(void)
{
	unsigned long cpsr, masked;

	__asm__ volatile("mrs %0, cpsr" : "=r"(cpsr));
	masked = cpsr | LX_CPSR_IRQ_MASK | LX_CPSR_FIQ_MASK;
	__asm__ volatile("msr cpsr_c, %0" : : "r"(masked) : "memory", "cc");
	return cpsr;
}

/* Restores the CPSR control byte lx_irq_mask_save returned. */
static inline void lx_irq_mask_restore(unsigned long cpsr)
{
	__asm__ volatile("msr cpsr_c, %0" : : "r"(cpsr) : "memory", "cc");
}
#else
/* Masks every interrupt of the host kernel; returns the state before. */
unsigned long lx_irq_mask_save(void);
/* Restores the state lx_irq_mask_save returned. */
void lx_irq_mask_restore(unsigned long saved);
#endif

#endif /* _LINUX_COMPAT_IRQMASK_H */
