/* trigspline._gufunc: the numpy generalized ufunc behind trigspline.interp.
 *
 *   interp(x(n), f(n), xq(m), opt(k)) -> y(m), status(), index(), gap()
 *
 * One series per core call: the spline is built with ts_spline_new and
 * evaluated with ts_spline_eval_batch, the calls trigspline.Spline makes, so the
 * values are those of one Spline per series.  Loops: float64 in and out,
 * float32 data (x and queries float32 or float64) to float32 out; the fit is
 * always in float64.  numpy runs these loops without the GIL (no object
 * dtypes); nothing here touches Python objects inside a loop.
 *
 * A series that cannot be fitted never raises: its y is NaN and status holds
 * the ts_status (index: the point or interval it names, in the caller's
 * numbering, -1 if none).  Queries outside the data under extrapolation
 * "nan" (and NaN queries) are NaN without a status.
 *
 * Missing points (x or f NaN or ±Inf) stay local unless skipna: the series
 * is split at them into runs of consecutive finite points, each run of two
 * or more points is fitted on its own (fit_runs), and a query gets the value
 * of the run whose [first, last] knot holds it; queries in an interval that
 * touches a missing point, at a missing point or in a run of one point are
 * NaN.  Extrapolation is the first (last) run's when it starts (ends) at the
 * series' end, NaN otherwise.  Status TS_ERR_NONFINITE, index = the first
 * missing point, marks such a series (its values are written); a run that
 * fails makes the whole series fail with that run's status.  Each run's
 * values depend on its knots only as a spline's do (docs/method.md §3, §6),
 * so a window of the series (a dask chunk with its halo) gives the same
 * values on its own intervals.
 *
 * opt (float64, OPT_LEN values; the layout is trigspline.interp's):
 *   shape, form, slopes, extrapolate (-1: NaN outside), alpha,
 *   lower.m, lower.c, upper.m, upper.c, margin, skipna, certify, want_gap,
 *   gap_first, gap_end (the least gap is taken over intervals
 *   [gap_first, gap_end) of the fitted series; gap_end < 0: to the last);
 * then, when the vector is longer, constraint records (docs/method.md §13):
 *   n_records, and per record kind, value, first, count, n_poly,
 *   px[n_poly], py[n_poly] (n_poly 0: a constant bound).  A scope counts
 *   the series' intervals; a run of fit_runs gets each record cut to its own
 *   intervals (a record outside the run is left out), so a scope means the
 *   same intervals with or without missing points.  The least gap of a
 *   series with records is that of its lower and upper records (exact
 *   minima, ts_spline_constraint_report).
 *
 * float32 output keeps the bound (docs/method.md §5): each value is rounded
 * to nearest, then moved one float32 step back inside where rounding crossed
 * the scheme's boundary (positive: S >= 0; lines: strictly beyond the line
 * evaluated in double as m*x + c).  Knots come back exactly: S(x_i) = f_i in
 * double, f_i is a float32, rounding returns it, and it is inside the region
 * (the data checks of docs/method.md §5.8), so no step is taken.  Rounding
 * to nearest is monotone, so monotone output stays monotone.
 */
#define PY_SSIZE_T_CLEAN
#include <Python.h>

#define NPY_NO_DEPRECATED_API NPY_1_7_API_VERSION
#include <numpy/arrayobject.h>
#include <numpy/ufuncobject.h>

#include <fenv.h>
#include <float.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "trigspline.h"

enum {
    OPT_SHAPE,
    OPT_FORM,
    OPT_SLOPES,
    OPT_EXTRAP,
    OPT_ALPHA,
    OPT_LOWER_M,
    OPT_LOWER_C,
    OPT_UPPER_M,
    OPT_UPPER_C,
    OPT_MARGIN,
    OPT_SKIPNA,
    OPT_CERTIFY,
    OPT_WANT_GAP,
    OPT_GAP_FIRST,
    OPT_GAP_END,
    OPT_LEN
};

typedef struct {
    ts_spline_options opt;
    int skipna, want_gap, nan_outside;
    double gap_first, gap_end;
} series_options;

/* Room for the records of an option vector of k values: the vector's copy
 * (polyline points point into it), the records, and the records of a run. */
typedef struct {
    double *v;
    ts_constraint *cons, *run;
    size_t cap;
} record_buf;

static int records_new(record_buf *rb, npy_intp k)
{
    memset(rb, 0, sizeof *rb);
    size_t uk = (size_t)(k > 0 ? k : 0) + 1, cap = uk / 5 + 1;
    if (uk > SIZE_MAX / sizeof(double) || cap > SIZE_MAX / sizeof(ts_constraint))
        return 0;
    rb->v = malloc(uk * sizeof(double));
    rb->cons = malloc(cap * sizeof(ts_constraint));
    rb->run = malloc(cap * sizeof(ts_constraint));
    rb->cap = cap;
    return rb->v && rb->cons && rb->run;
}

static void records_free(record_buf *rb)
{
    free(rb->v);
    free(rb->cons);
    free(rb->run);
}

/* A count in a double: a whole number in [0, max]. */
static int whole(double v, double max, size_t *out)
{
    if (!(0 <= v && v <= max) || v != floor(v))
        return 0;
    *out = (size_t)v;
    return 1;
}

/* The records after the first OPT_LEN values of rb->v (k values in all);
 * 0 when the layout is broken.  Kinds, values and points are checked by the
 * library (ts_spline_new). */
static int read_records(record_buf *rb, npy_intp k, series_options *so)
{
    const double *v = rb->v;
    size_t at = OPT_LEN, end = (size_t)k, nc;
    if (!whole(v[at++], (double)rb->cap, &nc) || nc > rb->cap)
        return 0;
    for (size_t r = 0; r < nc; r++) {
        ts_constraint *c = &rb->cons[r];
        size_t kind, np_;
        if (end - at < 5 || !whole(v[at], 255.0, &kind))
            return 0;
        ts_constraint_init(c, (ts_constraint_kind)kind);
        c->kind = (ts_constraint_kind)kind;
        c->value = v[at + 1];
        if (!whole(v[at + 2], 0x1p52, &c->first) || !whole(v[at + 3], 0x1p52, &c->count) ||
            !whole(v[at + 4], (double)(end - at - 5) / 2, &np_))
            return 0;
        at += 5;
        if (np_) {
            c->bound = TS_BOUND_POLYLINE;
            c->px = v + at;
            c->py = v + at + np_;
            c->n_poly = np_;
            at += 2 * np_;
        }
    }
    if (at != end)
        return 0;
    so->opt.constraints = rb->cons;
    so->opt.n_constraints = nc;
    return 1;
}

/* The option vector -> ts_spline_options; 0 if a value is not a valid enum
 * or the records' layout is broken (rb: room for them, NULL: none allowed). */
static int read_options(const char *p, npy_intp step, npy_intp k, series_options *so,
                        record_buf *rb)
{
    if (k != OPT_LEN && !(k > OPT_LEN && rb))
        return 0;
    double v[OPT_LEN];
    for (int i = 0; i < OPT_LEN; i++)
        v[i] = *(const double *)(p + i * step);
    ts_spline_options_init(&so->opt);
    /* enums travel as small integers in doubles; NaN-safe range checks */
    if (!(0 <= v[OPT_SHAPE] && v[OPT_SHAPE] <= TS_SHAPE_MONOTONE) || !(0 <= v[OPT_FORM] && v[OPT_FORM] <= TS_FORM_GEOMETRIC) ||
        !(0 <= v[OPT_SLOPES] && v[OPT_SLOPES] < TS_SLOPES_COUNT_ && v[OPT_SLOPES] != TS_SLOPES_USER) ||
        !(-1 <= v[OPT_EXTRAP] && v[OPT_EXTRAP] <= TS_EXTRAP_LINEAR) || v[OPT_EXTRAP] == TS_EXTRAP_ERROR)
        return 0;
    so->opt.shape = (ts_shape)v[OPT_SHAPE];
    so->opt.form = (ts_form)v[OPT_FORM];
    so->opt.slopes = (ts_slopes)v[OPT_SLOPES];
    so->nan_outside = v[OPT_EXTRAP] < 0;
    so->opt.extrapolate = so->nan_outside ? TS_EXTRAP_ERROR : (ts_extrap)v[OPT_EXTRAP];
    so->opt.alpha = v[OPT_ALPHA];
    so->opt.lower.m = v[OPT_LOWER_M];
    so->opt.lower.c = v[OPT_LOWER_C];
    so->opt.upper.m = v[OPT_UPPER_M];
    so->opt.upper.c = v[OPT_UPPER_C];
    so->opt.margin = v[OPT_MARGIN];
    so->skipna = v[OPT_SKIPNA] != 0;
    so->opt.certify = v[OPT_CERTIFY] != 0;
    so->want_gap = v[OPT_WANT_GAP] != 0;
    so->gap_first = v[OPT_GAP_FIRST];
    so->gap_end = v[OPT_GAP_END];
    if (!(so->gap_first >= 0) || isnan(so->gap_end))
        return 0;
    if (k == OPT_LEN)
        return 1;
    for (npy_intp i = 0; i < k; i++)
        rb->v[i] = *(const double *)(p + i * step);
    return read_records(rb, k, so);
}

/* The records of so cut to a run's intervals [p0, p0 + nint) of the series
 * (n_series_int intervals) into rb->run (see the top of the file). */
static void run_records(const series_options *so, record_buf *rb, size_t p0, size_t nint,
                        size_t n_series_int, ts_spline_options *out)
{
    *out = so->opt;
    if (!so->opt.n_constraints)
        return;
    size_t m = 0;
    for (size_t r = 0; r < so->opt.n_constraints; r++) {
        ts_constraint c = so->opt.constraints[r];
        if (c.first >= n_series_int || c.count > n_series_int - c.first) {
            c.first = nint; /* a scope beyond the series: refused as without gaps */
            rb->run[m++] = c;
            continue;
        }
        size_t a = c.first, b = c.count ? c.first + c.count : n_series_int;
        if (a < p0)
            a = p0;
        if (b > p0 + nint)
            b = p0 + nint;
        if (!(a < b))
            continue;
        c.first = a - p0;
        c.count = b - a;
        rb->run[m++] = c;
    }
    out->constraints = rb->run;
    out->n_constraints = m;
}

/* Least certified gap over intervals [first, end) (end < 0: to the last) and
 * their active boundaries (NaN when the scheme has none, e.g. monotone);
 * with constraint records, the least exact gap of its lower and upper
 * records. */
static double least_gap(const ts_spline *s, const ts_spline_options *o, double first, double end)
{
    double g = (double)NAN;
    size_t n = ts_spline_intervals(s);
    size_t i0 = first < (double)n ? (size_t)first : n;
    size_t i1 = end < 0 || end > (double)n ? n : (size_t)end;
    for (size_t i = i0; i < i1; i++) {
        if (o->n_constraints) {
            for (size_t k = 0; k < o->n_constraints; k++) {
                ts_constraint_kind kind = o->constraints[k].kind;
                ts_constraint_report r;
                ts_constraint_report_init(&r);
                if ((kind != TS_CONSTRAINT_LOWER && kind != TS_CONSTRAINT_UPPER) ||
                    ts_spline_constraint_report(s, k, i, &r) != TS_OK || !r.in_scope ||
                    isnan(r.gap))
                    continue;
                if (!(g <= r.gap))
                    g = r.gap;
            }
            continue;
        }
        ts_interval_report r = TS_INTERVAL_REPORT_INIT;
        if (ts_spline_report(s, i, &r) != TS_OK)
            return (double)NAN;
        if (r.has_lower && !(g <= r.gap_lower))
            g = r.gap_lower;
        if (r.has_upper && !(g <= r.gap_upper))
            g = r.gap_upper;
    }
    return g;
}

/* Scratch for one loop call: x, f, xq, y (double), the finite-point map and
 * the tables of fit_runs: run of each kept point, start of each run (and one
 * past the last), query offsets per run, run of each query, queries ordered
 * by run, gathered queries and values. */
typedef struct {
    double *x, *f, *xq, *y, *gq, *gy;
    npy_intp *keep, *rid, *rstart, *roff, *qrun, *qorder;
} scratch;

static int scratch_new(scratch *w, npy_intp n, npy_intp m)
{
    memset(w, 0, sizeof *w);
    size_t un = (size_t)n + 2, um = (size_t)m + 1;
    if (un > SIZE_MAX / sizeof(double) / 2 || um > SIZE_MAX / sizeof(double) / 2 ||
        un > SIZE_MAX / sizeof(npy_intp) / 2 || um > SIZE_MAX / sizeof(npy_intp) / 2)
        return 0;
    w->x = malloc(un * sizeof(double));
    w->f = malloc(un * sizeof(double));
    w->xq = malloc(um * sizeof(double));
    w->y = malloc(um * sizeof(double));
    w->gq = malloc(um * sizeof(double));
    w->gy = malloc(um * sizeof(double));
    w->keep = malloc(un * sizeof(npy_intp));
    w->rid = malloc(un * sizeof(npy_intp));
    w->rstart = malloc(un * sizeof(npy_intp));
    w->roff = malloc(un * sizeof(npy_intp));
    w->qrun = malloc(um * sizeof(npy_intp));
    w->qorder = malloc(um * sizeof(npy_intp));
    return w->x && w->f && w->xq && w->y && w->gq && w->gy && w->keep && w->rid &&
           w->rstart && w->roff && w->qrun && w->qorder;
}

static void scratch_free(scratch *w)
{
    free(w->x);
    free(w->f);
    free(w->xq);
    free(w->y);
    free(w->gq);
    free(w->gy);
    free(w->keep);
    free(w->rid);
    free(w->rstart);
    free(w->roff);
    free(w->qrun);
    free(w->qorder);
}

/* The run whose knots hold query q (-1: NaN there); kept points x[0..nn-1]
 * at series positions keep[], n the series length (see the top of the
 * file). */
static npy_intp query_run(const scratch *w, npy_intp nn, npy_intp n, double q)
{
    if (nn == 0 || isnan(q))
        return -1;
    npy_intp r;
    if (q < w->x[0]) {
        r = w->keep[0] == 0 ? w->rid[0] : -1;
    } else if (q > w->x[nn - 1]) {
        r = w->keep[nn - 1] == n - 1 ? w->rid[nn - 1] : -1;
    } else {
        npy_intp lo = 0, hi = nn - 1; /* the last j with x[j] <= q */
        while (lo < hi) {
            npy_intp mid = lo + (hi - lo + 1) / 2;
            if (w->x[mid] <= q)
                lo = mid;
            else
                hi = mid - 1;
        }
        if (w->x[lo] == q || (lo + 1 < nn && w->rid[lo + 1] == w->rid[lo]))
            r = w->rid[lo];
        else
            r = -1;
    }
    if (r >= 0 && w->rstart[r + 1] - w->rstart[r] < 2)
        r = -1;
    return r;
}

/* A series with missing points (not skipna): each run fitted on its own. */
static ts_status fit_runs(scratch *w, npy_intp n, npy_intp m, const series_options *so,
                          record_buf *rb, npy_int64 *index, double *gap)
{
    npy_intp nn = 0, nrun = 0, first_missing = -1;
    for (npy_intp i = 0; i < n; i++) {
        if (isfinite(w->x[i]) && isfinite(w->f[i])) {
            if (nn == 0 || w->keep[nn - 1] != i - 1)
                w->rstart[nrun++] = nn;
            w->x[nn] = w->x[i];
            w->f[nn] = w->f[i];
            w->rid[nn] = nrun - 1;
            w->keep[nn++] = i;
        } else if (first_missing < 0) {
            first_missing = i;
        }
    }
    w->rstart[nrun] = nn;
    for (npy_intp j = 1; j < nn; j++) { /* runs in order (within a run: the library) */
        if (w->rid[j] != w->rid[j - 1] && !(w->x[j - 1] < w->x[j])) {
            *index = (npy_int64)w->keep[j];
            return TS_ERR_UNSORTED;
        }
    }
    /* queries ordered by run (counting sort): off[r + 2] counts run r's
     * queries, then off[r + 1] is their start, then (placed) their end */
    npy_intp *off = w->roff, *order = w->qorder;
    for (npy_intp r = 0; r <= nrun + 1; r++)
        off[r] = 0;
    for (npy_intp j = 0; j < m; j++) {
        w->qrun[j] = query_run(w, nn, n, w->xq[j]);
        w->y[j] = (double)NAN;
        if (w->qrun[j] >= 0)
            off[w->qrun[j] + 2]++;
    }
    for (npy_intp r = 2; r <= nrun + 1; r++)
        off[r] += off[r - 1];
    for (npy_intp j = 0; j < m; j++)
        if (w->qrun[j] >= 0)
            order[off[w->qrun[j] + 1]++] = j;
    /* run r's queries: order[off[r] .. off[r + 1]) */
    ts_status st = TS_OK;
    for (npy_intp r = 0; r < nrun && st == TS_OK; r++) {
        npy_intp a = w->rstart[r], len = w->rstart[r + 1] - a;
        if (len < 2)
            continue;
        ts_spline *s = NULL;
        ts_error err;
        ts_spline_options ro;
        run_records(so, rb, (size_t)w->keep[a], (size_t)len - 1, (size_t)n - 1, &ro);
        st = ts_spline_new(w->x + a, w->f + a, (size_t)len, &ro, &s, &err);
        if (st == TS_OK && (ro.shape != TS_SHAPE_NONE || ro.n_constraints) &&
            !ts_spline_certified(s)) {
            st = TS_ERR_VIOLATED;
            err.index = TS_NO_INDEX;
        }
        if (st != TS_OK) {
            ts_spline_free(s);
            if (err.index != TS_NO_INDEX)
                *index = (npy_int64)(err.index < (size_t)len ? w->keep[a + (npy_intp)err.index]
                                                             : w->keep[a] + (npy_intp)err.index);
            break;
        }
        npy_intp q0 = off[r], q1 = off[r + 1];
        for (npy_intp k = q0; k < q1; k++)
            w->gq[k - q0] = w->xq[order[k]];
        ts_cursor cur = TS_CURSOR_INIT;
        /* TS_ERR_DOMAIN only: those queries are NaN, the others evaluated */
        (void)ts_spline_eval_batch(s, 0, w->gq, (size_t)(q1 - q0), w->gy, &cur, NULL);
        for (npy_intp k = q0; k < q1; k++)
            w->y[order[k]] = w->gy[k - q0];
        if (so->want_gap) {
            /* the run's intervals inside [gap_first, gap_end) of the series */
            double first = so->gap_first - (double)w->keep[a];
            double end = so->gap_end < 0 ? -1.0 : so->gap_end - (double)w->keep[a];
            double g = so->gap_end >= 0 && end <= 0 ? (double)NAN
                                                    : least_gap(s, &ro, first > 0 ? first : 0,
                                                                end);
            if (!isnan(g) && !(*gap <= g))
                *gap = g;
        }
        ts_spline_free(s);
    }
    if (st != TS_OK) {
        *gap = (double)NAN;
        for (npy_intp j = 0; j < m; j++)
            w->y[j] = (double)NAN;
        return st;
    }
    *index = (npy_int64)first_missing;
    return TS_ERR_NONFINITE;
}

/* Fit one series from w->x, w->f (n points) and evaluate at w->xq (m) into
 * w->y; returns the status, *index in the caller's numbering, *gap, and
 * *valued = 1 when w->y holds the values (always for TS_OK). */
static ts_status fit_series(scratch *w, npy_intp n, npy_intp m, const series_options *so,
                            record_buf *rb, npy_int64 *index, double *gap, int *valued)
{
    *index = -1;
    *gap = (double)NAN;
    *valued = 0;
    if (!so->skipna) {
        for (npy_intp i = 0; i < n; i++) {
            if (!(isfinite(w->x[i]) && isfinite(w->f[i]))) {
                ts_status st = fit_runs(w, n, m, so, rb, index, gap);
                *valued = st == TS_ERR_NONFINITE; /* NaN where no run gives a value */
                return st;
            }
        }
    }
    npy_intp nn = n;
    if (so->skipna) { /* fit through the finite points only */
        nn = 0;
        for (npy_intp i = 0; i < n; i++) {
            if (isfinite(w->x[i]) && isfinite(w->f[i])) {
                w->x[nn] = w->x[i];
                w->f[nn] = w->f[i];
                w->keep[nn++] = i;
            }
        }
    }
    ts_spline *s = NULL;
    ts_error err;
    ts_status st = ts_spline_new(w->x, w->f, (size_t)nn, &so->opt, &s, &err);
    if (st == TS_OK && (so->opt.shape != TS_SHAPE_NONE || so->opt.n_constraints) &&
        !ts_spline_certified(s)) {
        st = TS_ERR_VIOLATED;
        err.index = TS_NO_INDEX;
    }
    if (st != TS_OK) {
        ts_spline_free(s);
        for (npy_intp j = 0; j < m; j++)
            w->y[j] = (double)NAN;
        if (err.index != TS_NO_INDEX && (npy_intp)err.index < nn)
            *index = so->skipna ? (npy_int64)w->keep[err.index] : (npy_int64)err.index;
        return st;
    }
    ts_cursor cur = TS_CURSOR_INIT;
    /* TS_ERR_DOMAIN only: those queries are NaN, the others evaluated */
    (void)ts_spline_eval_batch(s, 0, w->xq, (size_t)m, w->y, &cur, NULL);
    if (so->want_gap)
        *gap = least_gap(s, &so->opt, so->gap_first, so->gap_end);
    ts_spline_free(s);
    *valued = 1;
    return TS_OK;
}

static void load(double *dst, const char *src, npy_intp step, npy_intp len, int is_float)
{
    if (is_float) {
        for (npy_intp i = 0; i < len; i++)
            dst[i] = (double)*(const float *)(src + i * step);
    } else {
        for (npy_intp i = 0; i < len; i++)
            dst[i] = *(const double *)(src + i * step);
    }
}

/* y rounded to float32 without leaving the region (see the top of the file).
 * Overflow and underflow are decided here, so no flag is raised. */
static float to_float32(double y, double x, const series_options *so)
{
    if (isnan(y))
        return NAN;
    double ay = fabs(y);
    if (ay > (double)FLT_MAX) /* 0x1.ffffffp127: halfway between FLT_MAX and 2^128 */
        return ay < 0x1.ffffffp127 ? (y > 0 ? FLT_MAX : -FLT_MAX) : (y > 0 ? INFINITY : -INFINITY);
    float r = (float)y;
    int lo = 0, hi = 0, strict = 1;
    double L = 0, U = 0;
    switch (so->opt.shape) {
    case TS_SHAPE_POSITIVE:
        lo = 1, strict = 0; /* zeros allowed: S >= 0 */
        break;
    case TS_SHAPE_ABOVE:
        lo = 1, L = so->opt.lower.m * x + so->opt.lower.c;
        break;
    case TS_SHAPE_BELOW:
        hi = 1, U = so->opt.upper.m * x + so->opt.upper.c;
        break;
    case TS_SHAPE_BETWEEN:
        lo = hi = 1;
        L = so->opt.lower.m * x + so->opt.lower.c;
        U = so->opt.upper.m * x + so->opt.upper.c;
        break;
    default:
        return r;
    }
    if (lo && y >= L && ((double)r < L || ((double)r == L && (strict || y > L))))
        r = nextafterf(r, INFINITY);
    if (hi && y <= U && ((double)r > U || ((double)r == U && y < U)))
        r = nextafterf(r, -INFINITY);
    return r;
}

/* args: x, f, xq, opt, y, status, index, gap.  is_f32: f and y are float32;
 * x_f32: x and xq are float32 too. */
static void interp_loop(char **args, npy_intp const *dims, npy_intp const *steps, int is_f32,
                        int x_f32)
{
    npy_intp N = dims[0], n = dims[1], m = dims[2], k = dims[3];
    npy_intp sx = steps[8], sf = steps[9], sq = steps[10], so_ = steps[11], sy = steps[12];
    scratch w;
    record_buf rb;
    int ok = scratch_new(&w, n, m);
    ok &= records_new(&rb, k);
    /* Floating-point flags raised in here carry no information: the library's
     * vectorised construction loops compute lanes they then discard (see
     * src/internal.h, TS_VECTOR_LOOP), and float32 rounding underflows by
     * design.  Every failure is reported through status instead, so the
     * caller's flags are left as they were (numpy would turn stray flags into
     * FloatingPointError or RuntimeWarning). */
    fexcept_t flags;
    fegetexceptflag(&flags, FE_ALL_EXCEPT);
    for (npy_intp s = 0; s < N; s++) {
        char *px = args[0] + s * steps[0], *pf = args[1] + s * steps[1];
        char *pq = args[2] + s * steps[2], *po = args[3] + s * steps[3];
        char *py = args[4] + s * steps[4];
        npy_int32 *pst = (npy_int32 *)(args[5] + s * steps[5]);
        npy_int64 *pix = (npy_int64 *)(args[6] + s * steps[6]);
        double *pgap = (double *)(args[7] + s * steps[7]);
        series_options so;
        ts_status st;
        npy_int64 index = -1;
        double gap = (double)NAN;
        int valued = 0;
        if (!ok) {
            st = TS_ERR_NOMEM;
        } else if (!read_options(po, so_, k, &so, &rb)) {
            st = TS_ERR_OPTION;
        } else {
            load(w.x, px, sx, n, x_f32);
            load(w.f, pf, sf, n, is_f32);
            load(w.xq, pq, sq, m, x_f32);
            st = fit_series(&w, n, m, &so, &rb, &index, &gap, &valued);
        }
        *pst = (npy_int32)st;
        *pix = index;
        *pgap = gap;
        if (!valued) {
            for (npy_intp j = 0; j < m; j++) {
                if (is_f32)
                    *(float *)(py + j * sy) = NAN;
                else
                    *(double *)(py + j * sy) = (double)NAN;
            }
        } else if (is_f32) {
            for (npy_intp j = 0; j < m; j++)
                *(float *)(py + j * sy) = to_float32(w.y[j], w.xq[j], &so);
        } else {
            for (npy_intp j = 0; j < m; j++)
                *(double *)(py + j * sy) = w.y[j];
        }
    }
    fesetexceptflag(&flags, FE_ALL_EXCEPT);
    scratch_free(&w);
    records_free(&rb);
}

static void loop_f64(char **args, npy_intp const *dims, npy_intp const *steps, void *data)
{
    (void)data;
    interp_loop(args, dims, steps, 0, 0);
}

static void loop_f32_xf64(char **args, npy_intp const *dims, npy_intp const *steps, void *data)
{
    (void)data;
    interp_loop(args, dims, steps, 1, 0);
}

static void loop_f32(char **args, npy_intp const *dims, npy_intp const *steps, void *data)
{
    (void)data;
    interp_loop(args, dims, steps, 1, 1);
}

/* Resolution takes the first loop the inputs cast to safely: all float32;
 * float32 data with float64 coordinates (datetimes as seconds); float64. */
static PyUFuncGenericFunction interp_funcs[] = {loop_f32, loop_f32_xf64, loop_f64};
static void *interp_data[] = {NULL, NULL, NULL};
static char interp_types[] = {
    NPY_FLOAT, NPY_FLOAT, NPY_FLOAT, NPY_DOUBLE, NPY_FLOAT, NPY_INT32, NPY_INT64, NPY_DOUBLE,
    NPY_DOUBLE, NPY_FLOAT, NPY_DOUBLE, NPY_DOUBLE, NPY_FLOAT, NPY_INT32, NPY_INT64, NPY_DOUBLE,
    NPY_DOUBLE, NPY_DOUBLE, NPY_DOUBLE, NPY_DOUBLE, NPY_DOUBLE, NPY_INT32, NPY_INT64, NPY_DOUBLE,
};

static PyObject *py_strerror(PyObject *self, PyObject *arg)
{
    (void)self;
    long code = PyLong_AsLong(arg);
    if (code == -1 && PyErr_Occurred())
        return NULL;
    if (code < 0 || code > INT32_MAX)
        code = TS_STATUS_COUNT_; /* ts_strerror has a string for unknown codes */
    return PyUnicode_FromString(ts_strerror((ts_status)code));
}

/* message(code, index, where, x, f, opt): the library's sentence
 * (ts_error_message) of a series' failure, with its data and the options of
 * the option vector (index -1: none). */
static PyObject *py_message(PyObject *self, PyObject *args)
{
    (void)self;
    int code, where;
    long long index;
    PyObject *ox, *of, *oopt;
    if (!PyArg_ParseTuple(args, "iLiOOO", &code, &index, &where, &ox, &of, &oopt))
        return NULL;
    PyArrayObject *ax = (PyArrayObject *)PyArray_FROMANY(ox, NPY_DOUBLE, 1, 1, NPY_ARRAY_IN_ARRAY);
    PyArrayObject *af = ax ? (PyArrayObject *)PyArray_FROMANY(of, NPY_DOUBLE, 1, 1,
                                                              NPY_ARRAY_IN_ARRAY)
                           : NULL;
    PyArrayObject *ao = af ? (PyArrayObject *)PyArray_FROMANY(oopt, NPY_DOUBLE, 1, 1,
                                                              NPY_ARRAY_IN_ARRAY)
                           : NULL;
    PyObject *result = NULL;
    series_options so;
    record_buf rb;
    int have_rb = ao != NULL && records_new(&rb, PyArray_SIZE(ao));
    if (!ao) {
        /* exception set */
    } else if (!have_rb) {
        PyErr_NoMemory();
    } else if (PyArray_SIZE(ax) != PyArray_SIZE(af) ||
               !read_options(PyArray_DATA(ao), (npy_intp)sizeof(double), PyArray_SIZE(ao), &so,
                             &rb)) {
        PyErr_SetString(PyExc_ValueError, "message: x and f differ in length, or a bad option vector");
    } else {
        ts_error e = {(ts_status)code, index < 0 ? TS_NO_INDEX : (size_t)index,
                      (ts_where)where};
        ts_error_context ctx;
        ts_error_context_init(&ctx);
        ctx.x = PyArray_DATA(ax);
        ctx.f = PyArray_DATA(af);
        ctx.n_points = (size_t)PyArray_SIZE(ax);
        ctx.spline_options = &so.opt;
        char buf[1024];
        ts_error_message(&e, &ctx, buf, sizeof buf);
        result = PyUnicode_DecodeUTF8(buf, (Py_ssize_t)strlen(buf), "replace");
    }
    if (have_rb)
        records_free(&rb);
    Py_XDECREF(ax);
    Py_XDECREF(af);
    Py_XDECREF(ao);
    return result;
}

static PyMethodDef methods[] = {
    {"strerror", py_strerror, METH_O, "strerror(code) -> the library's fixed message for a status code."},
    {"message", py_message, METH_VARARGS,
     "message(code, index, where, x, f, opt) -> the library's sentence of a series' failure."},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef moduledef = {
    PyModuleDef_HEAD_INIT, "_gufunc",
    "numpy generalized ufuncs of trigspline (see trigspline.interp).", -1, methods,
    NULL, NULL, NULL, NULL,
};

PyMODINIT_FUNC PyInit__gufunc(void)
{
    PyObject *mod = PyModule_Create(&moduledef);
    if (!mod)
        return NULL;
    import_array();
    import_umath();
    PyObject *uf = PyUFunc_FromFuncAndDataAndSignature(
        interp_funcs, interp_data, interp_types, 3, 4, 4, PyUFunc_None, "interp",
        "interp(x, f, xq, opt) -> (y, status, index, gap): one certified spline per "
        "series; see trigspline.interp.",
        0, "(n),(n),(m),(k)->(m),(),(),()");
    if (!uf || PyModule_AddObject(mod, "interp", uf) < 0) {
        Py_XDECREF(uf);
        Py_DECREF(mod);
        return NULL;
    }
    if (PyModule_AddIntConstant(mod, "OPT_LEN", OPT_LEN) < 0 ||
        PyModule_AddStringConstant(mod, "version", ts_version()) < 0) {
        Py_DECREF(mod);
        return NULL;
    }
    return mod;
}
