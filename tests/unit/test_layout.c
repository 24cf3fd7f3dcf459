/* What the spline derives instead of storing (src/internal.h, struct
 * ts_spline): the running integral kept at every TS_CUM_STEP-th knot
 * (ts__cum against the running sum of the wholes, re-added here in
 * order), the geometric form's B1, B2 (ts__B against f_i ± k_i d_i with
 * k_i = 2h/(3π a_i), docs/method.md §4, formed here), and the geometric
 * form's vectorised control-value proofs (ts__skip_proven against the
 * interval-by-interval ts__check_interval), and what the paper and C¹
 * forms store besides: dθ/dx = (π/2)/h_i, from every construction path.
 * Every comparison is bitwise: the derived values must be the bits the
 * stored ones were. */
#include "th.h"
#include "trigspline.h"
#include "internal.h"

#include <math.h>
#include <stdlib.h>
#include <string.h>

#define NMAX 3000

static double xs[NMAX + 1], fs[NMAX + 1], fm[NMAX + 1];

static void make_data(size_t np)
{
    xs[0] = 0.0;
    for (size_t i = 1; i < np; i++)
        xs[i] = xs[i - 1] + 0.5 + 0.25 * sin(1.7 * (double)i) + (i % 41 == 0 ? 9.0 : 0.0);
    for (size_t i = 0; i < np; i++) {
        fs[i] = 1.6 + sin(0.05 * xs[i]) + 0.3 * sin(0.37 * xs[i]) - (i % 29 == 0 ? 0.1 : 0.0);
        fm[i] = (i ? fm[i - 1] : 0.0) + (i % 13 == 0 ? 0.0 : fs[i] * fs[i]);
    }
}

static int same(double a, double b)
{
    return memcmp(&a, &b, sizeof a) == 0;
}

/* ts__cum(s, i) for every i <= n against 0 + w_0 + ... + w_{i-1} in order. */
static void check_cum(const ts_spline *s, const char *what)
{
    size_t n = s->n;
    double *w = malloc(n * sizeof *w);
    CHECK(w != NULL);
    if (!w)
        return;
    ts__form(s->form)->wholes(s, 0, n, w);
    double sum = 0.0;
    long bad = 0;
    for (size_t i = 0; i <= n; i++) {
        bad += !same(ts__cum(s, i), sum);
        if (i < n)
            sum += w[i];
    }
    CHECKF(bad == 0, "%s, n = %zu: %ld running integrals differ from the ordered sum", what, n, bad);
    free(w);
}

static void test_cum(void)
{
    const size_t sizes[] = {2, 3, 8, 9, 10, 17, 1031, NMAX + 1};
    for (size_t k = 0; k < sizeof sizes / sizeof *sizes; k++) {
        size_t np = sizes[k];
        make_data(np);
        for (int form = 0; form < 3; form++) {
            ts_spline_options o;
            ts_spline_options_init(&o);
            o.form = (ts_form)form;
            o.shape = TS_SHAPE_BETWEEN;
            o.lower = (ts_line){1e-5, 0.1};
            o.upper = (ts_line){0.0, 4.0};
            ts_spline *s = NULL;
            CHECKF(ts_spline_new(xs, fs, np, &o, &s, NULL) == TS_OK, "form %d, %zu points", form, np);
            if (s)
                check_cum(s, "between");
            ts_spline_free(s);
        }
    }
    /* constraint records recompute the integrals after their repairs */
    make_data(1001);
    ts_constraint c;
    ts_constraint_init(&c, TS_CONSTRAINT_INCREASING);
    ts_spline_options o;
    ts_spline_options_init(&o);
    o.constraints = &c;
    o.n_constraints = 1;
    ts_spline *s = NULL;
    CHECK(ts_spline_new(xs, fm, 1001, &o, &s, NULL) == TS_OK);
    if (s) {
        check_cum(s, "increasing record");
        CHECK(s->b1 != NULL && s->b2 != NULL); /* stored: the records may nudge them */
    }
    ts_spline_free(s);
}

/* docs/method.md §4: B1 = f_i + k d_i, B2 = f_{i+1} − k d_{i+1}, k = 2h/(3π a). */
static void test_geo_controls(void)
{
    make_data(NMAX + 1);
    const ts_shape shapes[4] = {TS_SHAPE_NONE, TS_SHAPE_POSITIVE, TS_SHAPE_BETWEEN, TS_SHAPE_MONOTONE};
    for (int k = 0; k < 4; k++) {
        ts_spline_options o;
        ts_spline_options_init(&o);
        o.shape = shapes[k];
        o.lower = (ts_line){1e-5, 0.1};
        o.upper = (ts_line){0.0, 4.0};
        ts_spline *s = NULL;
        CHECK(ts_spline_new(xs, shapes[k] == TS_SHAPE_MONOTONE ? fm : fs, NMAX + 1, &o, &s, NULL) == TS_OK);
        if (!s)
            continue;
        CHECK(s->form == TS_FORM_GEOMETRIC && s->b1 == NULL && s->b2 == NULL);
        long bad = 0;
        for (size_t i = 0; i < s->n; i++) {
            double B[4], X[4], a = 0.0;
            CHECK(ts_spline_control(s, i, B, X) == TS_OK && ts_spline_a(s, i, &a) == TS_OK);
            double h = s->x[i + 1] - s->x[i], kk = 2.0 / (3.0 * TH_PI) * h / a;
            const double *d = ts_spline_slopes(s);
            bad += !same(B[0], s->f[i]) + !same(B[1], s->f[i] + kk * d[i]) +
                   !same(B[2], s->f[i + 1] - kk * d[i + 1]) + !same(B[3], s->f[i + 1]);
        }
        CHECKF(bad == 0, "shape %d: %ld control values are not f ± k d", (int)shapes[k], bad);
        ts_spline_free(s);
    }
}

/* ts__skip_proven (vector loops) stops at the first interval that
 * ts__check_interval (not exact: the control-value proof) does not pass. */
static void check_skip(const ts_spline *s, const char *what)
{
    size_t n = s->n, fails = 0;
    long bad = 0;
    for (size_t i = 0; i < n; i += 37) {
        size_t j = ts__skip_proven(s, i, n), k = i;
        while (k < n && ts__check_interval(s, k, 0))
            k++;
        bad += j != k;
        fails += k < n;
    }
    CHECKF(bad == 0, "%s: %ld starts where the skip and the interval checks disagree", what, bad);
    CHECKF(fails > 0, "%s: no interval fails its proof: the test proves nothing", what);
}

static void test_skip_geo(void)
{
    make_data(NMAX + 1);
    const ts_shape shapes[5] = {TS_SHAPE_POSITIVE, TS_SHAPE_ABOVE, TS_SHAPE_BELOW, TS_SHAPE_BETWEEN,
                                TS_SHAPE_MONOTONE};
    for (int k = 0; k < 5; k++) {
        ts_spline_options o;
        ts_spline_options_init(&o);
        o.shape = shapes[k];
        o.lower = (ts_line){1e-5, 0.1};
        o.upper = (ts_line){-1e-5, 4.0};
        ts_spline *s = NULL;
        const double *f = shapes[k] == TS_SHAPE_MONOTONE ? fm : fs;
        CHECK(ts_spline_new(xs, f, NMAX + 1, &o, &s, NULL) == TS_OK);
        if (!s)
            continue;
        /* built certified: every interval passes one proof or the other; move
         * the boundaries (or the values' sign pattern) so that some do not */
        s->lower = (ts_line){1e-4, 1.0};
        s->upper = (ts_line){-1e-5, 2.4};
        double *beta = (double *)ts_spline_beta(s), *kap = s->kappa;
        if (shapes[k] == TS_SHAPE_POSITIVE || shapes[k] == TS_SHAPE_MONOTONE) {
            /* smaller a_i: B1, B2 swing further, beyond 0 or out of order */
            for (size_t i = 0; i < s->n; i += 3) {
                beta[i] = 0.0;
                kap[i] = ts__kappa(s->alpha[i]);
            }
            for (size_t i = 0; i < s->n; i += 5)
                s->d[i] = (i % 2 ? 40.0 : -40.0);
        }
        check_skip(s, ts__vocab_name(TS_VOCAB_SHAPE, (int)shapes[k]));
        ts_spline_free(s);
    }
}

/* The paper and C¹ forms' stored dθ/dx: w_i = (π/2)/(x_{i+1} − x_i)
 * bitwise (docs/method.md §2, formed here) for every i; none in the
 * geometric form. */
static long check_w(const ts_spline *s)
{
    if (s->form == TS_FORM_GEOMETRIC)
        return s->w != NULL || s->kappa == NULL;
    if (!s->w)
        return 1;
    long bad = 0;
    for (size_t i = 0; i < s->n; i++)
        bad += !same(s->w[i], TH_HALF_PI / (s->x[i + 1] - s->x[i]));
    return bad;
}

/* Every construction path: each form and shape scheme (blocks of
 * spline.c's TS_BLOCK intervals: NMAX + 1 points span three), user
 * slopes, a constraint record, and a bound spline's copy kept by the
 * spline it bounds (each form of bound). */
static void test_widths(void)
{
    make_data(NMAX + 1);
    const ts_shape shapes[6] = {TS_SHAPE_NONE,  TS_SHAPE_POSITIVE, TS_SHAPE_ABOVE,
                                TS_SHAPE_BELOW, TS_SHAPE_BETWEEN,  TS_SHAPE_MONOTONE};
    for (int form = 0; form < 3; form++) {
        for (int k = 0; k < 7; k++) {
            ts_spline_options o;
            ts_spline_options_init(&o);
            o.form = (ts_form)form;
            o.lower = (ts_line){1e-5, 0.1};
            o.upper = (ts_line){0.0, 4.0};
            if (k < 6) {
                o.shape = shapes[k];
            } else {
                o.slopes = TS_SLOPES_USER;
                o.user_slopes = fs; /* any finite slopes */
                o.n_user_slopes = NMAX + 1;
            }
            ts_spline *s = NULL;
            CHECKF(ts_spline_new(xs, k == 5 ? fm : fs, NMAX + 1, &o, &s, NULL) == TS_OK, "form %d, case %d",
                   form, k);
            if (!s)
                continue;
            long bad = check_w(s);
            CHECKF(bad == 0, "form %d, case %d: %ld widths' dθ/dx differ", form, k, bad);
            ts_spline_free(s);
        }
    }
    /* constraint records (the geometric form only): an increasing one, and
     * a lower bound spline of each form, a copy of which the record keeps
     * and evaluates (constrain_spline.c) */
    double bx[4] = {-1.0, 100.0, 900.0, 4000.0}, by[4] = {-5.0, -4.0, -6.0, -5.0};
    for (int form = 0; form < 3; form++) {
        ts_spline_options o;
        ts_spline_options_init(&o);
        o.form = (ts_form)form;
        ts_spline *b = NULL, *s = NULL, *t = NULL;
        CHECK(ts_spline_new(bx, by, 4, &o, &b, NULL) == TS_OK);
        o.form = TS_FORM_GEOMETRIC;
        ts_constraint c[2];
        ts_constraint_init(&c[0], TS_CONSTRAINT_LOWER);
        c[0].bound = TS_BOUND_SPLINE, c[0].spline = b;
        ts_constraint_init(&c[1], TS_CONSTRAINT_INCREASING);
        o.constraints = c;
        o.n_constraints = 1;
        CHECKF(ts_spline_new(xs, fs, NMAX + 1, &o, &s, NULL) == TS_OK, "form %d, bound spline", form);
        o.constraints = &c[1];
        CHECKF(ts_spline_new(xs, fm, NMAX + 1, &o, &t, NULL) == TS_OK, "form %d, increasing", form);
        ts_spline_free(b); /* the copy stays */
        if (s) {
            CHECKF(check_w(s) == 0, "form %d: the bound spline's spline", form);
            CHECKF(s->ncon == 1 && s->con[0].spline == &s->con_spl[0], "form %d: the copy", form);
            if (s->ncon == 1) {
                const ts_spline *cb = s->con[0].spline;
                CHECKF(cb->n == 3 && check_w(cb) == 0, "form %d: the bound's copy", form);
            }
        }
        if (t)
            CHECKF(check_w(t) == 0, "form %d: the increasing record's spline", form);
        ts_spline_free(s);
        ts_spline_free(t);
    }
}

int main(void)
{
    TH_CASE("cum");
    test_cum();
    TH_CASE("geo_controls");
    test_geo_controls();
    TH_CASE("skip_geo");
    test_skip_geo();
    TH_CASE("widths");
    test_widths();
    return th_report("test_layout");
}
