/*
 * asm/page.h — page geometry and the kernel's address translations.
 *
 * ev3lx has one flat address space (the AM1808 runs with the MMU's identity
 * map; the host uses its own addresses), so a "physical" address is the
 * kernel virtual address itself: virt_to_phys and phys_to_virt are the
 * identity and a pfn is the address shifted by PAGE_SHIFT.  phys_addr_t is as
 * wide as a pointer (linux/types.h), so this holds on a 64-bit host too.
 */
#ifndef _ASM_PAGE_H
#define _ASM_PAGE_H

#include <linux/types.h>

#define PAGE_SHIFT	12
#define PAGE_SIZE	(1UL << PAGE_SHIFT)
#define PAGE_MASK	(~(PAGE_SIZE - 1))

/* Rounds an address or length up to the next page boundary. */
#define PAGE_ALIGN(addr) \
	((__typeof__(addr))(((unsigned long)(addr) + PAGE_SIZE - 1) & PAGE_MASK))
#define PAGE_ALIGNED(addr)	(((unsigned long)(addr) & (PAGE_SIZE - 1)) == 0)
#define offset_in_page(p)	((unsigned long)(p) & ~PAGE_MASK)

/* The physical address of a kernel (direct-mapped) address: the identity. */
static inline phys_addr_t virt_to_phys(const volatile void *address)
{
	return (phys_addr_t)(uintptr_t)address;
}

/* The kernel address of a physical address: the identity. */
static inline void *phys_to_virt(phys_addr_t address)
{
	return (void *)(uintptr_t)address;
}

#define __pa(x)			virt_to_phys((const volatile void *)(x))
#define __va(x)			phys_to_virt((phys_addr_t)(x))
#define __phys_to_pfn(p)	((unsigned long)((p) >> PAGE_SHIFT))
#define __pfn_to_phys(pfn)	((phys_addr_t)(pfn) << PAGE_SHIFT)
#define virt_to_pfn(kaddr)	__phys_to_pfn(virt_to_phys(kaddr))
#define pfn_to_virt(pfn)	phys_to_virt(__pfn_to_phys(pfn))
#define virt_addr_valid(kaddr)	((kaddr) != NULL)

/* Page protections: recorded by remap_pfn_range, no MMU effect in ev3lx. */
typedef struct { unsigned long pgprot; } pgprot_t;
#define pgprot_val(x)	((x).pgprot)
#define __pgprot(x)	((pgprot_t) { (x) })

#define L_PTE_PRESENT	(1UL << 0)
#define L_PTE_USER	(1UL << 8)
#define L_PTE_RDONLY	(1UL << 7)
#define L_PTE_XN	(1UL << 9)
#define PAGE_NONE	__pgprot(0)
#define PAGE_SHARED	__pgprot(L_PTE_PRESENT | L_PTE_USER | L_PTE_XN)
#define PAGE_SHARED_EXEC __pgprot(L_PTE_PRESENT | L_PTE_USER)
#define PAGE_READONLY	__pgprot(L_PTE_PRESENT | L_PTE_USER | L_PTE_RDONLY | L_PTE_XN)
#define PAGE_KERNEL	__pgprot(L_PTE_PRESENT | L_PTE_XN)
#define pgprot_noncached(prot)		(prot)
#define pgprot_writecombine(prot)	(prot)

#endif /* _ASM_PAGE_H */
