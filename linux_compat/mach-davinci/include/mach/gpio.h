/*
 * mach/gpio.h — DaVinci GPIO: the register layout and the legacy gpio API.
 *
 * Pins are numbered as DaVinci does: GPIO_TO_PIN(bank, bit) = 16 * bank +
 * bit (GP5_11 is 91), 144 pins in 9 banks.  Two banks share one register
 * block (struct gpio_controller) at DA8XX_GPIO_BASE + 0x10 + (gpio / 32) *
 * 0x28, the even bank in bits 0..15 and the odd one in bits 16..31; BINTEN
 * (bank interrupt enables) is at base + 0x08.
 *
 * Every access goes through the asm/io.h accessors, i.e. SIL register
 * accesses.  gpio_set_value/gpio_get_value are inline: a bounds check, the
 * block's address and one register access, since drivers call them for many
 * pins every 1-2 ms.  The rest is in linux_compat/mach-davinci/gpio.c:
 * - gpio_request/gpio_free track ownership (-EBUSY if taken, -EINVAL if not
 *   a valid pin), but as in Linux's legacy API the other calls work on any
 *   valid pin, requested or not;
 * - gpio_direction_input/output read-modify-write DIR with interrupts locked
 *   (drivers change directions from timers and IRQs too); output sets the
 *   level before turning the driver on, so the pin never glitches;
 * - gpio_to_irq(gpio) = 101 + gpio (mach/irqs.h); the pin IRQs are
 *   demultiplexed from the bank interrupts (linux_compat/irq.h).
 */
#ifndef __DAVINCI_GPIO_H
#define __DAVINCI_GPIO_H

#include <linux/types.h>
#include <linux/compiler.h>
#include <linux/errno.h>
#include <asm/io.h>
#include <mach/irqs.h>
#include <mach/da8xx.h>

#define ARCH_NR_GPIOS		DAVINCI_N_GPIO
#define DAVINCI_GPIO_BASE	DA8XX_GPIO_BASE

/* GPIO_TO_PIN(bank, bit); GPIO(x) is the identity, GPIO(bank, bit) = GPIO_TO_PIN. */
#define GPIO_TO_PIN(bank, gpio)	(16 * (bank) + (gpio))
#define __LX_GPIO_SEL(_1, _2, name, ...)	name
#define __LX_GPIO_1(x)			(x)
#define GPIO(...)	__LX_GPIO_SEL(__VA_ARGS__, GPIO_TO_PIN, __LX_GPIO_1, 0)(__VA_ARGS__)

struct gpio_controller {
	u32	dir;            /* 1 = input */
	u32	out_data;
	u32	set_data;       /* write 1 to set OUT_DATA bits */
	u32	clr_data;       /* write 1 to clear OUT_DATA bits */
	u32	in_data;        /* read only: the pins' levels */
	u32	set_rising;     /* write 1: interrupt on rising edges */
	u32	clr_rising;
	u32	set_falling;    /* write 1: interrupt on falling edges */
	u32	clr_falling;
	u32	intstat;        /* pending edges, write 1 to clear */
};

#define LX_GPIO_BINTEN		0x08
#define LX_GPIO_BANK_OFFSET(gpio)	(0x10 + ((gpio) >> 5) * 0x28)

/* The mapped GPIO block (NULL until mapped: at boot, or lazily on first use). */
extern void __iomem *lx_gpio_base;
/* Maps the GPIO block if needed; NULL (reported) if it cannot be mapped. */
void __iomem *lx_gpio_map(void);
/* Reports a gpio_set/get_value on an invalid pin or an unmapped block. */
void lx_gpio_bad_access(unsigned int gpio, const char *what);

/* The register block of gpio's bank pair, or NULL for an invalid pin. */
static inline struct gpio_controller __iomem *__gpio_to_controller(unsigned int gpio)
{
	void __iomem *base = lx_gpio_base;

	if (unlikely(gpio >= DAVINCI_N_GPIO))
		return NULL;
	if (unlikely(!base)) {
		base = lx_gpio_map();
		if (!base)
			return NULL;
	}
	return (struct gpio_controller __iomem *)((char __iomem *)base + LX_GPIO_BANK_OFFSET(gpio));
}

/* gpio's bit in its bank pair's registers. */
static inline u32 __gpio_mask(unsigned int gpio)
{
	return 1U << (gpio & 31);
}

/* Drives gpio's output latch high (value != 0) or low.  Any context. */
static inline void gpio_set_value(unsigned int gpio, int value)
{
	struct gpio_controller __iomem *g = __gpio_to_controller(gpio);

	if (unlikely(!g)) {
		lx_gpio_bad_access(gpio, "gpio_set_value");
		return;
	}
	__raw_writel(__gpio_mask(gpio), value ? &g->set_data : &g->clr_data);
}

/* The level of gpio (0 or 1), from IN_DATA.  Any context. */
static inline int gpio_get_value(unsigned int gpio)
{
	struct gpio_controller __iomem *g = __gpio_to_controller(gpio);

	if (unlikely(!g)) {
		lx_gpio_bad_access(gpio, "gpio_get_value");
		return 0;
	}
	return (__raw_readl(&g->in_data) & __gpio_mask(gpio)) ? 1 : 0;
}

/* True for a pin number this SoC has (0..143). */
static inline bool gpio_is_valid(int number)
{
	return number >= 0 && number < DAVINCI_N_GPIO;
}

/* Claims gpio for label: 0, -EINVAL (no such pin) or -EBUSY (already claimed). */
int gpio_request(unsigned int gpio, const char *label);
/* Releases a claim; warns if gpio was not claimed. */
void gpio_free(unsigned int gpio);
/* Makes gpio an input (DIR bit set): 0 or -EINVAL.  Any context. */
int gpio_direction_input(unsigned int gpio);
/* Sets the level, then makes gpio an output: 0 or -EINVAL.  Any context. */
int gpio_direction_output(unsigned int gpio, int value);
/* 1 if gpio is an input, 0 if an output, -EINVAL for an invalid pin. */
int gpio_get_direction(unsigned int gpio);
/* The label gpio was requested with, or NULL if it is free. */
const char *gpio_label(unsigned int gpio);

/* The pin IRQ of gpio (101 + gpio), or -EINVAL. */
static inline int gpio_to_irq(unsigned int gpio)
{
	return gpio < DAVINCI_N_GPIO ? (int)(DAVINCI_N_AINTC_IRQ + gpio) : -EINVAL;
}

/* The gpio of a pin IRQ, or -EINVAL. */
static inline int irq_to_gpio(unsigned int irq)
{
	return irq >= DAVINCI_N_AINTC_IRQ && irq < NR_IRQS ?
		(int)(irq - DAVINCI_N_AINTC_IRQ) : -EINVAL;
}

/* On-chip GPIOs never sleep. */
static inline int gpio_cansleep(unsigned int gpio)
{
	(void)gpio;
	return 0;
}

#define gpio_get_value_cansleep(gpio)		gpio_get_value(gpio)
#define gpio_set_value_cansleep(gpio, value)	gpio_set_value((gpio), (value))
#define __gpio_get_value(gpio)			gpio_get_value(gpio)
#define __gpio_set_value(gpio, value)		gpio_set_value((gpio), (value))

#endif /* __DAVINCI_GPIO_H */
