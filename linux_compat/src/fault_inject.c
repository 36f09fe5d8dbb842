/*
 * fault_inject.c — allocation-failure injection (linux_compat/fault_inject.h).
 * The generator is xorshift32: deterministic, the same on both targets.
 */
#include <linux_compat/fault_inject.h>
#include <sil.h>

static struct {
	unsigned long nth;        /* 0: nth mode off */
	unsigned int percent;     /* 0: probability mode off */
	uint32_t seed;
	long times;               /* failures allowed per boot in probability mode, -1: no limit */
} setting;

static struct {
	unsigned long attempts;
	unsigned long injected;
	uint32_t state;
} run;

void lx_fail_alloc_nth(unsigned long nth)
{
	SIL_PRE_LOC;

	SIL_LOC_INT();
	setting.nth = nth;
	setting.percent = 0;
	SIL_UNL_INT();
}

void lx_fail_alloc_random(unsigned int percent, uint32_t seed, long times)
{
	SIL_PRE_LOC;

	SIL_LOC_INT();
	setting.nth = 0;
	setting.percent = percent > 100 ? 100 : percent;
	setting.seed = seed ? seed : 1;
	setting.times = times;
	run.state = setting.seed;
	SIL_UNL_INT();
}

void lx_fail_alloc_off(void)
{
	lx_fail_alloc_nth(0);
}

unsigned long lx_alloc_attempts(void)
{
	return run.attempts;
}

unsigned long lx_alloc_injected_failures(void)
{
	return run.injected;
}

void lx_fail_alloc_boot(void)
{
	run.attempts = 0;
	run.injected = 0;
	run.state = setting.seed ? setting.seed : 1;
}

/* The next number of the xorshift32 sequence. */
static uint32_t next_random(void)
{
	uint32_t x = run.state;

	x ^= x << 13;
	x ^= x >> 17;
	x ^= x << 5;
	run.state = x;
	return x;
}

bool lx_fail_alloc_should_fail_locked(void)
{
	bool fail = false;

	run.attempts++;
	if (setting.nth != 0)
		fail = run.attempts == setting.nth;
	else if (setting.percent != 0 && (setting.times < 0 || (long)run.injected < setting.times))
		fail = next_random() % 100U < setting.percent;
	if (fail)
		run.injected++;
	return fail;
}
