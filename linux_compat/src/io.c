/*
 * io.c — ioremap and the SYSCFG windows.
 *
 * Host: a physical register range is reachable only through the window the
 * installed MMIO handler (host_sim) returns for it, so that every access has
 * declared semantics; an unmodelled range maps to NULL.  AM1808: the MMU maps
 * the peripheral space flat, so the window is the physical address itself.
 */
#include <linux/io.h>
#include <linux/kernel.h>
#include <linux/sizes.h>
#include <mach/da8xx.h>
#include <mach/hardware.h>
#include <linux_compat/irq.h>
#if defined(EV3LX_HOST)
#include <rtos_host.h>
#endif

void __iomem *da8xx_syscfg0_base;
void __iomem *da8xx_syscfg1_base;

void __iomem *lx_io_map(phys_addr_t phys, size_t size)
{
	if (size == 0 || phys + size - 1 < phys)
		return NULL;
#if defined(EV3LX_HOST)
	return (void __iomem *)rtos_host_map_io((uintptr_t)phys, (SIZE)size);
#else
	return (void __iomem *)(uintptr_t)phys;
#endif
}

void __iomem *ioremap(phys_addr_t phys, size_t size)
{
	void __iomem *addr;

	lx_might_sleep("ioremap()", __FILE__, __LINE__);
	addr = lx_io_map(phys, size);
	if (!addr)
		pr_err("ioremap(%#llx, %#lx): no device registers there\n",
		       (unsigned long long)phys, (unsigned long)size);
	return addr;
}

void iounmap(volatile void __iomem *addr)
{
	(void)addr;
	lx_might_sleep("iounmap()", __FILE__, __LINE__);
}

unsigned long lx_io_address(phys_addr_t phys)
{
	return (unsigned long)(uintptr_t)lx_io_map(phys, 4);
}

void memcpy_fromio(void *to, const volatile void __iomem *from, size_t count)
{
	u8 *dst = to;
	const volatile u8 __iomem *src = from;

	while (count--)
		*dst++ = __raw_readb(src++);
}

void memcpy_toio(volatile void __iomem *to, const void *from, size_t count)
{
	volatile u8 __iomem *dst = to;
	const u8 *src = from;

	while (count--)
		__raw_writeb(*src++, dst++);
}

void memset_io(volatile void __iomem *addr, int value, size_t count)
{
	volatile u8 __iomem *dst = addr;

	while (count--)
		__raw_writeb((u8)value, dst++);
}

void lx_iomap_boot(void)
{
	da8xx_syscfg0_base = lx_io_map(DA8XX_SYSCFG0_BASE, SZ_4K);
	da8xx_syscfg1_base = lx_io_map(DA8XX_SYSCFG1_BASE, SZ_4K);
}
