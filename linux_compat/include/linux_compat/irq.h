/*
 * linux_compat/irq.h — how Linux IRQs sit on the RTOS's interrupt lines.
 *
 * The EV3RT approach: interrupt service routines are bound statically.  The
 * configuration fragment linux_irq_cfg (the machine's irq_cfg.c, included
 * by linux_compat's RTOS configuration) declares CFG_INT + ATT_ISR for every
 * line in the machine's LX_IRQ_LINES (linux_compat/machine.h), initially
 * disabled.  request_irq records the Linux handler and unmasks the IRQ
 * through its chip (struct lx_irq_chip below: ena_int for an AINTC line);
 * free_irq of the last handler masks it again.  A line's ISR calls the
 * handlers in interrupt context, bracketed by lx_irq_enter/exit.
 *
 * Priority: every Linux line runs at LX_IRQ_PRIORITY, the tick's priority,
 * so Linux handlers and hrtimer callbacks (run from the tick) never nest -
 * each runs to completion, as in Linux since 2.6.35 - while anything the RTOS
 * configures above (TMIN_INTPRI) still preempts them.
 *
 * On the DaVinci machine, GPIO bank lines (42..50) are demultiplexed into
 * per-pin IRQs (101 + gpio, mach/irqs.h) by the machine's lx_gpio_bank_isr:
 * drivers request the pin IRQs, never the bank lines.
 */
#ifndef _LINUX_COMPAT_IRQ_H
#define _LINUX_COMPAT_IRQ_H

#include <linux/types.h>
#include <stdbool.h>
#include <mach/irqs.h>

/* Interrupt priority of every Linux line: the tick's (INTPRI_TICK, a build
 * setting: rtos_cfg.h), so Linux handlers and hrtimer callbacks never nest. */
#ifdef INTPRI_TICK
#define LX_IRQ_PRIORITY		(INTPRI_TICK)
#else
#define LX_IRQ_PRIORITY		(-28)
#endif

/* Handler records (struct irqaction) available to request_irq in total. */
#ifndef LX_NR_IRQ_ACTIONS
#define LX_NR_IRQ_ACTIONS	32
#endif

/*
 * The controller behind an IRQ, as Linux's struct irq_chip: the generic
 * core (irq.c) masks, unmasks and checks trigger types only through it, and
 * the machine (linux_compat/machine.h) says which chip serves which IRQ.
 */
struct lx_irq_chip {
	const char *name;
	/* Lets irq deliver, with trigger type (IRQ_TYPE_NONE: the chip's
	 * default); also called again when the type of a live IRQ changes.
	 * Returns 0 or -EINVAL. */
	int  (*irq_unmask)(unsigned int irq, unsigned int type);
	/* Stops irq delivering. */
	void (*irq_mask)(unsigned int irq);
	/* 0 if the chip supports trigger type (IRQ_TYPE_* sense bits), else -EINVAL. */
	int  (*irq_check_type)(unsigned int type);
};

/* The RTOS configuration fragment declaring the lines (and lx_io_boot). */
struct rtos_cfg;
extern const struct rtos_cfg linux_irq_cfg;

/* ISR of a line that carries one Linux IRQ: runs the Linux handlers of IRQ exinf. */
void lx_irq_dispatch(intptr_t exinf);

/* Runs the Linux handlers of irq in interrupt context; returns true if one handled it.
 * While irq is disabled it runs none and records the interrupt as pending. */
bool lx_handle_irq(unsigned int irq);

/* Records that an interrupt of irq came while it was disabled (a chip found
 * it latched when masking its line): enable_irq replays it (Linux's IRQS_PENDING). */
void lx_irq_set_pending(unsigned int irq);

/* Unmasks irq's line through its chip (IRQ_TYPE_NONE) / masks it (asm/fiq.h's enable_fiq). */
int lx_irq_line_unmask(unsigned int irq);
void lx_irq_line_mask(unsigned int irq);

/* If irq is routed to the FIQ (enable_fiq): runs the FIQ handler (or, while
 * the FIQ is masked, leaves it pending) and returns true; false otherwise. */
bool lx_fiq_take(unsigned int irq);
/* Forgets the FIQ's owner, handler, routes and mask (boot). */
void lx_fiq_boot(void);

/* True if drivers may request irq (the machine has a chip for it). */
bool lx_irq_valid(unsigned int irq);

/* Handler calls of irq where every handler returned IRQ_NONE (since boot). */
unsigned long lx_irq_unhandled_count(unsigned int irq);
/* Times the handlers of irq ran (since boot). */
unsigned long lx_irq_count(unsigned int irq);

/* ATT_INI of linux_irq_cfg: forgets all IRQ handlers, the machine's state, I/O
 * regions and registered devices of a previous boot (host tests boot repeatedly).
 * Must run before any module init. */
void lx_io_boot(intptr_t exinf);

/* Resets the I/O region registry (lx_io_boot). */
void lx_resource_boot(void);
/* Resets the device registry (lx_io_boot). */
void lx_devfs_boot(void);
/* Forgets buses, the deferred-probe list and the core lock (lx_io_boot). */
void lx_driver_core_boot(void);
/* The driver core's lock (re-entrant for its holder), for src/sysfs.c. */
void lx_driver_core_lock(void);
void lx_driver_core_unlock(void);
struct bus_type;
/* Registers bus at boot (lx_platform_boot), before any task runs: no lock. */
void lx_bus_register_boot(struct bus_type *bus);
/* Registers the platform bus afresh, its auto ids free (lx_io_boot). */
void lx_platform_boot(void);
/* Frees every GPIO descriptor and forgets the lookup tables (lx_io_boot). */
void lx_gpiolib_boot(void);
/* Forgets SPI controllers, devices, drivers and board info (lx_io_boot). */
void lx_spi_boot(void);
/* Forgets PWM chips and lookup tables (lx_io_boot). */
void lx_pwm_boot(void);
/* Forgets IIO devices and maps, registers the iio bus (lx_io_boot). */
void lx_iio_boot(void);
/* Forgets I2C adapters, clients and board info; registers the I2C bus (lx_io_boot). */
void lx_i2c_boot(void);
/* Forgets the EV3 input ports' I2C buses (lx_io_boot). */
void lx_legoev3_i2c_boot(void);
/* Forgets tty drivers and line disciplines but N_TTY (lx_io_boot). */
void lx_tty_boot(void);
/* Forgets the DaVinci UART ports and their tty driver (lx_io_boot). */
void lx_davinci_serial_boot(void);
/* Forgets the DaVinci I2C controllers' adapters (lx_io_boot). */
void lx_davinci_i2c_boot(void);
/* Forgets registered frame buffers (lx_io_boot). */
void lx_fb_boot(void);
/* Puts every task back to USER_DS (lx_io_boot). */
void lx_uaccess_boot(void);

#endif /* _LINUX_COMPAT_IRQ_H */
