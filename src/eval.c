/* Evaluation entry points: single, batch and threaded batch, integrals;
 * each form is routed to its interval evaluator or batch kernel (docs/method.md §2–§4). */
#define _POSIX_C_SOURCE 200809L
#include "internal.h"

#include <math.h>
#include <pthread.h>
#include <unistd.h>

#if defined(__GNUC__)
#define TS_NOINLINE __attribute__((noinline))
#else
#define TS_NOINLINE
#endif

/* x outside [x0, xn] or NaN: extrapolation mode (ts_extrap, header); o[1],
 * o[2] are 0 where it has no derivative.  lim: ±Inf under TS_EXTRAP_LINEAR
 * gives the limit (ts_spline_eval_mode) instead of TS_ERR_DOMAIN (ts_spline_eval). */
static ts_status eval_out(const ts_spline *sp, ts_extrap mode, int lim, double x, int want,
                          double o[3])
{
    o[1] = o[2] = 0.0;
    if (isnan(x) || (isinf(x) && mode != TS_EXTRAP_CLAMP && !(lim && mode == TS_EXTRAP_LINEAR)))
        return TS_ERR_DOMAIN;
    size_t n = sp->n;
    int left = x < sp->x[0];
    size_t i = left ? 0 : n - 1;
    double xe = left ? sp->x[0] : sp->x[n];
    switch (mode) {
    case TS_EXTRAP_CLAMP:
        o[0] = sp->f[left ? 0 : n];
        return TS_OK;
    case TS_EXTRAP_EXTEND:
        ts__interval_eval(sp, i, x, want, o);
        return TS_OK;
    case TS_EXTRAP_LINEAR: {
        double e[3] = {0.0, 0.0, 0.0};
        ts__interval_eval(sp, i, xe, 1, e);
        /* a flat end at ±Inf: the end value (the step, not the product,
         * chosen: 0 · Inf would raise FE_INVALID where a compiler computes
         * both sides of a select) */
        double dx = isinf(x) && e[1] == 0.0 ? 0.0 : x - xe;
        o[0] = sp->f[left ? 0 : n] + e[1] * dx;
        o[1] = e[1];
        return TS_OK;
    }
    case TS_EXTRAP_ERROR:
    default:
        return TS_ERR_DOMAIN;
    }
}

/* d^nu S/dx^nu, nu >= 3, paper and C¹ forms, at any x (docs/method.md §2,
 * derivatives of any order): 0 outside under CLAMP and LINEAR, the end
 * interval's own formula under EXTEND. */
static ts_status eval_high(const ts_spline *sp, ts_extrap mode, int lim, double x, int nu,
                           ts_cursor *cur, double *y)
{
    if (sp->x[0] <= x && x <= sp->x[sp->n]) { /* NaN fails */
        *y = ts__interval_deriv(sp, ts__locate(sp, x, cur), x, nu);
        return TS_OK;
    }
    double o[3];
    ts_status st = eval_out(sp, mode, lim, x, 0, o);
    if (st != TS_OK) {
        *y = (double)NAN;
        return st;
    }
    if (mode == TS_EXTRAP_EXTEND)
        *y = ts__interval_deriv(sp, x < sp->x[0] ? 0 : sp->n - 1, x, nu);
    else
        *y = 0.0;
    return TS_OK;
}

/* S, S', S'' at any x (o[0..want]; o[1], o[2] 0 beyond want inside, as
 * eval_out's outside). */
static ts_status eval_at(const ts_spline *sp, ts_extrap mode, int lim, double x, ts_cursor *cur,
                         int want, double o[3])
{
    if (!(sp->x[0] <= x && x <= sp->x[sp->n])) /* NaN fails */
        return eval_out(sp, mode, lim, x, want, o);
    o[1] = o[2] = 0.0;
    /* ts__locate's interval; dθ/dx stored where the cursor held x, formed
     * after a search (ts__trig_eval_in) */
    size_t n = sp->n, i = ts__cursor_interval(sp, x, cur);
    int held = i < n;
    if (!held)
        i = ts__search(sp->x, n, x, cur);
    if (sp->form == TS_FORM_GEOMETRIC)
        ts__geo_in(sp, i, x, want, o);
    else
        ts__trig_eval_in(sp, i, x, held ? sp->w[i] : ts__w(sp->x[i], sp->x[i + 1]), want, o);
    return TS_OK;
}

/* ts_spline_eval's every other case, out of line so that its usual one needs no
 * stack frame. */
static TS_NOINLINE ts_status eval_value(const ts_spline *s, double x, ts_cursor *cur, double *y)
{
    double o[3];
    ts_status st = s ? eval_at(s, s->extrap, 0, x, cur, 0, o) : TS_ERR_NULL;
    if (y)
        *y = st == TS_OK ? o[0] : (double)NAN;
    return st;
}

/* ts_spline_eval's usual case in the geometric form (x in interval i), out
 * of line so that the other forms' needs no stack frame. */
static TS_NOINLINE ts_status eval_geo(const ts_spline *s, size_t i, double x, double *y)
{
    double o[3];
    ts__geo_in(s, i, x, 0, o);
    *y = o[0];
    return TS_OK;
}

ts_status ts_spline_eval(const ts_spline *s, double x, ts_cursor *cur, double *y)
{
    /* the usual case: x in the cursor's interval or the next (so inside the
     * data; NaN fails); the same value as eval_at's */
    if (s && y) {
        size_t i = ts__cursor_step(s, x, cur);
        if (i < s->n) {
            if (s->form == TS_FORM_GEOMETRIC)
                return eval_geo(s, i, x, y);
            double o[3];
            ts__trig_eval_in(s, i, x, s->w[i], 0, o);
            *y = o[0];
            return TS_OK;
        }
    }
    return eval_value(s, x, cur, y);
}

ts_status ts_spline_eval_deriv(const ts_spline *s, double x, ts_cursor *cur, double *y, double *dy,
                               double *d2y)
{
    double o[3];
    ts_status st = s ? eval_at(s, s->extrap, 0, x, cur, d2y ? 2 : dy ? 1 : 0, o) : TS_ERR_NULL;
    if (st != TS_OK)
        o[0] = o[1] = o[2] = (double)NAN;
    if (y)
        *y = o[0];
    if (dy)
        *dy = o[1];
    if (d2y)
        *d2y = o[2];
    return st;
}

/* yq[j] = S^(deriv)(xq[j]), deriv >= 3 (paper and C¹ forms): one query at a
 * time, the cursor walking sorted queries. */
static ts_status batch_high(const ts_spline *s, ts_extrap mode, int lim, int deriv,
                            const double *xq, size_t m, double *yq, ts_cursor *cur, ts_error *err)
{
    ts_status result = TS_OK;
    for (size_t j = 0; j < m; j++) {
        ts_status st = eval_high(s, mode, lim, xq[j], deriv, cur, &yq[j]);
        if (st != TS_OK && result == TS_OK) {
            result = st;
            ts__error_set(err, st, j, TS_WHERE_QUERY);
        }
    }
    return result;
}

static ts_status batch_eval(const ts_spline *s, ts_extrap mode, int lim, int deriv,
                            const double *xq, size_t m, double *yq, ts_cursor *cur, ts_error *err)
{
    ts__error_set(err, TS_OK, TS_NO_INDEX, TS_WHERE_NONE);
    if (!s || (m && (!xq || !yq))) {
        ts__error_set(err, TS_ERR_NULL, TS_NO_INDEX, TS_WHERE_NONE);
        return TS_ERR_NULL;
    }
    if (deriv < 0 || (deriv > 2 && s->form == TS_FORM_GEOMETRIC) ||
        (unsigned)mode > (unsigned)TS_EXTRAP_LINEAR) {
        for (size_t j = 0; j < m; j++)
            yq[j] = (double)NAN;
        ts__error_set(err, TS_ERR_OPTION, TS_NO_INDEX, TS_WHERE_NONE);
        return TS_ERR_OPTION;
    }
    ts_cursor local = TS_CURSOR_INIT;
    if (!cur)
        cur = &local;
    if (deriv > 2)
        return batch_high(s, mode, lim, deriv, xq, m, yq, cur, err);
    double x0 = s->x[0], xn = s->x[s->n];
    ts_status result = TS_OK;
    /* The kernels take every block of queries inside [x0, xn]; a block that
     * holds a query outside (or NaN) is split into runs of in-range queries
     * (kernels again) and single queries (eval_out). */
    size_t j = 0;
    while (j < m) {
        j += ts__fast_batch(s, deriv, xq + j, m - j, yq + j, cur);
        if (j == m)
            break;
        size_t end = m - j < TS_FAST_BLOCK ? m : j + TS_FAST_BLOCK;
        size_t run = j; /* start of the current run of in-range queries */
        for (;; j++) { /* leaves at j == end */
            if (j < end && x0 <= xq[j] && xq[j] <= xn)
                continue;
            if (j > run)
                ts__fast_batch(s, deriv, xq + run, j - run, yq + run, cur);
            run = j + 1;
            if (j == end)
                break;
            double o[3];
            ts_status st = eval_out(s, mode, lim, xq[j], deriv, o);
            yq[j] = st == TS_OK ? o[deriv] : (double)NAN;
            if (st != TS_OK && result == TS_OK) {
                result = st;
                ts__error_set(err, st, j, TS_WHERE_QUERY);
            }
        }
    }
    return result;
}

ts_status ts_spline_eval_batch(const ts_spline *s, int deriv, const double *xq, size_t m,
                               double *yq, ts_cursor *cur, ts_error *err)
{
    return batch_eval(s, s ? s->extrap : TS_EXTRAP_ERROR, 0, deriv, xq, m, yq, cur, err);
}

ts_status ts_spline_eval_batch_mode(const ts_spline *s, int nu, ts_extrap extrap, const double *xq,
                                    size_t m, double *yq, ts_cursor *cur, ts_error *err)
{
    return batch_eval(s, extrap, 1, nu, xq, m, yq, cur, err);
}

ts_status ts_spline_eval_mode(const ts_spline *s, double x, int nu, ts_extrap extrap,
                              ts_cursor *cur, double *y)
{
    if (y)
        *y = (double)NAN;
    if (!s || !y)
        return TS_ERR_NULL;
    if (nu < 0 || (nu > 2 && s->form == TS_FORM_GEOMETRIC) ||
        (unsigned)extrap > (unsigned)TS_EXTRAP_LINEAR)
        return TS_ERR_OPTION;
    if (nu > 2)
        return eval_high(s, extrap, 1, x, nu, cur, y);
    double o[3];
    ts_status st = eval_at(s, extrap, 1, x, cur, nu, o);
    *y = st == TS_OK ? o[nu] : (double)NAN;
    return st;
}

typedef struct mt_job {
    const ts_spline *s;
    ts_extrap mode;
    int lim;
    int deriv;
    const double *xq;
    size_t m;
    double *yq;
    ts_status st;
    ts_error err;
} mt_job;

static void *mt_run(void *arg)
{
    mt_job *j = arg;
    j->st = batch_eval(j->s, j->mode, j->lim, j->deriv, j->xq, j->m, j->yq, NULL, &j->err);
    return NULL;
}

#define TS_MT_MAX 64
/* Below this many queries per thread a second thread costs more than it
 * saves (docs/design.md: 0.16x at 1e3 random queries, 1.24-1.49x at 1e4). */
#define TS_MT_MIN_PER_THREAD 8192

unsigned ts__mt_threads(unsigned asked, long online)
{
    unsigned long t = asked ? asked : online > 0 ? (unsigned long)online : 1ul;
    return t < TS_MT_MAX ? (unsigned)t : TS_MT_MAX;
}

static ts_status batch_mt(const ts_spline *s, ts_extrap mode, int lim, int deriv, const double *xq,
                          size_t m, double *yq, unsigned nthreads, ts_error *err)
{
    nthreads = ts__mt_threads(nthreads, nthreads ? 0 : sysconf(_SC_NPROCESSORS_ONLN));
    if (!s || nthreads <= 1 || m / TS_MT_MIN_PER_THREAD < (size_t)nthreads)
        return batch_eval(s, mode, lim, deriv, xq, m, yq, NULL, err);
    if (!xq || !yq || deriv < 0 || (deriv > 2 && s->form == TS_FORM_GEOMETRIC) ||
        (unsigned)mode > (unsigned)TS_EXTRAP_LINEAR)
        return batch_eval(s, mode, lim, deriv, xq, m, yq, NULL, err);
    ts__error_set(err, TS_OK, TS_NO_INDEX, TS_WHERE_NONE);
    mt_job jobs[TS_MT_MAX];
    pthread_t th[TS_MT_MAX];
    int started[TS_MT_MAX];
    size_t chunk = m / nthreads;
    for (unsigned t = 0; t < nthreads; t++) {
        size_t a = t * chunk, b = t + 1 == nthreads ? m : a + chunk;
        jobs[t] = (mt_job){
            s, mode, lim, deriv, xq + a, b - a, yq + a, TS_OK, {TS_OK, TS_NO_INDEX, TS_WHERE_NONE}};
        /* thread 0 runs on the caller's thread; a failed create runs inline */
        started[t] = t > 0 && pthread_create(&th[t], NULL, mt_run, &jobs[t]) == 0;
    }
    for (unsigned t = 0; t < nthreads; t++)
        if (!started[t])
            mt_run(&jobs[t]);
    ts_status result = TS_OK;
    for (unsigned t = 0; t < nthreads; t++) {
        if (started[t])
            pthread_join(th[t], NULL);
    }
    for (unsigned t = 0; t < nthreads; t++) {
        if (jobs[t].st != TS_OK) {
            /* only TS_ERR_DOMAIN, at a query (the arguments are checked above) */
            result = jobs[t].st;
            ts__error_set(err, result, t * chunk + jobs[t].err.index, jobs[t].err.where);
            break;
        }
    }
    return result;
}

ts_status ts_spline_eval_batch_mt(const ts_spline *s, int deriv, const double *xq, size_t m, double *yq,
                                  unsigned nthreads, ts_error *err)
{
    return batch_mt(s, s ? s->extrap : TS_EXTRAP_ERROR, 0, deriv, xq, m, yq, nthreads, err);
}

ts_status ts_spline_eval_batch_mode_mt(const ts_spline *s, int nu, ts_extrap extrap,
                                       const double *xq, size_t m, double *yq, unsigned nthreads,
                                       ts_error *err)
{
    return batch_mt(s, extrap, 1, nu, xq, m, yq, nthreads, err);
}

/* Piece i of an integral over [a, b] times 2^-*ki, *ki the first of k,
 * k + 128, ... that brings it below 2^(1023 - k) (each factor of h scaled:
 * finite from k + 1152 on, as h < 2^1024 and |B| <= TS_VALUE_MAX). */
static double scaled_piece(const ts_spline *s, size_t i, double a, double b, int k, int *ki)
{
    double lim = ldexp(1.0, 1023 - k), p;
    int kk = k;
    while (!(fabs(p = ts__interval_integral_scaled(s, i, a, b, kk)) <= lim) && kk < k + TS_LIMIT(integral_steps))
        kk += 128;
    *ki = kk;
    return p;
}

ts_status ts_spline_integral(const ts_spline *s, double a, double b, double *out)
{
    if (out)
        *out = (double)NAN;
    if (!s || !out)
        return TS_ERR_NULL;
    double x0 = s->x[0], xn = s->x[s->n];
    if (!(x0 <= a && a <= xn && x0 <= b && b <= xn))
        return TS_ERR_DOMAIN;
    if (a == b) {
        *out = 0.0;
        return TS_OK;
    }
    double sign = 1.0;
    if (a > b) {
        double t = a;
        a = b;
        b = t;
        sign = -1.0;
    }
    size_t ia, ib;
    ia = ts__locate(s, a, NULL);
    ib = ts__locate(s, b, NULL);
    double r;
    if (ia == ib)
        r = ts__interval_integral_scaled(s, ia, a, b, 0);
    else
        r = (ts__cum(s, ib) - ts__cum(s, ia + 1)) +
            ts__interval_integral_scaled(s, ia, a, s->x[ia + 1], 0) +
            ts__interval_integral_scaled(s, ib, s->x[ib], b, 0);
    if (!isfinite(r)) {
        /* the cumulative sums, two antiderivatives or one piece overflowed:
         * sum the pieces again, piece i times 2^-k_i with k_i the first of
         * k, k + 128, ... that brings it below 2^(1023 - k), k enough for
         * ib - ia + 1 such pieces to add up without overflow; then on the
         * largest k_i's scale.  Finite where the integral is, ±Inf where it
         * overflows, never NaN */
        int k = 2;
        for (size_t np = ib - ia + 1; np > 1; np = (np + 1) / 2)
            k++;
        int kmax = k;
        for (int pass = 0; pass < 2; pass++) {
            double sum = 0.0;
            for (size_t i = ia; i <= ib; i++) {
                int ki;
                double p = scaled_piece(s, i, i == ia ? a : s->x[i], i == ib ? b : s->x[i + 1],
                                        k, &ki);
                kmax = ki > kmax ? ki : kmax;
                sum += ldexp(p, ki - kmax);
            }
            r = ldexp(sum, kmax);
        }
    }
    *out = sign * r;
    return TS_OK;
}
