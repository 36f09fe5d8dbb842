/*
 * test_regs.c — the register space: each declared kind (RO, RW, W1S, W1C,
 * COR, WO, reserved), masks, aliases, arrays, widths, hooks with their
 * old/new/written values, the stall helper, the register log, and the loud
 * reports for accesses outside the declarations (unmodelled address, wrong
 * width, wrong direction, reserved, unpowered module, unmapped range).
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <string.h>

#include "tap.h"
#include "sil.h"
#include "rtos_host.h"
#include "host_sim/board.h"
#include "host_sim/clock.h"
#include "host_sim/psc.h"
#include "host_sim/regs.h"
#include "host_sim/scenario.h"
#include "host_sim/trace.h"

#define TDEV_PHYS  0x01E00000U
#define PDEV_PHYS  0x01E01000U

static struct {
	unsigned writes;
	uint32_t old, now, written;
	unsigned index, width;
	uint64_t ready_at;
	bool ready;
} dev;

static void ctl_written(void *ctx, const struct hs_access *a, uint32_t old, uint32_t now, uint32_t written)
{
	(void)ctx;
	dev.writes++;
	dev.old = old;
	dev.now = now;
	dev.written = written;
	dev.index = a->index;
	dev.width = a->width;
}

static void cor_read(void *ctx, const struct hs_access *a, uint32_t *value)
{
	(void)ctx; (void)a;
	*value |= 0x100;    /* a sticky status bit the model keeps */
}

static void become_ready(void *arg)
{
	(void)arg;
	dev.ready = true;
}

/* A busy device: the read takes until it is ready. */
static void busy_read(void *ctx, const struct hs_access *a, uint32_t *value)
{
	(void)ctx; (void)a;
	if (!dev.ready && dev.ready_at)
		hs_access_stall_until(dev.ready_at);
	*value = dev.ready ? 1U : 0U;
}

/* DIRECT's hooks and direct accesses: which path each access took. */
static struct {
	unsigned hook_reads, hook_writes, direct_reads, direct_writes;
} path;

static void direct_hook_read(void *ctx, const struct hs_access *a, uint32_t *value)
{
	(void)ctx; (void)a;
	path.hook_reads++;
	*value += 1;        /* every read counts up, whichever path it takes */
}

static void direct_hook_written(void *ctx, const struct hs_access *a, uint32_t old, uint32_t now, uint32_t written)
{
	(void)ctx; (void)a; (void)old; (void)now; (void)written;
	path.hook_writes++;
}

static uint32_t direct_read(const struct rtos_host_mmio_route *rt)
{
	const struct hs_direct *d = hs_direct_of(rt);

	path.direct_reads += d->ctx == &path;
	return ++*d->value;
}

static void direct_write(const struct rtos_host_mmio_route *rt, uint32_t data)
{
	const struct hs_direct *d = hs_direct_of(rt);

	path.direct_writes += d->ctx == &path;
	*d->value = data;
}

static const struct hs_reg tdev_regs[] = {
	{ .name = "ID",     .offset = 0x00, .kind = HS_RO,  .reset = 0x1234 },
	{ .name = "CTL",    .offset = 0x04, .kind = HS_RW,  .mask = 0x0000FFFF, .after_write = ctl_written },
	{ .name = "SET",    .offset = 0x08, .kind = HS_W1S, .mask = 0x000000F0 },
	{ .name = "FLAGS",  .offset = 0x0C, .kind = HS_W1C, .reset = 0xFF },
	{ .name = "ERR",    .offset = 0x10, .kind = HS_COR, .mask = 0x0F, .reset = 0x05, .before_read = cor_read },
	{ .name = "STATUS", .offset = 0x14, .kind = HS_RO,  .reset = 0xA5 },
	{ .name = "CMD",    .offset = 0x14, .kind = HS_WO,  .after_write = ctl_written },
	{ .name = "RES",    .offset = 0x18, .kind = HS_RSVD },
	{ .name = "ARR",    .offset = 0x20, .kind = HS_RW,  .count = 4, .after_write = ctl_written },
	{ .name = "CTLSET", .offset = 0x30, .kind = HS_W1S, .alias = "CTL", .mask = 0x0000FFFF, .after_write = ctl_written },
	{ .name = "H16",    .offset = 0x40, .width = 2, .kind = HS_RW },
	{ .name = "B8",     .offset = 0x44, .width = 1, .kind = HS_RW },
	{ .name = "NARROW", .offset = 0x48, .kind = HS_RW, .widths = HS_W8 | HS_W16 },
	{ .name = "BUSY",   .offset = 0x4C, .kind = HS_RO, .before_read = busy_read },
	{ .name = "GO",     .offset = 0x50, .kind = HS_WO },
	{ .name = "DIRECT", .offset = 0x54, .kind = HS_RW, .widths = HS_W16 | HS_W32,
	  .before_read = direct_hook_read, .after_write = direct_hook_written,
	  .read_direct = direct_read, .write_direct = direct_write },
};

static const struct hs_reg pdev_regs[] = {
	{ .name = "X", .offset = 0x00, .kind = HS_RW },
};

static const struct rtos_cfg empty_cfg = { .name = "regs" };

/* Expects exactly one bug report while running fn-like code; returns its text check. */
#define EXPECT_BUG(code, needle, ...) do { \
	uint_t before_ = rtos_host_bug_count(); \
	code; \
	ok(rtos_host_bug_count() == before_ + 1U && strstr(rtos_host_last_bug(), (needle)) != NULL, __VA_ARGS__); \
	if (rtos_host_bug_count() != before_ + 1U || !strstr(rtos_host_last_bug(), (needle))) \
		tap_diag("  bugs %u -> %u, last: %s", before_, rtos_host_bug_count(), rtos_host_last_bug()); \
} while (0)

int main(void)
{
	struct hs_scenario scn = { .rtos = &empty_cfg, .board = &(struct hs_board_cfg){ .access_ns = 100 } };
	uint8_t *w;
	uint32_t v;
	uint64_t t0;
	char *logbuf = NULL;
	size_t loglen = 0;
	FILE *log;

	tap_plan(54);
	if (hs_sim_boot(&scn) != E_OK)
		tap_bail_out("boot failed");
	ok(hs_region_add(&(struct hs_region_cfg){ .name = "TDEV", .phys = TDEV_PHYS, .size = 0x1000,
		.regs = tdev_regs, .nregs = HS_ARRAY_SIZE(tdev_regs), .ctx = &path }) != NULL, "test region registers");
	w = rtos_host_map_io(TDEV_PHYS, 0x100);
	ok(w != NULL, "ioremap-style map returns a window");

	/* RO */
	is_int(sil_rew_mem((uint32_t *)(w + 0x00)), 0x1234, "RO reads its reset value");
	/* RW with mask; hook sees old/new/written */
	sil_wrw_mem((uint32_t *)(w + 0x04), 0xABCD1234);
	is_int(sil_rew_mem((uint32_t *)(w + 0x04)), 0x1234, "RW stores only the mask bits");
	ok(dev.writes == 1 && dev.old == 0 && dev.now == 0x1234 && dev.written == 0xABCD1234 && dev.width == 4,
	   "after_write gets old, new and written");
	/* W1S */
	sil_wrw_mem((uint32_t *)(w + 0x08), 0x30);
	sil_wrw_mem((uint32_t *)(w + 0x08), 0x0F);
	is_int(sil_rew_mem((uint32_t *)(w + 0x08)), 0x30, "W1S sets ones within its mask, keeps others");
	sil_wrw_mem((uint32_t *)(w + 0x08), 0x00);
	is_int(sil_rew_mem((uint32_t *)(w + 0x08)), 0x30, "W1S: zeros change nothing");
	/* W1C */
	sil_wrw_mem((uint32_t *)(w + 0x0C), 0x81);
	is_int(sil_rew_mem((uint32_t *)(w + 0x0C)), 0x7E, "W1C clears the ones written");
	/* COR */
	is_int(sil_rew_mem((uint32_t *)(w + 0x10)), 0x105, "COR read returns the value (hook adds a bit)");
	is_int(sil_rew_mem((uint32_t *)(w + 0x10)), 0x100, "COR read cleared its mask bits only");
	/* RO and WO at one offset */
	sil_wrw_mem((uint32_t *)(w + 0x14), 0x77);
	is_int(sil_rew_mem((uint32_t *)(w + 0x14)), 0xA5, "read and write registers share an offset");
	is_int(dev.written, 0x77, "the write went to the write-only register");
	/* Arrays */
	sil_wrw_mem((uint32_t *)(w + 0x28), 0x42);
	is_int(dev.index, 2, "array element index reaches the hook");
	is_int(hs_reg_get(hs_region_by_name("TDEV"), 0x28), 0x42, "hs_reg_get reads an array element");
	/* Alias */
	sil_wrw_mem((uint32_t *)(w + 0x30), 0x8000);
	is_int(sil_rew_mem((uint32_t *)(w + 0x04)), 0x9234, "W1S alias sets bits of its target");
	is_int(sil_rew_mem((uint32_t *)(w + 0x30)), 0x9234, "alias reads its target");
	/* Widths */
	sil_wrh_mem((uint16_t *)(w + 0x40), 0xBEEF);
	is_int(sil_reh_mem((uint16_t *)(w + 0x40)), 0xBEEF, "16-bit register at 16 bits");
	sil_wrb_mem(w + 0x44, 0x5A);
	is_int(sil_reb_mem(w + 0x44), 0x5A, "8-bit register at 8 bits");
	sil_wrw_mem((uint32_t *)(w + 0x48), 0x11223344);
	sil_wrb_mem(w + 0x48, 0xAA);
	is_int(sil_rew_mem((uint32_t *)(w + 0x48)), 0x112233AA, "narrow write replaces the low byte only");
	is_int(sil_reh_mem((uint16_t *)(w + 0x48)), 0x33AA, "narrow read returns the low half");
	/* Byte lanes: a narrow access inside a wider register reaches the lanes it addresses */
	sil_wrh_mem((uint16_t *)(w + 0x4A), 0x5566);
	is_int(sil_rew_mem((uint32_t *)(w + 0x48)), 0x556633AA, "16-bit write at +2 replaces the upper half only");
	is_int(sil_reh_mem((uint16_t *)(w + 0x4A)), 0x5566, "16-bit read at +2 returns the upper half");
	sil_wrb_mem(w + 0x49, 0x77);
	is_int(sil_rew_mem((uint32_t *)(w + 0x48)), 0x556677AA, "8-bit write at +1 replaces byte 1 only");
	is_int(sil_reb_mem(w + 0x4B), 0x55, "8-bit read at +3 returns byte 3");
	/* Model side */
	hs_reg_set(hs_region_by_name("TDEV"), 0x14, 0x5);
	is_int(sil_rew_mem((uint32_t *)(w + 0x14)), 0x5, "hs_reg_set changes the value without hooks");
	/* Access cost */
	t0 = hs_now();
	(void)sil_rew_mem((uint32_t *)(w + 0x00));
	is_u64(hs_now() - t0, 100, "an access costs the configured virtual time");
	/* Stall helper */
	dev.ready_at = hs_now() + 8000;
	hs_event_at(dev.ready_at, become_ready, NULL);
	t0 = hs_now();
	v = sil_rew_mem((uint32_t *)(w + 0x4C));
	ok(v == 1 && hs_now() == dev.ready_at + 100, "a stalled read returns the ready state at the device's time");
	tap_diag("  read %u after %llu ns", v, (unsigned long long)(hs_now() - t0));

	/* Direct accesses: unlogged 32-bit ones call them, with the region's context
	 * and the stored value; narrower ones take the hooks */
	sil_wrw_mem((uint32_t *)(w + 0x54), 0x10);
	t0 = hs_now();
	v = sil_rew_mem((uint32_t *)(w + 0x54));
	ok(v == 0x11 && path.direct_writes == 1 && path.direct_reads == 1 && path.hook_reads + path.hook_writes == 0,
	   "32-bit accesses of a register with direct accesses take them");
	is_u64(hs_now() - t0, 100, "a direct access costs the configured virtual time");
	sil_wrh_mem((uint16_t *)(w + 0x54), 0x20);
	v = sil_reh_mem((uint16_t *)(w + 0x54));
	ok(v == 0x21 && path.hook_writes == 1 && path.hook_reads == 1 && path.direct_reads + path.direct_writes == 2,
	   "16-bit accesses of it take the hooks");

	/* Register log */
	log = open_memstream(&logbuf, &loglen);
	hs_trace_reglog("TDEV", log);
	sil_wrw_mem((uint32_t *)(w + 0x04), 0x1);
	(void)sil_rew_mem((uint32_t *)(w + 0x00));
	hs_trace_reglog("GPIO", log);
	(void)sil_rew_mem((uint32_t *)(w + 0x00));
	hs_trace_reglog(NULL, NULL);
	fclose(log);
	ok(strstr(logbuf, "W4 TDEV.CTL @0x01e00004 = 0x00000001") && strstr(logbuf, "R4 TDEV.ID @0x01e00000 = 0x00001234"),
	   "register log names region, register, address and value");
	ok(strchr(logbuf, '\n') && strchr(strchr(logbuf, '\n') + 1, '\n') && !strchr(strchr(strchr(logbuf, '\n') + 1, '\n') + 1, '\n'),
	   "register log filter leaves out other regions");
	tap_diag("%s", logbuf);
	free(logbuf);
	/* a logged register's direct accesses give way to the hooks and the log */
	log = open_memstream(&logbuf, &loglen);
	hs_trace_reglog("TDEV", log);
	sil_wrw_mem((uint32_t *)(w + 0x54), 0x30);
	v = sil_rew_mem((uint32_t *)(w + 0x54));
	hs_trace_reglog(NULL, NULL);
	fclose(log);
	ok(v == 0x31 && path.hook_writes == 2 && path.hook_reads == 2 && path.direct_reads + path.direct_writes == 2 &&
	   strstr(logbuf, "W4 TDEV.DIRECT @0x01e00054 = 0x00000030") && strstr(logbuf, "R4 TDEV.DIRECT @0x01e00054 = 0x00000031"),
	   "logged 32-bit accesses of it take the hooks and are logged");
	free(logbuf);
	(void)sil_rew_mem((uint32_t *)(w + 0x54));
	is_int(path.direct_reads, 2, "with the log off again they take the direct accesses");

	/* Loud reports */
	rtos_host_expect_bugs(true);
	EXPECT_BUG(sil_wrw_mem((uint32_t *)(w + 0x00), 1), "TDEV.ID is read-only", "write to RO is reported");
	is_int(sil_rew_mem((uint32_t *)(w + 0x00)), 0x1234, "and has no effect");
	EXPECT_BUG((void)sil_rew_mem((uint32_t *)(w + 0x1C)), "no register there", "read of an unmodelled offset");
	EXPECT_BUG(sil_wrw_mem((uint32_t *)(w + 0x1C), 3), "of 0x00000003", "write report carries the value");
	EXPECT_BUG((void)sil_rew_mem((uint32_t *)(w + 0x18)), "TDEV.RES is reserved", "reserved register");
	EXPECT_BUG((void)sil_reh_mem((uint16_t *)(w + 0x04)), "is a 4-byte register", "wrong width");
	EXPECT_BUG((void)sil_reb_mem(w + 0x45), "no register there", "access inside no register");
	EXPECT_BUG((void)sil_reh_mem((uint16_t *)(w + 0x06)), "is a 4-byte register", "narrow access at a lane of a register that takes only 32 bits");
	EXPECT_BUG((void)sil_rew_mem((uint32_t *)(w + 0x40)), "crosses the end of TDEV.H16", "an access crossing a register's end");
	EXPECT_BUG((void)sil_rew_mem((uint32_t *)(w + 0x50)), "TDEV.GO is write-only", "read of a write-only register");
	EXPECT_BUG((void)hs_cpu_read(0x01E03000, 4), "no modelled device there", "unmodelled physical address");
	ok(rtos_host_map_io(0x01E03000, 4) == NULL, "map of an unmodelled range is NULL");
	ok(rtos_host_map_io(TDEV_PHYS + 0xF00, 0x200) == (void *)(w + 0xF00),
	   "a map crossing the region's end is one window, as Linux's ioremap");

	/* Power */
	ok(hs_region_add(&(struct hs_region_cfg){ .name = "PDEV", .phys = PDEV_PHYS, .size = 0x1000,
		.regs = pdev_regs, .nregs = 1, .power = HS_PSC1_MODULE(HS_LPSC1_EHRPWM) }) != NULL,
	   "powered region registers");
	EXPECT_BUG((void)hs_cpu_read(PDEV_PHYS, 4), "PDEV is not powered (PSC1 module 17 is SwRstDisable", "unpowered module");
	sil_wrw_mem(rtos_host_map_io(0x01E27000 + 0xA44, 4), 3);      /* MDCTL17 = Enable */
	ok(!hs_psc_enabled(HS_PSC1_MODULE(HS_LPSC1_EHRPWM)), "MDCTL alone does not power the module");
	sil_wrw_mem(rtos_host_map_io(0x01E27000 + 0x120, 4), 1);      /* PTCMD.GO0 */
	ok(hs_psc_enabled(HS_PSC1_MODULE(HS_LPSC1_EHRPWM)), "PTCMD.GO makes the transition");
	is_int(sil_rew_mem(rtos_host_map_io(0x01E27000 + 0x844, 4)) & 0x3F, 3, "MDSTAT17 shows Enable");
	hs_cpu_write(PDEV_PHYS, 4, 9);
	is_int(hs_cpu_read(PDEV_PHYS, 4), 9, "the powered region answers");
	/* Bad declarations */
	EXPECT_BUG(hs_region_add(&(struct hs_region_cfg){ .name = "OVL", .phys = TDEV_PHYS, .size = 0x1000,
		.regs = pdev_regs, .nregs = 1 }), "overlaps region TDEV", "overlapping region refused");
	rtos_host_expect_bugs(false);

	hs_sim_shutdown();
	return tap_done();
}
