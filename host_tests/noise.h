/* SPDX-License-Identifier: MIT */
/*
 * noise.h: deterministic Gaussian noise for the fit's test and benchmark
 * (xorshift64, Marsaglia 2003, and the Box-Muller transform): the same
 * sequence on every machine and compiler. Include after <math.h> and
 * <stdint.h>.
 */
#ifndef MDR_NOISE_H
#define MDR_NOISE_H

#define NOISE_SEED0 88172645463325252ull /* the sequence's start (noise_reseed) */
static uint64_t noise_state = NOISE_SEED0;

/* the sequence from its start: a test that draws from it gets the same
 * noise whichever tests ran before it (test_fit: a cmocka setup) */
static inline int noise_reseed(void **state)
{
    (void)state;
    noise_state = NOISE_SEED0;
    return 0;
}

/* uniform in (0, 1), 53 bits */
static double noise_uniform(void)
{
    noise_state ^= noise_state << 13;
    noise_state ^= noise_state >> 7;
    noise_state ^= noise_state << 17;
    return ((double)(noise_state >> 11) + 0.5) / 9007199254740992.0;
}

/* standard normal */
static double gauss(void)
{
    double u1 = noise_uniform(), u2 = noise_uniform();
    return sqrt(-2 * log(u1)) * cos(2 * M_PI * u2);
}

#endif /* MDR_NOISE_H */
