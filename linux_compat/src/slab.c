/*
 * slab.c — kmalloc & co. on a static pool: a binary buddy allocator.
 *
 * The pool (lx_heap_area, LX_HEAP_SIZE bytes, page-aligned) is cut into
 * power-of-two blocks of order LX_MIN_ORDER (32 bytes) and up.  A block of
 * order k sits at a pool offset that is a multiple of 2^k, so blocks of a
 * page or more are page-aligned and every block is 32-byte aligned.
 *
 * Bounded time: free blocks sit in one doubly linked list per order, a bit
 * mask tells which lists are non-empty, so kmalloc finds a block with one
 * count-trailing-zeros and splits at most (orders - 1) times; kfree merges
 * with free buddies at most (orders - 1) times.  Everything runs with
 * interrupts locked (GFP_ATOMIC callers in ISRs share the pool) for at most
 * those few dozen steps.
 *
 * Block state lives beside the pool, one byte per 32-byte granule, non-zero
 * only at the first granule of a current block: FREE or USED plus the order.
 * So kfree can tell a live block from a stray or double free, and under
 * AddressSanitizer free blocks and the slack after each request are poisoned
 * (the free-list links inside free blocks are unpoisoned only while the
 * allocator itself touches them).
 */
#include <linux/slab.h>
#include <linux/mm.h>
#include <linux/kernel.h>
#include <linux/string.h>
#include <linux/bug.h>
#include <linux/printk.h>
#include <linux_compat/fault_inject.h>
#include <linux_compat/report.h>
#include <sil.h>
#include <rtos_cfg.h>

#if defined(__SANITIZE_ADDRESS__)
/* AddressSanitizer's run-time interface (what <sanitizer/asan_interface.h>
 * declares; that header needs the C library's <stdint.h>, which Linux code
 * does not see): free blocks are poisoned, so a use after kfree is caught. */
void __asan_poison_memory_region(void const volatile *addr, size_t size);
void __asan_unpoison_memory_region(void const volatile *addr, size_t size);
#define lx_poison(addr, size)	__asan_poison_memory_region((addr), (size))
#define lx_unpoison(addr, size)	__asan_unpoison_memory_region((addr), (size))
#else
#define lx_poison(addr, size)	((void)(addr), (void)(size))
#define lx_unpoison(addr, size)	((void)(addr), (void)(size))
#endif

#define LX_MIN_ORDER	5U
#define LX_NR_GRANULES	(LX_HEAP_SIZE >> LX_MIN_ORDER)
#define LX_MAX_ORDERS	32U

#define BLK_FREE	0x80U
#define BLK_USED	0x40U
#define BLK_ORDER	0x1fU

_Static_assert(LX_HEAP_SIZE % PAGE_SIZE == 0, "LX_HEAP_SIZE must be a multiple of PAGE_SIZE");
_Static_assert((1UL << LX_MIN_ORDER) == LX_HEAP_MIN_BLOCK, "granule size");

unsigned char lx_heap_area[LX_HEAP_SIZE] __attribute__((aligned(PAGE_SIZE))) EV3LX_SHARED_RO;

/* The free-list link stored in the first bytes of a free block (granule indices). */
struct free_link {
	uint32_t next;
	uint32_t prev;
};
#define NO_BLOCK	U32_MAX

static uint8_t block_state[LX_NR_GRANULES];
static uint32_t free_head[LX_MAX_ORDERS];
static uint32_t free_mask;             /* bit k: free_head[k] is non-empty */
static unsigned int top_order;         /* largest order a block can have */
static bool heap_ready;
static struct lx_heap_stats stats;

static inline unsigned char *granule_addr(uint32_t g)
{
	return lx_heap_area + ((size_t)g << LX_MIN_ORDER);
}

static inline size_t order_bytes(unsigned int order)
{
	return (size_t)1 << order;
}

/* Reads the link of free block g. */
static struct free_link link_get(uint32_t g)
{
	struct free_link link;

	lx_unpoison(granule_addr(g), sizeof(link));
	memcpy(&link, granule_addr(g), sizeof(link));
	lx_poison(granule_addr(g), sizeof(link));
	return link;
}

/* Writes the link of free block g. */
static void link_set(uint32_t g, struct free_link link)
{
	lx_unpoison(granule_addr(g), sizeof(link));
	memcpy(granule_addr(g), &link, sizeof(link));
	lx_poison(granule_addr(g), sizeof(link));
}

/* Puts block g of the given order on its free list. */
static void free_list_push(uint32_t g, unsigned int order)
{
	uint32_t head = free_head[order];
	struct free_link link = { head, NO_BLOCK };

	if (head != NO_BLOCK) {
		struct free_link old = link_get(head);

		old.prev = g;
		link_set(head, old);
	}
	link_set(g, link);
	free_head[order] = g;
	free_mask |= 1U << order;
	block_state[g] = (uint8_t)(BLK_FREE | order);
}

/* Takes free block g of the given order off its free list. */
static void free_list_remove(uint32_t g, unsigned int order)
{
	struct free_link link = link_get(g);

	if (link.prev != NO_BLOCK) {
		struct free_link prev = link_get(link.prev);

		prev.next = link.next;
		link_set(link.prev, prev);
	} else {
		free_head[order] = link.next;
		if (link.next == NO_BLOCK)
			free_mask &= ~(1U << order);
	}
	if (link.next != NO_BLOCK) {
		struct free_link next = link_get(link.next);

		next.prev = link.prev;
		link_set(link.next, next);
	}
	block_state[g] = 0;
}

/* Cuts the pool into the largest aligned blocks and frees them.  Interrupts locked. */
static void heap_init_locked(void)
{
	size_t offset = 0;
	unsigned int order;

	for (order = 0; order < LX_MAX_ORDERS; order++)
		free_head[order] = NO_BLOCK;
	free_mask = 0;
	memset(block_state, 0, sizeof(block_state));
	lx_poison(lx_heap_area, sizeof(lx_heap_area));

	top_order = LX_MIN_ORDER;
	while (top_order + 1 < LX_MAX_ORDERS && order_bytes(top_order + 1) <= LX_HEAP_SIZE)
		top_order++;

	for (order = top_order; order >= LX_MIN_ORDER; order--) {
		if (LX_HEAP_SIZE - offset >= order_bytes(order)) {
			free_list_push((uint32_t)(offset >> LX_MIN_ORDER), order);
			offset += order_bytes(order);
		}
	}
	memset(&stats, 0, sizeof(stats));
	stats.size = LX_HEAP_SIZE;
	heap_ready = true;
}

/* The smallest order whose blocks hold size bytes. */
static unsigned int order_for(size_t size)
{
	unsigned int order = LX_MIN_ORDER;

	while (order_bytes(order) < size)
		order++;
	return order;
}

/* Takes a block of the order from the free lists, splitting a larger one;
 * NO_BLOCK if none is large enough.  Interrupts locked. */
static uint32_t block_take_locked(unsigned int order)
{
	uint32_t candidates = free_mask & ~((1U << order) - 1U);
	unsigned int found;
	uint32_t g;

	if (candidates == 0)
		return NO_BLOCK;
	found = (unsigned int)__builtin_ctz(candidates);
	g = free_head[found];
	free_list_remove(g, found);
	while (found > order) {
		found--;
		free_list_push(g + (uint32_t)(order_bytes(found) >> LX_MIN_ORDER), found);
	}
	block_state[g] = (uint8_t)(BLK_USED | order);
	return g;
}

/* Returns block g of the order, merging it with free buddies.  Interrupts locked. */
static void block_release_locked(uint32_t g, unsigned int order)
{
	while (order < top_order) {
		uint32_t buddy = g ^ (uint32_t)(order_bytes(order) >> LX_MIN_ORDER);

		if (((size_t)buddy << LX_MIN_ORDER) + order_bytes(order) > LX_HEAP_SIZE)
			break;
		if (block_state[buddy] != (BLK_FREE | order))
			break;
		free_list_remove(buddy, order);
		block_state[g] = 0;
		if (buddy < g)
			g = buddy;
		order++;
	}
	free_list_push(g, order);
}

/* The granule index of a live block at p, or NO_BLOCK.  Interrupts locked. */
static uint32_t live_block_locked(const void *p)
{
	uintptr_t offset;
	uint32_t g;

	if (!lx_heap_contains(p))
		return NO_BLOCK;
	offset = (uintptr_t)p - (uintptr_t)lx_heap_area;
	if (offset & (LX_HEAP_MIN_BLOCK - 1))
		return NO_BLOCK;
	g = (uint32_t)(offset >> LX_MIN_ORDER);
	if (!(block_state[g] & BLK_USED))
		return NO_BLOCK;
	return g;
}

bool lx_heap_contains(const void *p)
{
	uintptr_t a = (uintptr_t)p, base = (uintptr_t)lx_heap_area;

	return a >= base && a < base + LX_HEAP_SIZE;
}

void *kmalloc(size_t size, gfp_t flags)
{
	unsigned int order;
	uint32_t g = NO_BLOCK;
	void *p;
	SIL_PRE_LOC;

	if (gfpflags_allow_blocking(flags))
		lx_might_sleep("kmalloc(GFP_KERNEL)", __FILE__, __LINE__);
	if (size == 0)
		return ZERO_SIZE_PTR;

	SIL_LOC_INT();
	if (!heap_ready)
		heap_init_locked();
	if (unlikely(lx_fail_alloc_should_fail_locked())) {
		stats.failures++;
		SIL_UNL_INT();
		return NULL;
	}
	if (size <= order_bytes(top_order)) {
		order = order_for(size);
		g = block_take_locked(order);
	} else {
		order = 0;
	}
	if (g == NO_BLOCK) {
		stats.failures++;
	} else {
		stats.allocations++;
		stats.in_use += order_bytes(order);
		if (stats.in_use > stats.high_water)
			stats.high_water = stats.in_use;
	}
	SIL_UNL_INT();

	if (g == NO_BLOCK) {
		if (!((__force unsigned int)flags & ___GFP_NOWARN))
			pr_warn("kmalloc: cannot allocate %lu bytes (pool of %lu bytes exhausted)\n",
				(unsigned long)size, (unsigned long)LX_HEAP_SIZE);
		return NULL;
	}
	p = granule_addr(g);
	lx_unpoison(p, size);
	if ((__force unsigned int)flags & ___GFP_ZERO)
		memset(p, 0, size);
	return p;
}

void kfree(const void *objp)
{
	uint32_t g;
	unsigned int order;
	SIL_PRE_LOC;

	if (ZERO_OR_NULL_PTR(objp))
		return;
	SIL_LOC_INT();
	g = heap_ready ? live_block_locked(objp) : NO_BLOCK;
	if (g != NO_BLOCK) {
		order = block_state[g] & BLK_ORDER;
		lx_poison(granule_addr(g), order_bytes(order));
		block_release_locked(g, order);
		stats.frees++;
		stats.in_use -= order_bytes(order);
	}
	SIL_UNL_INT();
	if (g == NO_BLOCK)
		lx_report("bad kfree", __FILE__, __LINE__,
			  "kfree(%p): not a live kmalloc block (double free, or not from kmalloc)", objp);
}

size_t ksize(const void *objp)
{
	uint32_t g;
	size_t size = 0;
	SIL_PRE_LOC;

	if (ZERO_OR_NULL_PTR(objp))
		return 0;
	SIL_LOC_INT();
	g = heap_ready ? live_block_locked(objp) : NO_BLOCK;
	if (g != NO_BLOCK)
		size = order_bytes(block_state[g] & BLK_ORDER);
	SIL_UNL_INT();
	if (g == NO_BLOCK) {
		lx_report("bad ksize", __FILE__, __LINE__,
			  "ksize(%p): not a live kmalloc block", objp);
		return 0;
	}
	/* As with KASAN: the caller may now use the whole block. */
	lx_unpoison(objp, size);
	return size;
}

void *krealloc(const void *objp, size_t new_size, gfp_t flags)
{
	size_t old_size;
	void *p;

	if (new_size == 0) {
		kfree(objp);
		return ZERO_SIZE_PTR;
	}
	if (ZERO_OR_NULL_PTR(objp))
		return kmalloc(new_size, flags);
	old_size = ksize(objp);
	if (old_size == 0)
		return NULL;
	if (new_size <= old_size) {
		if ((__force unsigned int)flags & ___GFP_ZERO)
			memset((char *)objp + new_size, 0, old_size - new_size);
		return (void *)objp;
	}
	p = kmalloc(new_size, flags);
	if (!p)
		return NULL;
	memcpy(p, objp, old_size);
	kfree(objp);
	return p;
}

void kfree_sensitive(const void *objp)
{
	size_t size = ksize(objp);

	if (size)
		memset((void *)objp, 0, size);
	kfree(objp);
}

void *kmemdup(const void *src, size_t len, gfp_t flags)
{
	void *p = kmalloc(len, flags);

	if (p && len)
		memcpy(p, src, len);
	return p;
}

char *kstrndup(const char *s, size_t max, gfp_t flags)
{
	size_t len;
	char *p;

	if (!s)
		return NULL;
	len = strnlen(s, max);
	p = kmalloc(len + 1, flags);
	if (p) {
		memcpy(p, s, len);
		p[len] = '\0';
	}
	return p;
}

char *kstrdup(const char *s, gfp_t flags)
{
	return s ? kstrndup(s, strlen(s), flags) : NULL;
}

unsigned long __get_free_pages(gfp_t gfp_mask, unsigned int order)
{
	if (order > 20)
		return 0;
	return (unsigned long)kmalloc(PAGE_SIZE << order, gfp_mask);
}

void free_pages(unsigned long addr, unsigned int order)
{
	(void)order;
	if (addr)
		kfree((const void *)addr);
}

struct kmem_cache *kmem_cache_create(const char *name, unsigned int size, unsigned int align,
				     slab_flags_t flags, void (*ctor)(void *object))
{
	struct kmem_cache *cache;

	lx_might_sleep("kmem_cache_create()", __FILE__, __LINE__);
	if (align == 0)
		align = ARCH_KMALLOC_MINALIGN;
	if ((__force unsigned int)flags & (__force unsigned int)SLAB_HWCACHE_ALIGN && align < 32)
		align = 32;
	if ((align & (align - 1)) || align > PAGE_SIZE || size == 0) {
		if ((__force unsigned int)flags & (__force unsigned int)SLAB_PANIC)
			BUG();
		return NULL;
	}
	cache = kzalloc(sizeof(*cache), GFP_KERNEL);
	if (!cache) {
		if ((__force unsigned int)flags & (__force unsigned int)SLAB_PANIC)
			BUG();
		return NULL;
	}
	cache->name = name;
	cache->align = align;
	/* A block is aligned to its power-of-two size (up to a page), so rounding
	 * the object size up to the alignment gives every object that alignment. */
	cache->size = (size + align - 1) & ~((size_t)align - 1);
	cache->flags = flags;
	cache->ctor = ctor;
	return cache;
}

void kmem_cache_destroy(struct kmem_cache *cache)
{
	kfree(cache);
}

void *kmem_cache_alloc(struct kmem_cache *cache, gfp_t flags)
{
	void *p = kmalloc(cache->size, flags);

	if (p && cache->ctor)
		cache->ctor(p);
	return p;
}

void kmem_cache_free(struct kmem_cache *cache, void *objp)
{
	(void)cache;
	kfree(objp);
}

void lx_heap_get_stats(struct lx_heap_stats *out)
{
	unsigned int order;
	SIL_PRE_LOC;

	SIL_LOC_INT();
	if (!heap_ready)
		heap_init_locked();
	*out = stats;
	out->largest_free = 0;
	for (order = top_order + 1; order-- > LX_MIN_ORDER;) {
		if (free_mask & (1U << order)) {
			out->largest_free = order_bytes(order);
			break;
		}
	}
	SIL_UNL_INT();
}

/* Empties the pool (boot): it is rebuilt, poisoned, at the next use. */
void lx_heap_reset(void)
{
	SIL_PRE_LOC;

	SIL_LOC_INT();
	heap_ready = false;
	lx_fail_alloc_boot();
	SIL_UNL_INT();
}

void lx_heap_reset_high_water(void)
{
	SIL_PRE_LOC;

	SIL_LOC_INT();
	stats.high_water = stats.in_use;
	SIL_UNL_INT();
}
