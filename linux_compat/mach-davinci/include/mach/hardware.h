/*
 * mach/hardware.h — DaVinci's I/O space and IO_ADDRESS.
 *
 * DaVinci maps its peripheral space statically and IO_ADDRESS(phys) gives
 * the virtual address of a register.  In ev3lx that is ioremap's window:
 * the identity on the AM1808, host_sim's window on the host (0 if the
 * address is not modelled).
 */
#ifndef __ASM_ARCH_HARDWARE_H
#define __ASM_ARCH_HARDWARE_H

#include <linux/types.h>
#include <linux/compiler.h>

#define IO_PHYS			0x01c00000UL
#define IO_SIZE			0x00400000UL

/* ioremap without the process-context check: for linux_compat itself
 * (GPIO fast paths may map lazily from interrupt context). */
void __iomem *lx_io_map(phys_addr_t phys, size_t size);

/* The kernel address of physical register address phys (see above). */
unsigned long lx_io_address(phys_addr_t phys);
#define IO_ADDRESS(phys)	lx_io_address(phys)

#endif /* __ASM_ARCH_HARDWARE_H */
