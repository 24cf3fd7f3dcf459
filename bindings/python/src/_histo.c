/* trigspline._histo: the numpy generalized ufunc behind trigspline.disaggregate.
 *
 *   disaggregate(edges(p), totals(n), grid(q), opt(k)) -> out(q), status(), index()
 *
 * One series per core call: ts_histo_new from the bins (p = n + 1 edges),
 * then on the grid either the totals of its cells (out[0] = 0, out[j] the
 * total over [grid[j-1], grid[j]]: ts_histo_totals) or the rate at its
 * points (ts_histo_eval_batch) or the rate's derivative.  A series that
 * cannot be built never raises: its out is NaN and status holds the
 * ts_status, index the bin or edge it names (-1 if none).  float64 only;
 * numpy runs the loop without the GIL.
 *
 * opt (float64, OPT_LEN values): kind (0 totals, 1 rate, 2 derivative,
 * 3 every bin cut into q / n equal cells: ts_histo_subdivide, the grid's
 * values unused), alpha, lo, hi. */
#define PY_SSIZE_T_CLEAN
#include <Python.h>

#define NPY_NO_DEPRECATED_API NPY_1_7_API_VERSION
#include <numpy/arrayobject.h>
#include <numpy/ufuncobject.h>

#include <fenv.h>
#include <math.h>
#include <stdint.h>
#include <stdlib.h>
#include <string.h>

#include "trigspline.h"

enum { OPT_KIND, OPT_ALPHA, OPT_LO, OPT_HI, OPT_LEN };

static void load(double *dst, const char *src, npy_intp step, npy_intp len)
{
    for (npy_intp i = 0; i < len; i++)
        dst[i] = *(const double *)(src + i * step);
}

/* The len values at src: in place when contiguous, else copied to dst. */
static const double *view(double *dst, const char *src, npy_intp step, npy_intp len)
{
    if (step == (npy_intp)sizeof(double))
        return (const double *)src;
    load(dst, src, step, len);
    return dst;
}

/* One series: bins (e, T), grid g (q points) -> out (q); the status. */
static ts_status one_series(const double *e, npy_intp p, const double *T, npy_intp n,
                            const double *g, npy_intp q, const double *o, double *out,
                            npy_int64 *index)
{
    *index = -1; /* out is set to NaN by the caller on failure */
    int kind = (int)o[OPT_KIND];
    if (!(o[OPT_KIND] == 0.0 || o[OPT_KIND] == 1.0 || o[OPT_KIND] == 2.0 || o[OPT_KIND] == 3.0))
        return TS_ERR_OPTION;
    if (p != n + 1 || (kind == 3 && (n == 0 || q % n != 0)))
        return TS_ERR_LENGTH;
    ts_histo_options ho;
    ts_histo_options_init(&ho);
    ho.alpha = o[OPT_ALPHA];
    ho.lo = o[OPT_LO];
    ho.hi = o[OPT_HI];
    ts_histo *h = NULL;
    ts_error err;
    ts_status st = ts_histo_new(e, T, (size_t)n, &ho, &h, &err);
    if (st == TS_OK) {
        if (kind == 3) {
            st = q > 0 ? ts_histo_subdivide(h, (size_t)(q / n), out, &err) : TS_OK;
        } else if (kind == 0) {
            st = ts_histo_totals(h, g, (size_t)q, q > 1 ? out + 1 : NULL, &err);
            if (st == TS_OK && q > 0)
                out[0] = 0.0;
        } else {
            double *d = NULL;
            if (kind == 2) {
                d = out;
                out = malloc((size_t)(q > 0 ? q : 1) * sizeof(double));
                if (!out) {
                    ts_histo_free(h);
                    return TS_ERR_NOMEM;
                }
            }
            st = ts_histo_eval_batch(h, g, (size_t)q, out, d, &err);
            if (kind == 2) {
                free(out);
                out = d;
            }
        }
        if (st != TS_OK)
            for (npy_intp j = 0; j < q; j++)
                out[j] = (double)NAN;
    }
    ts_histo_free(h);
    if (st != TS_OK && err.index != TS_NO_INDEX)
        *index = (npy_int64)err.index;
    return st;
}

/* args: edges, totals, grid, opt, out, status, index */
static void loop_f64(char **args, npy_intp const *dims, npy_intp const *steps, void *data)
{
    (void)data;
    npy_intp N = dims[0], p = dims[1], n = dims[2], q = dims[3], k = dims[4];
    npy_intp se = steps[7], sT = steps[8], sg = steps[9], so = steps[10], sout = steps[11];
    size_t len = (size_t)(p + n + 2 * q + 1);
    double *buf = malloc(len * sizeof(double));
    fexcept_t flags;
    fegetexceptflag(&flags, FE_ALL_EXCEPT);
    for (npy_intp s = 0; s < N; s++) {
        char *pe = args[0] + s * steps[0], *pT = args[1] + s * steps[1];
        char *pg = args[2] + s * steps[2], *po = args[3] + s * steps[3];
        char *pout = args[4] + s * steps[4];
        npy_int32 *pst = (npy_int32 *)(args[5] + s * steps[5]);
        npy_int64 *pix = (npy_int64 *)(args[6] + s * steps[6]);
        ts_status st;
        npy_int64 index = -1;
        double *eb = buf, *Tb = buf + p, *gb = Tb + n, *out = gb + q;
        const double *e = eb, *T = Tb, *g = gb;
        /* contiguous output: written in place */
        if (sout == (npy_intp)sizeof(double))
            out = (double *)pout;
        if (!buf) {
            st = TS_ERR_NOMEM;
        } else if (k != OPT_LEN) {
            st = TS_ERR_OPTION;
        } else {
            double o[OPT_LEN];
            load(o, po, so, OPT_LEN);
            e = view(eb, pe, se, p);
            T = view(Tb, pT, sT, n);
            if (o[OPT_KIND] != 3.0) /* kind 3 reads only the grid's length */
                g = view(gb, pg, sg, q);
            st = one_series(e, p, T, n, g, q, o, out, &index);
        }
        *pst = (npy_int32)st;
        *pix = index;
        if (st != TS_OK || out != (double *)pout)
            for (npy_intp j = 0; j < q; j++)
                *(double *)(pout + j * sout) = (st == TS_OK) ? out[j] : (double)NAN;
    }
    fesetexceptflag(&flags, FE_ALL_EXCEPT);
    free(buf);
}

static PyUFuncGenericFunction funcs[] = {loop_f64};
static void *funcs_data[] = {NULL};
static char types[] = {NPY_DOUBLE, NPY_DOUBLE, NPY_DOUBLE, NPY_DOUBLE,
                       NPY_DOUBLE, NPY_INT32,  NPY_INT64};

/* message(edges, totals, alpha, lo, hi): the library's sentence
 * (ts_error_message) of why ts_histo_new refuses these bins, or None when it
 * builds them. */
static PyObject *py_message(PyObject *self, PyObject *args)
{
    (void)self;
    PyObject *oe, *ot;
    ts_histo_options ho;
    ts_histo_options_init(&ho);
    if (!PyArg_ParseTuple(args, "OOddd", &oe, &ot, &ho.alpha, &ho.lo, &ho.hi))
        return NULL;
    PyArrayObject *ae = (PyArrayObject *)PyArray_FROMANY(oe, NPY_DOUBLE, 1, 1, NPY_ARRAY_IN_ARRAY);
    PyArrayObject *at = ae ? (PyArrayObject *)PyArray_FROMANY(ot, NPY_DOUBLE, 1, 1,
                                                              NPY_ARRAY_IN_ARRAY)
                           : NULL;
    PyObject *result = NULL;
    if (!at) {
        /* exception set */
    } else if (PyArray_SIZE(ae) != PyArray_SIZE(at) + 1) {
        PyErr_SetString(PyExc_ValueError, "message: edges need one more value than totals");
    } else {
        const double *e = PyArray_DATA(ae), *t = PyArray_DATA(at);
        size_t n = (size_t)PyArray_SIZE(at);
        ts_histo *h = NULL;
        ts_error err;
        ts_status st = ts_histo_new(e, t, n, &ho, &h, &err);
        ts_histo_free(h);
        if (st == TS_OK) {
            result = Py_None;
            Py_INCREF(result);
        } else {
            ts_error_context ctx;
            ts_error_context_init(&ctx);
            ctx.x = e;
            ctx.f = t;
            ctx.n_points = n + 1;
            ctx.histo_options = &ho;
            char buf[1024];
            ts_error_message(&err, &ctx, buf, sizeof buf);
            result = PyUnicode_DecodeUTF8(buf, (Py_ssize_t)strlen(buf), "replace");
        }
    }
    Py_XDECREF(ae);
    Py_XDECREF(at);
    return result;
}

static PyMethodDef methods[] = {
    {"message", py_message, METH_VARARGS,
     "message(edges, totals, alpha, lo, hi) -> the library's sentence of why the bins are "
     "refused, or None."},
    {NULL, NULL, 0, NULL},
};

static struct PyModuleDef moduledef = {
    PyModuleDef_HEAD_INIT, "_histo",
    "numpy generalized ufunc of trigspline.disaggregate (rates from bin totals).", -1, methods,
    NULL, NULL, NULL, NULL,
};

PyMODINIT_FUNC PyInit__histo(void)
{
    PyObject *mod = PyModule_Create(&moduledef);
    if (!mod)
        return NULL;
    import_array();
    import_umath();
    PyObject *uf = PyUFunc_FromFuncAndDataAndSignature(
        funcs, funcs_data, types, 1, 4, 3, PyUFunc_None, "disaggregate",
        "disaggregate(edges, totals, grid, opt) -> (out, status, index): one rate per "
        "series; see trigspline.disaggregate.",
        0, "(p),(n),(q),(k)->(q),(),()");
    if (!uf || PyModule_AddObject(mod, "disaggregate", uf) < 0) {
        Py_XDECREF(uf);
        Py_DECREF(mod);
        return NULL;
    }
    ts_histo_options ho; /* the library's defaults, never restated */
    ts_histo_options_init(&ho);
    if (PyModule_AddIntConstant(mod, "OPT_LEN", OPT_LEN) < 0 ||
        PyModule_AddObject(mod, "DEFAULT_ALPHA", PyFloat_FromDouble(ho.alpha)) < 0 ||
        PyModule_AddObject(mod, "DEFAULT_LO", PyFloat_FromDouble(ho.lo)) < 0 ||
        PyModule_AddObject(mod, "DEFAULT_HI", PyFloat_FromDouble(ho.hi)) < 0) {
        Py_DECREF(mod);
        return NULL;
    }
    return mod;
}
