/* The core spline (docs/method.md §3, §6) against an independent reference.
 *
 * Expected values:
 *  - tests/ref/core_ref.csv, written by tests/ref/reference.py (mpmath, 40
 *    digits, docs/method.md §3 recomputed from scratch; derivatives by mpmath.diff and
 *    integrals by mpmath.quad of the script's own S).  Regenerate with
 *      /usr/bin/python3 tests/ref/reference.py > tests/ref/core_ref.csv
 *  - docs/method.md formulas re-derived here (control values, end slopes d_i/a_i,
 *    d_{i+1}/a_i, the C¹ option's d̂), and finite differences.
 *
 * Tolerances.  Let M = max(1, max |B_l| over all intervals) ("scale" in the
 * CSV) and w = π/(2h) = dθ/dx of the interval.  On [0, π/2] the basis obeys
 * Σ|A_l| = 1, Σ max|A_l'| <= 12, Σ max|A_l''| <= 28 (<= 67 by the coefficient
 * bound of test_basis.c), Σ max|A_l'''| <= 98.  The library computes B to a few
 * ulp of M and θ = (x - x_i)·w to ~2 ulp of π/2, so
 *   |S - S_ref|   <= (4 + 12·4)ε·M            ~ 1.2e-14·M -> tol 1e-13·M
 *   |S' - S'_ref| <= w·(12·4 + 67·4)ε·M       ~ 7e-14·w·M -> tol 2e-13·w·M
 *   |S''- S''_ref|<= w²·(67·4 + 98·4)ε·M      ~ 1.5e-13·w²·M -> tol 1e-12·w²·M
 * (a factor >= 5 of margin over the estimate).  Outside [0, π/2] (extension)
 * the basis sums grow to 19, 27, 40 (test_basis.c), and the rounding of θ grows
 * with |θ|: tol 1e-12·w^k·M·(1 + |θ|).  Integrals: the closed form per
 * interval loses a few ulp of h·M, cumulative sums a few ulp of their
 * magnitude <= (x_n - x_0)·M: tol 1e-13·M·(x_n - x_0).
 */
#include "th.h"
#include "th_options.h"
#include "common/th_rng.h"
#include "trigspline.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#ifndef TS_SOURCE_DIR
#define TS_SOURCE_DIR "."
#endif
#define REF_PATH TS_SOURCE_DIR "/tests/ref/core_ref.csv"
#define PI 3.14159265358979323846
#define EPS DBL_EPSILON
#define MAXV 64

typedef struct tcase {
    char name[64];
    int form, slopes;
    size_t np, nal, nbe, n;
    double x[MAXV], f[MAXV], d[MAXV], al[MAXV], be[MAXV];
    double scale;
    ts_spline *sp, *ext;
    double kl[MAXV], kr[MAXV]; /* reference one-sided S' at knots */
    int n_pt, n_ext, n_int, n_sensitive;
} tcase;

/* Split "tag,v1,v2,..." into numbers after the tag; returns the count. */
static size_t parse_nums(const char *line, double *out, size_t max)
{
    const char *p = strchr(line, ',');
    size_t k = 0;
    while (p && k < max) {
        char *end;
        out[k++] = strtod(p + 1, &end);
        p = strchr(end, ',');
    }
    return k;
}

static size_t interval_of(const tcase *tc, double x)
{
    size_t i = 0;
    while (i + 1 < tc->n && x >= tc->x[i + 1])
        i++;
    return i;
}

static double h_of(const tcase *tc, size_t i) { return tc->x[i + 1] - tc->x[i]; }

static ts_spline *build(const tcase *tc, ts_extrap ex)
{
    ts_spline_options o;
    th_options_paper(&o);
    o.form = tc->form ? TS_FORM_C1 : TS_FORM_PAPER;
    if (tc->slopes == 6) {
        o.slopes = TS_SLOPES_USER;
        o.user_slopes = tc->d;
        o.n_user_slopes = tc->np;
    } else {
        o.slopes = TS_SLOPES_ARITHMETIC;
    }
    if (tc->nal == 1)
        o.alpha = tc->al[0];
    else
        o.alphas = tc->al, o.n_alphas = tc->nal;
    if (tc->nbe == 1)
        o.beta = tc->be[0];
    else
        o.betas = tc->be, o.n_betas = tc->nbe;
    o.extrapolate = ex;
    ts_spline *sp = NULL;
    ts_error err;
    ts_status st = ts_spline_new(tc->x, tc->f, tc->np, &o, &sp, &err);
    CHECKF(st == TS_OK && sp, "%s: ts_spline_new -> %d (%s) index %zu", tc->name, (int)st,
           ts_strerror(st), err.index);
    return st == TS_OK ? sp : NULL;
}

static double alpha_i(const tcase *tc, size_t i) { return tc->nal == 1 ? tc->al[0] : tc->al[i]; }
static double beta_i(const tcase *tc, size_t i) { return tc->nbe == 1 ? tc->be[0] : tc->be[i]; }
static double a_i(const tcase *tc, size_t i) { return alpha_i(tc, i) + beta_i(tc, i); }

/* docs/method.md §3 C¹ option: d̂_j = d_j / max(a_{j-1}, a_j), one-sided at the ends. */
static double dhat(const tcase *tc, const double *d, size_t j)
{
    if (j == 0)
        return d[0] / a_i(tc, 0);
    if (j == tc->n)
        return d[j] / a_i(tc, tc->n - 1);
    return d[j] / fmax(a_i(tc, j - 1), a_i(tc, j));
}

/* Expected one-sided slopes of interval i at its left / right end. */
static double slope_start(const tcase *tc, const double *d, size_t i)
{
    return tc->form ? dhat(tc, d, i) : d[i] / a_i(tc, i);
}
static double slope_end(const tcase *tc, const double *d, size_t i)
{
    return tc->form ? dhat(tc, d, i + 1) : d[i + 1] / a_i(tc, i);
}

static double deriv_at(const ts_spline *sp, double x)
{
    double y, dy, d2;
    ts_status st = ts_spline_eval_deriv(sp, x, NULL, &y, &dy, &d2);
    CHECK(st == TS_OK);
    return dy;
}

/* Left limit of S' at x_{i+1} (i.e. the end slope of interval i) by first-order
 * Richardson extrapolation from inside interval i: 2 S'(x-η) - S'(x-2η) has
 * error <= 3η²·max|S'''| (Taylor), with max|S'''| <= w³·98·M; plus 3 times the
 * rounding bound of S' near the knot (2e-13·w·M).  η = 1e-6·h. */
static double left_limit(const tcase *tc, size_t i, double *tol)
{
    double h = h_of(tc, i), w = PI / (2 * h), eta = 1e-6 * h, xe = tc->x[i + 1];
    double s1 = deriv_at(tc->sp, xe - eta), s2 = deriv_at(tc->sp, xe - 2 * eta);
    /* the shifted abscissae are rounded: use the actual offsets */
    double e1 = xe - (xe - eta), e2 = xe - (xe - 2 * eta);
    /* linear extrapolation to offset 0 through (e1, s1), (e2, s2) */
    double lim = s1 + (s1 - s2) * e1 / (e2 - e1);
    *tol = 3 * eta * eta * w * w * w * 98 * tc->scale + 3 * 2e-13 * w * tc->scale;
    return lim;
}

static void case_begin(tcase *tc)
{
    tc->n = tc->np - 1;
    tc->sp = build(tc, TS_EXTRAP_ERROR);
    tc->ext = build(tc, TS_EXTRAP_EXTEND);
    tc->n_pt = tc->n_ext = tc->n_int = tc->n_sensitive = 0;
    if (!tc->sp)
        return;
    const ts_spline *sp = tc->sp;
    size_t n = tc->n;

    /* ---- accessors return what was built */
    CHECK(ts_spline_intervals(sp) == n);
    CHECK(ts_spline_form(sp) == (tc->form ? TS_FORM_C1 : TS_FORM_PAPER));
    CHECK(ts_spline_shape(sp) == TS_SHAPE_NONE);
    CHECK(ts_spline_extrapolation(sp) == TS_EXTRAP_ERROR);
    CHECK(ts_spline_extrapolation(tc->ext) == TS_EXTRAP_EXTEND);
    const double *X = ts_spline_x(sp), *F = ts_spline_f(sp), *D = ts_spline_slopes(sp);
    const double *AL = ts_spline_alpha(sp), *BE = ts_spline_beta(sp);
    CHECK(X && F && D && AL && BE);
    if (!(X && F && D && AL && BE))
        return;
    double hmin = TH_INF;
    for (size_t i = 0; i < n; i++)
        hmin = fmin(hmin, h_of(tc, i));
    for (size_t j = 0; j <= n; j++) {
        CHECKF(X[j] == tc->x[j] && F[j] == tc->f[j], "%s: knot %zu copied", tc->name, j);
        if (tc->slopes == 6)
            CHECKF(D[j] == tc->d[j], "%s: user slope %zu used as given", tc->name, j);
        else /* arithmetic mean in double vs the mpmath one: a few ulp of M/h_min */
            CHECKF(fabs(D[j] - tc->d[j]) <= 1e-13 * tc->scale / hmin, "%s: slope %zu = %.17g, ref %.17g",
                   tc->name, j, D[j], tc->d[j]);
    }
    for (size_t i = 0; i < n; i++) {
        CHECKF(AL[i] == alpha_i(tc, i) && BE[i] == beta_i(tc, i), "%s: alpha/beta %zu", tc->name, i);
        double a = TH_NAN;
        CHECK(ts_spline_a(sp, i, &a) == TS_OK);
        CHECK_CLOSE(a, a_i(tc, i), 2 * EPS * a_i(tc, i));
        /* control values re-derived from docs/method.md §3 with the slopes the spline used */
        double B[4], Xc[4], h = h_of(tc, i), K = 2 * h / (3 * PI);
        double e1 = tc->f[i] + K * slope_start(tc, D, i), e2 = tc->f[i + 1] - K * slope_end(tc, D, i);
        CHECK(ts_spline_control(sp, i, B, Xc) == TS_OK);
        CHECKF(B[0] == tc->f[i] && B[3] == tc->f[i + 1], "%s: B0, B3 of %zu", tc->name, i);
        CHECK_CLOSE(B[1], e1, 8 * EPS * tc->scale);
        CHECK_CLOSE(B[2], e2, 8 * EPS * tc->scale);
        /* header: in the paper and C¹ forms X = x_i + (0, K, h - K, h), K = 2h/(3π),
         * so the first and last legs of the polygon are tangent to the curve */
        CHECKF(Xc[0] == tc->x[i] && Xc[3] == tc->x[i + 1] &&
                   fabs(Xc[1] - (tc->x[i] + K)) <= 4 * EPS * fabs(tc->x[i + 1]) + 4 * EPS * h &&
                   fabs(Xc[2] - (tc->x[i + 1] - K)) <= 4 * EPS * fabs(tc->x[i + 1]) + 4 * EPS * h,
               "%s: control abscissae of %zu = %.17g %.17g %.17g %.17g (header: x_i + (0, K, h-K, h))", tc->name,
               i, Xc[0], Xc[1], Xc[2], Xc[3]);
        /* tangency: (B1 - B0)/K and (B3 - B2)/K are the end slopes */
        CHECK_CLOSE((B[1] - B[0]) / (Xc[1] - Xc[0]), slope_start(tc, D, i),
                    16 * EPS * tc->scale / K + 1e-12 * fabs(slope_start(tc, D, i)));
        CHECK_CLOSE((B[3] - B[2]) / (Xc[3] - Xc[2]), slope_end(tc, D, i),
                    16 * EPS * tc->scale / K + 1e-12 * fabs(slope_end(tc, D, i)));
        double B2[4];
        CHECK(ts_spline_control(sp, i, B2, NULL) == TS_OK && B2[1] == B[1] && B2[2] == B[2]);
    }

    /* ---- every knot is interpolated (θ = 0 exactly at x_i; at x_n θ is π/2
     * up to rounding: 4ε·M) */
    for (size_t j = 0; j <= n; j++) {
        double y = TH_NAN;
        CHECK(ts_spline_eval(sp, tc->x[j], NULL, &y) == TS_OK);
        CHECKF(fabs(y - tc->f[j]) <= 4 * EPS * tc->scale, "%s: S(x_%zu) = %.17g, f = %.17g", tc->name, j, y,
               tc->f[j]);
    }

    /* ---- both end slopes of every interval (docs/method.md §3: d_i/a_i and d_{i+1}/a_i;
     * C¹: d̂_i, d̂_{i+1}).  This catches the paper's printed "+" in B2, which
     * makes the right end slope -d_{i+1}/a_i. */
    for (size_t i = 0; i < n; i++) {
        double h = h_of(tc, i), w = PI / (2 * h);
        /* right-hand derivative at x_i: ts_spline_eval_deriv uses interval i there.
         * S'(x_i+) = w·3(B1 - B0): rounding 6ε·M·w, expected value 4ε. */
        double want = slope_start(tc, D, i);
        double got = deriv_at(sp, tc->x[i]);
        double tol = 16 * EPS * tc->scale * w + 4 * EPS * fabs(want);
        CHECKF(fabs(got - want) <= tol, "%s: S'(x_%zu+) = %.17g, d_i/a_i = %.17g", tc->name, i, got, want);
        double wantr = slope_end(tc, D, i), tl;
        double gotl = left_limit(tc, i, &tl);
        CHECKF(fabs(gotl - wantr) <= tl + 4 * EPS * fabs(wantr),
               "%s: S'(x_%zu-) of interval %zu = %.17g, want %.17g (tol %.3g)", tc->name, i + 1, i, gotl,
               wantr, tl);
        /* the check must be able to see the printed "+" sign: it would give -wantr */
        if (fabs(2 * wantr) > 10 * tl)
            tc->n_sensitive++;
        if (i + 1 == n) { /* at x_n the library uses the last interval: exact left end */
            double gn = deriv_at(sp, tc->x[n]);
            CHECKF(fabs(gn - wantr) <= 64 * EPS * tc->scale * w + 4 * EPS * fabs(wantr),
                   "%s: S'(x_n) = %.17g want %.17g", tc->name, gn, wantr);
        }
        /* C¹ option: left and right derivatives equal at inner knots; paper
         * form: the jump is d_j (1/a_i - 1/a_{i+1}) (docs/method.md §3) */
        if (i + 1 < n) {
            double right = deriv_at(sp, tc->x[i + 1]);
            double jump = tc->form ? 0.0 : D[i + 1] / a_i(tc, i + 1) - D[i + 1] / a_i(tc, i);
            CHECKF(fabs((right - gotl) - jump) <= tl + 16 * EPS * tc->scale * PI / (2 * h_of(tc, i + 1)) +
                                                      8 * EPS * (fabs(right) + fabs(gotl)),
                   "%s: derivative jump at x_%zu: %.17g, want %.17g", tc->name, i + 1, right - gotl, jump);
        }
    }
    CHECKF(tc->n_sensitive > 0 || n == 0, "%s: no interval where the end-slope check can see a sign error",
           tc->name);
}

static void check_knot_ref(tcase *tc, size_t j, double left, double right)
{
    if (!tc->sp || j > tc->n)
        return;
    const double *D = ts_spline_slopes(tc->sp);
    /* the docs/method.md formula with the library's slopes vs the mpmath derivative of the
     * reference's own S: the slopes differ by a few ulp of M/h_min */
    double hmin = TH_INF;
    for (size_t i = 0; i < tc->n; i++)
        hmin = fmin(hmin, h_of(tc, i));
    double tol = 1e-12 * tc->scale / hmin;
    if (j > 0) {
        double tl, lim = left_limit(tc, j - 1, &tl);
        CHECKF(fabs(slope_end(tc, D, j - 1) - left) <= tol, "%s: knot %zu left slope vs reference", tc->name, j);
        CHECKF(fabs(lim - left) <= tl + tol, "%s: knot %zu numeric left slope %.17g vs reference %.17g", tc->name,
               j, lim, left);
    }
    if (j < tc->n) {
        double r = deriv_at(tc->sp, tc->x[j]);
        CHECKF(fabs(slope_start(tc, D, j) - right) <= tol, "%s: knot %zu right slope vs reference", tc->name, j);
        CHECKF(fabs(r - right) <= tol, "%s: knot %zu S'(x+) %.17g vs reference %.17g", tc->name, j, r, right);
    }
}

static void check_ctl(tcase *tc, const double *v, size_t k)
{
    if (!tc->sp || k != 5)
        return;
    size_t i = (size_t)v[0];
    double B[4];
    CHECK(ts_spline_control(tc->sp, i, B, NULL) == TS_OK);
    for (int l = 0; l < 4; l++)
        CHECKF(fabs(B[l] - v[1 + l]) <= 1e-13 * tc->scale, "%s: B%d of interval %zu = %.17g, ref %.17g",
               tc->name, l, i, B[l], v[1 + l]);
}

static void check_pt(tcase *tc, const double *v)
{
    if (!tc->sp)
        return;
    double x = v[0], y, dy, d2y;
    size_t i = interval_of(tc, x);
    double w = PI / (2 * h_of(tc, i)), M = tc->scale;
    ts_status st = ts_spline_eval_deriv(tc->sp, x, NULL, &y, &dy, &d2y);
    CHECK(st == TS_OK);
    CHECKF(fabs(y - v[1]) <= 1e-13 * M, "%s: S(%.17g) = %.17g, ref %.17g", tc->name, x, y, v[1]);
    CHECKF(fabs(dy - v[2]) <= 2e-13 * w * M, "%s: S'(%.17g) = %.17g, ref %.17g", tc->name, x, dy, v[2]);
    CHECKF(fabs(d2y - v[3]) <= 1e-12 * w * w * M, "%s: S''(%.17g) = %.17g, ref %.17g", tc->name, x, d2y, v[3]);
    /* ts_spline_eval gives the same value; a cursor gives the same values */
    double y0 = TH_NAN;
    ts_cursor cur = {(size_t)tc->n_pt * 7919u % (tc->n + 3)}; /* arbitrary, possibly stale hint */
    CHECK(ts_spline_eval(tc->sp, x, &cur, &y0) == TS_OK && y0 == y);
    tc->n_pt++;
}

static void check_ext(tcase *tc, const double *v)
{
    if (!tc->ext)
        return;
    double x = v[0], y, dy, d2y;
    size_t i = x < tc->x[0] ? 0 : tc->n - 1;
    double h = h_of(tc, i), w = PI / (2 * h), M = tc->scale;
    double theta = (x - tc->x[i]) * w, g = 1 + fabs(theta);
    ts_status st = ts_spline_eval_deriv(tc->ext, x, NULL, &y, &dy, &d2y);
    CHECK(st == TS_OK);
    CHECKF(fabs(y - v[1]) <= 1e-12 * M * g, "%s: extended S(%.17g) = %.17g, ref %.17g", tc->name, x, y, v[1]);
    CHECKF(fabs(dy - v[2]) <= 1e-12 * w * M * g, "%s: extended S'(%.17g) = %.17g, ref %.17g", tc->name, x, dy,
           v[2]);
    CHECKF(fabs(d2y - v[3]) <= 1e-12 * w * w * M * g, "%s: extended S''(%.17g) = %.17g, ref %.17g", tc->name, x,
           d2y, v[3]);
    /* the default policy refuses the same query with NaN outputs */
    y = dy = d2y = 0;
    CHECK(ts_spline_eval_deriv(tc->sp, x, NULL, &y, &dy, &d2y) == TS_ERR_DOMAIN && isnan(y) && isnan(dy) && isnan(d2y));
    tc->n_ext++;
}

static void check_int(tcase *tc, const double *v)
{
    if (!tc->sp)
        return;
    double r = TH_NAN, r2 = TH_NAN;
    double tol = 1e-13 * tc->scale * (tc->x[tc->n] - tc->x[0]);
    CHECK(ts_spline_integral(tc->sp, v[0], v[1], &r) == TS_OK);
    CHECKF(fabs(r - v[2]) <= tol, "%s: integral %.17g..%.17g = %.17g, ref %.17g", tc->name, v[0], v[1], r, v[2]);
    CHECK(ts_spline_integral(tc->sp, v[1], v[0], &r2) == TS_OK);
    CHECK_CLOSE(r2, -r, 1e-15 * tc->scale * (tc->x[tc->n] - tc->x[0]));
    /* every extrapolation policy integrates the same inside the data */
    CHECK(ts_spline_integral(tc->ext, v[0], v[1], &r2) == TS_OK && r2 == r);
    tc->n_int++;
}

/* Checks that need only the spline and the data (run at "end"). */
static void case_end(tcase *tc)
{
    const ts_spline *sp = tc->sp;
    if (sp) {
        size_t n = tc->n;
        double x0 = tc->x[0], xn = tc->x[n], L = xn - x0, M = tc->scale;
        CHECKF(tc->n_pt >= (int)(8 * n) && tc->n_ext >= 6 && tc->n_int >= 8, "%s: reference records read",
               tc->name);

        /* integral additivity on a pseudo-random set of triples */
        th_rng gen = TH_RNG_INIT(777u);
        for (int k = 0; k < 60; k++) {
            double u[3];
            for (int m = 0; m < 3; m++) {
                u[m] = x0 + L * th_rng_unit(&gen);
            }
            if (k % 5 == 0)
                u[1] = tc->x[(size_t)k % (n + 1)]; /* a knot in the middle */
            double ab = TH_NAN, bc = TH_NAN, ac = TH_NAN; /* NaN if a call fails */
            CHECK(ts_spline_integral(sp, u[0], u[1], &ab) == TS_OK && ts_spline_integral(sp, u[1], u[2], &bc) == TS_OK &&
                  ts_spline_integral(sp, u[0], u[2], &ac) == TS_OK);
            CHECK_CLOSE(ab + bc, ac, 3e-13 * M * L);
        }
        /* the whole range equals the sum over intervals */
        double whole, sum = 0;
        CHECK(ts_spline_integral(sp, x0, xn, &whole) == TS_OK);
        for (size_t i = 0; i < n; i++) {
            double p;
            CHECK(ts_spline_integral(sp, tc->x[i], tc->x[i + 1], &p) == TS_OK);
            sum += p;
        }
        CHECK_CLOSE(whole, sum, 1e-13 * M * L);

        /* second derivative vs central differences of S' and first derivative
         * vs central differences of S, at points >= 1e-3 h from the knots.
         * δ = 1e-4·h: truncation δ²/6·w⁴·(4·56)·M (resp. δ²/6·w³·98·M), rounding
         * 2·2e-13·w·M/(2δ) (resp. 2·1e-13·M/(2δ)). */
        for (size_t i = 0; i < n; i++) {
            double h = h_of(tc, i), w = PI / (2 * h), del = 1e-4 * h;
            for (int k = 1; k <= 9; k++) {
                double x = tc->x[i] + h * (0.001 + 0.998 * k / 10.0);
                double y, dy, d2y, yp, yq, dp, dq, dd;
                CHECK(ts_spline_eval_deriv(sp, x, NULL, &y, &dy, &d2y) == TS_OK);
                CHECK(ts_spline_eval_deriv(sp, x + del, NULL, &yp, &dp, &dd) == TS_OK);
                CHECK(ts_spline_eval_deriv(sp, x - del, NULL, &yq, &dq, &dd) == TS_OK);
                double e1 = x + del - x, e2 = x - (x - del); /* actual offsets */
                double fd2 = (dp - dq) / (e1 + e2), fd1 = (yp - yq) / (e1 + e2);
                double t2 = del * del / 6 * pow(w, 4) * 224 * M + 2e-13 * w * M / del;
                double t1 = del * del / 6 * pow(w, 3) * 98 * M + 1e-13 * M / del;
                CHECKF(fabs(d2y - fd2) <= t2, "%s: S'' at %.17g = %.17g, FD %.17g (tol %.3g)", tc->name, x, d2y,
                       fd2, t2);
                CHECKF(fabs(dy - fd1) <= t1, "%s: S' at %.17g = %.17g, FD %.17g (tol %.3g)", tc->name, x, dy, fd1,
                       t1);
            }
        }

        /* extrapolation policies other than EXTEND */
        ts_spline *cl = build(tc, TS_EXTRAP_CLAMP), *li = build(tc, TS_EXTRAP_LINEAR);
        if (cl && li) {
            double h0 = h_of(tc, 0), hn = h_of(tc, n - 1);
            const double *D = ts_spline_slopes(sp);
            double s0 = slope_start(tc, D, 0), sn = slope_end(tc, D, n - 1);
            double qs[6] = {x0 - 1e-9 * h0, x0 - 0.5 * h0, x0 - 1e6 * h0, xn + 1e-9 * hn, xn + 3 * hn, xn + 1e6 * hn};
            for (int k = 0; k < 6; k++) {
                double x = qs[k], y, dy, d2y;
                int left = k < 3;
                double fe = left ? tc->f[0] : tc->f[n], xe = left ? x0 : xn, se = left ? s0 : sn;
                double w = PI / (2 * (left ? h0 : hn));
                CHECK(ts_spline_eval_deriv(cl, x, NULL, &y, &dy, &d2y) == TS_OK);
                CHECKF(y == fe && dy == 0 && d2y == 0, "%s: clamp at %.17g: %.17g %.17g %.17g", tc->name, x, y, dy,
                       d2y);
                CHECK(ts_spline_eval_deriv(li, x, NULL, &y, &dy, &d2y) == TS_OK);
                /* tangent line: end value + one-sided end slope (docs/method.md §3 slope, to
                 * the rounding of S' at the end, 16ε·w·M) */
                double ts = 16 * EPS * w * M + 4 * EPS * fabs(se);
                CHECKF(fabs(dy - se) <= ts, "%s: linear slope at %.17g = %.17g, want %.17g", tc->name, x, dy, se);
                CHECKF(fabs(y - (fe + se * (x - xe))) <= 4 * EPS * M + ts * fabs(x - xe) + 4 * EPS * fabs(se * (x - xe)),
                       "%s: linear value at %.17g = %.17g, want %.17g", tc->name, x, y, fe + se * (x - xe));
                CHECK(d2y == 0);
                /* continuity of EXTEND and LINEAR at the end: 1e-9·h away the value
                 * differs from f_end by <= 1e-9·h·|S'| + rounding */
                if (k == 0 || k == 3) {
                    double ye;
                    CHECK(ts_spline_eval(tc->ext, x, NULL, &ye) == TS_OK);
                    CHECKF(fabs(ye - fe) <= 1e-9 * (left ? h0 : hn) * (fabs(se) + 1e-9 * w * w * 67 * M) +
                                              1e-13 * M,
                           "%s: extension not continuous at the end", tc->name);
                    /* LINEAR and EXTEND agree to first order: η²/2·w²·67·M */
                    double eta = 1e-9 * (left ? h0 : hn);
                    CHECK(fabs(y - ye) <= eta * eta / 2 * w * w * 67 * M + 2e-13 * M + eta * ts);
                }
            }
            /* inside the data every policy agrees exactly */
            for (int k = 0; k <= 20; k++) {
                double x = x0 + L * k / 20.0, a = TH_NAN, b = TH_NAN, c = TH_NAN, d = TH_NAN;
                CHECK(ts_spline_eval(sp, x, NULL, &a) == TS_OK && ts_spline_eval(cl, x, NULL, &b) == TS_OK &&
                      ts_spline_eval(li, x, NULL, &c) == TS_OK && ts_spline_eval(tc->ext, x, NULL, &d) == TS_OK);
                CHECK(a == b && a == c && a == d);
            }
            /* integrals outside the data are refused under every policy */
            double r = 0;
            CHECK(ts_spline_integral(cl, x0 - h0, xn, &r) == TS_ERR_DOMAIN);
            CHECK(ts_spline_integral(li, x0, xn + hn, &r) == TS_ERR_DOMAIN);
            /* ±Inf (header): clamped under TS_EXTRAP_CLAMP, TS_ERR_DOMAIN under
             * every other policy, NaN outputs */
            double y, dy, d2y;
            CHECKF(ts_spline_eval_deriv(cl, TH_INF, NULL, &y, &dy, &d2y) == TS_OK && y == tc->f[n] && dy == 0 &&
                       d2y == 0,
                   "%s: clamp at +Inf", tc->name);
            CHECKF(ts_spline_eval(cl, -TH_INF, NULL, &y) == TS_OK && y == tc->f[0], "%s: clamp at -Inf", tc->name);
            const ts_spline *others[3] = {sp, li, tc->ext};
            for (int k = 0; k < 3; k++)
                for (int sg = -1; sg <= 1; sg += 2) {
                    y = dy = d2y = 0;
                    CHECKF(ts_spline_eval_deriv(others[k], sg < 0 ? -HUGE_VAL : HUGE_VAL, NULL, &y, &dy, &d2y) == TS_ERR_DOMAIN &&
                               isnan(y) && isnan(dy) && isnan(d2y),
                           "%s: policy %d at %g*Inf", tc->name, k, (double)sg);
                }
            CHECK(ts_spline_eval(cl, TH_NAN, NULL, &y) == TS_ERR_DOMAIN && isnan(y));
            CHECK(ts_spline_eval(li, TH_NAN, NULL, &y) == TS_ERR_DOMAIN && isnan(y));
            CHECK(ts_spline_eval(tc->ext, TH_NAN, NULL, &y) == TS_ERR_DOMAIN && isnan(y));
        }
        ts_spline_free(cl);
        ts_spline_free(li);
    }
    ts_spline_free(tc->sp);
    ts_spline_free(tc->ext);
    tc->sp = tc->ext = NULL;
}

/* opt == NULL means all defaults: same spline as ts_spline_options_init's, which are
 * the geometric form, Steffen's slopes, alpha = TS_DEFAULT_ALPHA >= 8/(3π)
 * (docs/method.md §5.10), beta 0, extrapolation error. */
static void test_defaults(void)
{
    const double x[5] = {0, 1, 2.5, 3, 4.75}, f[5] = {1, -2, 0.5, 3, 2};
    ts_spline *a = NULL, *b = NULL;
    ts_spline_options o;
    ts_spline_options_init(&o);
    CHECK(o.form == TS_FORM_GEOMETRIC && o.slopes == TS_SLOPES_STEFFEN &&
          o.alpha == TS_DEFAULT_ALPHA && o.beta == 0.0 &&
          o.shape == TS_SHAPE_NONE && o.extrapolate == TS_EXTRAP_ERROR && o.margin == TS_DEFAULT_MARGIN &&
          o.alphas == NULL && o.betas == NULL && o.user_slopes == NULL && o.certify == 1);
    /* the bound of docs/method.md §5.10 with D = 2, and not far above it */
    CHECK(TS_DEFAULT_ALPHA >= 8.0 / (3.0 * TH_PI) && TS_DEFAULT_ALPHA < 1.002 * 8.0 / (3.0 * TH_PI));
    CHECK(ts_spline_new(x, f, 5, NULL, &a, NULL) == TS_OK);
    CHECK(ts_spline_new(x, f, 5, &o, &b, NULL) == TS_OK);
    if (a && b) {
        for (int k = 0; k <= 50; k++) {
            double t = 4.75 * k / 50.0, ya, yb, da, db, sa, sb;
            CHECK(ts_spline_eval_deriv(a, t, NULL, &ya, &da, &sa) == TS_OK);
            CHECK(ts_spline_eval_deriv(b, t, NULL, &yb, &db, &sb) == TS_OK);
            CHECK(ya == yb && da == db && sa == sb);
        }
        CHECK(ts_spline_alpha(a)[2] == TS_DEFAULT_ALPHA && ts_spline_beta(a)[2] == 0.0);
        CHECK(ts_spline_form(a) == TS_FORM_GEOMETRIC);
        /* arithmetic mean is exact on quadratics (docs/method.md §6): slopes of 2x² - x */
        ts_spline_free(a);
        a = NULL;
        double q[5];
        for (int i = 0; i < 5; i++)
            q[i] = 2 * x[i] * x[i] - x[i];
        ts_spline_options ar = o;
        ar.slopes = TS_SLOPES_ARITHMETIC;
        CHECK(ts_spline_new(x, q, 5, &ar, &a, NULL) == TS_OK);
        if (a)
            for (int i = 0; i < 5; i++)
                CHECK_CLOSE(ts_spline_slopes(a)[i], 4 * x[i] - 1, 1e-13 * 50);
        /* evaluation does not change the spline */
        double y;
        CHECK(ts_spline_eval(b, 1.7, NULL, &y) == TS_OK);
        CHECK(ts_spline_x(b)[1] == 1.0 && ts_spline_f(b)[1] == -2.0);
    }
    ts_spline_free(a);
    ts_spline_free(b);
    /* the library linked in is the header's version (generated from
     * CMakeLists.txt; tests/check_version.py compares that with the rest) */
    CHECK(strcmp(ts_version(), TS_VERSION_STRING) == 0);
    char v[64];
    snprintf(v, sizeof v, "%d.%d.%d", TS_VERSION_MAJOR, TS_VERSION_MINOR, TS_VERSION_PATCH);
    CHECK(strcmp(ts_version(), v) == 0);
    CHECK(TS_VERSION_NUM == TS_VERSION_MAJOR * 65536 + TS_VERSION_MINOR * 256 + TS_VERSION_PATCH);
    CHECK(TS_VERSION_AT_LEAST(TS_VERSION_MAJOR, TS_VERSION_MINOR, TS_VERSION_PATCH));
    CHECK(TS_VERSION_AT_LEAST(0, 0, 0) && TS_VERSION_AT_LEAST(0, 1, 255));
    CHECK(!TS_VERSION_AT_LEAST(TS_VERSION_MAJOR, TS_VERSION_MINOR, TS_VERSION_PATCH + 1));
    CHECK(!TS_VERSION_AT_LEAST(TS_VERSION_MAJOR, TS_VERSION_MINOR + 1, 0));
    CHECK(!TS_VERSION_AT_LEAST(TS_VERSION_MAJOR + 1, 0, 0));
#if !TS_VERSION_AT_LEAST(0, 2, 0) || TS_VERSION_NUM < 0x000200
    CHECK(!"TS_VERSION_AT_LEAST and TS_VERSION_NUM work in #if");
#endif
}

/* A constant is reproduced exactly (ΣA = 1, all B equal), whatever a_i. */
static void test_constant(void)
{
    double x[4] = {-1, 0.5, 0.75, 4}, f[4] = {2.5, 2.5, 2.5, 2.5}, al[3] = {0.1, 3, 1}, be[3] = {0, 0.5, 7};
    ts_spline_options o;
    th_options_paper(&o);
    o.alphas = al, o.n_alphas = 3, o.betas = be, o.n_betas = 3;
    for (int form = 0; form < 2; form++) {
        o.form = form ? TS_FORM_C1 : TS_FORM_PAPER;
        ts_spline *s = NULL;
        CHECK(ts_spline_new(x, f, 4, &o, &s, NULL) == TS_OK);
        if (!s)
            continue;
        for (int k = 0; k <= 100; k++) {
            double t = -1 + 5 * k / 100.0, y, dy, d2y;
            CHECK(ts_spline_eval_deriv(s, t, NULL, &y, &dy, &d2y) == TS_OK);
            CHECK_CLOSE(y, 2.5, 4 * EPS * 2.5);
            CHECK_CLOSE(dy, 0, 64 * EPS * 2.5 * PI / 2 / 0.25);
            CHECK_CLOSE(d2y, 0, 256 * EPS * 2.5 * pow(PI / 2 / 0.25, 2));
        }
        double r;
        CHECK(ts_spline_integral(s, -1, 4, &r) == TS_OK);
        CHECK_CLOSE(r, 12.5, 1e-14 * 12.5);
        ts_spline_free(s);
    }
}

int main(void)
{
    TH_CASE("reference cases"); /* each check's message names its case */
    FILE *fp = fopen(REF_PATH, "r");
    CHECKF(fp != NULL, "cannot open %s", REF_PATH);
    int n_cases = 0;
    if (fp) {
        static char line[1 << 16];
        static tcase tc;
        double v[MAXV];
        int in_case = 0;
        while (fgets(line, sizeof line, fp)) {
            line[strcspn(line, "\r\n")] = 0;
            if (line[0] == '#' || line[0] == 0)
                continue;
            if (strncmp(line, "case,", 5) == 0) {
                memset(&tc, 0, sizeof tc);
                char *p = line + 5, *q = strchr(p, ',');
                size_t len = q ? (size_t)(q - p) : 0;
                if (len >= sizeof tc.name)
                    len = sizeof tc.name - 1;
                memcpy(tc.name, p, len);
                size_t k = parse_nums(q ? q - 1 : line, v, 6);
                /* parse_nums skips to the first comma after its start: q - 1 is
                 * the name's last character, so v = FORM, SLOPES, NP, NAL, NBE */
                CHECK(k == 5);
                tc.form = (int)v[0], tc.slopes = (int)v[1];
                tc.np = (size_t)v[2], tc.nal = (size_t)v[3], tc.nbe = (size_t)v[4];
                CHECK(tc.np >= 2 && tc.np <= MAXV);
                in_case = 1;
                n_cases++;
                continue;
            }
            if (!in_case)
                continue;
            size_t k = parse_nums(line, v, MAXV);
            if (strncmp(line, "x,", 2) == 0) {
                CHECK(k == tc.np);
                memcpy(tc.x, v, k * sizeof *v);
            } else if (strncmp(line, "f,", 2) == 0) {
                memcpy(tc.f, v, k * sizeof *v);
            } else if (strncmp(line, "d,", 2) == 0) {
                memcpy(tc.d, v, k * sizeof *v);
            } else if (strncmp(line, "alpha,", 6) == 0) {
                CHECK(k == tc.nal);
                memcpy(tc.al, v, k * sizeof *v);
            } else if (strncmp(line, "beta,", 5) == 0) {
                CHECK(k == tc.nbe);
                memcpy(tc.be, v, k * sizeof *v);
            } else if (strncmp(line, "scale,", 6) == 0) {
                tc.scale = v[0];
                case_begin(&tc);
            } else if (strncmp(line, "ctl,", 4) == 0) {
                check_ctl(&tc, v, k);
            } else if (strncmp(line, "knot,", 5) == 0) {
                check_knot_ref(&tc, (size_t)v[0], v[1], v[2]);
            } else if (strncmp(line, "pt,", 3) == 0) {
                check_pt(&tc, v);
            } else if (strncmp(line, "ext,", 4) == 0) {
                check_ext(&tc, v);
            } else if (strncmp(line, "int,", 4) == 0) {
                check_int(&tc, v);
            } else if (strcmp(line, "end") == 0) {
                case_end(&tc);
                in_case = 0;
            }
        }
        fclose(fp);
    }
    CHECKF(n_cases >= 16, "only %d reference cases read", n_cases);
    TH_CASE("defaults");
    test_defaults();
    TH_CASE("constant");
    test_constant();
    return th_report("test_core");
}
