/*
 * syscfg.c — SYSCFG0 (kick lock, pin multiplexing, CFGCHIPn) and SYSCFG1
 * (pull-up/down enables).  Host only.
 *
 * A write to a protected SYSCFG0 register while the kick registers are
 * locked is dropped, as the chip does, and reported: a driver that forgets
 * the unlock would otherwise see its pinmux silently not take effect.
 */
#include <inttypes.h>
#include <stdio.h>
#include <string.h>

#include "rtos_host.h"
#include "host_sim/board.h"
#include "host_sim/regs.h"
#include "host_sim/syscfg.h"
#include "soc_parts.h"

#define SYSCFG_KICK0R    0x038U
#define SYSCFG_KICK1R    0x03CU
#define SYSCFG_PINMUX0   0x120U
#define SYSCFG1_PUPD_ENA 0x00CU
#define SYSCFG1_PUPD_SEL 0x010U
#define MAX_WATCHES      16U

static struct {
	struct hs_region *r0, *r1;
	uint32_t *pinmux[20];       /* PINMUX0..19's stored values (hs_syscfg_pinmux on every pin change) */
	struct {
		hs_syscfg_watch_fn fn;
		void *ctx;
	} watches[MAX_WATCHES];
} sc;

bool hs_syscfg_unlocked(void)
{
	return sc.r0 && hs_reg_get(sc.r0, SYSCFG_KICK0R) == HS_KICK0_UNLOCK &&
	       hs_reg_get(sc.r0, SYSCFG_KICK1R) == HS_KICK1_UNLOCK;
}

/* After a write to a protected register: undo it if locked, else tell the watchers. */
static void protected_written(void *ctx, const struct hs_access *a, uint32_t old, uint32_t now, uint32_t written)
{
	(void)ctx;
	if (!hs_syscfg_unlocked()) {
		char idx[16] = "";

		hs_reg_set(sc.r0, a->offset, old);
		if (a->reg->count)
			snprintf(idx, sizeof(idx), "[%u]", a->index);
		rtos_host_bug("host_sim", "write of 0x%08" PRIx32 " to SYSCFG0.%s%s (0x%08" PRIx32 ")"
			      " while SYSCFG0 is locked: dropped (write KICK0R=0x%08X and KICK1R=0x%08X first)",
			      written, a->reg->name, idx, (uint32_t)(HS_SYSCFG0_BASE + a->offset),
			      HS_KICK0_UNLOCK, HS_KICK1_UNLOCK);
		return;
	}
	if (old == now)
		return;
	for (unsigned i = 0; i < MAX_WATCHES; i++)
		if (sc.watches[i].fn)
			sc.watches[i].fn(sc.watches[i].ctx, a->offset, old, now);
}

/* After a write to a kick register: trace lock state changes. */
static void kick_written(void *ctx, const struct hs_access *a, uint32_t old, uint32_t now, uint32_t written)
{
	(void)ctx; (void)a; (void)old; (void)now; (void)written;
	rtos_host_trace("host_sim", "SYSCFG0 %s", hs_syscfg_unlocked() ? "unlocked" : "locked");
}

static const struct hs_reg syscfg0_regs[] = {
	{ .name = "REVID",       .offset = 0x000, .kind = HS_RO, .reset = 0x4E840102 },
	{ .name = "DIEIDR",      .offset = 0x008, .kind = HS_RO, .count = 4 },
	{ .name = "DEVIDR0",     .offset = 0x018, .kind = HS_RO, .reset = 0x1B7D102F },
	{ .name = "BOOTCFG",     .offset = 0x020, .kind = HS_RO },
	{ .name = "CHIPREVIDR",  .offset = 0x024, .kind = HS_RO },
	{ .name = "KICK0R",      .offset = SYSCFG_KICK0R, .kind = HS_RW, .after_write = kick_written },
	{ .name = "KICK1R",      .offset = SYSCFG_KICK1R, .kind = HS_RW, .after_write = kick_written },
	{ .name = "HOST0CFG",    .offset = 0x040, .kind = HS_RW, .after_write = protected_written },
	{ .name = "HOST1CFG",    .offset = 0x044, .kind = HS_RW, .after_write = protected_written },
	{ .name = "IRAWSTAT",    .offset = 0x0E0, .kind = HS_RW, .mask = 0x3, .after_write = protected_written },
	{ .name = "IENSTAT",     .offset = 0x0E4, .kind = HS_W1C, .mask = 0x3, .after_write = protected_written },
	{ .name = "IENSET",      .offset = 0x0E8, .kind = HS_W1S, .mask = 0x3, .alias = "IENSTAT" },
	{ .name = "IENCLR",      .offset = 0x0EC, .kind = HS_W1C, .mask = 0x3, .alias = "IENSTAT" },
	{ .name = "EOI",         .offset = 0x0F0, .kind = HS_WO, .mask = 0xFF },
	{ .name = "FLTADDRR",    .offset = 0x0F4, .kind = HS_RO },
	{ .name = "FLTSTAT",     .offset = 0x0F8, .kind = HS_RO },
	{ .name = "MSTPRI",      .offset = 0x110, .kind = HS_RW, .count = 3, .after_write = protected_written },
	{ .name = "PINMUX",      .offset = SYSCFG_PINMUX0, .kind = HS_RW, .count = 20, .after_write = protected_written },
	{ .name = "SUSPSRC",     .offset = 0x170, .kind = HS_RW, .after_write = protected_written },
	{ .name = "CHIPSIG",     .offset = 0x174, .kind = HS_RW, .mask = 0x1F, .after_write = protected_written },
	{ .name = "CHIPSIG_CLR", .offset = 0x178, .kind = HS_W1C, .mask = 0x1F, .alias = "CHIPSIG" },
	{ .name = "CFGCHIP",     .offset = HS_SYSCFG0_CFGCHIP(0), .kind = HS_RW, .count = 5, .after_write = protected_written },
};

static const struct hs_reg syscfg1_regs[] = {
	{ .name = "VTPIO_CTL", .offset = 0x000, .kind = HS_RW, .reset = 0x00000000 },
	{ .name = "DDR_SLEW",  .offset = 0x004, .kind = HS_RW },
	{ .name = "DEEPSLEEP", .offset = 0x008, .kind = HS_RW },
	{ .name = "PUPD_ENA",  .offset = SYSCFG1_PUPD_ENA, .kind = HS_RW, .reset = 0xFFFFFFFF },
	{ .name = "PUPD_SEL",  .offset = SYSCFG1_PUPD_SEL, .kind = HS_RW, .reset = 0xC3FFFFFF },
	{ .name = "RXACTIVE",  .offset = 0x014, .kind = HS_RW, .reset = 0xFFFFFFFF },
	{ .name = "PWRDN",     .offset = 0x018, .kind = HS_RW },
};

ER hs_syscfg_create(bool cold)
{
	memset(&sc, 0, sizeof(sc));
	sc.r0 = hs_region_add(&(struct hs_region_cfg){
		.name = "SYSCFG0", .phys = HS_SYSCFG0_BASE, .size = 0x1000,
		.regs = syscfg0_regs, .nregs = HS_ARRAY_SIZE(syscfg0_regs), .power = HS_NO_PSC });
	sc.r1 = hs_region_add(&(struct hs_region_cfg){
		.name = "SYSCFG1", .phys = HS_SYSCFG1_BASE, .size = 0x1000,
		.regs = syscfg1_regs, .nregs = HS_ARRAY_SIZE(syscfg1_regs), .power = HS_NO_PSC });
	if (!sc.r0 || !sc.r1)
		return E_SYS;
	for (unsigned n = 0; n < 20U; n++)
		sc.pinmux[n] = hs_reg_value_ptr(sc.r0, SYSCFG_PINMUX0 + 4U * n);
	/* U-Boot unlocks the kick registers and Linux leaves them so. */
	if (!cold) {
		hs_reg_set(sc.r0, SYSCFG_KICK0R, HS_KICK0_UNLOCK);
		hs_reg_set(sc.r0, SYSCFG_KICK1R, HS_KICK1_UNLOCK);
	}
	return E_OK;
}

void hs_syscfg_destroy(void)
{
	memset(&sc, 0, sizeof(sc));
}

uint32_t hs_syscfg_pinmux(unsigned n)
{
	if (!sc.r0 || n >= 20U)
		return 0;
	return *sc.pinmux[n];
}

const uint32_t *hs_syscfg_pinmux_ptr(unsigned n)
{
	return sc.r0 && n < 20U ? sc.pinmux[n] : NULL;
}

unsigned hs_syscfg_pinmux_field(unsigned n, unsigned shift)
{
	return shift > 28U ? 0U : (hs_syscfg_pinmux(n) >> shift) & 0xFU;
}

uint32_t hs_syscfg_cfgchip(unsigned n)
{
	if (!sc.r0 || n >= 5U)
		return 0;
	return hs_reg_get(sc.r0, HS_SYSCFG0_CFGCHIP(n));
}

bool hs_syscfg_tbclksync(void)
{
	return (hs_syscfg_cfgchip(1) & HS_CFGCHIP1_TBCLKSYNC) != 0;
}

uint32_t hs_syscfg_pupd_ena(void)
{
	return sc.r1 ? hs_reg_get(sc.r1, SYSCFG1_PUPD_ENA) : 0U;
}

uint32_t hs_syscfg_pupd_sel(void)
{
	return sc.r1 ? hs_reg_get(sc.r1, SYSCFG1_PUPD_SEL) : 0U;
}

int hs_syscfg_watch(hs_syscfg_watch_fn fn, void *ctx)
{
	for (unsigned i = 0; i < MAX_WATCHES; i++) {
		if (!sc.watches[i].fn) {
			sc.watches[i].fn = fn;
			sc.watches[i].ctx = ctx;
			return (int)i + 1;
		}
	}
	return 0;
}

void hs_syscfg_unwatch(int handle)
{
	if (handle > 0 && (unsigned)handle <= MAX_WATCHES)
		sc.watches[handle - 1].fn = NULL;
}
