/* Edge paths of the public API's construction and accessors that the other
 * programs do not reach (coverage): the large-block allocator and
 * its failure paths, size overflow of every product of ts_spline_new and
 * ts_curve_new, the first offender of alpha/beta checks at the ends of a
 * block, knots and box rules that overflow in ts_curve_new, a box repair
 * that cannot succeed, NULL handles of the accessors, every status's
 * message.  Expected values: the header's documented statuses and indices,
 * and values worked out by hand in the comments (no library call as oracle).
 *
 * Linked with --wrap=aligned_alloc (tests/CMakeLists.txt): the wrapper can
 * refuse, so that ts__alloc_block's fallback to malloc runs. */
#include "th.h"
#include "internal.h"
#include "trigspline.h"

#include <float.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

void *__real_aligned_alloc(size_t alignment, size_t size);
void *__wrap_aligned_alloc(size_t alignment, size_t size);
static int refuse_aligned;
static long aligned_calls;
void *__wrap_aligned_alloc(size_t alignment, size_t size)
{
    aligned_calls++;
    return refuse_aligned ? NULL : __real_aligned_alloc(alignment, size);
}

#define U 0x1p-52 /* one ulp of 1 */

/* every status 0 .. TS_STATUS_COUNT_-1 has its own message; others do not */
static void test_messages(void)
{
    const char *unknown = ts_strerror((ts_status)-1);
    CHECK(strcmp(unknown, "unknown status code") == 0);
    CHECK(strcmp(ts_strerror(TS_STATUS_COUNT_), unknown) == 0);
    for (int s = 0; s < (int)TS_STATUS_COUNT_; s++) {
        const char *m = ts_strerror((ts_status)s);
        CHECKF(m != NULL && strcmp(m, unknown) != 0 && m[0] != '\0', "status %d", s);
    }
}

/* the header's values for a NULL spline */
static void test_null_accessors(void)
{
    CHECK(ts_spline_intervals(NULL) == 0);
    CHECK(ts_spline_x(NULL) == NULL && ts_spline_f(NULL) == NULL);
    CHECK(ts_spline_slopes(NULL) == NULL && ts_spline_alpha(NULL) == NULL);
    CHECK(ts_spline_beta(NULL) == NULL);
    CHECK(ts_spline_form(NULL) == TS_FORM_PAPER);
    CHECK(ts_spline_shape(NULL) == TS_SHAPE_NONE);
    CHECK(ts_spline_extrapolation(NULL) == TS_EXTRAP_ERROR);
    ts_spline_options_init(NULL); /* a no-op, no crash */
    double a = 0.0;
    CHECK(ts_curve_params(NULL, 0, &a, NULL) == TS_ERR_NULL && isnan(a));
}

/* n_points so large that one step of the block's size overflows; the
 * arrays are not read (ASan would see it): x and f have 2 points.
 * The layout of spline.c: 3 arrays of np = n + 1 doubles, per of n (alpha,
 * beta, and b1, b2 in the paper form, κ in the geometric form), n/8 + 1
 * running integrals (TS_CUM_STEP), n term bytes. */
static size_t layout_doubles(size_t n, size_t per)
{
    return 3 * (n + 1) + per * n + n / TS_CUM_STEP + 1;
}

static void test_size_overflow(void)
{
    static const double x[2] = {0, 1}, f[2] = {0, 1};
    const size_t M = SIZE_MAX;
    for (int geo = 0; geo <= 1; geo++) {
        ts_spline_options o;
        ts_spline_options_init(&o);
        o.form = geo ? TS_FORM_GEOMETRIC : TS_FORM_PAPER;
        size_t per = geo ? 3 : 4, q = 3 + per, np[4];
        np[0] = M / 2;  /* 3 np does not fit */
        np[1] = M / 5;  /* 3 np and per n fit, their sum does not */
        np[2] = M / 16; /* the doubles fit, times 8 bytes they do not */
        /* case 3: the largest n whose doubles times 8 fit; plus n bytes they do not */
        size_t n3 = (M / 8 - 4) / (8 * q + 1) * 8;
        CHECK(layout_doubles(n3, per) <= M / 8);
        while (layout_doubles(n3 + 1, per) <= M / 8)
            n3++;
        np[3] = n3 + 1;
        for (int k = 0; k < 4; k++) {
            ts_spline *s = (ts_spline *)(uintptr_t)1;
            ts_error e;
            CHECKF(ts_spline_new(x, f, np[k], &o, &s, &e) == TS_ERR_OVERFLOW && s == NULL &&
                       e.status == TS_ERR_OVERFLOW, "form %d, case %d", geo, k);
        }
        /* case 3 is tight: the bytes of the doubles fit, with n more they do not */
        size_t c3 = 8 * layout_doubles(n3, per);
        CHECKF(c3 / 8 == layout_doubles(n3, per) && n3 > M - c3, "form %d", geo);
    }
}

/* f constant 3 on x = 0..n: every interval is flat, S = 3 exactly
 * (docs/method.md §3: all four control values equal f), ∫ = 3 n. */
static ts_spline *flat_spline(size_t np, ts_error *e)
{
    double *x = malloc(np * sizeof *x), *f = malloc(np * sizeof *f);
    ts_spline *s = NULL;
    if (x && f) {
        for (size_t i = 0; i < np; i++)
            x[i] = (double)i, f[i] = 3.0;
        (void)ts_spline_new(x, f, np, NULL, &s, e);
    }
    free(x);
    free(f);
    return s;
}

static void check_flat(const ts_spline *s, size_t np)
{
    size_t n = np - 1;
    double y = 0.0, I = 0.0;
    CHECK(ts_spline_intervals(s) == n);
    CHECK(ts_spline_eval(s, (double)n, NULL, &y) == TS_OK && y == 3.0);
    CHECK(ts_spline_eval(s, 0.5 * (double)n + 0.25, NULL, &y) == TS_OK && y == 3.0);
    /* sum of n terms 3: exact in double (3n < 2^53) */
    CHECK(ts_spline_integral(s, 0.0, (double)n, &I) == TS_OK);
    CHECK_CLOSE(I, 3.0 * (double)n, 1e-12 * 3.0 * (double)n); /* n additions of ~1 ulp */
}

/* 1026 points: the second block of 1024 intervals has one interval, and
 * its points were copied with the first (spline.c copy_points). */
static void test_mt_refusals(void)
{
    /* a batch large enough to be split over 2 threads (8192 queries each at
     * least, src/eval.c), refused before any thread starts: deriv 3 in the
     * geometric form and an extrapolation mode out of range give
     * TS_ERR_OPTION and every value NaN (include/trigspline.h) */
    const size_t m = 3 * 8192;
    double *xq = malloc(m * sizeof *xq), *yq = malloc(m * sizeof *yq);
    ts_error e;
    ts_spline *s = flat_spline(4, &e);
    CHECK(xq && yq && s);
    if (xq && yq && s) {
        for (size_t j = 0; j < m; j++)
            xq[j] = 3.0 * (double)j / (double)m;
        CHECK(ts_spline_eval_batch_mt(s, 3, xq, m, yq, 2, &e) == TS_ERR_OPTION &&
              e.status == TS_ERR_OPTION);
        size_t nan = 0;
        for (size_t j = 0; j < m; j++)
            nan += isnan(yq[j]) != 0;
        CHECK(nan == m);
        CHECK(ts_spline_eval_batch_mode_mt(s, 0, (ts_extrap)9, xq, m, yq, 2, &e) == TS_ERR_OPTION);
        CHECK(ts_spline_eval_batch_mode_mt(s, 0, TS_EXTRAP_ERROR, xq, m, yq, 2, &e) == TS_OK);
        CHECK(yq[0] == 3.0 && yq[m - 1] == 3.0);
    }
    ts_spline_free(s);
    free(xq);
    free(yq);
}

static void test_block_edge(void)
{
    ts_error e;
    ts_spline *s = flat_spline(1026, &e);
    CHECK(s != NULL);
    if (s)
        check_flat(s, 1026);
    ts_spline_free(s);
}

/* A block of >= 8 MiB (status.c ts__alloc_block): 180,000 points in the
 * default (geometric) form need 8 (3 np + 3 n + n/8 + 1) + n = 9.0 MB.  Then: the allocation
 * refused by the test hook (TS_ERR_NOMEM: the handle is allocation 1, the
 * block 2), and aligned_alloc refused (the fallback to malloc builds the
 * same spline). */
static void test_large_block(void)
{
    const size_t np = 180000;
    ts_error e;
    long before = aligned_calls;
    ts_spline *s = flat_spline(np, &e);
    CHECK(s != NULL && aligned_calls == before + 1);
    if (s)
        check_flat(s, np);
    ts_spline_free(s);

    ts__test_fail_alloc = 2;
    s = flat_spline(np, &e);
    CHECK(ts__test_fail_alloc == 0); /* the second allocation was the one refused */
    ts__test_fail_alloc = 0;
    CHECK(s == NULL && e.status == TS_ERR_NOMEM);

    refuse_aligned = 1;
    s = flat_spline(np, &e);
    refuse_aligned = 0;
    CHECK(s != NULL);
    if (s)
        check_flat(s, np);
    ts_spline_free(s);
}

/* The first bad alpha_i / beta_i is named, also the last interval of a
 * block (ts_spline_new's documented TS_ERR_ALPHA / TS_ERR_BETA). */
static void test_alpha_beta_offenders(void)
{
    static const double x[5] = {0, 1, 2, 3, 4}, f[5] = {0, 1, 0, 1, 0};
    struct { double al[4], be[4]; ts_status st; size_t index; } cases[] = {
        {{1, 1, 0, 1}, {0, 0, 0, 0}, TS_ERR_ALPHA, 2},
        {{1, 1, 1, -1}, {0, 0, 0, 0}, TS_ERR_ALPHA, 3},
        {{1, 1, 1, TH_INF}, {0, 0, 0, 0}, TS_ERR_ALPHA, 3},
        {{1, TH_NAN, 1, 1}, {0, 0, 0, 0}, TS_ERR_ALPHA, 1},
        {{1, 1, 1, 1}, {0, -1, 0, 0}, TS_ERR_BETA, 1},
        {{1, 1, 1, 1}, {0, 0, TH_NAN, 0}, TS_ERR_BETA, 2},
        {{1, 1, 1, 1}, {0, 0, 0, TH_INF}, TS_ERR_BETA, 3},
        /* both finite, alpha + beta overflows */
        {{1, 1, 1, DBL_MAX}, {0, 0, 0, DBL_MAX}, TS_ERR_BETA, 3},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        ts_spline_options o;
        ts_spline_options_init(&o);
        o.alphas = cases[k].al;
        o.n_alphas = 4;
        o.betas = cases[k].be;
        o.n_betas = 4;
        ts_spline *s = NULL;
        ts_error e;
        ts_status st = ts_spline_new(x, f, 5, &o, &s, &e);
        CHECKF(st == cases[k].st && e.index == cases[k].index && e.where == TS_WHERE_INTERVAL &&
                   s == NULL, "case %zu: status %d index %zu", k, (int)st, e.index);
        ts_spline_free(s);
    }
}

static ts_status curve(const double *P, size_t np, size_t dim, const ts_curve_options *o,
                       ts_error *e)
{
    ts_curve *c = (ts_curve *)(uintptr_t)1;
    ts_status st = ts_curve_new(P, np, dim, o, &c, e);
    CHECK((st == TS_OK) == (c != NULL));
    ts_curve_free(c);
    return st;
}

static void test_curve_refusals(void)
{
    ts_curve_options o;
    ts_error e;
    /* the control points (4 dim doubles per segment) would overflow size_t:
     * refused before a point is read (P has one point) */
    static const double P1[3] = {0, 0, 0};
    CHECK(curve(P1, SIZE_MAX / 2 / 4 / 8 + 1, 2, NULL, &e) == TS_ERR_OVERFLOW);
    CHECK(curve(P1, SIZE_MAX / 3 / 4 / 8 + 1, 3, NULL, &e) == TS_ERR_OVERFLOW);

    /* chord length 2e308 overflows: knot 1 is not finite */
    static const double P2[4] = {-1e308, 0, 1e308, 0};
    CHECK(curve(P2, 2, 2, NULL, &e) == TS_ERR_NONFINITE && e.index == 1 &&
          e.where == TS_WHERE_POINT);

    /* closed, centripetal knots: |AB| = |BC| = 1.41e308 (sqrt: 1.19e154 each),
     * |CA| = 2e308 overflows on the closing segment, which ends at point 0 */
    static const double P3[6] = {-1e308, 0, 0, 1e308, 1e308, 0};
    ts_curve_options_init(&o);
    o.closed = 1;
    o.param = TS_PARAM_CENTRIPETAL;
    CHECK(curve(P3, 3, 2, &o, &e) == TS_ERR_NONFINITE && e.index == 0 &&
          e.where == TS_WHERE_POINT);

    /* box rule finite (margin 1e308, the terms negative) but alpha + beta =
     * 1.5e308 + 1e308 overflows: infeasible */
    static const double P4[4] = {0, 1, 1, 2};
    ts_curve_options_init(&o);
    o.alpha = 1.5e308;
    o.margin = 1e308;
    o.has_lo[1] = 1;
    o.lo[1] = 0.0;
    CHECK(curve(P4, 2, 2, &o, &e) == TS_ERR_INFEASIBLE && e.index == 0 &&
          e.where == TS_WHERE_INTERVAL);

    /* box repair that cannot succeed (as test_curve's box_repair, y scaled):
     * closed, uniform knots, P0 one ulp above the floor y = 1, P2 at 1e292.
     * Periodic mean slope d_y(P0) = ((1 + u - 1e292) + (1 - u)) / 2 = -5e291;
     * the docs/method.md §5 rule: a = t + K 5e291 / u, K = 2/(3 pi): a = 9.6e306,
     * which puts B1 = P0 + k d within rounding of the floor (here B1 rounds
     * onto it: not certified); the repair doubles a to 1.9e307 > 1e307, the
     * largest a it tries (header): TS_ERR_INFEASIBLE on segment 0.  (With
     * P2 at 1e288 .. 1e291 the rule is 9.6e302 .. 9.6e305 and B1 rounds
     * above the floor: certified by the rule, no repair.) */
    static const double P5[6] = {0, 1 + U, 1, 2, 2, 1e292};
    ts_curve_options_init(&o);
    o.closed = 1;
    o.param = TS_PARAM_UNIFORM;
    o.has_lo[1] = 1;
    o.lo[1] = 1.0;
    CHECK(curve(P5, 3, 2, &o, &e) == TS_ERR_INFEASIBLE && e.index == 0 &&
          e.where == TS_WHERE_INTERVAL);
}

/* Subnormal chord 1e-309 (dθ/dt = (π/2)/h overflows): first and second
 * derivative divide by h instead.  y ≡ 0: its control values are 0, so
 * dy/dt = d²y/dt² = 0 exactly; x: the straight segment, dx/dt finite. */
static void test_curve_subnormal_step(void)
{
    static const double P[4] = {0, 0, 1e-309, 0};
    ts_curve_options o;
    ts_curve_options_init(&o);
    o.param = TS_PARAM_CHORD;
    ts_curve *c = NULL;
    ts_error e;
    CHECK(ts_curve_new(P, 2, 2, &o, &c, &e) == TS_OK);
    if (!c)
        return;
    double p[2], dp[2], d2p[2];
    CHECK(ts_curve_eval(c, 0.5e-309, NULL, p, dp, d2p) == TS_OK);
    CHECK(dp[1] == 0.0 && d2p[1] == 0.0);
    /* dx/dt over [0, h] averages 1 (x goes from 0 to h): finite, positive */
    CHECK(isfinite(dp[0]) && dp[0] > 0.0 && !isnan(d2p[0]));
    /* NULL out-parameters (header: TS_ERR_NULL, the others set to NaN) */
    double a = 0.0, b = 0.0;
    CHECK(ts_curve_params(c, 0, &a, NULL) == TS_ERR_NULL && isnan(a));
    CHECK(ts_curve_params(c, 0, NULL, &b) == TS_ERR_NULL && isnan(b));
    int has[3] = {1, 0, 0};
    double lim[3] = {-1.0, -1.0, -1.0};
    CHECK(ts_curve_certify_box(c, NULL, NULL, has, NULL, NULL, NULL) == TS_ERR_NULL);
    CHECK(ts_curve_certify_box(c, has, NULL, NULL, NULL, NULL, NULL) == TS_ERR_NULL);
    CHECK(ts_curve_certify_box(c, has, lim, NULL, NULL, NULL, NULL) == TS_OK); /* x > -1 */
    /* m - 1 samples per segment, 1 + dim columns: r (1 + dim) overflows */
    size_t rows = 7;
    CHECK(ts_curve_sample(c, SIZE_MAX / 2, NULL, 0, &rows) == TS_ERR_OVERFLOW && rows == 0);
    ts_curve_free(c);
}

/* ts_spline_certify with both lines where the lower one fails: the upper gap is
 * still reported.  f = 0, 1, 0 on x = 0, 1, 2 (paper form, no shape): S
 * interpolates 0 at x = 0 and 2, below y = 0.5 on both intervals.  S is a
 * convex combination of its control values (A_l >= 0, sum 1); d_1 = 0 and
 * the end slopes are positive on the rising and negative on the falling
 * side, so B is monotone [0, K d_0, 1, 1] and mirrored: min S = 0 (gap to
 * 0.5: -0.5 exactly), max S = 1, the gap to y = 10 is 9 (to rounding). */
static void test_certify_both_lines(void)
{
    static const double x[3] = {0, 1, 2}, f[3] = {0, 1, 0};
    ts_spline *s = NULL;
    CHECK(ts_spline_new(x, f, 3, NULL, &s, NULL) == TS_OK);
    if (!s)
        return;
    ts_line lo = {0.0, 0.5}, hi = {0.0, 10.0};
    ts_interval_report r[2];
    ts_interval_report_init(r, sizeof r / sizeof r[0]);
    ts_error e;
    CHECK(ts_spline_certify(s, &lo, &hi, r, &e) == TS_ERR_VIOLATED && e.index == 0);
    for (int i = 0; i < 2; i++) {
        CHECK(r[i].certified == 0 && r[i].has_lower && r[i].has_upper);
        CHECK(r[i].gap_lower == -0.5); /* at the knot value 0: exact */
        CHECK_CLOSE(r[i].gap_upper, 9.0, 8 * DBL_EPSILON); /* roundings of 10 - S ~ 1e-15 */
    }
    CHECK(ts_spline_certified(s) == 0); /* no shape: nothing promised */
    /* only an upper line: certified (max S = 1 < 10), its gap 9 */
    CHECK(ts_spline_certify(s, NULL, &hi, r, &e) == TS_OK && r[0].certified && !r[0].has_lower);
    ts_spline_free(s);
}

/* Geometric form, shape below y = 3, certify = 0 (the control-value proof
 * at build, gaps computed by ts_spline_report): f = 1 everywhere, so every
 * control value is 1, S = 1 and the gap to the upper line is 2 exactly. */
static void test_report_upper_uncertified_build(void)
{
    static const double x[4] = {0, 1, 3, 4}, f[4] = {1, 1, 1, 1};
    ts_spline_options o;
    ts_spline_options_init(&o);
    o.form = TS_FORM_GEOMETRIC;
    o.shape = TS_SHAPE_BELOW;
    o.upper.m = 0.0;
    o.upper.c = 3.0;
    o.certify = 0;
    ts_spline *s = NULL;
    CHECK(ts_spline_new(x, f, 4, &o, &s, NULL) == TS_OK);
    if (!s)
        return;
    CHECK(ts_spline_certified(s) == 1);
    for (size_t i = 0; i < 3; i++) {
        ts_interval_report r = TS_INTERVAL_REPORT_INIT;
        CHECK(ts_spline_report(s, i, &r) == TS_OK);
        CHECK(r.certified == 1 && r.has_upper && !r.has_lower);
        CHECK_CLOSE(r.gap_upper, 2.0, 4 * DBL_EPSILON); /* 3 - 1: a few roundings of 3 */
        CHECK(r.at_upper >= x[i] && r.at_upper <= x[i + 1]);
    }
    ts_spline_free(s);
}

int main(void)
{
    TH_CASE("messages");
    test_messages();
    TH_CASE("null_accessors");
    test_null_accessors();
    TH_CASE("size_overflow");
    test_size_overflow();
    TH_CASE("block_edge");
    test_block_edge();
    TH_CASE("large_block");
    test_large_block();
    TH_CASE("alpha_beta_offenders");
    test_alpha_beta_offenders();
    TH_CASE("curve_refusals");
    test_curve_refusals();
    TH_CASE("curve_subnormal_step");
    test_curve_subnormal_step();
    TH_CASE("certify_both_lines");
    test_certify_both_lines();
    TH_CASE("report_upper_uncertified_build");
    test_report_upper_uncertified_build();
    TH_CASE("mt refusals");
    test_mt_refusals();
    return th_report("test_cover_api");
}
