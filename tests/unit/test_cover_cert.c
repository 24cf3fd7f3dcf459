/* Paths of the certificate code that the other tests do not reach (issue
 * 18, coverage): the root isolation of the exact minimum when P has an
 * exact zero at a subdivision point and when a double root keeps sign
 * changes down to the depth limit (src/trigmin.c, docs/method.md §5.6);
 * every outcome of the monotone control-polygon proof; a margin so large
 * that a_i + t overflows (src/repair.c: capped at 1e307).  Expected values
 * from closed forms and from a minimiser in long double (grid and golden
 * section, tests/common/th_gapmin.h), not from the code under test. */
#include "th.h"
#include "th_options.h"
#include "common/th_gapmin.h"
#include "internal.h"
#include "trigspline.h"

#include <float.h>
#include <math.h>
#include <string.h>


/* The minimum over [0, π/2] of g(θ) = Σ A_l C_l − κ θ (tests/common/th_gapmin.h,
 * a 4096-point grid). */
static long double ref_min(const double C[4], double k)
{
    long double Cl[4] = {(long double)C[0], (long double)C[1], (long double)C[2],
                         (long double)C[3]};
    return th_gap_min(Cl, (long double)k, 4096);
}

/* P(t) = q³ g'(θ) = 3D0 (1−t)⁵(1+t) + 4D1 t(1−t⁴) + 24D2 t⁵ − κ q³
 * (docs/method.md §5.6), D = (−8, 3, −6), κ = 0: P(1/2) = (9D0 + 120D1 +
 * 48D2)/64 = 0, and the Bernstein coefficients (−24, −6, 4, 6, 8, −16,
 * −144) are integers with two sign changes, so the first subdivision at
 * t = 1/2 computes P(1/2) = 0 exactly: the split point is a candidate.
 * Then D = (243, −174, 1024): P has a double root at t = 1/3 (P(1/3) =
 * P'(1/3) = 0, solved in rationals), coefficients (729, 127, −232, −348,
 * −464, 3632, 24576): the cells around 1/3 keep two sign changes until
 * rounding blurs them (about 38 levels deep; exact arithmetic would go to
 * the depth limit); P >= 0, so g increases and its minimum is C0 at θ = 0. */
static void root_isolation(void)
{
    const double C1[4] = {20, 12, 15, 9};
    double th, t, eb;
    double v = ts__trig_min_core(C1[0], C1[1], C1[2], C1[3], 0.0, &th, &t, &eb);
    long double r = ref_min(C1, 0.0);
    /* the computed minimum is within its guard of the true one; the
     * reference to 1e-15 in θ: |g'| there far below 1e-12 */
    CHECKF(fabsl((long double)v - r) <= (long double)eb && eb < 1e-10,
           "split root: min %.17g, reference %.17Lg, guard %.3g", v, r, eb);
    const double C2[4] = {5, 248, 74, 1098};
    v = ts__trig_min_core(C2[0], C2[1], C2[2], C2[3], 0.0, &th, &t, &eb);
    CHECKF(v == 5.0 && th == 0.0 && t == 0.0, "double root: min %.17g at θ %.3g", v, th);
    /* and the same through ts__trig_min (θ of the minimum) */
    CHECK(ts__trig_min(C2, 0.0, &th) == 5.0 && th == 0.0);
}

/* Every outcome of the monotone control-polygon proof (docs/method.md §5.5:
 * B monotone in either direction; equal ends need equal values), through
 * ts__check_ctl on a monotone spline (paper form: no X). */
static void monotone_polygon(void)
{
    const double x[3] = {0, 1, 2}, f[3] = {0, 1, 2};
    ts_spline_options o;
    th_options_paper(&o);
    o.shape = TS_SHAPE_MONOTONE;
    ts_spline *s = NULL;
    CHECK(ts_spline_new(x, f, 3, &o, &s, NULL) == TS_OK);
    if (!s)
        return;
    static const struct {
        double B[4];
        int mono;
    } cases[] = {
        {{0, 1, 2, 3}, 1},  {{0, -1, 2, 3}, 0}, {{0, 2, 1, 3}, 0}, {{0, 1, 4, 3}, 0},
        {{3, 2, 1, 0}, 1},  {{3, 4, 1, 0}, 0},  {{3, 1, 2, 0}, 0},  {{3, 2, -1, 0}, 0},
        {{1, 1, 1, 1}, 1},  {{1, 2, 1, 1}, 0},  {{1, 1, 0, 1}, 0},  {{1, 1, 2, 1}, 0},
        {{0, 0, 0, 1}, 1},  {{1, 1, 0, 0}, 1},
    };
    for (size_t k = 0; k < sizeof cases / sizeof cases[0]; k++) {
        ts__cert cr;
        int ok = ts__check_ctl(s, 0, cases[k].B, NULL, 1, &cr, 0);
        CHECKF(ok == cases[k].mono, "case %zu: %d", k, ok);
    }
    ts_spline_free(s);
}

/* A margin of 1e308 (allowed: t <= DBL_MAX): a_i + t overflows and is
 * capped at 1e307, the largest a the repair uses (header: "the a needed
 * exceeds 1e307").  Data 1 above y = x with the user slope −1e301 at the
 * middle knot: the rule's beta is capped at 1e300, where interval 1's
 * B1 = f_1 + k d_1 is 2.1 below f_1 (k = 2h/(3π a)), under the line; the
 * limit a -> ∞ (the curve f_i c² + f_{i+1} s², 0.105 h Δ from the chord
 * at most) is inside, so the repair doubles a_1, bisects, and adds the
 * margin: 1e307, where B1 = f_1 − 2e-7 is inside. */
static void huge_margin(void)
{
    const double x[3] = {0, 1, 2}, f[3] = {1, 2, 3}, d[3] = {1, -1e301, 1};
    ts_spline_options o;
    th_options_paper(&o);
    o.shape = TS_SHAPE_ABOVE;
    o.lower.m = 1;
    o.lower.c = 0;
    o.slopes = TS_SLOPES_USER;
    o.user_slopes = d;
    o.n_user_slopes = 3;
    o.margin = 1e308;
    ts_spline *s = NULL;
    ts_error e;
    ts_status st = ts_spline_new(x, f, 3, &o, &s, &e);
    CHECKF(st == TS_OK, "%s at %zu", ts_strerror(st), e.index);
    for (size_t i = 0; s && i < 2; i++) {
        ts_interval_report r = TS_INTERVAL_REPORT_INIT;
        ts_spline_report(s, i, &r);
        CHECKF(r.certified && r.a <= 1e307, "interval %zu: a %.17g term %d", i, r.a, (int)r.term);
        if (i == 1)
            CHECKF(r.term == TS_TERM_CERTIFY && r.a == 1e307, "interval 1: a %.17g term %d", r.a,
                   (int)r.term);
    }
    ts_spline_free(s);
}

static ts_status build(const double *x, const double *f, size_t np, const ts_spline_options *o,
                       ts_error *e)
{
    ts_spline *s = NULL;
    ts_status st = ts_spline_new(x, f, np, o, &s, e);
    ts_spline_free(s);
    return st;
}

/* The exact side of a line where a point equals the line's rounded value
 * and the rounding error cannot be formed exactly (src/shape.c: m x beyond
 * 2^1020 or near underflow, c or the value beyond 2^1020): undecided, taken
 * as on the line.  Each case below is on or across the line in exact
 * arithmetic (worked out in its comment), so TS_ERR_SIDE is right. */
static void side_edges(void)
{
    ts_spline_options o;
    th_options_paper(&o);
    o.shape = TS_SHAPE_ABOVE;
    ts_error e;
    /* m x = 2^1021 at x = 2^30, c = −2^1021: the line is 0 there, f = 0 */
    const double x1[2] = {0x1p30 - 1, 0x1p30}, f1[2] = {0, 0};
    o.lower.m = 0x1p991, o.lower.c = -0x1p1021;
    CHECK(build(x1, f1, 2, &o, &e) == TS_ERR_SIDE && e.index == 1);
    /* c = 2^1021, m = 1: at x = 1 the line is 2^1021 + 1, f = 2^1021 below */
    const double x2[2] = {0, 1}, f2[2] = {0x1p1021 * (1 + 0x1p-50), 0x1p1021};
    o.lower.m = 1, o.lower.c = 0x1p1021;
    CHECK(build(x2, f2, 2, &o, &e) == TS_ERR_SIDE && e.index == 1);
    /* m = 2^1019, c = 2^1020: the line is 2^1021 at x = 2, f on it */
    const double x3[2] = {0, 2}, f3[2] = {0x1p1020 * (1 + 0x1p-50), 0x1p1021};
    o.lower.m = 0x1p1019, o.lower.c = 0x1p1020;
    CHECK(build(x3, f3, 2, &o, &e) == TS_ERR_SIDE && e.index == 1);
    /* m x = 1e-400 (underflows), c = 1: the line is 1 + 1e-400, f = 1 below */
    const double x4[2] = {-1, 1e-200}, f4[2] = {2, 1};
    o.lower.m = 1e-200, o.lower.c = 1;
    CHECK(build(x4, f4, 2, &o, &e) == TS_ERR_SIDE && e.index == 1);
    /* a constant line: m x = 0 exactly; f = 1 on y = 1 may touch it
     * (docs/method.md §5.8), an ulp below may not */
    const double f7[2] = {2, 1}, f8[2] = {2, 1 - 0x1p-53};
    o.lower.m = 0, o.lower.c = 1;
    CHECK(build(x2, f7, 2, &o, &e) == TS_OK);
    CHECK(build(x2, f8, 2, &o, &e) == TS_ERR_SIDE && e.index == 1);
    /* x = 0: m x = 0 exactly, on y = x */
    const double f5[2] = {0, 2};
    o.lower.m = 1, o.lower.c = 0;
    CHECK(build(x2, f5, 2, &o, &e) == TS_ERR_SIDE && e.index == 0);
    /* two lines whose values at x = 1e-200 round alike to 1: the upper
     * 1 − 1e-250 (m x formed exactly), the lower 1 + 1e-400 (m x underflows:
     * undecided): TS_ERR_LINES there, right, as the lower one is above; at
     * x = −1e40 they are 1 − 1e-160 and 1 + 1e-10, f between */
    o.shape = TS_SHAPE_BETWEEN;
    o.lower.m = 1e-200, o.lower.c = 1;
    o.upper.m = -1e-50, o.upper.c = 1;
    const double x6[2] = {-1e40, 1e-200}, f6[2] = {1 + 5e-11, 1};
    CHECK(build(x6, f6, 2, &o, &e) == TS_ERR_LINES && e.index == 1);
}

/* Below y = 0.1 x with a point at fl(0.1·5), 2.8e-17 below 0.1·5 (0.1 the
 * double; exact in long double): it passes the data check, its rule gap
 * (the line's rounded value minus f) is 0, so the rule takes no term there,
 * and the certificate cannot decide a gap of 2.8e-17 (the arithmetic mean
 * slope there is the line's, 0.1): TS_ERR_PRECISION next to it. */
static void rule_zero_gap(void)
{
    double x[7], f[7];
    for (int k = 0; k < 7; k++) {
        x[k] = k;
        f[k] = 0.1 * k - 1.0;
    }
    f[5] = 0.1 * 5;
    CHECK((long double)f[5] < (long double)0.1 * 5);
    ts_spline_options o;
    th_options_paper(&o);
    o.shape = TS_SHAPE_BELOW;
    o.upper.m = 0.1;
    o.upper.c = 0;
    ts_error e;
    ts_status st = build(x, f, 7, &o, &e);
    CHECKF(st == TS_ERR_PRECISION && (e.index == 4 || e.index == 5), "%s at %zu", ts_strerror(st),
           e.index);
}

/* Per-interval margins of 1e300 with alpha = DBL_MAX: beta = t would make
 * a overflow, so beta = DBL_MAX − alpha = 0 (src/shape.c, as for one margin). */
static void margins_at_the_top(void)
{
    const double x[3] = {0, 1, 2}, f[3] = {1, 2, 3}, al[2] = {DBL_MAX, DBL_MAX}, t[2] = {1e300, 1e300};
    ts_spline_options o;
    th_options_paper(&o);
    o.shape = TS_SHAPE_POSITIVE;
    o.alphas = al;
    o.n_alphas = 2;
    o.margins = t;
    o.n_margins = 2;
    ts_spline *s = NULL;
    ts_error e;
    ts_status st = ts_spline_new(x, f, 3, &o, &s, &e);
    CHECKF(st == TS_OK, "%s at %zu", ts_strerror(st), e.index);
    for (size_t i = 0; s && i < 2; i++) {
        ts_interval_report r = TS_INTERVAL_REPORT_INIT;
        ts_spline_report(s, i, &r);
        CHECKF(r.beta == 0.0 && r.a == DBL_MAX, "interval %zu: beta %g", i, r.beta);
    }
    ts_spline_free(s);
}

/* Periodic positive data with f_0 = f_n = 0 over several construction
 * blocks (2500 points): the ends are one inner knot, so d_0 = d_n = 0
 * (docs/method.md §5.1), set when the last block is done. */
static void periodic_zero(void)
{
    enum { N = 2500 };
    static double x[N], f[N];
    for (int k = 0; k < N; k++) {
        x[k] = k;
        f[k] = k == 0 || k == N - 1 ? 0.0 : 2.0 + sin(0.01 * k);
    }
    ts_spline_options o;
    th_options_paper(&o);
    o.shape = TS_SHAPE_POSITIVE;
    o.slopes = TS_SLOPES_PERIODIC;
    ts_spline *s = NULL;
    ts_error e;
    ts_status st = ts_spline_new(x, f, N, &o, &s, &e);
    CHECKF(st == TS_OK, "%s at %zu", ts_strerror(st), e.index);
    if (s) {
        const double *d = ts_spline_slopes(s);
        CHECK(d[0] == 0.0 && d[N - 1] == 0.0);
    }
    ts_spline_free(s);
}

/* More than one block (256 intervals) of the paper form's batch
 * certificate: 600 intervals above y = 0.5 x, gaps 1.5 + sin x >= 0.5. */
static void batch_blocks(void)
{
    enum { N = 601 };
    static double x[N], f[N];
    for (int k = 0; k < N; k++) {
        x[k] = 0.1 * k;
        f[k] = 0.5 * x[k] + 1.5 + sin(x[k]);
    }
    ts_spline_options o;
    th_options_paper(&o);
    o.shape = TS_SHAPE_ABOVE;
    o.lower.m = 0.5;
    o.lower.c = 0;
    ts_spline *s = NULL;
    ts_error e;
    ts_status st = ts_spline_new(x, f, N, &o, &s, &e);
    CHECKF(st == TS_OK && ts_spline_certified(s), "%s at %zu", ts_strerror(st), e.index);
    ts_spline_free(s);
}

int main(void)
{
    TH_CASE("root isolation");
    root_isolation();
    TH_CASE("monotone polygon");
    monotone_polygon();
    TH_CASE("huge margin");
    huge_margin();
    TH_CASE("side edges");
    side_edges();
    TH_CASE("rule with a zero gap");
    rule_zero_gap();
    TH_CASE("margins at the top");
    margins_at_the_top();
    TH_CASE("periodic zero ends");
    periodic_zero();
    TH_CASE("batch blocks");
    batch_blocks();
    return th_report("test_cover_cert");
}
