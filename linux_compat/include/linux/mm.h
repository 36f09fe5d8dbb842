/*
 * linux/mm.h — pages, mappings and remap_pfn_range.
 *
 * As in 2.6.33, including linux/mm.h also makes kmalloc reachable (LEGO's
 * d_analog uses kmalloc without including linux/slab.h).
 *
 * virt_to_page accepts any kernel address: pages of the kmalloc pool map to
 * their fixed struct page; for other addresses (static buffers) a struct page
 * is taken from a table of LX_NR_FOREIGN_PAGES on first use, and exhausting
 * that table is reported.  page_address(virt_to_page(p)) is p's page.
 */
#ifndef _LINUX_MM_H
#define _LINUX_MM_H

#include <linux/types.h>
#include <linux/gfp.h>
#include <linux/slab.h>
#include <linux/string.h>    /* as in Linux (through its bitmap headers): LEGO's drivers rely on it */
#include <linux/mm_types.h>
#include <linux/page-flags.h>
#include <asm/page.h>

/* struct pages available for kernel pages outside the kmalloc pool. */
#ifndef LX_NR_FOREIGN_PAGES
#define LX_NR_FOREIGN_PAGES	64
#endif

#define VM_NONE		0x00000000UL
#define VM_READ		0x00000001UL
#define VM_WRITE	0x00000002UL
#define VM_EXEC		0x00000004UL
#define VM_SHARED	0x00000008UL
#define VM_MAYREAD	0x00000010UL
#define VM_MAYWRITE	0x00000020UL
#define VM_MAYEXEC	0x00000040UL
#define VM_MAYSHARE	0x00000080UL
#define VM_IO		0x00004000UL
#define VM_DONTCOPY	0x00020000UL
#define VM_DONTEXPAND	0x00040000UL
#define VM_LOCKED	0x00002000UL
#define VM_ACCOUNT	0x00100000UL
#define VM_NORESERVE	0x00200000UL
#define VM_PFNMAP	0x00000400UL
#define VM_DONTDUMP	0x04000000UL
#define VM_RESERVED	(VM_DONTEXPAND | VM_DONTDUMP)  /* 2.6.33's name */

/* The struct page of the page holding kernel address addr (see above). */
struct page *lx_virt_to_page(const void *addr);
#define virt_to_page(addr)	lx_virt_to_page((const void *)(addr))

/* The kernel address of the start of a page. */
static inline void *page_address(const struct page *page)
{
	return page->virtual;
}

#define page_to_virt(page)	page_address(page)
#define page_to_pfn(page)	virt_to_pfn(page_address(page))
#define pfn_to_page(pfn)	virt_to_page(pfn_to_virt(pfn))
#define page_to_phys(page)	virt_to_phys(page_address(page))
#define pfn_valid(pfn)		((pfn) != 0)

/* The allocation order for size bytes: the smallest o with PAGE_SIZE << o >= size. */
static inline int get_order(unsigned long size)
{
	int order = 0;

	size = (size - 1) >> PAGE_SHIFT;
	while (size) {
		order++;
		size >>= 1;
	}
	return order;
}

/* Maps kernel memory (pfn onward) at [addr, addr + size) of vma: records it
 * for the caller of the mmap (lx_dev_mmap).  The range must lie inside the vma
 * and continue any mapping already made in it.  0, or -EINVAL. */
int remap_pfn_range(struct vm_area_struct *vma, unsigned long addr,
		    unsigned long pfn, unsigned long size, pgprot_t prot);
#define io_remap_pfn_range	remap_pfn_range

/* Maps physical memory [start, start + len) over the whole vma (honouring vm_pgoff). */
int vm_iomap_memory(struct vm_area_struct *vma, phys_addr_t start, unsigned long len);

/* Whole pages: PAGE_SIZE << order bytes from the kmalloc pool, page-aligned. */
unsigned long __get_free_pages(gfp_t gfp_mask, unsigned int order);
#define __get_free_page(gfp_mask)	__get_free_pages((gfp_mask), 0)
#define get_zeroed_page(gfp_mask)	__get_free_pages((gfp_mask) | __GFP_ZERO, 0)
/* Returns pages from __get_free_pages; 0 is ignored. */
void free_pages(unsigned long addr, unsigned int order);
#define free_page(addr)			free_pages((addr), 0)

static inline bool is_vmalloc_addr(const void *x)
{
	(void)x;
	return false;
}

#endif /* _LINUX_MM_H */
