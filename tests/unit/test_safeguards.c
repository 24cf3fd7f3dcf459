/* The termination safeguards of the library's searches, provoked through
 * the test hook ts__test_limits (src/internal.h; trigspline_internal only,
 * the product reads the constants): each limit is lowered until the search
 * ends there, and the result must still be a correct answer: a certified
 * spline passes the independent exact certificate (ts_spline_certify, run
 * with the default limits) or the refusal is a documented status; a
 * length, integral, root or minimum is the value the early stop defines,
 * compared with a closed form or with the run under the default limits.
 *
 * Each case fails if the safeguard's path returned a wrong value or status
 * (a spline reported certified that ts_spline_certify rejects, a NaN, a
 * root that is not one, a minimum below the true one), and the cases that
 * can tell check that the early stop happened (a root count, a value that
 * differs from the default run's).  `make coverage` shows each safeguard
 * branch taken (docs/design.md "Coverage"). */
#include "th.h"
#include "th_options.h"
#include "common/th_rng.h"
#include "trigspline.h"
#include "internal.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <stdint.h>
#include <string.h>

static const ts__limits defaults = TS_LIMITS_DEFAULT;
static th_rng rng = TH_RNG_INIT(0x9E3779B97F4A7C15u);

static void reset(void) { ts__test_limits = defaults; }

/* ---- curve length: depth and piece limits -------------------------------- */

static void curve_length(void)
{
    TH_CASE("curve length limits");
    /* 8 points on the unit circle, closed: a smooth curve whose segments
     * need more than one level at tol 1e-14 (the whole and the halves
     * differ by more than 1e-14 of the segment) */
    double P[16];
    for (int k = 0; k < 8; k++) {
        P[2 * k] = cos(k * TH_PI / 4.0);
        P[2 * k + 1] = sin(k * TH_PI / 4.0);
    }
    ts_curve_options o;
    ts_curve_options_init(&o);
    o.closed = 1;
    ts_curve *c = NULL;
    ts_error e;
    CHECK(ts_curve_new(P, 8, 2, &o, &c, &e) == TS_OK && c);
    if (!c)
        return;
    double L0 = TH_NAN, L1 = TH_NAN, L2 = TH_NAN;
    reset();
    CHECK(ts_curve_length(c, 1e-14, &L0) == TS_OK);
    ts__test_limits.curve_len_depth = 0; /* one level: the two halves */
    CHECK(ts_curve_length(c, 1e-14, &L1) == TS_OK);
    reset();
    ts__test_limits.curve_len_pieces = 1; /* the same through the piece count */
    CHECK(ts_curve_length(c, 1e-14, &L2) == TS_OK);
    reset();
    /* the halves' 10-point Gauss–Legendre sums of an analytic speed: within
     * 1e-9 relative of the converged length (the two differ by more than
     * the 1e-14 asked, else the limit would not be reached) */
    CHECK_CLOSE(L1, L0, 1e-9 * L0);
    CHECK(L1 == L2);
    /* the curve runs near the circle: its length near 2π (a spline through
     * 8 points of it, within 1 %) */
    CHECK_CLOSE(L0, 2.0 * TH_PI, 0.01 * 2.0 * TH_PI);
    ts_curve_free(c);
}

/* ---- spline repair: bisection width, neighbour steps, repair budget ------ */

/* A random problem above a sloped line: data 1e-6..1 above it, steep slopes
 * between, so that many intervals need a repair (docs/method.md §5). */
static void random_above(double *x, double *f, size_t np, ts_line *ln, double gap_min)
{
    ln->m = th_rng_range(&rng, -2.0, 2.0);
    ln->c = th_rng_range(&rng, -1.0, 1.0);
    double t = 0.0;
    for (size_t k = 0; k < np; k++) {
        t += th_rng_logu(&rng, 0.01, 1.0);
        x[k] = t;
        double gap = th_rng_chance(&rng, 0.5) ? th_rng_logu(&rng, gap_min, 1e-2) : th_rng_range(&rng, 0.1, 3.0);
        f[k] = ln->m * x[k] + ln->c + gap;
    }
}

/* A spline built under the current limits; if TS_OK it must pass the exact
 * certificate under the default limits, else refuse with a documented
 * status of the shape schemes.  Returns the status. */
static const double *alphas_of_next; /* per-interval alphas for the next build */

static ts_status build_check(const double *x, const double *f, size_t np, ts_form form,
                             const ts_line *ln, double margin, int *certified)
{
    ts_spline_options o;
    th_options_paper(&o);
    o.alphas = alphas_of_next;
    o.n_alphas = alphas_of_next ? np - 1 : 0;
    alphas_of_next = NULL;
    o.form = form;
    o.shape = TS_SHAPE_ABOVE;
    o.lower = *ln;
    o.margin = margin;
    ts_spline *s = NULL;
    ts_error e;
    ts_status st = ts_spline_new(x, f, np, &o, &s, &e);
    ts__limits lowered = ts__test_limits;
    reset();
    if (st == TS_OK) {
        ts_error ce;
        ts_status cs = ts_spline_certify(s, ln, NULL, NULL, &ce);
        CHECKF(cs == TS_OK, "form %d: certified spline fails the certificate at %zu: %s", (int)form,
               ce.index, ts_strerror(cs));
        *certified += cs == TS_OK;
    } else {
        CHECKF(st == TS_ERR_INFEASIBLE || st == TS_ERR_PRECISION || st == TS_ERR_UNPROVEN,
               "form %d: refusal %s", (int)form, ts_strerror(st));
    }
    ts_spline_free(s);
    ts__test_limits = lowered;
    return st;
}

static void spline_repair(void)
{
    TH_CASE("spline repair limits");
    enum { NP = 12, PROBLEMS = 240 };
    double x[NP], f[NP];
    ts_line ln;
    int certified[5] = {0}, refused[5] = {0};
    for (int p = 0; p < PROBLEMS; p++) {
        random_above(x, f, NP, &ln, p % 2 ? 1e-6 : 1e-3);
        for (int form = 0; form < 2; form++) {
            ts_form fm = form ? TS_FORM_C1 : TS_FORM_PAPER;
            /* bisection to adjacent doubles: it stops where the middle
             * rounds to an end */
            reset();
            ts__test_limits.repair_width = 0.0;
            refused[0] += build_check(x, f, NP, fm, &ln, 1e-3, &certified[0]) != TS_OK;
            /* the C¹ neighbours' bisection with no steps: a_j stays */
            reset();
            ts__test_limits.repair_relax_steps = 0;
            refused[1] += build_check(x, f, NP, fm, &ln, 1e-3, &certified[1]) != TS_OK;
            if (fm != TS_FORM_C1 || p % 4)
                continue; /* the paper form moves on after every repair; C¹: 60 problems */
            /* no repair allowed: the first one goes to the uniform family */
            reset();
            ts__test_limits.repair_budget_per = 0;
            ts__test_limits.repair_budget_base = 0;
            refused[2] += build_check(x, f, NP, fm, &ln, 1e-9, &certified[2]) != TS_OK;
            refused[3] += build_check(x, f, NP, fm, &ln, 1e-3, &certified[3]) != TS_OK;
            /* alphas 1 and one of 64: the uniform family's first A, 64,
             * may certify at once; a margin below ulp(64) leaves a_j = 64
             * there, beta_j = 0 */
            double al[NP - 1];
            for (size_t k = 0; k + 1 < NP; k++)
                al[k] = k == (size_t)p % (NP - 1) ? 64.0 : 1.0;
            alphas_of_next = al;
            refused[4] += build_check(x, f, NP, fm, &ln, 1e-300, &certified[4]) != TS_OK;
        }
    }
    /* the same with data farther from the line (gaps 0.01 or 0.1 .. 3), which
     * the uniform family certifies at its first A = 64: a_j = 64 for every
     * j, beta_j = 0 where alpha_j = 64 (the margin is below ulp(64)) */
    for (int p = 0; p < 120; p++) {
        random_above(x, f, NP, &ln, 1e-2);
        double al[NP - 1];
        for (size_t k = 0; k + 1 < NP; k++)
            al[k] = k == (size_t)p % (NP - 1) ? 64.0 : 1.0;
        reset();
        ts__test_limits.repair_budget_per = 0;
        ts__test_limits.repair_budget_base = 0;
        alphas_of_next = al;
        refused[4] += build_check(x, f, NP, TS_FORM_C1, &ln, 1e-300, &certified[4]) != TS_OK;
    }
    /* more intervals than one block of the exact paper form's batch
     * certificate (TS_CERT_BLOCK = 256, repair.c) left by the control-value
     * proof: the default limits, the same checks */
    enum { NB = 700 };
    static double xb[NB], fb[NB];
    for (int p = 0; p < 4; p++) {
        /* unit steps, values 1 .. 2 and 1e-30 .. 2e-30 in turn above y = 0:
         * the low points' control values are within the bound's rounding
         * guard of the line, so the control-value proof leaves them to the
         * exact batch from the first interval on */
        ts_line lb = {0.0, 0.0};
        for (size_t k = 0; k < NB; k++) {
            xb[k] = (double)k;
            fb[k] = k % 2 ? th_rng_logu(&rng, 1.0, 2.0) : 1e-30 * th_rng_logu(&rng, 1.0, 2.0);
        }
        ts_spline_options o;
        ts_spline_options_init(&o);
        o.form = TS_FORM_PAPER;
        o.shape = TS_SHAPE_ABOVE; /* a line: the exact certificate */
        o.lower = lb;
        ts_spline *s = NULL;
        ts_error e;
        reset();
        ts_status st = ts_spline_new(xb, fb, NB, &o, &s, &e);
        CHECKF(st == TS_OK, "%s", ts_strerror(st));
        if (st == TS_OK) {
            size_t first = ts__skip_proven(s, 0, NB - 1);
            CHECKF(NB - 1 - first > 256, "first interval left to the batch: %zu", first);
            st = ts_spline_certify(s, &lb, NULL, NULL, &e);
            CHECKF(st == TS_OK, "above: %s at %zu", ts_strerror(st), e.index);
        }
        ts_spline_free(s);
    }
    reset();
    /* some certified under every lowered limit (the checks above apply) */
    for (int k = 0; k < 5; k++)
        CHECKF(certified[k] > 0, "limit %d: none certified (%d refused)", k, refused[k]);
}

/* ---- the exact minimum of a trigonometric piece: steps and depth --------- */

/* g(θ) = Σ A_l(θ) C_l − κ θ, from the library's basis */
static double g_at(const double C[4], double kappa, double th)
{
    double A[4];
    ts__basis(sin(th), cos(th), A);
    return A[0] * C[0] + A[1] * C[1] + A[2] * C[2] + A[3] * C[3] - kappa * th;
}

static void trig_min_limits(void)
{
    TH_CASE("trig_min limits");
    int differ_steps = 0, differ_depth = 0;
    for (int rep = 0; rep < 400; rep++) {
        double C[4], kappa = th_rng_range(&rng, -1.0, 1.0);
        for (int l = 0; l < 4; l++)
            C[l] = th_rng_range(&rng, -1.0, 1.0);
        double th0, th1, th2;
        reset();
        double m0 = ts__trig_min(C, kappa, &th0);
        ts__test_limits.trigmin_steps = 0;
        double m1 = ts__trig_min(C, kappa, &th1);
        reset();
        ts__test_limits.trigmin_depth = 0;
        double m2 = ts__trig_min(C, kappa, &th2);
        reset();
        /* each is g at its θ (a candidate's value), never below the
         * converged minimum (its rounding guard: 64 ε of the scale 8,
         * ts__trig_min_guard at depth <= 46 is below that) */
        double tol = 64.0 * DBL_EPSILON * 8.0;
        CHECKF(m1 >= m0 - tol && m2 >= m0 - tol, "C %g %g %g %g k %g: %.17g %.17g below %.17g",
               C[0], C[1], C[2], C[3], kappa, m1, m2, m0);
        CHECK_CLOSE(m1, g_at(C, kappa, th1), tol);
        CHECK_CLOSE(m2, g_at(C, kappa, th2), tol);
        CHECK(0.0 <= th1 && th1 <= TH_HALF_PI && 0.0 <= th2 && th2 <= TH_HALF_PI);
        differ_steps += m1 != m0;
        differ_depth += m2 != m0;
    }
    /* the early stops changed some minima (the limits were reached) */
    CHECK(differ_steps > 0);
    CHECK(differ_depth > 0);
}

/* ---- a surface patch's certificate: depth and node limits ---------------- */

static void surface_cert_limits(void)
{
    TH_CASE("surface certificate limits");
    enum { N = 5 };
    double x[N], y[N], z[N * N];
    for (int k = 0; k < N; k++)
        x[k] = y[k] = k;
    for (int k = 0; k < N * N; k++)
        z[k] = 2.0 + sin(1.7 * k) + 0.5 * cos(0.3 * k * k);
    ts_surface_options o;
    ts_surface_options_init(&o);
    o.form = TS_FORM_PAPER;
    ts_surface *s = NULL;
    ts_error e;
    CHECK(ts_surface_new(x, N, y, N, z, &o, &s, &e) == TS_OK && s);
    if (!s)
        return;
    /* a sloped plane below the data: the linear rest makes the search
     * subdivide */
    ts_plane pl = {0.1, -0.05, 0.2};
    int lowered = 0;
    for (size_t i = 0; i + 1 < N; i++)
        for (size_t j = 0; j + 1 < N; j++) {
            double pv0, sv0, ax0, ay0, pv1, sv1, ax1, ay1, pv2, sv2, ax2, ay2;
            reset();
            int ok0 = ts__surf_certify_patch(s, i, j, &pl, 1, &pv0, &sv0, &ax0, &ay0);
            ts__test_limits.surface_cert_depth = 1;
            int ok1 = ts__surf_certify_patch(s, i, j, &pl, 1, &pv1, &sv1, &ax1, &ay1);
            reset();
            ts__test_limits.surface_cert_nodes = 1;
            int ok2 = ts__surf_certify_patch(s, i, j, &pl, 1, &pv2, &sv2, &ax2, &ay2);
            reset();
            /* a shallower search proves a lower bound that is no higher
             * (each is a bound on the same minimum: never above a sampled
             * value, of either run) and certifies only what it proves */
            CHECK(pv1 <= sv0 && pv2 <= sv0 && pv1 <= sv1 && pv2 <= sv2);
            CHECK(!ok1 || pv1 > 0.0 || ok0);
            CHECK(!ok2 || pv2 > 0.0 || ok0);
            CHECK(isfinite(pv1) && isfinite(pv2));
            lowered += pv1 < pv0 || pv2 < pv0;
        }
    CHECK(lowered > 0); /* the limits ended some searches sooner */
    ts_surface_free(s);
}

/* ---- roots: the stored count and the subdivision depth ------------------- */

static ts_spline *two_point(double f0, double f1, double b1, double b2)
{
    double x[2] = {0.0, 1.0}, f[2] = {f0, f1};
    ts_spline_options o;
    th_options_paper(&o);
    ts_spline *s = NULL;
    ts_error e;
    if (ts_spline_new(x, f, 2, &o, &s, &e) != TS_OK)
        return NULL;
    /* the control values under test (docs/method.md §2: S = Σ A_l B_l) */
    s->b1[0] = b1;
    s->b2[0] = b2;
    return s;
}

/* x of t = tan(θ/2) on [0, 1] (paper form, solve.c) */
static double x_of_t(double t) { return 2.0 * atan(t) / TH_HALF_PI; }

static void solve_limits(void)
{
    TH_CASE("solve limits");
    /* B = (0, 1, −1, 0) − y, y = 0.01: S rises, falls below y, rises back
     * to 0 < y: two roots inside (0, 1) */
    ts_spline *s = two_point(0.0, 0.0, 1.0, -1.0);
    CHECK(s != NULL);
    if (!s)
        return;
    double r[4] = {TH_NAN, TH_NAN, TH_NAN, TH_NAN}, y = 0.01, v;
    size_t cnt = 0;
    reset();
    CHECK(ts_spline_solve(s, y, r, 4, &cnt) == TS_OK && cnt == 2);
    double r0 = r[0], r1 = r[1];
    ts__test_limits.solve_cap = 1; /* one root stored per interval */
    CHECK(ts_spline_solve(s, y, r, 4, &cnt) == TS_OK && cnt == 1 && r[0] == r0);
    reset();
    ts__test_limits.solve_depth = 0; /* no subdivision: the middle */
    CHECK(ts_spline_solve(s, y, r, 4, &cnt) == TS_OK && cnt == 1);
    CHECK(r[0] == x_of_t(0.5));
    reset();
    /* the default run's roots are roots (|S| <= 1: 64 ε of it) */
    CHECK(ts_spline_eval(s, r0, NULL, &v) == TS_OK && fabs(v - y) <= 64.0 * DBL_EPSILON);
    CHECK(ts_spline_eval(s, r1, NULL, &v) == TS_OK && fabs(v - y) <= 64.0 * DBL_EPSILON);
    ts_spline_free(s);

    /* a root exactly at the first subdivision's middle, t = 1/2: with
     * B = (−12, −9, 6, −3), q³S at t = 1/2 is (−12 + 44·(−9) + 72·6 + 8·(−3))/64
     * = 0 (solve.c's factored forms at t = 1/2: 1/64, 11/16, 9/8, 1/8),
     * exact in double, as is the de Casteljau middle; the Bernstein
     * coefficients have 2 sign changes, so the search subdivides, finds
     * the middle a root, and the right half starts at a root */
    TH_CASE("solve root at the middle");
    s = two_point(-12.0, -3.0, -9.0, 6.0);
    CHECK(s != NULL);
    if (!s)
        return;
    CHECK(ts_spline_solve(s, 0.0, r, 4, &cnt) == TS_OK && cnt == 2);
    CHECK(r[0] == x_of_t(0.5));
    /* the other root: S changes sign around it (q³S > 0 just right of
     * t = 1/2, < 0 at t = 1) */
    double ya, yb;
    CHECK(r[1] > r[0] && r[1] < 1.0);
    CHECK(ts_spline_eval(s, r[1] - 1e-6, NULL, &ya) == TS_OK &&
          ts_spline_eval(s, r[1] + 1e-6, NULL, &yb) == TS_OK && ya * yb < 0.0);
    ts_spline_free(s);

    /* B = (−12, −11, 7, −1): q³S(1/2) = (−12 − 484 + 504 − 8)/64 = 0, exact
     * in the factored form, while the de Casteljau middle rounds to 6 ε:
     * the right half starts at a root its coefficient does not show, and
     * the search takes the coefficient's sign.  Every returned x must be a
     * root: the bisection ends within 4 ε in t, and |dS/dt| < 250 here
     * (q³S has Bernstein coefficients of size <= 12·1.6, degree 6, q³ >= 1,
     * and |d(q⁻³)/dt| <= 2), so |S| < 1e3 ε */
    s = two_point(-12.0, -1.0, -11.0, 7.0);
    CHECK(s != NULL);
    if (!s)
        return;
    CHECK(ts_spline_solve(s, 0.0, r, 4, &cnt) == TS_OK && cnt >= 1 && cnt <= 4);
    for (size_t k = 0; k < cnt && k < 4; k++) {
        CHECK(0.0 < r[k] && r[k] < 1.0);
        CHECKF(ts_spline_eval(s, r[k], NULL, &v) == TS_OK && fabs(v) <= 1e3 * DBL_EPSILON,
               "root %zu at %.17g: S = %g", k, r[k], v);
    }
    ts_spline_free(s);
}

/* ---- the integral's scale search ----------------------------------------- */

static void integral_limit(void)
{
    TH_CASE("integral scale search limit");
    /* S = 1e300 on [0, 1e300]: the integral 1e600 overflows; with no scale
     * steps the search ends at once and the sum is +Inf, as it is with them */
    double x[2] = {0.0, 1e300}, f[2] = {1e300, 1e300}, out0 = 0.0, out1 = 0.0;
    ts_spline_options o;
    th_options_paper(&o);
    ts_spline *s = NULL;
    ts_error e;
    CHECK(ts_spline_new(x, f, 2, &o, &s, &e) == TS_OK);
    if (!s)
        return;
    reset();
    CHECK(ts_spline_integral(s, 0.0, 1e300, &out0) == TS_OK && out0 == TH_INF);
    ts__test_limits.integral_steps = 0;
    CHECK(ts_spline_integral(s, 0.0, 1e300, &out1) == TS_OK && out1 == TH_INF);
    CHECK(ts_spline_integral(s, 1e300, 0.0, &out1) == TS_OK && out1 == -TH_INF);
    reset();
    ts_spline_free(s);
}

/* ---- a short piece's Gauss–Legendre node rounded past its right end ----- */

static void short_piece_end(void)
{
    TH_CASE("integral short piece at a binade");
    /* [a, b] = [−2 − 2^-51, −2]: the middle a + (b − a)/2 rounds onto the
     * coarser grid below −2, and the node a + (b − a)/2 + 0.77·(b − a)/2
     * (and others) then rounds to −2 + 2^-52, beyond b (found by a search
     * over the ulps around ±1, ±2, ±4; none beyond b for positive ends,
     * where the middle is on b's grid or a finer one); interval.c moves it
     * back onto b */
    double x[2] = {-3.0, -1.0}, f[2] = {1.0, 2.0}, a = -2.0000000000000004, b = -2.0;
    ts_spline_options o;
    th_options_paper(&o);
    ts_spline *s = NULL;
    ts_error e;
    CHECK(ts_spline_new(x, f, 2, &o, &s, &e) == TS_OK);
    if (!s)
        return;
    double I = TH_NAN, J = TH_NAN, S2 = TH_NAN;
    CHECK(ts_spline_integral(s, a, b, &I) == TS_OK && ts_spline_integral(s, b, a, &J) == TS_OK);
    CHECK(ts_spline_eval(s, b, NULL, &S2) == TS_OK);
    /* (b − a)·S(−2) up to S's change over 2^-51 (|S'| <= 10 here: far
     * below) and the rule's rounding: 16 ε relative */
    CHECK_CLOSE(I, (b - a) * S2, 16.0 * DBL_EPSILON * fabs((b - a) * S2));
    CHECK(J == -I);
    ts_spline_free(s);
}

/* ---- the constraint scheme's doubling search (constrain.c) -------------- */

/* A polyline lower bound close under random data: certificates that need
 * a_i raised (the search of docs/method.md §13.4).  With no doublings
 * allowed, the search goes straight to its 16 values below a0: each fit
 * is then certified (every report proven, as under the default limits)
 * or refused with the documented TS_ERR_UNPROVEN, and some fit differs
 * from the default one (the limit was reached). */
static void con_doublings_limit(void)
{
    TH_CASE("constraint doublings limit");
    uint64_t st = 0x243F6A8885A308D3u;
    int differ = 0, built = 0;
    for (int p = 0; p < 60; p++) {
        double x[6], f[6], px[11], py[11];
        for (int j = 0; j < 6; j++) {
            st ^= st << 13, st ^= st >> 7, st ^= st << 17;
            x[j] = j;
            f[j] = 4.0 * (double)(st >> 11) * 0x1p-53;
        }
        /* teeth: 0.5 under the data at the knots, and at each interval's
         * middle just under the chord, where the curve of convex-looking
         * data dips below it unless a_i is raised (towards the chord);
         * the pieces' lines extended over an interval pass above its data,
         * so no closed form applies (§13.3) */
        for (int j = 0; j < 11; j++) {
            st ^= st << 13, st ^= st >> 7, st ^= st << 17;
            int k = j / 2;
            px[j] = 0.5 * j;
            py[j] = j % 2 ? 0.5 * (f[k] + f[k + 1]) - 1e-3 * (0.1 + (double)(st >> 11) * 0x1p-53)
                          : f[k] - 0.5;
        }
        ts_constraint c;
        ts_constraint_init(&c, TS_CONSTRAINT_LOWER);
        c.bound = TS_BOUND_POLYLINE;
        c.px = px;
        c.py = py;
        c.n_poly = 11;
        ts_spline_options o;
        ts_spline_options_init(&o);
        o.constraints = &c;
        o.n_constraints = 1;
        ts_spline *s0 = NULL, *s1 = NULL;
        reset();
        ts_status a = ts_spline_new(x, f, 6, &o, &s0, NULL);
        ts__test_limits.con_doublings = 0;
        ts_status b = ts_spline_new(x, f, 6, &o, &s1, NULL);
        reset();
        CHECKF(b == TS_OK || b == TS_ERR_UNPROVEN || (b == a && a == TS_ERR_CONDITION), "%s",
               ts_status_name(b));
        if (a != b)
            differ++;
        else if (a == TS_OK) {
            for (size_t i = 0; i < 5; i++)
                if (s0->alpha[i] + s0->beta[i] != s1->alpha[i] + s1->beta[i])
                    differ++, i = 5;
        }
        if (s1) {
            built++;
            for (size_t i = 0; i < 5; i++) {
                ts_constraint_report r;
                ts_constraint_report_init(&r);
                CHECK(ts_spline_constraint_report(s1, 0, i, &r) == TS_OK && r.certified == 1 &&
                      r.gap >= 0.0);
            }
        }
        ts_spline_free(s0);
        ts_spline_free(s1);
    }
    CHECKF(differ > 0 && built > 0, "%d differ, %d built", differ, built);
    printf("constraint doublings limit: %d of 60 differ, %d built\n", differ, built);
}

/* ---- the constraint scheme's minima and bound-spline certificates --------- */

/* Four records on random data (convex data for the convex one): reports of
 * the spline built under the default limits, again under a lowered limit
 * of the minimum's root isolation (candidates: the ends only; no
 * subdivision; no bisection steps).  A lowered minimum is a least value
 * over fewer or coarser candidates, each a value of the gap: never below
 * the default one beyond the evaluation's rounding (1e-12 of the scale);
 * some differ (the limit was reached). */
static void con_root_limits(void)
{
    TH_CASE("constraint minimum limits");
    uint64_t st = 0x13198A2E03707344u;
    int differ = 0;
    for (int p = 0; p < 40; p++) {
        double x[6], f[6], px[3] = {-1.0, 2.5, 6.0}, py[3];
        for (int j = 0; j < 6; j++) {
            st ^= st << 13, st ^= st >> 7, st ^= st << 17;
            x[j] = j + 0.5 * (double)(st >> 11) * 0x1p-53;
            f[j] = p % 4 == 0 ? x[j] * x[j] : 3.0 * (double)(st >> 11) * 0x1p-53;
        }
        py[0] = py[2] = -1.0, py[1] = -0.2;
        ts_constraint c;
        ts_constraint_init(&c, p % 4 == 0   ? TS_CONSTRAINT_CONVEX
                               : p % 4 == 1 ? TS_CONSTRAINT_SLOPE_ABS
                               : p % 4 == 2 ? TS_CONSTRAINT_UPPER
                                            : TS_CONSTRAINT_LOWER);
        c.value = p % 4 == 1 ? 50.0 : 3.5;
        if (p % 4 == 3)
            c.bound = TS_BOUND_POLYLINE, c.px = px, c.py = py, c.n_poly = 3;
        ts_spline_options o;
        ts_spline_options_init(&o);
        o.constraints = &c;
        o.n_constraints = 1;
        ts_spline *s = NULL;
        reset();
        if (ts_spline_new(x, f, 6, &o, &s, NULL) != TS_OK)
            continue;
        for (size_t i = 0; i < 5; i++) {
            ts_constraint_report r0, r;
            ts_constraint_report_init(&r0);
            CHECK(ts_spline_constraint_report(s, 0, i, &r0) == TS_OK && r0.certified == 1);
            for (int lim = 0; lim < 3; lim++) {
                reset();
                if (lim == 0)
                    ts__test_limits.con_root_cap = 2;
                else if (lim == 1)
                    ts__test_limits.con_root_depth = 0;
                else
                    ts__test_limits.con_root_steps = 0;
                ts_constraint_report_init(&r);
                CHECK(ts_spline_constraint_report(s, 0, i, &r) == TS_OK);
                reset();
                CHECKF(r.gap >= r0.gap - 1e-12 * (1.0 + fabs(r0.gap)), "%d: %.17g < %.17g", lim,
                       r.gap, r0.gap);
                differ += r.gap != r0.gap;
            }
        }
        ts_spline_free(s);
    }
    CHECKF(differ > 0, "%d", differ);
    printf("constraint minimum limits: %d minima differ\n", differ);
}

/* A lower bound spline B (geometric, through points of 0.4 sin) under
 * random data 0.01 to 0.06 above it: built with the certificate's cells or depth
 * lowered to 1 and 0, each fit is certified under the default limits or
 * refused with the documented TS_ERR_UNPROVEN, and some are refused (the
 * limit was reached).  The report's bisection without steps keeps its
 * scan points' least value: never below the default one (1e-12). */
static void bcurve_limits(void)
{
    TH_CASE("bound spline limits");
    double bx[9], by[9];
    for (int j = 0; j < 9; j++)
        bx[j] = 0.5 * j, by[j] = 0.4 * sin(1.3 * bx[j]);
    ts_spline_options ob;
    ts_spline_options_init(&ob);
    ts_spline *b = NULL;
    CHECK(ts_spline_new(bx, by, 9, &ob, &b, NULL) == TS_OK);
    uint64_t st = 0xA4093822299F31D0u;
    int refused = 0, built = 0, differ = 0;
    for (int p = 0; p < 30 && b; p++) {
        double x[5], f[5];
        for (int j = 0; j < 5; j++) {
            st ^= st << 13, st ^= st >> 7, st ^= st << 17;
            x[j] = j;
            f[j] = 0.4 * sin(1.3 * x[j]) + 0.01 + 0.05 * (double)(st >> 11) * 0x1p-53;
        }
        ts_constraint c;
        ts_constraint_init(&c, TS_CONSTRAINT_LOWER);
        c.bound = TS_BOUND_SPLINE, c.spline = b;
        ts_spline_options o;
        ts_spline_options_init(&o);
        o.constraints = &c;
        o.n_constraints = 1;
        for (int lim = 0; lim < 2; lim++) {
            ts_spline *s = NULL;
            reset();
            if (lim == 0)
                ts__test_limits.bcurve_cells = 1;
            else
                ts__test_limits.bcurve_depth = 0;
            ts_status r = ts_spline_new(x, f, 5, &o, &s, NULL);
            reset();
            CHECKF(r == TS_OK || r == TS_ERR_UNPROVEN, "%s", ts_status_name(r));
            refused += r == TS_ERR_UNPROVEN;
            built += r == TS_OK;
            for (size_t i = 0; s && i < 4; i++) {
                ts_constraint_report rp;
                ts_constraint_report_init(&rp);
                CHECK(ts_spline_constraint_report(s, 0, i, &rp) == TS_OK && rp.certified == 1);
            }
            ts_spline_free(s);
        }
        ts_spline *s = NULL;
        if (ts_spline_new(x, f, 5, &o, &s, NULL) != TS_OK)
            continue;
        for (size_t i = 0; i < 4; i++) {
            ts_constraint_report r0, r1;
            ts_constraint_report_init(&r0);
            ts_constraint_report_init(&r1);
            CHECK(ts_spline_constraint_report(s, 0, i, &r0) == TS_OK);
            ts__test_limits.bcurve_gap_steps = 0;
            CHECK(ts_spline_constraint_report(s, 0, i, &r1) == TS_OK);
            reset();
            CHECKF(r1.gap >= r0.gap - 1e-12 * (1.0 + fabs(r0.gap)), "%.17g < %.17g", r1.gap,
                   r0.gap);
            differ += r1.gap != r0.gap;
        }
        ts_spline_free(s);
    }
    ts_spline_free(b);
    CHECKF(refused > 0 && differ > 0, "%d refused, %d built, %d differ", refused, built, differ);
    printf("bound spline limits: %d refused, %d built, %d minima differ\n", refused, built, differ);
}

int main(void)
{
    curve_length();
    spline_repair();
    trig_min_limits();
    surface_cert_limits();
    solve_limits();
    integral_limit();
    short_piece_end();
    con_doublings_limit();
    con_root_limits();
    bcurve_limits();
    reset();
    return th_report("test_safeguards");
}
