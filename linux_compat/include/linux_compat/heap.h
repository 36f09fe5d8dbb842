/*
 * linux_compat/heap.h — the kmalloc pool: its configured size and statistics.
 *
 * kmalloc serves every request from one static pool of LX_HEAP_SIZE bytes
 * (a buddy allocator: power-of-two blocks of 32 bytes and up, segregated free
 * lists, O(number of orders) split and merge, so bounded time; see
 * linux_compat/src/slab.c).  The size is a build-time setting of the
 * configuration: -DLX_HEAP_SIZE=<bytes> (a multiple of PAGE_SIZE) for the
 * whole build.  The default, 512 KiB, holds the three reference drivers'
 * mmap areas (a 53 KiB kmalloc for the UART's 42 KiB page-aligned area takes
 * a 64 KiB block) with ample room for the rest.
 */
#ifndef _LINUX_COMPAT_HEAP_H
#define _LINUX_COMPAT_HEAP_H

#include <stddef.h>
#include <stdbool.h>

#ifndef LX_HEAP_SIZE
#define LX_HEAP_SIZE	(512UL * 1024UL)
#endif

/* Smallest block (and so the alignment of every allocation), in bytes. */
#define LX_HEAP_MIN_BLOCK	32UL

/* The pool itself, page-aligned: a configuration may grant a user domain
 * access to it (struct rtos_mem_cfg) so that mmap'd driver buffers are
 * readable from applications. */
extern unsigned char lx_heap_area[LX_HEAP_SIZE];

struct lx_heap_stats {
	size_t size;            /* bytes in the pool */
	size_t in_use;          /* bytes in allocated blocks (block sizes, not requests) */
	size_t high_water;      /* largest in_use seen since boot or lx_heap_reset_high_water */
	size_t largest_free;    /* size of the largest free block */
	unsigned long allocations;  /* successful kmalloc-family calls */
	unsigned long frees;        /* kfree calls that released a block */
	unsigned long failures;     /* requests refused (pool exhausted or too large) */
};

/* Fills *stats with a consistent snapshot of the pool.  Any context. */
void lx_heap_get_stats(struct lx_heap_stats *stats);

/* Empties the pool: every block is free and the statistics restart (linux_compat's
 * boot reset - a fresh system; memory from an earlier boot must not be used any more). */
void lx_heap_reset(void);

/* Restarts the high-water mark at the current use.  Any context. */
void lx_heap_reset_high_water(void);

/* True if p points into the pool. */
bool lx_heap_contains(const void *p);

#endif /* _LINUX_COMPAT_HEAP_H */
