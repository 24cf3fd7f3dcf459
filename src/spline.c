/* ts_spline_new: the one construction path for every form; accessors
 * (docs/method.md §1, §3). */
#include "internal.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

void ts__options_defaults(ts_spline_options *opt)
{
    if (!opt)
        return;
    memset(opt, 0, sizeof *opt);
    opt->struct_size = sizeof *opt;
    opt->form = TS_FORM_GEOMETRIC; /* docs/method.md §5.10 */
    opt->slopes = TS_SLOPES_STEFFEN;
    opt->alpha = TS_DEFAULT_ALPHA;
    opt->beta = 0.0;
    opt->shape = TS_SHAPE_NONE;
    opt->margin = TS_DEFAULT_MARGIN;
    opt->certify = 1;
    opt->extrapolate = TS_EXTRAP_ERROR;
    opt->constraints = NULL;
    opt->n_constraints = 0;
}

/* Overflow-checked a * b, b > 0. */
static int mul_ok(size_t a, size_t b, size_t *r)
{
    if (a > SIZE_MAX / b)
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

/* 1 if every alpha_i, i in [i0, i1), passes ts__alpha_ok. */
TS_VECTOR_LOOP static int alpha_ok(const double *restrict al, size_t i0, size_t i1)
{
    int ok = 1;
    for (size_t i = i0; i < i1; i++)
        ok &= ts__alpha_ok(al[i]);
    return ok;
}

/* Points [*done, upto) of x, f into sp. */
static void copy_points(ts_spline *sp, const double *x, const double *f, size_t *done, size_t upto)
{
    size_t p0 = *done;
    if (upto <= p0)
        return;
    memcpy(sp->x + p0, x + p0, (upto - p0) * sizeof *x);
    memcpy(sp->f + p0, f + p0, (upto - p0) * sizeof *f);
    *done = upto;
}

/* w_i = dθ/dx of intervals [i0, i1) (ts__w; x through i1 copied). */
TS_VECTOR_LOOP static void widths(const double *restrict x, double *restrict w, size_t i0, size_t i1)
{
    for (size_t i = i0; i < i1; i++)
        w[i] = ts__w(x[i], x[i + 1]);
}

/* docs/method.md §6 user slopes, points [p0, p1) (array checked non-NULL, length np). */
static ts_status user_slopes(ts_spline *sp, const ts_spline_options *o, size_t p0, size_t p1,
                             ts_error *err)
{
    for (size_t i = p0; i < p1; i++) {
        if (!isfinite(o->user_slopes[i]))
            return ts__fail(err, TS_ERR_NONFINITE, i, TS_WHERE_POINT);
        sp->d[i] = o->user_slopes[i];
    }
    return TS_OK;
}

static ts_status check_alpha(const ts_spline *sp, size_t i0, size_t i1, ts_error *err)
{
    if (alpha_ok(sp->alpha, i0, i1))
        return TS_OK;
    return ts__fail(err, TS_ERR_ALPHA, ts__first_bad_alpha(0.0, sp->alpha, i0, i1),
                    TS_WHERE_INTERVAL);
}

/* 1 if every beta_i, i in [i0, i1), passes ts__beta_ok; term USER. */
TS_VECTOR_LOOP static int beta_ok(const double *restrict al, const double *restrict be,
                                  unsigned char *restrict term, size_t i0, size_t i1)
{
    int ok = 1;
    for (size_t i = i0; i < i1; i++) {
        ok &= ts__beta_ok(al[i], be[i]);
        term[i] = (unsigned char)TS_TERM_USER;
    }
    return ok;
}

/* TS_SHAPE_NONE: the caller's beta (filled), checked (alpha already is);
 * term USER. */
static ts_status check_beta(ts_spline *sp, size_t i0, size_t i1, ts_error *err)
{
    if (beta_ok(sp->alpha, sp->beta, sp->term, i0, i1))
        return TS_OK;
    return ts__fail(err, TS_ERR_BETA, ts__first_bad_beta(0.0, sp->alpha, 0.0, sp->beta, i0, i1),
                    TS_WHERE_INTERVAL);
}

/* Intervals per block of the construction: its dozen arrays stay in the L2
 * cache (~100 KiB) from the slopes to the integrals (docs/design.md). */
#define TS_BLOCK 1024

/* The running integral over intervals [i0, i1) (i0 a multiple of
 * TS_CUM_STEP) from sum (the integral up to x_{i0}), which it returns,
 * kept at every TS_CUM_STEP-th knot (ts__cum adds the wholes after it in
 * the same order). */
static double cumulate(ts_spline *sp, size_t i0, size_t i1, double sum)
{
    double wh[TS_BLOCK];
    for (size_t j0 = i0; j0 < i1; j0 += TS_BLOCK) {
        size_t j1 = i1 - j0 > TS_BLOCK ? j0 + TS_BLOCK : i1;
        ts__form(sp->form)->wholes(sp, j0, j1, wh);
        for (size_t i = j0; i < j1; i++) {
            sum += wh[i - j0];
            if ((i + 1) % TS_CUM_STEP == 0)
                sp->cum[(i + 1) / TS_CUM_STEP] = sum;
        }
    }
    return sum;
}

static void spline_release(ts_spline *s);


/* 1 if every |b1[i]|, |b2[i]| <= TS_VALUE_MAX, i in [i0, i1) (NaN-safe). */
TS_VECTOR_LOOP static int values_ok(const double *restrict b1, const double *restrict b2,
                                    size_t i0, size_t i1)
{
    int ok = 1;
    for (size_t i = i0; i < i1; i++)
        ok &= (fabs(b1[i]) <= TS_VALUE_MAX) & (fabs(b2[i]) <= TS_VALUE_MAX);
    return ok;
}

/* values_ok of the geometric form's derived B1, B2 (ts__B), i in [i0, i1). */
TS_VECTOR_LOOP static int geo_values_ok(const double *restrict x, const double *restrict f,
                                        const double *restrict d, const double *restrict al,
                                        const double *restrict be, size_t i0, size_t i1)
{
    int ok = 1;
    for (size_t i = i0; i < i1; i++) {
        double a = al[i] + be[i];
        double b1 = ts__geo_b1(x[i], x[i + 1], f[i], d[i], a);
        double b2 = ts__geo_b2(x[i], x[i + 1], f[i + 1], d[i + 1], a);
        ok &= (fabs(b1) <= TS_VALUE_MAX) & (fabs(b2) <= TS_VALUE_MAX);
    }
    return ok;
}

/* values_ok or geo_values_ok of intervals [i0, i1), whichever sp stores. */
static int controls_ok(const ts_spline *sp, size_t i0, size_t i1)
{
    return sp->b1 ? values_ok(sp->b1, sp->b2, i0, i1)
                  : geo_values_ok(sp->x, sp->f, sp->d, sp->alpha, sp->beta, i0, i1);
}

/* The first non-finite d_i, i in [p0, p1) (there is one). */
static ts_status nonfinite_slope(const ts_spline *sp, size_t p0, size_t p1, ts_error *err)
{
    size_t i = p0;
    while (i + 1 < p1 && isfinite(sp->d[i]))
        i++;
    return ts__fail(err, TS_ERR_SLOPE_OVERFLOW, i, TS_WHERE_POINT);
}

/* The one construction path, every form: the stages (docs/method.md §6 slopes, alpha,
 * docs/method.md §5 beta by the scheme or the caller's beta, the docs/method.md §4 bound, docs/method.md §3
 * and §4 controls, docs/method.md §5 certificates, integrals) run on TS_BLOCK intervals
 * at a time while their arrays are in cache.  In the paper and geometric forms
 * an interval depends only on its own knots (its slopes on the neighbours,
 * read from the caller's x, f), so every stage completes in the block; in the
 * C¹ form the controls of an interval depend on its neighbours' a_j, and the
 * repair may step back, so controls, certificates and integrals run once
 * after the blocks.  The first fault found is the one reported: the order is
 * documented at ts_spline_new. */
static ts_status build(ts_spline *sp, const ts_spline_options *o, const double *x, const double *f,
                       ts_error *err)
{
    size_t n = sp->n, np = n + 1, done = 0;
    int user = o->slopes == TS_SLOPES_USER, shaped = o->shape != TS_SHAPE_NONE, dir = 0;
    int vals = 1; /* controls_ok of the blocks, checked while they are in cache */
    const ts__form_ops *form = ts__form(sp->form);
    int c1 = form->neighbours, geo = form->geometric;
    ts_status st = TS_OK;
    if (user && !o->user_slopes)
        return ts__fail(err, TS_ERR_NULL, TS_NO_INDEX, TS_WHERE_NONE);
    if (user && o->n_user_slopes != np)
        return ts__fail(err, TS_ERR_LENGTH, TS_NO_INDEX, TS_WHERE_NONE);
    if (o->slopes == TS_SLOPES_PERIODIC && !(f[0] == f[n]))
        return ts__fail(err, TS_ERR_PERIODIC, n, TS_WHERE_POINT);
    if ((o->alphas && o->n_alphas != n) || (!shaped && o->betas && o->n_betas != n))
        return ts__fail(err, TS_ERR_LENGTH, TS_NO_INDEX, TS_WHERE_NONE);
    if (shaped && (st = ts__shape_begin(sp, o, f, &dir, err)) != TS_OK)
        return st;
    double sum = 0.0;
    sp->cum[0] = sum;
    for (size_t i0 = 0; i0 < n; i0 += TS_BLOCK) {
        size_t i1 = n - i0 > TS_BLOCK ? i0 + TS_BLOCK : n;
        /* points p0..i1: d_{i1} is needed for interval i1 - 1 */
        size_t p0 = i0 ? i0 + 1 : 0, p1 = i1 + 1;
        copy_points(sp, x, f, &done, i1 + 2 < np ? i1 + 2 : np);
        if (!geo)
            widths(sp->x, sp->w, i0, i1);
        if (user) {
            st = user_slopes(sp, o, p0, p1, err);
        } else {
            ts__slopes_range(o->slopes, x, f, np, sp->d, p0, p1);
            if (!all_finite(sp->d, p0, p1))
                st = nonfinite_slope(sp, p0, p1, err);
        }
        if (st != TS_OK)
            return st;
        fill(sp->alpha, i0, i1, o->alpha, o->alphas);
        if ((st = check_alpha(sp, i0, i1, err)) != TS_OK)
            return st;
        if (!shaped) {
            fill(sp->beta, i0, i1, o->beta, o->betas);
            st = check_beta(sp, i0, i1, err);
        } else {
            st = ts__shape_range(sp, o, dir, p0, p1, i0, i1, err);
        }
        if (st == TS_OK && geo)
            st = ts__geo_check(sp, i0, i1, err);
        if (st != TS_OK)
            return st;
        if (c1)
            continue;
        form->controls(sp, i0, i1);
        if (shaped && (st = ts__certify_range(sp, o, i0, i1, err)) != TS_OK)
            return st;
        sum = cumulate(sp, i0, i1, sum);
        vals &= controls_ok(sp, i0, i1);
    }
    if (c1) {
        form->controls(sp, 0, n);
        if (shaped && (st = ts__certify_range(sp, o, 0, n, err)) != TS_OK)
            return st;
        (void)cumulate(sp, 0, n, 0.0);
        vals = controls_ok(sp, 0, n);
    }
    if (shaped)
        ts__certify_done(sp, o);
    /* control values must be finite (a tiny a_i with a large slope can
     * overflow B1, B2 with no scheme to catch it) and at most TS_VALUE_MAX
     * (so S between the knots cannot overflow), reported after every other
     * check of the build; an integral that overflows is not an error:
     * ts_spline_integral then returns ±Inf */
    if (!vals) {
        size_t i = 0; /* the first offender (there is one) */
        double B[4];
        for (;; i++) {
            ts__B(sp, i, B);
            if (i + 1 == n || !(fabs(B[1]) <= TS_VALUE_MAX && fabs(B[2]) <= TS_VALUE_MAX))
                break;
        }
        return ts__fail(err, isfinite(B[1]) && isfinite(B[2]) ? TS_ERR_TOO_LARGE
                                                              : TS_ERR_CONTROL_OVERFLOW,
                        i, TS_WHERE_INTERVAL);
    }
    return TS_OK;
}

/* The constraint records' slopes, betas and their bookkeeping (docs/method.md
 * §13), made before the spline is allocated; freed by con_prep_free. */
typedef struct con_prep {
    double *d, *beta;
    int *by, *bind;
} con_prep;

static void con_prep_free(con_prep *p)
{
    free(p->d);
    free(p->beta);
    free(p->by);
    free(p->bind);
}

static ts_status con_begin(const double *x, const double *f, size_t np, const ts_spline_options *o,
                           con_prep *p, ts_spline_options *o2, ts_error *err,
                           ts_constraint_failure *fail)
{
    size_t n = np - 1;
    ts_status st = ts__con_validate(o, n, err, fail);
    if (st != TS_OK)
        return st;
    if ((o->alphas && o->n_alphas != n) || (o->margins && o->n_margins != n))
        return ts__fail(err, TS_ERR_LENGTH, TS_NO_INDEX, TS_WHERE_NONE);
    if (o->slopes == TS_SLOPES_USER && !o->user_slopes)
        return ts__fail(err, TS_ERR_NULL, TS_NO_INDEX, TS_WHERE_NONE);
    if (o->slopes == TS_SLOPES_USER && o->n_user_slopes != np)
        return ts__fail(err, TS_ERR_LENGTH, TS_NO_INDEX, TS_WHERE_NONE);
    if (o->slopes == TS_SLOPES_PERIODIC && !(f[0] == f[n]))
        return ts__fail(err, TS_ERR_PERIODIC, n, TS_WHERE_POINT);
    for (size_t i = 0; i < n; i++)
        if (!ts__margin_ok(o->margins ? o->margins[i] : o->margin))
            return ts__fail(err, TS_ERR_MARGIN, i, TS_WHERE_INTERVAL);
    /* np·sizeof cannot overflow here (spline_new checked 3 np doubles);
     * ts__malloc_n checks it anyway */
    p->d = ts__malloc_n(np, sizeof *p->d);
    p->beta = ts__malloc_n(np, sizeof *p->beta);
    p->by = ts__malloc_n(np, sizeof *p->by);
    p->bind = ts__malloc_n(np, sizeof *p->bind);
    if (!p->d || !p->beta || !p->by || !p->bind)
        return ts__fail(err, TS_ERR_NOMEM, TS_NO_INDEX, TS_WHERE_NONE);
    if (o->slopes == TS_SLOPES_USER)
        memcpy(p->d, o->user_slopes, np * sizeof *p->d);
    else
        ts__slopes_range(o->slopes, x, f, np, p->d, 0, np);
    for (size_t j = 0; j < np; j++)
        if (!isfinite(p->d[j]))
            return ts__fail(err, o->slopes == TS_SLOPES_USER ? TS_ERR_NONFINITE : TS_ERR_SLOPE_OVERFLOW,
                            j, TS_WHERE_POINT);
    if ((st = ts__con_prepare(x, f, n, o, p->d, p->by, err, fail)) != TS_OK)
        return st;
    ts__con_betas(x, f, n, o, p->d, p->beta, p->bind);
    *o2 = *o;
    o2->slopes = TS_SLOPES_USER;
    o2->user_slopes = p->d;
    o2->n_user_slopes = np;
    o2->betas = p->beta;
    o2->n_betas = n;
    o2->constraints = NULL;
    o2->n_constraints = 0;
    return TS_OK;
}

/* The bound a record's copy keeps: LOWER and UPPER records' own (validated:
 * a polyline has px, py, a spline bound its spline); other kinds ignore the
 * bound fields (include/trigspline.h), whatever the caller left in them. */
static ts_bound kept_bound(const ts_constraint *c)
{
    int bounded = c->kind == TS_CONSTRAINT_LOWER || c->kind == TS_CONSTRAINT_UPPER;
    return bounded ? c->bound : TS_BOUND_CONSTANT;
}

/* After build: certify and repair, the integrals again, and the records
 * copied into the spline (which owns them). */
static ts_status con_finish(ts_spline *sp, const ts_spline_options *o, con_prep *p, ts_error *err,
                            ts_constraint_failure *fail)
{
    ts_status st = ts__con_certify(sp, o->constraints, o->n_constraints, err, fail);
    if (st != TS_OK)
        return st;
    (void)cumulate(sp, 0, sp->n, 0.0);
    size_t nc = o->n_constraints, npts = 0;
    for (size_t k = 0; k < nc; k++)
        if (kept_bound(&o->constraints[k]) == TS_BOUND_POLYLINE)
            npts += 2 * o->constraints[k].n_poly; /* each <= the caller's arrays: no overflow */
        else if (kept_bound(&o->constraints[k]) == TS_BOUND_SPLINE)
            npts += ts__bcurve_doubles(o->constraints[k].spline); /* <= its arrays */
    sp->con = ts__malloc_n(nc, sizeof *sp->con);
    sp->con_pts = ts__malloc_n(npts ? npts : 1, sizeof *sp->con_pts);
    sp->con_spl = ts__malloc_n(nc, sizeof *sp->con_spl);
    if (!sp->con || !sp->con_pts || !sp->con_spl)
        return ts__fail(err, TS_ERR_NOMEM, TS_NO_INDEX, TS_WHERE_NONE);
    memcpy(sp->con, o->constraints, nc * sizeof *sp->con);
    double *q = sp->con_pts;
    for (size_t k = 0; k < nc; k++) {
        ts_constraint *c = &sp->con[k];
        ts_bound b = kept_bound(c);
        if (b == TS_BOUND_SPLINE) {
            /* the fitted spline keeps its own copy of B (docs/method.md §13.7) */
            ts__bcurve_copy(c->spline, &sp->con_spl[k], q);
            q += ts__bcurve_doubles(c->spline);
            c->spline = &sp->con_spl[k];
        } else {
            c->spline = NULL;
        }
        if (b != TS_BOUND_POLYLINE) {
            c->px = c->py = NULL;
            continue;
        }
        memcpy(q, c->px, c->n_poly * sizeof *q);
        memcpy(q + c->n_poly, c->py, c->n_poly * sizeof *q);
        c->px = q;
        c->py = q + c->n_poly;
        q += 2 * c->n_poly;
    }
    sp->ncon = nc;
    sp->con_by = p->by;
    sp->con_bind = p->bind;
    p->by = p->bind = NULL;
    return TS_OK;
}

static ts_status spline_new(const double *x, const double *f, size_t n_points,
                            const ts_spline_options *opt, ts_spline **out, ts_error *err,
                            ts_constraint_failure *fail);

ts_status ts_spline_new(const double *x, const double *f, size_t n_points,
                        const ts_spline_options *opt, ts_spline **out, ts_error *err)
{
    return spline_new(x, f, n_points, opt, out, err, NULL);
}

static void failure_reset(ts_constraint_failure *f)
{
    memset(f, 0, sizeof *f);
    f->struct_size = sizeof *f;
    f->status = TS_OK;
    f->constraint = TS_NO_INDEX;
    f->index = TS_NO_INDEX;
    f->where = TS_WHERE_NONE;
    f->condition = TS_CONDITION_NONE;
}

void ts_constraint_failure_init(ts_constraint_failure *f)
{
    if (f)
        failure_reset(f);
}

ts_status ts_constraints_diagnose(const double *x, const double *f, size_t n_points,
                                  const ts_spline_options *opt, ts_constraint_failure *fail)
{
    if (!fail)
        return TS_ERR_NULL;
    if (fail->struct_size != sizeof *fail)
        return TS_ERR_VERSION;
    failure_reset(fail);
    ts_error e;
    ts_spline *s = NULL;
    ts_status st = spline_new(x, f, n_points, opt, &s, &e, fail);
    spline_release(s);
    fail->status = st;
    if (st != TS_OK && fail->index == TS_NO_INDEX) {
        fail->index = e.index;
        fail->where = e.where;
    }
    return st;
}

static ts_status spline_new(const double *x, const double *f, size_t n_points,
                            const ts_spline_options *opt, ts_spline **out, ts_error *err,
                            ts_constraint_failure *fail)
{
    ts__error_set(err, TS_OK, TS_NO_INDEX, TS_WHERE_NONE);
    if (out)
        *out = NULL;
    if (!x || !f || !out)
        return ts__fail(err, TS_ERR_NULL, TS_NO_INDEX, TS_WHERE_NONE);
    if (opt && opt->struct_size != sizeof *opt)
        return ts__fail(err, TS_ERR_VERSION, TS_NO_INDEX, TS_WHERE_NONE);
    ts_spline_options defaults;
    if (!opt) {
        ts__options_defaults(&defaults);
        opt = &defaults;
    }
    if (n_points < 2)
        return ts__fail(err, TS_ERR_TOO_FEW, TS_NO_INDEX, TS_WHERE_NONE);
    if ((unsigned)opt->form > (unsigned)TS_FORM_GEOMETRIC ||
        (unsigned)opt->slopes >= (unsigned)TS_SLOPES_COUNT_ ||
        (unsigned)opt->shape > (unsigned)TS_SHAPE_MONOTONE ||
        (unsigned)opt->extrapolate > (unsigned)TS_EXTRAP_LINEAR)
        return ts__fail(err, TS_ERR_OPTION, TS_NO_INDEX, TS_WHERE_NONE);

    /* layout: 3 arrays of n+1 (x, f, d), n/TS_CUM_STEP + 1 running integrals,
     * alpha and beta (n each), the control values b1, b2 (n each; the
     * geometric form derives them unless constraint records may nudge
     * them), the geometric form's κ or the other forms' w (n), term bytes.
     * Only what cannot be derived cheaply: every byte per knot costs
     * construction time. */
    int geo = ts__form(opt->form)->geometric;
    int keep_b = !geo || opt->n_constraints;
    size_t per_interval_arrays = 2 + 2 * (size_t)keep_b + 1;
    size_t n = n_points - 1, a, b, c, total, bytes;
    if (!mul_ok(n_points, 3, &a) || !mul_ok(n, per_interval_arrays, &b))
        return ts__fail(err, TS_ERR_OVERFLOW, TS_NO_INDEX, TS_WHERE_NONE);
    total = a + b;
    if (total < a || total + (n / TS_CUM_STEP + 1) < total)
        return ts__fail(err, TS_ERR_OVERFLOW, TS_NO_INDEX, TS_WHERE_NONE);
    total += n / TS_CUM_STEP + 1;
    if (!mul_ok(total, sizeof(double), &c) || c + n < c)
        return ts__fail(err, TS_ERR_OVERFLOW, TS_NO_INDEX, TS_WHERE_NONE);
    bytes = c + n;

    /* widths finite and normal (dθ/dx = (π/2)/h must not overflow), |f| <=
     * TS_VALUE_MAX (S cannot overflow between knots) */
    size_t at;
    ts_status st = ts__check_knots(x, f, n_points, TS_VALUE_MAX, DBL_MIN, DBL_MAX, &at);
    if (st != TS_OK)
        return ts__fail(err, st, at, TS_WHERE_POINT);

    con_prep prep = {NULL, NULL, NULL, NULL};
    ts_spline_options o2;
    if (opt->n_constraints) {
        st = con_begin(x, f, n_points, opt, &prep, &o2, err, fail);
        if (st != TS_OK) {
            con_prep_free(&prep);
            return st;
        }
    }
    ts_spline *sp = ts__calloc(1, sizeof *sp);
    double *blk = sp ? ts__alloc_block(bytes) : NULL;
    if (!blk) {
        free(sp);
        con_prep_free(&prep);
        return ts__fail(err, TS_ERR_NOMEM, TS_NO_INDEX, TS_WHERE_NONE);
    }
    sp->n = n;
    sp->form = opt->form;
    sp->shape = opt->shape;
    sp->extrap = opt->extrapolate;
    double *p = blk;
    sp->x = p, p += n_points;
    sp->f = p, p += n_points;
    sp->d = p, p += n_points;
    sp->cum = p, p += n / TS_CUM_STEP + 1;
    sp->alpha = p, p += n;
    sp->beta = p, p += n;
    if (keep_b) {
        sp->b1 = p, p += n;
        sp->b2 = p, p += n;
    }
    if (geo)
        sp->kappa = p, p += n;
    else
        sp->w = p, p += n;
    sp->term = (unsigned char *)p;
    st = build(sp, opt->n_constraints ? &o2 : opt, x, f, err);
    if (st == TS_OK && opt->n_constraints)
        st = con_finish(sp, opt, &prep, err, fail);
    con_prep_free(&prep);
    if (st != TS_OK) {
        spline_release(sp);
        return st;
    }
    *out = sp;
    return TS_OK;
}

static void spline_release(ts_spline *s)
{
    if (!s)
        return;
    free(s->x);
    free(s->con);
    free(s->con_pts);
    free(s->con_spl);
    free(s->con_bind);
    free(s->con_by);
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
        *a = (double)NAN;
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
        B[0] = B[1] = B[2] = B[3] = (double)NAN;
    if (X)
        X[0] = X[1] = X[2] = X[3] = (double)NAN;
    if (!s || !B)
        return TS_ERR_NULL;
    if (i >= s->n)
        return TS_ERR_INDEX;
    ts__B(s, i, B);
    if (X) { /* docs/method.md §3, §4: X = [x_i, x_i + k, x_{i+1} - k, x_{i+1}] */
        double k = ts__form(s->form)->k(s, i);
        X[0] = s->x[i];
        X[1] = s->x[i] + k;
        X[2] = s->x[i + 1] - k;
        X[3] = s->x[i + 1];
    }
    return TS_OK;
}

void ts_spline_options_init(ts_spline_options *opt)
{
    ts__options_defaults(opt);
}

void ts_spline_free(ts_spline *s)
{
    spline_release(s);
}
