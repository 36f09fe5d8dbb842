/*
 * test_irq_chips.c — the DaVinci machine's interrupt controllers as the
 * generic IRQ core sees them (struct lx_irq_chip): which chip serves which
 * IRQ (the AINTC for the lines of LX_IRQ_LINES that run the dispatcher, the
 * GPIO chip for every pin IRQ, none for bank lines and unconfigured lines),
 * the trigger types each accepts, and that request_irq / irq_set_irq_type
 * follow exactly what the chips say.
 */
#include "lx_test.h"
#include <linux/gpio.h>
#include <linux/interrupt.h>
#include <linux/irq.h>
#include <linux/string.h>
#include <linux_compat/irq.h>
#include <linux_compat/machine.h>

#define PIN_IRQ_GPIO	91      /* GP5_11, a tacho input */

static irqreturn_t handler(int irq, void *dev)
{
	return IRQ_HANDLED;
}

static void body(void)
{
	const struct lx_irq_chip *aintc = lx_mach_irq_chip(IRQ_DA8XX_UARTINT0);
	const struct lx_irq_chip *gpio = lx_mach_irq_chip((unsigned int)gpio_to_irq(PIN_IRQ_GPIO));
	unsigned int irq, mismatches = 0;
	int dev;

	ok(aintc && strcmp(aintc->name, "AINTC") == 0, "a UART line is served by the AINTC chip");
	ok(gpio && strcmp(gpio->name, "GPIO") == 0, "a pin IRQ is served by the GPIO chip");
	ok(lx_mach_irq_chip(IRQ_DA8XX_EVTOUT1) == aintc, "a PRU event line is an AINTC line too");
	ok(lx_mach_irq_chip(IRQ_DA8XX_GPIO5) == NULL, "a GPIO bank line has no chip: drivers request its pins");
	ok(lx_mach_irq_chip(IRQ_DA8XX_MMCSDINT0) == NULL, "a line the configuration does not carry has no chip");
	ok(lx_mach_irq_chip(NR_IRQS) == NULL, "nothing beyond NR_IRQS");
	for (irq = 0; irq <= NR_IRQS; irq++)
		if (lx_irq_valid(irq) != (lx_mach_irq_chip(irq) != NULL))
			mismatches++;
	is_int(mismatches, 0, "lx_irq_valid is exactly 'the machine has a chip for it'");

	is_int(aintc->irq_check_type(IRQ_TYPE_LEVEL_HIGH), 0, "AINTC: level-high accepted");
	is_int(aintc->irq_check_type(IRQ_TYPE_EDGE_RISING), 0, "AINTC: rising edge accepted");
	is_int(aintc->irq_check_type(IRQ_TYPE_EDGE_FALLING), -EINVAL, "AINTC: falling edge refused");
	is_int(gpio->irq_check_type(IRQ_TYPE_EDGE_BOTH), 0, "GPIO: both edges accepted");
	is_int(gpio->irq_check_type(IRQ_TYPE_LEVEL_LOW), -EINVAL, "GPIO: level types refused");

	is_int(request_irq(IRQ_DA8XX_GPIO5, handler, 0, "bank", &dev), -EINVAL,
	       "request_irq of a bank line: -EINVAL (no chip)");
	is_int(request_irq(IRQ_DA8XX_UARTINT0, handler, IRQF_TRIGGER_FALLING, "uart", &dev), -EINVAL,
	       "request_irq with a type the AINTC refuses: -EINVAL");
	is_int(request_irq(IRQ_DA8XX_UARTINT0, handler, 0, "uart", &dev), 0, "request_irq of a UART line");
	is_int(irq_set_irq_type(IRQ_DA8XX_UARTINT0, IRQ_TYPE_EDGE_FALLING), -EINVAL,
	       "irq_set_irq_type: the chip's refusal stands");
	is_int(irq_set_irq_type(IRQ_DA8XX_UARTINT0, IRQ_TYPE_LEVEL_HIGH), 0, "...and its acceptance");
	(void)free_irq(IRQ_DA8XX_UARTINT0, &dev);
}

int main(void)
{
	tap_plan(18);
	ok(lx_test_run(body), "test task ran to completion");
	return tap_done();
}
