/* The GSL adapter (adapters/gsl/trigspline_gsl.h): gsl_spline / gsl_interp
 * through the adapter against ts_spline_eval / ts_spline_eval_deriv / ts_spline_integral on the
 * same data and options, error statuses, the accelerator, configuration.
 *
 * Expected values: the adapter must call the same library functions with the
 * same arguments, so results are compared for exact equality (the ts_cursor
 * hint only changes how the interval is found, never the arithmetic).
 * Independent checks: interpolation of the data, S >= 0 (positive types) and
 * monotone samples (monotone types) on dense grids, where GSL's own cubic
 * spline leaves the region on the same data. */
#include "th.h"
#include "trigspline_gsl.h"

#include <gsl/gsl_errno.h>
#include <math.h>
#include <string.h>

static int handler_calls;
static void count_handler(const char *reason, const char *file, int line, int gsl_errno)
{
    (void)reason, (void)file, (void)line, (void)gsl_errno;
    handler_calls++;
}

/* The paper's Table 1 (data/paper/table1_positive.csv). */
static const double T1x[] = {0, 2, 3, 5, 15, 25, 27, 28, 30};
static const double T1f[] = {2, 1.58, 1.55, 1.54, 1.8, 1.54, 1.55, 1.58, 2};
/* Non-uniform, positive, not monotone. */
static const double D2x[] = {0.0, 0.7, 1.5, 3.1, 4.0, 6.2};
static const double D2f[] = {1.0, 2.2, 1.7, 3.5, 0.4, 2.0};
/* Non-decreasing with a flat piece and sharp steps. */
static const double D3x[] = {0, 1, 2, 4, 5, 7, 8};
static const double D3f[] = {0, 0.1, 3, 3, 9, 9.5, 9.6};
/* Positive with a sharp dip close to zero: GSL's natural cubic spline goes
 * below zero between the small values. */
static const double D4x[] = {0, 1, 2, 3, 4, 5, 6};
static const double D4f[] = {10, 10, 0.05, 0.02, 0.05, 10, 10};

#define N_OF(a) (sizeof(a) / sizeof((a)[0]))

static unsigned long rng_state = 12345u;
static double urand(void) /* deterministic LCG in [0, 1) */
{
    rng_state = rng_state * 6364136223846793005ul + 1442695040888963407ul;
    return (double)(rng_state >> 11) / 9007199254740992.0;
}

/* Compare a gsl_spline of type T with ts_spline_new(opt) on the data. */
static void compare(const gsl_interp_type *T, const ts_spline_options *opt, const double *x,
                    const double *f, size_t n, const char *what)
{
    gsl_spline *sp = gsl_spline_alloc(T, n);
    gsl_interp_accel *acc = gsl_interp_accel_alloc();
    ts_spline *s = NULL;
    CHECKF(sp && acc, "%s: alloc", what);
    if (!sp || !acc) {
        gsl_spline_free(sp);
        gsl_interp_accel_free(acc);
        return;
    }
    CHECKF(gsl_spline_init(sp, x, f, n) == GSL_SUCCESS, "%s: init", what);
    CHECKF(ts_spline_new(x, f, n, opt, &s, NULL) == TS_OK, "%s: ts_spline_new", what);
    CHECK(ts_gsl_spline(sp->interp) != NULL);
    CHECK(ts_gsl_last_error(sp->interp, NULL) == TS_OK);
    CHECK(gsl_spline_min_size(sp) == 2);
    if (!s) {
        gsl_spline_free(sp);
        gsl_interp_accel_free(acc);
        return;
    }
    double x0 = x[0], xn = x[n - 1];
    long bad[4] = {0, 0, 0, 0};
    /* a sorted sweep with the accelerator, then random order without */
    for (int pass = 0; pass < 2; pass++) {
        for (int j = 0; j <= 600; j++) {
            double q = pass == 0 ? x0 + (xn - x0) * j / 600.0 : x0 + (xn - x0) * urand();
            if (j < (int)n && pass == 1)
                q = x[j]; /* every knot exactly */
            gsl_interp_accel *a = pass == 0 ? acc : NULL;
            double g0, g1, g2, t0, t1, t2;
            int r0 = gsl_spline_eval_e(sp, q, a, &g0);
            int r1 = gsl_spline_eval_deriv_e(sp, q, a, &g1);
            int r2 = gsl_spline_eval_deriv2_e(sp, q, a, &g2);
            ts_status st = ts_spline_eval_deriv(s, q, NULL, &t0, &t1, &t2);
            if (r0 || r1 || r2 || st != TS_OK)
                bad[3]++;
            if (!(g0 == t0)) bad[0]++;
            if (!(g1 == t1)) bad[1]++;
            if (!(g2 == t2)) bad[2]++;
            /* the non-_e entry points return the same numbers */
            if (!(gsl_spline_eval(sp, q, a) == t0)) bad[0]++;
            if (!(gsl_spline_eval_deriv(sp, q, a) == t1)) bad[1]++;
            if (!(gsl_spline_eval_deriv2(sp, q, a) == t2)) bad[2]++;
        }
    }
    CHECKF(bad[0] == 0 && bad[1] == 0 && bad[2] == 0 && bad[3] == 0,
           "%s: mismatches value %ld, d1 %ld, d2 %ld, status %ld", what, bad[0], bad[1], bad[2],
           bad[3]);
    CHECKF(acc->hit_count > acc->miss_count && acc->cache < n - 1,
           "%s: accelerator hits %zu, misses %zu, cache %zu", what, acc->hit_count,
           acc->miss_count, acc->cache);
    /* integrals: GSL needs a <= b inside the data */
    long ibad = 0;
    for (int j = 0; j < 200; j++) {
        double a = x0 + (xn - x0) * urand(), b = x0 + (xn - x0) * urand();
        if (a > b) {
            double t = a;
            a = b;
            b = t;
        }
        if (j == 0)
            a = x0, b = xn;
        double g, t;
        int r = gsl_spline_eval_integ_e(sp, a, b, acc, &g);
        ts_status st = ts_spline_integral(s, a, b, &t);
        if (r != GSL_SUCCESS || st != TS_OK || !(g == t) || !(gsl_spline_eval_integ(sp, a, b, acc) == t))
            ibad++;
    }
    CHECKF(ibad == 0, "%s: %ld integral mismatches", what, ibad);
    /* interpolation: knots reproduced (rounding of one evaluation, 1e-15 relative) */
    for (size_t i = 0; i < n; i++)
        CHECK_CLOSE(gsl_spline_eval(sp, x[i], acc), f[i], 1e-15 * (1.0 + fabs(f[i])));
    ts_spline_free(s);
    gsl_spline_free(sp);
    gsl_interp_accel_free(acc);
}

static void test_compare(void)
{
    ts_spline_options o;
    ts_spline_options_init(&o);
    compare(ts_gsl_interp_trig, &o, T1x, T1f, N_OF(T1x), "trig/T1");
    compare(ts_gsl_interp_trig, &o, D2x, D2f, N_OF(D2x), "trig/D2");
    compare(ts_gsl_interp_trig, &o, D2x, D2f, 2, "trig/n=2");
    o.shape = TS_SHAPE_POSITIVE;
    compare(ts_gsl_interp_positive, &o, T1x, T1f, N_OF(T1x), "positive/T1");
    compare(ts_gsl_interp_positive, &o, D4x, D4f, N_OF(D4x), "positive/D4");
    o.form = TS_FORM_C1;
    compare(ts_gsl_interp_positive_c1, &o, D4x, D4f, N_OF(D4x), "positive_c1/D4");
    o.shape = TS_SHAPE_MONOTONE;
    compare(ts_gsl_interp_monotone_c1, &o, D3x, D3f, N_OF(D3x), "monotone_c1/D3");
    o.form = TS_FORM_GEOMETRIC; /* ts_spline_options_init's form: the types without "_c1" */
    compare(ts_gsl_interp_monotone, &o, D3x, D3f, N_OF(D3x), "monotone/D3");
    compare(ts_gsl_interp_monotone, &o, T1x, T1f, 4, "monotone/T1 decreasing part");

    /* the types' defaults are what the header says */
    const struct {
        const gsl_interp_type *T;
        const char *name;
        ts_shape shape;
        ts_form form;
    } types[] = {
        {ts_gsl_interp_trig, "trigspline", TS_SHAPE_NONE, TS_FORM_GEOMETRIC},
        {ts_gsl_interp_positive, "trigspline-positive", TS_SHAPE_POSITIVE, TS_FORM_GEOMETRIC},
        {ts_gsl_interp_monotone, "trigspline-monotone", TS_SHAPE_MONOTONE, TS_FORM_GEOMETRIC},
        {ts_gsl_interp_positive_c1, "trigspline-positive-c1", TS_SHAPE_POSITIVE, TS_FORM_C1},
        {ts_gsl_interp_monotone_c1, "trigspline-monotone-c1", TS_SHAPE_MONOTONE, TS_FORM_C1},
    };
    for (size_t k = 0; k < N_OF(types); k++) {
        gsl_spline *sp = gsl_spline_alloc(types[k].T, N_OF(D3x));
        CHECK(sp != NULL);
        if (!sp)
            continue;
        CHECK(strcmp(gsl_spline_name(sp), types[k].name) == 0);
        CHECK(types[k].T->min_size == 2);
        CHECK(ts_gsl_is_trigspline(types[k].T));
        CHECK(gsl_spline_init(sp, D3x, D3f, N_OF(D3x)) == GSL_SUCCESS);
        const ts_spline *s = ts_gsl_spline(sp->interp);
        CHECK(s && ts_spline_shape(s) == types[k].shape && ts_spline_form(s) == types[k].form);
        CHECK(s && ts_spline_alpha(s)[0] == TS_DEFAULT_ALPHA);
        if (s && types[k].shape != TS_SHAPE_NONE)
            CHECK(ts_spline_certified(s) == 1);
        gsl_spline_free(sp);
    }
}

/* Dense-grid checks that do not rely on the library: the positive types stay
 * >= 0 and the monotone ones monotone, where GSL's cubic spline does not. */
static void test_shape(void)
{
    const size_t m = 20001;
    gsl_spline *cs = gsl_spline_alloc(gsl_interp_cspline, N_OF(D4x));
    gsl_spline *ps = gsl_spline_alloc(ts_gsl_interp_positive, N_OF(D4x));
    gsl_spline *pc = gsl_spline_alloc(ts_gsl_interp_positive_c1, N_OF(D4x));
    gsl_interp_accel *acc = gsl_interp_accel_alloc();
    CHECK(cs && ps && pc && acc);
    if (!(cs && ps && pc && acc))
        return;
    CHECK(gsl_spline_init(cs, D4x, D4f, N_OF(D4x)) == GSL_SUCCESS);
    CHECK(gsl_spline_init(ps, D4x, D4f, N_OF(D4x)) == GSL_SUCCESS);
    CHECK(gsl_spline_init(pc, D4x, D4f, N_OF(D4x)) == GSL_SUCCESS);
    double cmin = (double)INFINITY, pmin = (double)INFINITY, qmin = (double)INFINITY;
    for (size_t j = 0; j < m; j++) {
        double q = 6.0 * (double)j / (double)(m - 1);
        double c = gsl_spline_eval(cs, q, NULL), p = gsl_spline_eval(ps, q, acc),
               r = gsl_spline_eval(pc, q, NULL);
        cmin = c < cmin ? c : cmin;
        pmin = p < pmin ? p : pmin;
        qmin = r < qmin ? r : qmin;
    }
    CHECKF(cmin < 0.0, "GSL cspline dips below zero on D4 (min %g)", cmin);
    CHECKF(pmin > 0.0 && qmin > 0.0, "positive types stay > 0 (min %g, %g)", pmin, qmin);
    gsl_spline_free(cs);
    gsl_spline_free(ps);
    gsl_spline_free(pc);

    gsl_spline *mc = gsl_spline_alloc(gsl_interp_cspline, N_OF(D3x));
    gsl_spline *mo = gsl_spline_alloc(ts_gsl_interp_monotone, N_OF(D3x));
    gsl_spline *m1 = gsl_spline_alloc(ts_gsl_interp_monotone_c1, N_OF(D3x));
    CHECK(mc && mo && m1);
    if (!(mc && mo && m1))
        return;
    CHECK(gsl_spline_init(mc, D3x, D3f, N_OF(D3x)) == GSL_SUCCESS);
    CHECK(gsl_spline_init(mo, D3x, D3f, N_OF(D3x)) == GSL_SUCCESS);
    CHECK(gsl_spline_init(m1, D3x, D3f, N_OF(D3x)) == GSL_SUCCESS);
    /* steps that go down by more than rounding: two evaluations of a value of
     * size <= max f = 9.6, each within a few eps of it (fast.c bounds one at
     * 8 eps M); a flat piece evaluates to 3 +- 1e-15 */
    const double tol = 16.0 * 2.220446049250313e-16 * 9.6;
    long cdown = 0, mdown = 0;
    double pc_ = gsl_spline_eval(mc, 0, NULL), pm = gsl_spline_eval(mo, 0, acc),
           p1 = gsl_spline_eval(m1, 0, NULL);
    for (size_t j = 1; j < m; j++) {
        double q = 8.0 * (double)j / (double)(m - 1);
        double c = gsl_spline_eval(mc, q, NULL), v = gsl_spline_eval(mo, q, acc),
               w = gsl_spline_eval(m1, q, NULL);
        cdown += c < pc_ - tol;
        mdown += v < pm - tol || w < p1 - tol;
        pc_ = c, pm = v, p1 = w;
    }
    CHECKF(cdown > 0, "GSL cspline is not monotone on D3 (%ld decreasing steps)", cdown);
    CHECKF(mdown == 0, "monotone types: %ld decreasing steps", mdown);
    gsl_spline_free(mc);
    gsl_spline_free(mo);
    gsl_spline_free(m1);
    gsl_interp_accel_free(acc);
}

static void test_errors(void)
{
    int calls0 = handler_calls;
    ts_error e;
    double v;
    /* NaN / Inf in y: GSL_EINVAL from init, every evaluation GSL_EINVAL + NaN */
    double y[N_OF(D2f)];
    memcpy(y, D2f, sizeof y);
    y[3] = (double)NAN;
    gsl_spline *sp = gsl_spline_alloc(ts_gsl_interp_positive, N_OF(D2x));
    CHECK(sp != NULL);
    if (!sp)
        return;
    CHECK(ts_gsl_last_error(sp->interp, &e) == TS_ERR_NULL); /* never initialised */
    CHECK(ts_gsl_spline(sp->interp) == NULL);
    CHECK(gsl_spline_init(sp, D2x, y, N_OF(D2x)) == GSL_EINVAL);
    CHECK(ts_gsl_last_error(sp->interp, &e) == TS_ERR_NONFINITE && e.index == 3 &&
          e.where == TS_WHERE_POINT);
    CHECK(ts_gsl_spline(sp->interp) == NULL);
    v = 0;
    CHECK(gsl_spline_eval_e(sp, 1.0, NULL, &v) == GSL_EINVAL && isnan(v));
    v = 0;
    CHECK(gsl_spline_eval_deriv_e(sp, 1.0, NULL, &v) == GSL_EINVAL && isnan(v));
    v = 0;
    CHECK(gsl_spline_eval_deriv2_e(sp, 1.0, NULL, &v) == GSL_EINVAL && isnan(v));
    v = 0;
    CHECK(gsl_spline_eval_integ_e(sp, 0.5, 1.0, NULL, &v) == GSL_EINVAL && isnan(v));
    y[3] = (double)INFINITY;
    CHECK(gsl_spline_init(sp, D2x, y, N_OF(D2x)) == GSL_EINVAL);
    /* negative data for the positive scheme: GSL_EDOM, index of the point */
    y[3] = -0.5;
    CHECK(gsl_spline_init(sp, D2x, y, N_OF(D2x)) == GSL_EDOM);
    CHECK(ts_gsl_last_error(sp->interp, &e) == TS_ERR_NEGATIVE && e.index == 3);
    /* the same object recovers with good data */
    CHECK(gsl_spline_init(sp, D2x, D2f, N_OF(D2x)) == GSL_SUCCESS);
    CHECK(ts_gsl_last_error(sp->interp, &e) == TS_OK && e.index == TS_NO_INDEX);
    CHECK(gsl_spline_eval_e(sp, 1.0, NULL, &v) == GSL_SUCCESS && isfinite(v));
    /* a NaN query passes GSL's range check and is ours: GSL_EDOM, NaN */
    v = 0;
    CHECK(gsl_spline_eval_e(sp, (double)NAN, NULL, &v) == GSL_EDOM && isnan(v));
    v = 0;
    CHECK(gsl_spline_eval_deriv_e(sp, (double)NAN, NULL, &v) == GSL_EDOM && isnan(v));
    gsl_interp_accel *acc = gsl_interp_accel_alloc();
    v = 0;
    CHECK(gsl_spline_eval_deriv2_e(sp, (double)NAN, acc, &v) == GSL_EDOM && isnan(v));
    CHECK(acc && acc->cache < N_OF(D2x) - 1);
    v = 0;
    CHECK(gsl_spline_eval_integ_e(sp, (double)NAN, 1.0, NULL, &v) == GSL_EDOM && isnan(v));
    CHECK(handler_calls == calls0); /* the adapter never called the handler */
    /* ... but GSL's non-_e wrapper does (DISCARD_STATUS), as the header says */
    v = gsl_spline_eval(sp, (double)NAN, NULL);
    CHECK(isnan(v) && handler_calls == calls0 + 1);
    gsl_interp_accel_free(acc);
    gsl_spline_free(sp);

    calls0 = handler_calls;
    sp = gsl_spline_alloc(ts_gsl_interp_monotone, N_OF(D2x));
    CHECK(sp && gsl_spline_init(sp, D2x, D2f, N_OF(D2x)) == GSL_EDOM);
    CHECK(sp && ts_gsl_last_error(sp->interp, &e) == TS_ERR_NONMONOTONE &&
          e.where == TS_WHERE_POINT && e.index < N_OF(D2x));
    gsl_spline_free(sp);
    CHECK(handler_calls == calls0);

    /* GSL's own checks (not the adapter): min_size and increasing x */
    CHECK(gsl_spline_alloc(ts_gsl_interp_trig, 1) == NULL && handler_calls > calls0);

    /* the status map */
    CHECK(ts_gsl_status(TS_OK) == GSL_SUCCESS);
    CHECK(ts_gsl_status(TS_ERR_NOMEM) == GSL_ENOMEM);
    const ts_status edom[] = {TS_ERR_DOMAIN, TS_ERR_NEGATIVE, TS_ERR_NONMONOTONE, TS_ERR_SIDE,
                              TS_ERR_LINES, TS_ERR_INFEASIBLE, TS_ERR_ZERO_SLOPE};
    for (size_t k = 0; k < N_OF(edom); k++)
        CHECK(ts_gsl_status(edom[k]) == GSL_EDOM);
    int n_einval = 0;
    for (int k = 1; k < TS_STATUS_COUNT_; k++)
        n_einval += ts_gsl_status((ts_status)k) == GSL_EINVAL;
    CHECK(n_einval == TS_STATUS_COUNT_ - 1 - 1 - (int)N_OF(edom));
    CHECK(ts_gsl_status((ts_status)999) == GSL_EINVAL);
}

static void test_interp_and_configure(void)
{
    /* the low-level gsl_interp API with the caller's arrays */
    size_t n = N_OF(T1x);
    gsl_interp *it = gsl_interp_alloc(ts_gsl_interp_positive, n);
    gsl_interp_accel *acc = gsl_interp_accel_alloc();
    CHECK(it && acc);
    if (!it || !acc)
        return;
    CHECK(gsl_interp_init(it, T1x, T1f, n) == GSL_SUCCESS);
    ts_spline_options o;
    ts_spline_options_init(&o);
    o.shape = TS_SHAPE_POSITIVE;
    ts_spline *s = NULL;
    CHECK(ts_spline_new(T1x, T1f, n, &o, &s, NULL) == TS_OK);
    double v = 0, t = 1;
    CHECK(gsl_interp_eval_e(it, T1x, T1f, 4.2, acc, &v) == GSL_SUCCESS);
    ts_spline_eval(s, 4.2, NULL, &t);
    CHECK(v == t);
    CHECK(ts_spline_integral(s, 1.0, 29.0, &t) == TS_OK);
    CHECK(gsl_interp_eval_integ(it, T1x, T1f, 1.0, 29.0, acc) == t);
    ts_spline_free(s);
    s = NULL;

    /* configure: the paper's Figure 4c alpha = 0.15, then back to defaults */
    o.alpha = 0.15;
    CHECK(ts_gsl_configure(it, &o) == GSL_SUCCESS);
    CHECK(gsl_interp_init(it, T1x, T1f, n) == GSL_SUCCESS);
    CHECK(ts_spline_new(T1x, T1f, n, &o, &s, NULL) == TS_OK);
    const ts_spline *g = ts_gsl_spline(it);
    CHECK(g && ts_spline_alpha(g)[0] == 0.15 && ts_spline_certified(g));
    long bad = 0, differ = 0;
    for (int j = 0; j <= 300; j++) {
        double q = 30.0 * j / 300.0;
        gsl_interp_eval_e(it, T1x, T1f, q, acc, &v);
        ts_spline_eval(s, q, NULL, &t);
        bad += !(v == t);
    }
    CHECK(bad == 0);
    CHECK(ts_gsl_configure(it, NULL) == GSL_SUCCESS);
    CHECK(gsl_interp_init(it, T1x, T1f, n) == GSL_SUCCESS);
    g = ts_gsl_spline(it);
    CHECK(g && ts_spline_alpha(g)[0] == TS_DEFAULT_ALPHA);
    for (int j = 0; j <= 300; j++) {
        double q = 30.0 * j / 300.0;
        gsl_interp_eval_e(it, T1x, T1f, q, acc, &v);
        ts_spline_eval(s, q, NULL, &t);
        differ += fabs(v - t) > 1e-3; /* alpha 1 vs 0.15: visibly different curves */
    }
    CHECK(differ > 100);
    ts_spline_free(s);

    /* configure rejects foreign objects and bad enums */
    ts_spline_options bad_o;
    ts_spline_options_init(&bad_o);
    bad_o.shape = (ts_shape)42;
    CHECK(ts_gsl_configure(it, &bad_o) == GSL_EINVAL);
    CHECK(ts_gsl_configure(NULL, &o) == GSL_EINVAL);
    gsl_interp *lin = gsl_interp_alloc(gsl_interp_linear, n);
    CHECK(lin && ts_gsl_configure(lin, &o) == GSL_EINVAL);
    CHECK(lin && gsl_interp_init(lin, T1x, T1f, n) == GSL_SUCCESS);
    CHECK(ts_gsl_spline(lin) == NULL && ts_gsl_spline(NULL) == NULL);
    ts_error e;
    CHECK(ts_gsl_last_error(lin, &e) == TS_ERR_NULL && e.status == TS_ERR_NULL);
    CHECK(ts_gsl_last_error(NULL, NULL) == TS_ERR_NULL);
    CHECK(!ts_gsl_is_trigspline(gsl_interp_cspline) && !ts_gsl_is_trigspline(NULL));
    gsl_interp_free(lin);

    /* a configured option the scheme refuses: a line the data cross */
    ts_spline_options_init(&o);
    o.shape = TS_SHAPE_ABOVE;
    o.lower.m = 0.0;
    o.lower.c = 1.6;
    CHECK(ts_gsl_configure(it, &o) == GSL_SUCCESS);
    CHECK(gsl_interp_init(it, T1x, T1f, n) == GSL_EDOM);
    CHECK(ts_gsl_last_error(it, &e) == TS_ERR_SIDE && e.index == 1);
    gsl_interp_free(it);
    gsl_interp_accel_free(acc);
}

int main(void)
{
    gsl_set_error_handler(&count_handler);
    test_compare();
    test_shape();
    test_errors();
    test_interp_and_configure();
    return th_report("test_gsl_adapter");
}
