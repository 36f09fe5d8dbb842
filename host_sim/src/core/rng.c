/*
 * rng.c — the models' deterministic random numbers: xoshiro256** seeded by
 * splitmix64 (Blackman and Vigna, "Scrambled linear pseudorandom number
 * generators", 2018), one stream per model name.
 */
#include <math.h>
#include "host_sim/rng.h"

static uint64_t base_seed;    /* the scenario's seed, mixed into every stream */

void hs_rng_set_base_seed(uint64_t seed)
{
	base_seed = seed;
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
	hs_rng_seed(rng, h ^ splitmix64(&(uint64_t){ base_seed }));
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
