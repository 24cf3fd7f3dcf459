/* The range and overshoot fields of the report (docs/method.md §5.9) against
 * independent dense sampling: every form, shape schemes and none, ts_spline_certify,
 * curve coordinates; the reset of the fields on failure.
 *
 * Oracle: the segment S(θ) = Σ A_l(θ) B_l sampled at N+1 equally spaced θ in
 * [0, π/2] with the tests' own basis (tests/common/th_basis.h, plain sin/cos),
 * from the control values B of the report.  Over an interval the curve takes
 * exactly the values of S(θ), θ in [0, π/2], in every form (in the geometric
 * form x = X(θ) runs from x0 to x1), so the range of the samples brackets
 * the exact range from inside.  Tolerances:
 *   te = 64 ε·max|B|: rounding of the report's value (trigmin.c's guard is
 *        16 ε·max|C| plus the subdivision term, a few ε·max|C|) and of
 *        the test's basis (a few ulp of 1 per A_l, times max|B|);
 *   ts = ½ g2 (Δ/2)², Δ = (π/2)/N: at an interior extremum S' = 0, so the
 *        nearest sample is within ½ max|S''| (Δ/2)² of it; g2 = 8|B1−B0| +
 *        8|B2−B0| + 6|B3−B0| bounds |S''| (max|A_l''| = 6, 8, 8, 6 on
 *        [0, π/2] and Σ A_l'' = 0).
 * Checks: exact min in [sampled min − ts − te, sampled min + te] (likewise
 * max); S(at_y_min) from ts_spline_eval within te + the evaluator's rounding of
 * y_min; the excursions from the sampled range and the end values. */
#include "common/th_basis.h"
#include "th.h"
#include "trigspline.h"

#include <float.h>
#include <math.h>
#include <stddef.h>
#include <stdio.h>

#define N_SAMPLES 20000

static double maxabs4(const double B[4])
{
    double m = 0.0;
    for (int l = 0; l < 4; l++)
        m = fabs(B[l]) > m ? fabs(B[l]) : m;
    return m;
}

/* Sampled range of Σ A_l B_l over θ in [0, π/2]. */
static void sampled_range(const double B[4], double *lo, double *hi)
{
    *lo = (double)INFINITY;
    *hi = -(double)INFINITY;
    for (int j = 0; j <= N_SAMPLES; j++) {
        double A[4], th = TH_HALF_PI * j / N_SAMPLES;
        th_basis(th, A);
        double y = A[0] * B[0] + A[1] * B[1] + A[2] * B[2] + A[3] * B[3];
        if (j == 0)
            y = B[0]; /* the basis at the ends: A = (1,0,0,0), (0,0,0,1) */
        if (j == N_SAMPLES)
            y = B[3];
        *lo = y < *lo ? y : *lo;
        *hi = y > *hi ? y : *hi;
    }
}

/* One report against sampling of its B; spl (may be NULL): check S(at). */
static void check_report(const ts_interval_report *r, const ts_spline *spl, const char *what,
                         size_t i)
{
    double lo, hi, sc = maxabs4(r->B), d = TH_HALF_PI / N_SAMPLES;
    double te = 64.0 * DBL_EPSILON * (sc > 0.0 ? sc : 1.0);
    double g2 = 8.0 * fabs(r->B[1] - r->B[0]) + 8.0 * fabs(r->B[2] - r->B[0]) +
                6.0 * fabs(r->B[3] - r->B[0]);
    double ts = 0.5 * g2 * (d / 2) * (d / 2);
    sampled_range(r->B, &lo, &hi);
    CHECKF(r->y_min <= lo + te && r->y_min >= lo - ts - te,
           "%s interval %zu: y_min %.17g, sampled %.17g (ts %.3g)", what, i, r->y_min, lo, ts);
    CHECKF(r->y_max >= hi - te && r->y_max <= hi + ts + te,
           "%s interval %zu: y_max %.17g, sampled %.17g (ts %.3g)", what, i, r->y_max, hi, ts);
    double top = r->B[0] > r->B[3] ? r->B[0] : r->B[3], bot = r->B[0] < r->B[3] ? r->B[0] : r->B[3];
    double ea = hi - top > 0.0 ? hi - top : 0.0, eb = bot - lo > 0.0 ? bot - lo : 0.0;
    CHECKF(r->excursion_above >= 0.0 && fabs(r->excursion_above - ea) <= ts + 2 * te,
           "%s interval %zu: excursion_above %.17g, sampled %.17g", what, i, r->excursion_above, ea);
    CHECKF(r->excursion_below >= 0.0 && fabs(r->excursion_below - eb) <= ts + 2 * te,
           "%s interval %zu: excursion_below %.17g, sampled %.17g", what, i, r->excursion_below, eb);
    CHECKF(r->at_y_min >= r->x0 && r->at_y_min <= r->x1 && r->at_y_max >= r->x0 &&
               r->at_y_max <= r->x1,
           "%s interval %zu: places outside [x0, x1]", what, i);
    if (spl) {
        /* the evaluator at the reported place: its rounding (a few ulp of
         * max|B|) plus the slope times the rounding of the place itself */
        double y0, y1, tol = 64.0 * te + 1e-9 * sc;
        CHECK(ts_spline_eval(spl, r->at_y_min, NULL, &y0) == TS_OK);
        CHECK(ts_spline_eval(spl, r->at_y_max, NULL, &y1) == TS_OK);
        CHECKF(fabs(y0 - r->y_min) <= tol, "%s interval %zu: S(at_y_min) %.17g vs %.17g", what, i,
               y0, r->y_min);
        CHECKF(fabs(y1 - r->y_max) <= tol, "%s interval %zu: S(at_y_max) %.17g vs %.17g", what, i,
               y1, r->y_max);
    }
}

static ts_spline *build(const double *x, const double *f, size_t np, ts_form form, ts_shape shape,
                        double alpha)
{
    ts_spline_options o;
    ts_spline_options_init(&o);
    o.form = form;
    o.shape = shape;
    o.alpha = alpha;
    o.lower.m = 0.0, o.lower.c = 0.0;
    o.upper.m = 0.0, o.upper.c = 100.0;
    ts_spline *s = NULL;
    ts_error e;
    ts_status st = ts_spline_new(x, f, np, &o, &s, &e);
    CHECKF(st == TS_OK, "build failed: %s", ts_strerror(st));
    return s;
}

/* Rainfall-like data with zeros and a spike, a percentage touching 0 and 100. */
static const double XR[] = {0, 1, 2, 3, 4, 5, 6, 7, 8, 9, 10, 11};
static const double FR[] = {0, 0, 3.2, 25, 0.4, 0, 0, 7.5, 1.1, 0, 12, 0};
static const double XP[] = {0, 1, 3, 4, 6, 7, 9, 10};
static const double FP[] = {0, 2, 60, 100, 100, 97, 15, 0};
/* the paper's Table 2 data (docs/method.md §10): the plain spline overshoots */
static const double X2[] = {1, 2, 3, 9, 12, 14, 15};
static const double F2[] = {0.5, 3, 5, 25, 8, 2, 1};

static void spline_cases(void)
{
    const ts_form forms[] = {TS_FORM_PAPER, TS_FORM_C1, TS_FORM_GEOMETRIC};
    const char *fname[] = {"paper", "c1", "geometric"};
    /* the geometric form needs a >= 4/(3π) without a scheme (docs/method.md §4) */
    const double alphas[] = {0.1, 1.0, 10.0}, alphas_geo[] = {0.5, 1.0, 10.0};
    TH_CASE("spline reports");
    for (int k = 0; k < 3; k++) {
        for (int ai = 0; ai < 3; ai++) {
            struct {
                const double *x, *f;
                size_t n;
                ts_shape shape;
                const char *name;
            } cases[] = {
                {XR, FR, sizeof XR / sizeof *XR, TS_SHAPE_NONE, "rain none"},
                {XR, FR, sizeof XR / sizeof *XR, TS_SHAPE_POSITIVE, "rain positive"},
                {XP, FP, sizeof XP / sizeof *XP, TS_SHAPE_NONE, "percent none"},
                {X2, F2, sizeof X2 / sizeof *X2, TS_SHAPE_NONE, "table2 none"},
                {X2, F2, sizeof X2 / sizeof *X2, TS_SHAPE_POSITIVE, "table2 positive"},
            };
            for (size_t c = 0; c < sizeof cases / sizeof *cases; c++) {
                char what[96];
                snprintf(what, sizeof what, "%s %s alpha index %d", cases[c].name, fname[k], ai);
                double alpha = forms[k] == TS_FORM_GEOMETRIC ? alphas_geo[ai] : alphas[ai];
                ts_spline *s = build(cases[c].x, cases[c].f, cases[c].n, forms[k], cases[c].shape,
                                     alpha);
                if (!s)
                    continue;
                for (size_t i = 0; i < ts_spline_intervals(s); i++) {
                    ts_interval_report r;
                    CHECK(ts_spline_report(s, i, &r) == TS_OK);
                    check_report(&r, s, what, i);
                }
                /* ts_spline_certify fills the same fields */
                ts_interval_report reps[16];
                ts_line zero = {0.0, -1000.0};
                (void)ts_spline_certify(s, &zero, NULL, reps, NULL);
                for (size_t i = 0; i < ts_spline_intervals(s); i++) {
                    ts_interval_report r;
                    (void)ts_spline_report(s, i, &r);
                    CHECK(reps[i].y_min == r.y_min && reps[i].y_max == r.y_max &&
                          reps[i].excursion_above == r.excursion_above &&
                          reps[i].excursion_below == r.excursion_below);
                }
                ts_spline_free(s);
            }
        }
    }
}

/* The paper's Table 2 spline with alpha = beta = 0 in the paper form (plain
 * spline, TS_SHAPE_NONE): interval 3 [9, 12] overshoots 25, and at a knot where
 * the curve has its extreme the excursion is exactly 0. */
static void known_overshoot(void)
{
    TH_CASE("known overshoot");
    ts_spline *s = build(X2, F2, sizeof X2 / sizeof *X2, TS_FORM_PAPER, TS_SHAPE_NONE, 0.1);
    if (!s)
        return;
    double worst = 0.0;
    for (size_t i = 0; i < ts_spline_intervals(s); i++) {
        ts_interval_report r;
        (void)ts_spline_report(s, i, &r);
        worst = r.excursion_above > worst ? r.excursion_above : worst;
        /* an interval whose range is its ends has excursions exactly 0 */
        if (r.y_max == (r.B[0] > r.B[3] ? r.B[0] : r.B[3]))
            CHECK(r.excursion_above == 0.0);
    }
    CHECKF(worst > 1.0, "alpha 0.1 on Table 2 should overshoot (worst %g)", worst);
    ts_spline_free(s);
}

static void curve_cases(void)
{
    TH_CASE("curve reports");
    /* a closed outline in a box [0, 10] x [0, 6], points near the sides */
    const double P[] = {0.2, 3, 2, 0.3, 8, 0.2, 9.8, 3, 8, 5.7, 2, 5.8};
    ts_curve_options o;
    ts_curve_options_init(&o);
    o.closed = 1;
    o.alpha = 0.3;
    ts_curve *c = NULL;
    ts_error e;
    CHECK(ts_curve_new(P, 6, 2, &o, &c, &e) == TS_OK);
    if (!c)
        return;
    size_t n = ts_curve_segments(c);
    ts_interval_report reps[32];
    int lo_on[3] = {1, 1, 0}, hi_on[3] = {1, 1, 0};
    double lo[3] = {0, 0, 0}, hi[3] = {10, 6, 0};
    (void)ts_curve_certify_box(c, lo_on, lo, hi_on, hi, reps, &e);
    for (size_t j = 0; j < n * 2; j++)
        check_report(&reps[j], NULL, "closed curve", j);
    ts_curve_free(c);
}

static void resets(void)
{
    TH_CASE("resets");
    ts_interval_report r;
    r.y_min = r.y_max = r.at_y_min = r.at_y_max = r.excursion_above = r.excursion_below = 1.0;
    CHECK(ts_spline_report(NULL, 0, &r) == TS_ERR_NULL);
    CHECK(isnan(r.y_min) && isnan(r.y_max) && isnan(r.at_y_min) && isnan(r.at_y_max) &&
          isnan(r.excursion_above) && isnan(r.excursion_below));
    ts_spline *s = build(XR, FR, sizeof XR / sizeof *XR, TS_FORM_PAPER, TS_SHAPE_POSITIVE, 1.0);
    r.y_min = 1.0;
    CHECK(ts_spline_report(s, 99, &r) == TS_ERR_INDEX);
    CHECK(isnan(r.y_min) && isnan(r.excursion_above));
    ts_interval_report reps[16];
    for (int j = 0; j < 16; j++)
        reps[j].y_max = 1.0;
    CHECK(ts_spline_certify(s, NULL, NULL, reps, NULL) == TS_ERR_NULL);
    CHECK(isnan(reps[0].y_max) && isnan(reps[10].excursion_below));
    ts_spline_free(s);
}

int main(void)
{
    spline_cases();
    known_overshoot();
    curve_cases();
    resets();
    return th_report("test_overshoot");
}
