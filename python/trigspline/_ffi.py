"""ctypes mirror of include/trigspline.h: library loading, structs, prototypes.

Every struct below repeats the C declaration field by field, in order, with
the C types: enums are ``int`` (GCC/Clang on every ABI we target give an enum
whose values fit in ``int`` the size of ``int``), ``size_t`` is
``c_size_t``.  ctypes applies the platform's alignment rules, so padding
(e.g. after ``ts_options.shape`` and inside ``ts_error``) comes out as in C.
tests/test_python.py compiles a small C program that prints sizeof/offsetof
and compares them with these classes.
"""
import ctypes
import ctypes.util
import os

__all__ = ["lib", "lib_path", "TsError", "TsLine", "TsOptions", "TsIntervalReport",
           "TsCurveOptions", "TsCursor", "NO_INDEX"]

c_double_p = ctypes.POINTER(ctypes.c_double)
c_int_p = ctypes.POINTER(ctypes.c_int)

NO_INDEX = ctypes.c_size_t(-1).value  # TS_NO_INDEX


class TsError(ctypes.Structure):
    _fields_ = [("status", ctypes.c_int),
                ("index", ctypes.c_size_t),
                ("where", ctypes.c_int)]


class TsLine(ctypes.Structure):
    _fields_ = [("m", ctypes.c_double),
                ("c", ctypes.c_double)]


class TsOptions(ctypes.Structure):
    _fields_ = [("form", ctypes.c_int),
                ("slopes", ctypes.c_int),
                ("user_slopes", c_double_p),
                ("n_user_slopes", ctypes.c_size_t),
                ("alpha", ctypes.c_double),
                ("alphas", c_double_p),
                ("n_alphas", ctypes.c_size_t),
                ("beta", ctypes.c_double),
                ("betas", c_double_p),
                ("n_betas", ctypes.c_size_t),
                ("shape", ctypes.c_int),
                ("lower", TsLine),
                ("upper", TsLine),
                ("margin", ctypes.c_double),
                ("margins", c_double_p),
                ("n_margins", ctypes.c_size_t),
                ("certify", ctypes.c_int),
                ("extrapolate", ctypes.c_int)]


class TsIntervalReport(ctypes.Structure):
    _fields_ = [("x0", ctypes.c_double),
                ("x1", ctypes.c_double),
                ("alpha", ctypes.c_double),
                ("beta", ctypes.c_double),
                ("a", ctypes.c_double),
                ("B", ctypes.c_double * 4),
                ("term", ctypes.c_int),
                ("has_lower", ctypes.c_int),
                ("has_upper", ctypes.c_int),
                ("gap_lower", ctypes.c_double),
                ("at_lower", ctypes.c_double),
                ("gap_upper", ctypes.c_double),
                ("at_upper", ctypes.c_double),
                ("certified", ctypes.c_int)]


class TsCurveOptions(ctypes.Structure):
    _fields_ = [("param", ctypes.c_int),
                ("closed", ctypes.c_int),
                ("slopes", ctypes.c_int),
                ("alpha", ctypes.c_double),
                ("alphas", c_double_p),
                ("n_alphas", ctypes.c_size_t),
                ("beta", ctypes.c_double),
                ("betas", c_double_p),
                ("n_betas", ctypes.c_size_t),
                ("has_lo", ctypes.c_int * 3),
                ("has_hi", ctypes.c_int * 3),
                ("lo", ctypes.c_double * 3),
                ("hi", ctypes.c_double * 3),
                ("margin", ctypes.c_double)]


class TsCursor(ctypes.Structure):
    _fields_ = [("interval", ctypes.c_size_t)]


STRUCTS = {"ts_error": TsError, "ts_line": TsLine, "ts_options": TsOptions,
           "ts_interval_report": TsIntervalReport, "ts_curve_options": TsCurveOptions,
           "ts_cursor": TsCursor}


def _candidates():
    """Where to look for libtrigspline, in order (see README.md)."""
    env = os.environ.get("TRIGSPLINE_LIB")
    if env:
        # an explicit choice is final: a wrong path is an error, not a fallback
        yield env
        return
    pkg = os.path.dirname(os.path.abspath(__file__))
    names = ("libtrigspline.so", "libtrigspline.dylib", "trigspline.dll")
    for d in (pkg, os.path.dirname(pkg)):
        for nm in names:
            yield os.path.join(d, nm)
    repo = os.path.dirname(os.path.dirname(pkg))  # python/trigspline -> repo
    for nm in names:
        yield os.path.join(repo, "build", nm)
    found = ctypes.util.find_library("trigspline")
    if found:
        yield found


def _load():
    tried = []
    explicit = bool(os.environ.get("TRIGSPLINE_LIB"))
    for path in _candidates():
        if not explicit and os.sep in path and not os.path.exists(path):
            tried.append(path)
            continue
        try:
            return ctypes.CDLL(path), path
        except OSError as e:
            tried.append("%s (%s)" % (path, e))
    raise ImportError("trigspline: libtrigspline not found; set TRIGSPLINE_LIB to its path "
                      "or build it (cmake -S . -B build && cmake --build build).  Tried: "
                      + "; ".join(tried))


lib, lib_path = _load()


def _proto(name, restype, *argtypes):
    fn = getattr(lib, name)
    fn.restype = restype
    fn.argtypes = list(argtypes)
    return fn


_p = ctypes.c_void_p
_sz = ctypes.c_size_t
_d = ctypes.c_double
_int = ctypes.c_int
P = ctypes.POINTER

_proto("ts_version", ctypes.c_char_p)
_proto("ts_strerror", ctypes.c_char_p, _int)
_proto("ts_options_init", None, P(TsOptions))
_proto("ts_slopes_compute", _int, _int, c_double_p, c_double_p, _sz, c_double_p, P(TsError))
_proto("ts_spline_new", _int, c_double_p, c_double_p, _sz, P(TsOptions), P(_p), P(TsError))
_proto("ts_spline_free", None, _p)
_proto("ts_spline_intervals", _sz, _p)
for _nm in ("ts_spline_x", "ts_spline_f", "ts_spline_slopes", "ts_spline_alpha",
            "ts_spline_beta"):
    _proto(_nm, c_double_p, _p)
_proto("ts_spline_form", _int, _p)
_proto("ts_spline_shape", _int, _p)
_proto("ts_spline_extrapolation", _int, _p)
_proto("ts_spline_a", _int, _p, _sz, c_double_p)
_proto("ts_spline_control", _int, _p, _sz, c_double_p, c_double_p)
_proto("ts_spline_report", _int, _p, _sz, P(TsIntervalReport))
_proto("ts_spline_certified", _int, _p)
_proto("ts_certify", _int, _p, P(TsLine), P(TsLine), P(TsIntervalReport), P(TsError))
_proto("ts_eval", _int, _p, _d, P(TsCursor), c_double_p)
_proto("ts_eval_deriv", _int, _p, _d, P(TsCursor), c_double_p, c_double_p, c_double_p)
_proto("ts_eval_batch", _int, _p, _int, c_double_p, _sz, c_double_p, P(TsCursor), P(TsError))
_proto("ts_eval_batch_mt", _int, _p, _int, c_double_p, _sz, c_double_p, ctypes.c_uint,
       P(TsError))
_proto("ts_integral", _int, _p, _d, _d, c_double_p)
_proto("ts_curve_options_init", None, P(TsCurveOptions))
_proto("ts_curve_new", _int, c_double_p, _sz, _sz, P(TsCurveOptions), P(_p), P(TsError))
_proto("ts_curve_free", None, _p)
_proto("ts_curve_segments", _sz, _p)
_proto("ts_curve_dim", _sz, _p)
_proto("ts_curve_closed", _int, _p)
_proto("ts_curve_knots", c_double_p, _p)
_proto("ts_curve_control", _int, _p, _sz, c_double_p)
_proto("ts_curve_params", _int, _p, _sz, c_double_p, c_double_p)
_proto("ts_curve_eval", _int, _p, _d, P(TsCursor), c_double_p, c_double_p, c_double_p)
_proto("ts_curve_sample", _int, _p, _sz, c_double_p, _sz, P(_sz))
_proto("ts_curve_length", _int, _p, _d, c_double_p)
_proto("ts_curve_certify", _int, _p, P(TsIntervalReport), P(TsError))
_proto("ts_curve_certify_box", _int, _p, c_int_p, c_double_p, c_int_p, c_double_p,
       P(TsIntervalReport), P(TsError))
_proto("ts_error_bound", _int, _p, _d, _d, _int, c_double_p, c_double_p)
