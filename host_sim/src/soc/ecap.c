/*
 * ecap.c — eCAP0/1 in APWM mode (AM1808 TRM chapter "eCAP"), reduced to
 * what a motor sees: the fraction of each period the output is low,
 * recomputed whenever it can change (a register write that acts at once, or
 * the shadow load at the period, an event at that exact instant).  The
 * counter is computed from the virtual clock.
 */
#include <stdlib.h>
#include "rtos_host.h"
#include "host_sim/clock.h"
#include "host_sim/psc.h"
#include "host_sim/regs.h"
#include "host_sim/devices/pwm.h"
#include "pwm_outputs.h"

#define PWM_CLOCK_HZ HS_PLL1_SYSCLK2_HZ

/* ---- eCAP0/1 in APWM mode ---- */

enum {
	TSCTR = 0x00, CTRPHS = 0x04, CAP1 = 0x08, CAP2 = 0x0C, CAP3 = 0x10, CAP4 = 0x14,
	ECCTL1 = 0x28, ECCTL2 = 0x2A, ECEINT = 0x2C, ECFLG = 0x2E, ECCLR = 0x30, ECFRC = 0x32,
	ECAP_REVID = 0x5C,
};
#define ECCTL2_TSCTRSTOP (1U << 4)
#define ECCTL2_APWM      (1U << 9)
#define ECCTL2_APWMPOL   (1U << 10)

struct ecap {
	struct hs_region *r;
	enum hs_pwm_output src;
	bool running;
	uint64_t t_ref;
	uint32_t cnt_ref;
	hs_event_t load_ev;
	double low;
};

/* eCAP counter now. */
static uint32_t ecap_counter(const struct ecap *c)
{
	uint64_t period = (uint64_t)hs_reg_get(c->r, CAP1) + 1U;
	uint64_t cnt = c->cnt_ref;

	if (c->running)
		cnt += hs_ns_to_cycles(hs_now() - c->t_ref, PWM_CLOCK_HZ);
	if (!(hs_reg_get(c->r, ECCTL2) & ECCTL2_APWM))
		return (uint32_t)cnt;
	return (uint32_t)(cnt % period);
}

/* Recomputes the APWM low fraction; tells the motors. */
static void ecap_update(struct ecap *c)
{
	uint32_t ctl2 = hs_reg_get(c->r, ECCTL2);
	uint64_t period = (uint64_t)hs_reg_get(c->r, CAP1) + 1U;
	uint64_t cmp = hs_reg_get(c->r, CAP2);
	bool active_low = ctl2 & ECCTL2_APWMPOL;
	double active, low;

	if (!(ctl2 & ECCTL2_APWM)) {
		low = 1.0;              /* capture mode: the pin is an input, the bridge sees low */
	} else if (!c->running) {
		bool act = ecap_counter(c) < cmp;

		low = (act == active_low) ? 1.0 : 0.0;
	} else {
		active = (double)(cmp < period ? cmp : period) / (double)period;
		low = active_low ? active : 1.0 - active;
	}
	if (low != c->low) {
		c->low = low;
		hs_pwm_output_changed(c->src);
	}
}

static void ecap_schedule_load(struct ecap *c);

/* Event: counter equals the period: CAP3/CAP4 shadows become active. */
static void ecap_load(void *arg)
{
	struct ecap *c = arg;

	c->load_ev = 0;
	c->cnt_ref = ecap_counter(c);
	c->t_ref = hs_now();
	hs_reg_set(c->r, CAP1, hs_reg_get(c->r, CAP3));
	hs_reg_set(c->r, CAP2, hs_reg_get(c->r, CAP4));
	ecap_update(c);
}

/* Schedules the shadow load at the next period if a shadow differs. */
static void ecap_schedule_load(struct ecap *c)
{
	uint32_t prd = hs_reg_get(c->r, CAP1), cnt;

	hs_event_cancel(&c->load_ev);
	if (!c->running || (hs_reg_get(c->r, CAP3) == prd && hs_reg_get(c->r, CAP4) == hs_reg_get(c->r, CAP2)))
		return;
	cnt = ecap_counter(c);
	c->load_ev = hs_event_after(hs_cycles_to_ns(cnt < prd ? prd - cnt : (uint64_t)prd + 1U, PWM_CLOCK_HZ),
				    ecap_load, c);
}

/* Re-bases the counter at now and re-reads ECCTL2. */
static void ecap_rebase(struct ecap *c)
{
	uint32_t ctl2 = hs_reg_get(c->r, ECCTL2);

	c->cnt_ref = ecap_counter(c);
	c->t_ref = hs_now();
	c->running = (ctl2 & ECCTL2_TSCTRSTOP) != 0;
	ecap_update(c);
	ecap_schedule_load(c);
}

/* TSCTR read: the counter now. */
static void ecap_read_tsctr(void *ctx, const struct hs_access *a, uint32_t *value)
{
	*value = ecap_counter(ctx);
}

/* eCAP register writes. */
static void ecap_write(void *ctx, const struct hs_access *a, uint32_t old, uint32_t nv, uint32_t written)
{
	struct ecap *c = ctx;
	bool apwm = hs_reg_get(c->r, ECCTL2) & ECCTL2_APWM;

	switch (a->offset) {
	case TSCTR:     /* a 16-bit half replaces that half of the running count */
		if (a->width < 4U) {
			uint32_t lanes = (0xFFFFFFFFU >> (32U - 8U * a->width)) << (8U * a->lane);

			nv = (ecap_counter(c) & ~lanes) | (nv & lanes);
		}
		c->cnt_ref = nv;
		c->t_ref = hs_now();
		break;
	case CAP1:      /* in APWM mode a write to an active register also sets its shadow */
		if (apwm)
			hs_reg_set(c->r, CAP3, nv);
		break;
	case CAP2:
		if (apwm)
			hs_reg_set(c->r, CAP4, nv);
		break;
	case ECEINT:
		if (nv)
			rtos_host_bug("host_sim", "%s.ECEINT = 0x%04x: eCAP interrupts are not modelled",
				      hs_region_name(c->r), (unsigned)nv);
		break;
	default:
		break;
	}
	ecap_rebase(c);
}

static const struct hs_reg ecap_regs[] = {
	/* TSCTR and CTRPHS take 16-bit halves, as CAP1..4 do: the eCAP's registers
	 * sit on a 32-bit peripheral bus with byte enables (AM1808 TRM, eCAP
	 * chapter, register map: 32-bit TSCTR/CTRPHS/CAPx beside the 16-bit
	 * ECCTLx; LEGO's d_pwm clears their low halves through a UWORD pointer). */
	{ .name = "TSCTR", .offset = TSCTR, .widths = HS_W16, .kind = HS_RW, .before_read = ecap_read_tsctr,
	  .after_write = ecap_write },
	{ .name = "CTRPHS", .offset = CTRPHS, .widths = HS_W16, .kind = HS_RW },
	{ .name = "CAP1", .offset = CAP1, .widths = HS_W16, .kind = HS_RW, .after_write = ecap_write },
	{ .name = "CAP2", .offset = CAP2, .widths = HS_W16, .kind = HS_RW, .after_write = ecap_write },
	{ .name = "CAP3", .offset = CAP3, .widths = HS_W16, .kind = HS_RW, .after_write = ecap_write },
	{ .name = "CAP4", .offset = CAP4, .widths = HS_W16, .kind = HS_RW, .after_write = ecap_write },
	{ .name = "ECCTL1", .offset = ECCTL1, .width = 2, .kind = HS_RW },
	{ .name = "ECCTL2", .offset = ECCTL2, .width = 2, .kind = HS_RW, .reset = 0x0006, .mask = 0x06FF,
	  .after_write = ecap_write },
	{ .name = "ECEINT", .offset = ECEINT, .width = 2, .kind = HS_RW, .after_write = ecap_write },
	{ .name = "ECFLG", .offset = ECFLG, .width = 2, .kind = HS_RO },
	{ .name = "ECCLR", .offset = ECCLR, .width = 2, .kind = HS_W1C, .alias = "ECFLG" },
	{ .name = "ECFRC", .offset = ECFRC, .width = 2, .kind = HS_RW },
	{ .name = "REVID", .offset = ECAP_REVID, .kind = HS_RO, .reset = 0x44D22100 },
};

/* Low fraction of the APWM output. */
static double ecap_low_fraction(const void *ctx, unsigned channel)
{
	const struct ecap *c = ctx;

	(void)channel;
	return c->low;
}

/* APWM frequency in Hz (0 if stopped). */
static double ecap_frequency(const void *ctx, unsigned channel)
{
	const struct ecap *c = ctx;

	(void)channel;
	if (!c->running)
		return 0;
	return (double)PWM_CLOCK_HZ / ((double)hs_reg_get(c->r, CAP1) + 1.0);
}

static const struct hs_pwm_source_ops ecap_ops = { ecap_low_fraction, ecap_frequency };

/* Creates eCAP n. */
static ER ecap_create_n(unsigned n, void **ctx)
{
	struct ecap *c = calloc(1, sizeof(*c));

	if (!c)
		return E_NOMEM;
	c->src = n ? HS_PWM_ECAP1 : HS_PWM_ECAP0;
	c->r = hs_region_add(&(struct hs_region_cfg){ .name = n ? "ECAP1" : "ECAP0",
		.phys = n ? HS_ECAP1_BASE : HS_ECAP0_BASE, .size = 0x1000, .regs = ecap_regs,
		.nregs = HS_ARRAY_SIZE(ecap_regs), .power = HS_PSC1_MODULE(HS_LPSC1_ECAP), .ctx = c });
	if (!c->r) {
		free(c);
		return E_PAR;
	}
	c->low = 1.0;
	hs_pwm_output_attach(c->src, &ecap_ops, c, 0);
	*ctx = c;
	return E_OK;
}

/* Board device: eCAP0. */
static ER ecap0_create(const struct hs_board_cfg *cfg, void **ctx)
{
	return ecap_create_n(0, ctx);
}

/* Board device: eCAP1. */
static ER ecap1_create(const struct hs_board_cfg *cfg, void **ctx)
{
	return ecap_create_n(1, ctx);
}

/* Frees an eCAP. */
static void ecap_destroy(void *ctx)
{
	struct ecap *c = ctx;

	hs_event_cancel(&c->load_ev);
	hs_pwm_output_attach(c->src, NULL, NULL, 0);
	free(c);
}

const struct hs_device hs_ecap0_device = { "ECAP0", ecap0_create, NULL, ecap_destroy };
const struct hs_device hs_ecap1_device = { "ECAP1", ecap1_create, NULL, ecap_destroy };
