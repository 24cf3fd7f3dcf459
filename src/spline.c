/* Construction, accessors and status strings (SPEC §1, §3). */
#define _DEFAULT_SOURCE /* MADV_HUGEPAGE */
#include "internal.h"

#include <float.h>
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

#ifdef TS_TEST_HOOKS
long ts__test_fail_alloc;

static int alloc_should_fail(void)
{
    return ts__test_fail_alloc > 0 && --ts__test_fail_alloc == 0;
}
#else
static int alloc_should_fail(void)
{
    return 0;
}
#endif

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

/* SPEC §3 (paper, C¹) and §4 (geometric) control values, one loop per form
 * with the arrays as restrict parameters, so that they vectorise (issue 6). */
#define TS_K0 (2.0 / (3.0 * TS_PI))

TS_VECTOR_LOOP static void controls_paper(const double *restrict f, const double *restrict d,
                                          const double *restrict h, const double *restrict al,
                                          const double *restrict be, double *restrict b1,
                                          double *restrict b2, size_t i0, size_t i1)
{
    for (size_t i = i0; i < i1; i++) {
        double K = TS_K0 * h[i];
        double k = K / (al[i] + be[i]);
        b1[i] = f[i] + k * d[i];
        b2[i] = f[i + 1] - k * d[i + 1];
    }
}

TS_VECTOR_LOOP static void controls_geo(const double *restrict x, const double *restrict f,
                                        const double *restrict d, const double *restrict h,
                                        const double *restrict al, const double *restrict be,
                                        double *restrict b1, double *restrict b2,
                                        double *restrict xc1, double *restrict xc2, size_t i0,
                                        size_t i1)
{
    for (size_t i = i0; i < i1; i++) {
        double k = TS_K0 * h[i] / (al[i] + be[i]);
        b1[i] = f[i] + k * d[i];
        b2[i] = f[i + 1] - k * d[i + 1];
        /* SPEC §4: X = [x_i, x_i + k, x_{i+1} - k, x_{i+1}] */
        xc1[i] = x[i] + k;
        xc2[i] = x[i + 1] - k;
    }
}

/* SPEC §3 C¹ option: d̂_j = d_j / max(a_{j-1}, a_j), one-sided at the ends;
 * intervals [i0, i1) with both neighbours (0 < i0, i1 < n). */
TS_VECTOR_LOOP static void controls_c1(const double *restrict f, const double *restrict d,
                                       const double *restrict h, const double *restrict al,
                                       const double *restrict be, double *restrict b1,
                                       double *restrict b2, size_t i0, size_t i1)
{
    for (size_t i = i0; i < i1; i++) {
        double K = TS_K0 * h[i];
        double a = al[i] + be[i], ap = al[i - 1] + be[i - 1], an = al[i + 1] + be[i + 1];
        double aL = ap > a ? ap : a, aR = an > a ? an : a;
        b1[i] = f[i] + K * (d[i] / aL);
        b2[i] = f[i + 1] - K * (d[i + 1] / aR);
    }
}

/* The same for one interval, also at an end. */
static void controls_c1_one(ts_spline *sp, size_t i)
{
    size_t n = sp->n;
    const double *al = sp->alpha, *be = sp->beta;
    double K = TS_K0 * sp->h[i];
    double a = al[i] + be[i];
    double aL = a, aR = a;
    if (i > 0) {
        double ap = al[i - 1] + be[i - 1];
        aL = ap > a ? ap : a;
    }
    if (i + 1 < n) {
        double an = al[i + 1] + be[i + 1];
        aR = an > a ? an : a;
    }
    sp->b1[i] = sp->f[i] + K * (sp->d[i] / aL);
    sp->b2[i] = sp->f[i + 1] - K * (sp->d[i + 1] / aR);
}

void ts__controls(ts_spline *sp, size_t i0, size_t i1)
{
    size_t n = sp->n;
    if (i1 > n)
        i1 = n;
    if (i0 >= i1)
        return;
    if (sp->form == TS_FORM_C1) {
        size_t m0 = i0 > 0 ? i0 : 1, m1 = i1 < n ? i1 : n - 1; /* both neighbours */
        if (i0 == 0)
            controls_c1_one(sp, 0);
        if (m0 < m1)
            controls_c1(sp->f, sp->d, sp->h, sp->alpha, sp->beta, sp->b1, sp->b2, m0, m1);
        if (i1 == n && n - 1 > 0)
            controls_c1_one(sp, n - 1);
    } else if (sp->form == TS_FORM_GEOMETRIC) {
        controls_geo(sp->x, sp->f, sp->d, sp->h, sp->alpha, sp->beta, sp->b1, sp->b2, sp->xc1,
                     sp->xc2, i0, i1);
    } else {
        controls_paper(sp->f, sp->d, sp->h, sp->alpha, sp->beta, sp->b1, sp->b2, i0, i1);
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

/* Fill dst[i0..i1) from a scalar or an array (of the right length). */
TS_VECTOR_LOOP static void fill(double *restrict dst, size_t i0, size_t i1, double scalar,
                                const double *restrict arr)
{
    if (arr) {
        memcpy(dst + i0, arr + i0, (i1 - i0) * sizeof *dst);
    } else {
        for (size_t i = i0; i < i1; i++)
            dst[i] = scalar;
    }
}

/* 1 if every v[i0..i1) is finite (a flag, so that it vectorises). */
TS_VECTOR_LOOP static int all_finite(const double *restrict v, size_t i0, size_t i1)
{
    int ok = 1;
    for (size_t i = i0; i < i1; i++)
        ok &= fabs(v[i]) <= DBL_MAX;
    return ok;
}

/* 1 if every alpha_i, i in [i0, i1), is finite and > 0. */
TS_VECTOR_LOOP static int alpha_ok(const double *restrict al, size_t i0, size_t i1)
{
    int ok = 1;
    for (size_t i = i0; i < i1; i++)
        ok &= (al[i] > 0.0) & (al[i] <= DBL_MAX);
    return ok;
}

/* h_i = x_{i+1} - x_i, i in [i0, i1). */
TS_VECTOR_LOOP static void widths(const double *restrict x, double *restrict h, size_t i0,
                                  size_t i1)
{
    for (size_t i = i0; i < i1; i++)
        h[i] = x[i + 1] - x[i];
}

/* Points [*done, upto) of x, f into sp, and the widths that completes. */
static void copy_points(ts_spline *sp, const double *x, const double *f, size_t *done, size_t upto)
{
    size_t p0 = *done;
    if (upto <= p0)
        return;
    memcpy(sp->x + p0, x + p0, (upto - p0) * sizeof *x);
    memcpy(sp->f + p0, f + p0, (upto - p0) * sizeof *f);
    widths(x, sp->h, p0 ? p0 - 1 : 0, upto - 1);
    *done = upto;
}

/* SPEC §6 user slopes, points [p0, p1) (array checked non-NULL, length np). */
static ts_status user_slopes(ts_spline *sp, const ts_options *o, size_t p0, size_t p1,
                             ts_error *err)
{
    for (size_t i = p0; i < p1; i++) {
        if (!isfinite(o->user_slopes[i]))
            return fail(err, TS_ERR_NONFINITE, i, TS_WHERE_POINT);
        sp->d[i] = o->user_slopes[i];
    }
    return TS_OK;
}

static ts_status check_alpha(const ts_spline *sp, size_t i0, size_t i1, ts_error *err)
{
    if (alpha_ok(sp->alpha, i0, i1))
        return TS_OK;
    for (size_t i = i0; i < i1; i++)
        if (!(sp->alpha[i] > 0.0 && isfinite(sp->alpha[i])))
            return fail(err, TS_ERR_ALPHA, i, TS_WHERE_INTERVAL);
    return TS_OK;
}

/* 1 if beta_i is valid for every i in [i0, i1) (check_beta's test); term USER. */
TS_VECTOR_LOOP static int beta_ok(const double *restrict al, const double *restrict be,
                                  unsigned char *restrict term, size_t i0, size_t i1)
{
    int ok = 1;
    for (size_t i = i0; i < i1; i++) {
        double b = be[i], a = al[i] + b;
        ok &= (b >= 0.0) & (b <= DBL_MAX) & (a > 0.0) & (a <= DBL_MAX);
        term[i] = (unsigned char)TS_TERM_USER;
    }
    return ok;
}

/* TS_SHAPE_NONE: the caller's beta (filled), checked; term USER. */
static ts_status check_beta(ts_spline *sp, size_t i0, size_t i1, ts_error *err)
{
    if (beta_ok(sp->alpha, sp->beta, sp->term, i0, i1))
        return TS_OK;
    for (size_t i = i0; i < i1; i++) {
        double b = sp->beta[i];
        if (!(b >= 0.0 && isfinite(b) && sp->alpha[i] + b > 0.0 && isfinite(sp->alpha[i] + b)))
            return fail(err, TS_ERR_BETA, i, TS_WHERE_INTERVAL);
        sp->term[i] = (unsigned char)TS_TERM_USER;
    }
    return TS_OK;
}

/* ∫ of interval i, i in [i0, i1), into cum[i + 1] (paper and C¹ forms). */
TS_VECTOR_LOOP static void wholes(const double *restrict h, const double *restrict f,
                                  const double *restrict b1, const double *restrict b2,
                                  double *restrict cum, size_t i0, size_t i1)
{
    /* ∫ A_l over [0, π/2]: 5π/4 - 11/3 (l = 0, 3), 11/3 - π (l = 1, 2) */
    const double e = 1.25 * TS_PI - 11.0 / 3.0, m = 11.0 / 3.0 - TS_PI;
    for (size_t i = i0; i < i1; i++)
        cum[i + 1] = (2.0 * h[i] / TS_PI) * (e * (f[i] + f[i + 1]) + m * (b1[i] + b2[i]));
}

/* Cumulative integrals cum[i0+1..i1] for ts_integral from the running sum
 * (cum[i0]), which it returns: the same additions in the same order. */
static double cumulate(ts_spline *sp, size_t i0, size_t i1, double sum)
{
    double *cum = sp->cum;
    if (sp->form == TS_FORM_GEOMETRIC) {
        for (size_t i = i0; i < i1; i++)
            cum[i + 1] = ts__geo_integral(sp, i, sp->x[i + 1]);
    } else {
        wholes(sp->h, sp->f, sp->b1, sp->b2, cum, i0, i1);
    }
    for (size_t i = i0; i < i1; i++) {
        sum += cum[i + 1];
        cum[i + 1] = sum;
    }
    return sum;
}

/* Intervals per block of the blocked construction: its dozen arrays stay in
 * the L2 cache (~100 KiB) from the slopes to the integrals. */
#define TS_BLOCK 1024

/* The paper form in blocks: every step of build() on TS_BLOCK intervals at a
 * time while their arrays are in cache, instead of one pass over all n per
 * step (issue 6: memory traffic dominated).  In the paper form each interval
 * depends only on its own knots (the slopes on the neighbours, read from the
 * caller's x, f), so every value is the one build() computes.  Returns TS_OK,
 * or anything else on any error (the errors of a block need not come in
 * build()'s order): build() then starts over in order and reports it. */
static ts_status build_blocked(ts_spline *sp, const ts_options *o, const double *x, const double *f,
                               size_t *done)
{
    size_t n = sp->n, np = n + 1;
    int user = o->slopes == TS_SLOPES_USER, shaped = o->shape != TS_SHAPE_NONE, dir = 0;
    ts_status st = TS_OK;
    if (user ? !o->user_slopes || o->n_user_slopes != np
             : o->slopes == TS_SLOPES_PERIODIC && !(f[0] == f[n]))
        return TS_ERR_OPTION;
    if ((o->alphas && o->n_alphas != n) || (!shaped && o->betas && o->n_betas != n))
        return TS_ERR_LENGTH;
    if (shaped && (st = ts__shape_begin(sp, o, f, &dir, NULL)) != TS_OK)
        return st;
    double sum = 0.0;
    sp->cum[0] = sum;
    for (size_t i0 = 0; i0 < n; i0 += TS_BLOCK) {
        size_t i1 = n - i0 > TS_BLOCK ? i0 + TS_BLOCK : n;
        /* points p0..i1: d_{i1} is needed for interval i1 - 1 */
        size_t p0 = i0 ? i0 + 1 : 0, p1 = i1 + 1;
        copy_points(sp, x, f, done, i1 + 2 < np ? i1 + 2 : np);
        if (user) {
            st = user_slopes(sp, o, p0, p1, NULL);
        } else {
            ts__slopes_range(o->slopes, x, f, np, sp->d, p0, p1);
            if (!all_finite(sp->d, p0, p1))
                st = TS_ERR_NONFINITE;
        }
        if (st != TS_OK)
            return st;
        fill(sp->alpha, i0, i1, o->alpha, o->alphas);
        if ((st = check_alpha(sp, i0, i1, NULL)) != TS_OK)
            return st;
        if (!shaped) {
            fill(sp->beta, i0, i1, o->beta, o->betas);
            st = check_beta(sp, i0, i1, NULL);
        } else {
            st = ts__shape_range(sp, o, dir, p0, p1, i0, i1, NULL);
        }
        if (st != TS_OK)
            return st;
        ts__controls(sp, i0, i1);
        if (shaped && (st = ts__certify_range(sp, o, i0, i1, NULL)) != TS_OK)
            return st;
        sum = cumulate(sp, i0, i1, sum);
    }
    if (shaped)
        ts__certify_done(sp, o);
    ts__fast_prepare(sp);
    return TS_OK;
}

static ts_status build_all(ts_spline *sp, const ts_options *o, const double *x, const double *f,
                           ts_error *err)
{
    size_t n = sp->n, np = n + 1, done = 0;
    ts_status st;

    if (o->form == TS_FORM_PAPER && build_blocked(sp, o, x, f, &done) == TS_OK)
        return TS_OK;
    /* other forms, or an error: step by step over all n (the first error) */
    copy_points(sp, x, f, &done, np);

    /* SPEC §6: slopes */
    if (o->slopes == TS_SLOPES_USER) {
        if (!o->user_slopes)
            return fail(err, TS_ERR_NULL, TS_NO_INDEX, TS_WHERE_NONE);
        if (o->n_user_slopes != np)
            return fail(err, TS_ERR_LENGTH, TS_NO_INDEX, TS_WHERE_NONE);
        st = user_slopes(sp, o, 0, np, err);
        if (st != TS_OK)
            return st;
    } else {
        if (o->slopes == TS_SLOPES_PERIODIC && !(sp->f[0] == sp->f[n]))
            return fail(err, TS_ERR_PERIODIC, n, TS_WHERE_POINT);
        st = ts__slopes(o->slopes, sp->x, sp->f, np, sp->d, err);
        if (st != TS_OK)
            return st;
    }

    if (o->alphas && o->n_alphas != n)
        return fail(err, TS_ERR_LENGTH, TS_NO_INDEX, TS_WHERE_NONE);
    fill(sp->alpha, 0, n, o->alpha, o->alphas);
    st = check_alpha(sp, 0, n, err);
    if (st != TS_OK)
        return st;

    if (o->shape == TS_SHAPE_NONE) {
        if (o->betas && o->n_betas != n)
            return fail(err, TS_ERR_LENGTH, TS_NO_INDEX, TS_WHERE_NONE);
        fill(sp->beta, 0, n, o->beta, o->betas);
        st = check_beta(sp, 0, n, err);
    } else {
        st = ts__shape_apply(sp, o, err);
    }
    if (st != TS_OK)
        return st;

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

    sp->cum[0] = 0.0;
    (void)cumulate(sp, 0, n, 0.0);
    ts__fast_prepare(sp);
    return TS_OK;
}

/* The build, then: control values must be finite (a tiny a_i with a large
 * slope can overflow B1, B2; no shape scheme to catch it).  An integral that
 * overflows is not an error: ts_integral then returns ±Inf. */
static ts_status build(ts_spline *sp, const ts_options *o, const double *x, const double *f,
                       ts_error *err)
{
    ts_status st = build_all(sp, o, x, f, err);
    if (st != TS_OK)
        return st;
    for (size_t i = 0; i < sp->n; i++)
        if (!(fabs(sp->b1[i]) <= DBL_MAX && fabs(sp->b2[i]) <= DBL_MAX))
            return fail(err, TS_ERR_NONFINITE, i, TS_WHERE_INTERVAL);
    return TS_OK;
}

/* x, f finite, x strictly increasing with finite widths: one pass for the
 * common case (ts_spline_new's ordered checks name the first offender). */
TS_VECTOR_LOOP static int points_ok(const double *restrict x, const double *restrict f, size_t i0,
                                    size_t i1)
{
    int ok = 1;
    for (size_t i = i0; i < i1; i++)
        ok &= (fabs(x[i]) <= DBL_MAX) & (fabs(f[i]) <= DBL_MAX) & (x[i] > x[i - 1]) &
              (x[i] - x[i - 1] <= DBL_MAX) & (x[i] - x[i - 1] >= DBL_MIN);
    return ok;
}

static int points_valid(const double *x, const double *f, size_t np)
{
    int ok = fabs(x[0]) <= DBL_MAX && fabs(f[0]) <= DBL_MAX;
    for (size_t i0 = 1; i0 < np && ok; i0 += 4096)
        ok = points_ok(x, f, i0, np - i0 > 4096 ? i0 + 4096 : np);
    return ok;
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

    /* layout: 4 arrays of n+1 (x, f, d, cum), 5 of n (h, alpha, beta, b1, b2),
     * 2 of n for the geometric form's X (xc1, xc2), fast, term bytes.  Only
     * what is used: every byte per knot costs construction time (issue 6). */
    int geo = opt->form == TS_FORM_GEOMETRIC;
    size_t per_interval_arrays = 5 + (size_t)(2 * geo) + TS_FAST_STRIDE;
    size_t n = n_points - 1, a, b, c, total, bytes;
    if (!mul_ok(n_points, 4, &a) || !mul_ok(n, per_interval_arrays, &b))
        return fail(err, TS_ERR_OVERFLOW, TS_NO_INDEX, TS_WHERE_NONE);
    total = a + b;
    if (total < a || !mul_ok(total, sizeof(double), &c) || c + n < c)
        return fail(err, TS_ERR_OVERFLOW, TS_NO_INDEX, TS_WHERE_NONE);
    bytes = c + n;

    if (!points_valid(x, f, n_points)) {
        for (size_t i = 0; i < n_points; i++)
            if (!isfinite(x[i]) || !isfinite(f[i]))
                return fail(err, TS_ERR_NONFINITE, i, TS_WHERE_POINT);
        for (size_t i = 1; i < n_points; i++)
            if (!(x[i] > x[i - 1]))
                return fail(err, TS_ERR_UNSORTED, i, TS_WHERE_POINT);
        /* widths must be finite and normal: dθ/dx = (π/2)/h must not overflow */
        for (size_t i = 0; i < n; i++)
            if (!(x[i + 1] - x[i] <= DBL_MAX && x[i + 1] - x[i] >= DBL_MIN))
                return fail(err, TS_ERR_NONFINITE, i + 1, TS_WHERE_POINT);
    }

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
    sp->h = p, p += n;
    sp->alpha = p, p += n;
    sp->beta = p, p += n;
    sp->b1 = p, p += n;
    sp->b2 = p, p += n;
    if (geo) {
        sp->xc1 = p, p += n;
        sp->xc2 = p, p += n;
    }
    sp->fast = p, p += n * TS_FAST_STRIDE;
    sp->term = (unsigned char *)p;
    ts_status st = build(sp, opt, x, f, err);
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
        X[3] = s->x[i + 1];
        if (s->form == TS_FORM_GEOMETRIC) {
            X[1] = s->xc1[i];
            X[2] = s->xc2[i];
        } else { /* SPEC §3: X = [x_i, x_i + K_i, x_{i+1} - K_i, x_{i+1}], as ts__controls had */
            double K = 2.0 / (3.0 * TS_PI) * s->h[i];
            X[1] = s->x[i] + K;
            X[2] = s->x[i + 1] - K;
        }
    }
    return TS_OK;
}
