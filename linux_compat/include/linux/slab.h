/*
 * linux/slab.h — kmalloc and friends over ev3lx's bounded-time pool.
 *
 * Semantics (linux_compat/src/slab.c, pool size in linux_compat/heap.h):
 * - NULL when the pool cannot satisfy the request (never sleeps, never
 *   waits for memory: GFP_KERNEL only adds the might_sleep check, so a
 *   GFP_KERNEL allocation from atomic context is reported as a context bug).
 * - Every block is at least 8-byte (in fact 32-byte) aligned; requests of
 *   PAGE_SIZE or more are page-aligned, as Linux's page allocator path is.
 * - kmalloc(0) returns ZERO_SIZE_PTR; kfree(NULL) and kfree(ZERO_SIZE_PTR)
 *   do nothing; kfree of anything else that is not a live block is reported.
 * - Freed memory is reused (blocks merge with their buddies).
 */
#ifndef _LINUX_SLAB_H
#define _LINUX_SLAB_H

#include <linux/types.h>
#include <linux/gfp.h>
#include <linux/compiler.h>
#include <linux/overflow.h>
#include <linux_compat/heap.h>

#define ZERO_SIZE_PTR		((void *)16)
#define ZERO_OR_NULL_PTR(x)	((unsigned long)(x) <= (unsigned long)ZERO_SIZE_PTR)

#define ARCH_KMALLOC_MINALIGN	8
#define ARCH_SLAB_MINALIGN	8
#define KMALLOC_MAX_SIZE	((size_t)LX_HEAP_SIZE)

/* Allocates size bytes from the pool; NULL if it cannot (see above). */
void *kmalloc(size_t size, gfp_t flags) __malloc;

/* Releases a block from kmalloc & co.; NULL and ZERO_SIZE_PTR are ignored.  Any context. */
void kfree(const void *objp);

/* The usable size of a live block (at least what was requested). */
size_t ksize(const void *objp);

/* Resizes a block, keeping min(old, new) bytes; NULL (old block kept) on failure. */
void *krealloc(const void *objp, size_t new_size, gfp_t flags);

/* A kmalloc'd copy of len bytes at src, or NULL. */
void *kmemdup(const void *src, size_t len, gfp_t flags);

/* A kmalloc'd copy of a string, or NULL (also for s == NULL). */
char *kstrdup(const char *s, gfp_t flags);

/* A kmalloc'd copy of at most max characters of s, NUL-terminated, or NULL. */
char *kstrndup(const char *s, size_t max, gfp_t flags);

/* kmalloc of zeroed memory. */
static inline void *kzalloc(size_t size, gfp_t flags)
{
	return kmalloc(size, flags | __GFP_ZERO);
}

/* kmalloc for an array of n elements; NULL if n * size overflows. */
static inline void *kmalloc_array(size_t n, size_t size, gfp_t flags)
{
	size_t bytes;

	if (unlikely(__builtin_mul_overflow(n, size, &bytes)))
		return NULL;
	return kmalloc(bytes, flags);
}

/* kmalloc_array of zeroed memory. */
static inline void *kcalloc(size_t n, size_t size, gfp_t flags)
{
	return kmalloc_array(n, size, flags | __GFP_ZERO);
}

/* krealloc for an array; NULL if new_n * new_size overflows. */
static inline void *krealloc_array(void *p, size_t new_n, size_t new_size, gfp_t flags)
{
	size_t bytes;

	if (unlikely(__builtin_mul_overflow(new_n, new_size, &bytes)))
		return NULL;
	return krealloc(p, bytes, flags);
}

/* Node-aware variants: one node here. */
#define kmalloc_node(size, flags, node)		kmalloc((size), (flags))
#define kzalloc_node(size, flags, node)		kzalloc((size), (flags))

/* kvmalloc & co.: there is no separate vmalloc space, the pool serves all. */
#define kvmalloc(size, flags)			kmalloc((size), (flags))
#define kvzalloc(size, flags)			kzalloc((size), (flags))
#define kvmalloc_array(n, size, flags)		kmalloc_array((n), (size), (flags))
#define kvcalloc(n, size, flags)		kcalloc((n), (size), (flags))
#define kvfree(p)				kfree(p)

/* Zeroes a block before freeing it (kfree_sensitive; kzfree before 5.9). */
void kfree_sensitive(const void *objp);
#define kzfree(p)				kfree_sensitive(p)

/* Object caches: each object is a kmalloc block of the cache's size and alignment. */
#define SLAB_HWCACHE_ALIGN	((__force slab_flags_t)0x00002000U)
#define SLAB_PANIC		((__force slab_flags_t)0x00040000U)
#define SLAB_ACCOUNT		((__force slab_flags_t)0x04000000U)
#define SLAB_RECLAIM_ACCOUNT	((__force slab_flags_t)0x00020000U)

struct kmem_cache {
	const char *name;
	size_t size;            /* object size rounded up to the alignment */
	size_t align;
	slab_flags_t flags;
	void (*ctor)(void *object);
};

/* Creates a cache of objects of size bytes; NULL if out of memory or align is not a power of two. */
struct kmem_cache *kmem_cache_create(const char *name, unsigned int size, unsigned int align,
				     slab_flags_t flags, void (*ctor)(void *object));
/* Destroys a cache (its objects must have been freed).  NULL is ignored. */
void kmem_cache_destroy(struct kmem_cache *cache);
/* One object of the cache, constructed by ctor, or NULL. */
void *kmem_cache_alloc(struct kmem_cache *cache, gfp_t flags) __malloc;
/* Returns an object to its cache. */
void kmem_cache_free(struct kmem_cache *cache, void *objp);

static inline void *kmem_cache_zalloc(struct kmem_cache *cache, gfp_t flags)
{
	return kmem_cache_alloc(cache, flags | __GFP_ZERO);
}

#define KMEM_CACHE(__struct, __flags) \
	kmem_cache_create(#__struct, sizeof(struct __struct), \
			  __alignof__(struct __struct), (__flags), NULL)

#endif /* _LINUX_SLAB_H */
