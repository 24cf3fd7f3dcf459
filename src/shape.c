/* SPEC §5: shape schemes choose beta_i.
 *
 * Order of checks (each error names the first offender): margins
 * (TS_ERR_LENGTH, TS_ERR_MARGIN/interval), lines (TS_ERR_NONFINITE), data vs
 * scheme point by point (TS_ERR_NEGATIVE, TS_ERR_LINES before TS_ERR_SIDE at
 * the same point, TS_ERR_NONMONOTONE), slopes at zero knots
 * (TS_ERR_ZERO_SLOPE, user slopes only).
 *
 * Slope adjustments (SPEC §5.1, §5.5):
 *  - positive, f_i = 0: inner knot d_i = 0; d_0 >= 0, d_n <= 0 at the ends
 *    (periodic slopes: the ends are one inner knot, d_0 = d_n = 0).  Estimated
 *    slopes are set so; user slopes that break it are refused with
 *    TS_ERR_ZERO_SLOPE (the user asked for a curve that must cross zero).
 *  - monotone: slopes of the wrong sign are set to 0 (user slopes too, as
 *    SPEC §5.5 says), and both slopes of a flat interval (Δ_i = 0) are 0.
 * Data on a line are refused (TS_ERR_SIDE): unlike y = 0 for positive data,
 * touching a sloped line cannot be kept in the paper form.
 */
#include "ts_internal.h"

#include <float.h>
#include <math.h>

/* beta is capped here; certify.c then checks (and repairs) the interval */
#define TS_BETA_CAP 1e300

static ts_status fail(ts_error *err, ts_status st, size_t index, ts_where where)
{
    ts__error_set(err, st, index, where);
    return st;
}

static double line_at(const ts_line *l, double x)
{
    return l->m * x + l->c;
}

static int line_finite(const ts_line *l)
{
    return isfinite(l->m) && isfinite(l->c);
}

/* Check the data against the scheme; first offending point. */
static ts_status check_data(const ts_spline *sp, ts_shape shape, ts_error *err)
{
    size_t np = sp->n + 1;
    const double *x = sp->x, *f = sp->f;
    if (shape == TS_SHAPE_POSITIVE) {
        for (size_t i = 0; i < np; i++)
            if (!(f[i] >= 0.0))
                return fail(err, TS_ERR_NEGATIVE, i, TS_WHERE_POINT);
        return TS_OK;
    }
    if (shape == TS_SHAPE_MONOTONE) {
        int dir = 0;
        for (size_t i = 1; i < np; i++) {
            double df = f[i] - f[i - 1];
            int s = (df > 0.0) - (df < 0.0);
            if (s == 0)
                continue;
            if (dir == 0)
                dir = s;
            else if (s != dir)
                return fail(err, TS_ERR_NONMONOTONE, i, TS_WHERE_POINT);
        }
        return TS_OK;
    }
    for (size_t i = 0; i < np; i++) {
        double lo = sp->has_lower ? line_at(&sp->lower, x[i]) : 0.0;
        double up = sp->has_upper ? line_at(&sp->upper, x[i]) : 0.0;
        if (sp->has_lower && sp->has_upper && !(lo < up))
            return fail(err, TS_ERR_LINES, i, TS_WHERE_POINT);
        if (sp->has_lower && !(f[i] - lo > 0.0))
            return fail(err, TS_ERR_SIDE, i, TS_WHERE_POINT);
        if (sp->has_upper && !(up - f[i] > 0.0))
            return fail(err, TS_ERR_SIDE, i, TS_WHERE_POINT);
    }
    return TS_OK;
}

/* SPEC §5.1: zero knots of non-negative data. */
static ts_status zero_slopes(ts_spline *sp, const ts_options *opt, ts_error *err)
{
    size_t n = sp->n;
    int user = opt->slopes == TS_SLOPES_USER;
    int periodic = opt->slopes == TS_SLOPES_PERIODIC;
    double *d = sp->d;
    for (size_t i = 0; i <= n; i++) {
        if (sp->f[i] != 0.0)
            continue;
        int inner = (i > 0 && i < n) || periodic;
        int bad = inner ? d[i] != 0.0 : (i == 0 ? d[i] < 0.0 : d[i] > 0.0);
        if (!bad)
            continue;
        if (user)
            return fail(err, TS_ERR_ZERO_SLOPE, i, TS_WHERE_POINT);
        d[i] = 0.0;
    }
    if (periodic && sp->f[0] == 0.0)
        d[0] = d[n] = 0.0;
    return TS_OK;
}

/* SPEC §5.5: wrong-sign slopes to 0, flat intervals get zero slopes. */
static void monotone_slopes(ts_spline *sp)
{
    size_t n = sp->n;
    double *d = sp->d, *f = sp->f;
    int dir = 0;
    for (size_t i = 0; i < n && dir == 0; i++)
        dir = (f[i + 1] > f[i]) - (f[i + 1] < f[i]);
    for (size_t i = 0; i <= n; i++)
        if (dir * d[i] < 0.0 || dir == 0)
            d[i] = 0.0;
    for (size_t i = 0; i < n; i++)
        if (f[i + 1] == f[i])
            d[i] = d[i + 1] = 0.0;
}

ts_status ts__shape_apply(ts_spline *sp, const ts_options *opt, ts_error *err)
{
    if (!sp || !opt)
        return fail(err, TS_ERR_NULL, TS_NO_INDEX, TS_WHERE_NONE);
    ts_shape shape = opt->shape;
    if (!(shape == TS_SHAPE_POSITIVE || shape == TS_SHAPE_ABOVE || shape == TS_SHAPE_BELOW ||
          shape == TS_SHAPE_BETWEEN || shape == TS_SHAPE_MONOTONE))
        return fail(err, TS_ERR_OPTION, TS_NO_INDEX, TS_WHERE_NONE);
    size_t n = sp->n;

    /* margins t_i of SPEC §5 */
    if (opt->margins && opt->n_margins != n)
        return fail(err, TS_ERR_LENGTH, TS_NO_INDEX, TS_WHERE_NONE);
    for (size_t i = 0; i < n; i++) {
        double t = opt->margins ? opt->margins[i] : opt->margin;
        if (!(t > 0.0 && t <= DBL_MAX))
            return fail(err, TS_ERR_MARGIN, i, TS_WHERE_INTERVAL);
    }

    /* boundaries */
    sp->has_lower = shape == TS_SHAPE_POSITIVE || shape == TS_SHAPE_ABOVE ||
                    shape == TS_SHAPE_BETWEEN;
    sp->has_upper = shape == TS_SHAPE_BELOW || shape == TS_SHAPE_BETWEEN;
    sp->lower.m = sp->lower.c = 0.0;
    sp->upper.m = sp->upper.c = 0.0;
    if (shape == TS_SHAPE_ABOVE || shape == TS_SHAPE_BETWEEN) {
        if (!line_finite(&opt->lower))
            return fail(err, TS_ERR_NONFINITE, TS_NO_INDEX, TS_WHERE_NONE);
        sp->lower = opt->lower;
    }
    if (shape == TS_SHAPE_BELOW || shape == TS_SHAPE_BETWEEN) {
        if (!line_finite(&opt->upper))
            return fail(err, TS_ERR_NONFINITE, TS_NO_INDEX, TS_WHERE_NONE);
        sp->upper = opt->upper;
    }

    ts_status st = check_data(sp, shape, err);
    if (st != TS_OK)
        return st;
    if (shape == TS_SHAPE_POSITIVE) {
        st = zero_slopes(sp, opt, err);
        if (st != TS_OK)
            return st;
    } else if (shape == TS_SHAPE_MONOTONE) {
        monotone_slopes(sp);
    }

    /* SPEC §5: beta_i = t_i + max{0, terms}; zero-gap knots drop their term */
    const double K0 = 2.0 / (3.0 * TS_PI);
    const double *x = sp->x, *f = sp->f, *d = sp->d;
    for (size_t i = 0; i < n; i++) {
        double t = opt->margins ? opt->margins[i] : opt->margin;
        double al = sp->alpha[i], K = K0 * sp->h[i];
        double best = 0.0, v;
        ts_term term = TS_TERM_MARGIN;
#define TS_CONSIDER(val, code)                                                 \
    do {                                                                       \
        v = (val);                                                             \
        if (v > best) {                                                        \
            best = v;                                                          \
            term = (code);                                                     \
        }                                                                      \
    } while (0)
        if (sp->has_lower) {
            /* SPEC §5 lower boundary: B1 - l > 0, B2 - l > 0 */
            double g0 = f[i] - line_at(&sp->lower, x[i]);
            double g1 = f[i + 1] - line_at(&sp->lower, x[i + 1]);
            /* SPEC §4: geometric form, exact conditions Y_l - m X_l - c > 0 */
            double ml = sp->form == TS_FORM_GEOMETRIC ? sp->lower.m : 0.0;
            if (g0 > 0.0)
                TS_CONSIDER(-al - K * (d[i] - ml) / g0, TS_TERM_LOWER_LEFT);
            if (g1 > 0.0)
                TS_CONSIDER(-al + K * (d[i + 1] - ml) / g1, TS_TERM_LOWER_RIGHT);
        }
        if (sp->has_upper) {
            /* SPEC §5 upper boundary, corrected signs (§5.3) */
            double G0 = line_at(&sp->upper, x[i]) - f[i];
            double G1 = line_at(&sp->upper, x[i + 1]) - f[i + 1];
            double mu = sp->form == TS_FORM_GEOMETRIC ? sp->upper.m : 0.0;
            if (G0 > 0.0)
                TS_CONSIDER(-al + K * (d[i] - mu) / G0, TS_TERM_UPPER_LEFT);
            if (G1 > 0.0)
                TS_CONSIDER(-al - K * (d[i + 1] - mu) / G1, TS_TERM_UPPER_RIGHT);
        }
        if (shape == TS_SHAPE_MONOTONE) {
            /* SPEC §5.5: a_i >= 2(d_i + d_{i+1}) / (3π Δ_i) */
            double df = f[i + 1] - f[i];
            if (df != 0.0)
                TS_CONSIDER(K * (d[i] + d[i + 1]) / df - al, TS_TERM_MONOTONE);
        }
#undef TS_CONSIDER
        double beta = t + best;
        if (!(beta <= TS_BETA_CAP))
            beta = TS_BETA_CAP;
        if (!(al + beta <= DBL_MAX)) /* alpha near DBL_MAX: keep a_i finite */
            beta = DBL_MAX - al;
        sp->beta[i] = beta;
        sp->term[i] = (unsigned char)term;
    }
    return TS_OK;
}
