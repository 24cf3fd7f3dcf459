/* The histogram rate (docs/method.md §12) where the shape search of §12.4
 * works at its edges: a bin mean next to neighbours far above or below it,
 * means at or next to a bound, bins touching both bounds, flat runs at a
 * bound, widths over many orders of magnitude.  Each rate that is built is
 * checked against the header: r within [lo, hi] exactly at dense samples,
 * every bin's integral its total (to the rounding of the sums, 1e-12 of
 * the largest of total and bound times width), the same status from
 * ts_histo_check; a refusal is a documented status. */
#include "trigspline.h"
#include "th.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>

static uint64_t rng = 0x9e3779b97f4a7c15u;
static double urand(void)
{
    rng ^= rng << 13, rng ^= rng >> 7, rng ^= rng << 17;
    return (double)(rng >> 11) * 0x1p-53;
}

static long built, refused;

static void check(const double *e, const double *t, size_t n, double lo, double hi)
{
    ts_histo_options o;
    ts_histo_options_init(&o);
    o.lo = lo, o.hi = hi;
    ts_histo *h = NULL;
    ts_error err;
    ts_status st = ts_histo_new(e, t, n, &o, &h, &err), sts[16];
    CHECK(ts_histo_check(e, t, n, &o, sts, NULL) == st);
    if (st != TS_OK) {
        CHECKF(st == TS_ERR_INFEASIBLE || st == TS_ERR_TOO_LARGE || st == TS_ERR_NEGATIVE,
               "%s", ts_status_name(st));
        CHECK(h == NULL && err.index < n);
        refused++;
        return;
    }
    built++;
    for (size_t j = 0; j < n; j++) {
        double w = e[j + 1] - e[j], v;
        CHECK(ts_histo_integral(h, e[j], e[j + 1], &v) == TS_OK);
        double scale = fmax(fabs(t[j]), fmax(fabs(lo), isinf(hi) ? 0.0 : fabs(hi)) * w);
        CHECKF(fabs(v - t[j]) <= 1e-12 * scale, "bin %zu: %.17g vs %.17g", j, v, t[j]);
        for (int k = 0; k <= 64; k++) {
            double x = k == 64 ? e[j + 1] : e[j] + w * k / 64.0, r;
            CHECK(ts_histo_eval(h, x, &r, NULL) == TS_OK);
            CHECKF(lo <= r && r <= hi, "bin %zu x %.17g: r %.17g outside [%g, %g]", j, x, r, lo, hi);
        }
    }
    ts_histo_free(h);
}

/* Hand-made: a small mean between large ones and its mirror under hi (the
 * flat solution's middle value clamped at 0 and at H), means on a bound,
 * a bin touching both bounds through its edges. */
static void test_cases(void)
{
    TH_CASE("constructed");
    double e3[4] = {0, 1, 2, 3}, e5[6] = {0, 1, 2, 3, 4, 5};
    double a[3] = {10, 0.1, 10}, b[3] = {0.1, 0.99, 0.1}, c[3] = {0.5, 0, 0.5};
    double d[3] = {0, 1, 0}, f[5] = {0, 1, 0, 1, 0}, g[5] = {1, 1e-300, 1, 1e-300, 1};
    check(e3, a, 3, 0.0, HUGE_VAL);
    check(e3, a, 3, 0.0, 10.5);
    check(e3, b, 3, 0.0, 1.0);
    check(e3, c, 3, 0.0, 1.0);
    check(e3, d, 3, 0.0, 1.0);
    check(e5, f, 5, 0.0, 1.0);
    check(e5, g, 5, 0.0, 1.0);
    check(e5, g, 5, 0.0, HUGE_VAL);
    /* widths 1e-300 .. 1e300 apart */
    double ew[4] = {0, 1e-300, 1.0, 1e300}, tw[3] = {1e-300, 1e-10, 1e300};
    check(ew, tw, 3, 0.0, HUGE_VAL);
    check(ew, tw, 3, 0.0, 2.0);
}

/* Random bins whose means are drawn near the bounds, on them, or far
 * apart (a fixed seed; 3000 histograms of up to 12 bins). */
static void test_random(void)
{
    TH_CASE("random near the bounds");
    double e[13], t[12];
    for (int p = 0; p < 3000; p++) {
        size_t n = 2 + (size_t)(urand() * 11);
        double lo = urand() < 0.5 ? 0.0 : -urand(), hi = urand() < 0.2 ? HUGE_VAL : lo + 1.0;
        double H = isinf(hi) ? 1.0 : hi - lo;
        e[0] = 0.0;
        for (size_t j = 0; j < n; j++) {
            double w = urand() < 0.2 ? ldexp(1.0, -(int)(urand() * 40)) : 0.5 + urand();
            e[j + 1] = e[j] + w;
            w = e[j + 1] - e[j]; /* the width the library sees (the sum rounds) */
            double u = urand(), m;
            if (u < 0.2)
                m = lo;
            else if (u < 0.4 && !isinf(hi))
                m = hi;
            else if (u < 0.55)
                m = lo + H * ldexp(1.0, -(int)(urand() * 50));
            else if (u < 0.7 && !isinf(hi))
                m = hi - H * ldexp(1.0, -(int)(urand() * 50));
            else
                m = lo + H * urand();
            t[j] = m * w;
        }
        check(e, t, n, lo, hi);
    }
    CHECKF(built > 500 && refused > 0, "%ld built, %ld refused", built, refused);
}

int main(void)
{
    test_cases();
    test_random();
    printf("histograms built %ld, refused %ld\n", built, refused);
    return th_report("test_histo_edges");
}
