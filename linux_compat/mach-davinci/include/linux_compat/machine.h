/*
 * linux_compat/machine.h — the DaVinci (AM1808) machine as linux_compat's
 * generic core sees it: which RTOS interrupt lines carry Linux IRQs, the
 * interrupt controller behind each IRQ, and the machine's boot-time state.
 * Another machine provides its own machine.h from its own directory.
 *
 * The DA8xx has one interrupt controller that the RTOS owns (AINTC: lines
 * are enabled and disabled with ena_int/dis_int) and GPIO banks that
 * demultiplex bank lines 42..50 into one IRQ per pin (101 + gpio,
 * mach/irqs.h), as Linux's gpio-davinci chained handler does.
 */
#ifndef _LINUX_COMPAT_MACHINE_H
#define _LINUX_COMPAT_MACHINE_H

#include <linux/types.h>
#include <mach/irqs.h>
#include <linux_compat/irq.h>

/*
 * The RTOS lines that carry Linux IRQs: X(intno, isr, exinf), one row per
 * line.  To give drivers another line (e.g. a UART host_sim adds), add one
 * row here.  GPIO bank lines run lx_gpio_bank_isr, which dispatches the
 * pending pins' IRQs; drivers request the pin IRQs, never the bank lines.
 */
#define LX_IRQ_LINES(X)						\
	X(IRQ_DA8XX_EVTOUT0,  lx_irq_dispatch,   IRQ_DA8XX_EVTOUT0)	\
	X(IRQ_DA8XX_EVTOUT1,  lx_irq_dispatch,   IRQ_DA8XX_EVTOUT1)	\
	X(IRQ_DA8XX_EVTOUT2,  lx_irq_dispatch,   IRQ_DA8XX_EVTOUT2)	\
	X(IRQ_DA8XX_EVTOUT3,  lx_irq_dispatch,   IRQ_DA8XX_EVTOUT3)	\
	X(IRQ_DA8XX_EVTOUT4,  lx_irq_dispatch,   IRQ_DA8XX_EVTOUT4)	\
	X(IRQ_DA8XX_EVTOUT5,  lx_irq_dispatch,   IRQ_DA8XX_EVTOUT5)	\
	X(IRQ_DA8XX_EVTOUT6,  lx_irq_dispatch,   IRQ_DA8XX_EVTOUT6)	\
	X(IRQ_DA8XX_EVTOUT7,  lx_irq_dispatch,   IRQ_DA8XX_EVTOUT7)	\
	X(IRQ_DA8XX_I2CINT0,     lx_irq_dispatch,   IRQ_DA8XX_I2CINT0)	\
	X(IRQ_DA8XX_TINT34_1, lx_irq_dispatch,   IRQ_DA8XX_TINT34_1)	\
	X(IRQ_DA8XX_UARTINT0, lx_irq_dispatch,   IRQ_DA8XX_UARTINT0)	\
	X(IRQ_DA8XX_GPIO0,    lx_gpio_bank_isr,  0)			\
	X(IRQ_DA8XX_GPIO1,    lx_gpio_bank_isr,  1)			\
	X(IRQ_DA8XX_GPIO2,    lx_gpio_bank_isr,  2)			\
	X(IRQ_DA8XX_GPIO3,    lx_gpio_bank_isr,  3)			\
	X(IRQ_DA8XX_GPIO4,    lx_gpio_bank_isr,  4)			\
	X(IRQ_DA8XX_GPIO5,    lx_gpio_bank_isr,  5)			\
	X(IRQ_DA8XX_GPIO6,    lx_gpio_bank_isr,  6)			\
	X(IRQ_DA8XX_GPIO7,    lx_gpio_bank_isr,  7)			\
	X(IRQ_DA8XX_GPIO8,    lx_gpio_bank_isr,  8)			\
	X(IRQ_DA8XX_I2CINT1,     lx_irq_dispatch,   IRQ_DA8XX_I2CINT1)	\
	X(IRQ_DA8XX_UARTINT1, lx_irq_dispatch,   IRQ_DA8XX_UARTINT1)	\
	X(IRQ_DA8XX_UARTINT2, lx_irq_dispatch,   IRQ_DA8XX_UARTINT2)

/* ISR of GPIO bank exinf (0..8): acknowledges and dispatches its pending pins. */
void lx_gpio_bank_isr(intptr_t exinf);

/* The controller of irq (struct lx_irq_chip, linux_compat/irq.h), or NULL
 * if drivers cannot request irq on this machine. */
const struct lx_irq_chip *lx_mach_irq_chip(unsigned int irq);

/* Forgets the machine's state of a previous boot (GPIO requests and pin
 * IRQs) and maps its register windows again (part of lx_io_boot). */
void lx_mach_boot(void);

/* The machine's parts of lx_mach_boot. */
void lx_gpio_boot(void);
void lx_iomap_boot(void);
void lx_davinci_spi_boot(void);

/* The GPIO pin IRQ chip's operations (gpio.c), for pin = irq - DAVINCI_N_AINTC_IRQ:
 * unmask (trigger edges per type), mask, and check a trigger type. */
void lx_gpio_irq_unmask(unsigned int pin, unsigned int type);
void lx_gpio_irq_mask(unsigned int pin);
int lx_gpio_irq_check_type(unsigned int type);

#endif /* _LINUX_COMPAT_MACHINE_H */
