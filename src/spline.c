/* Construction, accessors and status strings (SPEC §1, §3). */
#define _DEFAULT_SOURCE /* MADV_HUGEPAGE */
#include "ts_internal.h"

#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>
#if defined(__linux__)
#include <sys/mman.h>
#endif

const char *ts_version(void)
{
    return "0.1.0";
}

static const char *const ts_messages[TS_STATUS_COUNT_] = {
    [TS_OK] = "success",
    [TS_ERR_NULL] = "a required pointer argument is NULL",
    [TS_ERR_NOMEM] = "out of memory",
    [TS_ERR_OVERFLOW] = "size overflow: too many points",
    [TS_ERR_TOO_FEW] = "too few points: at least 2 are needed",
    [TS_ERR_NONFINITE] = "NaN or infinite value in the input",
    [TS_ERR_UNSORTED] = "x values are not strictly increasing (unsorted or duplicate)",
    [TS_ERR_ALPHA] = "alpha must be finite and > 0",
    [TS_ERR_BETA] = "beta must be finite and >= 0, and alpha + beta > 0",
    [TS_ERR_MARGIN] = "margin must be finite and > 0",
    [TS_ERR_LENGTH] = "a per-interval or per-point array has the wrong length",
    [TS_ERR_OPTION] = "invalid option value or combination",
    [TS_ERR_PERIODIC] = "periodic slopes need the first and last values equal",
    [TS_ERR_DOMAIN] = "query is NaN or outside the data range",
    [TS_ERR_NEGATIVE] = "negative data value for the positive scheme",
    [TS_ERR_SIDE] = "a data point lies on or across a constraint line",
    [TS_ERR_LINES] = "the lower line is not strictly below the upper line at a data point",
    [TS_ERR_NONMONOTONE] = "data are not monotone",
    [TS_ERR_INFEASIBLE] = "no beta keeps this interval inside the region",
    [TS_ERR_VIOLATED] = "the spline leaves the region on some interval",
    [TS_ERR_GEOMETRIC] = "alpha + beta below the geometric-form bound",
    [TS_ERR_DIMENSION] = "curve dimension must be 2 or 3",
    [TS_ERR_INDEX] = "index out of range",
    [TS_ERR_ZERO_SLOPE] = "slope of the wrong sign at a knot on the boundary",
};

const char *ts_strerror(ts_status status)
{
    if ((unsigned)status < (unsigned)TS_STATUS_COUNT_ && ts_messages[status])
        return ts_messages[status];
    return "unknown status code";
}

void ts__error_set(ts_error *err, ts_status st, size_t index, ts_where where)
{
    if (err) {
        err->status = st;
        err->index = index;
        err->where = where;
    }
}

long ts__test_fail_alloc;

static int alloc_should_fail(void)
{
    return ts__test_fail_alloc > 0 && --ts__test_fail_alloc == 0;
}

void *ts__malloc(size_t bytes)
{
    return alloc_should_fail() ? NULL : malloc(bytes);
}

void *ts__calloc(size_t count, size_t size)
{
    return alloc_should_fail() ? NULL : calloc(count, size);
}

/* The spline's one block.  Large blocks are 2 MiB-aligned and marked for
 * transparent huge pages where Linux offers them: first-touch page faults
 * dominate construction time at large n (issue 6, bench/RESULTS.md), and huge
 * pages cut them severalfold.  Freed with free() either way. */
static void *alloc_block(size_t bytes)
{
#if defined(__linux__) && defined(MADV_HUGEPAGE)
    const size_t huge = (size_t)2 << 20;
    if (bytes >= 4 * huge && bytes <= SIZE_MAX - huge) {
        if (alloc_should_fail())
            return NULL;
        size_t rounded = (bytes + huge - 1) / huge * huge;
        void *p = aligned_alloc(huge, rounded);
        if (p) {
            (void)madvise(p, rounded, MADV_HUGEPAGE); /* advice only: failure is harmless */
            return p;
        }
        return malloc(bytes);
    }
#endif
    return ts__malloc(bytes);
}

/* Record and return a failure. */
static ts_status fail(ts_error *err, ts_status st, size_t index, ts_where where)
{
    ts__error_set(err, st, index, where);
    return st;
}

void ts_options_init(ts_options *opt)
{
    if (!opt)
        return;
    memset(opt, 0, sizeof *opt);
    opt->form = TS_FORM_PAPER;
    opt->slopes = TS_SLOPES_ARITHMETIC;
    opt->alpha = 1.0;
    opt->beta = 0.0;
    opt->shape = TS_SHAPE_NONE;
    opt->margin = TS_DEFAULT_MARGIN;
    opt->certify = 1;
    opt->extrapolate = TS_EXTRAP_ERROR;
}

/* SPEC §3 (paper, C¹) and §4 (geometric) control values.  One loop per form,
 * through restrict-qualified locals (no reloads through possible aliases;
 * construction speed, issue 6); the arithmetic is the same expression by
 * expression. */
void ts__controls(ts_spline *sp, size_t i0, size_t i1)
{
    const double K0 = 2.0 / (3.0 * TS_PI);
    size_t n = sp->n;
    if (i1 > n)
        i1 = n;
    const double *restrict x = sp->x, *restrict f = sp->f, *restrict d = sp->d;
    const double *restrict h = sp->h, *restrict al = sp->alpha, *restrict be = sp->beta;
    double *restrict b1 = sp->b1, *restrict b2 = sp->b2;
    double *restrict xc1 = sp->xc1, *restrict xc2 = sp->xc2;
    if (sp->form == TS_FORM_C1) {
        for (size_t i = i0; i < i1; i++) {
            double K = K0 * h[i];
            double a = al[i] + be[i];
            /* SPEC §3 C¹ option: d̂_j = d_j / max(a_{j-1}, a_j), one-sided at the ends */
            double aL = a, aR = a;
            if (i > 0) {
                double ap = al[i - 1] + be[i - 1];
                aL = ap > a ? ap : a;
            }
            if (i + 1 < n) {
                double an = al[i + 1] + be[i + 1];
                aR = an > a ? an : a;
            }
            b1[i] = f[i] + K * (d[i] / aL);
            b2[i] = f[i + 1] - K * (d[i + 1] / aR);
            xc1[i] = x[i] + K;
            xc2[i] = x[i + 1] - K;
        }
    } else if (sp->form == TS_FORM_GEOMETRIC) {
        for (size_t i = i0; i < i1; i++) {
            double k = K0 * h[i] / (al[i] + be[i]);
            b1[i] = f[i] + k * d[i];
            b2[i] = f[i + 1] - k * d[i + 1];
            /* SPEC §4: X = [x_i, x_i + k, x_{i+1} - k, x_{i+1}] */
            xc1[i] = x[i] + k;
            xc2[i] = x[i + 1] - k;
        }
    } else {
        for (size_t i = i0; i < i1; i++) {
            double K = K0 * h[i];
            double k = K / (al[i] + be[i]);
            b1[i] = f[i] + k * d[i];
            b2[i] = f[i + 1] - k * d[i + 1];
            xc1[i] = x[i] + K;
            xc2[i] = x[i + 1] - K;
        }
    }
}

/* Overflow-checked a * b. */
static int mul_ok(size_t a, size_t b, size_t *r)
{
    if (b && a > SIZE_MAX / b)
        return 0;
    *r = a * b;
    return 1;
}

/* Fill a per-interval array from a scalar or an array of n values. */
static ts_status per_interval(double *dst, size_t n, double scalar, const double *arr,
                              size_t n_arr, ts_error *err)
{
    if (arr) {
        if (n_arr != n)
            return fail(err, TS_ERR_LENGTH, TS_NO_INDEX, TS_WHERE_NONE);
        memcpy(dst, arr, n * sizeof *dst);
    } else {
        for (size_t i = 0; i < n; i++)
            dst[i] = scalar;
    }
    return TS_OK;
}

static ts_status build(ts_spline *sp, const ts_options *o, ts_error *err)
{
    size_t n = sp->n, np = n + 1;
    ts_status st;

    /* SPEC §6: slopes */
    if (o->slopes == TS_SLOPES_USER) {
        if (!o->user_slopes)
            return fail(err, TS_ERR_NULL, TS_NO_INDEX, TS_WHERE_NONE);
        if (o->n_user_slopes != np)
            return fail(err, TS_ERR_LENGTH, TS_NO_INDEX, TS_WHERE_NONE);
        for (size_t i = 0; i < np; i++) {
            if (!isfinite(o->user_slopes[i]))
                return fail(err, TS_ERR_NONFINITE, i, TS_WHERE_POINT);
            sp->d[i] = o->user_slopes[i];
        }
    } else {
        if (o->slopes == TS_SLOPES_PERIODIC && !(sp->f[0] == sp->f[n]))
            return fail(err, TS_ERR_PERIODIC, n, TS_WHERE_POINT);
        st = ts__slopes(o->slopes, sp->x, sp->f, np, sp->d, err);
        if (st != TS_OK)
            return st;
    }

    st = per_interval(sp->alpha, n, o->alpha, o->alphas, o->n_alphas, err);
    if (st != TS_OK)
        return st;
    for (size_t i = 0; i < n; i++)
        if (!(sp->alpha[i] > 0.0 && isfinite(sp->alpha[i])))
            return fail(err, TS_ERR_ALPHA, i, TS_WHERE_INTERVAL);

    if (o->shape == TS_SHAPE_NONE) {
        st = per_interval(sp->beta, n, o->beta, o->betas, o->n_betas, err);
        if (st != TS_OK)
            return st;
        for (size_t i = 0; i < n; i++) {
            double b = sp->beta[i];
            if (!(b >= 0.0 && isfinite(b) && sp->alpha[i] + b > 0.0 &&
                  isfinite(sp->alpha[i] + b)))
                return fail(err, TS_ERR_BETA, i, TS_WHERE_INTERVAL);
            sp->term[i] = (unsigned char)TS_TERM_USER;
        }
    } else {
        st = ts__shape_apply(sp, o, err);
        if (st != TS_OK)
            return st;
    }

    if (sp->form == TS_FORM_GEOMETRIC) {
        st = ts__geo_check(sp, o, err);
        if (st != TS_OK)
            return st;
    }

    ts__controls(sp, 0, n);

    if (o->shape != TS_SHAPE_NONE) {
        st = ts__certify_build(sp, o, err);
        if (st != TS_OK)
            return st;
    }

    /* cumulative integrals for ts_integral (the running sum in a register:
     * the same additions in the same order, without a store-to-load chain) */
    double sum = 0.0;
    sp->cum[0] = sum;
    for (size_t i = 0; i < n; i++) {
        double whole;
        if (sp->form == TS_FORM_GEOMETRIC) {
            whole = ts__geo_integral(sp, i, sp->x[i + 1]);
        } else {
            /* ∫ A_l over [0, π/2]: 5π/4 - 11/3 (l = 0, 3), 11/3 - π (l = 1, 2) */
            const double e = 1.25 * TS_PI - 11.0 / 3.0, m = 11.0 / 3.0 - TS_PI;
            whole = (2.0 * sp->h[i] / TS_PI) *
                    (e * (sp->f[i] + sp->f[i + 1]) + m * (sp->b1[i] + sp->b2[i]));
        }
        sum += whole;
        sp->cum[i + 1] = sum;
    }

    ts__fast_prepare(sp);
    return TS_OK;
}

ts_status ts_spline_new(const double *x, const double *f, size_t n_points,
                        const ts_options *opt, ts_spline **out, ts_error *err)
{
    ts__error_set(err, TS_OK, TS_NO_INDEX, TS_WHERE_NONE);
    if (out)
        *out = NULL;
    if (!x || !f || !out)
        return fail(err, TS_ERR_NULL, TS_NO_INDEX, TS_WHERE_NONE);
    ts_options defaults;
    if (!opt) {
        ts_options_init(&defaults);
        opt = &defaults;
    }
    if (n_points < 2)
        return fail(err, TS_ERR_TOO_FEW, TS_NO_INDEX, TS_WHERE_NONE);
    if ((unsigned)opt->form > (unsigned)TS_FORM_GEOMETRIC ||
        (unsigned)opt->slopes >= (unsigned)TS_SLOPES_COUNT_ ||
        (unsigned)opt->shape > (unsigned)TS_SHAPE_MONOTONE ||
        (unsigned)opt->extrapolate > (unsigned)TS_EXTRAP_LINEAR)
        return fail(err, TS_ERR_OPTION, TS_NO_INDEX, TS_WHERE_NONE);

    /* layout: 5 arrays of n+1 (x, f, d, cum, spare), 11 of n, fast, term bytes */
    size_t n = n_points - 1, a, b, c, total, bytes;
    if (!mul_ok(n_points, 5, &a) || !mul_ok(n, 11 + TS_FAST_STRIDE, &b))
        return fail(err, TS_ERR_OVERFLOW, TS_NO_INDEX, TS_WHERE_NONE);
    total = a + b;
    if (total < a || !mul_ok(total, sizeof(double), &c) || c + n < c)
        return fail(err, TS_ERR_OVERFLOW, TS_NO_INDEX, TS_WHERE_NONE);
    bytes = c + n;

    for (size_t i = 0; i < n_points; i++)
        if (!isfinite(x[i]) || !isfinite(f[i]))
            return fail(err, TS_ERR_NONFINITE, i, TS_WHERE_POINT);
    for (size_t i = 1; i < n_points; i++)
        if (!(x[i] > x[i - 1]))
            return fail(err, TS_ERR_UNSORTED, i, TS_WHERE_POINT);
    for (size_t i = 0; i < n; i++)
        if (!isfinite(x[i + 1] - x[i]))
            return fail(err, TS_ERR_NONFINITE, i + 1, TS_WHERE_POINT);

    ts_spline *sp = ts__calloc(1, sizeof *sp);
    double *blk = sp ? alloc_block(bytes) : NULL;
    if (!blk) {
        free(sp);
        return fail(err, TS_ERR_NOMEM, TS_NO_INDEX, TS_WHERE_NONE);
    }
    sp->n = n;
    sp->form = opt->form;
    sp->shape = opt->shape;
    sp->extrap = opt->extrapolate;
    double *p = blk;
    sp->x = p, p += n_points;
    sp->f = p, p += n_points;
    sp->d = p, p += n_points;
    sp->cum = p, p += n_points;
    p += n_points; /* spare */
    sp->h = p, p += n;
    sp->alpha = p, p += n;
    sp->beta = p, p += n;
    sp->b1 = p, p += n;
    sp->b2 = p, p += n;
    sp->xc1 = p, p += n;
    sp->xc2 = p, p += n;
    sp->gap_lo = p, p += n;
    sp->at_lo = p, p += n;
    sp->gap_up = p, p += n;
    sp->at_up = p, p += n;
    sp->fast = p, p += n * TS_FAST_STRIDE;
    sp->term = (unsigned char *)p;
    memcpy(sp->x, x, n_points * sizeof *x);
    memcpy(sp->f, f, n_points * sizeof *f);
    for (size_t i = 0; i < n; i++) {
        sp->h[i] = x[i + 1] - x[i];
        sp->gap_lo[i] = sp->at_lo[i] = sp->gap_up[i] = sp->at_up[i] = NAN;
    }

    ts_status st = build(sp, opt, err);
    if (st != TS_OK) {
        ts_spline_free(sp);
        return st;
    }
    *out = sp;
    return TS_OK;
}

void ts_spline_free(ts_spline *s)
{
    if (!s)
        return;
    free(s->x);
    free(s);
}

size_t ts_spline_intervals(const ts_spline *s) { return s ? s->n : 0; }
const double *ts_spline_x(const ts_spline *s) { return s ? s->x : NULL; }
const double *ts_spline_f(const ts_spline *s) { return s ? s->f : NULL; }
const double *ts_spline_slopes(const ts_spline *s) { return s ? s->d : NULL; }
const double *ts_spline_alpha(const ts_spline *s) { return s ? s->alpha : NULL; }
const double *ts_spline_beta(const ts_spline *s) { return s ? s->beta : NULL; }
ts_form ts_spline_form(const ts_spline *s) { return s ? s->form : TS_FORM_PAPER; }
ts_shape ts_spline_shape(const ts_spline *s) { return s ? s->shape : TS_SHAPE_NONE; }
ts_extrap ts_spline_extrapolation(const ts_spline *s) { return s ? s->extrap : TS_EXTRAP_ERROR; }

ts_status ts_spline_a(const ts_spline *s, size_t i, double *a)
{
    if (a)
        *a = NAN;
    if (!s || !a)
        return TS_ERR_NULL;
    if (i >= s->n)
        return TS_ERR_INDEX;
    *a = s->alpha[i] + s->beta[i];
    return TS_OK;
}

ts_status ts_spline_control(const ts_spline *s, size_t i, double B[4], double X[4])
{
    if (B)
        B[0] = B[1] = B[2] = B[3] = NAN;
    if (X)
        X[0] = X[1] = X[2] = X[3] = NAN;
    if (!s || !B)
        return TS_ERR_NULL;
    if (i >= s->n)
        return TS_ERR_INDEX;
    ts__B(s, i, B);
    if (X) {
        X[0] = s->x[i];
        X[1] = s->xc1[i];
        X[2] = s->xc2[i];
        X[3] = s->x[i + 1];
    }
    return TS_OK;
}
