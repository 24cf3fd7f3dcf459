/* docs/method.md §7: parametric curves (open/closed, 2-D/3-D), box constraints of docs/method.md §5
 * applied per coordinate with a shared beta per segment. */
#include "internal.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

/* Per-coordinate bounds (docs/method.md §5 with constant lines). */
struct curve_box {
    int has_lo[3], has_hi[3];
    double lo[3], hi[3];
};

struct ts_curve {
    size_t n;            /* segments */
    size_t dim;          /* 2 or 3 */
    int closed;
    ts_param param;
    double *t;           /* n+1 parameter knots */
    double *p;           /* (n+1)*dim points (closed: row n == row 0) */
    double *d;           /* (n+1)*dim derivatives d_i per coordinate (in t) */
    double *alpha, *beta;/* n */
    double *ctrl;        /* n*4*dim control points, segment-major then row l */
    unsigned char *term; /* n: ts_term that set beta_i */
    int has_box;
    struct curve_box box;
};

/* Padding of the periodic extension used for closed-curve slopes: covers the
 * widest stencil of docs/method.md §6 (Akima: two secants on each side). */
#define CURVE_PAD 3

static void curve_options_defaults(ts_curve_options *opt)
{
    if (!opt)
        return;
    memset(opt, 0, sizeof *opt);
    opt->struct_size = sizeof *opt;
    opt->param = TS_PARAM_CENTRIPETAL;
    opt->closed = 0;
    opt->slopes = TS_SLOPES_ARITHMETIC;
    opt->alpha = 1.0;
    opt->alphas = NULL;
    opt->n_alphas = 0;
    opt->beta = 0.0;
    opt->betas = NULL;
    opt->n_betas = 0;
    for (int k = 0; k < 3; k++) {
        opt->has_lo[k] = opt->has_hi[k] = 0;
        opt->lo[k] = opt->hi[k] = 0.0;
    }
    opt->margin = TS_DEFAULT_MARGIN;
}

static void curve_release(ts_curve *c)
{
    if (!c)
        return;
    free(c->t);
    free(c->p);
    free(c->d);
    free(c->alpha);
    free(c->beta);
    free(c->ctrl);
    free(c->term);
    free(c);
}

/* count * size bytes (count >= 1; ts_curve_new checked that no size
 * overflows), or NULL with *st = TS_ERR_NOMEM. */
static void *alloc_n(size_t count, size_t size, ts_status *st)
{
    void *m = ts__malloc(count * size);
    if (!m)
        *st = TS_ERR_NOMEM;
    return m;
}

static int isfin(double v)
{
    return v - v == 0.0;
}

/* Euclidean norm of v[0..dim), scaled against overflow/underflow. */
static double norm_dim(const double *v, size_t dim)
{
    double m = 0.0;
    for (size_t k = 0; k < dim; k++) {
        double a = fabs(v[k]);
        if (a > m)
            m = a;
    }
    if (m == 0.0 || !isfin(m))
        return m;
    double s = 0.0;
    for (size_t k = 0; k < dim; k++) {
        double q = v[k] / m;
        s += q * q;
    }
    return m * sqrt(s);
}

/* sin and cos of theta = (pi/2) delta, delta in [0, 1], exact at both ends. */
static void sincos_delta(double delta, double *s, double *c)
{
    *s = sin(TS_HALF_PI * delta);
    *c = sin(TS_HALF_PI * (1.0 - delta));
}

/* Control values of coordinate k of segment i. */
static void ctrl_coord(const ts_curve *c, size_t i, size_t k, double B[4])
{
    const double *q = c->ctrl + i * 4 * c->dim;
    for (int l = 0; l < 4; l++)
        B[l] = q[(size_t)l * c->dim + k];
}

/* docs/method.md §3 control points of segment i from p, d, t, alpha, beta. */
static void seg_controls(ts_curve *c, size_t i)
{
    size_t dim = c->dim;
    double h = c->t[i + 1] - c->t[i];
    double k = ts__geo_k(h, c->alpha[i] + c->beta[i]);
    const double *p0 = c->p + i * dim, *p1 = p0 + dim;
    const double *d0 = c->d + i * dim, *d1 = d0 + dim;
    double *q = c->ctrl + i * 4 * dim;
    for (size_t j = 0; j < dim; j++) {
        q[j] = p0[j];
        q[dim + j] = p0[j] + k * d0[j];
        q[2 * dim + j] = p1[j] - k * d1[j];
        q[3 * dim + j] = p1[j];
    }
}

/* Exact gaps of coordinate k of segment i to the sides of box bx: the
 * certificate of a spline interval against the constant lines y = lo[k],
 * y = hi[k] (ts__gap_segment, docs/method.md §5), which also accepts every control
 * gap > 0 as a proof.  Returns 1 when every active side is certified. */
static int seg_gaps(const ts_curve *c, const struct curve_box *bx, size_t i, size_t k,
                    double *glo, double *tlo, double *ghi, double *thi)
{
    double B[4], h = c->t[i + 1] - c->t[i], guard;
    int ok = 1, proven;
    ctrl_coord(c, i, k, B);
    *glo = *tlo = *ghi = *thi = (double)NAN;
    if (bx->has_lo[k]) {
        ts_line ln = {0.0, bx->lo[k]};
        *glo = ts__gap_segment(B, c->t[i], h, &ln, 1, tlo, NULL, &guard, &proven);
        ok = proven || *glo > guard;
    }
    if (bx->has_hi[k]) {
        ts_line ln = {0.0, bx->hi[k]};
        *ghi = ts__gap_segment(B, c->t[i], h, &ln, -1, thi, NULL, &guard, &proven);
        ok = ok && (proven || *ghi > guard);
    }
    return ok;
}

static int seg_certified(const ts_curve *c, size_t i)
{
    double a, b, e, f;
    for (size_t k = 0; k < c->dim; k++)
        if (!seg_gaps(c, &c->box, i, k, &a, &b, &e, &f))
            return 0;
    return 1;
}

/* docs/method.md §5.8 per coordinate: where a point lies on a side of the
 * box, that coordinate's slope is 0 (an open curve's first and last point:
 * clamped to point into the box); estimated slopes only (curves take no
 * user slopes). */
static void touch_slopes(ts_curve *c)
{
    size_t n = c->n, dim = c->dim;
    for (size_t i = 0; i <= n; i++)
        for (size_t k = 0; k < dim; k++) {
            double v = c->p[i * dim + k], *d = &c->d[i * dim + k];
            int inner = c->closed || (i > 0 && i < n);
            for (int side = 0; side < 2; side++) {
                int has = side == 0 ? c->box.has_lo[k] : c->box.has_hi[k];
                double up = side == 0 ? 1.0 : -1.0; /* into the box */
                if (!has || v != (side == 0 ? c->box.lo[k] : c->box.hi[k]))
                    continue;
                if (ts__touch_leaves(*d, inner, i == 0, up))
                    *d = 0.0;
            }
        }
}

/* The repair search of splines (ts__repair_search, docs/method.md §5) on segment i. */
static void curve_set_a(void *ctx, size_t i, double a)
{
    ts_curve *c = ctx;
    c->beta[i] = a - c->alpha[i];
    seg_controls(c, i);
}

static int curve_inside(void *ctx, size_t i)
{
    return seg_certified(ctx, i);
}

/* a -> ∞: the chord, inside a box that holds both points */
static int curve_limit_inside(void *ctx, size_t i)
{
    (void)ctx;
    (void)i;
    return 1;
}

static int seg_repair(ts_curve *c, size_t i, double t)
{
    ts__repair_ops o = {c, curve_set_a, curve_inside, curve_limit_inside, NULL, NULL};
    return ts__repair_search(&o, i, c->alpha[i], c->alpha[i] + c->beta[i], t) == TS_OK ? 0 : -1;
}

static ts_status fail(ts_error *err, ts_status st, size_t index, ts_where where)
{
    ts__error_set(err, st, index, where);
    return st;
}

/* Point of slot j of the periodic extension (slot CURVE_PAD is point 0). */
static size_t ext_point(size_t j, size_t n)
{
    return (j + n * CURVE_PAD - CURVE_PAD) % n; /* n >= 3 for a closed curve */
}

/* docs/method.md §6 slopes of one coordinate.  Closed curves: the method applied to the
 * periodic extension (CURVE_PAD points each side), d_n = d_0 exactly. */
static ts_status coord_slopes(const ts_curve *c, ts_slopes method, size_t k, double *ft,
                              double *te, double *fe, double *de, ts_error *err)
{
    size_t n = c->n, dim = c->dim;
    ts_status st;
    if (!c->closed) {
        for (size_t i = 0; i <= n; i++)
            ft[i] = c->p[i * dim + k];
        st = ts__slopes(method, c->t, ft, n + 1, de, err);
        if (st != TS_OK)
            return st;
        for (size_t i = 0; i <= n; i++)
            c->d[i * dim + k] = de[i];
        return TS_OK;
    }
    if (method == TS_SLOPES_PERIODIC)
        method = TS_SLOPES_ARITHMETIC; /* periodic three-point mean */
    double T = c->t[n] - c->t[0];
    size_t ne = n + 1 + 2 * CURVE_PAD;
    for (size_t j = 0; j < ne; j++) {
        size_t r = ext_point(j, n);
        long long q = ((long long)j - CURVE_PAD - (long long)r) / (long long)n; /* periods */
        te[j] = c->t[r] + (double)q * T;
        fe[j] = c->p[r * dim + k];
        /* t_r + T can equal t_{r-1} + T when a step is far below ulp(T):
         * ts__slopes needs strictly increasing knots */
        if (j > 0 && !(te[j] > te[j - 1]))
            return fail(err, TS_ERR_UNSORTED, r, TS_WHERE_POINT);
    }
    ts_error e2;
    st = ts__slopes(method, te, fe, ne, de, &e2);
    /* method and f are valid here: the one failure is TS_ERR_SLOPE_OVERFLOW
     * at a point; name the point, not the slot of the extension */
    if (st != TS_OK)
        return fail(err, st, ext_point(e2.index, n), TS_WHERE_POINT);
    for (size_t i = 0; i < n; i++)
        c->d[i * dim + k] = de[i + CURVE_PAD];
    c->d[n * dim + k] = c->d[k];
    return TS_OK;
}

/* Are points i and j (rows of dim) the same? */
static int same_point(const double *points, size_t dim, size_t i, size_t j)
{
    for (size_t k = 0; k < dim; k++)
        if (points[i * dim + k] != points[j * dim + k])
            return 0;
    return 1;
}

/* Arguments and points before anything else: NULL, dim, options, sizes,
 * finite coordinates; *m distinct points (closed: an exact repetition of
 * the first point at the end dropped), *n segments. */
static ts_status check_args(const double *points, size_t n_points, size_t dim,
                            const ts_curve_options *opt, size_t *m, size_t *n, ts_error *err)
{
    if (dim != 2 && dim != 3)
        return fail(err, TS_ERR_DIMENSION, TS_NO_INDEX, TS_WHERE_NONE);
    if (!((int)opt->param >= 0 && (int)opt->param <= (int)TS_PARAM_UNIFORM))
        return fail(err, TS_ERR_OPTION, TS_NO_INDEX, TS_WHERE_NONE);
    if (!((int)opt->slopes >= 0 && (int)opt->slopes < TS_SLOPES_COUNT_) ||
        opt->slopes == TS_SLOPES_USER || (opt->slopes == TS_SLOPES_PERIODIC && !opt->closed))
        return fail(err, TS_ERR_OPTION, TS_NO_INDEX, TS_WHERE_NONE);
    if (n_points < 2)
        return fail(err, TS_ERR_TOO_FEW, TS_NO_INDEX, TS_WHERE_NONE);
    /* the largest array: 4 control points of dim doubles per segment (the
     * extension of a closed curve, n + 1 + 2 CURVE_PAD knots, is smaller) */
    if (n_points > SIZE_MAX / dim / 4 / sizeof(double))
        return fail(err, TS_ERR_OVERFLOW, TS_NO_INDEX, TS_WHERE_NONE);
    for (size_t i = 0; i < n_points; i++)
        for (size_t k = 0; k < dim; k++)
            if (!isfin(points[i * dim + k]))
                return fail(err, TS_ERR_NONFINITE, i, TS_WHERE_POINT);
    int closed = opt->closed != 0;
    *m = closed && same_point(points, dim, 0, n_points - 1) ? n_points - 1 : n_points;
    if (closed && *m < 3)
        return fail(err, TS_ERR_TOO_FEW, TS_NO_INDEX, TS_WHERE_NONE);
    *n = closed ? *m : *m - 1;
    return TS_OK;
}

/* alphas, betas (the spline's rules, checks.c), the box and its margin;
 * *has_box. */
static ts_status check_params(const ts_curve_options *opt, size_t n, size_t dim, int *has_box,
                              ts_error *err)
{
    if ((opt->alphas && opt->n_alphas != n) || (opt->betas && opt->n_betas != n))
        return fail(err, TS_ERR_LENGTH, TS_NO_INDEX, TS_WHERE_NONE);
    size_t i = ts__first_bad_alpha(opt->alpha, opt->alphas, 0, n);
    if (i < n)
        return fail(err, TS_ERR_ALPHA, i, TS_WHERE_INTERVAL);
    i = ts__first_bad_beta(opt->alpha, opt->alphas, opt->beta, opt->betas, 0, n);
    if (i < n)
        return fail(err, TS_ERR_BETA, i, TS_WHERE_INTERVAL);
    *has_box = 0;
    for (size_t k = 0; k < dim; k++) {
        *has_box |= opt->has_lo[k] != 0 || opt->has_hi[k] != 0;
        if ((opt->has_lo[k] && !isfin(opt->lo[k])) || (opt->has_hi[k] && !isfin(opt->hi[k])))
            return fail(err, TS_ERR_NONFINITE, TS_NO_INDEX, TS_WHERE_NONE);
    }
    if (*has_box && !ts__margin_ok(opt->margin))
        return fail(err, TS_ERR_MARGIN, TS_NO_INDEX, TS_WHERE_NONE);
    return TS_OK;
}

/* Consecutive equal points (closed: also the last kept point and the
 * first), then every point inside the box (on a side allowed,
 * docs/method.md §5.8, §7). */
static ts_status check_points(const double *points, size_t m, size_t dim, int closed,
                              const ts_curve_options *opt, ts_error *err)
{
    for (size_t i = 0; i + 1 < m; i++)
        if (same_point(points, dim, i, i + 1))
            return fail(err, TS_ERR_UNSORTED, i + 1, TS_WHERE_POINT);
    if (closed && same_point(points, dim, m - 1, 0))
        return fail(err, TS_ERR_UNSORTED, m - 1, TS_WHERE_POINT);
    for (size_t i = 0; i < m; i++)
        for (size_t k = 0; k < dim; k++) {
            double v = points[i * dim + k];
            if ((opt->has_lo[k] && !(v >= opt->lo[k])) || (opt->has_hi[k] && !(v <= opt->hi[k])))
                return fail(err, TS_ERR_SIDE, i, TS_WHERE_POINT);
        }
    return TS_OK;
}

/* The curve's arrays and the scratch of the slopes (ws[4]: ft, te, fe,
 * de); TS_ERR_NOMEM. */
static ts_status curve_alloc(ts_curve *c, double *ws[4])
{
    size_t n = c->n, dim = c->dim, ne = n + 1 + 2 * CURVE_PAD;
    ts_status st = TS_OK;
    c->t = alloc_n(n + 1, sizeof(double), &st);
    c->p = alloc_n((n + 1) * dim, sizeof(double), &st);
    c->d = alloc_n((n + 1) * dim, sizeof(double), &st);
    c->alpha = alloc_n(n, sizeof(double), &st);
    c->beta = alloc_n(n, sizeof(double), &st);
    c->ctrl = alloc_n(n * 4 * dim, sizeof(double), &st);
    c->term = alloc_n(n, 1, &st);
    ws[0] = alloc_n(n + 1, sizeof(double), &st);
    ws[1] = alloc_n(ne, sizeof(double), &st);
    ws[2] = alloc_n(ne, sizeof(double), &st);
    ws[3] = alloc_n(ne, sizeof(double), &st);
    return st;
}

/* docs/method.md §7: parameter knots (m distinct points). */
static ts_status curve_knots(ts_curve *c, size_t m, ts_error *err)
{
    size_t n = c->n, dim = c->dim;
    c->t[0] = 0.0;
    for (size_t i = 0; i < n; i++) {
        double dv[3], h;
        for (size_t k = 0; k < dim; k++)
            dv[k] = c->p[(i + 1) * dim + k] - c->p[i * dim + k];
        h = c->param == TS_PARAM_UNIFORM ? 1.0 : norm_dim(dv, dim);
        if (c->param == TS_PARAM_CENTRIPETAL)
            h = sqrt(h);
        c->t[i + 1] = c->param == TS_PARAM_UNIFORM ? (double)(i + 1) : c->t[i] + h;
        if (!isfin(c->t[i + 1]))
            return fail(err, TS_ERR_NONFINITE, i + 1 < m ? i + 1 : 0, TS_WHERE_POINT);
        if (!(c->t[i + 1] > c->t[i])) /* step lost to rounding */
            return fail(err, TS_ERR_UNSORTED, i + 1 < m ? i + 1 : m - 1, TS_WHERE_POINT);
    }
    return TS_OK;
}

/* docs/method.md §5 per coordinate with the box's constant lines (the
 * spline's rule, ts__beta_line): the largest term over the coordinates of
 * segment i with a = alpha_i; *bt the term that set it (TS_TERM_MARGIN: none
 * above 0). */
static double box_rule(const ts_curve *c, size_t i, double a, ts_term *bt)
{
    size_t dim = c->dim;
    double K = ts__geo_K(c->t[i + 1] - c->t[i]), best = 0.0;
    int t = TS_TERM_MARGIN;
    for (size_t k = 0; k < dim; k++) {
        double f0 = c->p[i * dim + k], f1 = c->p[(i + 1) * dim + k];
        double d0 = c->d[i * dim + k], d1 = c->d[(i + 1) * dim + k];
        if (c->box.has_lo[k])
            ts__beta_line(a, K, f0 - c->box.lo[k], f1 - c->box.lo[k], d0, d1, 1.0,
                          TS_TERM_LOWER_LEFT, &best, &t);
        if (c->box.has_hi[k])
            ts__beta_line(a, K, c->box.hi[k] - f0, c->box.hi[k] - f1, d0, d1, -1.0,
                          TS_TERM_UPPER_LEFT, &best, &t);
    }
    *bt = (ts_term)t;
    return best;
}

/* alpha, beta: the caller's; with a box beta_i = max(beta, t + the rule)
 * (docs/method.md §5), TS_ERR_INFEASIBLE where that overflows. */
static ts_status curve_betas(ts_curve *c, const ts_curve_options *opt, ts_error *err)
{
    for (size_t i = 0; i < c->n; i++) {
        double a = opt->alphas ? opt->alphas[i] : opt->alpha;
        double b = opt->betas ? opt->betas[i] : opt->beta;
        c->alpha[i] = a;
        c->beta[i] = b;
        c->term[i] = TS_TERM_USER;
        if (!c->has_box)
            continue;
        ts_term bt;
        double rule = opt->margin + box_rule(c, i, a, &bt);
        if (!isfin(rule) || !isfin(a + rule))
            return fail(err, TS_ERR_INFEASIBLE, i, TS_WHERE_INTERVAL);
        if (rule >= b) {
            c->beta[i] = rule;
            c->term[i] = (unsigned char)bt;
        }
    }
    return TS_OK;
}

/* docs/method.md §3 control points (TS_ERR_NONFINITE where they
 * overflow), then §5: the exact certificate per segment and coordinate,
 * repaired by the spline's search. */
static ts_status curve_controls(ts_curve *c, double margin, ts_error *err)
{
    size_t n = c->n, dim = c->dim;
    for (size_t i = 0; i < n; i++) {
        seg_controls(c, i);
        for (size_t j = 0; j < 4 * dim; j++)
            if (!isfin(c->ctrl[i * 4 * dim + j]))
                return fail(err, TS_ERR_NONFINITE, i, TS_WHERE_INTERVAL);
    }
    for (size_t i = 0; c->has_box && i < n; i++) {
        if (seg_certified(c, i))
            continue;
        if (seg_repair(c, i, margin) != 0)
            return fail(err, TS_ERR_INFEASIBLE, i, TS_WHERE_INTERVAL);
        c->term[i] = TS_TERM_CERTIFY;
    }
    return TS_OK;
}

/* The stages after the checks, on an allocated curve: points, knots,
 * slopes (docs/method.md §6, per coordinate; §5.8 at the box's sides), β,
 * controls and certificates. */
static ts_status curve_build(ts_curve *c, const double *points, size_t m,
                             const ts_curve_options *opt, double *ws[4], ts_error *err)
{
    size_t n = c->n, dim = c->dim;
    for (size_t i = 0; i < m; i++)
        memcpy(c->p + i * dim, points + i * dim, dim * sizeof(double));
    if (c->closed)
        memcpy(c->p + n * dim, points, dim * sizeof(double));
    ts_status st = curve_knots(c, m, err);
    for (size_t k = 0; k < dim && st == TS_OK; k++)
        st = coord_slopes(c, opt->slopes, k, ws[0], ws[1], ws[2], ws[3], err);
    if (st != TS_OK)
        return st;
    /* (ts__slopes refuses non-finite slopes: TS_ERR_SLOPE_OVERFLOW) */
    if (c->has_box)
        touch_slopes(c);
    if ((st = curve_betas(c, opt, err)) != TS_OK)
        return st;
    return curve_controls(c, opt->margin, err);
}

ts_status ts_curve_new(const double *points, size_t n_points, size_t dim,
                       const ts_curve_options *opt, ts_curve **out, ts_error *err)
{
    ts__error_set(err, TS_OK, TS_NO_INDEX, TS_WHERE_NONE);
    if (out)
        *out = NULL;
    if (!points || !out)
        return fail(err, TS_ERR_NULL, TS_NO_INDEX, TS_WHERE_NONE);
    if (opt && opt->struct_size != sizeof *opt)
        return fail(err, TS_ERR_VERSION, TS_NO_INDEX, TS_WHERE_NONE);
    ts_curve_options defaults;
    if (!opt) {
        curve_options_defaults(&defaults);
        opt = &defaults;
    }
    size_t m = 0, n = 0;
    int has_box = 0;
    ts_status st = check_args(points, n_points, dim, opt, &m, &n, err);
    if (st == TS_OK)
        st = check_params(opt, n, dim, &has_box, err);
    if (st == TS_OK)
        st = check_points(points, m, dim, opt->closed != 0, opt, err);
    if (st != TS_OK)
        return st;
    ts_curve *c = ts__calloc(1, sizeof *c);
    if (!c)
        return fail(err, TS_ERR_NOMEM, TS_NO_INDEX, TS_WHERE_NONE);
    c->n = n;
    c->dim = dim;
    c->closed = opt->closed != 0;
    c->param = opt->param;
    c->has_box = has_box;
    for (size_t k = 0; k < 3; k++) {
        c->box.has_lo[k] = k < dim && opt->has_lo[k] != 0;
        c->box.has_hi[k] = k < dim && opt->has_hi[k] != 0;
        c->box.lo[k] = c->box.has_lo[k] ? opt->lo[k] : 0.0;
        c->box.hi[k] = c->box.has_hi[k] ? opt->hi[k] : 0.0;
    }
    double *ws[4] = {NULL, NULL, NULL, NULL};
    st = curve_alloc(c, ws);
    if (st != TS_OK)
        fail(err, st, TS_NO_INDEX, TS_WHERE_NONE);
    else
        st = curve_build(c, points, m, opt, ws, err);
    for (int j = 0; j < 4; j++)
        free(ws[j]);
    if (st != TS_OK) {
        curve_release(c);
        return st;
    }
    *out = c;
    return TS_OK;
}

size_t ts_curve_segments(const ts_curve *c)
{
    return c ? c->n : 0;
}

size_t ts_curve_dim(const ts_curve *c)
{
    return c ? c->dim : 0;
}

int ts_curve_closed(const ts_curve *c)
{
    return c ? c->closed : 0;
}

const double *ts_curve_knots(const ts_curve *c)
{
    return c ? c->t : NULL;
}

ts_status ts_curve_control(const ts_curve *c, size_t i, double *ctrl)
{
    if (!c || !ctrl)
        return TS_ERR_NULL;
    if (i >= c->n) {
        for (size_t j = 0; j < 4 * c->dim; j++)
            ctrl[j] = (double)NAN;
        return TS_ERR_INDEX;
    }
    memcpy(ctrl, c->ctrl + i * 4 * c->dim, 4 * c->dim * sizeof(double));
    return TS_OK;
}

ts_status ts_curve_params(const ts_curve *c, size_t i, double *alpha, double *beta)
{
    if (alpha)
        *alpha = (double)NAN;
    if (beta)
        *beta = (double)NAN;
    if (!c || !alpha || !beta)
        return TS_ERR_NULL;
    if (i >= c->n)
        return TS_ERR_INDEX;
    *alpha = c->alpha[i];
    *beta = c->beta[i];
    return TS_OK;
}

/* Point and derivatives of segment i at delta in [0, 1], formed from the
 * nearer end as the 1-D spline (docs/method.md §3 "Evaluation", §7): past
 * the midpoint the control values are reversed and sin, cos exchanged
 * (ϑ = π/2 − θ, dϑ/dθ = −1), so both knots are exact and the error near
 * either end is an ulp of that end's value.  With a box the point is then
 * clamped into it (docs/method.md §7 "Evaluation inside the box"). */
static void seg_eval(const ts_curve *c, size_t i, double delta, double *p, double *dp,
                     double *d2p)
{
    double s, co, B[4], o[3];
    double h = c->t[i + 1] - c->t[i], w = TS_HALF_PI / h;
    int want = d2p ? 2 : dp ? 1 : 0;
    int r = 1.0 - delta < delta; /* 1 − delta is exact for delta >= 1/2 */
    sincos_delta(delta, &s, &co);
    if (r) {
        double tmp = s;
        s = co;
        co = tmp;
    }
    /* a subnormal step (chord length of points ~1e-310 apart) makes w = inf:
     * divide by h instead, so dP/dt stays finite (d²P/dt² ~ 1/h may not) */
    int wf = isfin(w);
    for (size_t k = 0; k < c->dim; k++) {
        ctrl_coord(c, i, k, B);
        if (r) {
            double b0 = B[0], b1 = B[1];
            B[0] = B[3];
            B[1] = B[2];
            B[2] = b1;
            B[3] = b0;
        }
        ts__seg_sc(B, s, co, want, o); /* docs/method.md §2, (2.1) */
        if (!isfin(o[0])) {
            /* differences B_l − B0 beyond DBL_MAX (control values near it of
             * both signs): the same sums on B/4 (exact), then times 4; the
             * value, a convex combination, is finite */
            double Bq[4] = {0.25 * B[0], 0.25 * B[1], 0.25 * B[2], 0.25 * B[3]};
            ts__seg_sc(Bq, s, co, want, o);
            for (int l = 0; l <= want; l++)
                o[l] *= 4.0;
        }
        if (r && want > 0)
            o[1] = -o[1];
        if (p) {
            double v = o[0];
            /* the exact point is inside the certified box: a value outside
             * it is rounding, moved onto the side (the closed box, sides
             * included, as the data may lie on them) */
            if (c->box.has_lo[k] && v < c->box.lo[k])
                v = c->box.lo[k];
            if (c->box.has_hi[k] && v > c->box.hi[k])
                v = c->box.hi[k];
            p[k] = v;
        }
        if (dp)
            dp[k] = wf ? o[1] * w : o[1] * TS_HALF_PI / h;
        if (d2p)
            d2p[k] = wf ? o[2] * w * w : o[2] * TS_HALF_PI / h * TS_HALF_PI / h;
    }
}

ts_status ts_curve_eval(const ts_curve *c, double t, ts_cursor *cur, double *p, double *dp,
                        double *d2p)
{
    if (!c)
        return TS_ERR_NULL;
    for (size_t k = 0; k < c->dim; k++) {
        if (p)
            p[k] = (double)NAN;
        if (dp)
            dp[k] = (double)NAN;
        if (d2p)
            d2p[k] = (double)NAN;
    }
    double t0 = c->t[0], tn = c->t[c->n];
    if (!isfin(t))
        return TS_ERR_DOMAIN;
    if (c->closed) {
        if (!(t0 <= t && t < tn)) { /* periodic: tn is t0 again */
            double T = tn - t0, r = fmod(t - t0, T);
            if (r < 0.0)
                r += T;
            if (!(r < T)) /* rounding */
                r = 0.0;
            t = t0 + r;
        }
    } else if (!(t0 <= t && t <= tn)) {
        return TS_ERR_DOMAIN;
    }
    size_t i = ts__search(c->t, c->n, t, cur); /* right-hand segment at inner knots */
    /* t_i <= t <= t_{i+1}: delta in [0, 1] (rounding is monotone) */
    double delta = (t - c->t[i]) / (c->t[i + 1] - c->t[i]);
    seg_eval(c, i, delta, p, dp, d2p);
    return TS_OK;
}

ts_status ts_curve_sample(const ts_curve *c, size_t m, double *out, size_t out_len, size_t *rows)
{
    if (rows)
        *rows = 0;
    if (!c || !rows || (!out && out_len > 0))
        return TS_ERR_NULL;
    if (m < 2)
        return TS_ERR_OPTION;
    size_t n = c->n, w = 1 + c->dim;
    if (m - 1 > (SIZE_MAX - 1) / n)
        return TS_ERR_OVERFLOW;
    size_t r = n * (m - 1) + 1;
    if (r > SIZE_MAX / w)
        return TS_ERR_OVERFLOW;
    *rows = r;
    if (out_len < r * w)
        return TS_ERR_LENGTH;
    size_t row = 0;
    for (size_t i = 0; i < n; i++) {
        double h = c->t[i + 1] - c->t[i];
        for (size_t j = 0; j + 1 < m; j++, row++) {
            double delta = (double)j / (double)(m - 1);
            out[row * w] = c->t[i] + h * delta;
            seg_eval(c, i, delta, out + row * w + 1, NULL, NULL);
        }
    }
    out[row * w] = c->t[n];
    seg_eval(c, n - 1, 1.0, out + row * w + 1, NULL, NULL);
    return TS_OK;
}

/* 10-point Gauss–Legendre on [-1, 1]: positive nodes and weights (roots of
 * P_10 computed with mpmath at 40 digits, rounded to 21). */
static const double gl_x[5] = {0.148874338981631210885, 0.433395394129247190799,
                               0.679409568299024406234, 0.865063366688984510732,
                               0.973906528517171720078};
static const double gl_w[5] = {0.295524224714752870174, 0.269266719309996355091,
                               0.219086362515982043996, 0.149451349150580593146,
                               0.0666713443086881375936};

/* Control values B of coordinate k on segment i; 1 when they are not all
 * equal (a constant coordinate adds nothing to the speed), *bmax = max|B|. */
static int coord_moves(const ts_curve *c, size_t i, size_t k, double B[4], double *bmax)
{
    ctrl_coord(c, i, k, B);
    double lo = fmin(fmin(B[0], B[1]), fmin(B[2], B[3]));
    double hi = fmax(fmax(B[0], B[1]), fmax(B[2], B[3]));
    *bmax = fmax(-lo, hi);
    return lo != hi;
}

/* |dP/dθ| of segment i at θ, times 2^-e (the moving coordinates' control
 * values scaled exactly by 2^-e <= 1/max|B|, so differences and sums cannot
 * overflow; a constant coordinate, perhaps far larger, is left out). */
static double seg_speed(const ts_curve *c, size_t i, double theta, int e)
{
    double s = sin(theta), co = cos(theta), v[3], B[4], o[3], bmax;
    for (size_t k = 0; k < c->dim; k++) {
        if (!coord_moves(c, i, k, B, &bmax)) {
            v[k] = 0.0;
            continue;
        }
        for (int l = 0; l < 4; l++)
            B[l] = ldexp(B[l], -e);
        ts__seg_sc(B, s, co, 1, o);
        v[k] = o[1];
    }
    return norm_dim(v, c->dim);
}

static double gl_seg(const ts_curve *c, size_t i, double a, double b, int e)
{
    double m = 0.5 * (a + b), r = 0.5 * (b - a), sum = 0.0;
    for (int j = 0; j < 5; j++)
        sum += gl_w[j] *
               (seg_speed(c, i, m - r * gl_x[j], e) + seg_speed(c, i, m + r * gl_x[j], e));
    return r * sum;
}

#define LEN_DEPTH TS_LIMIT_DEFAULT_curve_len_depth

ts_status ts_curve_length(const ts_curve *c, double tol, double *len)
{
    if (len)
        *len = (double)NAN;
    if (!c || !len)
        return TS_ERR_NULL;
    if (!(tol > 0.0))
        tol = 1e-12;
    if (tol < 1e-14)
        tol = 1e-14;
    double total = 0.0;
    const int max_depth = TS_LIMIT(curve_len_depth), max_pieces = TS_LIMIT(curve_len_pieces);
    for (size_t i = 0; i < c->n; i++) {
        struct { double a, b, I; int depth; } stk[LEN_DEPTH + 2];
        int sp = 0, pieces = 0, e = 0;
        /* the scale of the moving coordinates: a constant one of 1e300 next
         * to one moving by 1e-310 would flush the latter's speed to 0 */
        double cmax = 0.0, B[4], bmax;
        for (size_t k = 0; k < c->dim; k++)
            if (coord_moves(c, i, k, B, &bmax))
                cmax = fmax(cmax, bmax);
        (void)frexp(cmax, &e); /* cmax > 0: a segment joins two distinct points */
        double whole = gl_seg(c, i, 0.0, TS_HALF_PI, e), seg = 0.0;
        stk[sp].a = 0.0;
        stk[sp].b = TS_HALF_PI;
        stk[sp].I = whole;
        stk[sp].depth = 0;
        sp++;
        while (sp > 0) {
            sp--;
            double a = stk[sp].a, b = stk[sp].b, I = stk[sp].I;
            int depth = stk[sp].depth;
            double mid = 0.5 * (a + b);
            double L = gl_seg(c, i, a, mid, e), R = gl_seg(c, i, mid, b, e);
            double fine = L + R, dif = fabs(fine - I);
            double scale = fmax(fine, whole * (b - a) / TS_HALF_PI);
            pieces++;
            if (dif <= tol * scale || depth >= max_depth || pieces >= max_pieces) {
                seg += fine;
                continue;
            }
            stk[sp].a = mid; stk[sp].b = b; stk[sp].I = R; stk[sp].depth = depth + 1; sp++;
            stk[sp].a = a; stk[sp].b = mid; stk[sp].I = L; stk[sp].depth = depth + 1; sp++;
        }
        total += ldexp(seg, e); /* may overflow to inf, never NaN */
    }
    *len = total;
    return TS_OK;
}

/* Reports of a failed certify call: NaN values, nothing certified. */
static void reports_clear(const ts_curve *c, ts_interval_report *reports)
{
    for (size_t j = 0; c && reports && j < c->n * c->dim; j++) {
        ts_interval_report *r = &reports[j];
        r->struct_size = sizeof *r;
        r->x0 = r->x1 = r->alpha = r->beta = r->a = (double)NAN;
        r->B[0] = r->B[1] = r->B[2] = r->B[3] = (double)NAN;
        r->term = TS_TERM_USER;
        r->has_lower = r->has_upper = 0;
        r->gap_lower = r->at_lower = r->gap_upper = r->at_upper = (double)NAN;
        r->certified = 0;
        r->y_min = r->at_y_min = r->y_max = r->at_y_max = (double)NAN;
        r->excursion_above = r->excursion_below = (double)NAN;
    }
}

static ts_status certify_with(const ts_curve *c, const struct curve_box *bx,
                              ts_interval_report *reports, ts_error *err)
{
    size_t first = TS_NO_INDEX;
    for (size_t i = 0; i < c->n; i++) {
        double h = c->t[i + 1] - c->t[i];
        for (size_t k = 0; k < c->dim; k++) {
            double glo, tlo, ghi, thi;
            int ok = seg_gaps(c, bx, i, k, &glo, &tlo, &ghi, &thi);
            if (!ok && first == TS_NO_INDEX)
                first = i;
            if (!reports)
                continue;
            ts_interval_report *r = &reports[i * c->dim + k];
            r->struct_size = sizeof *r;
            r->x0 = c->t[i];
            r->x1 = c->t[i + 1];
            r->alpha = c->alpha[i];
            r->beta = c->beta[i];
            r->a = c->alpha[i] + c->beta[i];
            ctrl_coord(c, i, k, r->B);
            r->term = (ts_term)c->term[i];
            r->has_lower = bx->has_lo[k];
            r->has_upper = bx->has_hi[k];
            r->gap_lower = glo;
            r->at_lower = c->t[i] + h * tlo / TS_HALF_PI; /* NaN if inactive */
            r->gap_upper = ghi;
            r->at_upper = c->t[i] + h * thi / TS_HALF_PI;
            r->certified = ok;
            ts__range_segment(r->B, c->t[i], h, r);
        }
    }
    if (first != TS_NO_INDEX)
        return fail(err, TS_ERR_VIOLATED, first, TS_WHERE_INTERVAL);
    return TS_OK;
}

ts_status ts_curve_certify(const ts_curve *c, ts_interval_report *reports, ts_error *err)
{
    ts__error_set(err, TS_OK, TS_NO_INDEX, TS_WHERE_NONE);
    if (reports && reports[0].struct_size != sizeof *reports)
        return fail(err, TS_ERR_VERSION, TS_NO_INDEX, TS_WHERE_NONE);
    if (!c)
        return fail(err, TS_ERR_NULL, TS_NO_INDEX, TS_WHERE_NONE);
    return certify_with(c, &c->box, reports, err);
}

ts_status ts_curve_certify_box(const ts_curve *c, const int has_lo[3], const double lo[3],
                               const int has_hi[3], const double hi[3],
                               ts_interval_report *reports, ts_error *err)
{
    ts__error_set(err, TS_OK, TS_NO_INDEX, TS_WHERE_NONE);
    if (reports && reports[0].struct_size != sizeof *reports)
        return fail(err, TS_ERR_VERSION, TS_NO_INDEX, TS_WHERE_NONE);
    reports_clear(c, reports); /* out-params reset first */
    if (!c || (has_lo && !lo) || (has_hi && !hi))
        return fail(err, TS_ERR_NULL, TS_NO_INDEX, TS_WHERE_NONE);
    struct curve_box bx;
    memset(&bx, 0, sizeof bx);
    for (size_t k = 0; k < c->dim; k++) {
        bx.has_lo[k] = has_lo && has_lo[k] != 0;
        bx.has_hi[k] = has_hi && has_hi[k] != 0;
        if (bx.has_lo[k]) {
            bx.lo[k] = lo[k];
            if (!isfin(lo[k]))
                return fail(err, TS_ERR_NONFINITE, TS_NO_INDEX, TS_WHERE_NONE);
        }
        if (bx.has_hi[k]) {
            bx.hi[k] = hi[k];
            if (!isfin(hi[k]))
                return fail(err, TS_ERR_NONFINITE, TS_NO_INDEX, TS_WHERE_NONE);
        }
    }
    return certify_with(c, &bx, reports, err);
}

void ts_curve_options_init(ts_curve_options *opt)
{
    curve_options_defaults(opt);
}

void ts_curve_free(ts_curve *c)
{
    curve_release(c);
}
