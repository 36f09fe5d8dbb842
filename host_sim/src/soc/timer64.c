/*
 * timer64.c — TIMER64P3 (AM1808 TRM chapter "Timer64P"), whose counters are
 * computed from the virtual clock at each read.  Host only.
 *
 * Modes: dual 32-bit unchained (TGCR.TIMMODE 1, what LEGO uses): TIM12
 * counts the input clock, TIM34 the input / (TGCR.TDDR34 + 1); 64-bit
 * general purpose (TIMMODE 0): TIM34:TIM12 is one counter at the input
 * clock.  A half runs while it is out of reset (TGCR.TIMxxRS) and its
 * TCR.ENAMODExx is one-shot (stops at PRD) or continuous (wraps to 0 after
 * PRD).  Other modes (watchdog, chained) leave the counters stopped and are
 * reported in the trace.  Period interrupts are not modelled.
 */
#include <inttypes.h>
#include <string.h>

#include "rtos_host.h"
#include "host_sim/board.h"
#include "host_sim/clock.h"
#include "host_sim/regs.h"
#include "host_sim/timer64.h"
#include "soc_parts.h"

#define T_TIM12    0x10U
#define T_TIM34    0x14U
#define T_PRD12    0x18U
#define T_PRD34    0x1CU
#define T_TCR      0x20U
#define T_TGCR     0x24U

/* ---- TIMER64P3 ---- */

struct half {
	uint64_t base_t;      /* virtual time of base_count */
	uint32_t base_count;
};

static struct {
	struct hs_region *region;
	uint32_t tgcr, tcr, prd12, prd34;   /* settings in effect */
	struct half h12, h34;
	uint64_t input_hz;
} tm;

/* Counting rate of half 12 (hi = false) or 34 under the settings in effect; 0 if stopped. */
static uint64_t half_hz(bool hi)
{
	unsigned mode = (tm.tgcr >> 2) & 3U;
	unsigned ena = hi ? (tm.tcr >> 22) & 3U : (tm.tcr >> 6) & 3U;
	bool out_of_reset = hi ? (tm.tgcr & 2U) != 0 : (tm.tgcr & 1U) != 0;

	if (mode == 0U) {
		/* 64-bit: one counter enabled by ENAMODE12, both halves out of reset. */
		ena = (tm.tcr >> 6) & 3U;
		out_of_reset = (tm.tgcr & 3U) == 3U;
		return out_of_reset && ena ? tm.input_hz : 0U;
	}
	if (mode != 1U || !out_of_reset || ena == 0U)
		return 0U;
	return hi ? tm.input_hz / (((tm.tgcr >> 12) & 0xFU) + 1U) : tm.input_hz;
}

/* Value of a 32-bit half counting from h at hz, wrapping or stopping at prd. */
static uint32_t half_value(const struct half *h, uint64_t hz, uint32_t prd, bool one_shot, uint64_t now)
{
	uint64_t n = h->base_count + hs_ns_to_cycles(now - h->base_t, hz);

	if (hz == 0)
		return h->base_count;
	if (h->base_count > prd)                  /* past the period: counts up to wrap at 2^32 */
		return (uint32_t)n;
	if (one_shot)
		return n > prd ? prd : (uint32_t)n;
	return (uint32_t)(n % ((uint64_t)prd + 1U));
}

/* Both counters at the current instant under the settings in effect. */
static void timer_values(uint32_t *t12, uint32_t *t34)
{
	uint64_t now = rtos_host_now();
	unsigned mode = (tm.tgcr >> 2) & 3U;

	if (mode == 0U) {
		uint64_t hz = half_hz(false);
		uint64_t base = ((uint64_t)tm.h34.base_count << 32) | tm.h12.base_count;
		uint64_t prd = ((uint64_t)tm.prd34 << 32) | tm.prd12;
		uint64_t n = base + (hz ? hs_ns_to_cycles(now - tm.h12.base_t, hz) : 0U);
		bool one_shot = ((tm.tcr >> 6) & 3U) == 1U;

		if (base <= prd && hz)
			n = one_shot ? (n > prd ? prd : n) : (prd == UINT64_MAX ? n : n % (prd + 1U));
		*t12 = (uint32_t)n;
		*t34 = (uint32_t)(n >> 32);
		return;
	}
	*t12 = half_value(&tm.h12, half_hz(false), tm.prd12, ((tm.tcr >> 6) & 3U) == 1U, now);
	*t34 = half_value(&tm.h34, half_hz(true), tm.prd34, ((tm.tcr >> 22) & 3U) == 1U, now);
}

/* Freezes the counters at their current values as the new base (before a settings change). */
static void timer_rebase(void)
{
	uint32_t t12, t34;
	uint64_t now = rtos_host_now();

	timer_values(&t12, &t34);
	tm.h12.base_count = t12;
	tm.h34.base_count = t34;
	tm.h12.base_t = tm.h34.base_t = now;
}

uint32_t hs_timer64p3_tim12(void)
{
	uint32_t t12, t34;

	timer_values(&t12, &t34);
	return t12;
}

uint32_t hs_timer64p3_tim34(void)
{
	uint32_t t12, t34;

	timer_values(&t12, &t34);
	return t34;
}

uint64_t hs_timer64p3_tim34_hz(void)
{
	return ((tm.tgcr >> 2) & 3U) == 0U ? 0U : half_hz(true);
}

static void tim_read(void *ctx, const struct hs_access *a, uint32_t *value)
{
	uint32_t t12, t34;

	(void)ctx;
	timer_values(&t12, &t34);
	*value = a->offset == T_TIM12 ? t12 : t34;
}

static void tim_written(void *ctx, const struct hs_access *a, uint32_t old, uint32_t now, uint32_t written)
{
	(void)ctx; (void)old; (void)written;
	timer_rebase();
	if (a->offset == T_TIM12)
		tm.h12.base_count = now;
	else
		tm.h34.base_count = now;
}

static void setting_written(void *ctx, const struct hs_access *a, uint32_t old, uint32_t now, uint32_t written)
{
	unsigned mode;

	(void)ctx; (void)old; (void)written;
	timer_rebase();
	switch (a->offset) {
	case T_TCR:
		tm.tcr = now;
		break;
	case T_TGCR:
		/* Putting a half into reset clears its counter. */
		if (!(now & 1U))
			tm.h12.base_count = 0;
		if (!(now & 2U))
			tm.h34.base_count = 0;
		tm.tgcr = now;
		mode = (now >> 2) & 3U;
		if (mode >= 2U)
			rtos_host_trace("host_sim", "TIMER64P3: TIMMODE %u (%s) is not modelled; counters stopped",
					mode, mode == 2U ? "watchdog" : "chained");
		break;
	case T_PRD12:
		tm.prd12 = now;
		break;
	default:
		tm.prd34 = now;
		break;
	}
}

static const struct hs_reg timer_regs[] = {
	{ .name = "REVID",      .offset = 0x00, .kind = HS_RO, .reset = 0x44720211 },
	{ .name = "EMUMGT",     .offset = 0x04, .kind = HS_RW, .mask = 0x3 },
	{ .name = "GPINTGPEN",  .offset = 0x08, .kind = HS_RW, .mask = 0x00030003 },
	{ .name = "GPDATGPDIR", .offset = 0x0C, .kind = HS_RW, .mask = 0x00030003 },
	{ .name = "TIM12",      .offset = T_TIM12, .kind = HS_RW, .before_read = tim_read, .after_write = tim_written },
	{ .name = "TIM34",      .offset = T_TIM34, .kind = HS_RW, .before_read = tim_read, .after_write = tim_written },
	{ .name = "PRD12",      .offset = T_PRD12, .kind = HS_RW, .after_write = setting_written },
	{ .name = "PRD34",      .offset = T_PRD34, .kind = HS_RW, .after_write = setting_written },
	{ .name = "TCR",        .offset = T_TCR, .kind = HS_RW, .mask = 0x03C003C3, .after_write = setting_written },
	{ .name = "TGCR",       .offset = T_TGCR, .kind = HS_RW, .mask = 0x0000FF1F, .after_write = setting_written },
	{ .name = "WDTCR",      .offset = 0x28, .kind = HS_RW, .mask = 0xFFFF4000 },
	{ .name = "REL12",      .offset = 0x34, .kind = HS_RW },
	{ .name = "REL34",      .offset = 0x38, .kind = HS_RW },
	{ .name = "CAP12",      .offset = 0x3C, .kind = HS_RO },
	{ .name = "CAP34",      .offset = 0x40, .kind = HS_RO },
	{ .name = "INTCTLSTAT", .offset = 0x44, .kind = HS_RW, .mask = 0x000F000F },
	{ .name = "CMP",        .offset = 0x60, .kind = HS_RW, .count = 8 },
};

ER hs_timer64p3_create(bool cold)
{
	(void)cold;  /* Linux does not use TIMER64P3: reset state either way. */
	memset(&tm, 0, sizeof(tm));
	tm.input_hz = HS_PLL1_SYSCLK2_HZ;
	tm.region = hs_region_add(&(struct hs_region_cfg){
		.name = "TIMER64P3", .phys = HS_TIMER64P3_BASE, .size = 0x1000,
		.regs = timer_regs, .nregs = HS_ARRAY_SIZE(timer_regs), .power = HS_NO_PSC });
	return tm.region ? E_OK : E_SYS;
}

void hs_timer64p3_destroy(void)
{
	memset(&tm, 0, sizeof(tm));
}
