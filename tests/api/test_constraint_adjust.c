/* The slope adjustments of the constraint scheme (docs/method.md §13.2) in
 * configurations random data rarely produce: a scope's one-sided ends, a
 * one-interval scope, a constant bound touched at a scope's first and last
 * knot, intervals forced to be lines (collinear convex data, flat monotone
 * data, a secant on a slope bound) and two forced lines meeting at a knot
 * with different secants (the documented TS_ERR_INFEASIBLE).  Each fit is
 * checked against the header's promises: every report in scope certified
 * with gap >= 0, the property at dense samples, and where a slope or a line
 * is forced, its closed-form value. */
#include "trigspline.h"
#include "th.h"

#include <math.h>
#include <stdio.h>

static ts_status fit(const double *x, const double *f, size_t np, const ts_constraint *c,
                     size_t nc, ts_spline **s)
{
    ts_spline_options o;
    ts_spline_options_init(&o);
    o.constraints = c;
    o.n_constraints = nc;
    *s = NULL;
    return ts_spline_new(x, f, np, &o, s, NULL);
}

/* Every report of record k in scope certified with gap >= 0; the property
 * sampled at 400 points inside each interval in scope.  Tolerance of a sample:
 * 1e-9 of the sampled quantity's scale (the evaluation of S, S', S'' at
 * data of size <= 10 rounds far below it). */
static void check_record(const ts_spline *s, const ts_constraint *c, size_t k)
{
    size_t n = ts_spline_intervals(s);
    const double *x = ts_spline_x(s);
    for (size_t i = 0; i < n; i++) {
        ts_constraint_report r;
        ts_constraint_report_init(&r);
        CHECK(ts_spline_constraint_report(s, k, i, &r) == TS_OK);
        if (!r.in_scope)
            continue;
        CHECKF(r.certified == 1 && r.gap >= 0.0, "record %zu interval %zu: %d %.17g", k, i,
               r.certified, r.gap);
        double worst = HUGE_VAL;
        for (int j = 0; j < 400; j++) {
            /* inside the interval: S'' jumps at knots (GC¹) */
            double xx = x[i] + (x[i + 1] - x[i]) * (j + 0.5) / 400.0;
            double y, dy, d2y, v;
            CHECK(ts_spline_eval_deriv(s, xx, NULL, &y, &dy, &d2y) == TS_OK);
            switch (c->kind) {
            case TS_CONSTRAINT_CONVEX: v = d2y; break;
            case TS_CONSTRAINT_CONCAVE: v = -d2y; break;
            case TS_CONSTRAINT_INCREASING: v = dy; break;
            case TS_CONSTRAINT_DECREASING: v = -dy; break;
            case TS_CONSTRAINT_LOWER: v = y - c->value; break;
            case TS_CONSTRAINT_UPPER: v = c->value - y; break;
            case TS_CONSTRAINT_SLOPE_MIN: v = dy - c->value; break;
            case TS_CONSTRAINT_SLOPE_MAX: v = c->value - dy; break;
            default: v = c->value - fabs(dy); break;
            }
            worst = fmin(worst, v);
        }
        CHECKF(worst >= -1e-9, "record %zu interval %zu: sampled %.17g", k, i, worst);
    }
}

static double slope_at(const ts_spline *s, double x)
{
    double y, dy, d2y;
    CHECK(ts_spline_eval_deriv(s, x, NULL, &y, &dy, &d2y) == TS_OK);
    return dy;
}

/* Convex on points 2..5 only: data outside the scope pull the estimates at
 * its ends to the wrong side of the end secants (point 2: Δ1 = 10 > Δ2 = 1;
 * point 5: Δ5 = −6 < Δ4 = 3), so both are replaced by the one-sided
 * three-point slopes, Δ2 + (Δ2 − Δ3)/2 = 0.5 and Δ4 + (Δ4 − Δ3)/2 = 3.5
 * (unit steps; docs/method.md §13.2).  A second record, convex on interval
 * 3 alone, takes the one-interval scope (its ends already admissible). */
static void test_scope_ends(void)
{
    TH_CASE("convex scope ends");
    double x[7] = {0, 1, 2, 3, 4, 5, 6}, f[7] = {0, -10, 0, 1, 3, 6, 0};
    ts_constraint c[2];
    ts_constraint_init(&c[0], TS_CONSTRAINT_CONVEX);
    c[0].first = 2, c[0].count = 3;
    ts_constraint_init(&c[1], TS_CONSTRAINT_CONVEX);
    c[1].first = 3, c[1].count = 1;
    ts_spline *s;
    CHECK(fit(x, f, 7, c, 2, &s) == TS_OK);
    if (!s)
        return;
    CHECK_CLOSE(slope_at(s, 2.0), 0.5, 1e-12);
    CHECK_CLOSE(slope_at(s, 5.0), 3.5, 1e-12);
    check_record(s, &c[0], 0);
    check_record(s, &c[1], 1);
    ts_spline_free(s);
}

/* A one-interval convex scope whose estimates are inadmissible: both end
 * slopes become the interval's secant, and the interval is then a line
 * (d_i = Δ_i = d_{i+1}): S(x) = f_1 + Δ_1 (x − x_1) on it. */
static void test_one_interval(void)
{
    TH_CASE("convex one interval");
    double x[4] = {0, 1, 2, 3}, f[4] = {0, 3, 4, 10};
    ts_constraint c;
    ts_constraint_init(&c, TS_CONSTRAINT_CONVEX);
    c.first = 1, c.count = 1;
    ts_spline *s;
    CHECK(fit(x, f, 4, &c, 1, &s) == TS_OK);
    if (!s)
        return;
    for (int j = 0; j <= 8; j++) {
        double xx = 1.0 + j / 8.0, y;
        CHECK(ts_spline_eval(s, xx, NULL, &y) == TS_OK);
        CHECK_CLOSE(y, 3.0 + (xx - 1.0), 1e-12);
    }
    check_record(s, &c, 0);
    ts_spline_free(s);
}

/* A constant lower bound touched at the first and the last knot, where the
 * one-sided estimates point out of the region (−1 at x = 0, +0.5 at x = 5):
 * the slope there becomes 0 (docs/method.md §5.1), so S'(0) = S'(5) = 0;
 * the same mirrored for an upper bound. */
static void test_touch_ends(void)
{
    TH_CASE("constant bound touched at the scope's ends");
    double x[6] = {0, 1, 2, 3, 4, 5}, f[6] = {0, 1, 5, 5, 1, 0}, g[6];
    for (int sgn = 0; sgn < 2; sgn++) {
        ts_constraint c;
        ts_constraint_init(&c, sgn ? TS_CONSTRAINT_UPPER : TS_CONSTRAINT_LOWER);
        for (int j = 0; j < 6; j++)
            g[j] = sgn ? -f[j] : f[j];
        ts_spline *s;
        CHECK(fit(x, g, 6, &c, 1, &s) == TS_OK);
        if (!s)
            continue;
        CHECK(slope_at(s, 0.0) == 0.0);
        CHECK(slope_at(s, 5.0) == 0.0);
        check_record(s, &c, 0);
        ts_spline_free(s);
    }
}

/* Collinear convex data on points 0..3: intervals 0..2 must be lines, so
 * S(x) = x there exactly; convexity certified on the rest. */
static void test_forced_lines(void)
{
    TH_CASE("forced lines");
    double x[6] = {0, 1, 2, 3, 4, 5}, f[6] = {0, 1, 2, 3, 5, 8};
    ts_constraint c;
    ts_constraint_init(&c, TS_CONSTRAINT_CONVEX);
    ts_spline *s;
    CHECK(fit(x, f, 6, &c, 1, &s) == TS_OK);
    if (s) {
        for (int j = 0; j <= 30; j++) {
            double xx = j / 10.0, y;
            CHECK(ts_spline_eval(s, xx, NULL, &y) == TS_OK);
            CHECK_CLOSE(y, xx, 1e-12);
        }
        check_record(s, &c, 0);
        ts_spline_free(s);
    }
    /* increasing with a flat interval: S = 1 on [1, 2] */
    double h[5] = {0, 1, 1, 2, 4};
    ts_constraint_init(&c, TS_CONSTRAINT_INCREASING);
    CHECK(fit(x, h, 5, &c, 1, &s) == TS_OK);
    if (s) {
        for (int j = 0; j <= 10; j++) {
            double y;
            CHECK(ts_spline_eval(s, 1.0 + j / 10.0, NULL, &y) == TS_OK);
            CHECK_CLOSE(y, 1.0, 1e-12);
        }
        check_record(s, &c, 0);
        ts_spline_free(s);
    }
    /* a secant on a slope bound: the flat interval 1 of decreasing data under
     * a maximum slope 0, and of increasing data over a minimum slope 0, is
     * a line, S = 2 on [1, 2] (a bound 0 keeps the polygon test exact:
     * a bound L != 0 with the secant L fails it by the control values'
     * rounding, TS_ERR_UNPROVEN) */
    double q[2][4] = {{3, 2, 2, 1}, {1, 2, 2, 3}};
    for (int sm = 0; sm < 2; sm++) {
        ts_constraint_init(&c, sm ? TS_CONSTRAINT_SLOPE_MIN : TS_CONSTRAINT_SLOPE_MAX);
        CHECK(fit(x, q[sm], 4, &c, 1, &s) == TS_OK);
        if (!s)
            continue;
        for (int j = 0; j <= 10; j++) {
            double y;
            CHECK(ts_spline_eval(s, 1.0 + j / 10.0, NULL, &y) == TS_OK);
            CHECK_CLOSE(y, 2.0, 1e-12);
        }
        check_record(s, &c, 0);
        ts_spline_free(s);
    }
}

/* Two forced lines with different secants meeting at knot 1 (slope at
 * most 1 on interval 0 whose secant is 1, at least 2 on interval 1 whose
 * secant is 2): no C¹ curve exists, TS_ERR_INFEASIBLE, slope conflict at
 * point 1 (from either side: the records in both orders). */
static void test_conflict(void)
{
    TH_CASE("forced lines conflict");
    double x[3] = {0, 1, 2}, f[3] = {0, 1, 3};
    ts_constraint c[2];
    ts_constraint_init(&c[0], TS_CONSTRAINT_SLOPE_MAX);
    c[0].value = 1.0, c[0].first = 0, c[0].count = 1;
    ts_constraint_init(&c[1], TS_CONSTRAINT_SLOPE_MIN);
    c[1].value = 2.0, c[1].first = 1, c[1].count = 1;
    for (int order = 0; order < 2; order++) {
        ts_constraint cc[2] = {c[order], c[1 - order]};
        ts_spline_options o;
        ts_spline_options_init(&o);
        o.constraints = cc;
        o.n_constraints = 2;
        ts_spline *s = NULL;
        CHECK(ts_spline_new(x, f, 3, &o, &s, NULL) == TS_ERR_INFEASIBLE && s == NULL);
        ts_constraint_failure fl;
        ts_constraint_failure_init(&fl);
        CHECK(ts_constraints_diagnose(x, f, 3, &o, &fl) == TS_ERR_INFEASIBLE);
        CHECK(fl.condition == TS_CONDITION_SLOPE_CONFLICT && fl.index == 1 &&
              fl.where == TS_WHERE_POINT && fl.constraint == TS_NO_INDEX);
    }
}

static ts_status fit_user(const double *x, const double *f, const double *d, size_t np,
                          const ts_constraint *c, size_t nc, ts_spline **s)
{
    ts_spline_options o;
    ts_spline_options_init(&o);
    o.constraints = c;
    o.n_constraints = nc;
    o.slopes = TS_SLOPES_USER;
    o.user_slopes = d;
    o.n_user_slopes = np;
    *s = NULL;
    return ts_spline_new(x, f, np, &o, s, NULL);
}

/* Caller's slopes (TS_SLOPES_USER) that break the records, so that each
 * adjustment of §13.2 is taken with a known result (unit steps):
 * convex data with slopes 0 get the three-point means (Δ_{j−1} + Δ_j)/2
 * inside and Δ_3 + (Δ_3 − Δ_2)/2 = 4.5 at the right end (0 < Δ_0 stays);
 * a slope between two equal secants stays if it is exactly them, else
 * becomes them; a touched
 * lower bound with slopes pointing out at both ends gets 0 there, and a
 * touched upper bound the same mirrored; a slope beyond a slope bound is
 * clamped onto it. */
static void test_user_slopes(void)
{
    TH_CASE("caller's slopes adjusted");
    double x[5] = {0, 1, 2, 3, 4}, f[5] = {0, 1, 3, 6, 10}, z[5] = {0};
    ts_constraint c;
    ts_spline *s;
    ts_constraint_init(&c, TS_CONSTRAINT_CONVEX);
    CHECK(fit_user(x, f, z, 5, &c, 1, &s) == TS_OK);
    if (s) {
        double want[5] = {0, 1.5, 2.5, 3.5, 4.5};
        for (int j = 0; j < 5; j++)
            CHECK_CLOSE(slope_at(s, j == 4 ? 4.0 : x[j]), want[j], 1e-12);
        check_record(s, &c, 0);
        ts_spline_free(s);
    }
    /* equal secants (a line through points 0..2) and slopes exactly them,
     * then a slope 1.5 between them, replaced by their mean 1 */
    double g[5] = {0, 1, 2, 4, 7}, dg[5] = {1, 1, 1, 2.5, 3.5};
    for (int v = 0; v < 2; v++) {
        dg[1] = v ? 1.5 : 1.0;
        CHECK(fit_user(x, g, dg, 5, &c, 1, &s) == TS_OK);
        if (!s)
            continue;
        for (int j = 0; j <= 20; j++) {
            double xx = j / 10.0, y;
            CHECK(ts_spline_eval(s, xx, NULL, &y) == TS_OK);
            CHECK_CLOSE(y, xx, 1e-12);
        }
        check_record(s, &c, 0);
        ts_spline_free(s);
    }
    /* touched bounds: slopes pointing out at both ends, and inside */
    double t[5] = {0, 1, 0, 1, 0}, dt[5] = {-1, 0.5, 2, -0.5, 1}, tn[5], dn[5];
    for (int sgn = 0; sgn < 2; sgn++) {
        ts_constraint_init(&c, sgn ? TS_CONSTRAINT_UPPER : TS_CONSTRAINT_LOWER);
        for (int j = 0; j < 5; j++)
            tn[j] = sgn ? -t[j] : t[j], dn[j] = sgn ? -dt[j] : dt[j];
        CHECK(fit_user(x, tn, dn, 5, &c, 1, &s) == TS_OK);
        if (!s)
            continue;
        CHECK(slope_at(s, 0.0) == 0.0 && slope_at(s, 2.0) == 0.0 && slope_at(s, 4.0) == 0.0);
        CHECK(slope_at(s, 1.0) == dn[1] && slope_at(s, 3.0) == dn[3]);
        check_record(s, &c, 0);
        ts_spline_free(s);
    }
    /* slopes beyond |S'| <= 3 clamped onto ±3 (the secants are inside) */
    double q[5] = {0, 2, 3, 2, 0}, dq[5] = {5, 1, 0, -1, -7};
    ts_constraint_init(&c, TS_CONSTRAINT_SLOPE_ABS);
    c.value = 3.0;
    CHECK(fit_user(x, q, dq, 5, &c, 1, &s) == TS_OK);
    if (s) {
        /* the derivative at a knot evaluated from the control values: 1e-12 */
        CHECK_CLOSE(slope_at(s, 0.0), 3.0, 1e-12);
        CHECK_CLOSE(slope_at(s, 4.0), -3.0, 1e-12);
        check_record(s, &c, 0);
        ts_spline_free(s);
    }
}

int main(void)
{
    test_scope_ends();
    test_one_interval();
    test_touch_ends();
    test_forced_lines();
    test_conflict();
    test_user_slopes();
    return th_report("test_constraint_adjust");
}
