"""Results equal to the C library's, bit for bit: the same ts_spline_new and
ts_spline_eval_batch calls through ctypes on the shared library CMake builds
(TS_BUILD_DIR, default <repo>/build; make test builds it first)."""
import ctypes
import os

import numpy as np
import pytest

from trigspline import Spline
from conftest import REPO

LIB = os.path.join(os.environ.get("TS_BUILD_DIR", os.path.join(REPO, "build")),
                   "libtrigspline.so")
pytestmark = pytest.mark.skipif(not os.path.exists(LIB), reason="no CMake build at " + LIB)

dp = ctypes.POINTER(ctypes.c_double)


class Line(ctypes.Structure):
    _fields_ = [("m", ctypes.c_double), ("c", ctypes.c_double)]


class Options(ctypes.Structure):  # ts_spline_options, field by field (include/trigspline.h)
    _fields_ = [("struct_size", ctypes.c_size_t),
                ("form", ctypes.c_int), ("slopes", ctypes.c_int), ("user_slopes", dp),
                ("n_user_slopes", ctypes.c_size_t), ("alpha", ctypes.c_double),
                ("alphas", dp), ("n_alphas", ctypes.c_size_t), ("beta", ctypes.c_double),
                ("betas", dp), ("n_betas", ctypes.c_size_t), ("shape", ctypes.c_int),
                ("lower", Line), ("upper", Line), ("margin", ctypes.c_double),
                ("margins", dp), ("n_margins", ctypes.c_size_t), ("certify", ctypes.c_int),
                ("extrapolate", ctypes.c_int), ("constraints", ctypes.c_void_p),
                ("n_constraints", ctypes.c_size_t)]


class Error(ctypes.Structure):
    _fields_ = [("status", ctypes.c_int), ("index", ctypes.c_size_t), ("where", ctypes.c_int)]


@pytest.fixture(scope="module")
def lib():
    L = ctypes.CDLL(LIB)
    L.ts_spline_new.argtypes = [dp, dp, ctypes.c_size_t, ctypes.POINTER(Options),
                                ctypes.POINTER(ctypes.c_void_p), ctypes.POINTER(Error)]
    L.ts_spline_eval_batch.argtypes = [ctypes.c_void_p, ctypes.c_int, dp, ctypes.c_size_t, dp,
                                ctypes.c_void_p, ctypes.POINTER(Error)]
    L.ts_spline_free.argtypes = [ctypes.c_void_p]
    L.ts_spline_options_init.argtypes = [ctypes.POINTER(Options)]
    L.ts_spline_integral.argtypes = [ctypes.c_void_p, ctypes.c_double, ctypes.c_double, dp]
    return L


def c_eval(L, x, f, xq, nu, **fields):
    opt = Options()
    L.ts_spline_options_init(ctypes.byref(opt))
    for k, v in fields.items():
        setattr(opt, k, v)
    h = ctypes.c_void_p()
    err = Error()
    assert L.ts_spline_new(x.ctypes.data_as(dp), f.ctypes.data_as(dp), len(x), ctypes.byref(opt),
                           ctypes.byref(h), ctypes.byref(err)) == 0
    try:
        out = np.empty_like(xq)
        L.ts_spline_eval_batch(h, nu, xq.ctypes.data_as(dp), len(xq), out.ctypes.data_as(dp), None,
                        ctypes.byref(err))
        I = ctypes.c_double()
        L.ts_spline_integral(h, x[0], x[-1], ctypes.byref(I))
        return out, I.value, opt.form
    finally:
        L.ts_spline_free(h)


@pytest.mark.parametrize("form", [0, 1, 2])
@pytest.mark.parametrize("sorted_", [True, False])
def test_bit_identical(lib, form, sorted_):
    rng = np.random.default_rng(form)
    x = np.cumsum(rng.uniform(0.1, 1.0, 3000))
    f = rng.uniform(0.0, 3.0, 3000)
    xq = rng.uniform(x[0], x[-1], 50000)
    if sorted_:
        xq.sort()
    names = ["paper", "c1", "geometric"]
    for shape, kw, ckw in ((0, {}, {}), (1, {"shape": "positive", "alpha": 0.3},
                                         {"shape": 1, "alpha": 0.3})):
        s = Spline(x, f, form=names[form], **kw)
        for nu in (0, 1, 2):
            want, I, _ = c_eval(lib, x, f, xq, nu, form=form, **ckw)
            assert np.array_equal(s(xq, nu), want), (shape, nu)
        assert s.integrate(x[0], x[-1]) == I


def test_default_form_is_the_library_default(lib):
    rng = np.random.default_rng(9)
    x = np.cumsum(rng.uniform(0.1, 1.0, 100))
    f = rng.uniform(0.0, 3.0, 100)
    xq = np.linspace(x[0], x[-1], 999)
    want, _, form = c_eval(lib, x, f, xq, 0)
    s = Spline(x, f)
    assert s.form == ["paper", "c1", "geometric"][form]
    assert np.array_equal(s(xq), want)
