/* The checks of a spline built with constraint records (ts_spline_new with
 * opt->constraints, docs/method.md §13) before any arithmetic: each bad
 * field of the options and of a record gives the status the header lists
 * for it (include/trigspline.h, "Failures of ts_spline_new with
 * constraints" and ts_spline_new's list), with the index it names; every
 * allocation of the construction failing in turn gives TS_ERR_NOMEM and
 * leaks nothing (ASan and valgrind builds); ts_spline_constraint_report's
 * argument checks.  A check that let a bad field through would build a
 * spline (TS_OK) and fail the status comparison. */
#include "th.h"
#include "trigspline.h"
#include "internal.h"

#include <math.h>
#include <stdio.h>
#include <string.h>

enum { NP = 5, N = NP - 1 };
static const double X[NP] = {0.0, 1.0, 2.0, 3.0, 4.0};
static const double F[NP] = {0.0, 1.0, 4.0, 9.0, 16.0}; /* convex, increasing */

static void base(ts_spline_options *o, ts_constraint *c, ts_constraint_kind kind)
{
    ts_spline_options_init(o); /* geometric form: the constraint scheme's */
    ts_constraint_init(c, kind);
    o->constraints = c;
    o->n_constraints = 1;
}

/* ts_spline_new's status, and (TS_OK) the spline freed; err->index into *index */
static ts_status build(const ts_spline_options *o, const double *f, size_t *index)
{
    ts_spline *s = NULL;
    ts_error e;
    e.index = TS_NO_INDEX;
    ts_status st = ts_spline_new(X, f ? f : F, NP, o, &s, &e);
    CHECK((st == TS_OK) == (s != NULL));
    ts_spline_free(s);
    if (index)
        *index = e.index;
    return st;
}

static void option_checks(void)
{
    TH_CASE("options with constraints");
    ts_spline_options o;
    ts_constraint c;
    size_t at;
    base(&o, &c, TS_CONSTRAINT_CONVEX);
    CHECK(build(&o, NULL, NULL) == TS_OK); /* the base problem is valid */

    double three[3] = {1.0, 1.0, 1.0}, margins[N] = {1e-3, 1e-3, 0.0, 1e-3};
    base(&o, &c, TS_CONSTRAINT_CONVEX);
    o.alphas = three, o.n_alphas = 3; /* n = 4 needed */
    CHECK(build(&o, NULL, NULL) == TS_ERR_LENGTH);
    base(&o, &c, TS_CONSTRAINT_CONVEX);
    o.margins = three, o.n_margins = 3;
    CHECK(build(&o, NULL, NULL) == TS_ERR_LENGTH);
    base(&o, &c, TS_CONSTRAINT_CONVEX);
    o.margins = margins, o.n_margins = N; /* margin 0 at interval 2 */
    CHECK(build(&o, NULL, &at) == TS_ERR_MARGIN && at == 2);
    base(&o, &c, TS_CONSTRAINT_CONVEX);
    o.margin = (double)NAN;
    CHECK(build(&o, NULL, &at) == TS_ERR_MARGIN && at == 0);

    base(&o, &c, TS_CONSTRAINT_CONVEX);
    o.slopes = TS_SLOPES_USER; /* no slopes given */
    CHECK(build(&o, NULL, NULL) == TS_ERR_NULL);
    double d[NP] = {0.5, 2.0, 4.0, 6.0, (double)NAN};
    o.user_slopes = d, o.n_user_slopes = N;
    CHECK(build(&o, NULL, NULL) == TS_ERR_LENGTH);
    o.n_user_slopes = NP; /* a NaN slope at point 4 */
    CHECK(build(&o, NULL, &at) == TS_ERR_NONFINITE && at == 4);
    d[4] = 8.0;
    CHECK(build(&o, NULL, NULL) == TS_OK);

    /* per-interval alphas and margins of the right length: built, and every
     * interval certified convex, with a_i >= alpha_i */
    double al[N] = {1.0, 2.0, 0.5, 4.0}, mg[N] = {1e-3, 1e-2, 1e-3, 1e-1};
    base(&o, &c, TS_CONSTRAINT_CONVEX);
    o.alphas = al, o.n_alphas = N;
    o.margins = mg, o.n_margins = N;
    {
        ts_spline *s = NULL;
        ts_error e;
        CHECK(ts_spline_new(X, F, NP, &o, &s, &e) == TS_OK);
        for (size_t i = 0; s && i < N; i++) {
            ts_constraint_report r;
            ts_constraint_report_init(&r);
            double a = 0.0;
            CHECK(ts_spline_constraint_report(s, 0, i, &r) == TS_OK && r.certified && r.gap >= 0.0);
            CHECK(ts_spline_a(s, i, &a) == TS_OK && a >= al[i]);
        }
        ts_spline_free(s);
    }

    /* periodic slopes with f_0 = f_n: built, every interval above the bound */
    {
        static const double fp[NP] = {1.0, 2.0, 1.5, 3.0, 1.0};
        base(&o, &c, TS_CONSTRAINT_LOWER);
        c.value = 0.0;
        o.slopes = TS_SLOPES_PERIODIC;
        ts_spline *s = NULL;
        ts_error e;
        CHECK(ts_spline_new(X, fp, NP, &o, &s, &e) == TS_OK);
        for (size_t i = 0; s && i < N; i++) {
            ts_constraint_report r;
            ts_constraint_report_init(&r);
            CHECK(ts_spline_constraint_report(s, 0, i, &r) == TS_OK && r.certified && r.gap >= 0.0);
        }
        ts_spline_free(s);
    }

    base(&o, &c, TS_CONSTRAINT_CONVEX);
    o.slopes = TS_SLOPES_PERIODIC; /* f_0 != f_n */
    CHECK(build(&o, NULL, &at) == TS_ERR_PERIODIC && at == N);

    /* computed slopes beyond the double range: secants of ±1e300 over 1e-10 */
    static const double fo[NP] = {0.0, 1e300, 2e300, 3e300, 4e300};
    double xs[NP] = {0.0, 1e-10, 2e-10, 3e-10, 4e-10};
    base(&o, &c, TS_CONSTRAINT_INCREASING);
    ts_spline *s = NULL;
    ts_error e;
    ts_status st = ts_spline_new(xs, fo, NP, &o, &s, &e);
    CHECKF(st == TS_ERR_SLOPE_OVERFLOW && s == NULL, "%s", ts_strerror(st));
    ts_spline_free(s);
}

static void record_checks(void)
{
    TH_CASE("constraint records");
    ts_spline_options o;
    ts_constraint c;
    base(&o, &c, TS_CONSTRAINT_CONVEX);
    c.bound = (ts_bound)(TS_BOUND_SPLINE + 1); /* no such bound type */
    CHECK(build(&o, NULL, NULL) == TS_ERR_OPTION);
    base(&o, &c, TS_CONSTRAINT_CONVEX);
    c.first = N; /* scope beyond the intervals */
    CHECK(build(&o, NULL, NULL) == TS_ERR_OPTION);
    base(&o, &c, TS_CONSTRAINT_CONVEX);
    c.first = 1, c.count = N; /* 1 .. 4: one too many */
    CHECK(build(&o, NULL, NULL) == TS_ERR_OPTION);
    c.count = N - 1;
    CHECK(build(&o, NULL, NULL) == TS_OK);
    base(&o, &c, TS_CONSTRAINT_LOWER);
    c.value = (double)INFINITY;
    CHECK(build(&o, NULL, NULL) == TS_ERR_NONFINITE);
    base(&o, &c, TS_CONSTRAINT_SLOPE_ABS);
    c.value = -1.0; /* |S'| <= −1 */
    CHECK(build(&o, NULL, NULL) == TS_ERR_OPTION);

    /* polyline bounds */
    double px[3] = {0.0, 2.0, 4.0}, py[3] = {-1.0, -1.0, -1.0};
    base(&o, &c, TS_CONSTRAINT_LOWER);
    c.bound = TS_BOUND_POLYLINE;
    c.px = px, c.py = py, c.n_poly = 3;
    CHECK(build(&o, NULL, NULL) == TS_OK);
    c.px = NULL;
    CHECK(build(&o, NULL, NULL) == TS_ERR_NULL);
    c.px = px, c.py = NULL;
    CHECK(build(&o, NULL, NULL) == TS_ERR_NULL);
    c.py = py, c.n_poly = 1;
    CHECK(build(&o, NULL, NULL) == TS_ERR_LENGTH);
    c.n_poly = 3;
    px[1] = (double)NAN;
    CHECK(build(&o, NULL, NULL) == TS_ERR_NONFINITE);
    px[1] = 2.0, py[2] = (double)INFINITY;
    CHECK(build(&o, NULL, NULL) == TS_ERR_NONFINITE);
    py[2] = 0x1p1023; /* finite, beyond TS_VALUE_MAX */
    CHECK(build(&o, NULL, NULL) == TS_ERR_NONFINITE);
    py[2] = -1.0, px[2] = 2.0; /* not strictly increasing */
    CHECK(build(&o, NULL, NULL) == TS_ERR_UNSORTED);
}

static void allocation_failures(void)
{
    TH_CASE("allocation failures with constraints");
    ts_spline_options o;
    ts_constraint c[2];
    double px[2] = {0.0, 4.0}, py[2] = {-1.0, -1.0};
    ts_spline_options_init(&o);
    ts_constraint_init(&c[0], TS_CONSTRAINT_CONVEX);
    ts_constraint_init(&c[1], TS_CONSTRAINT_LOWER);
    c[1].bound = TS_BOUND_POLYLINE;
    c[1].px = px, c[1].py = py, c[1].n_poly = 2;
    o.constraints = c;
    o.n_constraints = 2;
    int nomem = 0, ok = 0;
    /* the k-th allocation fails, k = 1, 2, ...: NOMEM until k passes the
     * last one, then the spline is built */
    for (long k = 1; k < 64 && !ok; k++) {
        ts__test_fail_alloc = k;
        ts_status st = build(&o, NULL, NULL);
        ts__test_fail_alloc = 0;
        CHECKF(st == TS_ERR_NOMEM || st == TS_OK, "allocation %ld: %s", k, ts_strerror(st));
        nomem += st == TS_ERR_NOMEM;
        ok = st == TS_OK;
    }
    CHECK(ok && nomem >= 6); /* con_begin: 4 arrays; con_finish: 2; the spline's */
}

static void report_checks(void)
{
    TH_CASE("constraint report arguments");
    ts_spline_options o;
    ts_constraint c;
    base(&o, &c, TS_CONSTRAINT_CONVEX);
    ts_spline *s = NULL;
    ts_error e;
    CHECK(ts_spline_new(X, F, NP, &o, &s, &e) == TS_OK);
    ts_constraint_report r;
    ts_constraint_report_init(&r);
    CHECK(ts_spline_constraint_report(s, 0, 0, &r) == TS_OK && r.in_scope && r.certified);
    CHECK(ts_spline_constraint_report(NULL, 0, 0, &r) == TS_ERR_NULL);
    CHECK(ts_spline_constraint_report(s, 0, 0, NULL) == TS_ERR_NULL);
    CHECK(ts_spline_constraint_report(s, 1, 0, &r) == TS_ERR_INDEX);
    CHECK(ts_spline_constraint_report(s, 0, N, &r) == TS_ERR_INDEX);
    r.struct_size = 1;
    CHECK(ts_spline_constraint_report(s, 0, 0, &r) == TS_ERR_VERSION && r.struct_size == 1);
    ts_spline_free(s);

    /* a polyline lower bound on [0, 1] only: no bound on intervals 1 .. 3,
     * whose reports are out of scope (the rest NaN / 0, as the header says) */
    double px[2] = {0.0, 1.0}, py[2] = {-1.0, -0.5};
    base(&o, &c, TS_CONSTRAINT_LOWER);
    c.bound = TS_BOUND_POLYLINE;
    c.px = px, c.py = py, c.n_poly = 2;
    s = NULL;
    CHECK(ts_spline_new(X, F, NP, &o, &s, &e) == TS_OK);
    for (size_t i = 0; s && i < N; i++) {
        ts_constraint_report_init(&r);
        CHECK(ts_spline_constraint_report(s, 0, i, &r) == TS_OK);
        if (i == 0)
            CHECK(r.in_scope && r.certified && r.gap > 0.0);
        else
            CHECK(!r.in_scope && !r.certified && !r.active && isnan(r.gap) && isnan(r.at));
    }
    ts_spline_free(s);
}

/* Slope bounds at the ends of the double range: the data checks and the
 * polygon certificate form L (x_{i+1} − x_i) and L h exactly; there L x or
 * L h leaves the exact products' range (beyond 2^1020, below 2^-960).  The
 * answers are those of docs/method.md §13.1 and §13.3 in exact arithmetic:
 * a secant of 1 (or 1e-10) is below a slope-min of 1e300 (a necessary
 * condition fails, at interval 0), inside a slope-max of 1e300, above a
 * slope-min of 1e-300 (and straight data have S' = secant, so each interval
 * is certified).  Before, L x overflowed and the condition was missed
 * (TS_ERR_UNPROVEN), and the certificate refused L h beyond the range. */
static void extreme_slope_bounds(void)
{
    TH_CASE("slope bounds at extreme magnitudes");
    static const double xo[3] = {1e10, 1e10 + 1.0, 1e10 + 2.0}, fo[3] = {0.0, 1.0, 2.0};
    static const double xw[3] = {1e10, 2e10, 3e10}; /* h = 1e10: secant 1e-10 */
    struct {
        const double *x;
        ts_constraint_kind kind;
        double value;
        ts_status want;
    } t[] = {
        {xo, TS_CONSTRAINT_SLOPE_MIN, 1e300, TS_ERR_CONDITION},
        {xo, TS_CONSTRAINT_SLOPE_MAX, -1e300, TS_ERR_CONDITION},
        {xw, TS_CONSTRAINT_SLOPE_MIN, 1e300, TS_ERR_CONDITION},
        {xo, TS_CONSTRAINT_SLOPE_MIN, 1e-300, TS_OK},
        {xw, TS_CONSTRAINT_SLOPE_MIN, 1e-320, TS_OK},
        {xw, TS_CONSTRAINT_SLOPE_MAX, 1e300, TS_OK},
        {xw, TS_CONSTRAINT_SLOPE_ABS, 1e300, TS_OK},
        {xw, TS_CONSTRAINT_SLOPE_MIN, -1e300, TS_OK},
    };
    for (size_t k = 0; k < sizeof t / sizeof t[0]; k++) {
        ts_spline_options o;
        ts_constraint c;
        ts_spline_options_init(&o);
        ts_constraint_init(&c, t[k].kind);
        c.value = t[k].value;
        o.constraints = &c;
        o.n_constraints = 1;
        ts_spline *s = NULL;
        ts_error e;
        ts_status st = ts_spline_new(t[k].x, fo, 3, &o, &s, &e);
        CHECKF(st == t[k].want, "case %zu: %s", k, ts_strerror(st));
        if (st == TS_ERR_CONDITION) {
            ts_constraint_failure fl;
            ts_constraint_failure_init(&fl);
            CHECK(ts_constraints_diagnose(t[k].x, fo, 3, &o, &fl) == TS_ERR_CONDITION &&
                  fl.condition == TS_CONDITION_SECANT_SLOPE && fl.index == 0);
        }
        for (size_t i = 0; s && i < 2; i++) {
            ts_constraint_report r;
            ts_constraint_report_init(&r);
            CHECKF(ts_spline_constraint_report(s, 0, i, &r) == TS_OK && r.certified && r.gap >= 0.0,
                   "case %zu interval %zu: gap %g", k, i, r.gap);
        }
        ts_spline_free(s);
    }
}

static void diagnose_indices(void)
{
    TH_CASE("diagnose: the index of each failure");
    ts_spline_options o;
    ts_constraint c;
    ts_constraint_failure fl;
    /* a condition: the record's own index and point */
    static const double fd[NP] = {0.0, 1.0, 4.0, 3.0, 16.0}; /* not convex at points 2, 3 */
    base(&o, &c, TS_CONSTRAINT_CONVEX);
    ts_constraint_failure_init(&fl);
    CHECK(ts_constraints_diagnose(X, fd, NP, &o, &fl) == TS_ERR_CONDITION && fl.constraint == 0 &&
          fl.where == TS_WHERE_POINT && fl.index == 2 && fl.condition == TS_CONDITION_CONVEX_DATA);
    /* a failure of the spline itself (x not increasing: point 2): from its
     * error, no record to blame */
    static const double xd[NP] = {0.0, 1.0, 1.0, 3.0, 4.0};
    ts_constraint_failure_init(&fl);
    CHECK(ts_constraints_diagnose(xd, F, NP, &o, &fl) == TS_ERR_UNSORTED && fl.index == 2 &&
          fl.where == TS_WHERE_POINT && fl.constraint == TS_NO_INDEX &&
          fl.condition == TS_CONDITION_NONE);
    /* an option error: no index */
    o.form = TS_FORM_PAPER;
    ts_constraint_failure_init(&fl);
    CHECK(ts_constraints_diagnose(X, F, NP, &o, &fl) == TS_ERR_OPTION && fl.index == TS_NO_INDEX &&
          fl.status == TS_ERR_OPTION);
}

int main(void)
{
    option_checks();
    record_checks();
    allocation_failures();
    report_checks();
    diagnose_indices();
    extreme_slope_bounds();
    return th_report("test_constraint_checks");
}
