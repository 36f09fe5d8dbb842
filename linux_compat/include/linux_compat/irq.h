/*
 * linux_compat/irq.h — how Linux IRQs sit on the RTOS's interrupt lines.
 *
 * The EV3RT approach: interrupt service routines are bound statically.  The
 * configuration fragment linux_irq_cfg (linux_compat/mach-davinci/irq_cfg.c, included
 * by linux_compat's RTOS configuration) declares CFG_INT + ATT_ISR for every
 * line in LX_IRQ_LINES below, initially disabled.  request_irq records the
 * Linux handler and enables the line (ena_int); free_irq of the last handler
 * disables it again (dis_int).  The lines' ISR is a dispatcher that calls the
 * line's handlers in interrupt context, bracketed by lx_irq_enter/exit.
 *
 * Priority: every Linux line runs at LX_IRQ_PRIORITY, the tick's priority,
 * so Linux handlers and hrtimer callbacks (run from the tick) never nest -
 * each runs to completion, as in Linux since 2.6.35 - while anything the RTOS
 * configures above (TMIN_INTPRI) still preempts them.
 *
 * GPIO bank lines (42..50) are demultiplexed into per-pin IRQs
 * (101 + gpio, mach/irqs.h) by lx_gpio_bank_isr (linux_compat/mach-davinci/gpio.c):
 * drivers request the pin IRQs, never the bank lines.
 */
#ifndef _LINUX_COMPAT_IRQ_H
#define _LINUX_COMPAT_IRQ_H

#include <stdint.h>
#include <stdbool.h>
#include <mach/irqs.h>

/* Interrupt priority of every Linux line: the tick's (INTPRI_TICK, rtos_cfg.h). */
#define LX_IRQ_PRIORITY		(-6)

/* Handler records (struct irqaction) available to request_irq in total. */
#ifndef LX_NR_IRQ_ACTIONS
#define LX_NR_IRQ_ACTIONS	32
#endif

/*
 * The lines Linux drivers may use: X(intno, isr, exinf), one row per line.
 * To give drivers another line (e.g. a UART host_sim adds), add one row here.
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
	X(IRQ_DA8XX_UARTINT1, lx_irq_dispatch,   IRQ_DA8XX_UARTINT1)	\
	X(IRQ_DA8XX_UARTINT2, lx_irq_dispatch,   IRQ_DA8XX_UARTINT2)

/* The RTOS configuration fragment declaring those lines (and lx_io_boot). */
struct rtos_cfg;
extern const struct rtos_cfg linux_irq_cfg;

/* ISR of the AINTC lines: runs the Linux handlers of IRQ exinf. */
void lx_irq_dispatch(intptr_t exinf);
/* ISR of GPIO bank exinf (0..8): acknowledges and dispatches its pending pins. */
void lx_gpio_bank_isr(intptr_t exinf);

/* Runs the Linux handlers of irq in interrupt context; returns true if one handled it. */
bool lx_handle_irq(unsigned int irq);

/* True if irq has an RTOS line (AINTC) or is a GPIO pin IRQ. */
bool lx_irq_valid(unsigned int irq);

/* Handler calls of irq where every handler returned IRQ_NONE (since boot). */
unsigned long lx_irq_unhandled_count(unsigned int irq);
/* Times the handlers of irq ran (since boot). */
unsigned long lx_irq_count(unsigned int irq);

/* ATT_INI of linux_irq_cfg: forgets all IRQ handlers, GPIO state, I/O regions
 * and registered devices of a previous boot (host tests boot repeatedly).
 * Must run before any module init. */
void lx_io_boot(intptr_t exinf);

/* The GPIO side of the pin IRQs (gpio.c), called by the IRQ core with the
 * pin's state already updated: unmask (trigger edges per type), mask, and
 * check/record a trigger type.  pin = irq - DAVINCI_N_AINTC_IRQ. */
void lx_gpio_irq_unmask(unsigned int pin, unsigned int type);
void lx_gpio_irq_mask(unsigned int pin);
/* 0 if the GPIO block supports the trigger type (edges only), else -EINVAL. */
int lx_gpio_irq_check_type(unsigned int type);
/* Resets the GPIO layer's state (lx_io_boot). */
void lx_gpio_boot(void);
/* Maps da8xx_syscfg0_base/da8xx_syscfg1_base (lx_io_boot). */
void lx_iomap_boot(void);
/* Resets the I/O region registry (lx_io_boot). */
void lx_resource_boot(void);
/* Resets the device registry (lx_io_boot). */
void lx_devfs_boot(void);
/* Puts every task back to USER_DS (lx_io_boot). */
void lx_uaccess_boot(void);

#endif /* _LINUX_COMPAT_IRQ_H */
