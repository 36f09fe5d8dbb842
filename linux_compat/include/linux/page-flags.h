/*
 * linux/page-flags.h — page flag bits and their accessors.
 *
 * Flags are plain bits in struct page: drivers set them in process context
 * (mmap buffer setup), and a single CPU needs no atomic instruction for that.
 * PG_reserved is the one with meaning here: remap_pfn_range does not require
 * it (ev3lx has no page reclaim), but it is kept so drivers can test it.
 */
#ifndef _LINUX_PAGE_FLAGS_H
#define _LINUX_PAGE_FLAGS_H

#include <linux/mm_types.h>

enum pageflags {
	PG_locked,
	PG_referenced,
	PG_uptodate,
	PG_dirty,
	PG_lru,
	PG_active,
	PG_slab,
	PG_reserved,
	PG_private,
	PG_writeback,
	__NR_PAGEFLAGS
};

#define LX_PAGEFLAG(uname, lname)						\
static inline int Page##uname(const struct page *page)				\
{ return (int)((page->flags >> PG_##lname) & 1UL); }				\
static inline void SetPage##uname(struct page *page)				\
{ page->flags |= 1UL << PG_##lname; }						\
static inline void ClearPage##uname(struct page *page)				\
{ page->flags &= ~(1UL << PG_##lname); }					\
static inline void __SetPage##uname(struct page *page)				\
{ page->flags |= 1UL << PG_##lname; }						\
static inline void __ClearPage##uname(struct page *page)			\
{ page->flags &= ~(1UL << PG_##lname); }

LX_PAGEFLAG(Reserved, reserved)
LX_PAGEFLAG(Locked, locked)
LX_PAGEFLAG(Dirty, dirty)
LX_PAGEFLAG(Uptodate, uptodate)
LX_PAGEFLAG(Private, private)

#undef LX_PAGEFLAG

#endif /* _LINUX_PAGE_FLAGS_H */
