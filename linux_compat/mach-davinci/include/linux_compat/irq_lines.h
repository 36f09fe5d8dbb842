/*
 * linux_compat/irq_lines.h — the machine's Linux interrupt lines as a
 * configuration names them: their numbers (mach/irqs.h, this machine's own,
 * by relative path so that no other Linux layer's header of that name stands
 * in) and the routines attached to them, without any Linux header, so that a
 * configurator's pass and kernel_cfg.c (cfg/ev3lx.cfg) never meet two Linux
 * layers in one unit.
 */
#ifndef _LINUX_COMPAT_IRQ_LINES_H
#define _LINUX_COMPAT_IRQ_LINES_H

#include <kernel.h>
#include "../mach/irqs.h"

#ifndef TOPPERS_MACRO_ONLY
/* ISR of a Linux line: runs its Linux handlers (exinf: the line's IRQ number). */
void lx_irq_dispatch(intptr_t exinf);
/* ISR of GPIO bank exinf (0..8): acknowledges and dispatches its pending pins. */
void lx_gpio_bank_isr(intptr_t exinf);
/* ATT_INI: clears the I/O layer's state (a fresh boot). */
void lx_io_boot(intptr_t exinf);
#endif

#endif /* _LINUX_COMPAT_IRQ_LINES_H */
