/*
 * rng.h — deterministic random numbers for models.  Host only.
 *
 * Models draw randomness from streams seeded from the scenario seed and
 * their own name (hs_rng_stream), so adding a model does not change the
 * others' numbers.
 */
#ifndef HOST_SIM_RNG_H
#define HOST_SIM_RNG_H

#include <stdint.h>

/* Deterministic PRNG: xoshiro256** seeded through splitmix64. */
struct hs_rng { uint64_t s[4]; };
void hs_rng_seed(struct hs_rng *rng, uint64_t seed);
/* A stream for a named model, derived from the scenario seed and name. */
void hs_rng_stream(struct hs_rng *rng, const char *name);
uint64_t hs_rng_next(struct hs_rng *rng);
/* Uniform in [0, n) (n > 0), without modulo bias. */
uint32_t hs_rng_below(struct hs_rng *rng, uint32_t n);
/* Uniform in [0, 1). */
double hs_rng_unit(struct hs_rng *rng);
/* Normally distributed, mean 0, standard deviation 1. */
double hs_rng_gauss(struct hs_rng *rng);
/* The seed every stream derives from (the scenario's; 0 without one). */
void hs_rng_set_base_seed(uint64_t seed);

#endif /* HOST_SIM_RNG_H */
