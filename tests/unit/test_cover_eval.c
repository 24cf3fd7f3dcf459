/* Evaluation paths that no other test reaches, and the facts that make the
 * geometric solve one code path (coverage; docs/method.md §4):
 *  - solve_scan: over a dense (κ, u) grid every query stops within 9 Halley
 *    steps (the cap TS_GEO_PASSES is 16), the root's residual is rounding,
 *    and the start's model derivative is positive where it divides;
 *  - solve_worst: the slowest point of that grid (a_i = TS_GEOMETRIC_A_MIN,
 *    u near 1/2: 9 steps) through ts_spline_eval and every kernel, against a
 *    long-double solve;
 *  - huge_a: a_i = 1e300 at a knot (u = 0: Halley's denominator 18κ²
 *    underflows to 0, the guard keeps 0/0 and FE_INVALID away);
 *  - subnormal_u: the solve at subnormal u (steps are rounding noise; the
 *    iterate at the cap is u/(3κ) to a few 2^-1074/κ);
 *  - pick, mt_threads: the kernel choice for every CPU-feature combination
 *    and the thread count for every processor count;
 *  - entry_points: the NULL and NaN cases of ts_spline_eval and ts_spline_eval_deriv;
 *  - interval_eval: ts__interval_eval inside an interval with every want.
 * Expected values come from the definitions re-derived here (X̂ of
 * docs/method.md §4 with libm's sine and cosine in long double; the
 * documented choice of kernel and thread count), each tolerance where it is
 * used. */
#include "th.h"
#include "th_options.h"
#include "trigspline.h"
#include "internal.h"

#include <fenv.h>
#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

#define EPS DBL_EPSILON
/* the largest κ the library forms: a_i >= TS_GEOMETRIC_A_MIN, κ = 2/(3π a)
 * rounded as geometric.c rounds it (monotone in a) */
static double kappa_max(void)
{
    volatile double a = TS_GEOMETRIC_A_MIN;
    return ts__kappa(a);
}

/* X̂(φ) = s² + κ(A1 − A2) and X̂'(φ) in long double (docs/method.md §4, §2:
 * A1 = s(1 − s)(3 − s), A2 = c(1 − c)(3 − c)). */
static long double xhat_l(long double k, long double phi, long double *dx)
{
    long double s = sinl(phi), c = cosl(phi), h = sinl(phi / 2), mc = 2 * h * h; /* 1 − c */
    long double A1 = s * (1 - s) * (3 - s), A2 = c * mc * (3 - c);
    if (dx) {
        long double d1 = c * (3 - 8 * s + 3 * s * s), d2 = -s * (3 - 8 * c + 3 * c * c);
        *dx = 2 * s * c + k * (d1 - d2);
    }
    return s * s + k * (A1 - A2);
}

/* Steps of ts__geo_root (the same start and steps) until one is below
 * 2^-20 φ; 99 if none within 99. */
static int root_steps(double u, double k, double *root)
{
    double s, c, ms, mc, phi = ts__geo_halley(ts__geo_start(u, k), k, u, &s, &c, &ms, &mc);
    for (int it = 2; it < 99; it++) {
        double next = ts__geo_halley(phi, k, u, &s, &c, &ms, &mc);
        if (fabs(next - phi) <= 0x1p-20 * next) {
            *root = next;
            return it;
        }
        phi = next;
    }
    *root = phi;
    return 99;
}

static void solve_scan(void)
{
    /* κ in [0, κmax], finer towards κmax (a_i -> TS_GEOMETRIC_A_MIN, where
     * X̂'(π/4) = 1 − (8 − 9/√2)κ falls to 6.3e-5); u on a log grid down to
     * 2^-1022, a linear one, and 1/2 − 10^-t.  A denser run of the same
     * (1e8 points, 4000 κ in [0.45, κmax] by 20000 u near 1/2, and 2e7 over
     * the whole range) found at most 9 steps; the cap is 16, so a margin of
     * 7 steps; here at most 12 passes. */
    double kmax = kappa_max();
    int worst = 0, bad_res = 0, bad_mp = 0;
    for (int ik = 0; ik <= 260; ik++) {
        double k = ik <= 200 ? kmax * ik / 200.0 : kmax * (1.0 - ldexp(1.0, -(ik - 200) / 3));
        if (ik == 0)
            k = ts__kappa(DBL_MAX); /* the smallest: a_i = DBL_MAX */
        for (int iu = 0; iu < 900; iu++) {
            double u = iu < 300   ? ldexp(1.0, -1022) * pow(2.0, 1021.0 * iu / 299.0)
                       : iu < 600 ? 0.5 * (iu - 299) / 300.0
                                  : 0.5 - pow(10.0, -1.0 - 16.0 * (iu - 600) / 299.0);
            double phi;
            int n = root_steps(u, k, &phi);
            worst = n > worst ? n : worst;
            /* residual: X̂ is formed from terms of size at most
             * s² + κ(A1 + A2) <= 2, each to a few ε (8ε), plus the
             * rounding of φ itself (ε φ X̂') */
            long double dx, r = xhat_l((long double)k, (long double)phi, &dx) - (long double)u;
            if (!(fabsl(r) <= (long double)(8 * EPS * (u + 2 * k * phi)) + (long double)(EPS * phi) * fabsl(dx)) &&
                bad_res++ < 5)
                CHECKF(0, "residual %Lg at k %.17g u %.17g", r, k, u);
            /* the start divides by M' at the quadratic root (internal.h):
             * positive, at least 0.18·3κ (measured 0.182 on 1.6e8 points) */
            double b = 1.0 - 5.0 * k, bc = TS_GEO_B0 - TS_GEO_B1 * k;
            double bq = bc > b ? bc : b, d = 9.0 * k * k + 4.0 * bq * u;
            double p = (u + u) / (3.0 * k + sqrt(d > 0.0 ? d : 0.0));
            double c3 = TS_GEO_C30 + TS_GEO_C31 * k, c4 = TS_GEO_C40 + TS_GEO_C41 * k;
            p = p < TS_GEO_Q ? p : TS_GEO_Q;
            double Mp = 3.0 * k + p * (2.0 * b + p * (3.0 * c3 + 4.0 * c4 * p));
            if (!(Mp >= 0.18 * 3.0 * k && Mp > 0.0) && bad_mp++ < 5)
                CHECKF(0, "M' = %g at k %.17g u %.17g", Mp, k, u);
        }
    }
    CHECKF(worst <= TS_GEO_PASSES - 4, "%d Halley steps (cap %d)", worst, TS_GEO_PASSES);
    CHECK(bad_res == 0 && bad_mp == 0);
}

/* S at x of interval [0, 1], f = (f0, f1), d = (d0, d1), κ: X̂(φ) = x by
 * bisection in long double, then Y(φ) (docs/method.md §4, left end). */
static long double ref_value(long double k, double x, double f0, double f1, double d0, double d1)
{
    long double lo = 0, hi = 0.78539816339744830961566L;
    for (int it = 0; it < 200; it++) {
        long double mid = 0.5L * (lo + hi);
        if (xhat_l(k, mid, NULL) < (long double)x)
            lo = mid;
        else
            hi = mid;
    }
    long double phi = 0.5L * (lo + hi), s = sinl(phi), c = cosl(phi), h = sinl(phi / 2);
    long double A1 = s * (1 - s) * (3 - s), A2 = c * (2 * h * h) * (3 - c);
    return (long double)f0 * c * c + (long double)f1 * s * s + k * ((long double)d0 * A1 - (long double)d1 * A2);
}

static void solve_worst(void)
{
    /* the slowest point of the scan (9 steps), evaluated as the library
     * does, single and in every kernel */
    const double u = 0.49999999995301059;
    double phi;
    CHECK(root_steps(u, kappa_max(), &phi) == 9);
    const double x[2] = {0.0, 1.0}, f[2] = {0.0, 1.0}, d[2] = {2.0, -1.0};
    ts_spline_options o;
    th_options_paper(&o);
    o.form = TS_FORM_GEOMETRIC;
    o.alpha = TS_GEOMETRIC_A_MIN;
    o.slopes = TS_SLOPES_USER;
    o.user_slopes = d;
    o.n_user_slopes = 2;
    ts_spline *s = NULL;
    CHECK(ts_spline_new(x, f, 2, &o, &s, NULL) == TS_OK);
    if (!s)
        return;
    long double want = ref_value((long double)kappa_max(), u, f[0], f[1], d[0], d[1]);
    double y, dy;
    CHECK(ts_spline_eval_deriv(s, u, NULL, &y, &dy, NULL) == TS_OK);
    /* the solve's φ is good to ε/X̂' (F's rounding over X̂' ≈ 1e-4 here), so
     * S to ε(|S| + h|S'|) times a few (8), the derivative's own rounding
     * there included in |S'| */
    double tol = 8 * EPS * (fabs(y) + fabs(dy) + 1.0);
    CHECKF(fabsl((long double)y - want) <= (long double)tol, "S = %.17g, want %.17Lg (tol %g)", y, want, tol);
    for (int isa = 0; isa <= 2; isa++) {
        double yk;
        if (ts__fast_batch_isa(s, 0, &u, 1, &yk, NULL, isa, NULL))
            CHECKF(fabsl((long double)yk - want) <= (long double)tol, "kernel %d: %.17g, want %.17Lg", isa, yk,
                   want);
    }
    ts_spline_free(s);
}

static void kernel_copies(void)
{
    /* Every kernel (ISA) and deriv 0, 1, 2 of the geometric form, whose
     * solve and value are inlined into each: intervals with equal end
     * values and slopes (0, 0), (0, d), (d, 0) (the flat test's every
     * outcome), queries on both halves, at solve_worst's u (more than two
     * Halley passes) and at a subnormal distance from a knot (every pass).
     * Expected: on the (0, 0) interval S = f, S' = S'' = 0 exactly
     * (docs/method.md §4: Y = F0, Y' = Y'' = 0); elsewhere S to
     * solve_worst's long-double reference and tolerance where it applies
     * (the left half), and S, S', S'' to
     * ts_spline_eval_deriv within 1e-9 of |S| + |S'| + |S''| + 1 (the kernels agree
     * with it to tests/unit/test_fast.c's bounds, far below this; a swapped
     * side or slope gives errors of order 1). */
    const double x[5] = {-1.0, 0.0, 1.0, 2.0, 3.0}, f[5] = {1.0, 1.0, 1.0, 1.0, 1.0};
    const double d[5] = {0.0, 0.0, 0.3, 0.0, -0.2};
    ts_spline_options o;
    th_options_paper(&o);
    o.form = TS_FORM_GEOMETRIC;
    o.alpha = TS_GEOMETRIC_A_MIN;
    o.slopes = TS_SLOPES_USER;
    o.user_slopes = d;
    o.n_user_slopes = 5;
    ts_spline *s = NULL;
    CHECK(ts_spline_new(x, f, 5, &o, &s, NULL) == TS_OK);
    if (!s)
        return;
    const double w = 0.49999999995301059, sub = 4.9406564584124654e-324;
    double q[] = {-1.0 + 0.25, -sub, sub, 0.5, 1.0 - w, 1.0 + w, 2.0 - w, 2.5, 2.0 + w, 3.0 - w};
    size_t nq = sizeof q / sizeof q[0];
    for (size_t p = 0; p < nq; p++) {
        double y1[3];
        CHECK(ts_spline_eval_deriv(s, q[p], NULL, &y1[0], &y1[1], &y1[2]) == TS_OK);
        size_t i = q[p] < 0.0 ? 0 : (size_t)q[p] + 1; /* the interval [x[i], x[i+1]] */
        double h = x[i + 1] - x[i];
        long double u = ((long double)q[p] - (long double)x[i]) / (long double)h;
        double v[3]; /* the form table's evaluation (certificates, integrals) */
        ts__interval_eval(s, i, q[p], 2, v);
        for (int deriv = 0; deriv <= 2; deriv++)
            CHECKF(i == 0 ? v[deriv] == (deriv ? 0.0 : 1.0)
                          : fabs(v[deriv] - y1[deriv]) <=
                                1e-9 * (fabs(y1[0]) + fabs(y1[1]) + fabs(y1[2]) + 1.0),
                   "interval_eval deriv %d at %g: %.17g, single %.17g", deriv, q[p], v[deriv],
                   y1[deriv]);
        for (int isa = 0; isa <= 2; isa++) {
            for (int deriv = 0; deriv <= 2; deriv++) {
                double yk;
                if (!ts__fast_batch_isa(s, deriv, &q[p], 1, &yk, NULL, isa, NULL))
                    continue; /* kernel not on this CPU */
                if (i == 0) {
                    CHECKF(yk == (deriv ? 0.0 : 1.0), "kernel %d, deriv %d at %g: %.17g", isa,
                           deriv, q[p], yk);
                } else if (deriv == 0 && u <= 0.5L) { /* ref_value: from the left end */
                    long double want = ref_value((long double)ts__kappa(o.alpha), (double)u, f[i],
                                                 f[i + 1], d[i] * h, d[i + 1] * h);
                    double tol = 8 * EPS * (fabs(yk) + fabs(y1[1]) + 1.0);
                    CHECKF(fabsl((long double)yk - want) <= (long double)tol,
                           "kernel %d at %g: %.17g, want %.17Lg", isa, q[p], yk, want);
                } else {
                    CHECKF(fabs(yk - y1[deriv]) <= 1e-9 * (fabs(y1[0]) + fabs(y1[1]) + fabs(y1[2]) + 1.0),
                           "kernel %d, deriv %d at %g: %.17g, single %.17g", isa, deriv, q[p], yk,
                           y1[deriv]);
                }
            }
        }
    }
    ts_spline_free(s);
}

static void huge_a(void)
{
    /* a_i = 1 + 1e300: κ ≈ 2e-301, at a knot u = 0, φ = 0, F = 0 and
     * Halley's 2X̂'² = 18κ² underflows to 0: the guard keeps the step
     * 0/DBL_MIN = 0 (without it 0/0: a NaN, which the clamp of the next φ
     * turns into 0, but FE_INVALID raised; FE_DIVBYZERO is not checked:
     * clang evaluates the X̂'³ = 27κ³ of S'' (it underflows) also for S').
     * Expected: S(x_i) = f_i,
     * S'(x_i) = d_i (exact slopes of the form, docs/method.md §4; d_i to the
     * rounding of Y'(0)/X̂'(0) = 3k d_i/(3κ h), a few ulps: 4ε). */
    const double x[3] = {0.0, 1.0, 3.0}, f[3] = {1.0, 2.0, -1.0};
    ts_spline_options o;
    th_options_paper(&o);
    o.form = TS_FORM_GEOMETRIC;
    o.beta = 1e300;
    ts_spline *s = NULL;
    CHECK(ts_spline_new(x, f, 3, &o, &s, NULL) == TS_OK);
    if (!s)
        return;
    const double *D = ts_spline_slopes(s);
    for (int p = 0; p < 3; p++) {
        double y, dy;
        feclearexcept(FE_ALL_EXCEPT);
        CHECK(ts_spline_eval_deriv(s, x[p], NULL, &y, &dy, NULL) == TS_OK);
        CHECKF(!fetestexcept(FE_INVALID), "FE_INVALID at %g", x[p]);
        CHECKF(y == f[p], "S(%g) = %.17g", x[p], y);
        CHECKF(fabs(dy - D[p]) <= 4 * EPS * fabs(D[p]), "S'(%g) = %.17g, d = %.17g", x[p], dy, D[p]);
        for (int isa = 0; isa <= 2; isa++) {
            double yk[2];
            feclearexcept(FE_ALL_EXCEPT);
            for (int deriv = 0; deriv <= 1; deriv++)
                if (!ts__fast_batch_isa(s, deriv, &x[p], 1, &yk[deriv], NULL, isa, NULL))
                    yk[0] = yk[1] = TH_NAN, deriv = 2;
            CHECKF(!fetestexcept(FE_INVALID), "kernel %d: FE_INVALID at %g", isa, x[p]);
            if (isnan(yk[0]) && isnan(yk[1]))
                continue; /* kernel not on this CPU: both NaN only then */
            CHECKF(yk[0] == f[p], "kernel %d: S(%g) = %.17g", isa, x[p], yk[0]);
            CHECKF(fabs(yk[1] - D[p]) <= 4 * EPS * fabs(D[p]), "kernel %d: S'(%g) = %.17g", isa,
                   x[p], yk[1]);
        }
    }
    ts_spline_free(s);
}

static void subnormal_u(void)
{
    /* X̂(φ) = 3κφ + (1 − 5κ)φ² + O(φ³) (docs/method.md §4): for u <= 2^-1022
     * the root is u/(3κ) to a relative |1 − 5κ| u/(9κ²) < 1e-290 (κ >=
     * 2/(3π)·1e-3 here); the steps are rounding noise of F (2^-1074
     * granular) over X̂' = 3κ, so the iterate is within 16·2^-1074/κ. */
    const double ks[4] = {ts__kappa(1.0), 0.5, 0.2, 0.0};
    const double us[4] = {4.9406564584124654e-324, 7.1e-322, 2.0e-315, 1.0e-310};
    for (int a = 0; a < 4; a++) {
        double k = a < 3 ? ks[a] : kappa_max();
        for (int b = 0; b < 4; b++) {
            double sc[4], phi = ts__geo_root(us[b], k, sc);
            CHECKF(fabs(phi - us[b] / (3.0 * k)) <= 16 * ldexp(1.0, -1074) / k,
                   "phi %.17g, u/(3k) %.17g", phi, us[b] / (3.0 * k));
            CHECK(sc[1] == 1.0 && sc[3] == 0.0 && sc[2] == 1.0 - sc[0]);
            CHECK(ts__geo_solve(k, us[b]) == phi);
        }
        double sc[4];
        CHECK(ts__geo_root(0.0, k, sc) == 0.0 && ts__geo_solve(k, 0.0) == 0.0);
    }
}

static void pick(void)
{
    /* header of ts__fast_pick: −1 the best available, 0 portable, 1 AVX2+FMA,
     * 2 AVX-512F; −1 where that kernel cannot run or isa is none */
    for (int isa = -3; isa <= 4; isa++)
        for (int h2 = 0; h2 <= 1; h2++)
            for (int h5 = 0; h5 <= 1; h5++) {
                int want;
                if (isa == -1)
                    want = h5 ? 2 : h2 ? 1 : 0;
                else if (isa == 0)
                    want = 0;
                else if (isa == 1)
                    want = h2 ? 1 : -1;
                else if (isa == 2)
                    want = h5 ? 2 : -1;
                else
                    want = -1;
                int got = ts__fast_pick(isa, h2, h5);
                CHECKF(got == want, "pick(%d, %d, %d) = %d, want %d", isa, h2, h5, got, want);
            }
    /* a kernel that is none: refused, nothing done */
    const double x[2] = {0.0, 1.0}, f[2] = {0.0, 1.0};
    ts_spline *s = NULL;
    ts_spline_options po;
    th_options_paper(&po); /* the paper form has a fast kernel */
    CHECK(ts_spline_new(x, f, 2, &po, &s, NULL) == TS_OK);
    double q = 0.5, y = -7.0;
    size_t done = 9;
    CHECK(ts__fast_batch_isa(s, 0, &q, 1, &y, NULL, 3, &done) == 0 && y == -7.0 && done == 9);
    CHECK(ts__fast_batch_isa(s, 0, &q, 1, &y, NULL, 0, NULL) == 1 && y == 0.5);
    ts_spline_free(s);
}

static void mt_threads(void)
{
    /* ts_spline_eval_batch_mt (header): the threads asked, or with 0 the online
     * processors, 1 when that count is not positive; at most 64 */
    CHECK(ts__mt_threads(0, 4) == 4);
    CHECK(ts__mt_threads(0, 1) == 1);
    CHECK(ts__mt_threads(0, 0) == 1);
    CHECK(ts__mt_threads(0, -1) == 1);
    CHECK(ts__mt_threads(0, 64) == 64);
    CHECK(ts__mt_threads(0, 1000) == 64);
    CHECK(ts__mt_threads(3, -1) == 3);
    CHECK(ts__mt_threads(63, 0) == 63);
    CHECK(ts__mt_threads(65, 0) == 64);
    CHECK(ts__mt_threads(4000000000u, 2) == 64);
}

static void entry_points(void)
{
    const double x[3] = {0.0, 1.0, 2.0}, f[3] = {1.0, 3.0, 2.0};
    for (int form = 0; form < 2; form++) {
        ts_spline_options o;
        th_options_paper(&o);
        o.form = form ? TS_FORM_GEOMETRIC : TS_FORM_PAPER;
        ts_spline *s = NULL;
        CHECK(ts_spline_new(x, f, 3, &o, &s, NULL) == TS_OK);
        if (!s)
            return;
        double y = 0.0, dy = 0.0, d2y = 0.0;
        /* knots are interpolated exactly (docs/method.md §2, §4) */
        CHECK(ts_spline_eval(s, 1.0, NULL, NULL) == TS_OK);
        CHECK(ts_spline_eval(NULL, 1.0, NULL, &y) == TS_ERR_NULL && isnan(y));
        CHECK(ts_spline_eval(s, TH_NAN, NULL, &y) == TS_ERR_DOMAIN && isnan(y));
        CHECK(ts_spline_eval_deriv(NULL, 1.0, NULL, &y, &dy, &d2y) == TS_ERR_NULL && isnan(y) &&
              isnan(dy) && isnan(d2y));
        CHECK(ts_spline_eval_deriv(s, TH_NAN, NULL, &y, &dy, NULL) == TS_ERR_DOMAIN && isnan(y) && isnan(dy));
        CHECK(ts_spline_eval_deriv(s, 1.0, NULL, NULL, &dy, NULL) == TS_OK);
        CHECK(ts_spline_eval_deriv(s, 2.0, NULL, &y, NULL, NULL) == TS_OK && y == 2.0);
        /* a cursor on another interval: the search, the same value */
        ts_cursor c = TS_CURSOR_INIT;
        double y1;
        CHECK(ts_spline_eval(s, 1.75, &c, &y) == TS_OK && ts_spline_eval(s, 0.25, &c, &y1) == TS_OK);
        CHECK(ts_spline_eval(s, 0.25, NULL, &y) == TS_OK && y == y1);
        ts_spline_free(s);
    }
}

/* ts_spline_eval's inline cursor step (ts__cursor_step): from every cursor
 * (valid, past the end) and at every kind of query (inside, at and beside
 * each knot, outside, ±Inf, NaN), the status and value of the path without
 * a cursor (ts_spline_eval_deriv: the binary search), and the cursor
 * ts_spline_find_interval leaves (ts__search: the cursor, its successor,
 * else the search), which the header documents as the cursor's meaning.
 * The value is the same bits: the same interval's same operations
 * (docs/method.md §2, §4); so are ts_spline_eval_deriv's S, S', S'' with
 * and without the cursor. */
static void cursor_step(void)
{
    const double x[5] = {0.0, 1.0, 2.5, 3.0, 4.5}, f[5] = {1.0, 3.0, 2.0, 2.5, 0.5};
    double q[64];
    int nq = 0;
    for (int k = 0; k < 5; k++) {
        q[nq++] = x[k];
        q[nq++] = nextafter(x[k], -(double)INFINITY);
        q[nq++] = nextafter(x[k], (double)INFINITY);
        if (k < 4) {
            q[nq++] = 0.5 * (x[k] + x[k + 1]);
            q[nq++] = x[k] + 0.1 * (x[k + 1] - x[k]);
        }
    }
    q[nq++] = -1.0;
    q[nq++] = 7.0;
    q[nq++] = (double)INFINITY;
    q[nq++] = -(double)INFINITY;
    q[nq++] = TH_NAN;
    for (int form = 0; form < 3; form++) {
        for (int ex = 0; ex < 2; ex++) {
            ts_spline_options o;
            th_options_paper(&o);
            o.form = form == 0 ? TS_FORM_PAPER : form == 1 ? TS_FORM_C1 : TS_FORM_GEOMETRIC;
            o.extrapolate = ex ? TS_EXTRAP_EXTEND : TS_EXTRAP_ERROR;
            ts_spline *s = NULL;
            CHECK(ts_spline_new(x, f, 5, &o, &s, NULL) == TS_OK);
            if (!s)
                return;
            for (size_t c0 = 0; c0 <= 6; c0++) {
                for (int j = 0; j < nq; j++) {
                    ts_cursor c = {c0}, cf = {c0};
                    double y = 0.0, yr = 0.0;
                    size_t i;
                    ts_status st = ts_spline_eval(s, q[j], &c, &y);
                    ts_status sr = ts_spline_eval_deriv(s, q[j], NULL, &yr, NULL, NULL);
                    (void)ts_spline_find_interval(s, q[j], &cf, &i);
                    CHECKF(st == sr && (memcmp(&y, &yr, sizeof y) == 0 || (isnan(y) && isnan(yr))) &&
                               c.interval == cf.interval,
                           "form %d extrap %d cursor %zu x %.17g: %d %.17g (cursor %zu), expected %d "
                           "%.17g (cursor %zu)",
                           form, ex, c0, q[j], (int)st, y, c.interval, (int)sr, yr, cf.interval);
                    /* S, S', S'' from the cursor's interval (the paper and C¹
                     * forms read the stored dθ/dx) and after the search (they
                     * form it): the same bits */
                    ts_cursor cd = {c0};
                    double a[3], b[3];
                    ts_status sa = ts_spline_eval_deriv(s, q[j], &cd, &a[0], &a[1], &a[2]);
                    ts_status sb = ts_spline_eval_deriv(s, q[j], NULL, &b[0], &b[1], &b[2]);
                    int eq = sa == sb;
                    for (int k = 0; k < 3; k++)
                        eq &= memcmp(&a[k], &b[k], sizeof a[k]) == 0 || (isnan(a[k]) && isnan(b[k]));
                    CHECKF(eq, "form %d extrap %d cursor %zu x %.17g: S, S', S'' %.17g %.17g %.17g, without the "
                           "cursor %.17g %.17g %.17g", form, ex, c0, q[j], a[0], a[1], a[2], b[0], b[1], b[2]);
                }
            }
            ts_spline_free(s);
        }
    }
}

static void interval_eval(void)
{
    /* ts__interval_eval inside an interval with every want (the library
     * itself calls it inside only for the linear extension's slope, want 1).
     * Expected: a flat interval (f_1 = f_2, d = 0 there) is the constant
     * f_1 with zero derivatives exactly (docs/method.md §2: all control
     * values equal); at a knot S = f_i exactly and, in the geometric form,
     * S' = d_i (exact slopes, docs/method.md §4; 4ε as in huge_a). */
    const double x[4] = {0.0, 1.0, 2.0, 3.5}, f[4] = {0.0, 2.0, 2.0, 5.0}, d[4] = {1.0, 0.0, 0.0, 2.0};
    for (int form = 0; form < 2; form++) {
        ts_spline_options o;
        th_options_paper(&o);
        o.form = form ? TS_FORM_GEOMETRIC : TS_FORM_PAPER;
        o.slopes = TS_SLOPES_USER;
        o.user_slopes = d;
        o.n_user_slopes = 4;
        ts_spline *s = NULL;
        CHECK(ts_spline_new(x, f, 4, &o, &s, NULL) == TS_OK);
        if (!s)
            return;
        for (int want = 0; want <= 2; want++) {
            double v[3] = {-1.0, -1.0, -1.0};
            ts__interval_eval(s, 1, 1.3, want, v);
            CHECKF(v[0] == 2.0 && (want < 1 || v[1] == 0.0) && (want < 2 || v[2] == 0.0),
                   "form %d want %d: %.17g %.17g %.17g", form, want, v[0], v[1], v[2]);
            ts__interval_eval(s, 2, 3.5, want, v);
            CHECKF(v[0] == 5.0, "form %d want %d: S(3.5) = %.17g", form, want, v[0]);
            if (form && want > 0)
                CHECKF(fabs(v[1] - 2.0) <= 4 * 2.0 * EPS, "S'(3.5) = %.17g", v[1]);
        }
        ts_spline_free(s);
    }
}

int main(void)
{
    TH_CASE("solve_scan");
    solve_scan();
    TH_CASE("solve_worst");
    solve_worst();
    TH_CASE("kernel_copies");
    kernel_copies();
    TH_CASE("huge_a");
    huge_a();
    TH_CASE("subnormal_u");
    subnormal_u();
    TH_CASE("pick");
    pick();
    TH_CASE("mt_threads");
    mt_threads();
    TH_CASE("entry_points");
    entry_points();
    TH_CASE("cursor_step");
    cursor_step();
    TH_CASE("interval_eval");
    interval_eval();
    return th_report("test_cover_eval");
}
