/*
 * test_trace.c — traces: a run with pin edges, interrupts, a numeric and a
 * real signal writes a VCD (header, scopes, initial values, timestamps in
 * ns) and a CSV; the same seed gives byte-identical files, another seed
 * different ones; the PRNG streams are deterministic and per-name.
 */
#define _POSIX_C_SOURCE 200809L
#include <stdio.h>
#include <stdlib.h>
#include <string.h>
#include <unistd.h>

#include "tap.h"
#include "sil.h"
#include "rtos_host.h"
#include "host_sim/board.h"
#include "host_sim/clock.h"
#include "host_sim/gpio.h"
#include "host_sim/scenario.h"
#include "host_sim/trace.h"

#define GPIO       0x01E26000U
#define PAIR2      (GPIO + HS_GPIO_PAIR_OFFSET(64U))
#define TACHO      HS_GPIO(5, 11)
#define TACHO_BIT  (1U << 27)

static struct {
	struct hs_rng rng;
	struct hs_signal *count, *angle;
	uint64_t edges;
	bool level;
} model;

static void edge(void *arg)
{
	(void)arg;
	model.level = !model.level;
	hs_gpio_set_input(TACHO, model.level);
	hs_trace_set(model.count, ++model.edges);
	hs_trace_set_real(model.angle, (double)model.edges * 0.5 + hs_rng_gauss(&model.rng) * 0.01);
	hs_event_after(20000 + hs_rng_below(&model.rng, 200000), edge, NULL);
}

static void bank5_isr(intptr_t x)
{
	uint32_t st = sil_rew_mem(rtos_host_map_io(PAIR2 + 0x24, 4));

	(void)x;
	sil_wrw_mem(rtos_host_map_io(PAIR2 + 0x24, 4), st);
}

static const struct rtos_int_cfg ints[] = { { HS_GPIO_BANK_INTNO(5), TA_ENAINT, -3 } };
static const struct rtos_isr_cfg isrs[] = { { TA_NULL, 0, HS_GPIO_BANK_INTNO(5), bank5_isr, 1 } };
static const struct rtos_cfg cfg = { .name = "trace", .ints = RTOS_TABLE(ints), .isrs = RTOS_TABLE(isrs) };

/* Runs 50 ms of the scenario with seed, writing vcd and csv. */
static bool run(uint64_t seed, const char *vcd, const char *csv)
{
	struct hs_scenario scn = { .rtos = &cfg, .seed = seed, .vcd_path = vcd, .csv_path = csv };

	memset(&model, 0, sizeof(model));
	if (hs_sim_boot(&scn) != E_OK)
		return false;
	hs_rng_stream(&model.rng, "tacho");
	model.count = hs_trace_signal("motorA", "edges", 16);
	model.angle = hs_trace_signal_real("motorA", "angle");
	sil_wrw_mem(rtos_host_map_io(GPIO + 0x08, 4), 1U << 5);
	sil_wrw_mem(rtos_host_map_io(PAIR2 + 0x14, 4), TACHO_BIT);
	sil_wrw_mem(rtos_host_map_io(PAIR2 + 0x1C, 4), TACHO_BIT);
	hs_gpio_drive(TACHO, HS_EXT_LOW);
	hs_event_after(1000, edge, NULL);
	hs_sim_run_for(50000000);
	hs_sim_shutdown();
	return true;
}

/* Whole file into a malloc'd string (NULL if unreadable). */
static char *slurp(const char *path, size_t *len)
{
	FILE *f = fopen(path, "rb");
	char *buf;
	long n;

	if (!f)
		return NULL;
	fseek(f, 0, SEEK_END);
	n = ftell(f);
	rewind(f);
	buf = malloc((size_t)n + 1U);
	*len = fread(buf, 1, (size_t)n, f);
	buf[*len] = '\0';
	fclose(f);
	return buf;
}

int main(void)
{
	char p[6][64];
	char *a, *b, *c, *ca, *cb;
	size_t la, lb, lc, lca, lcb;
	struct hs_rng r1, r2;
	bool mono = true;
	uint64_t last = 0;

	tap_plan(14);
	for (int i = 0; i < 6; i++)
		snprintf(p[i], sizeof(p[i]), "/tmp/ev3lx-trace-%d-%d.%s", (int)getpid(), i, i % 2 ? "csv" : "vcd");
	ok(run(7, p[0], p[1]) && run(7, p[2], p[3]) && run(8, p[4], p[5]), "three runs (seeds 7, 7, 8)");
	a = slurp(p[0], &la);
	b = slurp(p[2], &lb);
	c = slurp(p[4], &lc);
	ca = slurp(p[1], &lca);
	cb = slurp(p[3], &lcb);
	ok(a && b && c && ca && cb, "files written");
	ok(la == lb && memcmp(a, b, la) == 0, "same seed: byte-identical VCD (%zu bytes)", la);
	ok(lca == lcb && memcmp(ca, cb, lca) == 0, "same seed: byte-identical CSV (%zu bytes)", lca);
	ok(la != lc || memcmp(a, c, la) != 0, "another seed: a different VCD");
	ok(strstr(a, "$timescale 1ns $end") && strstr(a, "$enddefinitions $end") && strstr(a, "$dumpvars"),
	   "VCD header: timescale, definitions, initial values");
	ok(strstr(a, "$scope module gpio $end") && strstr(a, " GP5_11 $end") &&
	   strstr(a, "$scope module irq $end") && strstr(a, " int47_gpio_b5 $end"),
	   "GPIO pins and interrupt lines are declared");
	ok(strstr(a, "$var wire 16 ") && strstr(a, " edges $end") && strstr(a, "$var real 64 ") && strstr(a, " angle $end"),
	   "model signals: a 16-bit vector and a real");
	for (const char *q = a; q && *q; q = strchr(q, '\n') ? strchr(q, '\n') + 1 : NULL) {
		if (q[0] == '#') {
			uint64_t t = strtoull(q + 1, NULL, 10);

			if (t < last)
				mono = false;
			last = t;
		}
	}
	ok(mono && last > 40000000, "timestamps in ns, increasing, up to the end of the run");
	ok(strncmp(ca, "time_ns,signal,value\n", 21) == 0 && strstr(ca, ",motorA.edges,1\n") && strstr(ca, ",motorA.angle,"),
	   "CSV: header and numeric signals");
	ok(!strstr(ca, "GP5_11"), "CSV leaves out 1-bit signals");

	hs_rng_seed(&r1, 42);
	hs_rng_seed(&r2, 42);
	ok(hs_rng_next(&r1) == hs_rng_next(&r2) && hs_rng_below(&r1, 10) == hs_rng_below(&r2, 10), "PRNG: same seed, same numbers");
	{
		struct hs_rng s1, s2;
		double sum = 0, sq = 0;

		hs_rng_stream(&s1, "a");
		hs_rng_stream(&s2, "b");
		for (int i = 0; i < 10000; i++) {
			double g = hs_rng_gauss(&r1);

			sum += g;
			sq += g * g;
		}
		ok(hs_rng_next(&s1) != hs_rng_next(&s2) && sum / 10000 > -0.05 && sum / 10000 < 0.05 &&
		   sq / 10000 > 0.95 && sq / 10000 < 1.05, "PRNG: named streams differ; gauss has mean 0, variance 1");
	}
	{
		/* a pair set at one instant counts each signal's own changes */
		struct hs_signal *pa = hs_trace_signal_real("pair", "a"), *pb = hs_trace_signal_real("pair", "b");

		hs_trace_set_real_pair(pa, 1.0, pb, 2.0);
		hs_trace_set_real_pair(pa, 1.0, pb, 3.0);
		ok(hs_signal_real(pa) == 1.0 && hs_signal_real(pb) == 3.0 && hs_signal_changes(pa) == 1 &&
		   hs_signal_changes(pb) == 2, "a pair of real signals: values and changes as set one by one");
	}
	free(a); free(b); free(c); free(ca); free(cb);
	for (int i = 0; i < 6; i++)
		unlink(p[i]);
	return tap_done();
}
