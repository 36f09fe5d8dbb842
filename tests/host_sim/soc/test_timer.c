/*
 * test_timer.c — TIMER64P3 against the virtual clock, set up as d_pwm does
 * (dual 32-bit unchained, TIM34 prescaled /4 from 132 MHz = 33 MHz,
 * continuous, PRD34 = 0xFFFFFFFF): the count at any instant, the ~7.76 us
 * stamp of TIM34 >> 8, wrap at PRD, one-shot stop, reset and writes.
 */
#include "tap.h"
#include "sil.h"
#include "rtos_host.h"
#include "host_sim/board.h"
#include "host_sim/clock.h"
#include "host_sim/scenario.h"
#include "host_sim/timer64.h"

#define T3     0x01F0D000U
#define TIM12  (T3 + 0x10)
#define TIM34  (T3 + 0x14)
#define PRD12  (T3 + 0x18)
#define PRD34  (T3 + 0x1C)
#define TCR    (T3 + 0x20)
#define TGCR   (T3 + 0x24)

static uint32_t rd(uint32_t phys)
{
	return sil_rew_mem(rtos_host_map_io(phys, 4));
}

static void wr(uint32_t phys, uint32_t v)
{
	sil_wrw_mem(rtos_host_map_io(phys, 4), v);
}

static const struct rtos_cfg cfg = { .name = "timer" };

int main(void)
{
	struct hs_scenario scn = { .rtos = &cfg };
	uint64_t t_start, t;
	uint32_t v, s1, s2;

	tap_plan(15);
	if (hs_sim_boot(&scn) != E_OK)
		tap_bail_out("boot failed");

	is_int(rd(TIM34), 0, "stopped at reset");
	hs_sim_run_for(1000000);
	is_int(rd(TIM34), 0, "and stays stopped");

	/* d_pwm's setup */
	wr(TGCR, 0x3304);
	wr(TGCR, rd(TGCR) | 2U);
	wr(PRD34, 0xFFFFFFFFU);
	t_start = hs_now();
	wr(TCR, 0x00800000U);          /* the counter runs from the write's instant */
	is_u64(hs_timer64p3_tim34_hz(), 33000000, "TIM34 counts at 132 MHz / 4");

	hs_sim_run_for(1000000);
	t = hs_now();
	v = rd(TIM34);
	is_u64(v, hs_ns_to_cycles(t - t_start, 33000000), "TIM34 after ~1 ms equals the elapsed 33 MHz cycles");
	in_range(v, 33000, 33010, "about 33000 counts per ms");
	is_int(rd(TIM12), 0, "TIM12 does not run (ENAMODE12 = 0)");

	/* The stamp LEGO uses: TIM34 >> 8 advances every 256/33 MHz = 7.757 us. */
	s1 = hs_timer64p3_tim34() >> 8;
	hs_sim_run_for(7758);
	s2 = hs_timer64p3_tim34() >> 8;
	ok(s2 - s1 == 1U || s2 - s1 == 2U, "one stamp tick per ~7.76 us");
	s1 = hs_timer64p3_tim34() >> 8;
	hs_sim_run_for(100000000);
	s2 = hs_timer64p3_tim34() >> 8;
	in_range(s2 - s1, 12890, 12891, "100 ms = 12890.6 stamp ticks");

	/* Writing the counter sets it; it keeps counting from there. */
	t = hs_now();              /* a write takes effect at its instant; its 50-ns cost follows */
	wr(TIM34, 1000);
	hs_sim_run_for(1000);
	is_u64(hs_timer64p3_tim34(), 1000 + hs_ns_to_cycles(hs_now() - t, 33000000),
	       "a written count continues from the written value");

	/* Continuous mode wraps after PRD. */
	wr(TCR, 0);
	wr(PRD34, 99);
	wr(TIM34, 0);
	t = hs_now();
	wr(TCR, 0x00800000U);
	hs_sim_run_for(10000);                 /* 330 counts: 3 wraps of 100 */
	is_u64(hs_timer64p3_tim34(), hs_ns_to_cycles(hs_now() - t, 33000000) % 100, "wraps to 0 after PRD");
	/* One-shot stops at PRD. */
	wr(TCR, 0);
	wr(TIM34, 0);
	wr(TCR, 0x00400000U);
	hs_sim_run_for(10000);
	is_int(hs_timer64p3_tim34(), 99, "one-shot stops at PRD");
	/* Stopping freezes, reset clears. */
	wr(TCR, 0);
	v = hs_timer64p3_tim34();
	hs_sim_run_for(10000);
	is_int(hs_timer64p3_tim34(), v, "ENAMODE 0 freezes the count");
	wr(TGCR, 0x3304);
	is_int(rd(TIM34), 0, "TIM34RS = 0 holds the half in reset at 0");
	/* 64-bit mode: TIM34:TIM12 one counter at the input clock, read a half at a time. */
	wr(TGCR, 0x0003);
	wr(PRD12, 0xFFFFFFFFU);
	wr(PRD34, 0xFFFFFFFFU);
	wr(TIM12, 0xFFFFFF00U);
	wr(TIM34, 7);
	t = hs_now();
	wr(TCR, 0x00000080U);
	hs_sim_run_for(10000);
	v = (uint32_t)hs_ns_to_cycles(hs_now() - t, 132000000);
	is_int(rd(TIM12), (uint32_t)(0xFFFFFF00U + v), "64-bit mode: TIM12 is the low half of the count");
	is_int(rd(TIM34), 8, "and TIM34 the high half, carried into");
	hs_sim_shutdown();
	return tap_done();
}
