/* The edges of the double range (findings of the robustness review):
 *  - slopes of finite data whose secant f_{i+1} − f_i or end-formula term
 *    Δ0 − Δ1 overflows although the slope does not: expected values from
 *    the same docs/method.md §6 formulas evaluated in long double (x87:
 *    15-bit exponent, nothing overflows), tolerance 4ε relative (a few
 *    roundings of the double path);
 *  - |f| and control values above TS_VALUE_MAX are refused (S could
 *    overflow between knots), values at the limit give finite samples;
 *  - integrals of pieces much shorter than their interval: relative error a
 *    few ε of the piece.  Reference: Simpson's rule on ts_spline_eval values over
 *    the piece (pieces <= 1e-4 h: the rule's error ~ (1e-4)^4 S''''/2880 is
 *    below 1e-18 of the piece); tolerance 16ε of |S| (b − a), for S bounded
 *    away from 0 on the test data;
 *  - the monotone scheme's samples are monotone in floating point, also
 *    across flat runs (finding 11). */
#include "th.h"
#include "common/th_rng.h"
#include "trigspline.h"

#include <float.h>
#include <math.h>
#include <string.h>

#define EPS DBL_EPSILON

static int rel_ok(double got, long double want, double tol)
{
    return fabsl((long double)got - want) <= (long double)tol * fabsl(want);
}

static void slopes_no_intermediate_overflow(void)
{
    /* right end: h0 = 1, h1 = 3, Δ0 = -0.6M, Δ1 = (0.9M - -0.9M)/3 = 0.6M:
     * f_2 − f_1 = 1.8M and Δ0 − Δ1 = -1.2M overflow, the end slope
     * Δ0 + (Δ0 − Δ1)/4 = -0.9M does not */
    const double M = DBL_MAX;
    const double x[4] = {0, 1, 4, 5}, f[4] = {-0.5 * M, -0.9 * M, 0.9 * M, 0.3 * M};
    double d[4];
    ts_error e;
    ts_status st = ts_slopes_compute(TS_SLOPES_ARITHMETIC, x, f, 4, d, &e);
    CHECKF(st == TS_OK, "%s at %zu", ts_strerror(st), e.index);
    long double D[3], H[3];
    for (int j = 0; j < 3; j++) {
        H[j] = (long double)x[j + 1] - (long double)x[j];
        D[j] = ((long double)f[j + 1] - (long double)f[j]) / H[j];
    }
    long double want[4];
    want[0] = D[0] + (D[0] - D[1]) * H[0] / (H[0] + H[1]);
    want[1] = (H[1] * D[0] + H[0] * D[1]) / (H[0] + H[1]);
    want[2] = (H[2] * D[1] + H[1] * D[2]) / (H[1] + H[2]);
    want[3] = D[2] + (D[2] - D[1]) * H[2] / (H[2] + H[1]);
    for (int i = 0; i < 4; i++)
        CHECKF(st == TS_OK && rel_ok(d[i], want[i], 4 * EPS), "d[%d] = %g, want %Lg", i, d[i],
               want[i]);
    /* a slope that truly overflows (Δ1 = -1.8M): its own status, naming the
     * first such point (d0 = Δ0 + (Δ0 − Δ1)/2 = 1.6M) */
    const double x2[4] = {0, 1, 2, 3}, f2[4] = {0.2 * M, 0.9 * M, -0.9 * M, 0.9 * M};
    st = ts_slopes_compute(TS_SLOPES_ARITHMETIC, x2, f2, 4, d, &e);
    CHECKF(st == TS_ERR_SLOPE_OVERFLOW && e.where == TS_WHERE_POINT && e.index == 0,
           "%s at %zu", ts_strerror(st), e.index);
    CHECK(strstr(ts_strerror(TS_ERR_SLOPE_OVERFLOW), "slope overflows") != NULL);
}

static void values_near_dbl_max(void)
{
    const double M = DBL_MAX, V = TS_VALUE_MAX;
    const double x[2] = {0, 1}, fm[2] = {M, M};
    for (int fm_ = 0; fm_ < 3; fm_++) {
        ts_spline_options o;
        ts_spline_options_init(&o);
        o.form = (ts_form)fm_;
        o.shape = TS_SHAPE_POSITIVE;
        ts_spline *s = NULL;
        ts_error e;
        ts_status st = ts_spline_new(x, fm, 2, &o, &s, &e);
        CHECKF(st == TS_ERR_TOO_LARGE && e.where == TS_WHERE_POINT && e.index == 0 && !s,
               "form %d: %s", fm_, ts_strerror(st));
        /* control values beyond the limit: an interval */
        const double x3[3] = {0, 1, 2}, f3[3] = {0.5 * V, V, 0.5 * V};
        o.shape = TS_SHAPE_NONE;
        o.slopes = TS_SLOPES_USER;
        const double dd[3] = {3 * V, 0, -3 * V};
        o.user_slopes = dd;
        o.n_user_slopes = 3;
        o.alpha = 1; /* k = 2/(3π) = 0.21: B1 = 1.14 V */
        st = ts_spline_new(x3, f3, 3, &o, &s, &e);
        CHECKF(st == TS_ERR_TOO_LARGE && e.where == TS_WHERE_INTERVAL && e.index == 0 && !s,
               "form %d: %s", fm_, ts_strerror(st));
        ts_spline_free(s);
    }
    /* random data up to the limit, every form and slope method: refused
     * with a documented status or every sample finite */
    th_rng r = TH_RNG_INIT(18);
    long built = 0, bad = 0;
    for (int trial = 0; trial < 300; trial++) {
        double xs[6], fs[6];
        xs[0] = 0;
        for (int i = 1; i < 6; i++)
            xs[i] = xs[i - 1] + th_rng_logu(&r, 0.1, 10);
        for (int i = 0; i < 6; i++)
            fs[i] = V * th_rng_range(&r, -1, 1);
        ts_spline_options o;
        ts_spline_options_init(&o);
        o.form = (ts_form)th_rng_below(&r, 3);
        o.slopes = (ts_slopes)th_rng_below(&r, 6);
        o.alpha = th_rng_logu(&r, 0.5, 4);
        ts_spline *s = NULL;
        ts_status st = ts_spline_new(xs, fs, 6, &o, &s, NULL);
        CHECKF(st == TS_OK || st == TS_ERR_TOO_LARGE || st == TS_ERR_SLOPE_OVERFLOW ||
                   st == TS_ERR_CONTROL_OVERFLOW,
               "%s", ts_strerror(st));
        if (st != TS_OK)
            continue;
        built++;
        double q[401], y[401];
        for (int k = 0; k <= 400; k++)
            q[k] = xs[0] + (xs[5] - xs[0]) * (k / 400.0);
        q[400] = xs[5];
        ts_spline_eval_batch(s, 0, q, 401, y, NULL, NULL);
        for (int k = 0; k <= 400; k++) {
            double ys;
            ts_spline_eval(s, q[k], NULL, &ys);
            bad += !(fabs(y[k]) <= M) || !(fabs(ys) <= M);
        }
        double I;
        CHECK(ts_spline_integral(s, xs[0], xs[5], &I) == TS_OK && !isnan(I));
        ts_spline_free(s);
    }
    CHECKF(bad == 0 && built > 50, "%ld non-finite samples, %ld built", bad, built);
}

static double simpson(const ts_spline *s, double a, double b)
{
    double ya, ym, yb;
    ts_spline_eval(s, a, NULL, &ya);
    ts_spline_eval(s, a + 0.5 * (b - a), NULL, &ym);
    ts_spline_eval(s, b, NULL, &yb);
    return (b - a) * (ya + 4 * ym + yb) / 6;
}

static void short_pieces(void)
{
    const double x[4] = {0, 1, 2.5, 3}, f[4] = {1, 3, 2, 5};
    for (int fm = 0; fm < 3; fm++) {
        ts_spline_options o;
        ts_spline_options_init(&o);
        o.form = (ts_form)fm;
        ts_spline *s = NULL;
        CHECK(ts_spline_new(x, f, 4, &o, &s, NULL) == TS_OK);
        if (!s)
            continue;
        double worst = 0;
        for (int i = 0; i < 3; i++) {
            double h = x[i + 1] - x[i];
            for (double rel = 1e-12; rel <= 1.1e-4; rel *= 100) {
                double starts[3] = {x[i], x[i] + 0.37 * h, x[i + 1] - rel * h};
                for (int k = 0; k < 3; k++) {
                    double a = starts[k], b = a + rel * h, I;
                    if (b > x[i + 1])
                        b = x[i + 1];
                    CHECK(ts_spline_integral(s, a, b, &I) == TS_OK);
                    double ref = simpson(s, a, b), err = fabs(I - ref) / fabs(ref);
                    worst = err > worst ? err : worst;
                    CHECKF(err <= 16 * EPS, "form %d interval %d [%.17g, %.17g]: rel err %g", fm,
                           i, a, b, err);
                    /* the reverse is the negative */
                    double J;
                    CHECK(ts_spline_integral(s, b, a, &J) == TS_OK && J == -I);
                }
            }
        }
        /* a short piece across a knot: two short end pieces */
        double I, a = 1 - 1e-9, b = 1 + 1e-9;
        CHECK(ts_spline_integral(s, a, b, &I) == TS_OK);
        double ref = simpson(s, a, 1) + simpson(s, 1, b);
        CHECKF(fabs(I - ref) <= 16 * EPS * fabs(ref), "form %d across a knot: %g vs %g", fm, I,
               ref);
        printf("form %d: worst relative error of short pieces %.3g (16 eps = %.3g)\n", fm, worst,
               16 * EPS);
        ts_spline_free(s);
    }
}

static void monotone_samples(void)
{
    /* flat runs between rises and falls of every size; samples dense enough
     * that neighbours differ by a few ulps inside the flat runs */
    const double x[10] = {0, 1, 2, 3, 4, 5, 7, 8, 9, 10};
    const double up[10] = {1, 1, 1, 1.5, 1.5, 3, 3, 3, 1e3, 1e3};
    for (int fm = 0; fm < 3; fm++)
        for (int sl = 0; sl < 6; sl++)
            for (int dir = 0; dir < 2; dir++) {
                double f[10];
                for (int i = 0; i < 10; i++)
                    f[i] = dir ? up[i] : -up[i];
                ts_spline_options o;
                ts_spline_options_init(&o);
                o.form = (ts_form)fm;
                o.slopes = (ts_slopes)sl;
                o.shape = TS_SHAPE_MONOTONE;
                ts_spline *s = NULL;
                ts_status st = ts_spline_new(x, f, 10, &o, &s, NULL);
                CHECKF(st == TS_OK, "%s", ts_strerror(st));
                if (!s)
                    continue;
                enum { NQ = 20001 };
                static double q[NQ], yb[NQ];
                for (int k = 0; k < NQ; k++)
                    q[k] = 10.0 * k / (NQ - 1);
                ts_spline_eval_batch(s, 0, q, NQ, yb, NULL, NULL);
                long wrong = 0;
                double prev = 0;
                for (int k = 0; k < NQ; k++) {
                    double ys;
                    ts_spline_eval(s, q[k], NULL, &ys);
                    if (k > 0) {
                        wrong += dir ? yb[k] < yb[k - 1] : yb[k] > yb[k - 1];
                        wrong += dir ? ys < prev : ys > prev;
                    }
                    prev = ys;
                }
                CHECKF(wrong == 0, "form %d slopes %d %s: %ld pairs out of order", fm, sl,
                       dir ? "up" : "down", wrong);
                ts_spline_free(s);
            }
}

int main(void)
{
    TH_CASE("slopes without intermediate overflow");
    slopes_no_intermediate_overflow();
    TH_CASE("values near DBL_MAX");
    values_near_dbl_max();
    TH_CASE("short pieces");
    short_pieces();
    TH_CASE("monotone samples");
    monotone_samples();
    return th_report("test_range_edges");
}
