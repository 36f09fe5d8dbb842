/*
 * linux/irq.h — IRQ trigger types and the per-IRQ configuration calls.
 *
 * Types: GPIO pin IRQs (101 + gpio) take IRQ_TYPE_EDGE_RISING, _FALLING or
 * _BOTH and program the bank's SET/CLR_RIS_TRIG and SET/CLR_FAL_TRIG as
 * DaVinci's gpio irq_chip does; level types are refused (-EINVAL), as there.
 * A pin IRQ requested with no type triggers on both edges (DaVinci default).
 * AINTC lines accept IRQ_TYPE_NONE, IRQ_TYPE_LEVEL_HIGH and
 * IRQ_TYPE_EDGE_RISING (what the AINTC's system interrupts are), recorded only.
 */
#ifndef _LINUX_IRQ_H
#define _LINUX_IRQ_H

#include <linux/types.h>
#include <linux/irqreturn.h>
#include <mach/irqs.h>

#define IRQ_TYPE_NONE		0x00000000
#define IRQ_TYPE_EDGE_RISING	0x00000001
#define IRQ_TYPE_EDGE_FALLING	0x00000002
#define IRQ_TYPE_EDGE_BOTH	(IRQ_TYPE_EDGE_FALLING | IRQ_TYPE_EDGE_RISING)
#define IRQ_TYPE_LEVEL_HIGH	0x00000004
#define IRQ_TYPE_LEVEL_LOW	0x00000008
#define IRQ_TYPE_LEVEL_MASK	(IRQ_TYPE_LEVEL_LOW | IRQ_TYPE_LEVEL_HIGH)
#define IRQ_TYPE_SENSE_MASK	0x0000000f
#define IRQ_TYPE_DEFAULT	IRQ_TYPE_SENSE_MASK

/* Sets the trigger type of irq (see above); 0 or -EINVAL.  Process context. */
int irq_set_irq_type(unsigned int irq, unsigned int type);
/* The 2.6.33 name of irq_set_irq_type (renamed in 2.6.39). */
int set_irq_type(unsigned int irq, unsigned int type);

/* The trigger type of irq as last set (IRQ_TYPE_NONE if never). */
unsigned int irq_get_trigger_type(unsigned int irq);

#endif /* _LINUX_IRQ_H */
