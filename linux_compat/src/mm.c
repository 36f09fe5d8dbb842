/*
 * mm.c — struct page lookup and remap_pfn_range.
 *
 * ev3lx has no page tables to edit: a driver's .mmap "maps" kernel memory by
 * calling remap_pfn_range, which records in the vm_area_struct which kernel
 * address backs the area; lx_dev_mmap (devfs.c) then hands that address to
 * the caller.  Flat address space: pfn << PAGE_SHIFT is the kernel address.
 */
#include <linux/mm.h>
#include <linux/errno.h>
#include <linux_compat/report.h>
#include <sil.h>

#define LX_HEAP_PAGES	(LX_HEAP_SIZE / PAGE_SIZE)

static struct page heap_pages[LX_HEAP_PAGES];
static struct page foreign_pages[LX_NR_FOREIGN_PAGES];
static unsigned int foreign_used;
static struct page lost_page;   /* handed out (after a report) when the table is full */

struct page *lx_virt_to_page(const void *addr)
{
	uintptr_t page_addr = (uintptr_t)addr & PAGE_MASK;
	struct page *page = NULL;
	unsigned int i;
	SIL_PRE_LOC;

	if (lx_heap_contains(addr)) {
		page = &heap_pages[(page_addr - (uintptr_t)lx_heap_area) >> PAGE_SHIFT];
		page->virtual = (void *)page_addr;
		return page;
	}
	SIL_LOC_INT();
	for (i = 0; i < foreign_used; i++) {
		if ((uintptr_t)foreign_pages[i].virtual == page_addr) {
			page = &foreign_pages[i];
			break;
		}
	}
	if (!page && foreign_used < LX_NR_FOREIGN_PAGES) {
		page = &foreign_pages[foreign_used++];
		page->flags = 0;
		page->virtual = (void *)page_addr;
	}
	SIL_UNL_INT();
	if (!page) {
		lx_report("virt_to_page: no struct page left", __FILE__, __LINE__,
			  "%p is outside the kmalloc pool and all %d spare struct pages are taken "
			  "(raise LX_NR_FOREIGN_PAGES)", addr, LX_NR_FOREIGN_PAGES);
		lost_page.virtual = (void *)page_addr;
		page = &lost_page;
	}
	return page;
}

int remap_pfn_range(struct vm_area_struct *vma, unsigned long addr,
		    unsigned long pfn, unsigned long size, pgprot_t prot)
{
	unsigned long kaddr = (unsigned long)(uintptr_t)pfn_to_virt(pfn);

	(void)prot;
	if (!vma || size == 0 || (addr & ~PAGE_MASK) ||
	    addr < vma->vm_start || addr > vma->vm_end || size > vma->vm_end - addr)
		return -EINVAL;
	if (addr == vma->vm_start) {
		vma->lx_kaddr = kaddr;
		vma->lx_mapped = 0;
	}
	/* ev3lx hands out one pointer per mapping, so pieces must be contiguous. */
	if (addr != vma->vm_start + vma->lx_mapped ||
	    kaddr != vma->lx_kaddr + (addr - vma->vm_start))
		return -EINVAL;
	vma->lx_mapped += size;
	vma->vm_flags |= VM_IO | VM_PFNMAP | VM_DONTEXPAND | VM_DONTDUMP;
	return 0;
}

int vm_iomap_memory(struct vm_area_struct *vma, phys_addr_t start, unsigned long len)
{
	unsigned long vm_len, pages;

	if (!vma || start + len < start)
		return -EINVAL;
	pages = (unsigned long)((len + ((unsigned long)start & ~PAGE_MASK) + PAGE_SIZE - 1) >> PAGE_SHIFT);
	if (vma->vm_pgoff > pages)
		return -EINVAL;
	vm_len = vma->vm_end - vma->vm_start;
	if ((vm_len >> PAGE_SHIFT) > pages - vma->vm_pgoff)
		return -EINVAL;
	return remap_pfn_range(vma, vma->vm_start,
			       (unsigned long)(start >> PAGE_SHIFT) + vma->vm_pgoff,
			       vm_len, vma->vm_page_prot);
}
