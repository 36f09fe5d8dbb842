/*
 * timer64.c — TIMER64P1 and TIMER64P3 (AM1808 TRM chapter "Timer64P"),
 * whose counters are computed from the virtual clock at each read.  Host
 * only.
 *
 * Modes: dual 32-bit unchained (TGCR.TIMMODE 1, what LEGO uses): TIM12
 * counts the input clock, TIM34 the input / (TGCR.TDDR34 + 1); 64-bit
 * general purpose (TIMMODE 0): TIM34:TIM12 is one counter at the input
 * clock.  A half runs while it is out of reset (TGCR.TIMxxRS) and its
 * TCR.ENAMODExx is one-shot (stops at PRD) or continuous (wraps to 0 after
 * PRD).  Other modes (watchdog, chained) leave the counters stopped and are
 * reported in the trace.
 *
 * Period interrupts (dual unchained mode): when a half's counter matches its
 * PRD with INTCTLSTAT.PRDINTENxx set, PRDINTSTATxx is set (write 1 to clear)
 * and the half's TINT line is pulsed — TIMER64P1: TINT12_1 = AINTC 23,
 * TINT34_1 = 24 (the line LEGO's I2C bit engine ticks on).  A continuous
 * half then counts 0..PRD again, so its period is PRD + 1 input cycles.
 * TIMER64P3 (LEGO's free-running timestamp) has no interrupt modelled.
 * TIMER64P0/P1 are clocked from the 24 MHz oscillator (AM1808 TRM, device
 * clocking), P2/P3 from the ASYNC3 domain.
 */
#include <inttypes.h>
#include <string.h>

#include "rtos_host.h"
#include "host_sim/board.h"
#include "host_sim/clock.h"
#include "host_sim/intc.h"
#include "host_sim/regs.h"
#include "host_sim/timer64.h"
#include "soc_parts.h"

#define T_TIM12    0x10U
#define T_TIM34    0x14U
#define T_PRD12    0x18U
#define T_PRD34    0x1CU
#define T_TCR      0x20U
#define T_TGCR     0x24U
#define T_INTCTLSTAT 0x44U

#define INT_ENABLE_BITS  0x00050005U   /* PRDINTEN12/EVTINTEN12, PRDINTEN34/EVTINTEN34 */
#define INT_STATUS_BITS  0x000A000AU   /* the matching status bits (write 1 to clear) */
#define PRDINTEN(hi)     ((hi) ? 0x00010000U : 0x1U)
#define PRDINTSTAT(hi)   ((hi) ? 0x00020000U : 0x2U)

struct timer64;

struct half {
	uint64_t base_t;      /* virtual time of base_count */
	uint32_t base_count;
	hs_event_t prd_ev;    /* next period match, while its interrupt is enabled */
	struct timer64 *owner;
	bool hi;              /* TIM34 */
};

struct timer64 {
	const char *name;
	struct hs_region *region;
	uint32_t tgcr, tcr, prd12, prd34, intctl;   /* settings in effect */
	uint64_t hz[2];       /* half_hz of TIM12 and TIM34 under them (rates_update) */
	struct half h12, h34;
	uint64_t input_hz;
	INTNO tint[2];        /* TINT12, TINT34 lines; 0: no interrupt modelled */
};

static struct timer64 tm3, tm1;

/* Counting rate of half 12 (hi = false) or 34 under the settings in effect; 0 if stopped. */
static uint64_t half_hz(const struct timer64 *tm, bool hi)
{
	unsigned mode = (tm->tgcr >> 2) & 3U;
	unsigned ena = hi ? (tm->tcr >> 22) & 3U : (tm->tcr >> 6) & 3U;
	bool out_of_reset = hi ? (tm->tgcr & 2U) != 0 : (tm->tgcr & 1U) != 0;

	if (mode == 0U) {
		/* 64-bit: one counter enabled by ENAMODE12, both halves out of reset. */
		ena = (tm->tcr >> 6) & 3U;
		out_of_reset = (tm->tgcr & 3U) == 3U;
		return out_of_reset && ena ? tm->input_hz : 0U;
	}
	if (mode != 1U || !out_of_reset || ena == 0U)
		return 0U;
	return hi ? tm->input_hz / (((tm->tgcr >> 12) & 0xFU) + 1U) : tm->input_hz;
}

/* Value of a 32-bit half counting from h at hz, wrapping or stopping at prd. */
static uint32_t half_value(const struct half *h, uint64_t hz, uint32_t prd, bool one_shot, uint64_t now)
{
	uint64_t n;

	if (hz == 0)
		return h->base_count;
	n = h->base_count + hs_ns_to_cycles(now - h->base_t, hz);
	if (h->base_count > prd)                  /* past the period: counts up to wrap at 2^32 */
		return (uint32_t)n;
	if (one_shot)
		return n > prd ? prd : (uint32_t)n;
	if (prd == UINT32_MAX)                    /* the free-running stamp: the wrap is the cast's */
		return (uint32_t)n;
	return (uint32_t)(n % ((uint64_t)prd + 1U));
}

/* Redoes tm->hz after TGCR or TCR changed (the counters read them on every read). */
static void rates_update(struct timer64 *tm)
{
	tm->hz[0] = half_hz(tm, false);
	tm->hz[1] = half_hz(tm, true);
}

/* One counter (TIM34 if hi) at the current instant under the settings in effect. */
static uint32_t timer_value(const struct timer64 *tm, bool hi)
{
	uint64_t now = rtos_host_now();

	if (((tm->tgcr >> 2) & 3U) == 0U) {
		uint64_t hz = tm->hz[0];
		uint64_t base = ((uint64_t)tm->h34.base_count << 32) | tm->h12.base_count;
		uint64_t prd = ((uint64_t)tm->prd34 << 32) | tm->prd12;
		uint64_t n = base + (hz ? hs_ns_to_cycles(now - tm->h12.base_t, hz) : 0U);
		bool one_shot = ((tm->tcr >> 6) & 3U) == 1U;

		if (base <= prd && hz)
			n = one_shot ? (n > prd ? prd : n) : (prd == UINT64_MAX ? n : n % (prd + 1U));
		return hi ? (uint32_t)(n >> 32) : (uint32_t)n;
	}
	if (hi)
		return half_value(&tm->h34, tm->hz[1], tm->prd34, ((tm->tcr >> 22) & 3U) == 1U, now);
	return half_value(&tm->h12, tm->hz[0], tm->prd12, ((tm->tcr >> 6) & 3U) == 1U, now);
}

/* Freezes the counters at their current values as the new base (before a settings change). */
static void timer_rebase(struct timer64 *tm)
{
	uint32_t t12 = timer_value(tm, false), t34 = timer_value(tm, true);
	uint64_t now = rtos_host_now();

	tm->h12.base_count = t12;
	tm->h34.base_count = t34;
	tm->h12.base_t = tm->h34.base_t = now;
}

static void period_due(void *arg);

/* Schedules the next period match of a half whose interrupt is enabled (or cancels it). */
static void period_schedule(struct timer64 *tm, bool hi)
{
	struct half *h = hi ? &tm->h34 : &tm->h12;
	uint32_t prd = hi ? tm->prd34 : tm->prd12;
	uint64_t hz = tm->hz[hi];
	uint64_t now = rtos_host_now(), k, t;

	hs_event_cancel(&h->prd_ev);
	if (!tm->tint[hi] || !(tm->intctl & PRDINTEN(hi)) || !hz || ((tm->tgcr >> 2) & 3U) != 1U ||
	    h->base_count > prd)
		return;
	/* cycles from base until the counter next equals prd, strictly after now */
	k = (uint64_t)(prd - h->base_count);
	t = h->base_t + hs_cycles_to_ns(k, hz);
	if (t <= now) {
		bool one_shot = hi ? ((tm->tcr >> 22) & 3U) == 1U : ((tm->tcr >> 6) & 3U) == 1U;
		uint64_t elapsed, periods;

		if (one_shot)
			return;                        /* stopped at PRD: matched once already */
		elapsed = hs_ns_to_cycles(now - h->base_t, hz) - k;
		periods = elapsed / ((uint64_t)prd + 1U) + 1U;
		t = h->base_t + hs_cycles_to_ns(k + periods * ((uint64_t)prd + 1U), hz);
	}
	h->prd_ev = hs_event_at(t, period_due, h);
}

/* Event: a half's counter matched its period. */
static void period_due(void *arg)
{
	struct half *h = arg;
	struct timer64 *tm = h->owner;

	h->prd_ev = 0;
	tm->intctl |= PRDINTSTAT(h->hi);
	hs_reg_set(tm->region, T_INTCTLSTAT, tm->intctl);
	hs_intc_raise(tm->tint[h->hi]);
	period_schedule(tm, h->hi);
}

static void timer_reschedule(struct timer64 *tm)
{
	period_schedule(tm, false);
	period_schedule(tm, true);
}

uint32_t hs_timer64p3_tim12(void)
{
	return timer_value(&tm3, false);
}

uint32_t hs_timer64p3_tim34(void)
{
	return timer_value(&tm3, true);
}

uint64_t hs_timer64p3_tim34_hz(void)
{
	return ((tm3.tgcr >> 2) & 3U) == 0U ? 0U : tm3.hz[1];
}

uint64_t hs_timer64p1_tim34_hz(void)
{
	return ((tm1.tgcr >> 2) & 3U) == 0U ? 0U : tm1.hz[1];
}

static void tim_read(void *ctx, const struct hs_access *a, uint32_t *value)
{
	*value = timer_value(ctx, a->offset != T_TIM12);
}

/* tim_read as TIM12's direct read (regs.h). */
static uint32_t tim12_read_direct(const struct rtos_host_mmio_route *rt)
{
	const struct hs_direct *d = hs_direct_of(rt);

	return *d->value = timer_value(d->ctx, false);
}

/* tim_read as TIM34's direct read (regs.h). */
static uint32_t tim34_read_direct(const struct rtos_host_mmio_route *rt)
{
	const struct hs_direct *d = hs_direct_of(rt);

	return *d->value = timer_value(d->ctx, true);
}

static void tim_written(void *ctx, const struct hs_access *a, uint32_t old, uint32_t now, uint32_t written)
{
	struct timer64 *tm = ctx;

	(void)old; (void)written;
	timer_rebase(tm);
	if (a->offset == T_TIM12)
		tm->h12.base_count = now;
	else
		tm->h34.base_count = now;
	timer_reschedule(tm);
}

static void setting_written(void *ctx, const struct hs_access *a, uint32_t old, uint32_t now, uint32_t written)
{
	struct timer64 *tm = ctx;
	unsigned mode;

	(void)old; (void)written;
	timer_rebase(tm);
	switch (a->offset) {
	case T_TCR:
		tm->tcr = now;
		break;
	case T_TGCR:
		/* Putting a half into reset clears its counter. */
		if (!(now & 1U))
			tm->h12.base_count = 0;
		if (!(now & 2U))
			tm->h34.base_count = 0;
		tm->tgcr = now;
		mode = (now >> 2) & 3U;
		if (mode >= 2U)
			rtos_host_trace("host_sim", "%s: TIMMODE %u (%s) is not modelled; counters stopped",
					tm->name, mode, mode == 2U ? "watchdog" : "chained");
		break;
	case T_PRD12:
		tm->prd12 = now;
		break;
	default:
		tm->prd34 = now;
		break;
	}
	rates_update(tm);
	timer_reschedule(tm);
}

/* INTCTLSTAT: enables are plain bits, status bits are write-1-to-clear. */
static void intctl_written(void *ctx, const struct hs_access *a, uint32_t old, uint32_t now, uint32_t written)
{
	struct timer64 *tm = ctx;

	(void)a; (void)now;
	tm->intctl = (written & INT_ENABLE_BITS) | (old & INT_STATUS_BITS & ~written);
	hs_reg_set(tm->region, T_INTCTLSTAT, tm->intctl);
	timer_reschedule(tm);
}

static const struct hs_reg timer_regs[] = {
	{ .name = "REVID",      .offset = 0x00, .kind = HS_RO, .reset = 0x44720211 },
	{ .name = "EMUMGT",     .offset = 0x04, .kind = HS_RW, .mask = 0x3 },
	{ .name = "GPINTGPEN",  .offset = 0x08, .kind = HS_RW, .mask = 0x00030003 },
	{ .name = "GPDATGPDIR", .offset = 0x0C, .kind = HS_RW, .mask = 0x00030003 },
	{ .name = "TIM12",      .offset = T_TIM12, .kind = HS_RW, .before_read = tim_read, .after_write = tim_written,
	  .read_direct = tim12_read_direct },
	{ .name = "TIM34",      .offset = T_TIM34, .kind = HS_RW, .before_read = tim_read, .after_write = tim_written,
	  .read_direct = tim34_read_direct },
	{ .name = "PRD12",      .offset = T_PRD12, .kind = HS_RW, .after_write = setting_written },
	{ .name = "PRD34",      .offset = T_PRD34, .kind = HS_RW, .after_write = setting_written },
	{ .name = "TCR",        .offset = T_TCR, .kind = HS_RW, .mask = 0x03C003C3, .after_write = setting_written },
	{ .name = "TGCR",       .offset = T_TGCR, .kind = HS_RW, .mask = 0x0000FF1F, .after_write = setting_written },
	{ .name = "WDTCR",      .offset = 0x28, .kind = HS_RW, .mask = 0xFFFF4000 },
	{ .name = "REL12",      .offset = 0x34, .kind = HS_RW },
	{ .name = "REL34",      .offset = 0x38, .kind = HS_RW },
	{ .name = "CAP12",      .offset = 0x3C, .kind = HS_RO },
	{ .name = "CAP34",      .offset = 0x40, .kind = HS_RO },
	{ .name = "INTCTLSTAT", .offset = T_INTCTLSTAT, .kind = HS_RW, .mask = 0x000F000F,
	  .after_write = intctl_written },
	{ .name = "CMP",        .offset = 0x60, .kind = HS_RW, .count = 8 },
};

static ER timer_create(struct timer64 *tm, const char *name, uintptr_t phys, uint64_t hz,
		       INTNO tint12, INTNO tint34)
{
	memset(tm, 0, sizeof(*tm));
	tm->name = name;
	tm->input_hz = hz;
	tm->tint[0] = tint12;
	tm->tint[1] = tint34;
	tm->h12.owner = tm->h34.owner = tm;
	tm->h34.hi = true;
	tm->region = hs_region_add(&(struct hs_region_cfg){
		.name = name, .phys = phys, .size = 0x1000,
		.regs = timer_regs, .nregs = HS_ARRAY_SIZE(timer_regs), .power = HS_NO_PSC, .ctx = tm });
	return tm->region ? E_OK : E_SYS;
}

static void timer_destroy(struct timer64 *tm)
{
	hs_event_cancel(&tm->h12.prd_ev);
	hs_event_cancel(&tm->h34.prd_ev);
	memset(tm, 0, sizeof(*tm));
}

ER hs_timer64p3_create(bool cold)
{
	(void)cold;  /* Linux does not use TIMER64P3: reset state either way. */
	return timer_create(&tm3, "TIMER64P3", HS_TIMER64P3_BASE, HS_PLL1_SYSCLK2_HZ, 0, 0);
}

void hs_timer64p3_destroy(void)
{
	timer_destroy(&tm3);
}

ER hs_timer64p1_create(bool cold)
{
	(void)cold;  /* Linux leaves TIMER64P1 to drivers: reset state either way. */
	return timer_create(&tm1, "TIMER64P1", HS_TIMER64P1_BASE, HS_TIMER64P1_INPUT_HZ,
			    HS_TIMER64P1_TINT12, HS_TIMER64P1_TINT34);
}

void hs_timer64p1_destroy(void)
{
	timer_destroy(&tm1);
}
