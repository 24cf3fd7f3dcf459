/* Steffen's slopes (docs/method.md §6) against hand-computed values, and the
 * promise of the defaults (docs/method.md §5.10): with ts_spline_options_init's
 * options every interval's control values are monotone and between its two
 * data values, and the curve stays inside each interval's data range.
 * Expected values: hand arithmetic below (exact in binary) and the theorem's
 * inequalities; no library output is pasted. */
#include "common/th_rng.h"
#include "th.h"
#include "trigspline.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>

#define EPS DBL_EPSILON

static void slopes_of(const double *x, const double *f, size_t np, double *d)
{
    CHECK(ts_slopes_compute(TS_SLOPES_STEFFEN, x, f, np, d, NULL) == TS_OK);
}

/* Hand re-derivation (Steffen 1990, eq. 11 inside, eq. 26 at the ends):
 * every value below is worked out on paper from the formulas in the header. */
static void test_hand(void)
{
    TH_CASE("hand");
    double d[5];
    {
        /* secants 2, 1, 0, -2; h = 1, 1, 2, 1.
         * d1: p = (1*2 + 1*1)/2 = 1.5, min(2, 1, 0.75) = 0.75 -> 1.5
         * d2, d3: a neighbouring secant is 0 -> 0
         * d0: 2 + (2 - 1)*1/2 = 2.5 (sign of Δ0, <= 4) -> 2.5
         * d4: -2 + (-2 - 0)*1/3 = -8/3 (sign of Δ3, |.| <= 4) -> -8/3 */
        const double x[5] = {0, 1, 2, 4, 5}, f[5] = {0, 2, 3, 3, 1};
        slopes_of(x, f, 5, d);
        CHECK(d[0] == 2.5 && d[1] == 1.5 && d[2] == 0.0 && d[3] == 0.0);
        CHECK_CLOSE(d[4], -8.0 / 3.0, 4 * EPS); /* one rounding of 1/3, one of the sum */
    }
    {
        /* secants 1, -3; h = 3, 1.  d1 = 0 (turn).
         * d0: 1 + (1 + 3)*3/4 = 4 > 2*1 -> capped to 2.
         * d2: -3 + (-3 - 1)*1/4 = -4, |.| <= 6 -> -4. */
        const double x[3] = {0, 3, 4}, f[3] = {0, 3, 0};
        slopes_of(x, f, 3, d);
        CHECK(d[0] == 2.0 && d[1] == 0.0 && d[2] == -4.0);
    }
    {
        /* secants 1, 10, 1 on a uniform grid: inside min(1, 10, 2.75) = 1 -> 2;
         * ends 1 + (1 - 10)/2 = -3.5, wrong sign -> 0 */
        const double x[4] = {0, 1, 2, 3}, f[4] = {0, 1, 11, 12};
        slopes_of(x, f, 4, d);
        CHECK(d[0] == 0.0 && d[1] == 2.0 && d[2] == 2.0 && d[3] == 0.0);
    }
    {
        /* smooth monotone data: inside, |p|/2 is the smallest, d = p (the
         * three-point slope): f = x² on 1, 2, 3, 4 gives secants 3, 5, 7,
         * p = 4, 6; ends 3 + (3 - 5)/2 = 2, 7 + (7 - 5)/2 = 8 (= 2x, <= 2Δ) */
        const double x[4] = {1, 2, 3, 4}, f[4] = {1, 4, 9, 16};
        slopes_of(x, f, 4, d);
        CHECK(d[0] == 2.0 && d[1] == 4.0 && d[2] == 6.0 && d[3] == 8.0);
    }
    {
        /* a line: every slope exactly m */
        const double x[5] = {0, 0.5, 2, 2.25, 7}, f[5] = {1, 2, 5, 5.5, 15};
        slopes_of(x, f, 5, d);
        for (int i = 0; i < 5; i++)
            CHECK(d[i] == 2.0);
    }
    {
        /* two points: the secant */
        const double x[2] = {0, 4}, f[2] = {1, -1};
        slopes_of(x, f, 2, d);
        CHECK(d[0] == -0.5 && d[1] == -0.5);
    }
}

/* More knots than one pass of the slope loop takes (1024 inner knots a
 * pass; here 2500) and a secant whose numerator overflows.
 * f = x² on the integers: secants 2i + 1, the three-point slope p_i = 2i,
 * min(2i - 1, 2i + 1, i) = i for i >= 1, so d_i = 2i exactly (every value
 * and operation exact in binary: weights 1/2).  The huge case:
 * x = 0, 8, 16, f = -2^1023, 2^1023, DBL_MAX: f_1 - f_0 = 2^1024 overflows
 * and the secant is taken by halves, Δ_0 = 2((2^1022 + 2^1022)/8) = 2^1021
 * exactly; Δ_1 = (DBL_MAX - 2^1023)/8 = 2^1020 - 2^968 exactly; both
 * positive, p_1 = (Δ_0 + Δ_1)/2 (weights 1/2) is the smallest of the three
 * halves' candidates (|p_1|/2 ~ 0.75·2^1020 < Δ_1), so d_1 = p_1, within one
 * rounding of its sum (the halvings are exact). */
static void test_long_and_huge(void)
{
    TH_CASE("long and huge");
    enum { NP = 2500 };
    static double x[NP], f[NP], d[NP];
    for (int i = 0; i < NP; i++) {
        x[i] = i;
        f[i] = (double)i * i;
    }
    slopes_of(x, f, NP, d);
    int bad = 0;
    for (int i = 1; i < NP - 1; i++)
        bad += d[i] != 2.0 * i;
    CHECKF(bad == 0, "%d inner slopes differ from 2i", bad);
    /* the same data between two lines with the defaults (geometric form,
     * certified a block of intervals at a time): certified, and by the
     * theorem of docs/method.md §5.10 every interval's control values
     * increase from f_i to f_{i+1} */
    ts_spline_options o;
    ts_spline_options_init(&o);
    o.shape = TS_SHAPE_BETWEEN;
    o.lower = (ts_line){1.0, -10.0};
    o.upper = (ts_line){0.0, 1e7};
    ts_spline *s = NULL;
    CHECK(ts_spline_new(x, f, NP, &o, &s, NULL) == TS_OK);
    if (s) {
        CHECK(ts_spline_certified(s) == 1);
        bad = 0;
        for (size_t i = 0; i + 1 < NP; i++) {
            double B[4];
            CHECK(ts_spline_control(s, i, B, NULL) == TS_OK);
            bad += !(B[0] == f[i] && B[0] <= B[1] && B[1] <= B[2] && B[2] <= B[3] && B[3] == f[i + 1]);
        }
        CHECKF(bad == 0, "%d intervals' control values not increasing", bad);
        ts_spline_free(s);
    }
    const double xs[3] = {0, 8, 16}, fs[3] = {-0x1p1023, 0x1p1023, DBL_MAX};
    double ds[3];
    slopes_of(xs, fs, 3, ds);
    double d0 = 0x1p1021, d1 = 0x1p1020 - 0x1p968;
    CHECK_CLOSE(ds[1], 0.5 * d0 + 0.5 * d1, EPS * (0.5 * d0 + 0.5 * d1));
}

/* Random data (monotone runs, flat runs, turns, uneven spacing): with the
 * defaults, per interval (i) Steffen's box 0 <= d/Δ <= 2 (exact comparison),
 * (ii) the control values B0..B3 monotone and between f_i, f_{i+1} (exact:
 * the theorem's slack at alpha = 0.85 is 1.4e-3 h|Δ|, far above rounding on
 * these data, docs/method.md §5.10 "Rounding"), (iii) dense samples inside
 * [min, max] of the interval's data up to 4 eps max(|f_i|, |f_{i+1}|) (the
 * rounding of B0 + Σ A_l (B_l - B0), a convex combination) and
 * non-decreasing (non-increasing) up to the same amount. */
static void test_promise(void)
{
    TH_CASE("promise");
    th_seed(20261206);
    long boxes = 0, polys = 0, samples = 0, out = 0, nonmono = 0;
    enum { NP_MAX = 40, PER = 64 };
    for (int rep = 0; rep < 3000; rep++) {
        double x[NP_MAX], f[NP_MAX];
        size_t np = 2 + th_below(NP_MAX - 1);
        int kind = (int)th_below(4);
        x[0] = th_range(-10, 10);
        f[0] = th_range(-5, 5);
        for (size_t i = 1; i < np; i++) {
            x[i] = x[i - 1] + (kind == 3 ? th_logu(1e-3, 1e3) : th_range(0.05, 2.0));
            double step = th_logu(1e-4, 10);
            if (kind == 0) /* monotone increasing */
                f[i] = f[i - 1] + step;
            else if (kind == 1) /* monotone with flat runs */
                f[i] = th_chance(0.3) ? f[i - 1] : f[i - 1] - step;
            else /* anything */
                f[i] = th_chance(0.1) ? f[i - 1] : f[i - 1] + (th_chance(0.5) ? step : -step);
        }
        ts_spline_options o;
        ts_spline_options_init(&o);
        ts_spline *s = NULL;
        ts_status st = ts_spline_new(x, f, np, &o, &s, NULL);
        CHECK(st == TS_OK);
        if (!s)
            continue;
        const double *d = ts_spline_slopes(s);
        for (size_t i = 0; i + 1 < np; i++) {
            double D = (f[i + 1] - f[i]) / (x[i + 1] - x[i]);
            double lo = fmin(f[i], f[i + 1]), hi = fmax(f[i], f[i + 1]);
            if (D != 0.0) {
                double p = d[i] / D, q = d[i + 1] / D;
                /* the box, up to the rounding of D and of the minimum's 2|Δ| */
                if (!(p >= 0 && q >= 0 && p <= 2 * (1 + 4 * EPS) && q <= 2 * (1 + 4 * EPS)))
                    boxes++;
            } else if (!(d[i] == 0.0 && d[i + 1] == 0.0)) {
                boxes++;
            }
            double B[4], X[4];
            CHECK(ts_spline_control(s, i, B, X) == TS_OK);
            int up = f[i + 1] >= f[i];
            for (int l = 0; l < 3; l++)
                if (up ? !(B[l] <= B[l + 1]) : !(B[l] >= B[l + 1]))
                    polys++;
            for (int l = 0; l < 4; l++)
                if (!(lo <= B[l] && B[l] <= hi))
                    polys++;
            double tol = 4 * EPS * fmax(fabs(f[i]), fabs(f[i + 1]));
            double prev = f[i];
            for (int k = 1; k < PER; k++) {
                double t = x[i] + (x[i + 1] - x[i]) * k / PER, y;
                if (!(t > x[i] && t < x[i + 1]))
                    continue;
                CHECK(ts_spline_eval(s, t, NULL, &y) == TS_OK);
                samples++;
                if (!(lo - tol <= y && y <= hi + tol))
                    out++;
                if (up ? y < prev - tol : y > prev + tol)
                    nonmono++;
                prev = y;
            }
        }
        ts_spline_free(s);
    }
    CHECKF(boxes == 0, "slopes outside Steffen's box: %ld", boxes);
    CHECKF(polys == 0, "control values not monotone or outside the data: %ld", polys);
    CHECKF(out == 0, "samples outside their interval's data range: %ld of %ld", out, samples);
    CHECKF(nonmono == 0, "non-monotone samples: %ld of %ld", nonmono, samples);
    CHECK(samples > 1000000);
}

/* The shape schemes keep the promise (they only raise a_i and set slopes
 * to 0, docs/method.md §5.10): positive data with shape = positive. */
static void test_promise_positive(void)
{
    TH_CASE("promise_positive");
    th_seed(7);
    long bad = 0;
    for (int rep = 0; rep < 1000; rep++) {
        double x[20], f[20];
        size_t np = 3 + th_below(17);
        x[0] = 0;
        f[0] = th_logu(1e-3, 10);
        for (size_t i = 1; i < np; i++) {
            x[i] = x[i - 1] + th_range(0.05, 2.0);
            f[i] = th_chance(0.3) ? th_logu(1e-6, 1e-2) : th_logu(1e-3, 10);
        }
        ts_spline_options o;
        ts_spline_options_init(&o);
        o.shape = TS_SHAPE_POSITIVE;
        ts_spline *s = NULL;
        CHECK(ts_spline_new(x, f, np, &o, &s, NULL) == TS_OK);
        if (!s)
            continue;
        for (size_t i = 0; i + 1 < np; i++) {
            double B[4], lo = fmin(f[i], f[i + 1]), hi = fmax(f[i], f[i + 1]);
            CHECK(ts_spline_control(s, i, B, NULL) == TS_OK);
            int up = f[i + 1] >= f[i];
            for (int l = 0; l < 3; l++)
                bad += up ? !(B[l] <= B[l + 1]) : !(B[l] >= B[l + 1]);
            for (int l = 0; l < 4; l++)
                bad += !(lo <= B[l] && B[l] <= hi);
        }
        ts_spline_free(s);
    }
    CHECKF(bad == 0, "positive scheme: control values outside the promise: %ld", bad);
}

int main(void)
{
    test_hand();
    test_long_and_huge();
    test_promise();
    test_promise_positive();
    return th_report("test_default_promise");
}
