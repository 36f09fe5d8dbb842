/*
 * space.c — the simulated register space: regions, declaration tables,
 * CPU-visible windows, and the one access path every register access takes
 * (accessors through rtos_stub's MMIO handler, trapped pointer accesses
 * through trap.c).  Host only.
 */
#define _GNU_SOURCE
#include <errno.h>
#include <inttypes.h>
#include <stddef.h>
#include <stdlib.h>
#include <string.h>
#include <sys/mman.h>
#include <unistd.h>

#include "rtos_host.h"
#include "host_sim/regs.h"
#include "space_internal.h"
#include "core_parts.h"

#define HS_PAGE          4096U
/*
 * The window space mirrors the AM1808's peripheral address range
 * 0x01C00000..0x01FFFFFF (AM1808 TRM, memory map: the SYSCFG/EDMA/PSC0/
 * UART0/SPI0 block at 0x01C0xxxx through eHRPWM/eCAP/timers at 0x01F0xxxx)
 * page for page, so that an ioremap of any range there — across pages,
 * regions and unmodelled holes, as Linux allows — is one contiguous window;
 * a region elsewhere (the AINTC at 0xFFFEE000) gets pages after the mirror.
 * On a 32-bit ARM host (the arm926 configuration under qemu-arm) the mirror is
 * placed at its physical address, so that ioremap() of a peripheral returns
 * the physical address itself, as the brick's identity mapping of the
 * peripherals does and as 2.6-era drivers that compare or print the pointers
 * assume; where that address is taken the space goes anywhere.
 */
#define HS_MIRROR_PHYS   0x01C00000U
#define HS_MIRROR_PAGES  1024U     /* 4 MiB */
#define HS_SPACE_PAGES   (HS_MIRROR_PAGES + 64U)
#define HS_MAX_REGIONS   64U
#define HS_NO_ELEM       (-1)

struct hs_route;

/* One register, or one element of a register array: what the access path
 * reads (its name, for reports and the log, is in the region's names). */
struct hs_elem {
	uint32_t *value;        /* stored value: own slot or the alias target's */
	hs_before_read_fn before_read;
	hs_after_write_fn after_write;
	uint32_t mask;          /* effective mask (width bits if declared 0) */
	uint32_t offset;
	uint16_t index;
	uint8_t width;          /* natural width */
	uint8_t widths;         /* allowed widths (HS_Wn bits) */
	uint8_t ok_widths;      /* widths an access may use without a report (none if reserved) */
	uint8_t kind;           /* enum hs_reg_kind */
	const struct hs_reg *reg;
	struct hs_route *routes[2];   /* read, write: see route_index; NULL if not that direction */
};

/*
 * How a CPU access of one width and direction reaches one element at one
 * byte lane: everything the access path needs once the checks passed, built
 * with the region.  It stays where it is until the region is freed, so the
 * accessors' route cache points to it and a hook is told its acc (a cache
 * slot may be refilled while the hook runs, a route is not).
 */
struct hs_route {
	/* First, so that the accessors' route cache calls its functions with it: for
	 * a read route the whole read (see route_read), for a write route the whole
	 * write (see route_write), chosen for what the route has to do. */
	struct hs_direct head;  /* head.base, the region's hook context, the element's stored value */
	hs_before_read_fn before_read;      /* read routes */
	hs_after_write_fn after_write;      /* write routes: the element's hook, or route_write_log; NULL: none */
	uint32_t wmask;         /* width_mask(width) */
	uint32_t bits;          /* write: the mask bits the lanes drive; read: those a clear-on-read clears, or 0 */
	/* A write driving lanes value turns the stored old into
	 * (old & keep & ~(value & clear)) | (value & set): the register's kind as masks. */
	uint32_t keep, clear, set;
	uint8_t shift;          /* 8 * the byte lane */
	bool logged;            /* the region's log flag, kept by hs_space_set_reglog */
	struct hs_access acc;   /* what the hooks are told */
	struct hs_region *r;
	struct hs_elem *e;
	uintptr_t phys;         /* of the access, for the log */
};

#define HS_ELEM_NAME 32U        /* "CMR[3]" */

struct hs_region {
	struct hs_region_cfg cfg;
	unsigned first_page;    /* in the window space */
	const bool *power_live;   /* the power module is on (HS_NO_PSC: always) */
	struct hs_elem *elems;
	char (*names)[HS_ELEM_NAME];   /* one per element */
	unsigned nelems;
	uint32_t *values;       /* one per element */
	/* Byte offset -> element, for offsets below map_len (the end of the last
	 * register: beyond it there is none, and the maps stay small and cached). */
	uint32_t map_len;
	int16_t *rd_map;        /* element readable there, or HS_NO_ELEM */
	int16_t *wr_map;        /* element writable there */
	int16_t *any_map;       /* element starting there in either direction */
	struct hs_route *routes;   /* every element's, both directions */
	unsigned nroutes;
	bool logged;            /* named by the register-log filter */
};

static struct {
	uint8_t *base;                              /* window space (PROT_NONE) */
	struct hs_region *page_owner[HS_SPACE_PAGES];
	struct hs_region *regions[HS_MAX_REGIONS];
	unsigned nregions;
	struct hs_region *last;                     /* last region hit: drivers mostly stay in one */
	unsigned next_page;
	uint32_t access_ns;
	char *log_filter;
	FILE *log_out;
	bool logging;
} space;

static const struct hs_power_controller *power_ctl;

/* All-ones mask of width bytes (1, 2 or 4): one shift, as it is on every access. */
static inline uint32_t width_mask(unsigned width)
{
	return 0xFFFFFFFFU >> ((32U - 8U * width) & 31U);
}

/*
 * What the checks of a recent window access found is kept in the accessors'
 * route cache (rtos_host_set_mmio_route_cache): an access that finds its
 * address, direction and width there goes from sil_host_read/write straight
 * to its route, skipping the page, map, width and power lookups (a chain of
 * dependent loads).  Emptied whenever a region is added or freed, the
 * register log changes or a PSC module's power does (hs_space_power_changed),
 * so it only ever names a powered route.
 */
static void wcache_clear(void)
{
	rtos_host_mmio_route_cache_clear();
}

void hs_space_power_changed(void)
{
	wcache_clear();
}

/* Routes an element of natural width w has per direction, when its narrowest
 * allowed width is wmin: one per width from w down to wmin, at each of its lanes. */
static unsigned route_count(unsigned w, unsigned wmin)
{
	return 2U * w / wmin - 1U;
}

/* Where the route of a width-byte access at byte lane lane is among its
 * element's: widest first, then by lane (width divides lane). */
static inline unsigned route_index(const struct hs_elem *e, unsigned width, unsigned lane)
{
	return e->width / width - 1U + lane / width;
}

/* The route of a checked width-byte access at byte lane lane of e. */
static inline const struct hs_route *elem_route(const struct hs_elem *e, bool write, unsigned width, unsigned lane)
{
	return &e->routes[write][route_index(e, width, lane)];
}

void hs_set_power_controller(const struct hs_power_controller *pc)
{
	power_ctl = pc;
}

/* Where a region's power module keeps its live flag. */
static const bool *power_live_flag(unsigned power)
{
	static const bool always = true, never = false;

	if (power == HS_NO_PSC)
		return &always;
	return power_ctl != NULL ? power_ctl->live_flag(power) : &never;
}

static const char *const kind_names[] = {
	[HS_RSVD] = "reserved", [HS_RW] = "read-write", [HS_RO] = "read-only",
	[HS_WO] = "write-only", [HS_W1S] = "write-1-to-set", [HS_W1C] = "write-1-to-clear",
	[HS_COR] = "clear-on-read",
};

/* Bit for an access width (1, 2, 4 -> HS_W8, HS_W16, HS_W32); 0 for others. */
static unsigned width_bit(unsigned width)
{
	return width == 1U ? HS_W8 : width == 2U ? HS_W16 : width == 4U ? HS_W32 : 0U;
}

static bool kind_readable(enum hs_reg_kind k)
{
	return k != HS_WO;
}

static bool kind_writable(enum hs_reg_kind k)
{
	return k != HS_RO && k != HS_COR;
}

/* Reserves the window space. */
int hs_space_init(uint32_t access_ns)
{
	void *p;

	if (space.base)
		return 0;
	p = MAP_FAILED;
#if defined(__arm__) && defined(MAP_FIXED_NOREPLACE)
	p = mmap((void *)(uintptr_t)HS_MIRROR_PHYS, (size_t)HS_SPACE_PAGES * HS_PAGE, PROT_NONE,
		 MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE | MAP_FIXED_NOREPLACE, -1, 0);
	if (p != MAP_FAILED && p != (void *)(uintptr_t)HS_MIRROR_PHYS) {
		munmap(p, (size_t)HS_SPACE_PAGES * HS_PAGE);      /* a kernel without NOREPLACE */
		p = MAP_FAILED;
	}
#endif
	if (p == MAP_FAILED)
		p = mmap(NULL, (size_t)HS_SPACE_PAGES * HS_PAGE, PROT_NONE,
			 MAP_PRIVATE | MAP_ANONYMOUS | MAP_NORESERVE, -1, 0);
	if (p == MAP_FAILED)
		return -1;
	space.base = p;
	space.next_page = HS_MIRROR_PAGES;
	space.nregions = 0;
	space.access_ns = access_ns;
	wcache_clear();
	memset(space.page_owner, 0, sizeof(space.page_owner));
	return 0;
}

/* Frees one region's tables. */
static void region_free(struct hs_region *r)
{
	free(r->elems);
	free(r->names);
	free(r->values);
	free(r->rd_map);
	free(r->wr_map);
	free(r->any_map);
	free(r->routes);
	free(r);
}

/* Frees every region and the window space. */
void hs_space_fini(void)
{
	for (unsigned i = 0; i < space.nregions; i++)
		region_free(space.regions[i]);
	space.nregions = 0;
	space.last = NULL;
	wcache_clear();
	if (space.base)
		munmap(space.base, (size_t)HS_SPACE_PAGES * HS_PAGE);
	space.base = NULL;
	memset(space.page_owner, 0, sizeof(space.page_owner));
	hs_space_set_reglog(NULL, NULL);
}

bool hs_space_claims(uintptr_t addr)
{
	uintptr_t b = (uintptr_t)space.base;

	return space.base && addr >= b && addr - b < (uintptr_t)HS_SPACE_PAGES * HS_PAGE;
}

void hs_space_bounds(uintptr_t *start, uintptr_t *len)
{
	*start = (uintptr_t)space.base;
	*len = space.base ? (uintptr_t)HS_SPACE_PAGES * HS_PAGE : 0;
}

uintptr_t hs_space_to_phys(uintptr_t addr)
{
	uintptr_t rel;
	struct hs_region *r;

	if (!hs_space_claims(addr))
		return 0;
	rel = addr - (uintptr_t)space.base;
	r = space.page_owner[rel / HS_PAGE];
	if (!r)
		return rel < (uintptr_t)HS_MIRROR_PAGES * HS_PAGE ? HS_MIRROR_PHYS + rel : 0;
	return r->cfg.phys + (rel - (uintptr_t)r->first_page * HS_PAGE);
}

/* The window page of [phys, phys + size) in the mirrored range; HS_SPACE_PAGES if it is not all there. */
static unsigned mirror_page(uintptr_t phys, size_t size)
{
	if (phys < HS_MIRROR_PHYS || size > (size_t)HS_MIRROR_PAGES * HS_PAGE ||
	    phys - HS_MIRROR_PHYS > (uintptr_t)HS_MIRROR_PAGES * HS_PAGE - size)
		return HS_SPACE_PAGES;
	return (unsigned)((phys - HS_MIRROR_PHYS) / HS_PAGE);
}

/* Region containing physical address phys, or NULL. */
static struct hs_region *region_at(uintptr_t phys)
{
	struct hs_region *last = space.last;

	if (last && phys >= last->cfg.phys && phys - last->cfg.phys < last->cfg.size)
		return last;
	for (unsigned i = 0; i < space.nregions; i++) {
		struct hs_region *r = space.regions[i];

		if (phys >= r->cfg.phys && phys - r->cfg.phys < r->cfg.size) {
			space.last = r;
			return r;
		}
	}
	return NULL;
}

struct hs_region *hs_region_find(uintptr_t phys)
{
	return region_at(phys);
}

struct hs_region *hs_region_by_name(const char *name)
{
	for (unsigned i = 0; i < space.nregions; i++)
		if (strcmp(space.regions[i]->cfg.name, name) == 0)
			return space.regions[i];
	return NULL;
}

const char *hs_region_name(const struct hs_region *r)
{
	return r ? r->cfg.name : "(none)";
}

uintptr_t hs_region_phys(const struct hs_region *r)
{
	return r ? r->cfg.phys : 0;
}

void *hs_region_ctx(const struct hs_region *r)
{
	return r ? r->cfg.ctx : NULL;
}

volatile void *hs_region_window(uintptr_t phys)
{
	struct hs_region *r = region_at(phys);

	if (!r)
		return NULL;
	return space.base + (size_t)r->first_page * HS_PAGE + (phys - r->cfg.phys);
}

/* Declaration check failure: reports and returns false. */
static bool decl_bug(const struct hs_region_cfg *cfg, const struct hs_reg *reg, const char *why)
{
	rtos_host_bug("host_sim", "region %s: register %s: %s", cfg->name ? cfg->name : "(unnamed)",
		      reg && reg->name ? reg->name : "(table)", why);
	return false;
}

/* Marks the bytes of element e in map; false if another element is there. */
static bool map_elem(int16_t *map, const struct hs_region *r, const struct hs_elem *e, int16_t idx)
{
	for (unsigned b = 0; b < e->width; b++) {
		uint32_t off = e->offset + b;
		/* Only the start byte maps to the element; the other bytes are claimed
		 * with a marker so overlaps are found and a narrow access finds its byte lane. */
		int16_t want = b == 0 ? idx : (int16_t)(-2 - idx);

		if (map[off] != HS_NO_ELEM)
			return false;
		map[off] = want;
	}
	(void)r;
	return true;
}

static uint32_t route_read_plain(const struct rtos_host_mmio_route *base);
static uint32_t route_read_after(const struct rtos_host_mmio_route *base);
static uint32_t route_read_hooked(const struct rtos_host_mmio_route *base);
static uint32_t route_read_hooked0(const struct rtos_host_mmio_route *base);
static uint32_t route_read_hooked_after(const struct rtos_host_mmio_route *base);
static void route_write_any(const struct rtos_host_mmio_route *base, uint32_t data);
static void route_write_store0(const struct rtos_host_mmio_route *base, uint32_t data);
static void route_write_store0_hooked(const struct rtos_host_mmio_route *base, uint32_t data);
static void route_write_log(void *ctx, const struct hs_access *a, uint32_t old, uint32_t now, uint32_t written);

/* Sets a route's log flag and what its access does: for a read, the read
 * function (something follows taking the value if a clear-on-read clears
 * bits or the access is logged), for a write the hook it calls. */
static void route_set_logged(struct hs_route *rt, bool logged)
{
	bool after_read = rt->bits != 0 || logged;
	/* the register's direct accesses serve its unlogged whole-register 32-bit accesses */
	bool direct = !logged && rt->acc.width == 4U && rt->shift == 0U;

	rt->logged = logged;
	if (rt->acc.write) {
		/* a plain store (read-write or write-only: keep = ~set, clear = 0) at byte lane 0 has its own */
		bool store0 = rt->shift == 0U && rt->clear == 0U && rt->keep == ~rt->set;

		rt->after_write = logged ? route_write_log : rt->e->after_write;
		if (direct && rt->e->reg->write_direct)
			rt->head.base.write = rt->e->reg->write_direct;
		else if (!store0)
			rt->head.base.write = route_write_any;
		else
			rt->head.base.write = rt->after_write ? route_write_store0_hooked : route_write_store0;
	} else if (direct && !after_read && rt->e->reg->read_direct)
		rt->head.base.read = rt->e->reg->read_direct;
	else if (rt->before_read && after_read)
		rt->head.base.read = route_read_hooked_after;
	else if (rt->before_read)
		rt->head.base.read = rt->shift == 0U ? route_read_hooked0 : route_read_hooked;
	else
		rt->head.base.read = after_read ? route_read_after : route_read_plain;
}

/* The masks of route_write for kind k driving bits. */
static void route_set_kind(struct hs_route *rt, enum hs_reg_kind k, uint32_t bits)
{
	rt->keep = k == HS_W1S || k == HS_W1C ? 0xFFFFFFFFU : ~bits;
	rt->clear = k == HS_W1C ? bits : 0U;
	rt->set = k == HS_W1C ? 0U : bits;
}

/* The narrowest width an element allows (its widths hold the width bits, HS_Wn == n). */
static unsigned elem_min_width(const struct hs_elem *e)
{
	return e->widths & (0U - e->widths);
}

/* Builds the routes of every element of r in the directions its kind allows
 * (after the aliases are resolved: a route holds the value's address). */
static bool region_build_routes(struct hs_region *r)
{
	unsigned n = 0;
	struct hs_route *rt;

	for (unsigned i = 0; i < r->nelems; i++) {
		const struct hs_elem *e = &r->elems[i];

		n += ((unsigned)kind_readable(e->kind) + (unsigned)kind_writable(e->kind)) *
		     route_count(e->width, elem_min_width(e));
	}
	r->routes = calloc(n ? n : 1U, sizeof(*r->routes));
	if (!r->routes)
		return decl_bug(&r->cfg, NULL, "out of memory");
	r->nroutes = n;
	rt = r->routes;
	for (unsigned i = 0; i < r->nelems; i++) {
		struct hs_elem *e = &r->elems[i];

		for (unsigned write = 0; write < 2U; write++) {
			if (!(write ? kind_writable(e->kind) : kind_readable(e->kind)))
				continue;
			e->routes[write] = rt;
			/* in route_index's order */
			for (unsigned width = e->width; width >= elem_min_width(e); width /= 2U) {
				for (unsigned lane = 0; lane < e->width; lane += width, rt++) {
					uint32_t lane_bits = e->mask & (width_mask(width) << (8U * lane));

					*rt = (struct hs_route){
						.head = { .ctx = r->cfg.ctx, .value = e->value },
						.before_read = write ? NULL : e->before_read,
						.wmask = width_mask(width),
						.bits = write || e->kind == HS_COR ? lane_bits : 0U,
						.shift = (uint8_t)(8U * lane),
						.acc = { e->reg, e->index, e->offset, width, write != 0, lane },
						.r = r,
						.e = e,
						.phys = r->cfg.phys + e->offset + lane,
					};
					if (write)
						route_set_kind(rt, (enum hs_reg_kind)e->kind, lane_bits);
					route_set_logged(rt, r->logged);
				}
			}
		}
	}
	return true;
}

/* Builds the flattened element table of a region; false after a bug report. */
static bool region_build(struct hs_region *r)
{
	const struct hs_region_cfg *cfg = &r->cfg;
	unsigned n = 0;

	for (unsigned i = 0; i < cfg->nregs; i++)
		n += cfg->regs[i].count ? cfg->regs[i].count : 1U;
	if (n > 30000U)
		return decl_bug(cfg, NULL, "too many registers");
	r->map_len = 0;
	for (unsigned i = 0; i < cfg->nregs; i++) {
		const struct hs_reg *reg = &cfg->regs[i];
		uint64_t width = reg->width ? reg->width : 4U;
		uint64_t count = reg->count ? reg->count : 1U;
		uint64_t end = (uint64_t)reg->offset + (count - 1U) * (reg->stride ? reg->stride : width) + width;

		if (end > r->map_len)
			r->map_len = end < cfg->size ? (uint32_t)end : cfg->size;
	}
	r->elems = calloc(n ? n : 1, sizeof(*r->elems));
	r->names = calloc(n ? n : 1, sizeof(*r->names));
	r->values = calloc(n ? n : 1, sizeof(*r->values));
	r->rd_map = malloc((r->map_len ? r->map_len : 1U) * sizeof(int16_t));
	r->wr_map = malloc((r->map_len ? r->map_len : 1U) * sizeof(int16_t));
	r->any_map = malloc((r->map_len ? r->map_len : 1U) * sizeof(int16_t));
	if (!r->elems || !r->names || !r->values || !r->rd_map || !r->wr_map || !r->any_map)
		return decl_bug(cfg, NULL, "out of memory");
	for (uint32_t i = 0; i < r->map_len; i++)
		r->rd_map[i] = r->wr_map[i] = HS_NO_ELEM;

	n = 0;
	for (unsigned i = 0; i < cfg->nregs; i++) {
		const struct hs_reg *reg = &cfg->regs[i];
		unsigned width = reg->width ? reg->width : 4U;
		unsigned count = reg->count ? reg->count : 1U;
		unsigned stride = reg->stride ? reg->stride : width;

		if (!reg->name)
			return decl_bug(cfg, reg, "no name");
		if (!width_bit(width))
			return decl_bug(cfg, reg, "width must be 1, 2 or 4");
		if (reg->offset % width)
			return decl_bug(cfg, reg, "offset not aligned to its width");
		if ((reg->widths & ~(HS_W8 | HS_W16 | HS_W32)) || (reg->widths & ~((width_bit(width) << 1) - 1U)))
			return decl_bug(cfg, reg, "allowed widths wider than the register");
		if ((unsigned)reg->kind > HS_COR)
			return decl_bug(cfg, reg, "unknown kind");
		if ((uint64_t)reg->offset + (uint64_t)(count - 1U) * stride + width > cfg->size)
			return decl_bug(cfg, reg, "beyond the region's size");
		if (stride < width)
			return decl_bug(cfg, reg, "stride smaller than width");
		for (unsigned k = 0; k < count; k++, n++) {
			struct hs_elem *e = &r->elems[n];

			e->reg = reg;
			e->before_read = reg->before_read;
			e->after_write = reg->after_write;
			e->kind = (uint8_t)reg->kind;
			e->index = (uint16_t)k;
			e->width = (uint8_t)width;
			e->widths = (uint8_t)(reg->widths | width_bit(width));
			e->ok_widths = reg->kind == HS_RSVD ? 0U : e->widths;
			e->offset = reg->offset + k * stride;
			e->mask = (reg->mask ? reg->mask : 0xFFFFFFFFU) & width_mask(width);
			e->value = &r->values[n];
			r->values[n] = reg->reset & width_mask(width);
			if (reg->count)
				snprintf(r->names[n], sizeof(r->names[n]), "%s[%u]", reg->name, k);
			else
				snprintf(r->names[n], sizeof(r->names[n]), "%s", reg->name);
			if (kind_readable(reg->kind) && !map_elem(r->rd_map, r, e, (int16_t)n))
				return decl_bug(cfg, reg, "overlaps another readable register");
			if (kind_writable(reg->kind) && !map_elem(r->wr_map, r, e, (int16_t)n))
				return decl_bug(cfg, reg, "overlaps another writable register");
		}
	}
	r->nelems = n;

	/* Resolve aliases: the element shares the stored value of the target's element. */
	for (unsigned i = 0; i < r->nelems; i++) {
		struct hs_elem *e = &r->elems[i];
		const struct hs_elem *t = NULL;
		unsigned tcount = 0;

		if (!e->reg->alias)
			continue;
		for (unsigned j = 0; j < r->nelems; j++) {
			if (strcmp(r->elems[j].reg->name, e->reg->alias) == 0 && !r->elems[j].reg->alias) {
				if (!t || r->elems[j].index == e->index)
					t = &r->elems[j];
				tcount = r->elems[j].reg->count ? r->elems[j].reg->count : 1U;
			}
		}
		if (!t)
			return decl_bug(cfg, e->reg, "alias names no (non-alias) register of the region");
		if (tcount != 1U && t->index != e->index)
			return decl_bug(cfg, e->reg, "alias has a different element count");
		e->value = t->value;
	}
	for (uint32_t off = 0; off < r->map_len; off++)
		r->any_map[off] = r->rd_map[off] >= 0 ? r->rd_map[off] : r->wr_map[off] >= 0 ? r->wr_map[off] : HS_NO_ELEM;
	return region_build_routes(r);
}

struct hs_region *hs_region_add(const struct hs_region_cfg *cfg)
{
	struct hs_region *r;
	unsigned pages;

	if (!space.base) {
		rtos_host_bug("host_sim", "hs_region_add(%s) without a board (call hs_board_init first)",
			      cfg && cfg->name ? cfg->name : "?");
		return NULL;
	}
	if (!cfg || !cfg->name || !cfg->regs || !cfg->size || cfg->size % HS_PAGE || cfg->phys % HS_PAGE) {
		rtos_host_bug("host_sim", "hs_region_add: bad configuration %s (name, table, page-aligned base and size required)",
			      cfg && cfg->name ? cfg->name : "(unnamed)");
		return NULL;
	}
	for (unsigned i = 0; i < space.nregions; i++) {
		const struct hs_region *o = space.regions[i];

		if (cfg->phys < o->cfg.phys + o->cfg.size && o->cfg.phys < cfg->phys + cfg->size) {
			rtos_host_bug("host_sim", "region %s at 0x%08" PRIxPTR " overlaps region %s",
				      cfg->name, cfg->phys, o->cfg.name);
			return NULL;
		}
		if (strcmp(o->cfg.name, cfg->name) == 0) {
			rtos_host_bug("host_sim", "region name %s used twice", cfg->name);
			return NULL;
		}
	}
	pages = cfg->size / HS_PAGE;
	if (space.nregions == HS_MAX_REGIONS ||
	    (mirror_page(cfg->phys, cfg->size) == HS_SPACE_PAGES && space.next_page + pages > HS_SPACE_PAGES)) {
		rtos_host_bug("host_sim", "region %s: no room left in the window space", cfg->name);
		return NULL;
	}
	r = calloc(1, sizeof(*r));
	if (!r) {
		rtos_host_bug("host_sim", "region %s: out of memory", cfg->name);
		return NULL;
	}
	r->cfg = *cfg;
	r->power_live = power_live_flag(cfg->power);
	if (!region_build(r)) {
		region_free(r);
		return NULL;
	}
	r->first_page = mirror_page(cfg->phys, cfg->size);
	if (r->first_page == HS_SPACE_PAGES) {
		r->first_page = space.next_page;
		space.next_page += pages;
	}
	for (unsigned p = 0; p < pages; p++)
		space.page_owner[r->first_page + p] = r;
	space.regions[space.nregions++] = r;
	hs_space_set_reglog(space.log_filter, space.log_out);
	return r;
}

/* Name of element e of region r ("CMR[3]"). */
static const char *elem_name(const struct hs_region *r, const struct hs_elem *e)
{
	return r->names[e - r->elems];
}

/* Element starting at offset for reading (or writing); NULL if none. */
static inline struct hs_elem *elem_at(const struct hs_region *r, uint32_t offset, bool write)
{
	int16_t i;

	if (offset >= r->map_len)
		return NULL;
	i = write ? r->wr_map[offset] : r->rd_map[offset];
	return i >= 0 ? &r->elems[i] : NULL;
}

/*
 * Element whose bytes include offset in one direction, with the byte lane of
 * offset in it (*lane, 0 at its start): a narrow access to a wider register
 * at a byte lane, as the AM1808's 32-bit peripheral bus carries it (byte
 * enables select the lanes); NULL where no element of that direction is.
 */
static inline struct hs_elem *elem_lane_at(const struct hs_region *r, uint32_t offset, bool write, unsigned *lane)
{
	int16_t i;
	struct hs_elem *e;

	*lane = 0;
	if (offset >= r->map_len)
		return NULL;
	i = write ? r->wr_map[offset] : r->rd_map[offset];
	if (i >= 0)
		return &r->elems[i];
	if (i == HS_NO_ELEM)
		return NULL;
	e = &r->elems[-2 - i];
	*lane = offset - e->offset;
	return e;
}

/* Element at offset in either direction (the readable one first), for the
 * model-side accessors; NULL after a bug report. */
static inline struct hs_elem *elem_any(const struct hs_region *r, uint32_t offset, const char *what)
{
	int16_t i;

	if (r && offset < r->map_len && (i = r->any_map[offset]) >= 0)
		return &r->elems[i];
	if (!r)
		rtos_host_bug("host_sim", "%s: NULL region", what);
	else
		rtos_host_bug("host_sim", "%s: no register at %s+0x%03" PRIx32, what, r->cfg.name, offset);
	return NULL;
}

/* The widest of 4, 2, 1 bytes that is at most n and to which addr is aligned. */
static unsigned piece_width(uintptr_t addr, unsigned n)
{
	unsigned w = n >= 4U ? 4U : n >= 2U ? 2U : 1U;

	while (w > 1U && (addr & (w - 1U)))
		w /= 2U;
	return w;
}

unsigned hs_space_split(uintptr_t addr, unsigned width, bool write, struct hs_piece *pieces)
{
	unsigned count = 0, done = 0;

	while (done < width) {
		uintptr_t a = addr + done, phys = hs_space_to_phys(a);
		struct hs_region *r = phys ? region_at(phys) : NULL;
		struct hs_elem *e = NULL;
		unsigned lane = 0, w, n = width - done;

		if (r && phys - r->cfg.phys < r->map_len)
			e = elem_lane_at(r, (uint32_t)(phys - r->cfg.phys), write, &lane);
		if (e && done == 0 && lane + width <= e->width) {
			pieces[0] = (struct hs_piece){ .addr = addr, .width = width };   /* inside one register */
			return 1;
		}
		w = piece_width(a, e && e->width - lane < n ? e->width - lane : n);
		pieces[count++] = (struct hs_piece){ .addr = a, .width = w };
		done += w;
	}
	return count;
}

uint32_t hs_reg_get(const struct hs_region *r, uint32_t offset)
{
	struct hs_elem *e = elem_any(r, offset, "hs_reg_get");

	return e ? *e->value : 0U;
}

void hs_reg_set(struct hs_region *r, uint32_t offset, uint32_t value)
{
	struct hs_elem *e = elem_any(r, offset, "hs_reg_set");

	if (e)
		*e->value = value & width_mask(e->width);
}

void hs_reg_update(struct hs_region *r, uint32_t offset, uint32_t clear, uint32_t set)
{
	struct hs_elem *e = elem_any(r, offset, "hs_reg_update");

	if (e)
		*e->value = ((*e->value & ~clear) | set) & width_mask(e->width);
}

uint32_t *hs_reg_value_ptr(struct hs_region *r, uint32_t offset)
{
	struct hs_elem *e = elem_any(r, offset, "hs_reg_value_ptr");

	return e ? e->value : NULL;
}

void hs_region_reset(struct hs_region *r)
{
	for (unsigned i = 0; r && i < r->nelems; i++)
		r->values[i] = r->elems[i].reg->reset & width_mask(r->elems[i].width);
}

/* ---- The access path ---- */

/* Writes one register-log line if the region is logged. */
static void reglog(const struct hs_region *r, const struct hs_elem *e, uintptr_t phys,
		   bool write, unsigned width, uint32_t value)
{
	char line[160];

	if (!space.logging || !r->logged)
		return;
	snprintf(line, sizeof(line), "%c%u %s.%s @0x%08" PRIxPTR " = 0x%0*" PRIx32,
		 write ? 'W' : 'R', width, r->cfg.name, e ? elem_name(r, e) : "?", phys,
		 (int)(2U * width), value);
	if (space.log_out)
		fprintf(space.log_out, "%" PRIu64 " %s\n", rtos_host_now(), line);
	else
		rtos_host_trace("mmio", "%s", line);
}

/* The access path compares an element's allowed widths with the access width itself. */
_Static_assert(HS_W8 == 1U && HS_W16 == 2U && HS_W32 == 4U, "HS_Wn bits are the widths in bytes");

/* Reports a CPU access to no region, or to one whose PSC module is not enabled. */
static void region_bug(const struct hs_region *r, uintptr_t phys, unsigned width, bool write, uint32_t value)
{
	char val[32] = "";

	if (write)
		snprintf(val, sizeof(val), " of 0x%0*" PRIx32, (int)(2U * width), value);
	if (!r) {
		rtos_host_bug("host_sim", "%s of %u bytes%s at 0x%08" PRIxPTR ": no modelled device there",
			      write ? "write" : "read", width, val, phys);
		return;
	}
	rtos_host_bug("host_sim", "%s of %u bytes%s at 0x%08" PRIxPTR " (%s+0x%03" PRIxPTR ")"
		      ": %s is not powered (PSC%u module %u is %s, not Enable)",
		      write ? "write" : "read", width, val, phys,
		      r->cfg.name, phys - r->cfg.phys, r->cfg.name,
		      (r->cfg.power >> 8) - 1U, r->cfg.power & 0xFFU,
		      power_ctl != NULL ? power_ctl->state_name(r->cfg.power) : "absent");
}

/* Reports a CPU access at offset off of r that found no usable element e
 * (none in that direction, a width it does not allow, or reserved). */
static void elem_bug(const struct hs_region *r, const struct hs_elem *e, uint32_t off, unsigned width,
		     bool write, uint32_t value)
{
	uintptr_t phys = r->cfg.phys + off;
	const struct hs_elem *other;
	char val[32] = "";

	if (write)
		snprintf(val, sizeof(val), " of 0x%0*" PRIx32, (int)(2U * width), value);
	if (!e) {
		other = elem_at(r, off, !write);
		if (other)
			rtos_host_bug("host_sim", "%s of %u bytes%s at 0x%08" PRIxPTR ": %s.%s is %s",
				      write ? "write" : "read", width, val, phys, r->cfg.name, elem_name(r, other),
				      kind_names[other->kind]);
		else
			rtos_host_bug("host_sim", "%s of %u bytes%s at 0x%08" PRIxPTR " (%s+0x%03" PRIx32
				      "): no register there", write ? "write" : "read", width, val, phys,
				      r->cfg.name, off);
	} else if (off - e->offset + width > e->width) {
		rtos_host_bug("host_sim", "%s of %u bytes%s at 0x%08" PRIxPTR ": crosses the end of %s.%s, a %u-byte register",
			      write ? "write" : "read", width, val, phys, r->cfg.name, elem_name(r, e), e->width);
	} else if (!(e->widths & width)) {
		rtos_host_bug("host_sim", "%s of %u bytes%s at 0x%08" PRIxPTR ": %s.%s is a %u-byte register",
			      write ? "write" : "read", width, val, phys, r->cfg.name, elem_name(r, e), e->width);
	} else {
		rtos_host_bug("host_sim", "%s of %u bytes%s at 0x%08" PRIxPTR ": %s.%s is reserved",
			      write ? "write" : "read", width, val, phys, r->cfg.name, elem_name(r, e));
	}
}

/* Spends the per-access CPU time (events and interrupts may run meanwhile). */
static inline void access_cost(void)
{
	if (space.access_ns)
		rtos_host_consume(space.access_ns);
}

/* The element a CPU access of width bytes at offset off of r reaches, and
 * its byte lane; NULL after a bug report (unpowered, no such register, a
 * width it does not allow). */
static inline __attribute__((always_inline)) struct hs_elem *access_checked(struct hs_region *r, uint32_t off,
									     unsigned width, bool write, uint32_t value,
									     unsigned *lane)
{
	struct hs_elem *e;

	if (!*r->power_live) {
		region_bug(r, r->cfg.phys + off, width, write, value);
		return NULL;
	}
	if ((e = elem_lane_at(r, off, write, lane)) == NULL || !(e->ok_widths & width) || *lane + width > e->width) {
		elem_bug(r, e, off, width, write, value);
		return NULL;
	}
	return e;
}

/* An accessor read's result: the access time it costs, unspent, and the value. */
static inline uint64_t cost_value(uint32_t ns, uint32_t v)
{
	return (uint64_t)ns << 32 | v;
}

/* The route whose base is base (its first member). */
static inline const struct hs_route *route_of(const struct rtos_host_mmio_route *base)
{
	return (const struct hs_route *)(const void *)base;
}

/* What a read through route rt returns, taken after its hook ran. */
static inline uint32_t route_value(const struct hs_route *rt)
{
	return (*rt->head.value >> rt->shift) & rt->wmask;
}

/* A read through a route with nothing before or after taking the value. */
static uint32_t route_read_plain(const struct rtos_host_mmio_route *base)
{
	return route_value(route_of(base));
}

/* A read through a route that has something after taking the value: clears
 * the clear-on-read bits, logs. */
static uint32_t route_read_after(const struct rtos_host_mmio_route *base)
{
	const struct hs_route *rt = route_of(base);
	uint32_t v = route_value(rt);

	*rt->head.value &= ~rt->bits;
	if (rt->logged)
		reglog(rt->r, rt->e, rt->phys, false, rt->acc.width, v);
	return v;
}

/* A read through a route with a hook and nothing after. */
static uint32_t route_read_hooked(const struct rtos_host_mmio_route *base)
{
	const struct hs_route *rt = route_of(base);

	rt->before_read(rt->head.ctx, &rt->acc, rt->head.value);
	return route_value(rt);
}

/* route_read_hooked for a route at byte lane 0 (the common case: a driver
 * reads its registers whole), whose value needs no shift. */
static uint32_t route_read_hooked0(const struct rtos_host_mmio_route *base)
{
	const struct hs_route *rt = route_of(base);

	rt->before_read(rt->head.ctx, &rt->acc, rt->head.value);
	return *rt->head.value & rt->wmask;
}

/* A read through a route with a hook and something after. */
static uint32_t route_read_hooked_after(const struct rtos_host_mmio_route *base)
{
	const struct hs_route *rt = route_of(base);

	rt->before_read(rt->head.ctx, &rt->acc, rt->head.value);
	return route_read_after(base);
}

/* A checked read through route rt: hooked, clear-on-read applied, logged; the
 * value (the access time is the caller's to spend).  One indirect call: the
 * route chose its read function when it was built or its log flag changed, so
 * the route cache's hit tests nothing more. */
static inline uint32_t route_read(const struct hs_route *rt)
{
	return rt->head.base.read(&rt->head.base);
}

/* One CPU read of width bytes (1, 2 or 4) at offset off of r: checked, hooked,
 * logged, and it costs the access time; 0 after a bug report. */
static inline __attribute__((always_inline)) uint32_t region_read(struct hs_region *r, uint32_t off, unsigned width)
{
	unsigned lane;
	struct hs_elem *e = access_checked(r, off, width, false, 0, &lane);
	uint32_t v = 0;

	if (e)
		v = route_read(elem_route(e, false, width, lane));
	access_cost();
	return v;
}

/* The route whose hooks are told a (a route's acc is inside it). */
static inline const struct hs_route *acc_route(const struct hs_access *a)
{
	return (const struct hs_route *)(const void *)((const char *)a - offsetof(struct hs_route, acc));
}

/* The after-write hook of a logged write route (see route_set_logged): the
 * log line of the data written, then the element's own hook. */
static void route_write_log(void *ctx, const struct hs_access *a, uint32_t old, uint32_t now, uint32_t written)
{
	const struct hs_route *rt = acc_route(a);
	hs_after_write_fn hook = rt->e->after_write;

	reglog(rt->r, rt->e, rt->phys, true, a->width, written >> rt->shift);
	if (hook)
		hook(ctx, a, old, now, written);
}

/* A write of data through a route of any kind and lane (see route_write). */
static void route_write_any(const struct rtos_host_mmio_route *base, uint32_t data)
{
	const struct hs_route *rt = route_of(base);
	uint32_t old = *rt->head.value;
	uint32_t value = (data & rt->wmask) << rt->shift;     /* the byte lanes the access drives */
	uint32_t nv = (old & rt->keep & ~(value & rt->clear)) | (value & rt->set);

	*rt->head.value = nv;
	if (rt->after_write)
		rt->after_write(rt->head.ctx, &rt->acc, old, nv, value);
}

/* route_write_any for a plain store at lane 0 without a hook: the mask bits
 * take data's (bits lies within the width, so data needs no masking). */
static void route_write_store0(const struct rtos_host_mmio_route *base, uint32_t data)
{
	const struct hs_route *rt = route_of(base);
	uint32_t old = *rt->head.value;

	*rt->head.value = old ^ ((old ^ data) & rt->bits);
}

/* route_write_store0 with a hook, which is told data masked to the width. */
static void route_write_store0_hooked(const struct rtos_host_mmio_route *base, uint32_t data)
{
	const struct hs_route *rt = route_of(base);
	uint32_t old = *rt->head.value;
	uint32_t value = data & rt->wmask;
	uint32_t nv = old ^ ((old ^ value) & rt->bits);

	*rt->head.value = nv;
	rt->after_write(rt->head.ctx, &rt->acc, old, nv, value);
}

/* A checked write of data through route rt: applied with the register's
 * kind, logged, hooked (the access time is the caller's to spend). */
static inline void route_write(const struct hs_route *rt, uint32_t data)
{
	rt->head.base.write(&rt->head.base, data);
}

/* One CPU write of width bytes (1, 2 or 4; value already masked to it) at
 * offset off of r: checked, applied with the register's kind, logged, hooked,
 * and it costs the access time. */
static inline __attribute__((always_inline)) void region_write(struct hs_region *r, uint32_t off, unsigned width,
								uint32_t value)
{
	unsigned lane;
	struct hs_elem *e = access_checked(r, off, width, true, value, &lane);

	if (e)
		route_write(elem_route(e, true, width, lane), value);
	access_cost();
}

uint32_t hs_cpu_read(uintptr_t phys, unsigned width)
{
	struct hs_region *r;

	if (!width_bit(width)) {
		rtos_host_bug("host_sim", "read of %u bytes at 0x%08" PRIxPTR ": unsupported width", width, phys);
		return 0;
	}
	r = region_at(phys);
	if (r)
		return region_read(r, (uint32_t)(phys - r->cfg.phys), width);
	region_bug(NULL, phys, width, false, 0);
	access_cost();
	return 0;
}

void hs_cpu_write(uintptr_t phys, unsigned width, uint32_t value)
{
	struct hs_region *r;

	if (!width_bit(width)) {
		rtos_host_bug("host_sim", "write of %u bytes at 0x%08" PRIxPTR ": unsupported width", width, phys);
		return;
	}
	value &= width_mask(width);
	r = region_at(phys);
	if (r) {
		region_write(r, (uint32_t)(phys - r->cfg.phys), width, value);
		return;
	}
	region_bug(NULL, phys, width, true, value);
	access_cost();
}

void hs_access_stall_until(uint64_t t_ns)
{
	uint64_t now = rtos_host_now();

	if (t_ns > now)
		rtos_host_consume(t_ns - now);
}

/* ---- rtos_stub's MMIO handler ---- */

static bool mmio_claims(const volatile void *addr, void *ctx)
{
	(void)ctx;
	return hs_space_claims((uintptr_t)addr);
}

/* The region whose window holds addr, and addr's offset in it; NULL outside every region. */
static inline struct hs_region *window_region(uintptr_t addr, uint32_t *off)
{
	uintptr_t rel = addr - (uintptr_t)space.base;
	struct hs_region *r;

	if (rel >= (uintptr_t)HS_SPACE_PAGES * HS_PAGE || (r = space.page_owner[rel / HS_PAGE]) == NULL)
		return NULL;
	*off = (uint32_t)(rel - (uintptr_t)r->first_page * HS_PAGE);
	return r;
}

/* One accessor read of width bytes at window address addr that the route
 * cache did not know: the access time it costs, unspent, and the value (0
 * after a bug report; see cost_value).  A checked access's route is cached. */
static uint64_t mmio_read_timed(const volatile void *addr, uint_t width, void *ctx)
{
	uint32_t off;
	unsigned lane;
	struct hs_region *r = window_region((uintptr_t)addr, &off);
	struct hs_elem *e;

	(void)ctx;
	if (!r) {
		rtos_host_bug("host_sim", "read of %u bytes at window address %p (physical 0x%08" PRIxPTR
			      "): no modelled device there", width, (const void *)addr, hs_space_to_phys((uintptr_t)addr));
		return cost_value(0, 0);
	}
	if (!width_bit(width)) {
		rtos_host_bug("host_sim", "read of %u bytes at 0x%08" PRIxPTR ": unsupported width", width,
			      r->cfg.phys + off);
		return cost_value(0, 0);
	}
	e = access_checked(r, off, width, false, 0, &lane);
	if (e) {
		const struct hs_route *rt = elem_route(e, false, width, lane);

		rtos_host_mmio_route_cache_fill(false, addr, width, &rt->head.base);
		return cost_value(space.access_ns, route_read(rt));
	}
	return cost_value(space.access_ns, 0);
}

/* One accessor write of width bytes at window address addr that the route
 * cache did not know; returns the access time it costs, unspent.  A checked
 * access's route is cached. */
static uint32_t mmio_write_timed(volatile void *addr, uint_t width, uint32_t data, void *ctx)
{
	uint32_t off;
	unsigned lane;
	struct hs_region *r = window_region((uintptr_t)addr, &off);
	struct hs_elem *e;

	(void)ctx;
	if (!r) {
		rtos_host_bug("host_sim", "write of %u bytes (0x%" PRIx32 ") at window address %p (physical 0x%08"
			      PRIxPTR "): no modelled device there", width, data, (void *)addr,
			      hs_space_to_phys((uintptr_t)addr));
		return 0;
	}
	if (!width_bit(width)) {
		rtos_host_bug("host_sim", "write of %u bytes at 0x%08" PRIxPTR ": unsupported width", width,
			      r->cfg.phys + off);
		return 0;
	}
	data &= width_mask(width);
	e = access_checked(r, off, width, true, data, &lane);
	if (e) {
		const struct hs_route *rt = elem_route(e, true, width, lane);

		rtos_host_mmio_route_cache_fill(true, addr, width, &rt->head.base);
		route_write(rt, data);
	}
	return space.access_ns;
}

/* The untimed read the handler must have: the timed one, then its cost spent. */
static uint32_t mmio_read(const volatile void *addr, uint_t width, void *ctx)
{
	uint64_t cv = mmio_read_timed(addr, width, ctx);

	if (cv >> 32)
		rtos_host_consume(cv >> 32);
	return (uint32_t)cv;
}

/* The untimed write the handler must have: the timed one, then its cost spent. */
static void mmio_write(volatile void *addr, uint_t width, uint32_t data, void *ctx)
{
	uint32_t ns = mmio_write_timed(addr, width, data, ctx);

	if (ns)
		rtos_host_consume(ns);
}

static void *mmio_map(uintptr_t phys, SIZE size, void *ctx)
{
	struct hs_region *r = region_at(phys);

	(void)ctx;
	if (size != 0 && mirror_page(phys, size) != HS_SPACE_PAGES) {
		/* Any range in the mirror that touches a modelled device: one window, as
		 * Linux's ioremap; a range with none at all is almost surely a wrong address. */
		for (unsigned p = mirror_page(phys, size); p <= mirror_page(phys + size - 1U, 1); p++)
			if (space.page_owner[p])
				return (void *)(space.base + (phys - HS_MIRROR_PHYS));
	}
	if (!r || size == 0 || size > r->cfg.size - (phys - r->cfg.phys)) {
		rtos_host_trace("host_sim", "map 0x%08" PRIxPTR "+0x%zx: no modelled region covers it", phys, (size_t)size);
		return NULL;
	}
	return (void *)(space.base + (size_t)r->first_page * HS_PAGE + (phys - r->cfg.phys));
}

static const struct rtos_host_mmio_ops space_mmio_ops = {
	.claims = mmio_claims,
	.read = mmio_read,
	.write = mmio_write,
	.map = mmio_map,
	.ctx = NULL,
};

void hs_space_install_handler(void)
{
	rtos_host_set_mmio_handler(&space_mmio_ops);
	rtos_host_set_mmio_window((uintptr_t)space.base, space.base ? (uintptr_t)HS_SPACE_PAGES * HS_PAGE : 0);
	rtos_host_set_mmio_timed(mmio_read_timed, mmio_write_timed);
	if (space.base)
		rtos_host_set_mmio_route_cache(space.access_ns);
}

void hs_space_remove_handler(void)
{
	rtos_host_set_mmio_handler(NULL);
}

/* true if name is in the comma-separated filter ("*" matches all). */
static bool filter_has(const char *filter, const char *name)
{
	size_t n = strlen(name);

	if (strcmp(filter, "*") == 0)
		return true;
	for (const char *p = filter; *p;) {
		const char *end = strchr(p, ',');
		size_t len = end ? (size_t)(end - p) : strlen(p);

		if (len == n && strncmp(p, name, n) == 0)
			return true;
		if (!end)
			break;
		p = end + 1;
	}
	return false;
}

void hs_space_set_reglog(const char *filter, FILE *out)
{
	if (filter != space.log_filter) {
		char *copy = filter ? strdup(filter) : NULL;

		free(space.log_filter);
		space.log_filter = copy;
	}
	space.log_out = out;
	space.logging = space.log_filter != NULL;
	wcache_clear();
	for (unsigned i = 0; i < space.nregions; i++) {
		struct hs_region *r = space.regions[i];

		r->logged = space.logging && filter_has(space.log_filter, r->cfg.name);
		for (unsigned k = 0; k < r->nroutes; k++)
			route_set_logged(&r->routes[k], r->logged);
	}
}
