/* Geometric form (docs/method.md §4): evaluation, derivatives, integral, extrapolation,
 * the bound on a_i, lines, knot slopes, batch, shape schemes and certificates.
 * Reference values: tests/ref/accuracy_ref.csv from tests/ref/accuracy_ref.py
 * (mpmath, 40 digits, written from docs/method.md §2-§4 without the library). */
#include "th.h"
#include "common/th_basis.h"
#include "common/th_rng.h"
#include "trigspline.h"

#include <float.h>
#include <stdio.h>
#include <string.h>

#define EPS DBL_EPSILON
#define TS_PI_T 3.14159265358979323846
#define TS_HALF_PI_T 1.57079632679489661923
#define MAXP 64

/* docs/method.md §2 basis: th_basis of common/th_basis.h (not the library's). */

static ts_spline *geo_new(const double *x, const double *f, const double *d, size_t np,
                          const double *al, const double *be, ts_extrap ex)
{
    ts_spline_options o;
    ts_spline_options_init(&o);
    o.form = TS_FORM_GEOMETRIC;
    o.slopes = TS_SLOPES_USER;
    o.user_slopes = d;
    o.n_user_slopes = np;
    o.alphas = al;
    o.n_alphas = np - 1;
    o.betas = be;
    o.n_betas = np - 1;
    o.extrapolate = ex;
    ts_spline *s = NULL;
    ts_status st = ts_spline_new(x, f, np, &o, &s, NULL);
    CHECKF(st == TS_OK, "geo_new: %s", ts_strerror(st));
    return s;
}

static int parse_row(char *line, const char *tag, double *v, int max)
{
    size_t tl = strlen(tag);
    if (strncmp(line, tag, tl) != 0 || line[tl] != ',')
        return -1;
    int k = 0;
    char *p = line + tl + 1;
    while (*p && k < max) {
        char *e;
        v[k++] = strtod(p, &e);
        if (e == p)
            break;
        p = *e == ',' ? e + 1 : e;
    }
    return k;
}

/* ---- reference cases ------------------------------------------------- */
static void test_reference(void)
{
    FILE *fp = fopen(TS_SOURCE_DIR "/tests/ref/accuracy_ref.csv", "r");
    CHECKF(fp != NULL, "cannot open the reference CSV");
    if (!fp)
        return;
    char line[4096];
    double x[MAXP], f[MAXP], d[MAXP], al[MAXP], be[MAXP], v[8];
    size_t np = 0;
    int ncase = 0, npt = 0, next = 0, nint = 0;
    ts_spline *s = NULL;
    double S = 0, hmin = 0, hmax = 0;
    while (fgets(line, sizeof line, fp)) {
        line[strcspn(line, "\r\n")] = 0;
        if (strncmp(line, "case,", 5) == 0) {
            np = (size_t)atoi(strrchr(line, ',') + 1);
            continue;
        }
        if (parse_row(line, "x", x, MAXP) > 0 || parse_row(line, "f", f, MAXP) > 0 ||
            parse_row(line, "d", d, MAXP) > 0 || parse_row(line, "alpha", al, MAXP) > 0)
            continue;
        if (parse_row(line, "beta", be, MAXP) > 0) {
            s = geo_new(x, f, d, np, al, be, TS_EXTRAP_EXTEND);
            ncase++;
            /* scale of the values: max |B_l| over the intervals */
            S = 0, hmin = TH_INF, hmax = 0;
            for (size_t i = 0; s && i + 1 < np; i++) {
                double B[4], h = x[i + 1] - x[i];
                ts_spline_control(s, i, B, NULL);
                for (int l = 0; l < 4; l++)
                    S = fmax(S, fabs(B[l]));
                hmin = fmin(hmin, h), hmax = fmax(hmax, h);
            }
            continue;
        }
        if (!s)
            continue;
        int kp = parse_row(line, "pt", v, 8), ke = kp < 0 ? parse_row(line, "ext", v, 8) : -1;
        if (kp == 6 || ke == 6) {
            double y, dy, d2y, X = v[0], XP = v[5];
            size_t i = 0;
            while (i + 2 < np && X >= x[i + 1])
                i++;
            double h = x[i + 1] - x[i];
            if (ke == 6)
                h = X < x[0] ? x[1] - x[0] : x[np - 1] - x[np - 2];
            ts_status st = ts_spline_eval_deriv(s, X, NULL, &y, &dy, &d2y);
            CHECK(st == TS_OK);
            /* Tolerances (C = 64 ulps): the rounding of Y is ε S.  θ(x) is found
             * to a relative 2ε, i.e. x is matched to ~ε h (the rounding of X̂
             * and u), so y moves by ε h |y'|, y' by ε h |y''|, y'' by ε h |y'''|.
             * y' = Y'/(h X̂'): relative error ε/X̂' from X̂' (terms of size 1
             * cancel to X̂'); y'' = (.)/(h² X̂'³): ε/X̂'³ on the S/h² scale.
             * X̂' (XP) and y''' come from the reference. */
            double C = 64 * EPS, xp = fmin(1.0, XP), xp3 = xp * xp * xp;
            double t0 = C * (S + h * fabs(v[2]));
            double t1 = C * ((S / h) / xp + fabs(v[2]) / xp + h * fabs(v[3]));
            double t2 = C * ((S / h / h) / xp3 + fabs(v[3]) / xp + h * fabs(v[4]));
            if (ke == 6) { /* parabola y_e + y'_e t + y''_e t²/2, |t| <= h/2, from the end values */
                t0 = C * S * (1 + 1 / xp + 1 / xp3);
                t1 = C * (S / h) * (1 / xp + 1 / xp3);
                t2 = C * (S / h / h) / xp3;
            }
            CHECK_CLOSE(y, v[1], t0);
            CHECK_CLOSE(dy, v[2], t1);
            CHECK_CLOSE(d2y, v[3], t2);
            if (kp == 6)
                npt++;
            else
                next++;
            continue;
        }
        if (parse_row(line, "int", v, 8) == 3) {
            double r;
            CHECK(ts_spline_integral(s, v[0], v[1], &r) == TS_OK);
            /* rounding of sums of h-weighted values: 64 ε S (|b − a| + h) */
            CHECK_CLOSE(r, v[2], 64 * EPS * S * (fabs(v[1] - v[0]) + hmax));
            nint++;
            continue;
        }
        if (strcmp(line, "end") == 0) {
            ts_spline_free(s);
            s = NULL;
        }
    }
    fclose(fp);
    (void)hmin;
    CHECKF(ncase == 4 && npt > 100 && next == 8 && nint == 24, "cases %d pts %d ext %d int %d",
           ncase, npt, next, nint);
}

/* ---- property tests -------------------------------------------------- */

/* Lines are reproduced to rounding: Y − mX − c = Σ A_l (Y_l − m X_l − c) = 0
 * (docs/method.md §4), so only the rounding of the control values and of θ(x) remains. */
static void test_lines(void)
{
    for (int rep = 0; rep < 40; rep++) {
        size_t np = 2 + (size_t)(th_unit() * 12);
        double x[16], f[16], d[16], al[16], be[16];
        double m = (th_unit() - 0.5) * 20, c = (th_unit() - 0.5) * 10, sc = rep % 3 == 0 ? 1e-6 : 1.0;
        x[0] = (th_unit() - 0.5) * 4 * sc;
        for (size_t i = 1; i < np; i++)
            x[i] = x[i - 1] + (0.01 + th_unit()) * sc;
        for (size_t i = 0; i < np; i++)
            f[i] = m * x[i] + c, d[i] = m;
        for (size_t i = 0; i + 1 < np; i++) {
            al[i] = rep % 4 == 0 ? TS_GEOMETRIC_A_MIN : 0.5 + 10 * th_unit();
            be[i] = 0;
        }
        ts_spline *s = geo_new(x, f, d, np, al, be, TS_EXTRAP_ERROR);
        if (!s)
            continue;
        double worst = 0, worst_d = 0, scale = fabs(c) + fabs(m) * (fabs(x[0]) + fabs(x[np - 1]));
        for (size_t i = 0; i + 1 < np; i++)
            for (int j = 0; j <= 50; j++) {
                double xx = x[i] + (x[i + 1] - x[i]) * j / 50.0, y, dy;
                ts_spline_eval_deriv(s, xx, NULL, &y, &dy, NULL);
                worst = fmax(worst, fabs(y - (m * xx + c)));
                if (al[i] > 0.4)
                    worst_d = fmax(worst_d, fabs(dy - m));
            }
        /* value: 32 ulps of the scale; slope: (Y'/X̂' with X̂' >= 0.3 for
         * a >= 0.5, docs/accuracy.md §1) 64 ulps of |m| + S/h over 0.3 */
        CHECKF(worst <= 32 * EPS * scale, "line rep %d: %g (scale %g)", rep, worst, scale);
        CHECKF(worst_d <= 64 * EPS * (fabs(m) + scale / (0.01 * sc)) / 0.3, "line slope rep %d: %g",
               rep, worst_d);
        ts_spline_free(s);
    }
}

/* The slope of the graph is d_i at both ends of every interval (docs/method.md §4). */
static void test_knot_slopes(void)
{
    for (int rep = 0; rep < 30; rep++) {
        size_t np = 3 + (size_t)(th_unit() * 10);
        double x[16], f[16], d[16], al[16], be[16];
        x[0] = th_unit();
        for (size_t i = 1; i < np; i++)
            x[i] = x[i - 1] + 0.05 + 3 * th_unit();
        for (size_t i = 0; i < np; i++)
            f[i] = 5 * (th_unit() - 0.5), d[i] = 8 * (th_unit() - 0.5);
        for (size_t i = 0; i + 1 < np; i++)
            al[i] = rep % 2 ? TS_GEOMETRIC_A_MIN : 0.4 + 5 * th_unit(), be[i] = rep % 3 ? 0 : th_unit();
        ts_spline *s = geo_new(x, f, d, np, al, be, TS_EXTRAP_ERROR);
        if (!s)
            continue;
        for (size_t i = 0; i < np; i++) {
            double y, dy, yl, dyl, d2l, h = i ? x[i] - x[i - 1] : x[1] - x[0];
            ts_spline_eval_deriv(s, x[i], NULL, &y, &dy, NULL);
            CHECK(y == f[i]); /* θ = 0 or π/2 exactly: Y = B0 or B3 */
            /* right-hand interval at x_i (the last knot: the left one): y' = Y'/X'
             * with Y'(0) = 3 k d_i, X'(0) = 3 k: two roundings of k */
            CHECK_CLOSE(dy, d[i], 8 * EPS * (fabs(d[i]) + 10 / h));
            if (i > 0 && i + 1 < np) {
                /* from the left, one ulp before the knot: y' moves by y''·ulp */
                double xl = nextafter(x[i], -TH_INF);
                ts_spline_eval_deriv(s, xl, NULL, &yl, &dyl, &d2l);
                CHECK_CLOSE(dyl, d[i], 8 * EPS * (fabs(d[i]) + 10 / h) + 2 * fabs(d2l) * (x[i] - xl));
            }
        }
        ts_spline_free(s);
    }
}

/* Round trip through the control polygon: for θ on a grid, (X(θ), Y(θ)) from
 * the docs/method.md §2 basis in this file must be a point of the evaluated graph.
 * Hostile cases: a at the bound, tiny and huge h, x at the ends. */
static void test_roundtrip(void)
{
    const double scales[4] = {1.0, 1e-12, 1e200, 1e-200};
    const double as[3] = {TS_GEOMETRIC_A_MIN, TS_GEOMETRIC_A_RAISE, 7.0};
    for (int si = 0; si < 4; si++)
        for (int ai = 0; ai < 3; ai++) {
            double h = scales[si], x[3] = {5 * h, 6 * h, 8.5 * h}, f[3] = {1.0, -2.0, 0.5};
            double d[3] = {3 / h, 0.5 / h, -1 / h}, al[2] = {as[ai], as[ai]}, be[2] = {0, 0};
            if (si == 1) /* a tiny interval far from 0 */
                x[0] = 1.0, x[1] = 1.0 + h, x[2] = 1.0 + 2.5 * h;
            ts_spline *s = geo_new(x, f, d, 3, al, be, TS_EXTRAP_ERROR);
            if (!s)
                continue;
            for (size_t i = 0; i < 2; i++) {
                double B[4], X[4];
                ts_spline_control(s, i, B, X);
                double hi = x[i + 1] - x[i], S = 0;
                for (int l = 0; l < 4; l++)
                    S = fmax(S, fabs(B[l]));
                for (int j = 0; j <= 400; j++) {
                    double t = TS_HALF_PI_T * j / 400.0, A[4], y, dy;
                    th_basis(t, A);
                    double xx = A[0] * X[0] + A[1] * X[1] + A[2] * X[2] + A[3] * X[3];
                    double yy = A[0] * B[0] + A[1] * B[1] + A[2] * B[2] + A[3] * B[3];
                    if (j == 0)
                        xx = X[0];
                    if (j == 400)
                        xx = X[3];
                    if (xx < x[i] || xx > x[i + 1])
                        continue;
                    ts_spline_eval_deriv(s, xx, NULL, &y, &dy, NULL);
                    /* xx itself carries ~8 ulps of |x| (the sum above), and y
                     * follows x with slope dy: 64 ε S + 16 ε |x| |dy| */
                    double tol = 64 * EPS * S + 16 * EPS * (fabs(xx) + hi) * fabs(dy);
                    CHECKF(fabs(y - yy) <= tol, "roundtrip scale %g a %g i %zu j %d: %g vs %g",
                           h, as[ai], i, j, y, yy);
                    if (!(fabs(y - yy) <= tol))
                        j = 400;
                }
            }
            ts_spline_free(s);
        }
}

/* Errors: the bound on a_i with caller-given beta (header at TS_FORM_GEOMETRIC). */
static void test_bound(void)
{
    double x[4] = {0, 1, 2, 3}, f[4] = {1, 2, 0, 1}, d[4] = {0, 1, 0, 1};
    double al[3] = {1, 1, 1}, be[3] = {0, 0, 0};
    ts_spline_options o;
    ts_spline_options_init(&o);
    o.form = TS_FORM_GEOMETRIC;
    o.slopes = TS_SLOPES_USER;
    o.user_slopes = d;
    o.n_user_slopes = 4;
    o.alphas = al;
    o.n_alphas = 3;
    o.betas = be;
    o.n_betas = 3;
    ts_spline *s = NULL;
    ts_error e;
    al[2] = nextafter(TS_GEOMETRIC_A_MIN, 0);
    CHECK(ts_spline_new(x, f, 4, &o, &s, &e) == TS_ERR_GEOMETRIC);
    CHECK(s == NULL && e.status == TS_ERR_GEOMETRIC && e.index == 2 && e.where == TS_WHERE_INTERVAL);
    /* alpha below, beta lifts a to the bound: accepted */
    al[2] = 0.3, be[2] = 0.0472;
    CHECK(ts_spline_new(x, f, 4, &o, &s, &e) == TS_OK);
    ts_spline_free(s);
    al[1] = 0.01, be[1] = 0.1;
    CHECK(ts_spline_new(x, f, 4, &o, &s, &e) == TS_ERR_GEOMETRIC && e.index == 1);
    /* scalar alpha */
    o.alphas = NULL, o.betas = NULL, o.alpha = 0.3, o.beta = 0.04;
    CHECK(ts_spline_new(x, f, 4, &o, &s, &e) == TS_ERR_GEOMETRIC && e.index == 0);
    o.beta = 0.05; /* 0.35 */
    CHECK(ts_spline_new(x, f, 4, &o, &s, &e) == TS_OK);
    double a;
    CHECK(ts_spline_a(s, 0, &a) == TS_OK && a == 0.3 + 0.05);
    /* X control points of §4 */
    double B[4], X[4], k = 2.0 / (3.0 * TS_PI_T * (0.3 + 0.05));
    ts_spline_control(s, 1, B, X);
    CHECK_CLOSE(X[1], 1 + k, 4 * EPS);
    CHECK_CLOSE(X[2], 2 - k, 4 * EPS);
    CHECK_CLOSE(B[1], 2 + k * 1, 8 * EPS);
    ts_spline_free(s);
    /* the exact threshold a* = (16 − 9√2)/(3π) lies just below the bound */
    double astar = (16 - 9 * sqrt(2.0)) / (3 * TS_PI_T);
    CHECK(astar < TS_GEOMETRIC_A_MIN && TS_GEOMETRIC_A_MIN - astar < 3e-5);
    CHECK_CLOSE(TS_GEOMETRIC_A_RAISE, 4 / (3 * TS_PI_T), 2 * EPS);
}

/* At a = a* + tiny, X̂' nearly vanishes at θ = π/4 (x = midpoint): the graph
 * is steep there but finite, and increasing for increasing data. */
static void test_steep(void)
{
    double x[2] = {0, 1}, f[2] = {0, 1}, al[1] = {TS_GEOMETRIC_A_MIN}, be[1] = {0};
    double d0[2] = {0.5, 0.5};
    ts_spline *s = geo_new(x, f, d0, 2, al, be, TS_EXTRAP_ERROR);

    if (!s)
        return;
    double prev = -1, y, dy, maxdy = 0;
    int mono = 1;
    for (int j = 0; j <= 20000; j++) {
        double xx = j / 20000.0;
        ts_spline_eval_deriv(s, xx, NULL, &y, &dy, NULL);
        if (y < prev)
            mono = 0;
        prev = y;
        maxdy = fmax(maxdy, dy);
        CHECK(isfinite(dy));
    }
    /* At θ = π/4 (x = 1/2 by symmetry), with g = A1' − A2' = −(8 − 4.5√2)
     * and κ_max = −1/g (docs/accuracy.md §1): Y' = 2sc + 0.5 κ g = 1 − 0.5 astar/a,
     * X̂' = 1 + κ g = 1 − astar/a, so S' = (1 − 0.5 astar/a)/(1 − astar/a) ≈ 8e3 */
    double astar = (16 - 9 * sqrt(2.0)) / (3 * TS_PI_T), r = astar / TS_GEOMETRIC_A_MIN;
    double expect = (1.0 - 0.5 * r) / (1.0 - r);
    ts_spline_eval_deriv(s, 0.5, NULL, &y, &dy, NULL);
    CHECK(mono);
    CHECK_CLOSE(y, 0.5, 4 * EPS);
    CHECK_CLOSE(dy, expect, 1e-9 * expect); /* a* in double: relative 1e-16/6e-5 */
    CHECK(maxdy <= dy * 1.01); /* the steepest point is the midpoint */
    ts_spline_free(s);
}

/* Batch evaluation (kernels.c) and the integral agree with single evaluation. */
static void test_batch_integral(void)
{
    double x[6] = {0, 0.5, 1.7, 2.0, 3.5, 4.0}, f[6] = {1, 3, 2, 2.5, 0, 1};
    double d[6] = {1, 2, -1, 0.5, -2, 1}, al[5] = {0.5, TS_GEOMETRIC_A_MIN, 1, 2, 40}, be[5] = {0};
    ts_spline *s = geo_new(x, f, d, 6, al, be, TS_EXTRAP_LINEAR);
    if (!s)
        return;
    double xq[403], yq[403];
    for (int j = 0; j < 401; j++)
        xq[j] = 4.0 * j / 400.0;
    xq[401] = -0.5, xq[402] = 4.5; /* outside: linear extrapolation */
    for (int der = 0; der <= 2; der++) {
        ts_error e;
        CHECK(ts_spline_eval_batch(s, der, xq, 403, yq, NULL, &e) == TS_OK);
        int bad = 0;
        for (int j = 0; j < 403; j++) {
            double o[3];
            ts_spline_eval_deriv(s, xq[j], NULL, &o[0], &o[1], &o[2]);
            /* kernels.c and geometric.c solve X̂(φ) = u each to rounding:
             * 1e-9 relative to the derivative scale, divided by the
             * condition of S^(k) in φ, 1/X̂'^k with X̂' >= 1 − (8 − 9/√2)κ
             * (at π/4; 7e-5 on the interval with a = a_min, where both
             * paths' S'' are 5e-8 off a long-double solve at x = 1.1) */
            int i = 0;
            while (i < 4 && x[i + 1] <= xq[j])
                i++;
            double xp = 1.0 - (8.0 - 9.0 / sqrt(2.0)) * (2.0 / (3.0 * 3.14159265358979323846 * al[i]));
            if (!(fabs(yq[j] - o[der]) <= 1e-9 * (1 + fabs(o[der])) / pow(xp, der)))
                bad++;
        }
        CHECKF(bad == 0, "batch deriv %d: %d mismatches", der, bad);
    }
    /* LINEAR extrapolation uses the exact end slope d */
    double y;
    ts_spline_eval(s, -0.5, NULL, &y);
    CHECK_CLOSE(y, 1 - 0.5 * 1, 8 * EPS);
    ts_spline_eval(s, 4.5, NULL, &y);
    CHECK_CLOSE(y, 1 + 0.5 * 1, 8 * EPS);
    /* additivity and the fundamental theorem: (I(x+η) − I(x−η))/2η ≈ S(x) */
    double I1, I2, I3;
    CHECK(ts_spline_integral(s, 0.2, 3.9, &I1) == TS_OK);
    CHECK(ts_spline_integral(s, 0.2, 1.0, &I2) == TS_OK);
    CHECK(ts_spline_integral(s, 1.0, 3.9, &I3) == TS_OK);
    CHECK_CLOSE(I1, I2 + I3, 64 * EPS * 4 * 3);
    for (int j = 1; j < 40; j++) {
        double xx = 4.0 * j / 40.0, eta = 1e-4, Ia, Ib, y0, dy, d2y;
        ts_spline_integral(s, 0, xx - eta, &Ia);
        ts_spline_integral(s, 0, xx + eta, &Ib);
        ts_spline_eval_deriv(s, xx, NULL, &y0, &dy, &d2y);
        /* central difference: error eta² |S''|/6 (+ the kink-free form is C¹) */
        double tol = eta * eta * fabs(d2y) + 1e-9;
        if (xx == 0.5 || xx == 1.7 || xx == 2.0 || xx == 3.5)
            tol = eta * (fabs(dy) + 10); /* S'' jumps at knots */
        CHECK_CLOSE((Ib - Ia) / (2 * eta), y0, tol);
    }
    ts_spline_free(s);
}

/* ---- shape schemes in the geometric form ------------------------------ */
static double sample_min_gap(const ts_spline *s, size_t i, const ts_line *L, int sign, int m)
{
    const double *x = ts_spline_x(s);
    double best = TH_INF;
    for (int j = 0; j <= m; j++) {
        double xx = x[i] + (x[i + 1] - x[i]) * j / (double)m, y;
        ts_spline_eval(s, xx, NULL, &y);
        double g = sign > 0 ? y - (L->m * xx + L->c) : (L->m * xx + L->c) - y;
        best = fmin(best, g);
    }
    return best;
}

static void test_shapes(void)
{
    /* paper Table 1 (positive data) */
    double x1[] = {0, 2, 3, 5, 6, 8, 9, 11, 12, 14, 15};
    double f1[] = {20, 1.58, 1.5, 1.2, 0.5, 0.05, 0.2, 1.3, 1.6, 2, 25};
    size_t n1 = sizeof x1 / sizeof *x1;
    ts_spline_options o;
    ts_spline_options_init(&o);
    o.form = TS_FORM_GEOMETRIC;
    o.shape = TS_SHAPE_POSITIVE;
    o.alpha = 0.01;
    ts_spline *s = NULL;
    ts_status st = ts_spline_new(x1, f1, n1, &o, &s, NULL);
    CHECKF(st == TS_OK, "positive/geometric: %s", ts_strerror(st));
    if (s) {
        ts_line zero = {0, 0};
        int raised = 0, ok = 1;
        for (size_t i = 0; i + 1 < n1; i++) {
            double a;
            ts_spline_a(s, i, &a);
            CHECK(a >= TS_GEOMETRIC_A_RAISE);
            ts_interval_report r;
            ts_spline_report(s, i, &r);
            raised += r.term == TS_TERM_GEOMETRIC;
            if (!(sample_min_gap(s, i, &zero, 1, 400) > 0))
                ok = 0;
        }
        CHECK(raised > 0); /* alpha = 0.01 plus a small beta: below 4/(3π) */
        CHECK(ok);
        CHECK(ts_spline_certified(s) == 1);
        ts_spline_free(s);
    }
    /* monotone data (docs/method.md §5.5: B1 <= B2 with X increasing) */
    double x2[] = {0, 1, 2, 3, 4, 5, 6, 7}, f2[] = {0, 0.1, 0.2, 3, 3.1, 3.1, 8, 8.05};
    o.shape = TS_SHAPE_MONOTONE;
    o.alpha = 0.2;
    st = ts_spline_new(x2, f2, 8, &o, &s, NULL);
    CHECKF(st == TS_OK, "monotone/geometric: %s", ts_strerror(st));
    if (s) {
        double prev = -TH_INF, y;
        int mono = 1;
        for (int j = 0; j <= 7000; j++) {
            ts_spline_eval(s, 7.0 * j / 7000, NULL, &y);
            if (y < prev - 1e-14)
                mono = 0;
            prev = y;
        }
        CHECK(mono);
        ts_spline_free(s);
    }
    /* above a line: S > L on dense samples and certified */
    double x3[] = {1, 2, 3, 9, 10, 14, 15}, f3[] = {0.5, 3, 5, 25, 28, 40, 47};
    ts_line L = {2.5, -3.0};
    o.shape = TS_SHAPE_ABOVE;
    o.lower = L;
    o.alpha = 0.05;
    st = ts_spline_new(x3, f3, 7, &o, &s, NULL);
    CHECKF(st == TS_OK, "above/geometric: %s", ts_strerror(st));
    if (s) {
        int ok = 1;
        for (size_t i = 0; i < 6; i++)
            if (!(sample_min_gap(s, i, &L, 1, 400) > 0))
                ok = 0;
        CHECK(ok);
        CHECK(ts_spline_certified(s) == 1);
        ts_spline_free(s);
    }
}

/* ts_spline_certify on user betas: the reported minima agree with dense sampling
 * (the exact minimum is <= every sample and within the sampling error). */
static void test_certify(void)
{
    double x[6] = {0, 1, 2, 3.5, 4, 6}, f[6] = {2, 0.3, 1.5, 0.2, 2.5, 1};
    double d[6] = {-3, 0.5, 1, -2, 3, -1}, al[5] = {0.5, TS_GEOMETRIC_A_MIN, 1, 0.4, 3}, be[5] = {0};
    ts_spline *s = geo_new(x, f, d, 6, al, be, TS_EXTRAP_ERROR);
    if (!s)
        return;
    ts_line lo = {0.2, -0.5}, up = {-0.3, 4.5};
    ts_interval_report rep[5];
    ts_error e;
    ts_status st = ts_spline_certify(s, &lo, &up, rep, &e);
    CHECKF(st == TS_OK || st == TS_ERR_VIOLATED, "certify: %s", ts_strerror(st));
    for (size_t i = 0; i < 5; i++) {
        double gl = sample_min_gap(s, i, &lo, 1, 20000), gu = sample_min_gap(s, i, &up, -1, 20000);
        /* sampling at spacing h/20000 misses the minimum by at most
         * |S'| h/20000 (at most ~1e4 at the bound near the midpoint, else ~10) */
        double tl = (al[i] < 0.35 ? 2.0 : 1e-3) * (x[i + 1] - x[i]) / 20000 * 10 + 1e-12;
        CHECKF(rep[i].gap_lower <= gl + 1e-12 && rep[i].gap_lower >= gl - tl,
               "interval %zu lower: certify %.15g sampled %.15g", i, rep[i].gap_lower, gl);
        CHECKF(rep[i].gap_upper <= gu + 1e-12 && rep[i].gap_upper >= gu - tl,
               "interval %zu upper: certify %.15g sampled %.15g", i, rep[i].gap_upper, gu);
    }
    ts_spline_free(s);
}

int main(void)
{
    TH_CASE("reference");
    test_reference();
    TH_CASE("lines");
    test_lines();
    TH_CASE("knot_slopes");
    test_knot_slopes();
    TH_CASE("roundtrip");
    test_roundtrip();
    TH_CASE("bound");
    test_bound();
    TH_CASE("steep");
    test_steep();
    TH_CASE("batch_integral");
    test_batch_integral();
    TH_CASE("shapes");
    test_shapes();
    TH_CASE("certify");
    test_certify();
    return th_report("test_geometric");
}
