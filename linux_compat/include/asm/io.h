/*
 * asm/io.h — memory-mapped I/O: ioremap and the register accessors.
 *
 * Every accessor is one access of exactly the named width, the same as the
 * TOPPERS SIL's sil_reb/reh/rew_mem and sil_wrb/wrh/wrw_mem: on the AM1808 a
 * volatile load or store; on the host the access goes to the MMIO handler
 * host_sim installed (sil_host_read/sil_host_write, declared here with C
 * types so that no TOPPERS name reaches a driver), which gives each register
 * its declared semantics.  Registers
 * are little-endian like the CPU, so no byte swapping.  readX/writeX order
 * against normal memory with a compiler barrier (one in-order CPU, device
 * memory strongly ordered); the _relaxed and __raw_ forms omit it.
 *
 * ioremap (linux_compat/src/io.c): host - the window host_sim models for the
 * physical range (rtos_host_map_io), NULL if nothing is modelled there;
 * AM1808 - the identity (peripherals are mapped flat).  iounmap releases
 * nothing (the windows are static).
 */
#ifndef __ASM_ARM_IO_H
#define __ASM_ARM_IO_H

#include <linux/types.h>
#include <linux/compiler.h>
#include <asm/page.h>

#ifdef EV3LX_HOST
uint32_t sil_host_read(const volatile void *mem, unsigned int width);
void sil_host_write(volatile void *mem, unsigned int width, uint32_t data);
#define __lx_mmio_read(type, addr) \
	((type)sil_host_read((__force const volatile void *)(addr), sizeof(type)))
#define __lx_mmio_write(type, value, addr) \
	sil_host_write((__force volatile void *)(addr), sizeof(type), (type)(value))
#else
#define __lx_mmio_read(type, addr)	(*(__force const volatile type *)(addr))
#define __lx_mmio_write(type, value, addr) \
	((void)(*(__force volatile type *)(addr) = (type)(value)))
#endif

#ifndef mb
#define mb()		__asm__ __volatile__("" : : : "memory")
#define rmb()		__asm__ __volatile__("" : : : "memory")
#define wmb()		__asm__ __volatile__("" : : : "memory")
#endif
#ifndef dma_rmb
#define dma_rmb()	rmb()
#define dma_wmb()	wmb()
#endif
#define mmiowb()	do { } while (0)

static inline u8 __raw_readb(const volatile void __iomem *addr)
{
	return __lx_mmio_read(u8, addr);
}

static inline u16 __raw_readw(const volatile void __iomem *addr)
{
	return __lx_mmio_read(u16, addr);
}

static inline u32 __raw_readl(const volatile void __iomem *addr)
{
	return __lx_mmio_read(u32, addr);
}

static inline void __raw_writeb(u8 value, volatile void __iomem *addr)
{
	__lx_mmio_write(u8, value, addr);
}

static inline void __raw_writew(u16 value, volatile void __iomem *addr)
{
	__lx_mmio_write(u16, value, addr);
}

static inline void __raw_writel(u32 value, volatile void __iomem *addr)
{
	__lx_mmio_write(u32, value, addr);
}

#define readb_relaxed(c)	__raw_readb(c)
#define readw_relaxed(c)	__raw_readw(c)
#define readl_relaxed(c)	__raw_readl(c)
#define writeb_relaxed(v, c)	__raw_writeb((v), (c))
#define writew_relaxed(v, c)	__raw_writew((v), (c))
#define writel_relaxed(v, c)	__raw_writel((v), (c))

#define readb(c)	({ u8 __lx_v = __raw_readb(c); rmb(); __lx_v; })
#define readw(c)	({ u16 __lx_v = __raw_readw(c); rmb(); __lx_v; })
#define readl(c)	({ u32 __lx_v = __raw_readl(c); rmb(); __lx_v; })
#define writeb(v, c)	({ wmb(); __raw_writeb((v), (c)); })
#define writew(v, c)	({ wmb(); __raw_writew((v), (c)); })
#define writel(v, c)	({ wmb(); __raw_writel((v), (c)); })

/* The iomap interface: the same accesses as readX/writeX. */
static inline unsigned int ioread8(const volatile void __iomem *addr)
{
	return readb(addr);
}

static inline unsigned int ioread16(const volatile void __iomem *addr)
{
	return readw(addr);
}

static inline unsigned int ioread32(const volatile void __iomem *addr)
{
	return readl(addr);
}

static inline void iowrite8(u8 value, volatile void __iomem *addr)
{
	writeb(value, addr);
}

static inline void iowrite16(u16 value, volatile void __iomem *addr)
{
	writew(value, addr);
}

static inline void iowrite32(u32 value, volatile void __iomem *addr)
{
	writel(value, addr);
}

/* Byte-wise copies between normal memory and registers (one access per byte). */
void memcpy_fromio(void *to, const volatile void __iomem *from, size_t count);
void memcpy_toio(volatile void __iomem *to, const void *from, size_t count);
void memset_io(volatile void __iomem *addr, int value, size_t count);

/* Maps the physical register range [phys, phys + size) (see above); NULL if impossible.  Process context. */
void __iomem *ioremap(phys_addr_t phys, size_t size);
/* Releases a mapping from ioremap (nothing to release: the windows are static). */
void iounmap(volatile void __iomem *addr);

#define ioremap_nocache(phys, size)	ioremap((phys), (size))
#define ioremap_wc(phys, size)		ioremap((phys), (size))
#define ioremap_uc(phys, size)		ioremap((phys), (size))
#define ioremap_cache(phys, size)	ioremap((phys), (size))

#endif /* __ASM_ARM_IO_H */
