/*
 * linux/mm_types.h — struct page and struct vm_area_struct.
 *
 * struct page carries only what drivers touch: flags (PG_reserved...) and
 * the kernel address of the page.  Pages of the kmalloc pool have a fixed
 * struct page each (O(1) virt_to_page); other kernel pages get one from a
 * small table on first use (linux_compat/src/mm.c).
 *
 * struct vm_area_struct is what a driver's .mmap sees when an application
 * maps a device through the registry (linux_compat/devfs.h: lx_dev_mmap).
 * There is no MMU work: remap_pfn_range records which kernel memory backs
 * the area and the caller gets a pointer to it.  The lx_* members are
 * ev3lx's record of that mapping.
 */
#ifndef _LINUX_MM_TYPES_H
#define _LINUX_MM_TYPES_H

#include <linux/types.h>
#include <asm/page.h>

struct page {
	unsigned long flags;    /* PG_* bits (linux/page-flags.h) */
	void *virtual;          /* kernel address of the page */
};

struct file;
struct vm_area_struct;
struct vm_fault;

typedef unsigned long vm_flags_t;
typedef unsigned int vm_fault_t;

struct vm_operations_struct {
	void (*open)(struct vm_area_struct *area);
	void (*close)(struct vm_area_struct *area);
	vm_fault_t (*fault)(struct vm_fault *vmf);
};

struct vm_area_struct {
	unsigned long vm_start;         /* first address of the area */
	unsigned long vm_end;           /* first address after the area */
	unsigned long vm_pgoff;         /* offset in the file, in pages */
	pgprot_t vm_page_prot;
	vm_flags_t vm_flags;            /* VM_READ, VM_WRITE, VM_SHARED... */
	const struct vm_operations_struct *vm_ops;
	struct file *vm_file;
	void *vm_private_data;
	/* ev3lx: kernel memory backing [vm_start, vm_start + lx_mapped) */
	unsigned long lx_kaddr;
	unsigned long lx_mapped;
};

#endif /* _LINUX_MM_TYPES_H */
