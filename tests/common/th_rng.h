/* The tests' one pseudo-random generator (test side only, never the library).
 *
 * splitmix64 (G. Steele, D. Lea, C. Flood, "Fast splittable pseudorandom
 * number generators", OOPSLA 2014; constants of S. Vigna's reference code):
 * the state advances by the odd constant 0x9E3779B97F4A7C15 (period 2^64,
 * every seed valid, 0 included) and each output is a bijective mix of the
 * state.  It passes BigCrush; only unsigned 64-bit arithmetic is used, so a
 * seed gives the same stream on every platform and compiler, and a failing
 * case is reproduced by its seed.
 *
 * Two ways to use it:
 *  - a generator of one's own: th_rng r = TH_RNG_INIT(seed); th_rng_unit(&r)...
 *    (one per thread, or to give one part of a test a stream of its own);
 *  - the program's default generator: th_seed(seed); th_unit(), th_range(a, b),
 *    th_below(n), th_chance(p), th_logu(a, b), th_normal(), th_u64().
 *    It starts from seed 0 unless th_seed is called.
 *
 * Distributions:
 *  - th_rng_unit: uniform on [0, 1), the 2^53 multiples of 2^-53 equally likely;
 *  - th_rng_range(a, b) = a + (b - a) u: [a, b) (b itself only through rounding);
 *  - th_rng_below(n): [0, n) by a 64-bit modulo (bias below n / 2^64), 0 if n = 0;
 *  - th_rng_chance(p): 1 with probability p;
 *  - th_rng_logu(lo, hi): log-uniform, lo (hi/lo)^u, 0 < lo < hi;
 *  - th_rng_normal: standard normal (Box-Muller, one value per call);
 *  - th_rng_hostile: a "hostile" double for robustness tests (NaN, ±Inf,
 *    ±DBL_MAX, subnormals, ±0, huge, tiny, random bit patterns, -1, or an
 *    ordinary value in [-10, 10)).
 */
#ifndef TS_TH_RNG_H
#define TS_TH_RNG_H

#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdint.h>
#include <string.h>

typedef struct th_rng {
    uint64_t s;
} th_rng;

#define TH_RNG_INIT(seed) {(uint64_t)(seed)}

static inline uint64_t th_rng_u64(th_rng *r)
{
    uint64_t z = (r->s += 0x9E3779B97F4A7C15u);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9u;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBu;
    return z ^ (z >> 31);
}

static inline double th_rng_unit(th_rng *r)
{
    return (double)(th_rng_u64(r) >> 11) * 0x1p-53;
}

static inline double th_rng_range(th_rng *r, double a, double b)
{
    return a + (b - a) * th_rng_unit(r);
}

static inline size_t th_rng_below(th_rng *r, size_t n)
{
    return n ? (size_t)(th_rng_u64(r) % (uint64_t)n) : 0;
}

static inline int th_rng_chance(th_rng *r, double p)
{
    return th_rng_unit(r) < p;
}

static inline double th_rng_logu(th_rng *r, double lo, double hi)
{
    return lo * pow(hi / lo, th_rng_unit(r));
}

static inline double th_rng_normal(th_rng *r)
{
    double u = 1.0 - th_rng_unit(r); /* (0, 1]: log(u) finite */
    double v = th_rng_unit(r);
    return sqrt(-2.0 * log(u)) * cos(6.283185307179586 * v);
}

static inline double th_rng_hostile(th_rng *r)
{
    double sign = th_rng_chance(r, 0.5) ? 1.0 : -1.0;
    switch (th_rng_below(r, 14)) {
    case 0: return (double)NAN;
    case 1: return (double)INFINITY;
    case 2: return -(double)INFINITY;
    case 3: return sign * DBL_MAX;
    case 4: return ldexp((double)th_rng_below(r, 1000) + 1.0, -1074); /* subnormal */
    case 5: return sign * DBL_MIN;
    case 6: return sign > 0 ? 0.0 : -0.0;
    case 7: return sign * th_rng_logu(r, 1e250, 1e308);  /* huge */
    case 8: return sign * th_rng_logu(r, 1e-320, 1e-250); /* tiny */
    case 9: {
        uint64_t b = th_rng_u64(r);
        double v;
        memcpy(&v, &b, sizeof v);
        return v;
    }
    case 10: return -1.0;
    case 11: return 5e-324;
    default: return th_rng_unit(r) * 20.0 - 10.0;
    }
}

/* ---- the program's default generator ------------------------------------ */
static th_rng th_rng_default_;

static inline void th_seed(uint64_t seed) { th_rng_default_.s = seed; }
static inline uint64_t th_u64(void) { return th_rng_u64(&th_rng_default_); }
static inline double th_unit(void) { return th_rng_unit(&th_rng_default_); }
static inline double th_range(double a, double b) { return th_rng_range(&th_rng_default_, a, b); }
static inline size_t th_below(size_t n) { return th_rng_below(&th_rng_default_, n); }
static inline int th_chance(double p) { return th_rng_chance(&th_rng_default_, p); }
static inline double th_logu(double lo, double hi) { return th_rng_logu(&th_rng_default_, lo, hi); }
static inline double th_normal(void) { return th_rng_normal(&th_rng_default_); }
static inline double th_hostile(void) { return th_rng_hostile(&th_rng_default_); }

#endif
