/*
 * test_route_cache.c — the accessors' route cache (rtos_host_set_mmio_route_cache):
 * an access the handler cached goes to its route and costs the cache's access
 * time; one of another width or direction, or at another address, goes to the
 * timed pair; bad widths and misaligned accesses are still reported however
 * the cache is filled; the cache refuses routes for accesses it must never
 * serve (outside the window, bad widths, misaligned, no function), ignores
 * fills while it is off, is emptied by rtos_host_mmio_route_cache_clear and
 * turned off by any change of the handler, its window or its timed pair; an
 * empty slot matches no access.
 */
#include <string.h>

#include "tap.h"
#include "kernel.h"
#include "sil.h"
#include "rtos_test.h"

#define ACCESS_NS 40U

static uint32_t regs[8];        /* the fake device's registers: the window */
static uint32_t outside[2];     /* plain memory */
static unsigned timed_reads, timed_writes, route_reads, route_writes;
static uint_t last_timed_width;

/* A register's route, either direction. */
struct reg_route {
	struct rtos_host_mmio_route base;
	uint32_t *reg;
};
static struct reg_route read_routes[8], write_routes[8];
static const struct reg_route no_read = { { NULL, NULL }, &regs[0] };

static uint32_t route_read(const struct rtos_host_mmio_route *rt)
{
	route_reads++;
	return *((const struct reg_route *)rt)->reg;
}

static void route_write(const struct rtos_host_mmio_route *rt, uint32_t data)
{
	route_writes++;
	*((const struct reg_route *)rt)->reg = data;
}

/* The register whose window address is addr (its first byte, any width). */
static unsigned reg_index(const volatile void *addr)
{
	return (unsigned)(((uintptr_t)addr - (uintptr_t)regs) / sizeof(regs[0]));
}

/* A timed read (the whole register, whatever the width), costing ACCESS_NS;
 * caches the route of a 4-byte access only. */
static uint64_t read_timed(const volatile void *addr, uint_t width, void *ctx)
{
	(void)ctx;
	timed_reads++;
	last_timed_width = width;
	if (width == 4U)
		rtos_host_mmio_route_cache_fill(false, addr, width, &read_routes[reg_index(addr)].base);
	return ((uint64_t)ACCESS_NS << 32) | regs[reg_index(addr)];
}

/* A timed write of the whole register, costing ACCESS_NS; caches its route. */
static uint32_t write_timed(volatile void *addr, uint_t width, uint32_t data, void *ctx)
{
	(void)ctx;
	timed_writes++;
	last_timed_width = width;
	if (width == 4U)
		rtos_host_mmio_route_cache_fill(true, addr, width, &write_routes[reg_index(addr)].base);
	regs[reg_index(addr)] = data;
	return ACCESS_NS;
}

static bool claims(const volatile void *addr, void *ctx)
{
	(void)ctx;
	return (uintptr_t)addr - (uintptr_t)regs < sizeof(regs);
}

static uint32_t read_untimed(const volatile void *addr, uint_t width, void *ctx)
{
	return (uint32_t)read_timed(addr, width, ctx);
}

static void write_untimed(volatile void *addr, uint_t width, uint32_t data, void *ctx)
{
	(void)write_timed(addr, width, data, ctx);
}

static const struct rtos_host_mmio_ops fake_device = {
	.claims = claims, .read = read_untimed, .write = write_untimed, .map = NULL, .ctx = NULL,
};

static const struct rtos_cfg cfg = { .name = "route_cache" };

/* Installs the fake device with its window and timed pair (the cache off). */
static void install(void)
{
	rtos_host_set_mmio_handler(&fake_device);
	rtos_host_set_mmio_window((uintptr_t)regs, sizeof(regs));
	rtos_host_set_mmio_timed(read_timed, write_timed);
}

static uint_t bugs_seen;

/* True if exactly one bug was reported since the last call, and its text has part. */
static bool one_bug(const char *part)
{
	uint_t before = bugs_seen;

	bugs_seen = rtos_host_bug_count();
	return bugs_seen == before + 1U && strstr(rtos_host_last_bug(), part) != NULL;
}

int main(void)
{
	uint64_t t;
	uint32_t v;

	tap_plan(21);
	for (unsigned i = 0; i < 8; i++) {
		read_routes[i] = (struct reg_route){ { route_read, NULL }, &regs[i] };
		write_routes[i] = (struct reg_route){ { NULL, route_write }, &regs[i] };
		regs[i] = 0x11111111U * i;
	}
	is_int(rtos_host_boot(&cfg), E_OK, "boot");
	rtos_host_expect_bugs(true);
	bugs_seen = rtos_host_bug_count();

	rtos_host_set_mmio_handler(&fake_device);
	ok((rtos_host_set_mmio_route_cache(ACCESS_NS), one_bug("without a window")),
	   "the cache needs a window and a timed pair");
	install();
	rtos_host_set_mmio_route_cache(ACCESS_NS);

	t = rtos_host_now();
	v = sil_rew_mem(&regs[3]);
	ok(v == 0x33333333U && timed_reads == 1 && route_reads == 0, "a first read takes the timed pair");
	v = sil_rew_mem(&regs[3]);
	ok(v == 0x33333333U && timed_reads == 1 && route_reads == 1, "the same read again takes its route");
	is_u64(rtos_host_now() - t, 2 * ACCESS_NS, "both cost the access time");

	v = sil_reh_mem((const uint16_t *)&regs[3]);
	ok(timed_reads == 2 && last_timed_width == 2 && route_reads == 1,
	   "a read of another width at the address takes the timed pair");
	sil_wrw_mem(&regs[3], 0xA5A5A5A5U);
	sil_wrw_mem(&regs[3], 0x5A5A5A5AU);
	ok(timed_writes == 1 && route_writes == 1 && regs[3] == 0x5A5A5A5AU && route_reads == 1,
	   "a write is cached apart from the reads: first the timed pair, then its route");
	v = sil_rew_mem(&regs[4]);
	ok(timed_reads == 3 && route_reads == 1 && v == 0x44444444U, "a read at another address takes the timed pair");

	ok((v = sil_host_read(&regs[3], 8U), one_bug("access width 8")) && v == 0,
	   "a bad width at a cached address is reported");
	ok((v = sil_host_read(&regs[3], 0U), one_bug("access width 0")) &&
	   (sil_host_write(&regs[3], 3U, 1U), one_bug("access width 3")),
	   "so are widths 0 and 3, reading or writing");
	ok((v = sil_host_read((const uint8_t *)&regs[3] + 2, 4U), one_bug("misaligned")) &&
	   (sil_host_write((uint8_t *)&regs[3] + 2, 4U, 1U), one_bug("misaligned")),
	   "and misaligned accesses next to a cached one");
	ok(regs[3] == 0x5A5A5A5AU && route_reads == 1 && route_writes == 1 && timed_reads == 3 && timed_writes == 1,
	   "none of them reached the device");

	ok((rtos_host_mmio_route_cache_fill(false, &outside[0], 4U, &read_routes[0].base), one_bug("not an access to cache")),
	   "a route outside the window is refused");
	ok((rtos_host_mmio_route_cache_fill(false, &regs[5], 3U, &read_routes[5].base), one_bug("not an access to cache")) &&
	   (rtos_host_mmio_route_cache_fill(true, (uint8_t *)&regs[5] + 1, 2U, &write_routes[5].base), one_bug("not an access to cache")),
	   "so is one of a bad width or misaligned");
	ok((rtos_host_mmio_route_cache_fill(false, &regs[5], 4U, NULL), one_bug("not an access to cache")) &&
	   (rtos_host_mmio_route_cache_fill(false, &regs[5], 4U, &no_read.base), one_bug("not an access to cache")) &&
	   (rtos_host_mmio_route_cache_fill(false, &regs[5], 4U, &write_routes[5].base), one_bug("not an access to cache")),
	   "and a missing route or one without the direction's function");
	outside[1] = 77U;
	ok(sil_rew_mem(&outside[1]) == 77U && route_reads == 1, "memory outside the window is still memory");

	rtos_host_mmio_route_cache_clear();
	(void)sil_rew_mem(&regs[3]);
	ok(timed_reads == 4 && route_reads == 1, "after a clear a cached access takes the timed pair again");
	ok((v = sil_host_read((const volatile void *)0, 0U), one_bug("access width 0")) &&
	   (v = sil_host_read((const volatile void *)1, 0U), one_bug("access width 0")),
	   "an empty slot matches no access (addresses 0 and 1, width 0)");

	rtos_host_set_mmio_timed(read_timed, write_timed);
	(void)sil_rew_mem(&regs[3]);
	(void)sil_rew_mem(&regs[3]);
	ok(timed_reads == 6 && route_reads == 1, "setting the timed pair again turns the cache off; fills are ignored");
	rtos_host_set_mmio_route_cache(ACCESS_NS);
	(void)sil_rew_mem(&regs[3]);
	rtos_host_set_mmio_window((uintptr_t)regs, sizeof(regs));
	(void)sil_rew_mem(&regs[3]);
	ok(timed_reads == 8 && route_reads == 1, "so does setting the window");

	rtos_host_set_mmio_route_cache(ACCESS_NS);
	(void)sil_rew_mem(&regs[3]);
	rtos_host_set_mmio_handler(NULL);
	regs[3] = 99U;
	ok(sil_rew_mem(&regs[3]) == 99U && timed_reads == 9 && route_reads == 1,
	   "after the handler is removed the window is plain memory");
	rtos_host_expect_bugs(false);
	rtos_host_shutdown();
	return tap_done();
}
