/*
 * scenario.c — booting and running a simulated EV3 in one call each, and
 * the deterministic PRNG models draw from.  Host only.
 */
#include <errno.h>
#include <math.h>
#include <string.h>

#include "rtos_host.h"
#include "host_sim/board.h"
#include "host_sim/clock.h"
#include "host_sim/scenario.h"
#include "host_sim/trace.h"

static struct {
	bool booted;
	uint64_t seed;
} sim;

ER hs_sim_boot(const struct hs_scenario *scn)
{
	ER er;

	if (!scn || !scn->rtos) {
		rtos_host_bug("host_sim", "hs_sim_boot: a scenario with an rtos configuration is required");
		return E_PAR;
	}
	if (sim.booted || hs_board_active())
		return E_OBJ;
	er = hs_board_init(scn->board);
	if (er != E_OK)
		return er;
	if (scn->vcd_path && hs_trace_open_vcd(scn->vcd_path) != 0) {
		rtos_host_bug("host_sim", "hs_sim_boot: cannot write %s: %s", scn->vcd_path, strerror(errno));
		hs_board_shutdown();
		return E_PAR;
	}
	if (scn->csv_path && hs_trace_open_csv(scn->csv_path) != 0) {
		rtos_host_bug("host_sim", "hs_sim_boot: cannot write %s: %s", scn->csv_path, strerror(errno));
		hs_board_shutdown();
		return E_PAR;
	}
	if (scn->reglog_filter)
		hs_trace_reglog(scn->reglog_filter, scn->reglog);
	sim.seed = scn->seed;
	er = rtos_host_boot(scn->rtos);
	if (er != E_OK) {
		hs_board_shutdown();
		return er;
	}
	hs_board_start();
	sim.booted = true;
	return E_OK;
}

void hs_sim_run_for(uint64_t ns)
{
	rtos_host_run_for(ns);
}

void hs_sim_run_until(uint64_t t_ns)
{
	rtos_host_run_until(t_ns);
}

hs_event_t hs_sim_at(uint64_t t_ns, rtos_host_event_fn fn, void *arg)
{
	if (!fn) {
		rtos_host_bug("host_sim", "hs_sim_at: NULL function");
		return 0;
	}
	return hs_event_at(t_ns, fn, arg);
}

void hs_sim_shutdown(void)
{
	if (sim.booted)
		rtos_host_shutdown();
	hs_board_shutdown();
	memset(&sim, 0, sizeof(sim));
}

uint64_t hs_sim_seed(void)
{
	return sim.seed;
}

/* ---- PRNG: xoshiro256** seeded by splitmix64 ---- */

/* One splitmix64 step. */
static uint64_t splitmix64(uint64_t *x)
{
	uint64_t z = (*x += 0x9E3779B97F4A7C15ULL);

	z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
	z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
	return z ^ (z >> 31);
}

void hs_rng_seed(struct hs_rng *rng, uint64_t seed)
{
	uint64_t x = seed;

	for (unsigned i = 0; i < 4U; i++)
		rng->s[i] = splitmix64(&x);
}

void hs_rng_stream(struct hs_rng *rng, const char *name)
{
	/* FNV-1a of the name, mixed with the scenario seed. */
	uint64_t h = 0xCBF29CE484222325ULL;

	for (const char *p = name ? name : ""; *p; p++)
		h = (h ^ (uint8_t)*p) * 0x100000001B3ULL;
	hs_rng_seed(rng, h ^ splitmix64(&(uint64_t){ sim.seed }));
}

static uint64_t rotl(uint64_t x, unsigned k)
{
	return (x << k) | (x >> (64U - k));
}

uint64_t hs_rng_next(struct hs_rng *rng)
{
	uint64_t *s = rng->s;
	uint64_t result = rotl(s[1] * 5U, 7) * 9U;
	uint64_t t = s[1] << 17;

	s[2] ^= s[0];
	s[3] ^= s[1];
	s[1] ^= s[2];
	s[0] ^= s[3];
	s[2] ^= t;
	s[3] = rotl(s[3], 45);
	return result;
}

uint32_t hs_rng_below(struct hs_rng *rng, uint32_t n)
{
	uint64_t limit;
	uint64_t x;

	if (n == 0U)
		return 0;
	/* Reject the top partial range so every value is equally likely. */
	limit = UINT64_MAX - UINT64_MAX % n;
	do
		x = hs_rng_next(rng);
	while (x >= limit);
	return (uint32_t)(x % n);
}

double hs_rng_unit(struct hs_rng *rng)
{
	return (double)(hs_rng_next(rng) >> 11) * (1.0 / 9007199254740992.0);
}

double hs_rng_gauss(struct hs_rng *rng)
{
	/* Box-Muller; u1 in (0, 1] so the logarithm is finite. */
	double u1 = 1.0 - hs_rng_unit(rng);
	double u2 = hs_rng_unit(rng);

	return sqrt(-2.0 * log(u1)) * cos(6.283185307179586 * u2);
}
