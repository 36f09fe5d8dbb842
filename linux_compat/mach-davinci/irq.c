/*
 * irq.c — the DaVinci machine's interrupt controllers as linux_compat's
 * generic IRQ core sees them (struct lx_irq_chip):
 *
 *   AINTC   the lines in LX_IRQ_LINES that run the plain dispatcher; the
 *           RTOS owns the controller, so unmasking is ena_int and masking
 *           dis_int.  The AINTC takes level-high or rising-edge sources
 *           (AM1808 TRM, AINTC chapter: system interrupts are active high).
 *   GPIO    one IRQ per pin after the AINTC's (gpio_to_irq), demultiplexed
 *           from the bank lines by lx_gpio_bank_isr (gpio.c); the pins
 *           trigger on edges only.
 */
#include <linux/irq.h>
#include <linux/kernel.h>
#include <linux/errno.h>
#include <linux_compat/irq.h>
#include <linux_compat/machine.h>
#include <kernel.h>

/* ena_int on the AINTC line; -EINVAL if the RTOS configuration lacks it. */
static int aintc_unmask(unsigned int irq, unsigned int type)
{
	ER ercd = ena_int((INTNO)irq);

	(void)type;
	if (ercd != E_OK) {
		pr_err("irq %u: ena_int failed (%d): is linux_irq_cfg in the RTOS configuration?\n",
		       irq, ercd);
		return -EINVAL;
	}
	return 0;
}

static void aintc_mask(unsigned int irq)
{
	(void)dis_int((INTNO)irq);
}

static int aintc_check_type(unsigned int type)
{
	if (type == IRQ_TYPE_NONE || type == IRQ_TYPE_LEVEL_HIGH || type == IRQ_TYPE_EDGE_RISING)
		return 0;
	return -EINVAL;
}

static const struct lx_irq_chip aintc_chip = {
	.name = "AINTC",
	.irq_unmask = aintc_unmask,
	.irq_mask = aintc_mask,
	.irq_check_type = aintc_check_type,
};

static int gpio_pin_unmask(unsigned int irq, unsigned int type)
{
	lx_gpio_irq_unmask(irq - DAVINCI_N_AINTC_IRQ, type);
	return 0;
}

static void gpio_pin_mask(unsigned int irq)
{
	lx_gpio_irq_mask(irq - DAVINCI_N_AINTC_IRQ);
}

static const struct lx_irq_chip gpio_chip = {
	.name = "GPIO",
	.irq_unmask = gpio_pin_unmask,
	.irq_mask = gpio_pin_mask,
	.irq_check_type = lx_gpio_irq_check_type,
};

#define LX_IRQ_DISPATCHED_CASE(intno, isr, exinf)	case intno: return (isr) == lx_irq_dispatch;

/* True if the AINTC line runs the plain dispatcher in linux_irq_cfg (bank
 * lines run lx_gpio_bank_isr: drivers request their pins instead). */
static bool aintc_line_requestable(unsigned int irq)
{
	switch (irq) {
	LX_IRQ_LINES(LX_IRQ_DISPATCHED_CASE)
	default:
		return false;
	}
}

const struct lx_irq_chip *lx_mach_irq_chip(unsigned int irq)
{
	if (irq >= NR_IRQS)
		return NULL;
	if (irq >= DAVINCI_N_AINTC_IRQ)
		return &gpio_chip;
	return aintc_line_requestable(irq) ? &aintc_chip : NULL;
}

void lx_mach_boot(void)
{
	lx_iomap_boot();
	lx_gpio_boot();
	lx_davinci_spi_boot();
}
