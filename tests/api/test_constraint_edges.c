/* Constraint records (docs/method.md §13) on inputs at the edges of the
 * scheme's arithmetic and of its rules: fields a record's kind does not
 * read, slope rules that contradict each other at a knot, forced lines
 * next to equal secants, closed forms whose requirement overflows, slope
 * bounds beyond the exact products' range, widths whose h κ underflows,
 * bound splines whose sums overflow, with knots far from 0, or shorter
 * than the data.  Each expectation is a closed form or the header's rule
 * (include/trigspline.h, "Failures of ts_spline_new with constraints");
 * a fit that succeeds has every report certified and is checked against
 * its bound at sample points. */
#include "trigspline.h"
#include "th.h"

#include <float.h>
#include <math.h>
#include <stdio.h>
#include <string.h>

static const double *user_d; /* slopes for the next fit (TS_SLOPES_USER), or NULL */

static ts_status fit(const double *x, const double *f, size_t np, const ts_constraint *c,
                     size_t nc, double alpha, double margin, ts_spline **out)
{
    ts_spline_options o;
    ts_spline_options_init(&o);
    if (user_d) {
        o.slopes = TS_SLOPES_USER;
        o.user_slopes = user_d;
        o.n_user_slopes = np;
        user_d = NULL;
    }
    o.constraints = c;
    o.n_constraints = nc;
    if (alpha > 0.0)
        o.alpha = alpha;
    if (margin > 0.0)
        o.margin = margin;
    ts_spline *s = NULL;
    ts_status st = ts_spline_new(x, f, np, &o, &s, NULL);
    CHECK((st == TS_OK) == (s != NULL));
    if (out)
        *out = s;
    else
        ts_spline_free(s);
    return st;
}

/* every report of record k in scope certified with gap >= 0 */
static void certified(const ts_spline *s, size_t k)
{
    for (size_t i = 0; i < ts_spline_intervals(s); i++) {
        ts_constraint_report r;
        ts_constraint_report_init(&r);
        CHECK(ts_spline_constraint_report(s, k, i, &r) == TS_OK);
        if (r.in_scope)
            CHECKF(r.certified == 1 && r.gap >= 0.0, "record %zu interval %zu: %d %g", k, i,
                   r.certified, r.gap);
    }
}

/* The bound field of a record that is not a lower or upper bound is not
 * read (the header: "A bound (lower, upper) is ..."): a convex record
 * naming a polyline or a spline gives the constant-bound record's spline,
 * bit for bit. */
static void unread_bound_fields(void)
{
    TH_CASE("bound fields of other kinds");
    double x[5] = {0, 1, 2, 3, 4}, f[5] = {4, 1, 0, 1, 4}, px[2] = {0, 4}, py[2] = {9, 9};
    ts_spline *b = NULL, *s[3] = {NULL, NULL, NULL};
    ts_spline_options o;
    ts_spline_options_init(&o);
    CHECK(ts_spline_new(x, f, 5, &o, &b, NULL) == TS_OK);
    for (int v = 0; v < 3; v++) {
        ts_constraint c;
        ts_constraint_init(&c, TS_CONSTRAINT_CONVEX);
        c.bound = v == 0 ? TS_BOUND_CONSTANT : v == 1 ? TS_BOUND_POLYLINE : TS_BOUND_SPLINE;
        c.px = px, c.py = py, c.n_poly = 2, c.spline = b;
        CHECK(fit(x, f, 5, &c, 1, 0.0, 0.0, &s[v]) == TS_OK);
    }
    ts_spline_free(b);
    for (int v = 1; v < 3; v++) {
        if (!s[0] || !s[v])
            continue;
        for (int j = 0; j <= 400; j++) {
            double xx = 4.0 * j / 400, y0, y1;
            CHECK(ts_spline_eval(s[0], xx, NULL, &y0) == TS_OK);
            CHECK(ts_spline_eval(s[v], xx, NULL, &y1) == TS_OK);
            CHECK(memcmp(&y0, &y1, sizeof y0) == 0);
        }
        for (size_t i = 0; i < 4; i++) {
            ts_constraint_report r0, r1;
            ts_constraint_report_init(&r0);
            ts_constraint_report_init(&r1);
            CHECK(ts_spline_constraint_report(s[0], 0, i, &r0) == TS_OK);
            CHECK(ts_spline_constraint_report(s[v], 0, i, &r1) == TS_OK);
            CHECK(r0.certified == 1 && r1.certified == 1 && r0.gap == r1.gap && r0.at == r1.at);
        }
    }
    for (int v = 0; v < 3; v++)
        ts_spline_free(s[v]);
}

/* Build with records c and expect status want, condition cond at point j
 * naming record k (ts_constraints_diagnose and the ts_error), and, when
 * said is not NULL, that text in ts_error_message's sentence. */
static void refused(const double *x, const double *f, size_t np, const ts_constraint *c,
                    size_t nc, ts_status want, ts_condition cond, size_t k, size_t j,
                    const char *said)
{
    ts_spline_options o;
    ts_spline_options_init(&o);
    o.constraints = c;
    o.n_constraints = nc;
    ts_spline *s = NULL;
    ts_error e;
    ts_status st = ts_spline_new(x, f, np, &o, &s, &e);
    CHECKF(st == want && s == NULL, "%s", ts_status_name(st));
    CHECK(e.index == j && e.where == TS_WHERE_POINT);
    ts_spline_free(s);
    ts_constraint_failure fl;
    ts_constraint_failure_init(&fl);
    CHECK(ts_constraints_diagnose(x, f, np, &o, &fl) == want);
    CHECKF(fl.condition == cond && fl.constraint == k && fl.index == j &&
               fl.where == TS_WHERE_POINT,
           "condition %d record %zu index %zu", (int)fl.condition, fl.constraint, fl.index);
    if (said) {
        ts_error_context ctx;
        ts_error_context_init(&ctx);
        ctx.x = x, ctx.f = f, ctx.n_points = np, ctx.spline_options = &o;
        char buf[512];
        (void)ts_error_message(&e, &ctx, buf, sizeof buf);
        CHECKF(strcmp(buf, said) == 0, "\n   got  \"%s\"\n   want \"%s\"", buf, said);
    }
}

/* Convex on [0, 2] needs S'(2) >= Δ_1 = 2 (S' non-decreasing with mean
 * Δ_1 on [1, 2]); S' <= 1.5 on [2, 3] needs S'(2) <= 1.5: no C¹ curve meets
 * both, refused as a condition on the data (docs/method.md §13.1,
 * curvature-slope; the secants are exact, so the sentence's numbers are).
 * A constant bound touched at x_2 (S <= 3 right of x_2 with S(2) = 3: S'(2)
 * <= 0), a polyline touched there (slope 1 right of it), and the mirror
 * (concave right of a knot: S'(x_1) >= Δ_1 = 2 against S' <= 1.5) likewise.
 * A bound equal to the secant (S' <= 2) is no contradiction (the interval
 * a line), one ulp below it is. */
static void contradicting_slopes(void)
{
    TH_CASE("convex next to a slope bound below its secant");
    double x[4] = {0, 1, 2, 3}, f[4] = {0, 1, 3, 4};
    ts_constraint c[2];
    ts_constraint_init(&c[0], TS_CONSTRAINT_CONVEX);
    c[0].count = 2;
    ts_constraint_init(&c[1], TS_CONSTRAINT_SLOPE_MAX);
    c[1].value = 1.5, c[1].first = 2, c[1].count = 1;
    refused(x, f, 4, c, 2, TS_ERR_CONDITION, TS_CONDITION_CURVATURE_SLOPE, 1, 2,
            "point 2 (x = 2, f = 3): constraint 0 (convex) needs a slope here of at least the "
            "secant 2 of the interval before it, but the slope-max constraint allows at most "
            "1.5 there: no curve with a continuous slope meets both (constraint 1, slope-max)");
    c[1].value = nextafter(2.0, 0.0);
    refused(x, f, 4, c, 2, TS_ERR_CONDITION, TS_CONDITION_CURVATURE_SLOPE, 1, 2, NULL);
    c[1].value = 2.0;
    ts_spline *s = NULL;
    ts_status st = fit(x, f, 4, c, 2, 0.0, 0.0, &s);
    CHECKF(st == TS_OK || st == TS_ERR_UNPROVEN, "%s", ts_status_name(st));
    ts_spline_free(s);

    TH_CASE("convex next to a touched constant bound");
    double f2[4] = {0, 1, 3, 2};
    ts_constraint_init(&c[1], TS_CONSTRAINT_UPPER);
    c[1].value = 3.0, c[1].first = 2, c[1].count = 1;
    refused(x, f2, 4, c, 2, TS_ERR_CONDITION, TS_CONDITION_CURVATURE_SLOPE, 1, 2,
            "point 2 (x = 2, f = 3): constraint 0 (convex) needs a slope here of at least the "
            "secant 2 of the interval before it, but the upper constraint allows at most 0 "
            "there: no curve with a continuous slope meets both (constraint 1, upper)");
    c[1].value = 3.5; /* not touched: S'(2) free */
    st = fit(x, f2, 4, c, 2, 0.0, 0.0, &s);
    CHECKF(st == TS_OK, "%s", ts_status_name(st));
    if (s)
        certified(s, 0), certified(s, 1);
    ts_spline_free(s);

    TH_CASE("convex next to a touched polyline");
    double px[3] = {1, 2, 3}, py[3] = {2, 3, 4}, f3[4] = {0, 1, 3, 3.5};
    c[1].bound = TS_BOUND_POLYLINE, c[1].px = px, c[1].py = py, c[1].n_poly = 3;
    refused(x, f3, 4, c, 2, TS_ERR_CONDITION, TS_CONDITION_CURVATURE_SLOPE, 1, 2,
            "point 2 (x = 2, f = 3): constraint 0 (convex) needs a slope here of at least the "
            "secant 2 of the interval before it, but the upper constraint allows at most 1 "
            "there: no curve with a continuous slope meets both (constraint 1, upper)");

    TH_CASE("convex right of a slope floor above its secant");
    /* convex on [2, 3] needs S'(2) <= Δ_2 = 0.5; S' >= 0.8 on [1, 2] (secant 1
     * there) needs S'(2) >= 0.8 */
    double f4[4] = {0, 1, 2, 2.5};
    ts_constraint_init(&c[0], TS_CONSTRAINT_CONVEX);
    c[0].first = 2, c[0].count = 1;
    ts_constraint_init(&c[1], TS_CONSTRAINT_SLOPE_MIN);
    c[1].value = 0.8, c[1].first = 1, c[1].count = 1;
    refused(x, f4, 4, c, 2, TS_ERR_CONDITION, TS_CONDITION_CURVATURE_SLOPE, 1, 2,
            "point 2 (x = 2, f = 2): constraint 0 (convex) needs a slope here of at most the "
            "secant 0.5 of the interval after it, but the slope-min constraint allows at least "
            "0.8 there: no curve with a continuous slope meets both (constraint 1, slope-min)");

    TH_CASE("concave right of a slope bound below its secant");
    double g[4] = {0, 0, 2, 3};
    ts_constraint_init(&c[0], TS_CONSTRAINT_CONCAVE);
    c[0].first = 1, c[0].count = 2;
    ts_constraint_init(&c[1], TS_CONSTRAINT_SLOPE_MAX);
    c[1].value = 1.5, c[1].count = 1;
    refused(x, g, 4, c, 2, TS_ERR_CONDITION, TS_CONDITION_CURVATURE_SLOPE, 1, 1,
            "point 1 (x = 1, f = 0): constraint 0 (concave) needs a slope here of at least the "
            "secant 2 of the interval after it, but the slope-max constraint allows at most "
            "1.5 there: no curve with a continuous slope meets both (constraint 1, slope-max)");

    TH_CASE("two slope bounds excluding each other at a knot");
    /* S' >= 1.5 on [0, 1], |S'| <= 1 on [1, 2]: S'(1) in [1.5, inf) and
     * [-1, 1] (the secants 2 and 0 meet their own bounds) */
    double y[3] = {0, 2, 2};
    ts_constraint_init(&c[0], TS_CONSTRAINT_SLOPE_MIN);
    c[0].value = 1.5, c[0].count = 1;
    ts_constraint_init(&c[1], TS_CONSTRAINT_SLOPE_ABS);
    c[1].value = 1.0, c[1].first = 1, c[1].count = 1;
    refused(x, y, 3, c, 2, TS_ERR_INFEASIBLE, TS_CONDITION_SLOPE_CONFLICT, TS_NO_INDEX, 1,
            NULL);
    c[0].value = 1.0; /* S'(1) = 1 meets both */
    st = fit(x, y, 3, c, 2, 0.0, 0.0, &s);
    CHECKF(st == TS_OK || st == TS_ERR_UNPROVEN, "%s", ts_status_name(st));
    ts_spline_free(s);
}

/* S' <= 2 on [x_0, x_2], S' >= 0 on [x_1, x_2], the secant of interval 1
 * 2 (1 − 2^-52)/(1 + 2^-53 ...) a few ulps below the bound: the closed form
 * raises a_1 until κ h d_1 falls below half an ulp of f_1 = 3, where B1
 * = f_1 would break the tangent at x_1 (left S' ≈ 1.5, right 2 in
 * floating point).  The search must not accept that (docs/method.md
 * §13.4): refused as unproven (the header's rule for a secant on its
 * bound), or a curve whose slope is continuous at x_1 (one-sided
 * derivatives one ulp of x away agree to 1e-6: a C¹ curve's S' moves by
 * |S''| 2^-52 there). */
static void no_tangent_break(void)
{
    TH_CASE("a control value rounded onto its knot");
    double x[3] = {0, 1.0009752911796965, 2.0009752911796967}, f[3] = {2, 3, 5};
    ts_constraint c[2];
    ts_constraint_init(&c[0], TS_CONSTRAINT_SLOPE_MIN);
    c[0].value = 0.0, c[0].first = 1, c[0].count = 1;
    ts_constraint_init(&c[1], TS_CONSTRAINT_SLOPE_MAX);
    c[1].value = 2.0, c[1].count = 2;
    ts_spline *s = NULL;
    ts_status st = fit(x, f, 3, c, 2, 0.0, 0.0, &s);
    CHECKF(st == TS_OK || st == TS_ERR_UNPROVEN, "%s", ts_status_name(st));
    if (s) {
        double y, dl, dr, d2;
        CHECK(ts_spline_eval_deriv(s, nextafter(x[1], 0.0), NULL, &y, &dl, &d2) == TS_OK);
        CHECK(ts_spline_eval_deriv(s, nextafter(x[1], 3.0), NULL, &y, &dr, &d2) == TS_OK);
        CHECKF(fabs(dl - dr) <= 1e-6, "S' %.17g left, %.17g right of x_1", dl, dr);
    }
    ts_spline_free(s);
}

/* f = 0, 0, 0, 1: interval 0 must be the line 0 (its secant on the bound
 * S' <= 0), so S'(1) = 0; convex on [1, 3] with S'(1) = 0 and S(2) = S(1)
 * forces S = 0 on [1, 2] too.  The forced line of interval 0 meets a
 * neighbour with the same secant (0) whose slope (the one-sided convex
 * estimate, −0.5) differs: no conflict. */
static void equal_neighbour_secant(void)
{
    TH_CASE("forced line next to an equal secant");
    double x[4] = {0, 1, 2, 3}, f[4] = {0, 0, 0, 1};
    ts_constraint c[2];
    ts_constraint_init(&c[0], TS_CONSTRAINT_CONVEX);
    c[0].first = 1, c[0].count = 2;
    ts_constraint_init(&c[1], TS_CONSTRAINT_SLOPE_MAX);
    c[1].value = 0.0, c[1].count = 1;
    ts_spline *s = NULL;
    CHECK(fit(x, f, 4, c, 2, 0.0, 0.0, &s) == TS_OK);
    if (!s)
        return;
    for (int j = 0; j <= 200; j++) {
        double y;
        CHECK(ts_spline_eval(s, 2.0 * j / 200, NULL, &y) == TS_OK);
        CHECKF(y == 0.0, "S(%g) = %g", 2.0 * j / 200, y);
    }
    certified(s, 0);
    certified(s, 1);
    ts_spline_free(s);
}

/* A point 2^-1074 above a lower bound 0 next to a slope of about 0.5: the
 * closed form K3 h d / g overflows (§13.3) and a_i is held at 1e300.  The
 * fit is certified (S >= 0 at every sample: the exact side of a double). */
static void overflowing_need(void)
{
    TH_CASE("closed form beyond 1e300");
    double x[3] = {0, 1, 2}, f[3] = {1, 0x1p-1074, 2};
    ts_constraint c;
    ts_constraint_init(&c, TS_CONSTRAINT_LOWER);
    ts_spline *s = NULL;
    CHECK(fit(x, f, 3, &c, 1, 0.0, 0.0, &s) == TS_OK);
    if (!s)
        return;
    certified(s, 0);
    for (int j = 0; j <= 2000; j++) {
        double y;
        CHECK(ts_spline_eval(s, 2.0 * j / 2000, NULL, &y) == TS_OK);
        CHECK(y >= 0.0);
    }
    ts_spline_free(s);
}

/* Slope bounds with |L h| beyond 2^1087 (h = 2^70, |L| = 1e308): |Δ_0| <=
 * 2^-69 here, so S' <= −1e308 and S' >= 1e308 are violated by the secant
 * (TS_ERR_CONDITION, secant-slope, interval 0) and S' <= 1e308, S' >=
 * −1e308 are not. */
static void huge_slope_bounds(void)
{
    TH_CASE("slope bounds beyond the exact products");
    double x[2] = {0, 0x1p70}, f[2] = {0, 1};
    const struct {
        ts_constraint_kind kind;
        double L;
        int violated;
    } cs[4] = {{TS_CONSTRAINT_SLOPE_MAX, -1e308, 1},
               {TS_CONSTRAINT_SLOPE_MIN, 1e308, 1},
               {TS_CONSTRAINT_SLOPE_MAX, 1e308, 0},
               {TS_CONSTRAINT_SLOPE_MIN, -1e308, 0}};
    for (int k = 0; k < 4; k++) {
        ts_constraint c;
        ts_constraint_init(&c, cs[k].kind);
        c.value = cs[k].L;
        ts_spline_options o;
        ts_spline_options_init(&o);
        o.constraints = &c;
        o.n_constraints = 1;
        ts_constraint_failure fl;
        ts_constraint_failure_init(&fl);
        ts_status st = ts_constraints_diagnose(x, f, 2, &o, &fl);
        if (cs[k].violated)
            CHECKF(st == TS_ERR_CONDITION && fl.condition == TS_CONDITION_SECANT_SLOPE &&
                       fl.index == 0,
                   "case %d: %s", k, ts_status_name(st));
        else
            CHECKF(st != TS_ERR_CONDITION, "case %d: %s", k, ts_status_name(st));
        ts_spline *s = NULL;
        st = fit(x, f, 2, &c, 1, 0.0, 0.0, &s);
        CHECK(cs[k].violated ? st == TS_ERR_CONDITION : st != TS_ERR_CONDITION);
        if (s)
            certified(s, 0);
        ts_spline_free(s);
    }
}

/* The header's case of TS_ERR_UNPROVEN for a slope bound a secant
 * reaches exactly (x = 0, 1, f = 0, 2, S' <= 2): the interval must be the
 * line, its rounded control values are not collinear, and the slopes
 * tried next (scaled: S' = 1 at both ends, below the bound) ask for an
 * infinite a_i (§13.3: e > 0 over a secant E = 0 on the bound). */
static void secant_on_bound(void)
{
    TH_CASE("a secant on a slope bound");
    double x[2] = {0, 1}, f[2] = {0, 2};
    ts_constraint c;
    ts_constraint_init(&c, TS_CONSTRAINT_SLOPE_MAX);
    c.value = 2.0;
    ts_status st = fit(x, f, 2, &c, 1, 0.0, 0.0, NULL);
    CHECKF(st == TS_ERR_UNPROVEN, "%s", ts_status_name(st));
}

/* Certificates that are never proven, whatever a_i: the fit is refused
 * with TS_ERR_UNPROVEN (or, were a proof found, certified).
 *  - S' <= 1e308 with a control value 2^-1074: the slope test scales its
 *    terms by 2^-k (|L h| > 2^1020) and that value loses its bit; with
 *    alpha 1e300 the doublings stop at once (2 a > 1e300), with alpha
 *    and margin 1e-300 the search starts at a_i = 4/(3π) exactly;
 *  - S' >= 1e-300 on steps of 1e-299: |L h| < 2^-960 and the legs of the
 *    polygon, below 2^-958, do not decide;
 *  - S >= 0 on widths 1e-300: h κ is below 2^-960 (also from a_i =
 *    4/(3π) exactly, where the values below a0 are not tried).
 * A polyline bound on those widths takes the minimum with a guard instead
 * and is certified. */
static void never_proven(void)
{
    TH_CASE("certificates out of the exact range");
    double x[3] = {0, 1, 2}, f[3] = {0, 0x1p-1074, 1};
    ts_constraint c;
    ts_constraint_init(&c, TS_CONSTRAINT_SLOPE_MAX);
    c.value = 1e308;
    const double am[3][2] = {{0.0, 0.0}, {1e300, 0.0}, {1e-300, 1e-300}};
    for (int k = 0; k < 3; k++) {
        ts_spline *s = NULL;
        ts_status st = fit(x, f, 3, &c, 1, am[k][0], am[k][1], &s);
        CHECKF(st == TS_ERR_UNPROVEN || st == TS_OK, "%s", ts_status_name(st));
        if (s)
            certified(s, 0);
        ts_spline_free(s);
    }
    double ft[3] = {0, 1e-299, 2e-299};
    ts_constraint_init(&c, TS_CONSTRAINT_SLOPE_MIN);
    c.value = 1e-300;
    ts_status st = fit(x, ft, 3, &c, 1, 0.0, 0.0, NULL);
    CHECKF(st == TS_ERR_UNPROVEN, "%s", ts_status_name(st));
    double xt[3] = {0, 1e-300, 2e-300}, fl[3] = {1, 2, 3}, px[2] = {-1, 1}, py[2] = {0, 0};
    ts_constraint_init(&c, TS_CONSTRAINT_LOWER);
    st = fit(xt, fl, 3, &c, 1, 0.0, 0.0, NULL);
    CHECKF(st == TS_ERR_UNPROVEN, "%s", ts_status_name(st));
    st = fit(xt, fl, 3, &c, 1, 1e-300, 1e-300, NULL); /* a_i = 4/(3π) exactly */
    CHECKF(st == TS_ERR_UNPROVEN, "%s", ts_status_name(st));
    c.bound = TS_BOUND_POLYLINE, c.px = px, c.py = py, c.n_poly = 2;
    ts_spline *s = NULL;
    CHECK(fit(xt, fl, 3, &c, 1, 0.0, 0.0, &s) == TS_OK);
    if (s)
        certified(s, 0);
    ts_spline_free(s);
}

static ts_spline *curve(const double *x, const double *y, size_t np, ts_form form)
{
    ts_spline_options o;
    ts_spline_options_init(&o);
    o.form = form;
    ts_spline *b = NULL;
    CHECK(ts_spline_new(x, y, np, &o, &b, NULL) == TS_OK);
    return b;
}

/* sg (S − B) >= 0 at m + 1 points of each interval where B is defined
 * (both evaluated: the margin of these fits is far above their rounding) */
static void above(const ts_spline *s, const ts_spline *b, double sg, int m)
{
    const double *x = ts_spline_x(s), *bx = ts_spline_x(b);
    size_t n = ts_spline_intervals(s), nb = ts_spline_intervals(b);
    for (size_t i = 0; i < n; i++)
        for (int j = 0; j <= m; j++) {
            double xx = j == m ? x[i + 1] : x[i] + (x[i + 1] - x[i]) * j / m, y, v;
            if (xx < bx[0] || xx > bx[nb])
                continue;
            CHECK(ts_spline_eval(s, xx, NULL, &y) == TS_OK);
            CHECK(ts_spline_eval(b, xx, NULL, &v) == TS_OK);
            CHECKF(sg * (y - v) >= 0.0, "x = %.17g: %g", xx, sg * (y - v));
        }
}

/* Bound splines B at the edges of the enclosures (docs/method.md §13.7):
 *  - values 4e307: the rational Bernstein sums overflow, B's enclosure is
 *    the whole line, and a point above B between its knots is within it:
 *    TS_ERR_CONDITION, inside-bound (the header's rule);
 *  - a data point one ulp right of a knot of a geometric B: the widened
 *    parameter falls below 0, the enclosure starts at B's knot;
 *  - knots near 1e6, 1e-8 apart: no widening in t moves x by an ulp, the
 *    whole interval of B is taken;
 *  - B on [0, 1.25] under data on [0, 2]: the cells beyond B's last knot meet
 *    no interval of B;
 *  - B rising above f_i inside an interval where d_i points down (the
 *    constant rule of §13.3 does not apply: the search does).
 * Each fit that succeeds is certified and above B at every sample. */
static void bound_spline_edges(void)
{
    TH_CASE("bound splines at the enclosures' edges");
    double bx[3] = {0, 1, 2}, by[3] = {4e307, 4e307, 4e307};
    ts_spline *b = curve(bx, by, 3, TS_FORM_PAPER), *s = NULL;
    ts_constraint c;
    ts_constraint_init(&c, TS_CONSTRAINT_LOWER);
    c.bound = TS_BOUND_SPLINE, c.spline = b;
    double x1[3] = {0.5, 1.0, 1.5}, f1[3] = {4.4e307, 4.4e307, 4.4e307};
    ts_spline_options o;
    ts_spline_options_init(&o);
    o.constraints = &c;
    o.n_constraints = 1;
    ts_constraint_failure fl;
    ts_constraint_failure_init(&fl);
    CHECK(ts_constraints_diagnose(x1, f1, 3, &o, &fl) == TS_ERR_CONDITION &&
          fl.condition == TS_CONDITION_INSIDE_BOUND && fl.index == 0);
    ts_spline_free(b);

    double gy[3] = {0.0, 1.0, 0.0};
    b = curve(bx, gy, 3, TS_FORM_GEOMETRIC);
    c.spline = b;
    double x2[3] = {nextafter(1.0, 2.0), 1.5, 2.0}, f2[3] = {1.5, 1.5, 1.5};
    CHECK(fit(x2, f2, 3, &c, 1, 0.0, 0.0, &s) == TS_OK);
    if (s) {
        certified(s, 0);
        above(s, b, 1.0, 500);
    }
    ts_spline_free(s);
    /* B on [0, 1.25] only (the line 0.8 x); data on [0, 2] */
    double x3[3] = {0.0, 1.0, 2.0}, f3[3] = {1.0, 0.85, 2.0}, b3x[2] = {0.0, 1.25}, b3y[2] = {0.0, 1.0};
    ts_spline *b3 = curve(b3x, b3y, 2, TS_FORM_GEOMETRIC);
    c.spline = b3;
    CHECK(fit(x3, f3, 3, &c, 1, 0.0, 0.0, &s) == TS_OK);
    if (s) {
        certified(s, 0);
        above(s, b3, 1.0, 500);
    }
    ts_spline_free(s);
    ts_spline_free(b3);
    ts_spline_free(b);

    double ox[4], oy[4] = {0.0, 0.5, 0.0, 0.5}, sx[4], sf[4] = {2.0, 2.5, 2.0, 2.5};
    for (int j = 0; j < 4; j++)
        ox[j] = 1e6 + 1e-8 * j, sx[j] = 1e6 + 1e-8 * j + (j == 1 || j == 2 ? 0.5e-8 : 0.0);
    b = curve(ox, oy, 4, TS_FORM_GEOMETRIC);
    c.spline = b;
    CHECK(fit(sx, sf, 4, &c, 1, 0.0, 0.0, &s) == TS_OK);
    if (s) {
        certified(s, 0);
        above(s, b, 1.0, 200);
    }
    ts_spline_free(s);
    ts_spline_free(b);

    /* B rising to 3.5 inside [1, 2], above f_1 (slope −1 there, data
     * falling) or above f_2 (slope 1, data rising): no closed form */
    double rx[4] = {0.0, 1.0, 1.5, 2.0}, ry[4] = {0.0, 0.0, 3.5, 0.0};
    b = curve(rx, ry, 4, TS_FORM_GEOMETRIC);
    c.spline = b;
    const double dx[3] = {0.0, 1.0, 2.0}, df[2][3] = {{3.0, 2.0, 1.0}, {1.0, 2.0, 3.0}},
                 dd[2][3] = {{-1.0, -1.0, -1.0}, {1.0, 1.0, 1.0}};
    for (int k = 0; k < 2; k++) {
        user_d = dd[k];
        ts_status st = fit(dx, df[k], 3, &c, 1, 0.0, 0.0, &s);
        CHECKF(st == TS_OK || st == TS_ERR_UNPROVEN, "%s", ts_status_name(st));
        if (s) {
            certified(s, 0);
            above(s, b, 1.0, 500);
        }
        ts_spline_free(s);
    }
    ts_spline_free(b);
}

/* A lower polyline whose second piece's line, extended left over interval
 * 0, passes through the data point (0, 0) while the slope there (below
 * the line's 1) points under it: the closed form (§13.3) leaves it to the
 * search.  Certified, and S >= the polyline at samples (exact: the
 * polyline's values at these x are exact). */
static void polyline_extension(void)
{
    TH_CASE("a polyline piece's line through a knot");
    double x[3] = {0.0, 1.0, 2.0}, f[3] = {0.0, 1.25, 1.3}, px[3] = {-1.0, 0.5, 1.5},
           py[3] = {-5.0, 0.5, 1.5};
    static const double d[3] = {0.5, 0.5, 0.0};
    user_d = d;
    ts_constraint c;
    ts_constraint_init(&c, TS_CONSTRAINT_LOWER);
    c.bound = TS_BOUND_POLYLINE, c.px = px, c.py = py, c.n_poly = 3;
    ts_spline *s = NULL;
    ts_status st = fit(x, f, 3, &c, 1, 0.0, 0.0, &s);
    CHECKF(st == TS_OK || st == TS_ERR_UNPROVEN, "%s", ts_status_name(st));
    if (s) {
        certified(s, 0);
        for (int j = 0; j <= 1000; j++) {
            double xx = 0.5 + j / 1000.0, y;
            CHECK(ts_spline_eval(s, xx, NULL, &y) == TS_OK);
            CHECK(y >= xx);
        }
    }
    ts_spline_free(s);
}

/* x_0 + (x_1 − x_0) rounds below x_1 here (3.4263564944267273 <
 * 3.4263564947844167), and the polyline starts between the two: the
 * interval's report covers its piece (gap the value of S near x_1, which
 * is f_1 = 1 up to |S'| (<= 1e-7 here) times the 4e-10 the piece spans),
 * certified. */
static void polyline_in_rounding_gap(void)
{
    TH_CASE("a polyline starting within the rounding of x_0 + h");
    double x[2] = {-223685658.3424624, 3.4263564947844167}, f[2] = {5.0, 1.0};
    double px[2] = {3.4263564946, 10.0}, py[2] = {0.0, 0.0};
    CHECK(x[0] + (x[1] - x[0]) < x[1] && x[0] + (x[1] - x[0]) < px[0] && px[0] < x[1]);
    ts_constraint c;
    ts_constraint_init(&c, TS_CONSTRAINT_LOWER);
    c.bound = TS_BOUND_POLYLINE, c.px = px, c.py = py, c.n_poly = 2;
    ts_spline *s = NULL;
    CHECK(fit(x, f, 2, &c, 1, 0.0, 0.0, &s) == TS_OK);
    if (!s)
        return;
    ts_constraint_report r;
    ts_constraint_report_init(&r);
    CHECK(ts_spline_constraint_report(s, 0, 0, &r) == TS_OK);
    CHECKF(r.in_scope == 1 && r.certified == 1 && fabs(r.gap - 1.0) <= 1e-9, "%d %d %.17g",
           r.in_scope, r.certified, r.gap);
    ts_spline_free(s);
}

int main(void)
{
    unread_bound_fields();
    contradicting_slopes();
    no_tangent_break();
    equal_neighbour_secant();
    overflowing_need();
    huge_slope_bounds();
    never_proven();
    secant_on_bound();
    bound_spline_edges();
    polyline_extension();
    polyline_in_rounding_gap();
    return th_report("test_constraint_edges");
}
