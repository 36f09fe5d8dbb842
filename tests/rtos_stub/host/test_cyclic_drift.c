/*
 * test_cyclic_drift.c — a cyclic handler over 1 000 000 periods: every
 * activation k happens at exactly phase + k * period of virtual time (no
 * drift, ever), and the idle tick path is cheap enough to do it quickly.
 */
#define _POSIX_C_SOURCE 200809L
#include <time.h>

#include "tap.h"
#include "kernel.h"
#include "rtos_host.h"

#define PERIODS 1000000ULL
#define PERIOD_MS 1U
#define PHASE_MS 3U

static uint64_t activations;
static uint64_t late;
static uint64_t first_late_k = UINT64_MAX;

static void cyc(intptr_t x)
{
	uint64_t expected = (PHASE_MS + activations * PERIOD_MS) * 1000000ULL;

	if (rtos_host_now() != expected) {
		late++;
		if (first_late_k == UINT64_MAX)
			first_late_k = activations;
	}
	activations++;
}

/* A 7 ms period is not a multiple of... anything special: check exact tick boundaries too. */
static uint64_t odd_count, odd_bad;
static void cyc_odd(intptr_t x)
{
	uint64_t expected = 7000000ULL * (odd_count + 1);

	if (rtos_host_now() != expected)
		odd_bad++;
	odd_count++;
}

static const struct rtos_cyc_cfg cycs[] = {
	{ 1, TA_STA, 0, cyc, PERIOD_MS, PHASE_MS, "drift" },
	{ 2, TA_STA, 0, cyc_odd, 7, 7, "odd" },
};
static const struct rtos_cfg cfg = { .name = "drift", .cycs = RTOS_TABLE(cycs) };

int main(void)
{
	struct timespec t0, t1;
	double secs;

	tap_plan(5);
	is_int(rtos_host_boot(&cfg), E_OK, "boot");
	clock_gettime(CLOCK_MONOTONIC, &t0);
	rtos_host_run_until((PHASE_MS + (PERIODS - 1) * PERIOD_MS) * 1000000ULL);
	clock_gettime(CLOCK_MONOTONIC, &t1);
	secs = (double)(t1.tv_sec - t0.tv_sec) + (double)(t1.tv_nsec - t0.tv_nsec) / 1e9;
	is_u64(activations, PERIODS, "exactly 1 000 000 activations");
	is_u64(late, 0, "every activation at exactly phase + k * period (no drift)");
	if (late)
		tap_diag("first off-grid activation k=%llu", (unsigned long long)first_late_k);
	ok(odd_count > 100000 && odd_bad == 0, "a second cyclic (7 ms) stays on its grid too (%llu activations)",
	   (unsigned long long)odd_count);
	tap_diag("%.0f s of virtual time in %.3f s of host time (%.0fx real time)",
		 (double)rtos_host_now() / 1e9, secs, (double)rtos_host_now() / 1e9 / secs);
	ok(secs < 30.0, "fast enough (%.3f s host time)", secs);
	rtos_host_shutdown();
	return tap_done();
}
