/*
 * gpio.c — DaVinci GPIO: the legacy gpiolib calls and the pin IRQs.
 *
 * The fast accessors are inline in mach/gpio.h.  Pin IRQs: a pin IRQ is
 * unmasked by writing its edge triggers (SET/CLR_RIS_TRIG, SET/CLR_FAL_TRIG)
 * and, for the first pin of a bank, setting the bank's BINTEN bit and
 * enabling the bank's RTOS line; masking undoes that.  The bank ISR does
 * what DaVinci's chained handler does: read the bank's INTSTAT bits,
 * acknowledge them (write 1 to clear) before calling any handler, then run
 * the handler of each pending pin, lowest first; repeat while new edges are
 * pending.
 */
#include <linux/gpio.h>
#include <linux/irq.h>
#include <linux/interrupt.h>
#include <linux/kernel.h>
#include <linux/string.h>
#include <linux/sizes.h>
#include <mach/gpio.h>
#include <mach/hardware.h>
#include <linux_compat/irq.h>
#include <linux_compat/machine.h>
#include <linux_compat/report.h>
#include <kernel.h>
#include <sil.h>

#define LX_GPIO_BANKS	(DAVINCI_N_GPIO / 16)

void __iomem *lx_gpio_base;
static const char *gpio_labels[DAVINCI_N_GPIO];
static u16 bank_unmasked[LX_GPIO_BANKS];      /* pins whose IRQ is live, per bank */

void __iomem *lx_gpio_map(void)
{
	if (!lx_gpio_base)
		lx_gpio_base = lx_io_map(DA8XX_GPIO_BASE, SZ_4K);
	return lx_gpio_base;
}

void lx_gpio_bad_access(unsigned int gpio, const char *what)
{
	if (gpio >= DAVINCI_N_GPIO)
		lx_report("invalid GPIO", __FILE__, __LINE__,
			  "%s(%u): no such pin (0..%d)", what, gpio, DAVINCI_N_GPIO - 1);
	else
		lx_report("GPIO block not mapped", __FILE__, __LINE__,
			  "%s(%u): DA8XX_GPIO_BASE cannot be mapped (no register model installed?)",
			  what, gpio);
}

/* The register block of a valid gpio, reporting (and NULL) if there is none. */
static struct gpio_controller __iomem *controller(unsigned int gpio, const char *what)
{
	struct gpio_controller __iomem *g = __gpio_to_controller(gpio);

	if (!g)
		lx_gpio_bad_access(gpio, what);
	return g;
}

int gpio_request(unsigned int gpio, const char *label)
{
	int err = 0;
	SIL_PRE_LOC;

	if (gpio >= DAVINCI_N_GPIO)
		return -EINVAL;
	SIL_LOC_INT();
	if (gpio_labels[gpio])
		err = -EBUSY;
	else
		gpio_labels[gpio] = label ? label : "?";
	SIL_UNL_INT();
	return err;
}

void gpio_free(unsigned int gpio)
{
	bool was_requested = false;
	SIL_PRE_LOC;

	if (gpio < DAVINCI_N_GPIO) {
		SIL_LOC_INT();
		was_requested = gpio_labels[gpio] != NULL;
		gpio_labels[gpio] = NULL;
		SIL_UNL_INT();
	}
	WARN(!was_requested, "gpio_free(%u): not requested", gpio);
}

const char *gpio_label(unsigned int gpio)
{
	return gpio < DAVINCI_N_GPIO ? gpio_labels[gpio] : NULL;
}

int gpio_direction_input(unsigned int gpio)
{
	struct gpio_controller __iomem *g = controller(gpio, "gpio_direction_input");
	SIL_PRE_LOC;

	if (!g)
		return -EINVAL;
	SIL_LOC_INT();
	__raw_writel(__raw_readl(&g->dir) | __gpio_mask(gpio), &g->dir);
	SIL_UNL_INT();
	return 0;
}

int gpio_direction_output(unsigned int gpio, int value)
{
	struct gpio_controller __iomem *g = controller(gpio, "gpio_direction_output");
	SIL_PRE_LOC;

	if (!g)
		return -EINVAL;
	SIL_LOC_INT();
	__raw_writel(__gpio_mask(gpio), value ? &g->set_data : &g->clr_data);
	__raw_writel(__raw_readl(&g->dir) & ~__gpio_mask(gpio), &g->dir);
	SIL_UNL_INT();
	return 0;
}

int gpio_get_direction(unsigned int gpio)
{
	struct gpio_controller __iomem *g = controller(gpio, "gpio_get_direction");

	if (!g)
		return -EINVAL;
	return (__raw_readl(&g->dir) & __gpio_mask(gpio)) ? 1 : 0;
}

int gpio_request_one(unsigned int gpio, unsigned long flags, const char *label)
{
	int err = gpio_request(gpio, label);

	if (err)
		return err;
	if (flags & GPIOF_DIR_IN)
		err = gpio_direction_input(gpio);
	else
		err = gpio_direction_output(gpio, (flags & GPIOF_INIT_HIGH) ? 1 : 0);
	if (err)
		gpio_free(gpio);
	return err;
}

int gpio_request_array(const struct gpio *array, size_t num)
{
	size_t i;
	int err;

	for (i = 0; i < num; i++) {
		err = gpio_request_one(array[i].gpio, array[i].flags, array[i].label);
		if (err) {
			while (i--)
				gpio_free(array[i].gpio);
			return err;
		}
	}
	return 0;
}

void gpio_free_array(const struct gpio *array, size_t num)
{
	while (num--)
		gpio_free(array[num].gpio);
}

int lx_gpio_irq_check_type(unsigned int type)
{
	return (type & ~(unsigned int)IRQ_TYPE_EDGE_BOTH) ? -EINVAL : 0;
}

void lx_gpio_irq_unmask(unsigned int pin, unsigned int type)
{
	struct gpio_controller __iomem *g = controller(pin, "gpio irq enable");
	unsigned int bank = pin / 16;
	u32 mask = __gpio_mask(pin);
	bool first;
	SIL_PRE_LOC;

	if (!g)
		return;
	if (type == IRQ_TYPE_NONE)
		type = IRQ_TYPE_EDGE_BOTH;   /* DaVinci's default for pin IRQs */
	__raw_writel(mask, (type & IRQ_TYPE_EDGE_RISING) ? &g->set_rising : &g->clr_rising);
	__raw_writel(mask, (type & IRQ_TYPE_EDGE_FALLING) ? &g->set_falling : &g->clr_falling);

	SIL_LOC_INT();
	first = bank_unmasked[bank] == 0;
	bank_unmasked[bank] |= (u16)(1U << (pin % 16));
	if (first) {
		void __iomem *binten = (char __iomem *)lx_gpio_base + LX_GPIO_BINTEN;

		__raw_writel(__raw_readl(binten) | (1U << bank), binten);
	}
	SIL_UNL_INT();
	if (first)
		(void)ena_int((INTNO)(IRQ_DA8XX_GPIO0 + bank));
}

/*
 * Acknowledges the edges latched in a bank whose line was just disabled and
 * records each as pending for its pin's IRQ (enable_irq replays it).  Linux
 * never disables the bank's chained interrupt, so such an edge reaches the
 * bank handler, which finds the pin disabled and marks it pending; an edge
 * waiting in INTSTAT behind the disabled line meets the same fate here.
 */
static void drain_bank(struct gpio_controller __iomem *g, unsigned int bank)
{
	unsigned int shift = (bank & 1U) * 16U;
	u32 latched = __raw_readl(&g->intstat) & (0xffffU << shift);

	if (!latched)
		return;
	__raw_writel(latched, &g->intstat);
	for (latched >>= shift; latched; latched &= latched - 1U)
		lx_irq_set_pending(DAVINCI_N_AINTC_IRQ + bank * 16U + (unsigned int)__builtin_ctz(latched));
}

void lx_gpio_irq_mask(unsigned int pin)
{
	struct gpio_controller __iomem *g = controller(pin, "gpio irq disable");
	unsigned int bank = pin / 16;
	u32 mask = __gpio_mask(pin);
	bool last = false;
	SIL_PRE_LOC;

	if (!g)
		return;
	__raw_writel(mask, &g->clr_rising);
	__raw_writel(mask, &g->clr_falling);

	SIL_LOC_INT();
	if (bank_unmasked[bank] & (1U << (pin % 16))) {
		bank_unmasked[bank] &= (u16)~(1U << (pin % 16));
		last = bank_unmasked[bank] == 0;
	}
	if (last) {
		void __iomem *binten = (char __iomem *)lx_gpio_base + LX_GPIO_BINTEN;

		__raw_writel(__raw_readl(binten) & ~(1U << bank), binten);
	}
	SIL_UNL_INT();
	if (last) {
		(void)dis_int((INTNO)(IRQ_DA8XX_GPIO0 + bank));
		drain_bank(g, bank);
	}
}

void lx_gpio_bank_isr(intptr_t exinf)
{
	unsigned int bank = (unsigned int)exinf;
	unsigned int shift = (bank & 1U) * 16U;
	unsigned int first_irq = DAVINCI_N_AINTC_IRQ + bank * 16U;
	struct gpio_controller __iomem *g;
	u32 pending;

	if (bank >= LX_GPIO_BANKS || !lx_gpio_base)
		return;
	g = (struct gpio_controller __iomem *)((char __iomem *)lx_gpio_base +
					       LX_GPIO_BANK_OFFSET(bank * 16U));
	for (;;) {
		pending = __raw_readl(&g->intstat) & (0xffffU << shift);
		if (!pending)
			break;
		__raw_writel(pending, &g->intstat);
		pending >>= shift;
		do {
			unsigned int bit = (unsigned int)__builtin_ctz(pending);

			pending &= pending - 1U;
			lx_handle_irq(first_irq + bit);
		} while (pending);
	}
}

void lx_gpio_boot(void)
{
	lx_gpio_base = NULL;
	memset(gpio_labels, 0, sizeof(gpio_labels));
	memset(bank_unmasked, 0, sizeof(bank_unmasked));
	(void)lx_gpio_map();
}
