/*
 * asm/fiq.h — the ARM's fast interrupt, as Linux's arch/arm/include/asm/fiq.h
 * (claim_fiq, release_fiq, set_fiq_handler, set_fiq_regs, get_fiq_regs,
 * enable_fiq, disable_fiq) with local_fiq_enable/local_fiq_disable.
 *
 * The FIQ is modelled as the highest-priority interrupt: enable_fiq(irq)
 * routes that Linux IRQ line to the FIQ, and when the line fires its FIQ
 * handler runs before any IRQ handler of the line (which then do not run:
 * the AINTC maps a channel to nFIQ or to nIRQ, never both) and is not nested
 * by any IRQ handler.  local_fiq_disable masks it (the CPSR F bit): a FIQ
 * that comes while masked runs at local_fiq_enable.
 *
 * Differences from Linux, where the handler is machine code copied to the
 * FIQ vector and runs with the FIQ mode's banked r8..r14: there is no vector
 * page here, so set_fiq_handler(start, length) takes start as the C function
 * `void (*)(void)` the FIQ calls (length is not used), and set_fiq_regs only
 * stores the registers get_fiq_regs returns (no code reads banked registers).
 * All Linux lines share one RTOS priority (linux_compat/irq.h), so a FIQ
 * preempts no IRQ handler that is already running; it is the first to run
 * when its line is pending.
 */
#ifndef _ASM_ARM_FIQ_H
#define _ASM_ARM_FIQ_H

#include <asm/ptrace.h>
#include <linux/irqflags.h>

struct fiq_handler {
	struct fiq_handler *next;
	const char *name;
	/* Asked to let go of the FIQ (relinquish 1; nonzero refuses) or told it has it back (0). */
	int (*fiq_op)(void *dev_id, int relinquish);
	void *dev_id;
};

/* Makes f the FIQ's owner if the current one (if any) relinquishes it: 0 or -EBUSY. */
int claim_fiq(struct fiq_handler *f);
/* Gives the FIQ back to the owner before f (told through its fiq_op). */
void release_fiq(struct fiq_handler *f);
/* Sets what the FIQ runs: here, start as a C function (see above). */
void set_fiq_handler(void *start, unsigned int length);
/* A C function as the FIQ handler: LEGO's EV3 kernel adds it to this header
 * (mindboards/ev3sources, extra/linux-03.20.00.13, arch/arm/kernel/fiq.c: a
 * stub at the vector jumps to a register-saving wrapper around handler); its
 * I2C engine, davinci-iic.c, sets its FIQ handler with it.  Here it is
 * set_fiq_handler's own model. */
void set_fiq_c_handler(void (*handler)(void));
/* Stores the FIQ mode's registers (r8..r14). */
void set_fiq_regs(struct pt_regs *regs);
/* The registers set_fiq_regs stored. */
void get_fiq_regs(struct pt_regs *regs);
/* Routes Linux IRQ fiq to the FIQ and unmasks it. */
void enable_fiq(int fiq);
/* Masks it and routes it back to the IRQ. */
void disable_fiq(int fiq);

#endif /* _ASM_ARM_FIQ_H */
