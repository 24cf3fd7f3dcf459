/* trigspline._core: the C extension behind the Python package.
 *
 * libtrigspline's sources are compiled into this module (setup.py), so the
 * installed package needs nothing else.  Three handle types own one C object
 * each (SplineHandle: ts_spline, CurveHandle: ts_curve, SurfaceHandle:
 * ts_surface); it is freed only in
 * tp_dealloc, when the last Python reference is gone, so no call reachable
 * from Python can use it after free or free it twice.  Fitted objects are
 * immutable (include/trigspline.h): the GIL is released around construction,
 * batch evaluation and every loop over queries or intervals.
 *
 * Failures of the library raise LibraryError(status, index, where) (a
 * ValueError) whose .message is the library's sentence (ts_error_message,
 * with the data and options of the call where it has them); the package
 * turns it into a TrigsplineError (trigspline/errors.py).
 *
 * The mathematics is the library's: derivatives of every order and the
 * extrapolation per call (ts_spline_eval_batch_mode), roots
 * (ts_spline_solve). */
#define PY_SSIZE_T_CLEAN
#include <Python.h>
#define NPY_NO_DEPRECATED_API NPY_1_7_API_VERSION
#include <numpy/arrayobject.h>

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#include "trigspline.h"

static PyObject *LibraryError;

/* Per-call extrapolation (ts_spline_eval_batch_mode; MODE_NAN: NaN outside). */
enum { MODE_EXTEND = 0, MODE_CLAMP = 1, MODE_LINEAR = 2, MODE_NAN = 3, MODE_ERROR = 4 };

/* Raise LibraryError(status, index, where) with .message = the library's
 * sentence (ts_error_message) for ctx, the data and options of the call
 * (NULL: the sentence without values). */
static PyObject *raise_ctx(ts_status st, size_t index, ts_where where,
                           const ts_error_context *ctx)
{
    PyObject *idx;
    if (index == TS_NO_INDEX) {
        idx = Py_None;
        Py_INCREF(idx);
    } else {
        idx = PyLong_FromSize_t(index);
    }
    ts_error e = {st, index, where};
    char buf[1024];
    ts_error_message(&e, ctx, buf, sizeof buf);
    PyObject *args = Py_BuildValue("(iNi)", (int)st, idx, (int)where);
    PyObject *exc = args ? PyObject_Call(LibraryError, args, NULL) : NULL;
    Py_XDECREF(args);
    PyObject *msg = exc ? PyUnicode_DecodeUTF8(buf, (Py_ssize_t)strlen(buf), "replace") : NULL;
    if (msg && PyObject_SetAttrString(exc, "message", msg) == 0)
        PyErr_SetObject(LibraryError, exc);
    Py_XDECREF(msg);
    Py_XDECREF(exc);
    return NULL;
}

static PyObject *raise_status(ts_status st, size_t index, ts_where where)
{
    return raise_ctx(st, index, where, NULL);
}

static PyObject *raise_err(ts_status st, const ts_error *e)
{
    return raise_status(st, e ? e->index : TS_NO_INDEX, e ? e->where : TS_WHERE_NONE);
}

/* raise_err for a failure on the spline data x, f (n points) with options opt. */
static PyObject *raise_spline_err(ts_status st, const ts_error *e, const double *x,
                                  const double *f, size_t n, const ts_spline_options *opt)
{
    ts_error_context ctx;
    ts_error_context_init(&ctx);
    ctx.x = x;
    ctx.f = f;
    ctx.n_points = n;
    ctx.spline_options = opt;
    return raise_ctx(st, e->index, e->where, &ctx);
}

/* A 1-D float64 C-contiguous array of obj (no copy when it already is one);
 * None stays NULL with *ok = 1. */
static PyArrayObject *as_vector(PyObject *obj, const char *what)
{
    PyArrayObject *a = (PyArrayObject *)PyArray_FROMANY(obj, NPY_DOUBLE, 1, 1,
                                                        NPY_ARRAY_IN_ARRAY);
    if (!a && PyErr_ExceptionMatches(PyExc_ValueError)) {
        PyErr_Clear();
        PyErr_Format(PyExc_ValueError, "%s must be a 1-D sequence of numbers", what);
    }
    return a;
}

/* A read-only array of n doubles at p, kept alive by owner. */
static PyObject *view(PyObject *owner, const double *p, npy_intp n)
{
    PyObject *a = PyArray_SimpleNewFromData(1, &n, NPY_DOUBLE, (void *)p);
    if (!a)
        return NULL;
    PyArray_CLEARFLAGS((PyArrayObject *)a, NPY_ARRAY_WRITEABLE);
    Py_INCREF(owner);
    if (PyArray_SetBaseObject((PyArrayObject *)a, owner) < 0) {
        Py_DECREF(a);
        return NULL;
    }
    return a;
}

/* ------------------------------------------------------------------ */
/* SplineHandle                                                         */
/* ------------------------------------------------------------------ */

typedef struct {
    PyObject_HEAD
    ts_spline *s;
    size_t n;
    double x0, xn;
    ts_form form;
} SplineHandle;

static void spline_dealloc(SplineHandle *self)
{
    ts_spline_free(self->s);
    self->s = NULL;
    Py_TYPE(self)->tp_free((PyObject *)self);
}

static PyTypeObject SplineHandleType;

/* Optional per-interval array: NULL/0 for None. */
static int opt_array(PyObject *obj, const char *what, PyArrayObject **keep, const double **p,
                     size_t *n)
{
    *keep = NULL;
    if (obj == Py_None)
        return 0;
    *keep = as_vector(obj, what);
    if (!*keep)
        return -1;
    *p = (const double *)PyArray_DATA(*keep);
    *n = (size_t)PyArray_SIZE(*keep);
    return 0;
}

static int opt_line(PyObject *obj, ts_line *l)
{
    if (obj == Py_None)
        return 0;
    return PyArg_ParseTuple(obj, "dd", &l->m, &l->c) ? 0 : -1;
}

/* spline_new(x, f, *, form=None, slopes=None, user_slopes=None, alpha=None,
 * alphas=None, beta=None, betas=None, shape=0, lower=None, upper=None,
 * margin=None, margins=None, certify=1, extrapolate=TS_EXTRAP_EXTEND).
 * None keeps the ts_spline_options_init default. */
static PyObject *spline_new(PyObject *mod, PyObject *args, PyObject *kw)
{
    (void)mod;
    static char *kwlist[] = {"x", "f", "form", "slopes", "user_slopes", "alpha", "alphas",
                             "beta", "betas", "shape", "lower", "upper", "margin", "margins",
                             "certify", "extrapolate", "constraints", NULL};
    PyObject *ox, *of, *oform = Py_None, *oslopes = Py_None, *ous = Py_None, *oalpha = Py_None,
                       *oalphas = Py_None, *obeta = Py_None, *obetas = Py_None,
                       *olower = Py_None, *oupper = Py_None, *omargin = Py_None,
                       *omargins = Py_None, *ocons = Py_None;
    int shape = 0, certify = 1, extrap = TS_EXTRAP_EXTEND;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "OO|$OOOOOOOiOOOOiiO", kwlist, &ox, &of, &oform,
                                     &oslopes, &ous, &oalpha, &oalphas, &obeta, &obetas, &shape,
                                     &olower, &oupper, &omargin, &omargins, &certify, &extrap,
                                     &ocons))
        return NULL;
    ts_spline_options opt;
    ts_spline_options_init(&opt);
    PyArrayObject *ax = NULL, *af = NULL, *aus = NULL, *aal = NULL, *abe = NULL, *ama = NULL;
    PyObject *result = NULL, *keep = NULL;
    ts_constraint *cons = NULL;
    ax = as_vector(ox, "x");
    if (!ax)
        goto done;
    af = as_vector(of, "f");
    if (!af)
        goto done;
    if (PyArray_SIZE(ax) != PyArray_SIZE(af)) {
        raise_status(TS_ERR_LENGTH, TS_NO_INDEX, TS_WHERE_NONE);
        goto done;
    }
    if (oform != Py_None) {
        opt.form = (ts_form)PyLong_AsLong(oform);
        if (PyErr_Occurred())
            goto done;
    }
    if (oslopes != Py_None) {
        opt.slopes = (ts_slopes)PyLong_AsLong(oslopes);
        if (PyErr_Occurred())
            goto done;
    }
    if (opt_array(ous, "user_slopes", &aus, &opt.user_slopes, &opt.n_user_slopes) < 0 ||
        opt_array(oalphas, "alphas", &aal, &opt.alphas, &opt.n_alphas) < 0 ||
        opt_array(obetas, "betas", &abe, &opt.betas, &opt.n_betas) < 0 ||
        opt_array(omargins, "margins", &ama, &opt.margins, &opt.n_margins) < 0)
        goto done;
    if (oalpha != Py_None && (opt.alpha = PyFloat_AsDouble(oalpha), PyErr_Occurred()))
        goto done;
    if (obeta != Py_None && (opt.beta = PyFloat_AsDouble(obeta), PyErr_Occurred()))
        goto done;
    if (omargin != Py_None && (opt.margin = PyFloat_AsDouble(omargin), PyErr_Occurred()))
        goto done;
    if (opt_line(olower, &opt.lower) < 0 || opt_line(oupper, &opt.upper) < 0)
        goto done;
    opt.shape = (ts_shape)shape;
    opt.certify = certify;
    opt.extrapolate = (ts_extrap)extrap;
    if (ocons != Py_None) {
        /* docs/method.md §13: a sequence of (kind, value, px or None, py or None,
         * first, count); px a SplineHandle (py None): a bound spline (§13.7) */
        PyObject *seq = PySequence_Fast(ocons, "constraints must be a sequence");
        if (!seq)
            goto done;
        Py_ssize_t nc = PySequence_Fast_GET_SIZE(seq);
        keep = PyList_New(0);
        cons = PyMem_Calloc(nc ? (size_t)nc : 1, sizeof *cons);
        if (!keep || !cons) {
            Py_DECREF(seq);
            if (!cons)
                PyErr_NoMemory();
            goto done;
        }
        for (Py_ssize_t k = 0; k < nc; k++) {
            PyObject *opx, *opy;
            int kind;
            Py_ssize_t first, count;
            ts_constraint_init(&cons[k], TS_CONSTRAINT_CONVEX);
            if (!PyArg_ParseTuple(PySequence_Fast_GET_ITEM(seq, k), "idOOnn", &kind,
                                  &cons[k].value, &opx, &opy, &first, &count)) {
                Py_DECREF(seq);
                goto done;
            }
            cons[k].kind = (ts_constraint_kind)kind;
            cons[k].first = (size_t)(first < 0 ? 0 : first);
            cons[k].count = (size_t)(count < 0 ? 0 : count);
            if (PyObject_TypeCheck(opx, &SplineHandleType)) {
                /* the record keeps opx alive during ts_spline_new; the
                 * fitted spline copies it */
                cons[k].bound = TS_BOUND_SPLINE;
                cons[k].spline = ((SplineHandle *)opx)->s;
            } else if (opx != Py_None) {
                PyArrayObject *a = as_vector(opx, "constraint points x"), *b = NULL;
                if (a)
                    b = as_vector(opy, "constraint points y");
                if (!a || !b || PyList_Append(keep, (PyObject *)a) < 0 ||
                    PyList_Append(keep, (PyObject *)b) < 0) {
                    Py_XDECREF(a);
                    Py_XDECREF(b);
                    Py_DECREF(seq);
                    goto done;
                }
                cons[k].bound = TS_BOUND_POLYLINE;
                cons[k].px = (const double *)PyArray_DATA(a);
                cons[k].py = (const double *)PyArray_DATA(b);
                cons[k].n_poly = (size_t)(PyArray_SIZE(a) < PyArray_SIZE(b) ? PyArray_SIZE(a)
                                                                             : PyArray_SIZE(b));
                Py_DECREF(a);
                Py_DECREF(b);
            }
        }
        Py_DECREF(seq);
        opt.constraints = cons;
        opt.n_constraints = (size_t)nc;
    }

    const double *px = (const double *)PyArray_DATA(ax), *pf = (const double *)PyArray_DATA(af);
    size_t np_ = (size_t)PyArray_SIZE(ax);
    ts_spline *s = NULL;
    ts_error err;
    ts_status st;
    Py_BEGIN_ALLOW_THREADS
    st = ts_spline_new(px, pf, np_, &opt, &s, &err);
    Py_END_ALLOW_THREADS
    if (st != TS_OK) {
        raise_spline_err(st, &err, px, pf, np_, &opt);
        goto done;
    }
    SplineHandle *h = PyObject_New(SplineHandle, &SplineHandleType);
    if (!h) {
        ts_spline_free(s);
        goto done;
    }
    h->s = s;
    h->n = ts_spline_intervals(s);
    h->x0 = ts_spline_x(s)[0];
    h->xn = ts_spline_x(s)[h->n];
    h->form = ts_spline_form(s);
    result = (PyObject *)h;
done:
    Py_XDECREF(ax);
    Py_XDECREF(af);
    Py_XDECREF(aus);
    Py_XDECREF(aal);
    Py_XDECREF(abe);
    Py_XDECREF(ama);
    Py_XDECREF(keep);
    PyMem_Free(cons);
    return result;
}

/* eval(xq, nu=0, mode=0, out=None, threads=1) -> ndarray of xq's shape
 * (0-d for a scalar).  NaN queries give NaN. */
static PyObject *spline_eval(SplineHandle *self, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"xq", "nu", "mode", "out", "threads", NULL};
    PyObject *oxq, *oout = Py_None;
    int nu = 0, mode = MODE_EXTEND, threads = 1;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "O|iiOi", kwlist, &oxq, &nu, &mode, &oout,
                                     &threads))
        return NULL;
    if (nu < 0) {
        PyErr_SetString(PyExc_ValueError, "the derivative order nu must be >= 0");
        return NULL;
    }
    if (nu > 2 && self->form == TS_FORM_GEOMETRIC) {
        PyErr_SetString(PyExc_ValueError,
                        "derivatives of order > 2 are available in the paper and c1 forms "
                        "only (the geometric form is parametric, docs/method.md §4)");
        return NULL;
    }
    PyArrayObject *aq = (PyArrayObject *)PyArray_FROMANY(oxq, NPY_DOUBLE, 0, 0, NPY_ARRAY_IN_ARRAY);
    if (!aq)
        return NULL;
    PyArrayObject *ao;
    if (oout == Py_None) {
        ao = (PyArrayObject *)PyArray_SimpleNew(PyArray_NDIM(aq), PyArray_DIMS(aq), NPY_DOUBLE);
        if (!ao) {
            Py_DECREF(aq);
            return NULL;
        }
    } else {
        if (!PyArray_Check(oout) || PyArray_TYPE((PyArrayObject *)oout) != NPY_DOUBLE ||
            !PyArray_IS_C_CONTIGUOUS((PyArrayObject *)oout) ||
            !PyArray_ISWRITEABLE((PyArrayObject *)oout) ||
            PyArray_SIZE((PyArrayObject *)oout) != PyArray_SIZE(aq)) {
            Py_DECREF(aq);
            PyErr_SetString(PyExc_ValueError, "out must be a writable C-contiguous float64 "
                                              "array with one element per query");
            return NULL;
        }
        ao = (PyArrayObject *)oout;
        Py_INCREF(ao);
    }
    const double *xq = (const double *)PyArray_DATA(aq);
    double *yq = (double *)PyArray_DATA(ao);
    npy_intp m = PyArray_SIZE(aq);
    /* MODE_EXTEND: the handle's own policy (TS_EXTRAP_EXTEND for the
     * package's handles), through ts_spline_eval_batch */
    ts_extrap ex = mode == MODE_CLAMP    ? TS_EXTRAP_CLAMP
                   : mode == MODE_LINEAR ? TS_EXTRAP_LINEAR
                                         : TS_EXTRAP_ERROR;
    unsigned nth = threads < 0 ? 0u : (unsigned)threads;
    ts_status st;
    ts_error err = {TS_OK, TS_NO_INDEX, TS_WHERE_NONE};
    npy_intp bad = -1;
    Py_BEGIN_ALLOW_THREADS
    if (mode == MODE_EXTEND)
        st = threads == 1 ? ts_spline_eval_batch(self->s, nu, xq, (size_t)m, yq, NULL, &err)
                          : ts_spline_eval_batch_mt(self->s, nu, xq, (size_t)m, yq, nth, &err);
    else if (threads == 1)
        st = ts_spline_eval_batch_mode(self->s, nu, ex, xq, (size_t)m, yq, NULL, &err);
    else
        st = ts_spline_eval_batch_mode_mt(self->s, nu, ex, xq, (size_t)m, yq, nth, &err);
    if (st == TS_ERR_DOMAIN) {
        /* invalid queries are NaN; MODE_ERROR (or an unknown mode) raises,
         * at the first one that is outside the data (NaN queries give NaN) */
        int raises = mode != MODE_EXTEND && mode != MODE_CLAMP && mode != MODE_LINEAR &&
                     mode != MODE_NAN;
        st = TS_OK;
        for (size_t j = err.index; raises && j < (size_t)m; j++)
            if (xq[j] == xq[j] && !(self->x0 <= xq[j] && xq[j] <= self->xn)) {
                bad = (npy_intp)j;
                break;
            }
    }
    Py_END_ALLOW_THREADS
    if (st != TS_OK || bad >= 0) {
        Py_DECREF(aq);
        Py_DECREF(ao);
        if (st != TS_OK)
            return raise_err(st, &err);
        return raise_status(TS_ERR_DOMAIN, PyArray_NDIM(aq) == 0 ? TS_NO_INDEX : (size_t)bad,
                            TS_WHERE_QUERY);
    }
    Py_DECREF(aq);
    return (PyObject *)ao;
}

/* integral(a, b) -> float (a, b in [x0, xn]). */
static PyObject *spline_integral(SplineHandle *self, PyObject *args)
{
    double a, b, r;
    if (!PyArg_ParseTuple(args, "dd", &a, &b))
        return NULL;
    ts_status st = ts_spline_integral(self->s, a, b, &r);
    if (st != TS_OK)
        return raise_status(st, TS_NO_INDEX, TS_WHERE_NONE);
    return PyFloat_FromDouble(r);
}

/* antiderivative(xq) -> ∫_{x0}^{xq} S per query, NaN outside [x0, xn]
 * (the package adds the extrapolated parts). */
static PyObject *spline_antiderivative(SplineHandle *self, PyObject *arg)
{
    PyArrayObject *aq = (PyArrayObject *)PyArray_FROMANY(arg, NPY_DOUBLE, 0, 0, NPY_ARRAY_IN_ARRAY);
    if (!aq)
        return NULL;
    PyArrayObject *ao =
        (PyArrayObject *)PyArray_SimpleNew(PyArray_NDIM(aq), PyArray_DIMS(aq), NPY_DOUBLE);
    if (!ao) {
        Py_DECREF(aq);
        return NULL;
    }
    const double *xq = (const double *)PyArray_DATA(aq);
    double *yq = (double *)PyArray_DATA(ao);
    npy_intp m = PyArray_SIZE(aq);
    Py_BEGIN_ALLOW_THREADS
    for (npy_intp j = 0; j < m; j++)
        if (ts_spline_integral(self->s, self->x0, xq[j], &yq[j]) != TS_OK)
            yq[j] = (double)NAN;
    Py_END_ALLOW_THREADS
    Py_DECREF(aq);
    return (PyObject *)ao;
}

/* ---- roots --------------------------------------------------------- */

/* solve(y) -> sorted x with S(x) = y in [x0, xn]; an interval where S == y
 * identically gives its left end followed by NaN (as SciPy's PPoly.roots). */
static PyObject *spline_solve(SplineHandle *self, PyObject *args)
{
    double y;
    if (!PyArg_ParseTuple(args, "d", &y))
        return NULL;
    size_t cap = 4 * self->n + 4, count = 0; /* enough unless S wiggles across y */
    double *buf = NULL;
    ts_status st = TS_ERR_LENGTH;
    for (int pass = 0; pass < 2 && st == TS_ERR_LENGTH; pass++) {
        if (pass)
            cap = count;
        PyMem_Free(buf);
        buf = cap <= PY_SSIZE_T_MAX / sizeof *buf ? PyMem_Malloc((cap ? cap : 1) * sizeof *buf)
                                                  : NULL;
        if (!buf)
            return PyErr_NoMemory();
        Py_BEGIN_ALLOW_THREADS
        st = ts_spline_solve(self->s, y, buf, cap, &count);
        Py_END_ALLOW_THREADS
    }
    if (st != TS_OK) {
        PyMem_Free(buf);
        return raise_status(st, TS_NO_INDEX, TS_WHERE_NONE);
    }
    npy_intp nr = (npy_intp)count;
    PyObject *a = PyArray_SimpleNew(1, &nr, NPY_DOUBLE);
    if (a && nr)
        memcpy(PyArray_DATA((PyArrayObject *)a), buf, count * sizeof(double));
    PyMem_Free(buf);
    return a;
}

/* ---- accessors ----------------------------------------------------- */

static PyObject *spline_x(SplineHandle *self, void *c)
{
    (void)c;
    return view((PyObject *)self, ts_spline_x(self->s), (npy_intp)self->n + 1);
}
static PyObject *spline_f(SplineHandle *self, void *c)
{
    (void)c;
    return view((PyObject *)self, ts_spline_f(self->s), (npy_intp)self->n + 1);
}
static PyObject *spline_slopes(SplineHandle *self, void *c)
{
    (void)c;
    return view((PyObject *)self, ts_spline_slopes(self->s), (npy_intp)self->n + 1);
}
static PyObject *spline_alpha(SplineHandle *self, void *c)
{
    (void)c;
    return view((PyObject *)self, ts_spline_alpha(self->s), (npy_intp)self->n);
}
static PyObject *spline_beta(SplineHandle *self, void *c)
{
    (void)c;
    return view((PyObject *)self, ts_spline_beta(self->s), (npy_intp)self->n);
}
static PyObject *spline_intervals(SplineHandle *self, void *c)
{
    (void)c;
    return PyLong_FromSize_t(self->n);
}
static PyObject *spline_form(SplineHandle *self, void *c)
{
    (void)c;
    return PyLong_FromLong((long)self->form);
}
static PyObject *spline_shape(SplineHandle *self, void *c)
{
    (void)c;
    return PyLong_FromLong((long)ts_spline_shape(self->s));
}
static PyObject *spline_certified(SplineHandle *self, void *c)
{
    (void)c;
    return PyBool_FromLong(ts_spline_certified(self->s));
}

/* control() -> (B, X), arrays of shape (n, 4). */
static PyObject *spline_control(SplineHandle *self, PyObject *unused)
{
    (void)unused;
    npy_intp dims[2] = {(npy_intp)self->n, 4};
    PyObject *B = PyArray_SimpleNew(2, dims, NPY_DOUBLE);
    PyObject *X = B ? PyArray_SimpleNew(2, dims, NPY_DOUBLE) : NULL;
    if (!X) {
        Py_XDECREF(B);
        return NULL;
    }
    double *pb = (double *)PyArray_DATA((PyArrayObject *)B);
    double *px = (double *)PyArray_DATA((PyArrayObject *)X);
    Py_BEGIN_ALLOW_THREADS
    for (size_t i = 0; i < self->n; i++)
        ts_spline_control(self->s, i, pb + 4 * i, px + 4 * i);
    Py_END_ALLOW_THREADS
    return Py_BuildValue("(NN)", B, X);
}

static PyObject *report_tuple(const ts_interval_report *r)
{
    return Py_BuildValue("(ddddd(dddd)iiiddddidddddd)", r->x0, r->x1, r->alpha, r->beta, r->a,
                         r->B[0], r->B[1], r->B[2], r->B[3], (int)r->term, r->has_lower,
                         r->has_upper, r->gap_lower, r->at_lower, r->gap_upper, r->at_upper,
                         r->certified, r->y_min, r->at_y_min, r->y_max, r->at_y_max,
                         r->excursion_above, r->excursion_below);
}

/* The result of a certify call: (ok, first violating index or None, [report
 * tuples]); raises for any other failure.  Frees reps. */
static PyObject *certify_result(ts_status st, const ts_error *err, ts_interval_report *reps,
                                size_t n)
{
    if (st != TS_OK && st != TS_ERR_VIOLATED) {
        PyMem_Free(reps);
        return raise_err(st, err);
    }
    PyObject *list = PyList_New((Py_ssize_t)n);
    for (size_t i = 0; list && i < n; i++) {
        PyObject *t = report_tuple(&reps[i]);
        if (!t) {
            Py_CLEAR(list);
            break;
        }
        PyList_SET_ITEM(list, (Py_ssize_t)i, t);
    }
    PyMem_Free(reps);
    if (!list)
        return NULL;
    PyObject *idx = st == TS_OK ? (Py_INCREF(Py_None), Py_None) : PyLong_FromSize_t(err->index);
    return Py_BuildValue("(ONN)", st == TS_OK ? Py_True : Py_False, idx, list);
}

/* report(i) -> tuple (x0, x1, alpha, beta, a, (B0..B3), term, has_lower,
 * has_upper, gap_lower, at_lower, gap_upper, at_upper, certified, y_min, at_y_min,
 * y_max, at_y_max, excursion_above, excursion_below). */
static PyObject *spline_report(SplineHandle *self, PyObject *args)
{
    Py_ssize_t i;
    if (!PyArg_ParseTuple(args, "n", &i))
        return NULL;
    ts_interval_report r = TS_INTERVAL_REPORT_INIT;
    ts_status st = i < 0 ? TS_ERR_INDEX : ts_spline_report(self->s, (size_t)i, &r);
    if (st != TS_OK)
        return raise_status(st, (size_t)i, TS_WHERE_INTERVAL);
    return report_tuple(&r);
}

/* constraint_report(k, i) -> (in_scope, active, gap, at, certified) (docs/method.md §13). */
static PyObject *spline_constraint_report(SplineHandle *self, PyObject *args)
{
    Py_ssize_t k, i;
    if (!PyArg_ParseTuple(args, "nn", &k, &i))
        return NULL;
    ts_constraint_report r;
    ts_constraint_report_init(&r);
    ts_status st = k < 0 || i < 0 ? TS_ERR_INDEX
                                  : ts_spline_constraint_report(self->s, (size_t)k, (size_t)i, &r);
    if (st != TS_OK)
        return raise_status(st, (size_t)i, TS_WHERE_INTERVAL);
    return Py_BuildValue("(iiddi)", r.in_scope, r.active, r.gap, r.at, r.certified);
}

static PyObject *spline_n_constraints(SplineHandle *self, void *closure)
{
    (void)closure;
    return PyLong_FromSize_t(ts_spline_constraints(self->s));
}

/* certify(lower, upper) -> (ok, first violating interval or None, [report tuples]). */
static PyObject *spline_certify(SplineHandle *self, PyObject *args)
{
    PyObject *olo, *oup;
    if (!PyArg_ParseTuple(args, "OO", &olo, &oup))
        return NULL;
    ts_line lo, up;
    if ((olo != Py_None && !PyArg_ParseTuple(olo, "dd", &lo.m, &lo.c)) ||
        (oup != Py_None && !PyArg_ParseTuple(oup, "dd", &up.m, &up.c)))
        return NULL;
    size_t n = self->n;
    ts_interval_report *reps = PyMem_Calloc(n ? n : 1, sizeof *reps);
    if (!reps)
        return PyErr_NoMemory();
    ts_interval_report_init(reps, 1);
    ts_error err;
    ts_status st;
    Py_BEGIN_ALLOW_THREADS
    st = ts_spline_certify(self->s, olo == Py_None ? NULL : &lo, oup == Py_None ? NULL : &up, reps, &err);
    Py_END_ALLOW_THREADS
    return certify_result(st, &err, reps, n);
}

/* error_bound(fprime_max, fsecond_max, exact_slopes) -> (bound, per-interval array). */
static PyObject *spline_error_bound(SplineHandle *self, PyObject *args)
{
    double fp, fs;
    int exact;
    if (!PyArg_ParseTuple(args, "ddp", &fp, &fs, &exact))
        return NULL;
    npy_intp n = (npy_intp)self->n;
    PyObject *per = PyArray_SimpleNew(1, &n, NPY_DOUBLE);
    if (!per)
        return NULL;
    double b;
    ts_status st = ts_spline_error_bound(self->s, fp, fs, exact, &b,
                                         (double *)PyArray_DATA((PyArrayObject *)per));
    if (st != TS_OK) {
        Py_DECREF(per);
        return raise_status(st, TS_NO_INDEX, TS_WHERE_NONE);
    }
    return Py_BuildValue("(dN)", b, per);
}

static PyMethodDef spline_methods[] = {
    {"eval", (PyCFunction)(void (*)(void))spline_eval, METH_VARARGS | METH_KEYWORDS,
     "eval(xq, nu=0, mode=0, out=None, threads=1): values or derivatives"},
    {"integral", (PyCFunction)spline_integral, METH_VARARGS, "integral(a, b)"},
    {"antiderivative", (PyCFunction)spline_antiderivative, METH_O,
     "antiderivative(xq): integral from x0 to each query (NaN outside)"},
    {"solve", (PyCFunction)spline_solve, METH_VARARGS, "solve(y): x in [x0, xn] with S(x) = y"},
    {"control", (PyCFunction)spline_control, METH_NOARGS, "control() -> (B, X), shape (n, 4)"},
    {"report", (PyCFunction)spline_report, METH_VARARGS, "report(i) -> tuple"},
    {"constraint_report", (PyCFunction)spline_constraint_report, METH_VARARGS,
     "constraint_report(k, i) -> (in_scope, active, gap, at, certified)"},
    {"certify", (PyCFunction)spline_certify, METH_VARARGS, "certify(lower, upper)"},
    {"error_bound", (PyCFunction)spline_error_bound, METH_VARARGS,
     "error_bound(fprime_max, fsecond_max, exact_slopes)"},
    {NULL, NULL, 0, NULL}};

static PyGetSetDef spline_getset[] = {
    {"x", (getter)spline_x, NULL, "knots (read-only view)", NULL},
    {"f", (getter)spline_f, NULL, "values (read-only view)", NULL},
    {"slopes", (getter)spline_slopes, NULL, "slopes used (read-only view)", NULL},
    {"alpha", (getter)spline_alpha, NULL, "alpha per interval (read-only view)", NULL},
    {"beta", (getter)spline_beta, NULL, "beta per interval (read-only view)", NULL},
    {"intervals", (getter)spline_intervals, NULL, "number of intervals", NULL},
    {"form", (getter)spline_form, NULL, "ts_form", NULL},
    {"shape", (getter)spline_shape, NULL, "ts_shape", NULL},
    {"n_constraints", (getter)spline_n_constraints, NULL, "constraint records", NULL},
    {"certified", (getter)spline_certified, NULL, "ts_spline_certified", NULL},
    {NULL, NULL, NULL, NULL, NULL}};

static PyTypeObject SplineHandleType = {
    PyVarObject_HEAD_INIT(NULL, 0).tp_name = "trigspline._core.SplineHandle",
    .tp_basicsize = sizeof(SplineHandle),
    .tp_dealloc = (destructor)spline_dealloc,
    .tp_flags = Py_TPFLAGS_DEFAULT,
    .tp_doc = "A fitted ts_spline (immutable; made by spline_new).",
    .tp_methods = spline_methods,
    .tp_getset = spline_getset,
};

/* ------------------------------------------------------------------ */
/* CurveHandle                                                          */
/* ------------------------------------------------------------------ */

typedef struct {
    PyObject_HEAD
    ts_curve *c;
    size_t n, dim;
} CurveHandle;

static void curve_dealloc(CurveHandle *self)
{
    ts_curve_free(self->c);
    self->c = NULL;
    Py_TYPE(self)->tp_free((PyObject *)self);
}

static PyTypeObject CurveHandleType;

/* curve_new(points (m, dim), *, param=None, closed=0, slopes=None, alpha=None,
 * alphas=None, beta=None, betas=None, lo=None, hi=None, margin=None);
 * lo/hi: sequences of dim values, NaN for an open side. */
static PyObject *curve_new(PyObject *mod, PyObject *args, PyObject *kw)
{
    (void)mod;
    static char *kwlist[] = {"points", "param", "closed", "slopes", "alpha", "alphas", "beta",
                             "betas", "lo", "hi", "margin", NULL};
    PyObject *op, *oparam = Py_None, *oslopes = Py_None, *oalpha = Py_None, *oalphas = Py_None,
                  *obeta = Py_None, *obetas = Py_None, *olo = Py_None, *ohi = Py_None,
                  *omargin = Py_None;
    int closed = 0;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "O|$OiOOOOOOOO", kwlist, &op, &oparam, &closed,
                                     &oslopes, &oalpha, &oalphas, &obeta, &obetas, &olo, &ohi,
                                     &omargin))
        return NULL;
    ts_curve_options opt;
    ts_curve_options_init(&opt);
    PyObject *result = NULL;
    PyArrayObject *ap = NULL, *aal = NULL, *abe = NULL, *alo = NULL, *ahi = NULL;
    ap = (PyArrayObject *)PyArray_FROMANY(op, NPY_DOUBLE, 2, 2, NPY_ARRAY_IN_ARRAY);
    if (!ap)
        goto done;
    opt.closed = closed;
    if (oparam != Py_None && (opt.param = (ts_param)PyLong_AsLong(oparam), PyErr_Occurred()))
        goto done;
    if (oslopes != Py_None && (opt.slopes = (ts_slopes)PyLong_AsLong(oslopes), PyErr_Occurred()))
        goto done;
    if (oalpha != Py_None && (opt.alpha = PyFloat_AsDouble(oalpha), PyErr_Occurred()))
        goto done;
    if (obeta != Py_None && (opt.beta = PyFloat_AsDouble(obeta), PyErr_Occurred()))
        goto done;
    if (omargin != Py_None && (opt.margin = PyFloat_AsDouble(omargin), PyErr_Occurred()))
        goto done;
    if (opt_array(oalphas, "alphas", &aal, &opt.alphas, &opt.n_alphas) < 0 ||
        opt_array(obetas, "betas", &abe, &opt.betas, &opt.n_betas) < 0)
        goto done;
    size_t dim = (size_t)PyArray_DIM(ap, 1);
    if (olo != Py_None || ohi != Py_None) {
        const double *p;
        size_t nb;
        if (opt_array(olo, "lo", &alo, &p, &nb) < 0 || opt_array(ohi, "hi", &ahi, &p, &nb) < 0)
            goto done;
        for (size_t k = 0; k < 3 && k < dim; k++) {
            if (alo && k < (size_t)PyArray_SIZE(alo)) {
                double v = ((const double *)PyArray_DATA(alo))[k];
                opt.has_lo[k] = v == v, opt.lo[k] = v;
            }
            if (ahi && k < (size_t)PyArray_SIZE(ahi)) {
                double v = ((const double *)PyArray_DATA(ahi))[k];
                opt.has_hi[k] = v == v, opt.hi[k] = v;
            }
        }
    }
    ts_curve *c = NULL;
    ts_error err;
    ts_status st;
    const double *pts = (const double *)PyArray_DATA(ap);
    size_t m = (size_t)PyArray_DIM(ap, 0);
    Py_BEGIN_ALLOW_THREADS
    st = ts_curve_new(pts, m, dim, &opt, &c, &err);
    Py_END_ALLOW_THREADS
    if (st != TS_OK) {
        ts_error_context ctx;
        ts_error_context_init(&ctx);
        ctx.points = pts;
        ctx.n_points = m;
        ctx.dim = dim;
        ctx.curve_options = &opt;
        raise_ctx(st, err.index, err.where, &ctx);
        goto done;
    }
    CurveHandle *h = PyObject_New(CurveHandle, &CurveHandleType);
    if (!h) {
        ts_curve_free(c);
        goto done;
    }
    h->c = c;
    h->n = ts_curve_segments(c);
    h->dim = ts_curve_dim(c);
    result = (PyObject *)h;
done:
    Py_XDECREF(ap);
    Py_XDECREF(aal);
    Py_XDECREF(abe);
    Py_XDECREF(alo);
    Py_XDECREF(ahi);
    return result;
}

/* eval(t, nu=0, mode=MODE_ERROR) -> array t.shape + (dim,); NaN t gives NaN;
 * outside an open curve: MODE_NAN gives NaN, MODE_ERROR raises. */
static PyObject *curve_eval(CurveHandle *self, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"t", "nu", "mode", NULL};
    PyObject *ot;
    int nu = 0, mode = MODE_ERROR;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "O|ii", kwlist, &ot, &nu, &mode))
        return NULL;
    if (nu < 0 || nu > 2) {
        PyErr_SetString(PyExc_ValueError, "curves have derivatives of order 0, 1 and 2");
        return NULL;
    }
    PyArrayObject *at = (PyArrayObject *)PyArray_FROMANY(ot, NPY_DOUBLE, 0, 0, NPY_ARRAY_IN_ARRAY);
    if (!at)
        return NULL;
    int nd = PyArray_NDIM(at);
    npy_intp dims[NPY_MAXDIMS];
    if (nd + 1 > NPY_MAXDIMS) {
        Py_DECREF(at);
        PyErr_SetString(PyExc_ValueError, "too many dimensions");
        return NULL;
    }
    for (int k = 0; k < nd; k++)
        dims[k] = PyArray_DIM(at, k);
    dims[nd] = (npy_intp)self->dim;
    PyArrayObject *ao = (PyArrayObject *)PyArray_SimpleNew(nd + 1, dims, NPY_DOUBLE);
    if (!ao) {
        Py_DECREF(at);
        return NULL;
    }
    const double *t = (const double *)PyArray_DATA(at);
    double *o = (double *)PyArray_DATA(ao);
    npy_intp m = PyArray_SIZE(at), bad = -1;
    size_t dim = self->dim;
    ts_status st = TS_OK;
    Py_BEGIN_ALLOW_THREADS
    ts_cursor cur = TS_CURSOR_INIT;
    for (npy_intp j = 0; j < m; j++) {
        double p[3][3];
        double *row = o + (size_t)j * dim;
        ts_status sj = ts_curve_eval(self->c, t[j], &cur, p[0], nu >= 1 ? p[1] : NULL,
                                     nu >= 2 ? p[2] : NULL);
        if (sj == TS_ERR_DOMAIN && (t[j] != t[j] || mode == MODE_NAN)) {
            for (size_t k = 0; k < dim; k++)
                row[k] = (double)NAN;
            continue;
        }
        if (sj != TS_OK) {
            st = sj;
            bad = j;
            break;
        }
        for (size_t k = 0; k < dim; k++)
            row[k] = p[nu][k];
    }
    Py_END_ALLOW_THREADS
    Py_DECREF(at);
    if (st != TS_OK) {
        Py_DECREF(ao);
        return raise_status(st, nd == 0 ? TS_NO_INDEX : (size_t)bad, TS_WHERE_QUERY);
    }
    return (PyObject *)ao;
}

static PyObject *curve_knots(CurveHandle *self, void *c)
{
    (void)c;
    return view((PyObject *)self, ts_curve_knots(self->c), (npy_intp)self->n + 1);
}
static PyObject *curve_segments(CurveHandle *self, void *c)
{
    (void)c;
    return PyLong_FromSize_t(self->n);
}
static PyObject *curve_dim(CurveHandle *self, void *c)
{
    (void)c;
    return PyLong_FromSize_t(self->dim);
}
static PyObject *curve_closed(CurveHandle *self, void *c)
{
    (void)c;
    return PyBool_FromLong(ts_curve_closed(self->c));
}

/* control() -> array (segments, 4, dim); params() -> (alpha, beta) arrays. */
static PyObject *curve_control(CurveHandle *self, PyObject *unused)
{
    (void)unused;
    npy_intp dims[3] = {(npy_intp)self->n, 4, (npy_intp)self->dim};
    PyObject *a = PyArray_SimpleNew(3, dims, NPY_DOUBLE);
    if (!a)
        return NULL;
    double *p = (double *)PyArray_DATA((PyArrayObject *)a);
    for (size_t i = 0; i < self->n; i++)
        ts_curve_control(self->c, i, p + 4 * self->dim * i);
    return a;
}

static PyObject *curve_params(CurveHandle *self, PyObject *unused)
{
    (void)unused;
    npy_intp n = (npy_intp)self->n;
    PyObject *al = PyArray_SimpleNew(1, &n, NPY_DOUBLE);
    PyObject *be = al ? PyArray_SimpleNew(1, &n, NPY_DOUBLE) : NULL;
    if (!be) {
        Py_XDECREF(al);
        return NULL;
    }
    double *pa = (double *)PyArray_DATA((PyArrayObject *)al);
    double *pb = (double *)PyArray_DATA((PyArrayObject *)be);
    for (size_t i = 0; i < self->n; i++)
        ts_curve_params(self->c, i, pa + i, pb + i);
    return Py_BuildValue("(NN)", al, be);
}

static PyObject *curve_length(CurveHandle *self, PyObject *args)
{
    double tol, len;
    if (!PyArg_ParseTuple(args, "d", &tol))
        return NULL;
    ts_status st;
    Py_BEGIN_ALLOW_THREADS
    st = ts_curve_length(self->c, tol, &len);
    Py_END_ALLOW_THREADS
    if (st != TS_OK)
        return raise_status(st, TS_NO_INDEX, TS_WHERE_NONE);
    return PyFloat_FromDouble(len);
}

/* sample(m) -> array (rows, 1 + dim). */
static PyObject *curve_sample(CurveHandle *self, PyObject *args)
{
    Py_ssize_t m;
    if (!PyArg_ParseTuple(args, "n", &m))
        return NULL;
    if (m < 2)
        return raise_status(TS_ERR_OPTION, TS_NO_INDEX, TS_WHERE_NONE);
    size_t rows = 0;
    ts_status st = ts_curve_sample(self->c, (size_t)m, NULL, 0, &rows);
    if (st != TS_OK && st != TS_ERR_LENGTH)
        return raise_status(st, TS_NO_INDEX, TS_WHERE_NONE);
    npy_intp dims[2] = {(npy_intp)rows, (npy_intp)(1 + self->dim)};
    PyObject *a = PyArray_SimpleNew(2, dims, NPY_DOUBLE);
    if (!a)
        return NULL;
    double *p = (double *)PyArray_DATA((PyArrayObject *)a);
    Py_BEGIN_ALLOW_THREADS
    st = ts_curve_sample(self->c, (size_t)m, p, rows * (1 + self->dim), &rows);
    Py_END_ALLOW_THREADS
    if (st != TS_OK) {
        Py_DECREF(a);
        return raise_status(st, TS_NO_INDEX, TS_WHERE_NONE);
    }
    return a;
}

/* certify(lo, hi) -> (ok, first segment or None, [report tuples]); lo/hi
 * None: the curve's own box; else sequences of dim values, NaN = open. */
static PyObject *curve_certify(CurveHandle *self, PyObject *args)
{
    PyObject *olo, *ohi;
    if (!PyArg_ParseTuple(args, "OO", &olo, &ohi))
        return NULL;
    int has_lo[3] = {0, 0, 0}, has_hi[3] = {0, 0, 0};
    double lo[3] = {0, 0, 0}, hi[3] = {0, 0, 0};
    int own = olo == Py_None && ohi == Py_None;
    for (int side = 0; side < 2 && !own; side++) {
        PyObject *o = side ? ohi : olo;
        if (o == Py_None)
            continue;
        PyArrayObject *a = as_vector(o, side ? "hi" : "lo");
        if (!a)
            return NULL;
        for (npy_intp k = 0; k < PyArray_SIZE(a) && k < 3; k++) {
            double v = ((const double *)PyArray_DATA(a))[k];
            (side ? has_hi : has_lo)[k] = v == v;
            (side ? hi : lo)[k] = v;
        }
        Py_DECREF(a);
    }
    size_t nr = self->n * self->dim;
    ts_interval_report *reps = PyMem_Calloc(nr ? nr : 1, sizeof *reps);
    if (!reps)
        return PyErr_NoMemory();
    ts_interval_report_init(reps, 1);
    ts_error err;
    ts_status st;
    Py_BEGIN_ALLOW_THREADS
    st = own ? ts_curve_certify(self->c, reps, &err)
             : ts_curve_certify_box(self->c, has_lo, lo, has_hi, hi, reps, &err);
    Py_END_ALLOW_THREADS
    return certify_result(st, &err, reps, nr);
}

static PyMethodDef curve_methods[] = {
    {"eval", (PyCFunction)(void (*)(void))curve_eval, METH_VARARGS | METH_KEYWORDS,
     "eval(t, nu=0, mode=4)"},
    {"control", (PyCFunction)curve_control, METH_NOARGS, "control points (segments, 4, dim)"},
    {"params", (PyCFunction)curve_params, METH_NOARGS, "(alpha, beta) per segment"},
    {"length", (PyCFunction)curve_length, METH_VARARGS, "length(tol)"},
    {"sample", (PyCFunction)curve_sample, METH_VARARGS, "sample(m)"},
    {"certify", (PyCFunction)curve_certify, METH_VARARGS, "certify(lo, hi)"},
    {NULL, NULL, 0, NULL}};

static PyGetSetDef curve_getset[] = {
    {"knots", (getter)curve_knots, NULL, "parameter knots (read-only view)", NULL},
    {"segments", (getter)curve_segments, NULL, "number of segments", NULL},
    {"dim", (getter)curve_dim, NULL, "dimension", NULL},
    {"closed", (getter)curve_closed, NULL, "closed curve", NULL},
    {NULL, NULL, NULL, NULL, NULL}};

static PyTypeObject CurveHandleType = {
    PyVarObject_HEAD_INIT(NULL, 0).tp_name = "trigspline._core.CurveHandle",
    .tp_basicsize = sizeof(CurveHandle),
    .tp_dealloc = (destructor)curve_dealloc,
    .tp_flags = Py_TPFLAGS_DEFAULT,
    .tp_doc = "A fitted ts_curve (immutable; made by curve_new).",
    .tp_methods = curve_methods,
    .tp_getset = curve_getset,
};

/* ------------------------------------------------------------------ */
/* SurfaceHandle                                                        */
/* ------------------------------------------------------------------ */

/* Queries outside the grid (not NaN): the per-object policy. */
enum { SURF_ERROR = 0, SURF_FILL = 1 };

typedef struct {
    PyObject_HEAD
    ts_surface *s;
    size_t nx, ny; /* patches */
    double x0, xn, y0, yn;
} SurfaceHandle;

static void surface_dealloc(SurfaceHandle *self)
{
    ts_surface_free(self->s);
    self->s = NULL;
    Py_TYPE(self)->tp_free((PyObject *)self);
}

static PyTypeObject SurfaceHandleType;

static int opt_plane(PyObject *obj, int *has, ts_plane *pl)
{
    if (obj == Py_None)
        return 0;
    *has = 1;
    return PyArg_ParseTuple(obj, "ddd", &pl->p, &pl->q, &pl->c) ? 0 : -1;
}

/* A gridded field (x, y, zt) (zt in the library's layout) into *g; the
 * three arrays into arr[0..3) (released by the caller); None: nothing. */
static int opt_grid(PyObject *obj, int *has, ts_grid_bound *g, PyArrayObject **arr)
{
    PyObject *ox, *oy, *oz;
    if (obj == Py_None)
        return 0;
    if (!PyArg_ParseTuple(obj, "OOO", &ox, &oy, &oz))
        return -1;
    if (!(arr[0] = as_vector(ox, "x")) || !(arr[1] = as_vector(oy, "y")))
        return -1;
    arr[2] = (PyArrayObject *)PyArray_FROMANY(oz, NPY_DOUBLE, 2, 2, NPY_ARRAY_IN_ARRAY);
    if (!arr[2])
        return -1;
    if (PyArray_DIM(arr[2], 0) != PyArray_SIZE(arr[1]) ||
        PyArray_DIM(arr[2], 1) != PyArray_SIZE(arr[0])) {
        raise_status(TS_ERR_LENGTH, TS_NO_INDEX, TS_WHERE_NONE);
        return -1;
    }
    *has = 1;
    *g = (ts_grid_bound){PyArray_DATA(arr[0]), (size_t)PyArray_SIZE(arr[0]), PyArray_DATA(arr[1]),
                         (size_t)PyArray_SIZE(arr[1]), PyArray_DATA(arr[2])};
    return 0;
}

/* surface_new(x, y, zt, *, form=None, slopes=None, zero_twist=0, alpha=None,
 * beta=None, margin=None, shape=0, lower=None, upper=None, lower_grid=None,
 * upper_grid=None); zt the values in the library's layout (ny+1, nx+1);
 * lower/upper (p, q, c) or None; lower_grid/upper_grid (x, y, zt) of a
 * gridded field (shape grids) or None.  None keeps the
 * ts_surface_options_init default. */
static PyObject *surface_new(PyObject *mod, PyObject *args, PyObject *kw)
{
    (void)mod;
    static char *kwlist[] = {"x", "y", "zt", "form", "slopes", "zero_twist", "alpha", "beta",
                             "margin", "shape", "lower", "upper", "lower_grid", "upper_grid",
                             NULL};
    PyObject *ox, *oy, *oz, *oform = Py_None, *oslopes = Py_None, *oalpha = Py_None,
                            *obeta = Py_None, *omargin = Py_None, *olower = Py_None,
                            *oupper = Py_None, *olgrid = Py_None, *ougrid = Py_None;
    int zero_twist = 0, shape = 0;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "OOO|$OOpOOOiOOOO", kwlist, &ox, &oy, &oz, &oform,
                                     &oslopes, &zero_twist, &oalpha, &obeta, &omargin, &shape,
                                     &olower, &oupper, &olgrid, &ougrid))
        return NULL;
    ts_surface_options opt;
    ts_surface_options_init(&opt);
    PyArrayObject *ax = NULL, *ay = NULL, *az = NULL, *garr[6] = {NULL};
    PyObject *result = NULL;
    if (!(ax = as_vector(ox, "x")) || !(ay = as_vector(oy, "y")))
        goto done;
    az = (PyArrayObject *)PyArray_FROMANY(oz, NPY_DOUBLE, 2, 2, NPY_ARRAY_IN_ARRAY);
    if (!az)
        goto done;
    if (PyArray_DIM(az, 0) != PyArray_SIZE(ay) || PyArray_DIM(az, 1) != PyArray_SIZE(ax)) {
        raise_status(TS_ERR_LENGTH, TS_NO_INDEX, TS_WHERE_NONE);
        goto done;
    }
    if (oform != Py_None && (opt.form = (ts_form)PyLong_AsLong(oform), PyErr_Occurred()))
        goto done;
    if (oslopes != Py_None &&
        (opt.slopes = (ts_slopes)PyLong_AsLong(oslopes), PyErr_Occurred()))
        goto done;
    if (oalpha != Py_None && (opt.alpha = PyFloat_AsDouble(oalpha), PyErr_Occurred()))
        goto done;
    if (obeta != Py_None && (opt.beta = PyFloat_AsDouble(obeta), PyErr_Occurred()))
        goto done;
    if (omargin != Py_None && (opt.margin = PyFloat_AsDouble(omargin), PyErr_Occurred()))
        goto done;
    if (opt_plane(olower, &opt.has_lower, &opt.lower) < 0 ||
        opt_plane(oupper, &opt.has_upper, &opt.upper) < 0)
        goto done;
    if (opt_grid(olgrid, &opt.has_lower, &opt.lower_grid, garr) < 0 ||
        opt_grid(ougrid, &opt.has_upper, &opt.upper_grid, garr + 3) < 0)
        goto done;
    opt.zero_twist = zero_twist;
    opt.shape = (ts_surface_shape)shape;
    const double *px = PyArray_DATA(ax), *py = PyArray_DATA(ay), *pz = PyArray_DATA(az);
    size_t nxp = (size_t)PyArray_SIZE(ax), nyp = (size_t)PyArray_SIZE(ay);
    ts_surface *s = NULL;
    ts_error err;
    ts_status st;
    Py_BEGIN_ALLOW_THREADS
    st = ts_surface_new(px, nxp, py, nyp, pz, &opt, &s, &err);
    Py_END_ALLOW_THREADS
    if (st != TS_OK) {
        raise_err(st, &err);
        goto done;
    }
    SurfaceHandle *h = PyObject_New(SurfaceHandle, &SurfaceHandleType);
    if (!h) {
        ts_surface_free(s);
        goto done;
    }
    h->s = s;
    h->nx = ts_surface_nx(s);
    h->ny = ts_surface_ny(s);
    h->x0 = ts_surface_x(s)[0];
    h->xn = ts_surface_x(s)[h->nx];
    h->y0 = ts_surface_y(s)[0];
    h->yn = ts_surface_y(s)[h->ny];
    result = (PyObject *)h;
done:
    Py_XDECREF(ax);
    Py_XDECREF(ay);
    Py_XDECREF(az);
    for (int k = 0; k < 6; k++)
        Py_XDECREF(garr[k]);
    return result;
}

static int surf_inside(const SurfaceHandle *h, double x, double y)
{
    return h->x0 <= x && x <= h->xn && h->y0 <= y && y <= h->yn;
}

#define SURF_BLOCK 1024

/* eval(xq, yq, partials=0, mode=SURF_ERROR, fill=nan) -> z, or (z, zx, zy)
 * with partials; xq, yq float64 arrays of one size and stride (the package
 * passes the columns of a points array, or two broadcast arrays).  Queries
 * go to ts_surface_eval_batch in blocks; a NaN coordinate gives NaN; a point
 * outside the grid raises (SURF_ERROR, index = the first) or gets fill. */
static PyObject *surface_eval(SurfaceHandle *self, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"xq", "yq", "partials", "mode", "fill", NULL};
    PyObject *oxq, *oyq;
    int partials = 0, mode = SURF_ERROR;
    double fill = (double)NAN;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "OO|pid", kwlist, &oxq, &oyq, &partials, &mode,
                                     &fill))
        return NULL;
    PyArrayObject *aq[2] = {NULL, NULL}, *ao[3] = {NULL, NULL, NULL};
    PyObject *result = NULL;
    for (int k = 0; k < 2; k++) {
        aq[k] = (PyArrayObject *)PyArray_FROMANY(k ? oyq : oxq, NPY_DOUBLE, 1, 1, NPY_ARRAY_ALIGNED);
        if (!aq[k])
            goto done;
    }
    npy_intp m = PyArray_SIZE(aq[0]);
    if (PyArray_SIZE(aq[1]) != m) {
        PyErr_SetString(PyExc_ValueError, "xq and yq must have the same number of values");
        goto done;
    }
    for (int k = 0; k < (partials ? 3 : 1); k++)
        if (!(ao[k] = (PyArrayObject *)PyArray_SimpleNew(1, &m, NPY_DOUBLE)))
            goto done;
    const char *bx = PyArray_BYTES(aq[0]), *by = PyArray_BYTES(aq[1]);
    npy_intp sx = PyArray_STRIDE(aq[0], 0), sy = PyArray_STRIDE(aq[1], 0);
    double *z = PyArray_DATA(ao[0]);
    double *zx = partials ? PyArray_DATA(ao[1]) : NULL, *zy = partials ? PyArray_DATA(ao[2]) : NULL;
    npy_intp bad = -1;
    ts_status st = TS_OK;
    Py_BEGIN_ALLOW_THREADS
    double xs[SURF_BLOCK], ys[SURF_BLOCK];
    for (npy_intp b0 = 0; b0 < m && bad < 0 && st == TS_OK; b0 += SURF_BLOCK) {
        size_t nb = (size_t)(m - b0 < SURF_BLOCK ? m - b0 : SURF_BLOCK);
        for (size_t k = 0; k < nb; k++) {
            xs[k] = *(const double *)(bx + (b0 + (npy_intp)k) * sx);
            ys[k] = *(const double *)(by + (b0 + (npy_intp)k) * sy);
        }
        ts_error err;
        st = ts_surface_eval_batch(self->s, xs, ys, nb, z + b0, zx ? zx + b0 : NULL,
                                   zy ? zy + b0 : NULL, &err);
        if (st != TS_ERR_DOMAIN)
            continue;
        st = TS_OK;
        for (size_t k = err.index; k < nb; k++) {
            if (xs[k] != xs[k] || ys[k] != ys[k] || surf_inside(self, xs[k], ys[k]))
                continue; /* NaN stays NaN */
            if (mode == SURF_ERROR) {
                bad = b0 + (npy_intp)k;
                break;
            }
            z[b0 + k] = fill;
            if (zx) {
                zx[b0 + k] = fill;
                zy[b0 + k] = fill;
            }
        }
    }
    Py_END_ALLOW_THREADS
    if (st != TS_OK) {
        raise_status(st, TS_NO_INDEX, TS_WHERE_NONE);
        goto done;
    }
    if (bad >= 0) {
        raise_status(TS_ERR_DOMAIN, (size_t)bad, TS_WHERE_QUERY);
        goto done;
    }
    if (partials)
        result = Py_BuildValue("(OOO)", ao[0], ao[1], ao[2]);
    else
        result = (PyObject *)ao[0], Py_INCREF(result);
done:
    for (int k = 0; k < 2; k++)
        Py_XDECREF(aq[k]);
    for (int k = 0; k < 3; k++)
        Py_XDECREF(ao[k]);
    return result;
}

/* eval_grid(xq, yq, mode=SURF_ERROR, fill=nan) -> array (len(yq), len(xq)),
 * out[b, a] = S(xq[a], yq[b]) (ts_surface_eval_grid; the package returns its
 * transpose).  NaN coordinates give NaN; outside: raise (index a for xq[a],
 * len(xq) + b for yq[b]) or fill. */
static PyObject *surface_eval_grid(SurfaceHandle *self, PyObject *args, PyObject *kw)
{
    static char *kwlist[] = {"xq", "yq", "mode", "fill", NULL};
    PyObject *oxq, *oyq;
    int mode = SURF_ERROR;
    double fill = (double)NAN;
    if (!PyArg_ParseTupleAndKeywords(args, kw, "OO|id", kwlist, &oxq, &oyq, &mode, &fill))
        return NULL;
    PyArrayObject *ax = as_vector(oxq, "xq"), *ay = ax ? as_vector(oyq, "yq") : NULL;
    if (!ay) {
        Py_XDECREF(ax);
        return NULL;
    }
    const double *xq = PyArray_DATA(ax), *yq = PyArray_DATA(ay);
    size_t mx = (size_t)PyArray_SIZE(ax), my = (size_t)PyArray_SIZE(ay);
    PyObject *result = NULL;
    /* a query outside (not NaN) under SURF_ERROR: named before any work */
    for (size_t k = 0; mode == SURF_ERROR && k < mx + my; k++) {
        double v = k < mx ? xq[k] : yq[k - mx];
        double lo = k < mx ? self->x0 : self->y0, hi = k < mx ? self->xn : self->yn;
        if (v == v && !(lo <= v && v <= hi)) {
            raise_status(TS_ERR_DOMAIN, k, TS_WHERE_QUERY);
            goto done;
        }
    }
    npy_intp dims[2] = {(npy_intp)my, (npy_intp)mx};
    PyArrayObject *ao = (PyArrayObject *)PyArray_SimpleNew(2, dims, NPY_DOUBLE);
    if (!ao)
        goto done;
    double *out = PyArray_DATA(ao);
    ts_status st;
    ts_error err;
    Py_BEGIN_ALLOW_THREADS
    st = ts_surface_eval_grid(self->s, xq, mx, yq, my, out, &err);
    if (st == TS_ERR_DOMAIN) {
        st = TS_OK;
        for (size_t b = 0; b < my; b++) {
            double y = yq[b];
            int yout = y == y && !(self->y0 <= y && y <= self->yn);
            for (size_t a = 0; a < mx; a++) {
                double x = xq[a];
                int xout = x == x && !(self->x0 <= x && x <= self->xn);
                if ((xout || yout) && x == x && y == y)
                    out[b * mx + a] = fill;
            }
        }
    }
    Py_END_ALLOW_THREADS
    if (st != TS_OK) {
        Py_DECREF(ao);
        raise_status(st, TS_NO_INDEX, TS_WHERE_NONE);
        goto done;
    }
    result = (PyObject *)ao;
done:
    Py_DECREF(ax);
    Py_DECREF(ay);
    return result;
}

/* integral(xa, xb, ya, yb) -> float (limits on the grid). */
static PyObject *surface_integral(SurfaceHandle *self, PyObject *args)
{
    double xa, xb, ya, yb, r;
    if (!PyArg_ParseTuple(args, "dddd", &xa, &xb, &ya, &yb))
        return NULL;
    ts_status st;
    Py_BEGIN_ALLOW_THREADS
    st = ts_surface_integral(self->s, xa, xb, ya, yb, &r);
    Py_END_ALLOW_THREADS
    if (st != TS_OK)
        return raise_status(st, TS_NO_INDEX, TS_WHERE_NONE);
    return PyFloat_FromDouble(r);
}

/* A patch report as one row of SURF_REPORT_FIELDS doubles: i, j, x0, x1, y0,
 * y1, ax, ay, B[16], has_lower, has_upper, proven_lower, sampled_lower,
 * at_lower[2], proven_upper, sampled_upper, at_upper[2], certified. */
#define SURF_REPORT_FIELDS 35

static void report_row(const ts_patch_report *r, double *o)
{
    double head[8] = {(double)r->i, (double)r->j, r->x0, r->x1, r->y0, r->y1, r->ax, r->ay};
    memcpy(o, head, sizeof head);
    memcpy(o + 8, r->B, sizeof r->B);
    double tail[11] = {r->has_lower, r->has_upper, r->proven_lower, r->sampled_lower,
                       r->at_lower[0], r->at_lower[1], r->proven_upper, r->sampled_upper,
                       r->at_upper[0], r->at_upper[1], r->certified};
    memcpy(o + 24, tail, sizeof tail);
}

/* report() -> array (ny * nx, SURF_REPORT_FIELDS), patch (i, j) in row
 * j * nx + i, against the scheme's own bounds (ts_surface_report). */
static PyObject *surface_report(SurfaceHandle *self, PyObject *unused)
{
    (void)unused;
    npy_intp dims[2] = {(npy_intp)(self->nx * self->ny), SURF_REPORT_FIELDS};
    PyObject *a = PyArray_SimpleNew(2, dims, NPY_DOUBLE);
    if (!a)
        return NULL;
    double *o = PyArray_DATA((PyArrayObject *)a);
    ts_status st = TS_OK;
    Py_BEGIN_ALLOW_THREADS
    for (size_t j = 0; j < self->ny && st == TS_OK; j++)
        for (size_t i = 0; i < self->nx && st == TS_OK; i++) {
            ts_patch_report r = TS_PATCH_REPORT_INIT;
            st = ts_surface_report(self->s, i, j, &r);
            report_row(&r, o + (j * self->nx + i) * SURF_REPORT_FIELDS);
        }
    Py_END_ALLOW_THREADS
    if (st != TS_OK) {
        Py_DECREF(a);
        return raise_status(st, TS_NO_INDEX, TS_WHERE_NONE);
    }
    return a;
}

/* certify(lower, upper) -> (ok, first patch not certified (j * nx + i) or
 * None, report array as report()); lower/upper (p, q, c) or None. */
static PyObject *surface_certify(SurfaceHandle *self, PyObject *args)
{
    PyObject *olo, *oup;
    if (!PyArg_ParseTuple(args, "OO", &olo, &oup))
        return NULL;
    int hl = 0, hu = 0;
    ts_plane lo = {0, 0, 0}, up = {0, 0, 0};
    if (opt_plane(olo, &hl, &lo) < 0 || opt_plane(oup, &hu, &up) < 0)
        return NULL;
    size_t np_ = self->nx * self->ny;
    ts_patch_report *reps = PyMem_Calloc(np_ ? np_ : 1, sizeof *reps);
    if (!reps)
        return PyErr_NoMemory();
    ts_patch_report_init(reps, 1);
    npy_intp dims[2] = {(npy_intp)np_, SURF_REPORT_FIELDS};
    PyObject *a = PyArray_SimpleNew(2, dims, NPY_DOUBLE);
    if (!a) {
        PyMem_Free(reps);
        return NULL;
    }
    double *o = PyArray_DATA((PyArrayObject *)a);
    ts_error err;
    ts_status st;
    Py_BEGIN_ALLOW_THREADS
    st = ts_surface_certify(self->s, hl ? &lo : NULL, hu ? &up : NULL, reps, &err);
    for (size_t c = 0; c < np_; c++)
        report_row(&reps[c], o + c * SURF_REPORT_FIELDS);
    Py_END_ALLOW_THREADS
    PyMem_Free(reps);
    if (st != TS_OK && st != TS_ERR_VIOLATED) {
        Py_DECREF(a);
        return raise_err(st, &err);
    }
    PyObject *idx = st == TS_OK ? (Py_INCREF(Py_None), Py_None) : PyLong_FromSize_t(err.index);
    return Py_BuildValue("(ONN)", st == TS_OK ? Py_True : Py_False, idx, a);
}

/* control(i, j) -> (B (4, 4) with [k, l], k along x; X (4,); Y (4,)). */
static PyObject *surface_control(SurfaceHandle *self, PyObject *args)
{
    Py_ssize_t i, j;
    if (!PyArg_ParseTuple(args, "nn", &i, &j))
        return NULL;
    npy_intp d2[2] = {4, 4}, d1 = 4;
    PyObject *B = PyArray_SimpleNew(2, d2, NPY_DOUBLE);
    PyObject *X = B ? PyArray_SimpleNew(1, &d1, NPY_DOUBLE) : NULL;
    PyObject *Y = X ? PyArray_SimpleNew(1, &d1, NPY_DOUBLE) : NULL;
    if (!Y) {
        Py_XDECREF(B);
        Py_XDECREF(X);
        return NULL;
    }
    ts_status st = i < 0 || j < 0 ? TS_ERR_INDEX
                                  : ts_surface_control(self->s, (size_t)i, (size_t)j,
                                                       PyArray_DATA((PyArrayObject *)B),
                                                       PyArray_DATA((PyArrayObject *)X),
                                                       PyArray_DATA((PyArrayObject *)Y));
    if (st != TS_OK) {
        Py_DECREF(B);
        Py_DECREF(X);
        Py_DECREF(Y);
        return raise_status(st, TS_NO_INDEX, TS_WHERE_INTERVAL);
    }
    return Py_BuildValue("(NNN)", B, X, Y);
}

/* ---- accessors: read-only views (node arrays in the library's layout,
 * (ny+1) rows of nx+1; the package transposes them) */
static PyObject *surface_x(SurfaceHandle *self, void *c)
{
    (void)c;
    return view((PyObject *)self, ts_surface_x(self->s), (npy_intp)self->nx + 1);
}
static PyObject *surface_y(SurfaceHandle *self, void *c)
{
    (void)c;
    return view((PyObject *)self, ts_surface_y(self->s), (npy_intp)self->ny + 1);
}
#define SURF_NODES(name, fn)                                                                 \
    static PyObject *name(SurfaceHandle *self, void *c)                                      \
    {                                                                                        \
        (void)c;                                                                             \
        return view((PyObject *)self, fn(self->s), (npy_intp)((self->nx + 1) * (self->ny + 1))); \
    }
SURF_NODES(surface_z, ts_surface_z)
SURF_NODES(surface_dzdx, ts_surface_dzdx)
SURF_NODES(surface_dzdy, ts_surface_dzdy)
SURF_NODES(surface_twist, ts_surface_twist)
static PyObject *surface_ax(SurfaceHandle *self, void *c)
{
    (void)c;
    return view((PyObject *)self, ts_surface_ax(self->s), (npy_intp)self->nx);
}
static PyObject *surface_ay(SurfaceHandle *self, void *c)
{
    (void)c;
    return view((PyObject *)self, ts_surface_ay(self->s), (npy_intp)self->ny);
}
static PyObject *surface_patches(SurfaceHandle *self, void *c)
{
    (void)c;
    return Py_BuildValue("(nn)", (Py_ssize_t)self->nx, (Py_ssize_t)self->ny);
}
static PyObject *surface_form(SurfaceHandle *self, void *c)
{
    (void)c;
    return PyLong_FromLong((long)ts_surface_form(self->s));
}
static PyObject *surface_shape(SurfaceHandle *self, void *c)
{
    (void)c;
    return PyLong_FromLong((long)ts_surface_shape_of(self->s));
}
static PyObject *surface_certified(SurfaceHandle *self, void *c)
{
    (void)c;
    return PyBool_FromLong(ts_surface_certified(self->s));
}

static PyMethodDef surface_methods[] = {
    {"eval", (PyCFunction)(void (*)(void))surface_eval, METH_VARARGS | METH_KEYWORDS,
     "eval(xq, yq, partials=False, mode=0, fill=nan)"},
    {"eval_grid", (PyCFunction)(void (*)(void))surface_eval_grid, METH_VARARGS | METH_KEYWORDS,
     "eval_grid(xq, yq, mode=0, fill=nan) -> (len(yq), len(xq))"},
    {"integral", (PyCFunction)surface_integral, METH_VARARGS, "integral(xa, xb, ya, yb)"},
    {"report", (PyCFunction)surface_report, METH_NOARGS, "report() -> (patches, 35)"},
    {"certify", (PyCFunction)surface_certify, METH_VARARGS, "certify(lower, upper)"},
    {"control", (PyCFunction)surface_control, METH_VARARGS, "control(i, j) -> (B, X, Y)"},
    {NULL, NULL, 0, NULL}};

static PyGetSetDef surface_getset[] = {
    {"x", (getter)surface_x, NULL, "grid x (read-only view)", NULL},
    {"y", (getter)surface_y, NULL, "grid y (read-only view)", NULL},
    {"z", (getter)surface_z, NULL, "values, library layout (read-only view)", NULL},
    {"dzdx", (getter)surface_dzdx, NULL, "slopes p used (read-only view)", NULL},
    {"dzdy", (getter)surface_dzdy, NULL, "slopes q used (read-only view)", NULL},
    {"twist", (getter)surface_twist, NULL, "twists r used (read-only view)", NULL},
    {"ax", (getter)surface_ax, NULL, "a^x per column interval (read-only view)", NULL},
    {"ay", (getter)surface_ay, NULL, "a^y per row interval (read-only view)", NULL},
    {"patches", (getter)surface_patches, NULL, "(nx, ny) patches", NULL},
    {"form", (getter)surface_form, NULL, "ts_form", NULL},
    {"shape", (getter)surface_shape, NULL, "ts_surface_shape", NULL},
    {"certified", (getter)surface_certified, NULL, "ts_surface_certified", NULL},
    {NULL, NULL, NULL, NULL, NULL}};

static PyTypeObject SurfaceHandleType = {
    PyVarObject_HEAD_INIT(NULL, 0).tp_name = "trigspline._core.SurfaceHandle",
    .tp_basicsize = sizeof(SurfaceHandle),
    .tp_dealloc = (destructor)surface_dealloc,
    .tp_flags = Py_TPFLAGS_DEFAULT,
    .tp_doc = "A fitted ts_surface (immutable; made by surface_new).",
    .tp_methods = surface_methods,
    .tp_getset = surface_getset,
};

/* ------------------------------------------------------------------ */
/* Module                                                               */
/* ------------------------------------------------------------------ */

/* slopes_compute(method, x, f) -> array of slopes. */
static PyObject *slopes_compute(PyObject *mod, PyObject *args)
{
    (void)mod;
    int method;
    PyObject *ox, *of;
    if (!PyArg_ParseTuple(args, "iOO", &method, &ox, &of))
        return NULL;
    PyArrayObject *ax = as_vector(ox, "x");
    if (!ax)
        return NULL;
    PyArrayObject *af = as_vector(of, "f");
    if (!af) {
        Py_DECREF(ax);
        return NULL;
    }
    PyObject *result = NULL;
    if (PyArray_SIZE(ax) != PyArray_SIZE(af)) {
        raise_status(TS_ERR_LENGTH, TS_NO_INDEX, TS_WHERE_NONE);
    } else {
        npy_intp n = PyArray_SIZE(ax);
        PyObject *d = PyArray_SimpleNew(1, &n, NPY_DOUBLE);
        if (d) {
            ts_error err;
            ts_status st;
            const double *px = PyArray_DATA(ax), *pf = PyArray_DATA(af);
            double *pd = PyArray_DATA((PyArrayObject *)d);
            Py_BEGIN_ALLOW_THREADS
            st = ts_slopes_compute((ts_slopes)method, px, pf, (size_t)n, pd, &err);
            Py_END_ALLOW_THREADS
            if (st != TS_OK) {
                Py_DECREF(d);
                ts_spline_options o;
                ts_spline_options_init(&o);
                o.slopes = (ts_slopes)method;
                raise_spline_err(st, &err, px, pf, (size_t)n, &o);
            } else {
                result = d;
            }
        }
    }
    Py_DECREF(ax);
    Py_DECREF(af);
    return result;
}

static PyObject *strerror_(PyObject *mod, PyObject *arg)
{
    (void)mod;
    long v = PyLong_AsLong(arg);
    if (v == -1 && PyErr_Occurred())
        return NULL;
    return PyUnicode_FromString(ts_strerror((ts_status)v));
}

static PyObject *library_version(PyObject *mod, PyObject *unused)
{
    (void)mod, (void)unused;
    return PyUnicode_FromString(ts_version());
}

/* options_defaults() -> (form, slopes, alpha, beta, margin, certify) of ts_spline_options_init. */
static PyObject *options_defaults(PyObject *mod, PyObject *unused)
{
    (void)mod, (void)unused;
    ts_spline_options o;
    ts_spline_options_init(&o);
    return Py_BuildValue("(iidddi)", (int)o.form, (int)o.slopes, o.alpha, o.beta, o.margin,
                         o.certify);
}

/* surface_options_defaults() -> (form, slopes, zero_twist, alpha, beta, margin) of
 * ts_surface_options_init. */
static PyObject *surface_options_defaults(PyObject *mod, PyObject *unused)
{
    (void)mod, (void)unused;
    ts_surface_options o;
    ts_surface_options_init(&o);
    return Py_BuildValue("(iiiddd)", (int)o.form, (int)o.slopes, o.zero_twist, o.alpha, o.beta,
                         o.margin);
}

/* vocab(kind) -> tuple of the canonical names of ts_vocab kind, by value
 * (ts_vocab_count, ts_vocab_name): the package's name tables. */
static PyObject *vocab(PyObject *mod, PyObject *arg)
{
    (void)mod;
    long kind = PyLong_AsLong(arg);
    if (kind == -1 && PyErr_Occurred())
        return NULL;
    if (!(kind >= 0 && kind < TS_VOCAB_COUNT_))
        return PyErr_Format(PyExc_ValueError, "no vocabulary %ld", kind);
    int n = ts_vocab_count((ts_vocab)kind);
    PyObject *t = PyTuple_New(n);
    for (int i = 0; t && i < n; i++) {
        PyObject *name = PyUnicode_FromString(ts_vocab_name((ts_vocab)kind, i));
        if (!name) {
            Py_DECREF(t);
            return NULL;
        }
        PyTuple_SET_ITEM(t, i, name);
    }
    return t;
}

/* defaults() -> {"spline": {...}, "curve": {...}, "surface": {...}}: the
 * value fields of ts_spline_options_init, ts_curve_options_init and
 * ts_surface_options_init by field name (pointer and count fields, NULL/0
 * by default, left out), enumerations by their canonical names, flags as
 * bool, lines as (m, c), planes as (p, q, c), per-coordinate boxes as
 * 3-tuples. */
static PyObject *defaults(PyObject *mod, PyObject *unused)
{
    (void)mod, (void)unused;
#define TS_NAME(vocab, v) ts_vocab_name(TS_VOCAB_##vocab, (int)(v))
    ts_spline_options o;
    ts_curve_options c;
    ts_surface_options u;
    ts_spline_options_init(&o);
    ts_curve_options_init(&c);
    ts_surface_options_init(&u);
    PyObject *sp = Py_BuildValue(
        "{s:s,s:s,s:d,s:d,s:s,s:(dd),s:(dd),s:d,s:O,s:s}", "form", TS_NAME(FORM, o.form),
        "slopes", TS_NAME(SLOPES, o.slopes), "alpha", o.alpha, "beta", o.beta, "shape",
        TS_NAME(SHAPE, o.shape), "lower", o.lower.m, o.lower.c, "upper", o.upper.m, o.upper.c,
        "margin", o.margin, "certify", o.certify ? Py_True : Py_False, "extrapolate",
        TS_NAME(EXTRAP, o.extrapolate));
    PyObject *cu = Py_BuildValue(
        "{s:s,s:O,s:s,s:d,s:d,s:(OOO),s:(OOO),s:(ddd),s:(ddd),s:d}", "param",
        TS_NAME(PARAM, c.param), "closed", c.closed ? Py_True : Py_False, "slopes",
        TS_NAME(SLOPES, c.slopes), "alpha", c.alpha, "beta", c.beta, "has_lo",
        c.has_lo[0] ? Py_True : Py_False, c.has_lo[1] ? Py_True : Py_False,
        c.has_lo[2] ? Py_True : Py_False, "has_hi", c.has_hi[0] ? Py_True : Py_False,
        c.has_hi[1] ? Py_True : Py_False, c.has_hi[2] ? Py_True : Py_False, "lo", c.lo[0],
        c.lo[1], c.lo[2], "hi", c.hi[0], c.hi[1], c.hi[2], "margin", c.margin);
    PyObject *su = Py_BuildValue(
        "{s:s,s:s,s:O,s:d,s:d,s:d,s:s,s:O,s:O,s:(ddd),s:(ddd)}", "form", TS_NAME(FORM, u.form),
        "slopes", TS_NAME(SLOPES, u.slopes), "zero_twist", u.zero_twist ? Py_True : Py_False,
        "alpha", u.alpha, "beta", u.beta, "margin", u.margin, "shape",
        TS_NAME(SURFACE_SHAPE, u.shape),
        "has_lower", u.has_lower ? Py_True : Py_False, "has_upper",
        u.has_upper ? Py_True : Py_False, "lower", u.lower.p, u.lower.q, u.lower.c, "upper",
        u.upper.p, u.upper.q, u.upper.c);
#undef TS_NAME
    if (!sp || !cu || !su) {
        Py_XDECREF(sp);
        Py_XDECREF(cu);
        Py_XDECREF(su);
        return NULL;
    }
#undef TS_NAME
    return Py_BuildValue("{s:N,s:N,s:N}", "spline", sp, "curve", cu, "surface", su);
}

static PyMethodDef module_methods[] = {
    {"spline_new", (PyCFunction)(void (*)(void))spline_new, METH_VARARGS | METH_KEYWORDS,
     "spline_new(x, f, **options) -> SplineHandle"},
    {"curve_new", (PyCFunction)(void (*)(void))curve_new, METH_VARARGS | METH_KEYWORDS,
     "curve_new(points, **options) -> CurveHandle"},
    {"surface_new", (PyCFunction)(void (*)(void))surface_new, METH_VARARGS | METH_KEYWORDS,
     "surface_new(x, y, zt, **options) -> SurfaceHandle"},
    {"surface_options_defaults", surface_options_defaults, METH_NOARGS,
     "defaults of ts_surface_options_init"},
    {"slopes_compute", slopes_compute, METH_VARARGS, "slopes_compute(method, x, f)"},
    {"strerror", strerror_, METH_O, "ts_strerror(status)"},
    {"vocab", vocab, METH_O, "vocab(kind) -> the canonical names of ts_vocab kind"},
    {"library_version", library_version, METH_NOARGS, "ts_version() of the compiled library"},
    {"options_defaults", options_defaults, METH_NOARGS, "defaults of ts_spline_options_init"},
    {"defaults", defaults, METH_NOARGS, "defaults() -> dict of the library's option defaults"},
    {NULL, NULL, 0, NULL}};

static struct PyModuleDef module_def = {PyModuleDef_HEAD_INIT, "trigspline._core",
                                        "libtrigspline compiled into a Python extension.", -1,
                                        module_methods, NULL, NULL, NULL, NULL};

#define TS_STR2(x) #x
#define TS_STR(x) TS_STR2(x)

PyMODINIT_FUNC PyInit__core(void)
{
    import_array();
    if (PyType_Ready(&SplineHandleType) < 0 || PyType_Ready(&CurveHandleType) < 0 ||
        PyType_Ready(&SurfaceHandleType) < 0)
        return NULL;
    PyObject *m = PyModule_Create(&module_def);
    if (!m)
        return NULL;
    LibraryError = PyErr_NewException("trigspline._core.LibraryError", PyExc_ValueError, NULL);
    if (!LibraryError || PyModule_AddObject(m, "LibraryError", LibraryError) < 0)
        goto fail;
    Py_INCREF(LibraryError);
    /* the version of include/trigspline.h this module was compiled with */
    if (PyModule_AddStringConstant(m, "HEADER_VERSION",
                                   TS_STR(TS_VERSION_MAJOR) "." TS_STR(TS_VERSION_MINOR) "." TS_STR(
                                       TS_VERSION_PATCH)) < 0 ||
        PyModule_AddIntConstant(m, "VOCAB_STATUS", TS_VOCAB_STATUS) < 0 ||
        PyModule_AddIntConstant(m, "VOCAB_FORM", TS_VOCAB_FORM) < 0 ||
        PyModule_AddIntConstant(m, "VOCAB_SLOPES", TS_VOCAB_SLOPES) < 0 ||
        PyModule_AddIntConstant(m, "VOCAB_SHAPE", TS_VOCAB_SHAPE) < 0 ||
        PyModule_AddIntConstant(m, "VOCAB_EXTRAP", TS_VOCAB_EXTRAP) < 0 ||
        PyModule_AddIntConstant(m, "VOCAB_PARAM", TS_VOCAB_PARAM) < 0 ||
        PyModule_AddIntConstant(m, "VOCAB_SURFACE_SHAPE", TS_VOCAB_SURFACE_SHAPE) < 0 ||
        PyModule_AddIntConstant(m, "VOCAB_TERM", TS_VOCAB_TERM) < 0 ||
        PyModule_AddIntConstant(m, "VOCAB_WHERE", TS_VOCAB_WHERE) < 0 ||
        PyModule_AddIntConstant(m, "VOCAB_CONSTRAINT", TS_VOCAB_CONSTRAINT) < 0 ||
        PyModule_AddIntConstant(m, "MODE_EXTEND", MODE_EXTEND) < 0 ||
        PyModule_AddIntConstant(m, "MODE_CLAMP", MODE_CLAMP) < 0 ||
        PyModule_AddIntConstant(m, "MODE_LINEAR", MODE_LINEAR) < 0 ||
        PyModule_AddIntConstant(m, "MODE_NAN", MODE_NAN) < 0 ||
        PyModule_AddIntConstant(m, "MODE_ERROR", MODE_ERROR) < 0 ||
        PyModule_AddIntConstant(m, "SURF_ERROR", SURF_ERROR) < 0 ||
        PyModule_AddIntConstant(m, "SURF_FILL", SURF_FILL) < 0)
        goto fail;
    Py_INCREF(&SplineHandleType);
    Py_INCREF(&CurveHandleType);
    Py_INCREF(&SurfaceHandleType);
    if (PyModule_AddObject(m, "SplineHandle", (PyObject *)&SplineHandleType) < 0 ||
        PyModule_AddObject(m, "CurveHandle", (PyObject *)&CurveHandleType) < 0 ||
        PyModule_AddObject(m, "SurfaceHandle", (PyObject *)&SurfaceHandleType) < 0)
        goto fail;
    return m;
fail:
    Py_DECREF(m);
    return NULL;
}
