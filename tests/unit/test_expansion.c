/* The expansion arithmetic of src/expansion.c (Shewchuk: grow, scale,
 * product, sign; ts__exact_sign) against the tests' big-integer sum
 * (tests/common/th_exact.h, a different method): for random doubles a, b,
 * c, d of random scales in 2^-300 .. 2^300 (the range ts__gb_side admits)
 * and ties made likely (equal or nearly equal values, zeros),
 *  - a − b as an expansion (grow) sums exactly to a − b: its components
 *    minus a and plus b sum to exactly 0;
 *  - (a − b)(c − d) as an expansion (product of two such) sums exactly to
 *    ac − ad − bc + bd, each product split exactly by fma (a c = P + e):
 *    the difference sums to exactly 0; scaled by a double likewise;
 *  - the sign of an expansion is the sign of its exact sum;
 *  - ts__exact_sign of up to 32 terms is th_exact_sign's. */
#include "th.h"
#include "common/th_exact.h"
#include "common/th_rng.h"
#include "internal.h"

#include <math.h>

static double pick(void)
{
    double v = ldexp(th_range(0.5, 1.0), (int)th_below(120) - 60);
    if (th_chance(0.1))
        v = ldexp(1.0, (int)th_below(600) - 300); /* a power of two */
    return th_chance(0.5) ? -v : v;
}

/* b: a itself, a neighbour of it, 0 or another value */
static double near_to(double a)
{
    switch (th_below(5)) {
    case 0: return a;
    case 1: return nextafter(a, th_chance(0.5) ? (double)INFINITY : -(double)INFINITY);
    case 2: return 0.0;
    case 3: return a * (1.0 + ldexp(th_range(-1.0, 1.0), -(int)th_below(60)));
    default: return pick();
    }
}

/* t[n++] = the two terms of ±a b (fma) */
static int put_product(double *t, int n, double sg, double a, double b)
{
    double P = a * b;
    t[n] = sg * P;
    t[n + 1] = sg * fma(a, b, -P);
    return n + 2;
}

int main(void)
{
    th_seed(20261206);
    TH_CASE("differences, products, scales: exact");
    for (int it = 0; it < 20000; it++) {
        double a = pick(), b = near_to(a), c = pick(), d = near_to(c), k = pick();
        double ab[2], cd[2], h[8], hk[16], t[64];
        CHECK(ts__exp_grow(&a, 1, -b, ab) == 2);
        t[0] = ab[0], t[1] = ab[1], t[2] = -a, t[3] = b;
        CHECK(th_exact_sign(t, 4) == 0);
        CHECK(ts__exp_sign(ab, 2) == (a > b) - (a < b));
        ts__exp_grow(&c, 1, -d, cd);
        int n = ts__exp_product(ab, 2, cd, 2, h);
        CHECK(n == 8);
        int m = 0;
        for (int l = 0; l < n; l++)
            t[m++] = h[l];
        m = put_product(t, m, -1.0, a, c);
        m = put_product(t, m, 1.0, a, d);
        m = put_product(t, m, 1.0, b, c);
        m = put_product(t, m, -1.0, b, d);
        CHECKF(th_exact_sign(t, m) == 0, "a %a b %a c %a d %a", a, b, c, d);
        CHECK(ts__exp_sign(h, n) == ((a > b) - (a < b)) * ((c > d) - (c < d)));
        /* (a − b)(c − d) k: its sign, and against the product of h by k
         * taken term by term (each h_l k split by fma) */
        CHECK(ts__exp_scale(h, n, k, hk) == 16);
        m = 0;
        for (int l = 0; l < 16; l++)
            t[m++] = hk[l];
        for (int l = 0; l < n; l++)
            m = put_product(t, m, -1.0, h[l], k);
        CHECK(th_exact_sign(t, m) == 0);
        CHECK(ts__exp_sign(hk, 16) == ts__exp_sign(h, n) * (k > 0.0 ? 1 : -1));
    }
    TH_CASE("ts__exact_sign against the big-integer sum");
    for (int it = 0; it < 20000; it++) {
        double v[TS_EXACT_TERMS];
        int n = 1 + (int)th_below(TS_EXACT_TERMS);
        for (int j = 0; j < n; j++)
            v[j] = j > 0 && th_chance(0.4) ? -near_to(v[th_below((uint64_t)j)]) : pick();
        CHECK(ts__exact_sign(v, n) == th_exact_sign(v, n));
    }
    TH_CASE("the empty and the zero expansion");
    {
        double z[2] = {0.0, -0.0}, h[4];
        CHECK(ts__exp_sign(z, 0) == 0 && ts__exp_sign(z, 2) == 0);
        CHECK(ts__exp_scale(z, 2, 3.0, h) == 4 && ts__exp_sign(h, 4) == 0);
        CHECK(ts__exact_sign(z, 0) == 0);
    }
    return th_report("test_expansion");
}
