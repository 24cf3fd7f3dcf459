/* Constraint records (docs/method.md §13): the closed-form a_i of each
 * constraint, the exact minima of S'', S', S − bound per interval against
 * dense sampling, every refusal with its named condition, and a property
 * test of random combined-constraint problems (TS_CON_PROBLEMS problems,
 * default 4000; `make test-constraints` runs 10^6) with the false-refusal
 * rate against a brute-force search, and its slice with a bound given by
 * another spline (TS_CON_SPLINE_PROBLEMS, default 1000; docs/method.md
 * §13.7). */
#include "trigspline.h"
#include "th.h"

#include <math.h>
#include <stdint.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define PI 3.14159265358979323846

static ts_spline *build(const double *x, const double *f, size_t np, ts_spline_options *o,
                        const ts_constraint *c, size_t nc, ts_status *st, ts_error *e)
{
    ts_spline *s = NULL;
    o->constraints = c;
    o->n_constraints = nc;
    *st = ts_spline_new(x, f, np, o, &s, e);
    return s;
}

/* Dense minimum over interval i of the record's quantity, through the
 * public evaluation (samples per interval: m + 1). */
static double sampled(const ts_spline *s, const ts_constraint *c, size_t i, int m)
{
    const double *x = ts_spline_x(s);
    double best = HUGE_VAL;
    for (int j = 0; j <= m; j++) {
        double xx = x[i] + (x[i + 1] - x[i]) * j / m, y, dy, d2, v = HUGE_VAL;
        ts_cursor cur = TS_CURSOR_INIT;
        if (j == m) /* the interval's own right end (an inner knot belongs to the next) */
            xx = i + 1 < ts_spline_intervals(s) ? nextafter(x[i + 1], -HUGE_VAL) : x[i + 1];
        CHECK(ts_spline_eval_deriv(s, xx, &cur, &y, &dy, &d2) == TS_OK);
        switch (c->kind) {
        case TS_CONSTRAINT_CONVEX: v = d2; break;
        case TS_CONSTRAINT_CONCAVE: v = -d2; break;
        case TS_CONSTRAINT_INCREASING: v = dy; break;
        case TS_CONSTRAINT_DECREASING: v = -dy; break;
        case TS_CONSTRAINT_SLOPE_MIN: v = dy - c->value; break;
        case TS_CONSTRAINT_SLOPE_MAX: v = c->value - dy; break;
        case TS_CONSTRAINT_SLOPE_ABS: v = c->value - fabs(dy); break;
        case TS_CONSTRAINT_LOWER:
        case TS_CONSTRAINT_UPPER: {
            double b;
            if (c->bound == TS_BOUND_CONSTANT) {
                b = c->value;
            } else if (c->bound == TS_BOUND_SPLINE) {
                const double *bx = ts_spline_x(c->spline);
                if (xx < bx[0] || xx > bx[ts_spline_intervals(c->spline)])
                    continue;
                CHECK(ts_spline_eval(c->spline, xx, NULL, &b) == TS_OK);
            } else {
                if (xx < c->px[0] || xx > c->px[c->n_poly - 1])
                    continue;
                size_t p = 0;
                while (p + 2 < c->n_poly && c->px[p + 1] <= xx)
                    p++;
                b = c->py[p] + (c->py[p + 1] - c->py[p]) * (xx - c->px[p]) / (c->px[p + 1] - c->px[p]);
            }
            v = c->kind == TS_CONSTRAINT_LOWER ? y - b : b - y;
            break;
        }
        }
        best = v < best ? v : best;
    }
    return best;
}

/* ---- closed forms ------------------------------------------------------- */

/* One interval, user slopes: a = max(alpha, 4/(3π), need) + t with the
 * need of docs/method.md §13.3 in closed form. */
static void test_closed_forms(void)
{
    double x[2] = {0.0, 2.0}, f[2] = {1.0, 3.0}; /* Δ = 1 */
    ts_spline_options o;
    ts_constraint c;
    ts_status st;
    ts_error e;
    double a;

    /* convex: d0 = 0.2, d1 = 1.6: need = 2(1.4)/(3π min(0.8, 0.6)) */
    double d[2] = {0.2, 1.6};
    ts_spline_options_init(&o);
    o.slopes = TS_SLOPES_USER;
    o.user_slopes = d;
    o.n_user_slopes = 2;
    o.alpha = 0.1;
    ts_constraint_init(&c, TS_CONSTRAINT_CONVEX);
    ts_spline *s = build(x, f, 2, &o, &c, 1, &st, &e);
    CHECK(st == TS_OK);
    CHECK(ts_spline_a(s, 0, &a) == TS_OK);
    double need = 2.0 * 1.4 / (3.0 * PI * 0.6) + 0.01;
    /* a few roundings of the rule and of alpha + beta: 1e-14 relative */
    CHECK(fabs(a - need) <= 1e-14 * need);
    CHECK(ts_spline_certified(s) == 1);
    ts_constraint_report r;
    ts_constraint_report_init(&r);
    CHECK(ts_spline_constraint_report(s, 0, 0, &r) == TS_OK);
    CHECK(r.in_scope && r.active && r.certified && r.gap >= 0.0);
    ts_interval_report ir = TS_INTERVAL_REPORT_INIT;
    CHECK(ts_spline_report(s, 0, &ir) == TS_OK && ir.certified == 1);
    ts_spline_free(s);

    /* slope-max U = 2 with d = (0.5, 0.9): need = 2((2 − 0.5) + (2 − 0.9))/(3π (2 − 1)) */
    double d2[2] = {0.5, 0.9};
    o.user_slopes = d2;
    ts_constraint_init(&c, TS_CONSTRAINT_SLOPE_MAX);
    c.value = 2.0;
    s = build(x, f, 2, &o, &c, 1, &st, &e);
    CHECK(st == TS_OK);
    CHECK(ts_spline_a(s, 0, &a) == TS_OK);
    need = 2.0 * (1.5 + 1.1) / (3.0 * PI) + 0.01;
    CHECK(fabs(a - need) <= 1e-14 * need);
    /* S' = Δ = 1 somewhere (mean value theorem): 0 <= gap <= U − Δ = 1 */
    ts_constraint_report_init(&r);
    CHECK(ts_spline_constraint_report(s, 0, 0, &r) == TS_OK);
    CHECK(r.certified && r.gap >= 0.0 && r.gap <= 1.0);
    ts_spline_free(s);

    /* constant lower bound 0.5 with d0 = −3: need = −K d0 / g0 = (2·2/(3π))·3/0.5 */
    double d3[2] = {-3.0, 1.0};
    o.user_slopes = d3;
    ts_constraint_init(&c, TS_CONSTRAINT_LOWER);
    c.value = 0.5;
    s = build(x, f, 2, &o, &c, 1, &st, &e);
    CHECK(st == TS_OK);
    CHECK(ts_spline_a(s, 0, &a) == TS_OK);
    need = 2.0 * 2.0 / (3.0 * PI) * 3.0 / 0.5 + 0.01;
    CHECK(fabs(a - need) <= 1e-14 * need);
    ts_spline_free(s);
}

/* f = x² (S'' of the interpolant is not 2, but the three-point slopes are
 * exact, d_j = 2 x_j, and the exact minimum must match dense sampling);
 * e^{-x} convex and decreasing; the option chain. */
static void check_minima(const ts_spline *s, const ts_constraint *c, size_t nc)
{
    if (!s)
        return;
    size_t n = ts_spline_intervals(s);
    for (size_t k = 0; k < nc; k++)
        for (size_t i = 0; i < n; i++) {
            ts_constraint_report r;
            ts_constraint_report_init(&r);
            CHECK(ts_spline_constraint_report(s, k, i, &r) == TS_OK);
            if (!r.in_scope)
                continue;
            CHECK(r.certified == 1);
            double dense = sampled(s, &c[k], i, 4000);
            /* the exact minimum is below every sample (up to the samples'
             * rounding, 1e-9 of the quantity's scale) and within the dense
             * grid's resolution of the best one (second order in the step:
             * 1e-6 relative here) */
            double scale = fabs(dense) + 1.0;
            CHECK(r.gap <= dense + 1e-9 * scale);
            CHECK(dense - r.gap <= 1e-6 * scale);
            CHECK(r.gap >= -1e-12 * scale);
        }
}

static void test_minima(void)
{
    double x[7] = {0.0, 0.5, 1.25, 2.0, 3.5, 4.0, 6.0}, f[7];
    for (int j = 0; j < 7; j++)
        f[j] = x[j] * x[j];
    ts_spline_options o;
    ts_spline_options_init(&o);
    ts_constraint c[3];
    ts_constraint_init(&c[0], TS_CONSTRAINT_CONVEX);
    ts_constraint_init(&c[1], TS_CONSTRAINT_INCREASING);
    ts_constraint_init(&c[2], TS_CONSTRAINT_SLOPE_MAX);
    c[2].value = 12.5; /* the last secant is 10, the exact end slope of x² 12 */
    ts_status st;
    ts_error e;
    ts_spline *s = build(x, f, 7, &o, c, 3, &st, &e);
    CHECK(st == TS_OK);
    const double *d = ts_spline_slopes(s);
    /* inner three-point slopes of a parabola are exact: 2 x_j (rounding) */
    for (int j = 1; j < 6; j++)
        CHECK(fabs(d[j] - 2.0 * x[j]) <= 1e-14 * (1.0 + 2.0 * x[j]));
    check_minima(s, c, 3);
    ts_spline_free(s);

    /* e^{-x}: convex, decreasing, above the polyline through (0, 0.5),
     * (2.5, 0.05), (6, 0) (below the data) */
    for (int j = 0; j < 7; j++)
        f[j] = exp(-x[j]);
    double px[3] = {0.0, 2.5, 6.0}, py[3] = {0.4, 0.03, 0.0};
    ts_constraint_init(&c[1], TS_CONSTRAINT_DECREASING);
    ts_constraint_init(&c[2], TS_CONSTRAINT_LOWER);
    c[2].bound = TS_BOUND_POLYLINE;
    c[2].px = px;
    c[2].py = py;
    c[2].n_poly = 3;
    s = build(x, f, 7, &o, c, 3, &st, &e);
    CHECK(st == TS_OK);
    check_minima(s, c, 3);
    ts_spline_free(s);
}

/* Call prices in strike (Black–Scholes, S0 = 100, σ = 0.2, T = 1, r = 0):
 * convex and decreasing, slope in [−1, 0]: certified convex, so the implied
 * density S'' >= 0 everywhere (Breeden–Litzenberger). */
static double ncdf(double z)
{
    return 0.5 * erfc(-z / sqrt(2.0));
}
static void test_option_chain(void)
{
    double K[9] = {60, 70, 80, 90, 100, 105, 110, 120, 140}, C[9];
    for (int j = 0; j < 9; j++) {
        double d1 = (log(100.0 / K[j]) + 0.02) / 0.2, d2 = d1 - 0.2;
        C[j] = 100.0 * ncdf(d1) - K[j] * ncdf(d2);
    }
    ts_spline_options o;
    ts_spline_options_init(&o);
    ts_constraint c[4];
    ts_constraint_init(&c[0], TS_CONSTRAINT_CONVEX);
    ts_constraint_init(&c[1], TS_CONSTRAINT_DECREASING);
    ts_constraint_init(&c[2], TS_CONSTRAINT_SLOPE_MIN);
    c[2].value = -1.0;
    ts_constraint_init(&c[3], TS_CONSTRAINT_LOWER);
    c[3].value = 0.0;
    ts_status st;
    ts_error e;
    ts_spline *s = build(K, C, 9, &o, c, 4, &st, &e);
    CHECK(st == TS_OK);
    CHECK(ts_spline_certified(s) == 1);
    check_minima(s, c, 4);
    ts_spline_free(s);
}

/* Hagan–West's test curve (Hagan & West 2006, "all cubic methods produce
 * negative forwards" on it): continuous zero rates r at t = 0.1, 1, 4, 9, 20,
 * 30 of 8.1, 7, 4.4, 7, 4, 3 %.  The spline is fitted to y = t r = −ln P
 * (with y(0) = 0); the forward is y', so 'increasing' with S' >= 0.005
 * certifies forwards >= 0.005 (the least secant is 0.01); y is C¹ (geometric
 * form), so the forwards are continuous and the zero curve y/t is C¹ for
 * t > 0: no NaN at any knot. */
static void test_hagan_west(void)
{
    double t[7] = {0.0, 0.1, 1.0, 4.0, 9.0, 20.0, 30.0};
    double r[7] = {0.081, 0.081, 0.07, 0.044, 0.07, 0.04, 0.03}, y[7];
    for (int j = 0; j < 7; j++)
        y[j] = t[j] * r[j];
    ts_spline_options o;
    ts_spline_options_init(&o);
    ts_constraint c[2];
    ts_constraint_init(&c[0], TS_CONSTRAINT_INCREASING);
    ts_constraint_init(&c[1], TS_CONSTRAINT_SLOPE_MIN);
    c[1].value = 0.005;
    ts_status st;
    ts_error e;
    ts_spline *s = build(t, y, 7, &o, c, 2, &st, &e);
    CHECK(st == TS_OK);
    if (!s)
        return;
    CHECK(ts_spline_certified(s) == 1);
    check_minima(s, c, 2);
    for (int j = 1; j < 7; j++) {
        double v, dv;
        CHECK(ts_spline_eval_deriv(s, t[j], NULL, &v, &dv, NULL) == TS_OK);
        /* the zero rate y/t at the knot is the datum (to the rounding of
         * t r / t) and the forward there is finite and >= 0.005 */
        CHECK(fabs(v / t[j] - r[j]) <= 4e-16 * r[j] + 1e-18);
        CHECK(isfinite(dv) && dv >= 0.005);
    }
    /* forwards continuous: the one-sided slopes at inner knots agree (the
     * geometric form's S' = d_j from both sides, to a few ulps) */
    for (int j = 1; j < 6; j++) {
        double dl, dr;
        CHECK(ts_spline_eval_deriv(s, nextafter(t[j], 0.0), NULL, NULL, &dl, NULL) == TS_OK);
        CHECK(ts_spline_eval_deriv(s, t[j], NULL, NULL, &dr, NULL) == TS_OK);
        CHECK(fabs(dl - dr) <= 1e-9 * (fabs(dr) + 1e-3));
    }
    ts_spline_free(s);
}

/* TSPACK's own test (Renka, TOMS 716, its test driver): f(x) = x² on
 * uniformly spaced points of [0, 1], positive, increasing and convex; here
 * 11 points.  Convex, increasing and S' <= 2 (f' at 1) certified, then
 * convex, increasing and S >= 0; the inner slopes are the exact 2x. */
static void test_tspack_quadratic(void)
{
    double x[11], f[11];
    for (int j = 0; j < 11; j++)
        x[j] = j / 10.0, f[j] = x[j] * x[j];
    ts_spline_options o;
    ts_spline_options_init(&o);
    ts_constraint c[3];
    ts_constraint_init(&c[0], TS_CONSTRAINT_CONVEX);
    ts_constraint_init(&c[1], TS_CONSTRAINT_INCREASING);
    ts_constraint_init(&c[2], TS_CONSTRAINT_SLOPE_MAX);
    c[2].value = 2.0;
    ts_status st;
    ts_error e;
    ts_spline *s = build(x, f, 11, &o, c, 3, &st, &e);
    CHECK(st == TS_OK);
    if (!s)
        return;
    const double *d = ts_spline_slopes(s);
    for (int j = 1; j < 10; j++)
        CHECK(fabs(d[j] - 2.0 * x[j]) <= 1e-15 * 4.0);
    check_minima(s, c, 3);
    ts_spline_free(s);
    /* with positivity too (f(0) = 0 touches the bound y = 0: the slope there
     * is 0, the parabola's own): S >= 0 certified, its minimum 0 at x = 0 */
    ts_constraint_init(&c[2], TS_CONSTRAINT_LOWER);
    s = build(x, f, 11, &o, c, 3, &st, &e);
    CHECK(st == TS_OK);
    if (!s)
        return;
    CHECK(ts_spline_slopes(s)[0] == 0.0);
    check_minima(s, c, 3);
    ts_constraint_report r;
    ts_constraint_report_init(&r);
    CHECK(ts_spline_constraint_report(s, 2, 0, &r) == TS_OK && r.gap == 0.0 && r.at == 0.0);
    ts_spline_free(s);
}

/* ---- refusals: each status and its named condition ---------------------- */

static void expect(const double *x, const double *f, size_t np, ts_spline_options *o,
                   const ts_constraint *c, size_t nc, ts_status want, size_t k, size_t index,
                   ts_where where, ts_condition cond)
{
    ts_status st;
    ts_error e;
    ts_spline *s = build(x, f, np, o, c, nc, &st, &e);
    CHECK(st == want && s == NULL);
    if (st != want)
        fprintf(stderr, "  got %s, want %s\n", ts_status_name(st), ts_status_name(want));
    ts_constraint_failure fl;
    ts_constraint_failure_init(&fl);
    CHECK(ts_constraints_diagnose(x, f, np, o, &fl) == want);
    CHECK(fl.status == want && fl.constraint == k && fl.index == index && fl.where == where &&
             fl.condition == cond);
    CHECK(e.index == index && e.where == where);
}

/* The sentence of a refusal names the record and what the data do. */
static void expect_message(const double *x, const double *f, size_t np, ts_spline_options *o,
                           const ts_constraint *c, size_t nc, const char *want)
{
    ts_status st;
    ts_error e;
    ts_spline *s = build(x, f, np, o, c, nc, &st, &e);
    CHECK(s == NULL);
    ts_error_context ctx;
    ts_error_context_init(&ctx);
    ctx.x = x;
    ctx.f = f;
    ctx.n_points = np;
    ctx.spline_options = o;
    char buf[512];
    (void)ts_error_message(&e, &ctx, buf, sizeof buf);
    CHECKF(strstr(buf, want) != NULL, "message \"%s\" lacks \"%s\"", buf, want);
}

/* ---- data on a polyline bound (docs/method.md §13.6) -------------------- */

/* The record's exact minimum on interval i, checked against dense samples;
 * returns the report. */
static ts_constraint_report touch_report(const ts_spline *s, const ts_constraint *c, size_t k,
                                         size_t i)
{
    ts_constraint_report r;
    ts_constraint_report_init(&r);
    CHECK(ts_spline_constraint_report(s, k, i, &r) == TS_OK && r.in_scope && r.certified);
    double dense = sampled(s, c, i, 4000);
    /* below every sample up to the samples' rounding (1e-12 here: values of
     * order 1), and the certificate's gap >= 0 holds for the samples too */
    CHECK(r.gap <= dense + 1e-12);
    CHECK(dense >= -1e-12);
    return r;
}

static void test_touch_polyline(void)
{
    ts_spline_options o;
    ts_spline_options_init(&o);
    ts_status st;
    ts_error e;
    double x[5] = {0, 1, 2, 3, 4};
    /* a lower bound peaking at (2, 2), the datum there on the peak: slopes
     * 1 then −1, so a C¹ curve above it has S'(2) in [−1, 1] */
    double f[5] = {2, 2.5, 2, 2.5, 3}, px[3] = {0, 2, 4}, py[3] = {0, 2, 0};
    ts_constraint c[2];
    ts_constraint_init(&c[0], TS_CONSTRAINT_LOWER);
    c[0].bound = TS_BOUND_POLYLINE;
    c[0].px = px;
    c[0].py = py;
    c[0].n_poly = 3;
    ts_spline *s = build(x, f, 5, &o, c, 1, &st, &e);
    CHECK(st == TS_OK && s && ts_spline_certified(s));
    if (s) {
        const double *d = ts_spline_slopes(s);
        CHECK(-1.0 <= d[2] && d[2] <= 1.0);
        /* the exact minimum is 0 at the touching knot, on both sides */
        ts_constraint_report r1 = touch_report(s, c, 0, 1), r2 = touch_report(s, c, 0, 2);
        CHECK(r1.gap == 0.0 && r1.at == 2.0);
        CHECK(r2.gap == 0.0 && r2.at == 2.0);
        CHECK(touch_report(s, c, 0, 0).gap > 0.0 && touch_report(s, c, 0, 3).gap > 0.0);
        double y;
        ts_cursor cur = TS_CURSOR_INIT;
        CHECK(ts_spline_eval(s, 2.0, &cur, &y) == TS_OK && y == 2.0);
        ts_spline_free(s);
    }
    /* a datum inside a sloped piece (y = x/2 through (2, 1)), with convex
     * data: the slope there must be the piece's, 0.5 */
    double g[5] = {1, 0.75, 1, 2, 3.5}, qx[2] = {0, 4}, qy[2] = {0, 2};
    ts_constraint_init(&c[0], TS_CONSTRAINT_CONVEX);
    ts_constraint_init(&c[1], TS_CONSTRAINT_LOWER);
    c[1].bound = TS_BOUND_POLYLINE;
    c[1].px = qx;
    c[1].py = qy;
    c[1].n_poly = 2;
    s = build(x, g, 5, &o, c, 2, &st, &e);
    CHECK(st == TS_OK && s && ts_spline_certified(s));
    if (s) {
        CHECK(ts_spline_slopes(s)[2] == 0.5);
        ts_constraint_report r1 = touch_report(s, &c[1], 1, 1), r2 = touch_report(s, &c[1], 1, 2);
        CHECK(r1.gap == 0.0 && r1.at == 2.0 && r2.gap == 0.0 && r2.at == 2.0);
        for (size_t i = 0; i < 4; i++)
            (void)touch_report(s, &c[0], 0, i); /* S'' >= 0 */
        ts_spline_free(s);
    }
    /* on a corner that turns towards the region: a V under the data (lower,
     * slopes −1 then 1) or a peak over them (upper, 1 then −1) at the datum:
     * no C¹ curve on its side passes through it, a necessary condition */
    double v[5] = {3, 1, 0, 1, 3}, vx[3] = {0, 2, 4}, vy[3] = {2, 0, 2};
    ts_constraint_init(&c[0], TS_CONSTRAINT_LOWER);
    c[0].bound = TS_BOUND_POLYLINE;
    c[0].px = vx;
    c[0].py = vy;
    c[0].n_poly = 3;
    expect(x, v, 5, &o, c, 1, TS_ERR_CONDITION, 0, 2, TS_WHERE_POINT, TS_CONDITION_TOUCH_CORNER);
    expect_message(x, v, 5, &o, c, 1,
                   "point 2 (x = 2, f = 0) lies on the lower bound at its breakpoint, where the "
                   "polyline's slope goes from -1 to 1: no curve with a continuous slope stays "
                   "above it through this point (constraint 0, lower)");
    double w[5] = {-1, 0.5, 2, 0.5, -1};
    c[0].kind = TS_CONSTRAINT_UPPER;
    c[0].py = py;
    expect(x, w, 5, &o, c, 1, TS_ERR_CONDITION, 0, 2, TS_WHERE_POINT, TS_CONDITION_TOUCH_CORNER);
    /* the same corner at the end of the record's scope constrains one side
     * only: intervals 0-1, knot 2 its last */
    c[0].count = 2;
    s = build(x, w, 5, &o, c, 1, &st, &e);
    CHECK(st == TS_OK && s);
    if (s) {
        ts_constraint_report r1 = touch_report(s, c, 0, 1);
        CHECKF(r1.gap == 0.0 && r1.at == 2.0, "gap %g at %g, slope %g", r1.gap, r1.at,
               ts_spline_slopes(s)[2]);
        ts_spline_free(s);
    }
    CHECK(strcmp(ts_vocab_name(TS_VOCAB_CONDITION, TS_CONDITION_TOUCH_CORNER), "touch-corner") ==
          0);
}

static void test_refusals(void)
{
    double x[4] = {0, 1, 2, 3}, f[4] = {0, 1, 1.5, 3}; /* secants 1, 0.5, 1.5 */
    ts_spline_options o;
    ts_spline_options_init(&o);
    ts_constraint c[2];
    ts_constraint_init(&c[0], TS_CONSTRAINT_INCREASING);
    ts_constraint_init(&c[1], TS_CONSTRAINT_CONVEX);
    expect(x, f, 4, &o, c, 2, TS_ERR_CONDITION, 1, 1, TS_WHERE_POINT, TS_CONDITION_CONVEX_DATA);
    /* concave over intervals 0..1 only holds; over 1..2 not (point 2) */
    ts_constraint_init(&c[1], TS_CONSTRAINT_CONCAVE);
    c[1].first = 1;
    expect(x, f, 4, &o, c, 2, TS_ERR_CONDITION, 1, 2, TS_WHERE_POINT, TS_CONDITION_CONCAVE_DATA);
    c[1].first = 0;
    c[1].count = 2;
    ts_status st;
    ts_error e;
    ts_spline *s = build(x, f, 4, &o, c, 2, &st, &e);
    CHECK(st == TS_OK);
    ts_constraint_report r;
    ts_constraint_report_init(&r);
    CHECK(ts_spline_constraint_report(s, 1, 2, &r) == TS_OK && r.in_scope == 0 && isnan(r.gap));
    CHECK(ts_spline_constraint_report(s, 2, 0, &r) == TS_ERR_INDEX);
    CHECK(ts_spline_constraint_report(s, 0, 3, &r) == TS_ERR_INDEX);
    CHECK(ts_spline_constraint_report(NULL, 0, 0, &r) == TS_ERR_NULL);
    r.struct_size = 1;
    CHECK(ts_spline_constraint_report(s, 0, 0, &r) == TS_ERR_VERSION);
    CHECK(ts_spline_constraints(s) == 2 && ts_spline_constraints(NULL) == 0);
    ts_spline_free(s);

    ts_constraint_init(&c[1], TS_CONSTRAINT_CONVEX);
    expect_message(x, f, 4, &o, c, 2,
                   "point 1 (x = 1, f = 1): the data are not convex here: the secant before it "
                   "is 1, the secant after it 0.5 (constraint 1, convex)");
    /* a secant beyond a slope bound; data changing direction */
    ts_constraint_init(&c[0], TS_CONSTRAINT_SLOPE_MAX);
    c[0].value = 1.2;
    expect(x, f, 4, &o, c, 1, TS_ERR_CONDITION, 0, 2, TS_WHERE_INTERVAL, TS_CONDITION_SECANT_SLOPE);
    expect_message(x, f, 4, &o, c, 1,
                   "interval 2 [2, 3]: its secant 1.5 is beyond the slope-max bound 1.2");
    double g[4] = {0, 1, 0.5, 3};
    ts_constraint_init(&c[0], TS_CONSTRAINT_INCREASING);
    expect(x, g, 4, &o, c, 1, TS_ERR_CONDITION, 0, 2, TS_WHERE_POINT, TS_CONDITION_MONOTONE_DATA);
    /* a point across a constant bound (touching it is allowed); across a
     * polyline (on it is allowed, test_touch_polyline) */
    ts_constraint_init(&c[0], TS_CONSTRAINT_LOWER);
    c[0].value = 0.5;
    expect(x, f, 4, &o, c, 1, TS_ERR_CONDITION, 0, 0, TS_WHERE_POINT, TS_CONDITION_INSIDE_BOUND);
    double px[2] = {0.5, 2.5}, py[2] = {0.0, 2.25}; /* y = 1.125 (x − 0.5): 1.6875 at point 2 */
    c[0].bound = TS_BOUND_POLYLINE;
    c[0].px = px;
    c[0].py = py;
    c[0].n_poly = 2;
    expect(x, f, 4, &o, c, 1, TS_ERR_CONDITION, 0, 2, TS_WHERE_POINT, TS_CONDITION_INSIDE_BOUND);
    expect_message(x, f, 4, &o, c, 1, "is not above the lower bound (constraint 0, lower)");
    /* |S'| <= 1 on secants 1, −1: both intervals lines, slopes 1 and −1 at
     * knot 1: no C¹ curve (a proof) */
    double h[3] = {0, 1, 0};
    ts_constraint_init(&c[0], TS_CONSTRAINT_SLOPE_ABS);
    c[0].value = 1.0;
    expect(x, h, 3, &o, c, 1, TS_ERR_INFEASIBLE, TS_NO_INDEX, 1, TS_WHERE_POINT,
           TS_CONDITION_SLOPE_CONFLICT);
    expect_message(x, h, 3, &o, c, 1, "straight lines of different slopes");
    /* a polyline peak above the only possible curve (flat data, slopes 0):
     * the search gives up without a proof */
    double fl[2] = {1, 1}, qx[3] = {0, 0.5, 1}, qy[3] = {0, 1.2, 0};
    ts_constraint_init(&c[0], TS_CONSTRAINT_LOWER);
    c[0].bound = TS_BOUND_POLYLINE;
    c[0].px = qx;
    c[0].py = qy;
    c[0].n_poly = 3;
    expect(x, fl, 2, &o, c, 1, TS_ERR_UNPROVEN, 0, 0, TS_WHERE_INTERVAL, TS_CONDITION_UNPROVEN);
    expect_message(x, fl, 2, &o, c, 1, "interval 0 [0, 1]: no alpha + beta");

    /* options */
    qx[1] = 0.0;
    expect(x, fl, 2, &o, c, 1, TS_ERR_UNSORTED, 0, TS_NO_INDEX, TS_WHERE_NONE, TS_CONDITION_NONE);
    qx[1] = 0.5;
    c[0].n_poly = 1;
    expect(x, fl, 2, &o, c, 1, TS_ERR_LENGTH, 0, TS_NO_INDEX, TS_WHERE_NONE, TS_CONDITION_NONE);
    c[0].n_poly = 3;
    qy[2] = TH_NAN;
    expect(x, fl, 2, &o, c, 1, TS_ERR_NONFINITE, 0, TS_NO_INDEX, TS_WHERE_NONE, TS_CONDITION_NONE);
    qy[2] = 0.0;
    c[0].px = NULL;
    expect(x, fl, 2, &o, c, 1, TS_ERR_NULL, 0, TS_NO_INDEX, TS_WHERE_NONE, TS_CONDITION_NONE);
    c[0].px = qx;
    c[0].first = 1;
    expect(x, fl, 2, &o, c, 1, TS_ERR_OPTION, 0, TS_NO_INDEX, TS_WHERE_NONE, TS_CONDITION_NONE);
    c[0].first = 0;
    c[0].kind = (ts_constraint_kind)TS_CONSTRAINT_COUNT_;
    expect(x, fl, 2, &o, c, 1, TS_ERR_OPTION, 0, TS_NO_INDEX, TS_WHERE_NONE, TS_CONDITION_NONE);
    ts_constraint_init(&c[0], TS_CONSTRAINT_SLOPE_ABS);
    c[0].value = -1.0;
    expect(x, fl, 2, &o, c, 1, TS_ERR_OPTION, 0, TS_NO_INDEX, TS_WHERE_NONE, TS_CONDITION_NONE);
    c[0].struct_size = 0;
    expect(x, fl, 2, &o, c, 1, TS_ERR_VERSION, 0, TS_NO_INDEX, TS_WHERE_NONE, TS_CONDITION_NONE);
    ts_constraint_init(&c[0], TS_CONSTRAINT_CONVEX);
    o.form = TS_FORM_PAPER;
    expect(x, fl, 2, &o, c, 1, TS_ERR_OPTION, TS_NO_INDEX, TS_NO_INDEX, TS_WHERE_NONE,
           TS_CONDITION_NONE);
    o.form = TS_FORM_GEOMETRIC;
    o.shape = TS_SHAPE_POSITIVE;
    expect(x, fl, 2, &o, c, 1, TS_ERR_OPTION, TS_NO_INDEX, TS_NO_INDEX, TS_WHERE_NONE,
           TS_CONDITION_NONE);
    o.shape = TS_SHAPE_NONE;
    expect(x, fl, 2, &o, NULL, 1, TS_ERR_NULL, TS_NO_INDEX, TS_NO_INDEX, TS_WHERE_NONE,
           TS_CONDITION_NONE);
    ts_constraint_failure bad;
    ts_constraint_failure_init(&bad);
    bad.struct_size = 0;
    CHECK(ts_constraints_diagnose(x, fl, 2, &o, &bad) == TS_ERR_VERSION);
    CHECK(ts_constraints_diagnose(x, fl, 2, &o, NULL) == TS_ERR_NULL);
    ts_constraint_failure_init(NULL);
    ts_constraint_init(NULL, TS_CONSTRAINT_CONVEX);
    ts_constraint_report_init(NULL);
    /* names */
    CHECK(strcmp(ts_vocab_name(TS_VOCAB_CONSTRAINT, TS_CONSTRAINT_SLOPE_ABS), "slope-abs") == 0);
    CHECK(strcmp(ts_vocab_name(TS_VOCAB_BOUND, TS_BOUND_POLYLINE), "polyline") == 0);
    CHECK(strcmp(ts_vocab_name(TS_VOCAB_CONDITION, TS_CONDITION_CONVEX_DATA), "convex-data") == 0);
    CHECK(strcmp(ts_status_name(TS_ERR_CONDITION), "TS_ERR_CONDITION") == 0);
}

/* ---- property test ------------------------------------------------------ */

static uint64_t rng = 0x9E3779B97F4A7C15u;
static double urand(void)
{
    rng ^= rng << 13;
    rng ^= rng >> 7;
    rng ^= rng << 17;
    return (double)(rng >> 11) * 0x1p-53;
}

typedef struct prob {
    size_t np;
    double x[16], f[16], px[6], py[6], qx[6], qy[6];
    ts_constraint c[10];
    size_t nc;
    int touch; /* a polyline breakpoint on a datum (docs/method.md §13.6) */
} prob;

/* The polyline's value at x (x inside it). */
static double poly_at(const double *px, const double *py, size_t m, double x, size_t *piece)
{
    size_t j = 0;
    while (j + 2 < m && px[j + 1] <= x)
        j++;
    *piece = j;
    return py[j] + (x - px[j]) * (py[j + 1] - py[j]) / (px[j + 1] - px[j]);
}

/* A breakpoint of the lower polyline (px, py, m points, below the data)
 * moved onto an inner datum, its neighbours lowered until every other datum
 * is clearly above the polyline again (a peak, so the touch is feasible:
 * §13.6); left as it was when that takes too long. */
static void touch_datum(prob *p, size_t m, double range)
{
    double sx[6], sy[6];
    memcpy(sx, p->px, sizeof sx);
    memcpy(sy, p->py, sizeof sy);
    size_t k = 1 + (size_t)(urand() * (double)(p->np - 2)), j = 0;
    for (size_t i = 1; i < m; i++)
        if (fabs(p->px[i] - p->x[k]) < fabs(p->px[j] - p->x[k]))
            j = i;
    if ((j > 0 && p->px[j - 1] >= p->x[k]) || (j + 1 < m && p->px[j + 1] <= p->x[k]))
        return;
    p->px[j] = p->x[k];
    p->py[j] = p->f[k];
    if (j > 0 && j + 1 < m) { /* a peak: the right slope at most the left one */
        double ml = (p->py[j] - p->py[j - 1]) / (p->px[j] - p->px[j - 1]);
        double top = p->py[j] + ml * (p->px[j + 1] - p->px[j]) - 1e-6 * range;
        if (p->py[j + 1] > top)
            p->py[j + 1] = top;
    }
    for (int pass = 0; pass < 60; pass++) {
        int ok = 1;
        for (size_t i = 0; i < p->np; i++) {
            if (i == k || p->x[i] < p->px[0] || p->x[i] > p->px[m - 1])
                continue;
            size_t q;
            double b = poly_at(p->px, p->py, m, p->x[i], &q), need = p->f[i] - 1e-6 * range;
            if (b > need) {
                ok = 0;
                if (q != j)
                    p->py[q] -= (b - need) * 2.0 + 1e-6 * range;
                if (q + 1 != j)
                    p->py[q + 1] -= (b - need) * 2.0 + 1e-6 * range;
            }
        }
        if (ok) {
            p->touch = 1;
            return;
        }
    }
    memcpy(p->px, sx, sizeof sx);
    memcpy(p->py, sy, sizeof sy);
}

/* Random data of a random shape and random constraints that the data meet
 * (the necessary conditions hold), some of them tight. */
static void make_problem(prob *p, int tight)
{
    size_t np = 3 + (size_t)(urand() * 10);
    double xx = 0.0;
    for (size_t j = 0; j < np; j++) {
        xx += 0.1 + 2.0 * urand();
        p->x[j] = xx;
    }
    int shape = (int)(urand() * 3); /* 0 convex, 1 concave, 2 any */
    double A = 0.2 + urand(), B = urand() * 4.0 - 2.0, C = urand() * 3.0, sgn = shape == 1 ? -1.0 : 1.0;
    double r = 0.2 + urand();
    for (size_t j = 0; j < np; j++) {
        double t = p->x[j] / xx;
        if (shape == 2)
            p->f[j] = C + sin(6.0 * t + B) + 0.3 * urand();
        else
            p->f[j] = C + B * t + sgn * A * (exp(3.0 * r * t) + t * t);
    }
    p->np = np;
    p->nc = 0;
    p->touch = 0;
    double dmin = HUGE_VAL, dmax = -HUGE_VAL, flo = HUGE_VAL, fhi = -HUGE_VAL;
    for (size_t j = 0; j + 1 < np; j++) {
        double D = (p->f[j + 1] - p->f[j]) / (p->x[j + 1] - p->x[j]);
        dmin = fmin(dmin, D);
        dmax = fmax(dmax, D);
    }
    for (size_t j = 0; j < np; j++)
        flo = fmin(flo, p->f[j]), fhi = fmax(fhi, p->f[j]);
    ts_constraint *c = p->c;
    if (shape < 2)
        ts_constraint_init(&c[p->nc++], shape == 0 ? TS_CONSTRAINT_CONVEX : TS_CONSTRAINT_CONCAVE);
    if (dmin >= 0.0 && urand() < 0.6)
        ts_constraint_init(&c[p->nc++], TS_CONSTRAINT_INCREASING);
    if (dmax <= 0.0 && urand() < 0.6)
        ts_constraint_init(&c[p->nc++], TS_CONSTRAINT_DECREASING);
    if (urand() < 0.5) {
        double cap = fmax(fabs(dmin), fabs(dmax)) * (1.0 + (urand() < 0.3 ? 0.01 : urand()));
        ts_constraint_init(&c[p->nc], urand() < 0.5 ? TS_CONSTRAINT_SLOPE_ABS : TS_CONSTRAINT_SLOPE_MAX);
        c[p->nc].value = c[p->nc].kind == TS_CONSTRAINT_SLOPE_ABS ? cap : dmax + cap * 0.05 * urand();
        p->nc++;
    }
    if (urand() < 0.3) {
        ts_constraint_init(&c[p->nc], TS_CONSTRAINT_SLOPE_MIN);
        c[p->nc++].value = dmin - (dmax - dmin + 0.1) * 0.05 * urand();
    }
    if (urand() < 0.5) {
        ts_constraint_init(&c[p->nc], TS_CONSTRAINT_LOWER);
        double u = urand(); /* a tenth touch the lowest datum */
        c[p->nc++].value = u < 0.1 ? flo : flo - (fhi - flo + 0.1) * (u < 0.35 ? 1e-3 : urand());
    }
    if (urand() < 0.4) {
        ts_constraint_init(&c[p->nc], TS_CONSTRAINT_UPPER);
        double u = urand();
        c[p->nc++].value = u < 0.1 ? fhi : fhi + (fhi - flo + 0.1) * (u < 0.35 ? 1e-3 : urand());
    }
    if (tight || urand() < 0.5) {
        /* a polyline lower bound below the data near each breakpoint: its
         * value at a breakpoint is under both neighbouring data values */
        size_t m = 2 + (size_t)(urand() * 4);
        ts_constraint *q = &c[p->nc++];
        ts_constraint_init(q, TS_CONSTRAINT_LOWER);
        q->bound = TS_BOUND_POLYLINE;
        for (size_t j = 0; j < m; j++)
            p->px[j] = p->x[0] + (xx - p->x[0]) * ((double)j + urand()) / (double)m;
        if (urand() < 0.5)
            p->px[0] = p->x[0] - 0.5;
        /* each breakpoint below every datum between its two neighbours
         * and the data bracketing it: then below all data */
        for (size_t j = 0; j < m; j++) {
            double a = j ? p->px[j - 1] : -HUGE_VAL, b = j + 1 < m ? p->px[j + 1] : HUGE_VAL;
            double lo = HUGE_VAL;
            for (size_t k = 0; k < np; k++) {
                int near = (k + 1 < np && p->x[k] <= p->px[j] && p->px[j] <= p->x[k + 1]) ||
                           (k > 0 && p->x[k - 1] <= p->px[j] && p->px[j] <= p->x[k]);
                if ((a <= p->x[k] && p->x[k] <= b) || near)
                    lo = fmin(lo, p->f[k]);
            }
            if (!(lo < HUGE_VAL))
                lo = flo;
            p->py[j] = lo - (fhi - flo + 0.1) * ((urand() < 0.3 ? 0.02 : 0.5) * urand() + 1e-6);
            if (tight) {
                /* near the data's chord at the breakpoint, up to 10% of the
                 * range above it: feasible or not, the search has to find out */
                size_t k = 0;
                while (k + 2 < np && p->x[k + 1] <= p->px[j])
                    k++;
                double u = (p->px[j] - p->x[k]) / (p->x[k + 1] - p->x[k]);
                double chord = p->f[k] + u * (p->f[k + 1] - p->f[k]);
                p->py[j] = chord + (fhi - flo + 0.1) * (0.12 * urand() - 0.02);
            }
        }
        /* then lowered until every datum is clearly above it */
        for (int pass = 0; pass < 8; pass++)
            for (size_t k = 0; k < np; k++) {
                if (p->x[k] < p->px[0] || p->x[k] > p->px[m - 1])
                    continue;
                size_t j = 0;
                while (j + 2 < m && p->px[j + 1] <= p->x[k])
                    j++;
                double u = (p->x[k] - p->px[j]) / (p->px[j + 1] - p->px[j]);
                double b = p->py[j] + u * (p->py[j + 1] - p->py[j]);
                double need = p->f[k] - 1e-6 * (fhi - flo + 0.1);
                if (b > need) {
                    p->py[j] -= (b - need) * 2.0;
                    p->py[j + 1] -= (b - need) * 2.0;
                }
            }
        if (!tight && urand() < 0.3)
            touch_datum(p, m, fhi - flo + 0.1);
        q->px = p->px;
        q->py = p->py;
        q->n_poly = m;
    }
    if (urand() < 0.3) {
        size_t first = (size_t)(urand() * (double)(np - 1));
        for (size_t k = 0; k < p->nc; k++)
            if (urand() < 0.3) {
                c[k].first = first;
                c[k].count = (size_t)(urand() * (double)(np - 1 - first));
            }
    }
}

/* Worst sampled violation of every record over the spline (<= 0 good),
 * relative to the tolerances of the samples' own rounding: values 1e-12,
 * slopes 1e-9, second derivatives 1e-7 of their scales (the evaluation's
 * quotients Y'/X', (Y''X' − Y'X'')/X'^3). */
static int violates(const ts_spline *s, const prob *p, int m)
{
    size_t n = ts_spline_intervals(s);
    double fr = 0.0;
    for (size_t j = 0; j < p->np; j++)
        fr = fmax(fr, fabs(p->f[j]));
    for (size_t k = 0; k < p->nc; k++)
        for (size_t i = 0; i < n; i++) {
            const ts_constraint *c = &p->c[k];
            size_t end = c->count ? c->first + c->count : n;
            if (i < c->first || i >= end)
                continue;
            double h = p->x[i + 1] - p->x[i], tol;
            switch (c->kind) {
            case TS_CONSTRAINT_CONVEX:
            case TS_CONSTRAINT_CONCAVE: tol = 1e-7 * (fr + 1.0) / (h * h); break;
            case TS_CONSTRAINT_LOWER:
            case TS_CONSTRAINT_UPPER: tol = 1e-12 * (fr + 1.0); break;
            default: tol = 1e-9 * (fr + 1.0) / h; break;
            }
            if (sampled(s, c, i, m) < -tol)
                return 1;
        }
    return 0;
}

/* Brute force for a refused problem: the library's slopes scaled by λ and
 * a uniform a over a grid, each spline checked by dense sampling. */
static int brute_feasible(const prob *p)
{
    static const double lam[5] = {1.0, 0.5, 0.25, 0.0, 1.5};
    double d[16], betas[16];
    for (int li = 0; li < 5; li++) {
        for (int ai = 0; ai < 14; ai++) {
            double a = 0.4245 * pow(2.0, ai);
            ts_spline_options o;
            ts_spline_options_init(&o);
            ts_error e;
            if (ts_slopes_compute(TS_SLOPES_STEFFEN, p->x, p->f, p->np, d, &e) != TS_OK)
                return 0;
            for (size_t j = 0; j < p->np; j++)
                d[j] *= lam[li];
            for (size_t i = 0; i + 1 < p->np; i++)
                betas[i] = a > o.alpha ? a - o.alpha : 0.0;
            o.slopes = TS_SLOPES_USER;
            o.user_slopes = d;
            o.n_user_slopes = p->np;
            o.betas = betas;
            o.n_betas = p->np - 1;
            ts_spline *s = NULL;
            if (ts_spline_new(p->x, p->f, p->np, &o, &s, &e) != TS_OK)
                continue;
            int bad = violates(s, p, 48) || violates(s, p, 1000); /* screen, then confirm */
            ts_spline_free(s);
            if (!bad)
                return 1;
        }
    }
    return 0;
}

/* gaps_only (TS_CON_GAPS_ONLY set): construction and the reports alone, no
 * sampling or brute force (a quick pass over many problems). */
static void test_property(long problems, int gaps_only)
{
    long built = 0, refused[TS_STATUS_COUNT_] = {0}, bad = 0, false_refusals = 0, gaps_bad = 0;
    long touched = 0, touched_built = 0;
    for (long t = 0; t < problems; t++) {
        prob p;
        make_problem(&p, t % 4 == 3); /* a quarter with polylines near the chords */
        ts_spline_options o;
        ts_spline_options_init(&o);
        ts_status st;
        ts_error e;
        ts_spline *s = build(p.x, p.f, p.np, &o, p.c, p.nc, &st, &e);
        touched += p.touch;
        touched_built += p.touch && st == TS_OK;
        if (st != TS_OK) {
            refused[st]++;
            if (!gaps_only && st != TS_ERR_CONDITION && brute_feasible(&p))
                false_refusals++;
            continue;
        }
        built++;
        if (!gaps_only && violates(s, &p, 64))
            bad++;
        for (size_t k = 0; k < p.nc; k++)
            for (size_t i = 0; i + 1 < p.np; i++) {
                ts_constraint_report r;
                ts_constraint_report_init(&r);
                /* the exact minimum's own rounding: the sampling tolerances of
                 * violates() (values 1e-12, slopes 1e-9, S'' 1e-7 of their
                 * scales) */
                double fr = 0.0, h = p.x[i + 1] - p.x[i], tol;
                for (size_t j = 0; j < p.np; j++)
                    fr = fmax(fr, fabs(p.f[j]));
                switch (p.c[k].kind) {
                case TS_CONSTRAINT_CONVEX:
                case TS_CONSTRAINT_CONCAVE: tol = 1e-7 * (fr + 1.0) / (h * h); break;
                case TS_CONSTRAINT_LOWER:
                case TS_CONSTRAINT_UPPER: tol = 1e-12 * (fr + 1.0); break;
                default: tol = 1e-9 * (fr + 1.0) / h; break;
                }
                if (ts_spline_constraint_report(s, k, i, &r) != TS_OK ||
                    (r.in_scope && (!r.certified || !(r.gap >= -tol)))) {
                    gaps_bad++;
                    printf("problem %ld record %zu (%s) interval %zu: certified %d, gap %.17g "
                           "(tolerance %.3g)\n",
                           t, k, ts_vocab_name(TS_VOCAB_CONSTRAINT, (int)p.c[k].kind), i,
                           r.certified, r.gap, tol);
                    if (getenv("TS_CON_DUMP")) {
                        const double *d = ts_spline_slopes(s);
                        double a, B[4], X[4], worst = -HUGE_VAL, at = 0.0;
                        ts_spline_a(s, i, &a);
                        ts_spline_control(s, i, B, X);
                        printf("  x %.17g %.17g f %.17g %.17g d %.17g %.17g a %.17g\n  B %.17g %.17g %.17g %.17g at %.17g\n",
                               p.x[i], p.x[i + 1], p.f[i], p.f[i + 1], d[i], d[i + 1], a, B[0], B[1], B[2], B[3], r.at);
                        for (int j = 0; j <= 200000; j++) {
                            double xx = p.x[i] + (p.x[i + 1] - p.x[i]) * j / 200000.0, y, dy, d2;
                            if (xx >= p.x[i + 1])
                                xx = nextafter(p.x[i + 1], 0.0);
                            ts_spline_eval_deriv(s, xx, NULL, &y, &dy, &d2);
                            if (d2 > worst)
                                worst = d2, at = xx;
                        }
                        printf("  dense max S'' %.17g at %.17g\n", worst, at);
                    }
                }
            }
        ts_spline_free(s);
    }
    long ref = 0;
    for (int k = 0; k < TS_STATUS_COUNT_; k++)
        ref += refused[k];
    printf("constraints property: %ld problems, %ld built and certified, %ld with a sample outside "
           "a constraint, %ld reports not certified or with a negative exact minimum; %ld refused "
           "(condition %ld, infeasible %ld, unproven %ld, other %ld); false refusals against the "
           "brute-force search: %ld (%.3g%% of the refusals that were not a data condition)\n",
           problems, built, bad, gaps_bad, ref, refused[TS_ERR_CONDITION],
           refused[TS_ERR_INFEASIBLE], refused[TS_ERR_UNPROVEN],
           ref - refused[TS_ERR_CONDITION] - refused[TS_ERR_INFEASIBLE] - refused[TS_ERR_UNPROVEN],
           false_refusals,
           ref - refused[TS_ERR_CONDITION]
               ? 100.0 * (double)false_refusals / (double)(ref - refused[TS_ERR_CONDITION])
               : 0.0);
    printf("constraints property: %ld problems with a datum on a polyline breakpoint, %ld of "
           "them built and certified\n", touched, touched_built);
    CHECK(bad == 0);
    CHECK(gaps_bad == 0);
    CHECK(refused[TS_ERR_CONDITION] == 0); /* the generator keeps the necessary conditions */
    CHECK(built > problems / 2);
}

/* A bound spline B (random form, 3 to 8 knots of its own over the data's
 * range or a part of it) below (sg = 1) or above (−1) every datum of p by at
 * least 1e-6 of the data's range (else the data would break the necessary
 * condition), added to p's records; NULL when it could not be placed. */
static ts_spline *add_spline_bound(prob *p, double sg)
{
    size_t np = p->np, m = 3 + (size_t)(urand() * 6);
    double bx[8], by[8], flo = HUGE_VAL, fhi = -HUGE_VAL, x0 = p->x[0], x1 = p->x[np - 1];
    for (size_t j = 0; j < np; j++)
        flo = fmin(flo, p->f[j]), fhi = fmax(fhi, p->f[j]);
    double span = fhi - flo + 0.1, a = x0, b = x1;
    if (urand() < 0.3)
        a = x0 + (x1 - x0) * 0.4 * urand();
    else if (urand() < 0.5)
        a = x0 - 0.5 * urand();
    if (urand() < 0.3)
        b = x1 - (x1 - x0) * 0.4 * urand();
    else if (urand() < 0.5)
        b = x1 + 0.5 * urand();
    int tight = urand() < 0.5;
    for (size_t k = 0; k < m; k++) {
        bx[k] = a + (b - a) * ((double)k + (k && k + 1 < m ? urand() - 0.5 : 0.0)) / (double)(m - 1);
        /* the data's broken line there (clamped), moved off by up to a
         * tenth (tight) or half of the range */
        size_t i = 0;
        while (i + 2 < np && p->x[i + 1] <= bx[k])
            i++;
        double u = fmin(1.0, fmax(0.0, (bx[k] - p->x[i]) / (p->x[i + 1] - p->x[i])));
        by[k] = p->f[i] + u * (p->f[i + 1] - p->f[i]) -
                sg * span * (tight ? 0.1 * urand() : 0.5 * urand());
    }
    static const ts_form forms[3] = {TS_FORM_GEOMETRIC, TS_FORM_PAPER, TS_FORM_C1};
    ts_spline_options o;
    ts_spline_options_init(&o);
    o.form = forms[(int)(urand() * 3)];
    for (int pass = 0; pass < 40; pass++) {
        ts_spline *B = NULL;
        if (ts_spline_new(bx, by, m, &o, &B, NULL) != TS_OK)
            return NULL;
        double worst = 0.0; /* how far the data are inside by less than the margin */
        for (size_t j = 0; j < np; j++) {
            double v;
            if (p->x[j] < bx[0] || p->x[j] > bx[m - 1])
                continue;
            CHECK(ts_spline_eval(B, p->x[j], NULL, &v) == TS_OK);
            worst = fmax(worst, sg * (v - p->f[j]) + 1e-6 * span);
        }
        if (worst == 0.0) {
            ts_constraint *c = &p->c[p->nc++];
            ts_constraint_init(c, sg > 0.0 ? TS_CONSTRAINT_LOWER : TS_CONSTRAINT_UPPER);
            c->bound = TS_BOUND_SPLINE;
            c->spline = B;
            return B;
        }
        ts_spline_free(B);
        for (size_t k = 0; k < m; k++)
            by[k] -= sg * 2.0 * worst;
    }
    return NULL;
}

/* The slice of the property test with bound splines: each problem of
 * make_problem with a lower (three in four) or upper bound spline added
 * (gaps_only: no brute-force search of the refusals). */
static void test_property_spline(long problems, int gaps_only)
{
    long built = 0, refused[TS_STATUS_COUNT_] = {0}, bad = 0, gaps_bad = 0, false_refusals = 0,
         reports = 0;
    for (long t = 0; t < problems; t++) {
        prob p;
        make_problem(&p, 0);
        ts_spline *B = add_spline_bound(&p, urand() < 0.75 ? 1.0 : -1.0);
        if (!B)
            continue;
        ts_spline_options o;
        ts_spline_options_init(&o);
        ts_status st;
        ts_error e;
        ts_spline *s = build(p.x, p.f, p.np, &o, p.c, p.nc, &st, &e);
        if (st != TS_OK) {
            refused[st]++;
            if (!gaps_only && st != TS_ERR_CONDITION && brute_feasible(&p))
                false_refusals++;
            ts_spline_free(B);
            continue;
        }
        built++;
        if (violates(s, &p, 64))
            bad++;
        size_t k = p.nc - 1;
        double fr = 0.0;
        for (size_t j = 0; j < p.np; j++)
            fr = fmax(fr, fabs(p.f[j]));
        for (size_t i = 0; i + 1 < p.np; i++) {
            ts_constraint_report r;
            ts_constraint_report_init(&r);
            CHECK(ts_spline_constraint_report(s, k, i, &r) == TS_OK);
            if (!r.in_scope)
                continue;
            reports++;
            /* certified, and the minimum (of values: 1e-12 of their scale,
             * violates()) not below 0 nor above the sampled minimum */
            double dense = sampled(s, &p.c[k], i, 64), tol = 1e-12 * (fr + 1.0);
            if (!r.certified || !(r.gap >= -tol) || !(r.gap <= dense + tol)) {
                gaps_bad++;
                printf("bound-spline problem %ld interval %zu: certified %d, gap %.17g at %.17g, "
                       "sampled %.17g (tolerance %.3g)\n",
                       t, i, r.certified, r.gap, r.at, dense, tol);
            }
        }
        ts_spline_free(s);
        ts_spline_free(B);
    }
    long ref = 0;
    for (int k = 0; k < TS_STATUS_COUNT_; k++)
        ref += refused[k];
    printf("constraints property, bound splines: %ld problems, %ld built and certified, %ld with a "
           "sample outside a constraint, %ld of %ld reports not certified or with a minimum "
           "outside [0, sampled]; %ld refused (condition %ld, unproven %ld, other %ld); false "
           "refusals against the brute-force search: %ld\n",
           problems, built, bad, gaps_bad, reports, ref, refused[TS_ERR_CONDITION],
           refused[TS_ERR_UNPROVEN], ref - refused[TS_ERR_CONDITION] - refused[TS_ERR_UNPROVEN],
           false_refusals);
    CHECK(bad == 0);
    CHECK(gaps_bad == 0);
    CHECK(refused[TS_ERR_CONDITION] == 0); /* the data are inside B by construction */
    CHECK(built > problems / 2);
}

int main(void)
{
    test_closed_forms();
    test_minima();
    test_option_chain();
    test_hagan_west();
    test_tspack_quadratic();
    test_touch_polyline();
    test_refusals();
    const char *env = getenv("TS_CON_PROBLEMS");
    test_property(env ? atol(env) : 4000, getenv("TS_CON_GAPS_ONLY") != NULL);
    const char *envs = getenv("TS_CON_SPLINE_PROBLEMS");
    test_property_spline(envs ? atol(envs) : 1000, getenv("TS_CON_GAPS_ONLY") != NULL);
    return th_report("test_constraints");
}
