/*
 * linux/vmalloc.h — virtually contiguous allocations.  There is no MMU
 * remapping here: vmalloc is kmalloc from the same pool (physically
 * contiguous, which satisfies every vmalloc caller), vfree is kfree.
 * Process context, as in Linux (vmalloc may sleep).  kvmalloc & co. are in
 * linux/slab.h.
 */
#ifndef _LINUX_VMALLOC_H
#define _LINUX_VMALLOC_H

#include <linux/types.h>
#include <linux/slab.h>

/* size bytes, or NULL. */
static inline void *vmalloc(unsigned long size)
{
	return kmalloc(size, GFP_KERNEL);
}

/* size zeroed bytes, or NULL. */
static inline void *vzalloc(unsigned long size)
{
	return kzalloc(size, GFP_KERNEL);
}

/* Releases a vmalloc'd block; NULL is ignored. */
static inline void vfree(const void *addr)
{
	kfree(addr);
}

#endif /* _LINUX_VMALLOC_H */
