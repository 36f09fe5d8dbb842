/*
 * test_example.c — the "modelling a new peripheral" example of
 * docs/host-sim.md (copied from it; keep the two in step), run: it must
 * compile and behave as described.
 */
#include "tap.h"
#include "sil.h"
#include "rtos_host.h"
#include "host_sim/scenario.h"

#include "host_sim/board.h"
#include "host_sim/clock.h"
#include "host_sim/intc.h"
#include "host_sim/regs.h"

#define TT_CTL 0x0
#define TT_CNT 0x4
#define TT_CMP 0x8
#define TT_STS 0xC

struct tiny_timer {
	struct hs_region *r;
	uint64_t t0;            /* virtual time the count was 0 */
	hs_event_t match;
};

static void tt_match(void *arg)
{
	struct tiny_timer *tt = arg;

	tt->match = 0;
	hs_reg_update(tt->r, TT_STS, 0, 1);        /* model-side: no hooks, no CPU time */
	hs_intc_raise(99);
}

/* Schedules the compare event from the current settings. */
static void tt_arm(struct tiny_timer *tt)
{
	hs_event_cancel(&tt->match);
	if (hs_reg_get(tt->r, TT_CTL) & 1)
		tt->match = hs_event_at(tt->t0 + hs_cycles_to_ns(hs_reg_get(tt->r, TT_CMP), 1000000),
					tt_match, tt);
}

static void tt_cnt_read(void *ctx, const struct hs_access *a, uint32_t *value)
{
	struct tiny_timer *tt = ctx;

	if (hs_reg_get(tt->r, TT_CTL) & 1)
		*value = (uint32_t)hs_ns_to_cycles(hs_now() - tt->t0, 1000000);
}

static void tt_written(void *ctx, const struct hs_access *a, uint32_t old, uint32_t now, uint32_t written)
{
	struct tiny_timer *tt = ctx;

	if (a->offset == TT_CTL && (now & 1) && !(old & 1))
		tt->t0 = hs_now();                  /* start counting from 0 */
	tt_arm(tt);
}

static const struct hs_reg tt_regs[] = {
	{ .name = "REVID", .offset = 0x10, .kind = HS_RO,  .reset = 0x00010000 },
	{ .name = "CTL",   .offset = TT_CTL, .kind = HS_RW, .mask = 0x1, .after_write = tt_written },
	{ .name = "CNT",   .offset = TT_CNT, .kind = HS_RO, .before_read = tt_cnt_read },
	{ .name = "CMP",   .offset = TT_CMP, .kind = HS_RW, .after_write = tt_written },
	{ .name = "STS",   .offset = TT_STS, .kind = HS_W1C, .mask = 0x1 },
};

static struct tiny_timer the_timer;

static ER tt_create(const struct hs_board_cfg *cfg, void **ctx)
{
	the_timer.r = hs_region_add(&(struct hs_region_cfg){
		.name = "TINYTIMER", .phys = 0x01F0E000, .size = 0x1000,
		.regs = tt_regs, .nregs = HS_ARRAY_SIZE(tt_regs),
		.power = HS_NO_PSC, .ctx = &the_timer });
	*ctx = &the_timer;
	return the_timer.r ? E_OK : E_SYS;
}

static const struct hs_device tiny_timer_device = { .name = "tiny timer", .create = tt_create };

static unsigned isr_runs;
static uint64_t isr_time;

static void tt_isr(intptr_t x)
{
	(void)x;
	isr_runs++;
	isr_time = hs_now();
	sil_wrw_mem(rtos_host_map_io(0x01F0E000 + TT_STS, 4), 1);
}

static const struct rtos_int_cfg ints[] = { { 99, TA_ENAINT, -2 } };
static const struct rtos_isr_cfg isrs[] = { { TA_NULL, 0, 99, tt_isr, 1 } };
static const struct rtos_cfg cfg = { .name = "example", .ints = RTOS_TABLE(ints), .isrs = RTOS_TABLE(isrs) };
static const struct hs_device *const devices[] = { &tiny_timer_device, NULL };

int main(void)
{
	struct hs_scenario scn = { .rtos = &cfg, .board = &(struct hs_board_cfg){ .devices = devices } };
	volatile uint32_t *w;
	uint64_t t_on;

	tap_plan(5);
	if (hs_sim_boot(&scn) != E_OK)
		tap_bail_out("boot failed");
	w = rtos_host_map_io(0x01F0E000, 0x20);
	sil_wrw_mem((uint32_t *)w + TT_CMP / 4, 100);
	t_on = hs_now();
	sil_wrw_mem((uint32_t *)w + TT_CTL / 4, 1);
	hs_sim_run_for(50000);
	in_range(sil_rew_mem((uint32_t *)w + TT_CNT / 4), 50, 51, "the count runs at 1 MHz");
	hs_sim_run_for(100000);
	is_int(isr_runs, 1, "the compare match raised interrupt 99 once");
	is_u64(isr_time, t_on + 100000, "at 100 counts after the start");
	is_int(sil_rew_mem((uint32_t *)w + TT_STS / 4), 0, "the ISR cleared the W1C status");
	rtos_host_expect_bugs(true);
	sil_wrw_mem((uint32_t *)w + TT_CNT / 4, 5);
	ok(rtos_host_bug_count() == 1, "writing the read-only count is reported");
	rtos_host_expect_bugs(false);
	hs_sim_shutdown();
	return tap_done();
}
