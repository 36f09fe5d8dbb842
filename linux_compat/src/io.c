/*
 * io.c — ioremap and the I/O memory copies.  Where a physical register range
 * is visible to the CPU is the target's business (lx_platform_io_window:
 * src/host/io.c, src/am1808/io.c).
 */
#include <linux/io.h>
#include <linux/kernel.h>
#include <mach/hardware.h>
#include <linux_compat/irq.h>
#include <linux_compat/platform.h>

void __iomem *lx_io_map(phys_addr_t phys, size_t size)
{
	if (size == 0 || phys + size - 1 < phys)
		return NULL;
	return (void __iomem *)lx_platform_io_window((uintptr_t)phys, size);
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
