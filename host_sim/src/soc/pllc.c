/*
 * pllc.c — PLLC0 and PLLC1 as register views of the clocks the board model
 * uses (PLL0 300 MHz, PLL1 132 MHz from the 24 MHz crystal).  Drivers map
 * them (d_pwm maps PLLC1) and may read them; the values describe the
 * modelled clocks.  Writes are stored but do not retune the model, so they
 * are traced.  Host only.
 */
#include <inttypes.h>

#include "rtos_host.h"
#include "host_sim/board.h"
#include "host_sim/regs.h"
#include "soc_parts.h"

/* A write to a PLL register: stored, traced, not applied to the clock model. */
static void pll_written(void *ctx, const struct hs_access *a, uint32_t old, uint32_t now, uint32_t written)
{
	(void)written;
	if (old != now)
		rtos_host_trace("host_sim", "%s.%s: 0x%08" PRIx32 " -> 0x%08" PRIx32 " (clock model unchanged)",
				(const char *)ctx, a->reg->name, old, now);
}

/* PLLM = multiplier - 1; PLLDIVn = 0x8000 | (divider - 1). */
#define PLLC_REGS(pllm, div1, div2, div3, postdiv) {                                              \
	{ .name = "REVID",   .offset = 0x000, .kind = HS_RO, .reset = 0x44813C00 },                   \
	{ .name = "RSTYPE",  .offset = 0x0E4, .kind = HS_RO, .reset = 0x1 },                          \
	{ .name = "PLLCTL",  .offset = 0x100, .kind = HS_RW, .reset = 0x00000049, .after_write = pll_written }, \
	{ .name = "OCSEL",   .offset = 0x104, .kind = HS_RW, .mask = 0x1F, .after_write = pll_written }, \
	{ .name = "PLLM",    .offset = 0x110, .kind = HS_RW, .mask = 0x1F, .reset = (pllm), .after_write = pll_written }, \
	{ .name = "PREDIV",  .offset = 0x114, .kind = HS_RW, .reset = 0x8000, .after_write = pll_written }, \
	{ .name = "PLLDIV1", .offset = 0x118, .kind = HS_RW, .reset = (div1), .after_write = pll_written }, \
	{ .name = "PLLDIV2", .offset = 0x11C, .kind = HS_RW, .reset = (div2), .after_write = pll_written }, \
	{ .name = "PLLDIV3", .offset = 0x120, .kind = HS_RW, .reset = (div3), .after_write = pll_written }, \
	{ .name = "OSCDIV",  .offset = 0x124, .kind = HS_RW, .reset = 0x8000, .after_write = pll_written }, \
	{ .name = "POSTDIV", .offset = 0x128, .kind = HS_RW, .reset = (postdiv), .after_write = pll_written }, \
	{ .name = "PLLCMD",  .offset = 0x138, .kind = HS_RW, .mask = 0x1 },                          \
	{ .name = "PLLSTAT", .offset = 0x13C, .kind = HS_RO, .reset = 0x5 },                          \
	{ .name = "ALNCTL",  .offset = 0x140, .kind = HS_RW },                                        \
	{ .name = "DCHANGE", .offset = 0x144, .kind = HS_RO },                                        \
	{ .name = "CKEN",    .offset = 0x148, .kind = HS_RW, .reset = 0x3 },                          \
	{ .name = "CKSTAT",  .offset = 0x14C, .kind = HS_RO, .reset = 0x3 },                          \
	{ .name = "SYSTAT",  .offset = 0x150, .kind = HS_RO, .reset = 0x7 },                          \
	{ .name = "PLLDIV4", .offset = 0x160, .kind = HS_RW, .reset = 0x8003, .after_write = pll_written }, \
	{ .name = "PLLDIV5", .offset = 0x164, .kind = HS_RW, .reset = 0x8002, .after_write = pll_written }, \
	{ .name = "PLLDIV6", .offset = 0x168, .kind = HS_RW, .reset = 0x8000, .after_write = pll_written }, \
	{ .name = "PLLDIV7", .offset = 0x16C, .kind = HS_RW, .reset = 0x8005, .after_write = pll_written }, \
}

/* PLL0: 24 MHz x 25 / 2 = 300 MHz; SYSCLK2 = /2 = 150 MHz. */
static const struct hs_reg pllc0_regs[] = PLLC_REGS(24, 0x8000, 0x8001, 0x8002, 0x8001);
/* PLL1 as LEGO sets it: 24 MHz x 22 / 2 = 264 MHz; SYSCLK2 = /2 = 132 MHz. */
static const struct hs_reg pllc1_regs[] = PLLC_REGS(21, 0x8000, 0x8001, 0x8002, 0x8001);

static char pllc0_name[] = "PLLC0";
static char pllc1_name[] = "PLLC1";

ER hs_pllc_create(bool cold)
{
	(void)cold;  /* the PLLs are locked by the boot ROM/U-Boot before anything we model runs */
	if (!hs_region_add(&(struct hs_region_cfg){
		    .name = "PLLC0", .phys = HS_PLLC0_BASE, .size = 0x1000,
		    .regs = pllc0_regs, .nregs = HS_ARRAY_SIZE(pllc0_regs), .power = HS_NO_PSC, .ctx = pllc0_name }))
		return E_SYS;
	if (!hs_region_add(&(struct hs_region_cfg){
		    .name = "PLLC1", .phys = HS_PLLC1_BASE, .size = 0x1000,
		    .regs = pllc1_regs, .nregs = HS_ARRAY_SIZE(pllc1_regs), .power = HS_NO_PSC, .ctx = pllc1_name }))
		return E_SYS;
	return E_OK;
}
