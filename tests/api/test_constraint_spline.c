/* A lower or upper bound given by another spline B (docs/method.md §13.7):
 * closed forms (B a line, B a constant: the report's minimum against the
 * library's independent exact gaps to a line), a known function (B through
 * points of sin, paper, C¹ and geometric forms) against dense sampling,
 * the negative control, the fitted spline's own copy of B, every refusal. */
#include "trigspline.h"
#include "th.h"

#include <math.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

static ts_spline *curve(const double *x, const double *y, size_t np, ts_form form)
{
    ts_spline_options o;
    ts_spline_options_init(&o);
    o.form = form;
    ts_spline *b = NULL;
    CHECK(ts_spline_new(x, y, np, &o, &b, NULL) == TS_OK);
    return b;
}

static ts_spline *fit(const double *x, const double *f, size_t np, const ts_constraint *c,
                      size_t nc, ts_status *st, ts_error *e)
{
    ts_spline_options o;
    ts_spline_options_init(&o);
    o.constraints = c;
    o.n_constraints = nc;
    ts_spline *s = NULL;
    *st = ts_spline_new(x, f, np, &o, &s, e);
    return s;
}

/* sg (S − B) at m + 1 points of interval i (where B is defined): the least. */
static double sampled(const ts_spline *s, const ts_spline *b, double sg, size_t i, int m)
{
    const double *x = ts_spline_x(s), *bx = ts_spline_x(b);
    size_t nb = ts_spline_intervals(b);
    double best = HUGE_VAL;
    for (int j = 0; j <= m; j++) {
        double xx = x[i] + (x[i + 1] - x[i]) * j / m, y, v;
        if (j == m)
            xx = x[i + 1];
        if (xx < bx[0] || xx > bx[nb])
            continue;
        CHECK(ts_spline_eval(s, xx, NULL, &y) == TS_OK);
        CHECK(ts_spline_eval(b, xx, NULL, &v) == TS_OK);
        best = fmin(best, sg * (y - v));
    }
    return best;
}

/* Every report of record k certified, its minimum below every sample (up
 * to both evaluations' rounding, 1e-12 of the values' scale) and within the
 * grid's resolution of the least sample (second order in the step, 4000
 * samples: 1e-6 relative here); returns the least minimum. */
static double check_reports(const ts_spline *s, const ts_spline *b, double sg, size_t k)
{
    size_t n = ts_spline_intervals(s);
    double least = HUGE_VAL;
    for (size_t i = 0; i < n; i++) {
        ts_constraint_report r;
        ts_constraint_report_init(&r);
        CHECK(ts_spline_constraint_report(s, k, i, &r) == TS_OK);
        if (!r.in_scope)
            continue;
        CHECK(r.certified == 1);
        double dense = sampled(s, b, sg, i, 4000), scale = fabs(dense) + 1.0;
        CHECKF(r.gap <= dense + 1e-12 * scale && dense - r.gap <= 1e-6 * scale,
               "interval %zu: reported %.17g, sampled %.17g", i, r.gap, dense);
        CHECK(r.gap > 0.0);
        const double *x = ts_spline_x(s);
        CHECK(x[i] <= r.at && r.at <= x[i + 1]);
        least = fmin(least, r.gap);
    }
    return least;
}

/* B the line y = x/2 + 1 through its own knots (geometric form: slopes
 * equal to the secants, so B is the line exactly, docs/method.md §4): the
 * reported minimum of S − B is the exact gap of S to the line, which
 * ts_spline_certify computes by another route (§5.6). */
static void test_line(void)
{
    double bx[5] = {-1, 1, 3, 5, 7}, by[5], x[7], f[7];
    for (int j = 0; j < 5; j++)
        by[j] = 0.5 * bx[j] + 1.0;
    for (int j = 0; j < 7; j++) {
        x[j] = j + 0.25 * (j % 2);
        f[j] = 0.5 * x[j] + 1.0 + 0.25 * (x[j] - 3.0) * (x[j] - 3.0) + 0.125;
    }
    ts_spline *b = curve(bx, by, 5, TS_FORM_GEOMETRIC);
    ts_constraint c;
    ts_constraint_init(&c, TS_CONSTRAINT_LOWER);
    c.bound = TS_BOUND_SPLINE;
    c.spline = b;
    ts_status st;
    ts_error e;
    ts_spline *s = fit(x, f, 7, &c, 1, &st, &e);
    CHECK(st == TS_OK && ts_spline_certified(s) == 1);
    ts_line line = {0.5, 1.0};
    ts_interval_report rep[6];
    ts_interval_report_init(rep, 6);
    CHECK(ts_spline_certify(s, &line, NULL, rep, NULL) == TS_OK);
    for (size_t i = 0; i < 6; i++) {
        ts_constraint_report r;
        ts_constraint_report_init(&r);
        CHECK(ts_spline_constraint_report(s, 0, i, &r) == TS_OK && r.in_scope && r.certified);
        /* both exact up to rounding of values of size 3: 1e-13 */
        CHECKF(fabs(r.gap - rep[i].gap_lower) <= 1e-13, "interval %zu: %.17g vs %.17g", i, r.gap,
               rep[i].gap_lower);
    }
    check_reports(s, b, 1.0, 0);
    ts_spline_free(s);
    ts_spline_free(b);
}

/* B through constant points (paper form: every control value the constant,
 * so B is it exactly): S − B's minimum is the range report's y_min − c. */
static void test_constant(void)
{
    double bx[4] = {0.3, 2.0, 2.5, 5.5}, by[4] = {0.2, 0.2, 0.2, 0.2};
    double x[6] = {0, 1, 2, 3, 4, 5}, f[6] = {1.0, 0.3, 0.25, 2.0, 0.22, 1.0};
    ts_spline *b = curve(bx, by, 4, TS_FORM_PAPER);
    ts_constraint c;
    ts_constraint_init(&c, TS_CONSTRAINT_LOWER);
    c.bound = TS_BOUND_SPLINE;
    c.spline = b;
    ts_status st;
    ts_error e;
    ts_spline *s = fit(x, f, 6, &c, 1, &st, &e);
    CHECK(st == TS_OK);
    for (size_t i = 0; i < 5; i++) {
        ts_constraint_report r;
        ts_constraint_report_init(&r);
        CHECK(ts_spline_constraint_report(s, 0, i, &r) == TS_OK && r.in_scope && r.certified);
        ts_interval_report ir = TS_INTERVAL_REPORT_INIT;
        CHECK(ts_spline_report(s, i, &ir) == TS_OK);
        if (i == 0) /* B starts at 0.3: the minimum over [0.3, 1] */
            continue;
        if (i == 4) /* B ends at 5.5: the interval [4, 5] is covered whole */
            CHECK(r.in_scope);
        CHECKF(fabs(r.gap - (ir.y_min - 0.2)) <= 1e-14, "interval %zu: %.17g vs %.17g", i, r.gap,
               ir.y_min - 0.2);
    }
    check_reports(s, b, 1.0, 0);
    ts_spline_free(s);
    ts_spline_free(b);
}

/* B through points of sin (each form), data above it: certified, against
 * dense sampling; an upper bound 1 above B too; the fitted spline still
 * reports after B is freed (its own copy; ASan would see a use after
 * free).  The negative control: the same data without the record cross B. */
static void test_sin(void)
{
    double bx[14], by[14], bu[14], x[9], f[9];
    for (int j = 0; j < 14; j++) {
        bx[j] = -0.2 + 6.6 * j / 13.0;
        by[j] = sin(bx[j]);
        bu[j] = by[j] + 1.0;
    }
    static const ts_form forms[3] = {TS_FORM_GEOMETRIC, TS_FORM_PAPER, TS_FORM_C1};
    for (int fm = 0; fm < 3; fm++) {
        ts_spline *b = curve(bx, by, 14, forms[fm]), *u = curve(bx, bu, 14, forms[fm]);
        /* the data above B by off: at least what the chords need (the
         * a-search raises the tension; B of the paper and C¹ forms dips
         * 4.25e-3 above the chords of its values at the data near x = 5.98) */
        double off = fm == 0 ? 0.004 : 0.006;
        for (int j = 0; j < 9; j++) {
            x[j] = 3.3 + 0.37 * j;
            CHECK(ts_spline_eval(b, x[j], NULL, &f[j]) == TS_OK);
            f[j] += off;
        }
        ts_constraint c[2];
        ts_constraint_init(&c[0], TS_CONSTRAINT_LOWER);
        c[0].bound = TS_BOUND_SPLINE;
        c[0].spline = b;
        ts_constraint_init(&c[1], TS_CONSTRAINT_UPPER);
        c[1].bound = TS_BOUND_SPLINE;
        c[1].spline = u;
        ts_status st;
        ts_error e;
        ts_spline *s = fit(x, f, 9, c, 2, &st, &e);
        CHECKF(st == TS_OK, "form %d: %s", fm, ts_status_name(st));
        if (!s)
            continue;
        double lo = check_reports(s, b, 1.0, 0);
        CHECK(lo < off); /* between the knots S comes closer to B than at them */
        check_reports(s, u, -1.0, 1);
        /* the negative control: default options, no record */
        ts_spline *free_s = fit(x, f, 9, NULL, 0, &st, &e);
        double worst = HUGE_VAL;
        for (size_t i = 0; i < 8; i++)
            worst = fmin(worst, sampled(free_s, b, 1.0, i, 400));
        CHECKF(worst < 0.0, "form %d: the unconstrained spline stays above B (%g)", fm, worst);
        ts_spline_free(free_s);
        /* B and U freed: the reports read the fitted spline's copies */
        ts_constraint_report before[8], after[8];
        for (size_t i = 0; i < 8; i++) {
            ts_constraint_report_init(&before[i]);
            CHECK(ts_spline_constraint_report(s, 0, i, &before[i]) == TS_OK);
        }
        ts_spline_free(b);
        ts_spline_free(u);
        for (size_t i = 0; i < 8; i++) {
            ts_constraint_report_init(&after[i]);
            CHECK(ts_spline_constraint_report(s, 0, i, &after[i]) == TS_OK);
            CHECK(after[i].gap == before[i].gap && after[i].certified == before[i].certified);
        }
        ts_spline_free(s);
    }
}

static void expect(const double *x, const double *f, size_t np, const ts_constraint *c, size_t nc,
                   ts_status want, size_t k, size_t index, ts_where where, ts_condition cond)
{
    ts_status st;
    ts_error e;
    ts_spline *s = fit(x, f, np, c, nc, &st, &e);
    CHECKF(st == want && s == NULL, "got %s, want %s", ts_status_name(st), ts_status_name(want));
    ts_spline_options o;
    ts_spline_options_init(&o);
    o.constraints = c;
    o.n_constraints = nc;
    ts_constraint_failure fl;
    ts_constraint_failure_init(&fl);
    CHECK(ts_constraints_diagnose(x, f, np, &o, &fl) == want);
    CHECK(fl.status == want && fl.constraint == k && fl.index == index && fl.where == where &&
          fl.condition == cond);
    CHECK(e.index == index && e.where == where);
    if (want == TS_ERR_CONDITION) {
        ts_error_context ctx;
        ts_error_context_init(&ctx);
        ctx.x = x;
        ctx.f = f;
        ctx.n_points = np;
        ctx.spline_options = &o;
        char buf[512];
        (void)ts_error_message(&e, &ctx, buf, sizeof buf);
        CHECKF(strstr(buf, "bound (constraint") != NULL, "message \"%s\"", buf);
    }
}

static void test_refusals(void)
{
    double bx[3] = {0.0, 1.5, 3.0}, by[3] = {0.0, 1.0, 0.0};
    double x[4] = {0, 1, 2, 3}, f[4] = {0.5, 1.5, 1.5, 0.5};
    ts_spline *b = curve(bx, by, 3, TS_FORM_GEOMETRIC);
    ts_constraint c[2];
    ts_constraint_init(&c[0], TS_CONSTRAINT_INCREASING);
    c[0].count = 1;
    ts_constraint_init(&c[1], TS_CONSTRAINT_LOWER);
    c[1].bound = TS_BOUND_SPLINE;
    c[1].spline = b;
    ts_status st;
    ts_error e;
    ts_spline *s = fit(x, f, 4, c, 2, &st, &e);
    CHECK(st == TS_OK);
    ts_spline_free(s);
    /* a point below B (B(1) > 0.5 by the hull: B's values at 0 and 1.5 and
     * its slope there); a point on B at B's knot (touching: refused); a
     * point within the rounding enclosure of B(x) off its knots */
    double g[4] = {0.5, 0.5, 1.5, 0.5};
    expect(x, g, 4, c, 2, TS_ERR_CONDITION, 1, 1, TS_WHERE_POINT, TS_CONDITION_INSIDE_BOUND);
    double x2[4] = {0, 1.5, 2, 3}, g2[4] = {0.5, 1.0, 1.5, 0.5};
    expect(x2, g2, 4, c, 2, TS_ERR_CONDITION, 1, 1, TS_WHERE_POINT, TS_CONDITION_INSIDE_BOUND);
    double g3[4] = {0.5, 1.5, 1.5, 0.5}, y2;
    CHECK(ts_spline_eval(b, 2.0, NULL, &y2) == TS_OK);
    g3[2] = y2;
    expect(x, g3, 4, c, 2, TS_ERR_CONDITION, 1, 2, TS_WHERE_POINT, TS_CONDITION_INSIDE_BOUND);
    /* an upper bound: the point above it */
    c[1].kind = TS_CONSTRAINT_UPPER;
    double g4[4] = {-0.5, -0.5, 1.5, -0.5};
    expect(x, g4, 4, c, 2, TS_ERR_CONDITION, 1, 2, TS_WHERE_POINT, TS_CONDITION_INSIDE_BOUND);
    c[1].kind = TS_CONSTRAINT_LOWER;
    /* flat data above a peak of B between two knots: the only slopes are 0,
     * S = 1 crosses B (peak 1.2); the search gives up without a proof */
    double px[3] = {0.0, 0.5, 1.0}, py[3] = {0.0, 1.2, 0.0}, fx[2] = {0, 1}, ff[2] = {1, 1};
    ts_spline *peak = curve(px, py, 3, TS_FORM_PAPER);
    c[1].spline = peak;
    expect(fx, ff, 2, &c[1], 1, TS_ERR_UNPROVEN, 0, 0, TS_WHERE_INTERVAL, TS_CONDITION_UNPROVEN);
    ts_spline_free(peak);
    /* options: no spline; an unknown bound type */
    c[1].spline = NULL;
    expect(x, f, 4, c, 2, TS_ERR_NULL, 1, TS_NO_INDEX, TS_WHERE_NONE, TS_CONDITION_NONE);
    c[1].spline = b;
    c[1].bound = (ts_bound)(TS_BOUND_SPLINE + 1);
    expect(x, f, 4, c, 2, TS_ERR_OPTION, 1, TS_NO_INDEX, TS_WHERE_NONE, TS_CONDITION_NONE);
    c[1].bound = TS_BOUND_SPLINE;
    /* B over part of the data only: the intervals beyond it are out of scope */
    double cx[2] = {1.2, 1.8}, cy[2] = {1.0, 1.0};
    ts_spline *part = curve(cx, cy, 2, TS_FORM_GEOMETRIC);
    c[1].spline = part;
    s = fit(x, f, 4, &c[1], 1, &st, &e);
    CHECK(st == TS_OK);
    ts_constraint_report r;
    ts_constraint_report_init(&r);
    CHECK(ts_spline_constraint_report(s, 0, 0, &r) == TS_OK && r.in_scope == 0 && isnan(r.gap));
    CHECK(ts_spline_constraint_report(s, 0, 1, &r) == TS_OK && r.in_scope == 1 && r.certified &&
          r.gap > 0.0 && 1.2 <= r.at && r.at <= 1.8);
    ts_spline_free(s);
    ts_spline_free(part);
    ts_spline_free(b);
    CHECK(strcmp(ts_vocab_name(TS_VOCAB_BOUND, TS_BOUND_SPLINE), "spline") == 0);
    int v = -1;
    CHECK(ts_vocab_value(TS_VOCAB_BOUND, "spline", &v) == TS_OK && v == TS_BOUND_SPLINE);
}

int main(void)
{
    test_line();
    test_constant();
    test_sin();
    test_refusals();
    return th_report("test_constraint_spline");
}
