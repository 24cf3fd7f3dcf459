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

#include <fenv.h>
#include <float.h>
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
            double x = k == 64 ? e[j + 1] : e[j] + w * (k / 64.0), r; /* w k: overflow */
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

/* The flat solution Z of §12.3 in a bin's report: its twelve inner control
 * values equal (v), and 3v = 4ρ − (Y0 + Y4)/2 − W1 (E0 − E4) with the edge
 * data read from the four outer ones (Y0 = B0, E0 = B1 − B0, Y4 = B15,
 * E4 = B15 − B14) and W1 = 22/(3π) − 2 (§12.2).  Tolerance: the library
 * rounds the right-hand side, the test re-forms it: a few ε of the largest
 * term (1e-14 of it). */
static int is_flat(const ts_bin_report *rep, double lo)
{
    int flat = 1;
    for (int l = 2; l < 14; l++)
        flat &= rep->B[l] == rep->B[2];
    double W1 = 22.0 / (3.0 * acos(-1.0)) - 2.0, rho = rep->mean - lo;
    double Y0 = rep->B[0], E0 = rep->B[1] - rep->B[0], Y4 = rep->B[15], E4 = rep->B[15] - rep->B[14];
    double rhs = 4.0 * rho - 0.5 * (Y0 + Y4) - W1 * (E0 - E4);
    double scale = fmax(4.0 * fabs(rho), fmax(fabs(Y0), fabs(Y4)));
    return flat && fabs(3.0 * rep->B[2] - rhs) <= 1e-14 * scale;
}

/* The scalar build of §12.3 (a bin whose C² solution X has a control value
 * outside [0, H]) in its three outcomes besides the ordinary blend, and
 * bins in more than one chunk of 64 (the build lists them 64 at a time). */
static void test_scalar_build(void)
{
    TH_CASE("the blend's fall-backs (§12.3, §12.6.1)");
    ts_histo_options o;
    ts_histo_options_init(&o);
    ts_histo *h = NULL;
    ts_bin_report rep;
    /* two bins at an upper bound whose H = hi − lo has a full significand:
     * constant data, so X = Z = H exactly; the rounded X leaves [0, H] and
     * b0/3 rounds to H or above (clamped to H), λ = 0: every control
     * value is H and r is hi to rounding (1e-15 relative: a sum of four
     * products A_l H with A_l summing to 1) */
    {
        double e[3] = {0, 1, 2}, hi = 0x1.b49eb5386a4a8p+4, t[2] = {hi, hi};
        o.lo = -0x1.777647fcd243fp-1, o.hi = hi;
        CHECK(ts_histo_new(e, t, 2, &o, &h, NULL) == TS_OK);
        for (size_t j = 0; j < 2 && h; j++) {
            ts_bin_report_init(&rep);
            CHECK(ts_histo_report(h, j, &rep) == TS_OK && rep.certified);
            for (int l = 0; l < 16; l++)
                CHECKF(rep.B[l] == hi - o.lo, "bin %zu B%d %a", j, l, rep.B[l]);
        }
        for (int k = 0; k <= 64 && h; k++) {
            double r;
            CHECK(ts_histo_eval(h, k / 32.0, &r, NULL) == TS_OK);
            CHECKF(r <= hi && hi - r <= 1e-15 * hi, "x %g: r %a", k / 32.0, r);
        }
        /* cells of 1/sub of a bin: hi/sub each (the cell totals, kept at or
         * below hi times the width, reach it where the sum rounds up; 1e-15
         * relative as above) */
        for (size_t sub = 1; sub <= 12 && h; sub++) {
            double c[24];
            CHECK(ts_histo_subdivide(h, sub, c, NULL) == TS_OK);
            for (size_t k = 0; k < 2 * sub; k++) {
                double cw = 1.0 / (double)sub;
                CHECKF(c[k] <= hi * cw && hi * cw - c[k] <= 1e-15 * hi * cw, "sub %zu cell %zu: %a",
                       sub, k, c[k]);
            }
        }
        ts_histo_free(h);
        h = NULL;
    }
    /* a bin below hi next to one at hi: the first bin's λ rounds to 1 with
     * a control value of X a few ulps outside [0, H]; that bin is Z
     * (is_flat; the blend at λ < 1 would not be flat), every bin certified
     * and its total kept (1e-15 relative: §12.6) */
    {
        double e[3] = {0, 1, 2}, t[2] = {-0x1.34e6409f88ae1p-4, -0x1.18c68732e31b1p-4};
        o.lo = -0x1.58326f9abec98p-4, o.hi = -0x1.18c68732e31b1p-4;
        CHECK(ts_histo_new(e, t, 2, &o, &h, NULL) == TS_OK);
        int flat = 0;
        for (size_t j = 0; j < 2 && h; j++) {
            ts_bin_report_init(&rep);
            CHECK(ts_histo_report(h, j, &rep) == TS_OK && rep.certified);
            CHECKF(fabs(rep.total - t[j]) <= 1e-15 * fabs(t[j]), "bin %zu total %a", j, rep.total);
            flat |= is_flat(&rep, o.lo) << j;
        }
        CHECKF(flat & 1, "flat bins %d", flat);
        ts_histo_free(h);
        h = NULL;
    }
    /* a mean of 2^1018 (below the limit 2^1019 of §12.6): one bin with
     * Y0 = Y4 = ρ and slopes 0, the constant ρ solves (12.3) (and is Z):
     * every control value 2^1018 to rounding (1e-15 relative: hrow's sums
     * and the division by 2400, a few ε), the total kept */
    {
        double e[2] = {0, 1}, t[1] = {0x1p1018};
        CHECK(ts_histo_new(e, t, 1, NULL, &h, NULL) == TS_OK);
        ts_bin_report_init(&rep);
        CHECK(h && ts_histo_report(h, 0, &rep) == TS_OK && rep.certified);
        for (int l = 0; l < 16; l++)
            CHECKF(fabs(rep.B[l] - 0x1p1018) <= 1e-15 * 0x1p1018, "B%d %a", l, rep.B[l]);
        CHECKF(fabs(rep.total - 0x1p1018) <= 1e-15 * 0x1p1018, "total %a", rep.total);
        ts_histo_free(h);
        h = NULL;
    }
    /* 200 bins of widths 0.5 .. 1.5 at the constant rate 2.5: more than one
     * chunk of edges and bins; the rate is 2.5 to rounding everywhere
     * (the constant solves (12.3); 1e-14 relative) */
    {
        enum { N = 200 };
        double e[N + 1], t[N];
        e[0] = 0.0;
        for (int j = 0; j < N; j++) {
            e[j + 1] = e[j] + 0.5 + (double)(j * 37 % 101) / 101.0;
            t[j] = 2.5 * (e[j + 1] - e[j]);
        }
        CHECK(ts_histo_new(e, t, N, NULL, &h, NULL) == TS_OK);
        for (int k = 0; k <= 4 * N && h; k++) {
            double x = k == 4 * N ? e[N] : e[0] + (e[N] - e[0]) * k / (4.0 * N), r;
            CHECK(ts_histo_eval(h, x, &r, NULL) == TS_OK);
            CHECKF(fabs(r - 2.5) <= 1e-14 * 2.5, "x %.17g: r %.17g", x, r);
        }
        ts_histo_free(h);
        h = NULL;
    }
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

/* Means from 2^1000 to the limit 2^1019 of §12.6 (totals up to about
 * DBL_MAX: widths to 16), with and without bounds: valid input, so no
 * FE_INVALID, FE_DIVBYZERO or FE_OVERFLOW (the header's promise; the sums
 * of (12.3) overflowed there and raised all three, then the edge-slope
 * limit room/K alone raised FE_OVERFLOW).  The scheme is homogeneous of degree
 * 1 in (totals, lo, hi): every operation is a sum, a product by a
 * constant, a quotient or a comparison, which commute with a power of 2
 * away from overflow and underflow, so the rate of totals 2^k T is 2^k
 * times the rate of T bit for bit (checked against the same series at
 * 2^k smaller, k up to 1012: the means of that series are below 2^8). */
static void test_huge_means(void)
{
    TH_CASE("means up to 2^1019: no flag, the rate scaled bit for bit");
    long flagged = 0, compared = 0;
    for (int rep = 0; rep < 400; rep++) {
        size_t n = 1 + (size_t)(urand() * 6);
        double e[8], t[7], ts[7];
        int k = 1000 + (int)(urand() * 13); /* 2^k: series means below 2^7 */
        e[0] = urand();
        for (size_t i = 1; i <= n; i++)
            e[i] = e[i - 1] + 0.25 + urand() * (urand() < 0.3 ? 15.0 : 1.0);
        for (size_t i = 0; i < n; i++) {
            ts[i] = (urand() < 0.2 ? 0.0 : 100.0 * urand()) * (e[i + 1] - e[i]);
            t[i] = ldexp(ts[i], k);
        }
        ts_histo_options o, os;
        ts_histo_options_init(&o);
        ts_histo_options_init(&os);
        if (urand() < 0.3)
            os.hi = 120.0, o.hi = ldexp(120.0, k);
        if (urand() < 0.3)
            os.lo = -3.0, o.lo = ldexp(-3.0, k);
        ts_histo *h = NULL, *hs = NULL;
        feclearexcept(FE_ALL_EXCEPT);
        ts_status st = ts_histo_new(e, t, n, &o, &h, NULL);
        flagged += st == TS_OK && fetestexcept(FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW);
        ts_status ss = ts_histo_new(e, ts, n, &os, &hs, NULL);
        CHECKF(st == ss, "%s vs %s", ts_status_name(st), ts_status_name(ss));
        for (int q = 0; q <= 40 && h && hs; q++) {
            double x = q == 40 ? e[n] : e[0] + (e[n] - e[0]) * q / 40.0, r = 0.0, rs = 0.0;
            CHECK(ts_histo_eval(h, x, &r, NULL) == TS_OK && ts_histo_eval(hs, x, &rs, NULL) == TS_OK);
            CHECKF(r == ldexp(rs, k), "2^%d: x %.17g r %a, scaled %a", k, x, r, ldexp(rs, k));
            flagged += !!fetestexcept(FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW);
            compared++;
        }
        ts_histo_free(h);
        ts_histo_free(hs);
    }
    CHECKF(flagged == 0, "%ld calls raised FE_INVALID, FE_DIVBYZERO or FE_OVERFLOW", flagged);
    CHECK(compared > 4000);
    /* totals near DBL_MAX = 2^1024 (1 − 2^-53) over widths 32: the mean
     * 2^1019 (1 − 2^-53) just below the limit, neighbours 2^1018, 2^1017;
     * with bounds a join may be refused (TS_ERR_INFEASIBLE, §12.4) */
    {
        double e[4] = {0, 32, 64, 96}, t[3] = {DBL_MAX / 2, DBL_MAX, 0x1p1022};
        ts_histo_options o;
        ts_histo_options_init(&o);
        for (int b = 0; b < 3; b++) {
            if (b == 1)
                o.hi = 0x1p1019;
            if (b == 2)
                o.lo = 0x1p1000, o.hi = HUGE_VAL; /* |mean − lo| within the limit */
            ts_histo *h = NULL;
            feclearexcept(FE_ALL_EXCEPT);
            ts_status st = ts_histo_new(e, t, 3, &o, &h, NULL);
            CHECKF((st == TS_OK || (b > 0 && st == TS_ERR_INFEASIBLE)) &&
                       !fetestexcept(FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW),
                   "bounds %d: %s", b, ts_status_name(st));
            for (size_t j = 0; j < 3 && h; j++) {
                ts_bin_report rep;
                ts_bin_report_init(&rep);
                CHECK(ts_histo_report(h, j, &rep) == TS_OK && rep.certified);
                CHECKF(fabs(rep.total - t[j]) <= 1e-13 * t[j], "bin %zu total %a", j, rep.total);
            }
            ts_histo_free(h);
        }
    }
}

/* Widths near DBL_MIN and near DBL_MAX: no flag from building, from r
 * anywhere, from r' where it is a double.  (1) Means up to 2^1018 over
 * widths from 2^-1022 to 2^-960 (the edge slope's limit room/K reaches
 * 2^2040, its central difference as much: both were formed and raised
 * FE_OVERFLOW); a limit beyond DBL_MAX does not bind, so the rates are
 * checked as everywhere (inside [lo, hi], the totals).  (2) Every width in
 * [2^-1022, 2^-1021): the end edges' slope is 0, and r' there is 0 (it was
 * 0 · π/(2q) with π/(2q) = ∞: NaN, FE_INVALID).  (3) Two widths near
 * DBL_MAX at an edge: their sum overflowed. */
static void test_extreme_widths(void)
{
    TH_CASE("widths near DBL_MIN and DBL_MAX: no flag");
    long flagged = 0, built0 = built;
    for (int rep = 0; rep < 300; rep++) {
        size_t n = 2 + (size_t)(urand() * 5);
        double e[8], t[7];
        int ex = -1022 + (int)(urand() * 60);
        e[0] = 0.0;
        for (size_t i = 1; i <= n; i++)
            e[i] = e[i - 1] + ldexp(1.0 + urand(), ex + (int)(urand() * 3));
        for (size_t i = 0; i < n; i++)
            t[i] = (urand() < 0.3 ? 0.0 : ldexp(urand(), 1010 + (int)(urand() * 9))) *
                   (e[i + 1] - e[i]);
        feclearexcept(FE_ALL_EXCEPT);
        check(e, t, n, 0.0, HUGE_VAL); /* builds, r, integrals */
        flagged += !!fetestexcept(FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW);
    }
    CHECKF(flagged == 0, "%ld series raised FE_INVALID, FE_DIVBYZERO or FE_OVERFLOW", flagged);
    CHECKF(built - built0 > 150, "%ld built", built - built0);
    {
        double e[4] = {0.0, 0x1p-1022, 0x1.fffffffffffffp-1021, 0x1.7ffffffffffffp-1020};
        double t[3] = {0x1p-7, 0x1p-6, 0x1p-8}; /* means 2^1015 to 2^1016 */
        ts_histo *h = NULL;
        feclearexcept(FE_ALL_EXCEPT);
        CHECK(ts_histo_new(e, t, 3, NULL, &h, NULL) == TS_OK);
        double r = 0.0, dr = 1.0;
        CHECK(ts_histo_eval(h, e[0], &r, &dr) == TS_OK);
        CHECKF(dr == 0.0, "r'(e0) %g", dr);
        CHECK(ts_histo_eval(h, e[3], &r, &dr) == TS_OK);
        CHECKF(dr == 0.0, "r'(e3) %g", dr);
        CHECK(!fetestexcept(FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW));
        ts_histo_free(h);
    }
    {
        /* widths 1e306, 1.69e308, 1.6e308 (each a double, the sum of the
         * last two is not) */
        double e[4] = {-1.7e308, -1.69e308, 0.0, 1.6e308}, t[3] = {1e300, 1e308, 3e307};
        feclearexcept(FE_ALL_EXCEPT);
        check(e, t, 3, 0.0, HUGE_VAL);
        CHECK(!fetestexcept(FE_INVALID | FE_DIVBYZERO | FE_OVERFLOW));
    }
}

int main(void)
{
    test_cases();
    test_scalar_build();
    test_random();
    test_huge_means();
    test_extreme_widths();
    printf("histograms built %ld, refused %ld\n", built, refused);
    return th_report("test_histo_edges");
}
