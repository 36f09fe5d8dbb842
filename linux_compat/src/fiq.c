/*
 * fiq.c — the ARM's FIQ (asm/fiq.h) as the highest-priority interrupt: an
 * owner stack (claim_fiq/release_fiq), the handler, the Linux IRQ lines
 * routed to it (enable_fiq), and its mask (local_fiq_disable/enable).
 */
#include <asm/fiq.h>
#include <linux/bitops.h>
#include <linux/errno.h>
#include <linux/irq.h>
#include <linux/printk.h>
#include <linux/string.h>
#include <linux_compat/context.h>
#include <linux_compat/irq.h>
#include <linux_compat/report.h>
#include <sil.h>

static struct {
	struct fiq_handler *owner;          /* top of the owner stack */
	void (*handler)(void);              /* what the FIQ runs */
	struct pt_regs regs;                /* set_fiq_regs' registers */
	unsigned long routed[BITS_TO_LONGS(NR_IRQS)];
	bool masked;                        /* local_fiq_disable */
	bool running;                       /* the handler runs: the FIQ is masked, as on entry */
	int pending_irq;                    /* a FIQ that came while masked, or -1 */
} fiq = { .pending_irq = -1 };

void lx_fiq_boot(void)
{
	memset(&fiq, 0, sizeof(fiq));
	fiq.pending_irq = -1;
}

/* Runs the FIQ handler for irq in interrupt context (interrupts already masked). */
static void fiq_run(unsigned int irq)
{
	bool masked = fiq.masked;       /* the CPSR: its F bit comes back from the SPSR on return */

	fiq.running = true;
	lx_irq_enter((int)irq);
	if (fiq.handler)
		fiq.handler();
	else
		lx_report("FIQ", NULL, 0, "irq %u is routed to the FIQ (enable_fiq) but no handler is set "
			  "(set_fiq_handler)", irq);
	lx_irq_exit();
	fiq.running = false;
	fiq.masked = masked;
}

bool lx_fiq_take(unsigned int irq)
{
	if (irq >= NR_IRQS || !test_bit(irq, fiq.routed))
		return false;
	if (fiq.masked || fiq.running)
		fiq.pending_irq = (int)irq;
	else
		fiq_run(irq);
	return true;
}

int claim_fiq(struct fiq_handler *f)
{
	int ret = 0;

	if (f == NULL)
		return -EINVAL;
	if (fiq.owner) {
		ret = -EBUSY;
		if (fiq.owner->fiq_op)
			ret = fiq.owner->fiq_op(fiq.owner->dev_id, 1);
	}
	if (ret)
		return ret;
	f->next = fiq.owner;
	fiq.owner = f;
	return 0;
}

void release_fiq(struct fiq_handler *f)
{
	if (f == NULL || fiq.owner != f) {
		pr_err("%s FIQ trying to release %s FIQ\n", f && f->name ? f->name : "?",
		       fiq.owner && fiq.owner->name ? fiq.owner->name : "no");
		return;
	}
	fiq.owner = f->next;
	if (fiq.owner && fiq.owner->fiq_op)
		fiq.owner->fiq_op(fiq.owner->dev_id, 0);
}

void set_fiq_handler(void *start, unsigned int length)
{
	(void)length;
	fiq.handler = (void (*)(void))start;
}

void set_fiq_c_handler(void (*handler)(void))
{
	fiq.handler = handler;
}

void set_fiq_regs(struct pt_regs *regs)
{
	if (regs)
		fiq.regs = *regs;
}

void get_fiq_regs(struct pt_regs *regs)
{
	if (regs)
		*regs = fiq.regs;
}

void enable_fiq(int irq)
{
	SIL_PRE_LOC;

	if (irq < 0 || irq >= NR_IRQS || !lx_irq_valid((unsigned int)irq)) {
		pr_err("enable_fiq: irq %d has no line\n", irq);
		return;
	}
	SIL_LOC_INT();
	set_bit((unsigned int)irq, fiq.routed);
	SIL_UNL_INT();
	lx_irq_line_unmask((unsigned int)irq);
}

void disable_fiq(int irq)
{
	SIL_PRE_LOC;

	if (irq < 0 || irq >= NR_IRQS)
		return;
	lx_irq_line_mask((unsigned int)irq);
	SIL_LOC_INT();
	clear_bit((unsigned int)irq, fiq.routed);
	if (fiq.pending_irq == irq)
		fiq.pending_irq = -1;
	SIL_UNL_INT();
}

void lx_local_fiq_disable(void)
{
	fiq.masked = true;
}

void lx_local_fiq_enable(void)
{
	int irq;
	SIL_PRE_LOC;

	SIL_LOC_INT();
	fiq.masked = false;
	irq = fiq.pending_irq;
	fiq.pending_irq = -1;
	if (irq >= 0 && !fiq.running)
		fiq_run((unsigned int)irq);     /* taken as soon as F is cleared */
	else if (irq >= 0)
		fiq.pending_irq = irq;
	SIL_UNL_INT();
}
