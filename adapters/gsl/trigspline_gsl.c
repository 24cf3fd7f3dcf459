/* GSL interpolation types backed by libtrigspline (see trigspline_gsl.h). */
#include "trigspline_gsl.h"

#include <gsl/gsl_errno.h>
#include <math.h>
#include <stdlib.h>

typedef struct ts_gsl_state {
    ts_spline *s;       /* NULL until a successful init */
    ts_error err;       /* of the last init */
    int inited;         /* an init was attempted */
    int configured;     /* opt replaces the type's defaults */
    ts_spline_options opt;
} ts_gsl_state;

/* The defaults of one type: the library's (ts_spline_options_init) with this shape,
 * and form C¹ for the "_c1" types. */
typedef struct ts_gsl_kind {
    ts_shape shape;
    int c1;
} ts_gsl_kind;

static const ts_gsl_kind kind_trig = {TS_SHAPE_NONE, 0};
static const ts_gsl_kind kind_positive = {TS_SHAPE_POSITIVE, 0};
static const ts_gsl_kind kind_monotone = {TS_SHAPE_MONOTONE, 0};
static const ts_gsl_kind kind_positive_c1 = {TS_SHAPE_POSITIVE, 1};
static const ts_gsl_kind kind_monotone_c1 = {TS_SHAPE_MONOTONE, 1};

int ts_gsl_status(ts_status status)
{
    switch (status) {
    case TS_OK:
        return GSL_SUCCESS;
    case TS_ERR_NOMEM:
        return GSL_ENOMEM;
    case TS_ERR_DOMAIN:
    case TS_ERR_NEGATIVE:
    case TS_ERR_NONMONOTONE:
    case TS_ERR_SIDE:
    case TS_ERR_LINES:
    case TS_ERR_INFEASIBLE:
    case TS_ERR_ZERO_SLOPE:
        return GSL_EDOM;
    default:
        return GSL_EINVAL;
    }
}

static void *ts_gsl_alloc(size_t size)
{
    (void)size;
    ts_gsl_state *st = calloc(1, sizeof *st);
    if (st) {
        st->s = NULL;
        st->err.status = TS_ERR_NULL;
        st->err.index = TS_NO_INDEX;
        st->err.where = TS_WHERE_NONE;
        ts_spline_options_init(&st->opt);
    }
    return st;
}

static void ts_gsl_free(void *vstate)
{
    ts_gsl_state *st = vstate;
    if (st)
        ts_spline_free(st->s);
    free(st);
}

static int init_kind(void *vstate, const double xa[], const double ya[], size_t size,
                     const ts_gsl_kind *k)
{
    ts_gsl_state *st = vstate;
    if (!st)
        return GSL_EINVAL;
    ts_spline_free(st->s);
    st->s = NULL;
    st->inited = 1;
    ts_spline_options o;
    if (st->configured) {
        o = st->opt;
    } else {
        ts_spline_options_init(&o);
        o.shape = k->shape;
        if (k->c1)
            o.form = TS_FORM_C1;
    }
    /* NaN / Inf in ya (or xa) gives TS_ERR_NONFINITE -> GSL_EINVAL */
    return ts_gsl_status(ts_spline_new(xa, ya, size, &o, &st->s, &st->err));
}

static int init_trig(void *st, const double xa[], const double ya[], size_t size)
{
    return init_kind(st, xa, ya, size, &kind_trig);
}

static int init_positive(void *st, const double xa[], const double ya[], size_t size)
{
    return init_kind(st, xa, ya, size, &kind_positive);
}

static int init_monotone(void *st, const double xa[], const double ya[], size_t size)
{
    return init_kind(st, xa, ya, size, &kind_monotone);
}

static int init_positive_c1(void *st, const double xa[], const double ya[], size_t size)
{
    return init_kind(st, xa, ya, size, &kind_positive_c1);
}

static int init_monotone_c1(void *st, const double xa[], const double ya[], size_t size)
{
    return init_kind(st, xa, ya, size, &kind_monotone_c1);
}

/* Value (which = 0) or derivative which of the spline at x; acc is the
 * ts_cursor hint. */
static int eval_which(const void *vstate, double x, gsl_interp_accel *acc, double *out,
                      int which)
{
    const ts_gsl_state *st = vstate;
    if (!out)
        return GSL_EINVAL;
    *out = (double)NAN;
    if (!st || !st->s)
        return GSL_EINVAL;
    double v[3];
    ts_status r;
    double *y = &v[0], *dy = which >= 1 ? &v[1] : NULL, *d2y = which >= 2 ? &v[2] : NULL;
    if (acc) {
        ts_cursor cur;
        cur.interval = acc->cache;
        r = ts_spline_eval_deriv(st->s, x, &cur, y, dy, d2y);
        if (cur.interval == acc->cache) {
            acc->hit_count++;
        } else {
            acc->miss_count++;
            acc->cache = cur.interval;
        }
    } else {
        r = ts_spline_eval_deriv(st->s, x, NULL, y, dy, d2y);
    }
    *out = v[which];
    return ts_gsl_status(r);
}

static int eval_y(const void *st, const double xa[], const double ya[], size_t size, double x,
                  gsl_interp_accel *acc, double *y)
{
    (void)xa, (void)ya, (void)size;
    return eval_which(st, x, acc, y, 0);
}

static int eval_d1(const void *st, const double xa[], const double ya[], size_t size, double x,
                   gsl_interp_accel *acc, double *y)
{
    (void)xa, (void)ya, (void)size;
    return eval_which(st, x, acc, y, 1);
}

static int eval_d2(const void *st, const double xa[], const double ya[], size_t size, double x,
                   gsl_interp_accel *acc, double *y)
{
    (void)xa, (void)ya, (void)size;
    return eval_which(st, x, acc, y, 2);
}

static int eval_integ(const void *vstate, const double xa[], const double ya[], size_t size,
                      gsl_interp_accel *acc, double a, double b, double *result)
{
    const ts_gsl_state *st = vstate;
    (void)xa, (void)ya, (void)size, (void)acc;
    if (!result)
        return GSL_EINVAL;
    *result = (double)NAN;
    if (!st || !st->s)
        return GSL_EINVAL;
    return ts_gsl_status(ts_spline_integral(st->s, a, b, result));
}

#define TS_GSL_TYPE(var, name, init)                                                         \
    static const gsl_interp_type var = {name, 2, &ts_gsl_alloc, &init, &eval_y, &eval_d1, \
                                        &eval_d2, &eval_integ, &ts_gsl_free}

TS_GSL_TYPE(type_trig, "trigspline", init_trig);
TS_GSL_TYPE(type_positive, "trigspline-positive", init_positive);
TS_GSL_TYPE(type_monotone, "trigspline-monotone", init_monotone);
TS_GSL_TYPE(type_positive_c1, "trigspline-positive-c1", init_positive_c1);
TS_GSL_TYPE(type_monotone_c1, "trigspline-monotone-c1", init_monotone_c1);

const gsl_interp_type *const ts_gsl_interp_trig = &type_trig;
const gsl_interp_type *const ts_gsl_interp_positive = &type_positive;
const gsl_interp_type *const ts_gsl_interp_monotone = &type_monotone;
const gsl_interp_type *const ts_gsl_interp_positive_c1 = &type_positive_c1;
const gsl_interp_type *const ts_gsl_interp_monotone_c1 = &type_monotone_c1;

int ts_gsl_is_trigspline(const gsl_interp_type *T)
{
    return T && (T == &type_trig || T == &type_positive || T == &type_monotone ||
                 T == &type_positive_c1 || T == &type_monotone_c1);
}

static ts_gsl_state *state_of(const gsl_interp *interp)
{
    if (!interp || !ts_gsl_is_trigspline(interp->type))
        return NULL;
    return interp->state;
}

int ts_gsl_configure(gsl_interp *interp, const ts_spline_options *opt)
{
    ts_gsl_state *st = state_of(interp);
    if (!st)
        return GSL_EINVAL;
    if (!opt) {
        st->configured = 0;
        ts_spline_options_init(&st->opt);
        return GSL_SUCCESS;
    }
    if ((unsigned)opt->form > (unsigned)TS_FORM_GEOMETRIC ||
        (unsigned)opt->slopes >= (unsigned)TS_SLOPES_COUNT_ ||
        (unsigned)opt->shape > (unsigned)TS_SHAPE_MONOTONE ||
        (unsigned)opt->extrapolate > (unsigned)TS_EXTRAP_LINEAR)
        return GSL_EINVAL;
    st->opt = *opt;
    st->configured = 1;
    return GSL_SUCCESS;
}

const ts_spline *ts_gsl_spline(const gsl_interp *interp)
{
    const ts_gsl_state *st = state_of(interp);
    return st ? st->s : NULL;
}

ts_status ts_gsl_last_error(const gsl_interp *interp, ts_error *err)
{
    const ts_gsl_state *st = state_of(interp);
    ts_error e = {TS_ERR_NULL, TS_NO_INDEX, TS_WHERE_NONE};
    if (st && st->inited)
        e = st->err;
    if (err)
        *err = e;
    return e.status;
}
