/*
 * test_interrupt_order.c — 2000 random batches of requests on 12 lines
 * (edges, levels asserted and released, latched edges cleared, lines
 * enabled and disabled, all under a SIL lock) come out at the unlock in the
 * order of a model that scans every line before each delivery: the most
 * urgent pending enabled line, the lowest number among equal priorities;
 * disabled lines stay pending for a later batch.
 */
#include <stdio.h>
#include <string.h>

#include "tap.h"
#include "kernel.h"
#include "sil.h"
#include "rtos_test.h"

#define NLINES   12U
#define BATCHES  2000U
#define LOG_MAX  64U

/* Line numbers out of priority order, several priorities shared. */
static const INTNO line_no[NLINES] = { 70, 12, 95, 40, 41, 3, 127, 64, 63, 88, 20, 22 };
static const PRI line_pri[NLINES] = { -2, -2, -5, -1, -5, -3, -7, -2, -4, -1, -3, -7 };

static struct {
	bool edge, level, enabled;
} model[NLINES];

static uint32_t rng_state = 12345U;
static uint8_t delivered[LOG_MAX], expected[LOG_MAX];
static unsigned ndelivered, nexpected, mismatches;
static unsigned deliveries;

/* A small deterministic generator (the test needs no quality). */
static uint32_t rng_below(uint32_t n)
{
	rng_state = rng_state * 1103515245U + 12345U;
	return (rng_state >> 16) % n;
}

/* The ISR of line index x: logged; a level line releases its request. */
static void isr_note(intptr_t x)
{
	if (ndelivered < LOG_MAX)
		delivered[ndelivered++] = (uint8_t)x;
	if (model[x].level)
		rtos_host_irq_set_level(line_no[x], false);
}

/* The model's deliveries at the unlock: scans every line before each. */
static void model_deliver(void)
{
	for (;;) {
		int best = -1;

		for (unsigned i = 0; i < NLINES; i++) {
			if (!model[i].enabled || !(model[i].edge || model[i].level))
				continue;
			if (best < 0 || line_pri[i] < line_pri[best] ||
			    (line_pri[i] == line_pri[best] && line_no[i] < line_no[best]))
				best = (int)i;
		}
		if (best < 0)
			return;
		if (nexpected < LOG_MAX)
			expected[nexpected++] = (uint8_t)best;
		model[best].edge = false;
		model[best].level = false;
	}
}

/* One random change of line i, on the kernel and on the model. */
static void random_change(unsigned i)
{
	switch (rng_below(6)) {
	case 0:
	case 1:
		rtos_host_irq_raise(line_no[i]);
		model[i].edge = true;
		break;
	case 2:
		rtos_host_irq_set_level(line_no[i], true);
		model[i].level = true;
		break;
	case 3:
		rtos_host_irq_clear(line_no[i]);
		model[i].edge = false;
		break;
	case 4:
		ena_int(line_no[i]);
		model[i].enabled = true;
		break;
	default:
		dis_int(line_no[i]);
		model[i].enabled = false;
		break;
	}
}

static void main_task(intptr_t x)
{
	(void)x;
	for (unsigned i = 0; i < NLINES; i++)
		model[i].enabled = true;
	for (unsigned b = 0; b < BATCHES; b++) {
		SIL_PRE_LOC;
		unsigned changes = 1U + rng_below(16);

		ndelivered = nexpected = 0;
		SIL_LOC_INT();
		for (unsigned c = 0; c < changes; c++)
			random_change(rng_below(NLINES));
		SIL_UNL_INT();
		model_deliver();
		deliveries += ndelivered;
		if (ndelivered != nexpected || memcmp(delivered, expected, ndelivered) != 0) {
			if (mismatches++ == 0)
				tap_diag("batch %u: %u delivered, %u expected", b, ndelivered, nexpected);
		}
	}
}

static const struct rtos_task_cfg tasks[] = {
	{ 1, TA_ACT, 0, main_task, 5, 4096, TDOM_KERNEL, "main" },
};
static const struct rtos_int_cfg ints[] = {
	{ 70, TA_ENAINT, -2 }, { 12, TA_ENAINT, -2 }, { 95, TA_ENAINT, -5 }, { 40, TA_ENAINT, -1 },
	{ 41, TA_ENAINT, -5 }, { 3, TA_ENAINT, -3 }, { 127, TA_ENAINT, -7 }, { 64, TA_ENAINT, -2 },
	{ 63, TA_ENAINT, -4 }, { 88, TA_ENAINT, -1 }, { 20, TA_ENAINT, -3 }, { 22, TA_ENAINT, -7 },
};
static const struct rtos_isr_cfg isrs[] = {
	{ TA_NULL, 0, 70, isr_note, 1 }, { TA_NULL, 1, 12, isr_note, 1 }, { TA_NULL, 2, 95, isr_note, 1 },
	{ TA_NULL, 3, 40, isr_note, 1 }, { TA_NULL, 4, 41, isr_note, 1 }, { TA_NULL, 5, 3, isr_note, 1 },
	{ TA_NULL, 6, 127, isr_note, 1 }, { TA_NULL, 7, 64, isr_note, 1 }, { TA_NULL, 8, 63, isr_note, 1 },
	{ TA_NULL, 9, 88, isr_note, 1 }, { TA_NULL, 10, 20, isr_note, 1 }, { TA_NULL, 11, 22, isr_note, 1 },
};
static const struct rtos_cfg cfg = {
	.name = "interrupt_order", .tasks = RTOS_TABLE(tasks), .ints = RTOS_TABLE(ints), .isrs = RTOS_TABLE(isrs),
};

int main(void)
{
	bool table_matches = true;

	tap_plan(4);
	for (unsigned i = 0; i < NLINES; i++)
		if (ints[i].intno != line_no[i] || ints[i].intpri != line_pri[i])
			table_matches = false;
	ok(table_matches, "the CFG_INT rows match the model's lines");
	is_int(rtos_host_boot(&cfg), E_OK, "boot");
	rtos_host_run_for(1000000000ULL);
	tap_diag("%u deliveries", deliveries);
	ok(deliveries > BATCHES, "the batches delivered many interrupts");
	is_int((int)mismatches, 0, "every batch came out in the model's order");
	rtos_host_shutdown();
	return tap_done();
}
