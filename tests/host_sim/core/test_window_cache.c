/*
 * test_window_cache.c — accesses through the CPU windows that repeat an
 * address (served from the accessors' route cache, which space.c fills)
 * behave as the first one: hooks run every time, another width is still checked, a module
 * powered off in between is still reported, and the register log started
 * or stopped in between sees exactly the accesses made while it is on.
 * Narrow accesses at byte lanes, repeated, reach their lanes and tell the
 * hooks their own width, element and direction; a hook that empties the
 * cache while its access is under way still sees that access.  A repeated
 * byte write of a value wider than a byte stores and tells only its byte,
 * with a hook or without, and a repeated write-1-to-set at a byte lane sets
 * only the ones of its lane.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <string.h>

#include "tap.h"
#include "sil.h"
#include "rtos_host.h"
#include "host_sim/board.h"
#include "host_sim/psc.h"
#include "host_sim/regs.h"
#include "host_sim/scenario.h"
#include "host_sim/trace.h"

#define CDEV_PHYS  0x01E00000U
#define PSC1       0x01E27000U
#define MODULE     17U          /* eHRPWM's LPSC, powered off at reset */

static unsigned reads, writes;

static void count_read(void *ctx, const struct hs_access *a, uint32_t *value)
{
	(void)ctx; (void)a;
	*value = ++reads;
}

static void count_write(void *ctx, const struct hs_access *a, uint32_t old, uint32_t now, uint32_t written)
{
	(void)ctx; (void)a; (void)old; (void)now; (void)written;
	writes++;
}

/* The access the last hook of told_* or emptying_read was told of, and what told_write was written. */
static struct hs_access told;
static uint32_t told_written;

static void told_read(void *ctx, const struct hs_access *a, uint32_t *value)
{
	(void)ctx; (void)value;
	told = *a;
}

static void told_write(void *ctx, const struct hs_access *a, uint32_t old, uint32_t now, uint32_t written)
{
	(void)ctx; (void)old; (void)now;
	told = *a;
	told_written = written;
}

/* Empties the window cache (changing the register log does) while its access is under way. */
static void emptying_read(void *ctx, const struct hs_access *a, uint32_t *value)
{
	(void)ctx;
	hs_trace_reglog(NULL, NULL);
	told = *a;
	*value = 0x5A;
}

static const struct hs_reg cdev_regs[] = {
	{ .name = "COUNT", .offset = 0x00, .kind = HS_RO, .before_read = count_read },
	{ .name = "CTL",   .offset = 0x04, .kind = HS_RW, .after_write = count_write },
	{ .name = "FLAGS", .offset = 0x08, .kind = HS_W1C, .reset = 0xFF, .after_write = count_write },
	{ .name = "LANES", .offset = 0x0C, .kind = HS_COR, .widths = HS_W8 | HS_W16, .mask = 0x00FF0000,
	  .reset = 0x44332211, .before_read = told_read },
	{ .name = "ARR",   .offset = 0x10, .kind = HS_RW, .widths = HS_W16, .count = 2, .after_write = told_write },
	{ .name = "EMPTY", .offset = 0x20, .kind = HS_RO, .before_read = emptying_read },
	{ .name = "BYTE",  .offset = 0x24, .width = 1, .kind = HS_RW, .after_write = told_write },
	{ .name = "PLAIN", .offset = 0x28, .width = 1, .kind = HS_RW },
	{ .name = "SET",   .offset = 0x2C, .kind = HS_W1S, .widths = HS_W8, .reset = 0x01 },
};

/* True if the last hook was told of a width-byte access to the element at offset in direction write. */
static bool told_of(unsigned width, uint32_t offset, bool write)
{
	return told.width == width && told.offset == offset && told.write == write;
}

static const struct rtos_cfg cfg = { .name = "window_cache" };

/* Powers the module on or off through the PSC's registers, as a driver does. */
static void power(bool on)
{
	sil_wrw_mem(rtos_host_map_io(PSC1 + 0xA00 + 4 * MODULE, 4), on ? 3 : 0);
	sil_wrw_mem(rtos_host_map_io(PSC1 + 0x120, 4), 1);
}

/* Lines in f. */
static unsigned lines_in(FILE *f)
{
	unsigned n = 0;
	int c;

	rewind(f);
	while ((c = fgetc(f)) != EOF)
		n += c == '\n';
	return n;
}

int main(void)
{
	struct hs_scenario scn = { .rtos = &cfg };
	volatile uint8_t *w;
	FILE *log = tmpfile();

	tap_plan(24);
	if (hs_sim_boot(&scn) != E_OK || !log)
		tap_bail_out("boot failed");
	ok(hs_region_add(&(struct hs_region_cfg){ .name = "CDEV", .phys = CDEV_PHYS, .size = 0x1000,
		.regs = cdev_regs, .nregs = HS_ARRAY_SIZE(cdev_regs), .power = HS_PSC1_MODULE(MODULE) }) != NULL,
	   "region registers");
	w = rtos_host_map_io(CDEV_PHYS, 0x1000);
	power(true);

	is_int(sil_rew_mem((uint32_t *)(w + 0x00)) + sil_rew_mem((uint32_t *)(w + 0x00)) +
	       sil_rew_mem((uint32_t *)(w + 0x00)), 1 + 2 + 3, "a repeated read runs the hook every time");
	sil_wrw_mem((uint32_t *)(w + 0x04), 5);
	sil_wrw_mem((uint32_t *)(w + 0x04), 6);
	is_int(writes, 2, "a repeated write runs the hook every time");
	is_int(sil_rew_mem((uint32_t *)(w + 0x04)), 6, "and stores its value");
	sil_wrw_mem((uint32_t *)(w + 0x08), 0x0F);
	sil_wrw_mem((uint32_t *)(w + 0x08), 0x30);
	is_int(sil_rew_mem((uint32_t *)(w + 0x08)), 0xC0, "a repeated write-1-to-clear clears each time");

	rtos_host_expect_bugs(true);
	(void)sil_reh_mem((uint16_t *)(w + 0x04));
	ok(strstr(rtos_host_last_bug(), "is a 4-byte register") != NULL,
	   "another width at a cached address is still checked (%s)", rtos_host_last_bug());
	power(false);
	ok(!hs_psc_enabled(HS_PSC1_MODULE(MODULE)), "module powered off");
	is_int(sil_rew_mem((uint32_t *)(w + 0x04)), 0, "a cached register of a dead module reads 0");
	ok(strstr(rtos_host_last_bug(), "CDEV is not powered") != NULL, "and is reported (%s)", rtos_host_last_bug());
	sil_wrw_mem((uint32_t *)(w + 0x04), 7);
	ok(strstr(rtos_host_last_bug(), "of 0x00000007") != NULL && writes == 4,
	   "a cached write to it too, and it does not reach the register");
	rtos_host_expect_bugs(false);
	power(true);
	is_int(sil_rew_mem((uint32_t *)(w + 0x04)), 6, "powered again, the register answers");

	hs_trace_reglog("CDEV", log);
	(void)sil_rew_mem((uint32_t *)(w + 0x04));
	sil_wrw_mem((uint32_t *)(w + 0x04), 8);
	hs_trace_reglog(NULL, NULL);
	(void)sil_rew_mem((uint32_t *)(w + 0x04));
	sil_wrw_mem((uint32_t *)(w + 0x04), 9);
	is_int(lines_in(log), 2, "the register log sees the cached accesses made while it is on, and only those");
	is_int(sil_rew_mem((uint32_t *)(w + 0x00)), 4, "after the log changed, reads still reach their hook");

	is_int(sil_reb_mem((uint8_t *)(w + 0x0E)), 0x33, "an 8-bit read at byte lane 2 returns that byte");
	ok(told_of(1, 0x0C, false), "and its hook is told a 1-byte read of the element");
	is_int(sil_reb_mem((uint8_t *)(w + 0x0E)), 0x00, "repeated, it finds the byte its clear-on-read cleared");
	is_int(sil_reb_mem((uint8_t *)(w + 0x0D)) + sil_reb_mem((uint8_t *)(w + 0x0D)), 0x22 + 0x22,
	       "a lane outside the clear-on-read mask keeps its byte");
	is_int(sil_reh_mem((uint16_t *)(w + 0x0E)), 0x4400, "a 16-bit read at lane 2 returns the upper half");
	ok(told_of(2, 0x0C, false), "and its hook is told a 2-byte read");
	sil_wrh_mem((uint16_t *)(w + 0x16), 0xBEEF);
	sil_wrh_mem((uint16_t *)(w + 0x16), 0xCAFE);
	ok(told_of(2, 0x14, true) && told.index == 1 && told_written == 0xCAFE0000U &&
	   sil_rew_mem((uint32_t *)(w + 0x14)) == 0xCAFE0000U,
	   "a repeated 16-bit write at lane 2 of an array element reaches its lanes and tells the element");
	ok(sil_rew_mem((uint32_t *)(w + 0x20)) == 0x5A && told_of(4, 0x20, false) &&
	   sil_rew_mem((uint32_t *)(w + 0x20)) == 0x5A && told_of(4, 0x20, false),
	   "a hook that empties the window cache mid-access is still told its access");
	sil_host_write(w + 0x24, 1, 0x1A5);
	sil_host_write(w + 0x24, 1, 0x1A5);
	ok(sil_reb_mem((uint8_t *)(w + 0x24)) == 0xA5 && told_of(1, 0x24, true) && told_written == 0xA5,
	   "a repeated byte write of a wider value stores and tells its byte only");
	sil_host_write(w + 0x28, 1, 0x13C);
	sil_host_write(w + 0x28, 1, 0x13C);
	is_int(sil_reb_mem((uint8_t *)(w + 0x28)), 0x3C, "so does one to a register without a hook");
	sil_wrb_mem((uint8_t *)(w + 0x2D), 0x80);
	sil_wrb_mem((uint8_t *)(w + 0x2D), 0x02);
	is_int(sil_rew_mem((uint32_t *)(w + 0x2C)), 0x8201, "repeated write-1-to-set bytes at lane 1 set their ones there");

	fclose(log);
	hs_sim_shutdown();
	return tap_done();
}
