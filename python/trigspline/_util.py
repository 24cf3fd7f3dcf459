"""Enum tables, number formatting and sequence -> C array conversion."""
import array
import ctypes
import math
import numbers

try:  # numpy is optional
    import numpy as np
except ImportError:  # pragma: no cover - depends on the machine
    np = None

c_double_p = ctypes.POINTER(ctypes.c_double)

# Order = the C enum values (include/trigspline.h).
STATUS_NAMES = ("TS_OK", "TS_ERR_NULL", "TS_ERR_NOMEM", "TS_ERR_OVERFLOW", "TS_ERR_TOO_FEW",
                "TS_ERR_NONFINITE", "TS_ERR_UNSORTED", "TS_ERR_ALPHA", "TS_ERR_BETA",
                "TS_ERR_MARGIN", "TS_ERR_LENGTH", "TS_ERR_OPTION", "TS_ERR_PERIODIC",
                "TS_ERR_DOMAIN", "TS_ERR_NEGATIVE", "TS_ERR_SIDE", "TS_ERR_LINES",
                "TS_ERR_NONMONOTONE", "TS_ERR_INFEASIBLE", "TS_ERR_VIOLATED",
                "TS_ERR_GEOMETRIC", "TS_ERR_DIMENSION", "TS_ERR_INDEX", "TS_ERR_ZERO_SLOPE",
                "TS_ERR_SLOPE_OVERFLOW", "TS_ERR_TOO_LARGE", "TS_ERR_CONTROL_OVERFLOW",
                "TS_ERR_WIDTH")
WHERE_NAMES = (None, "point", "interval", "query")
FORMS = ("paper", "c1", "geometric")
SLOPES = ("arithmetic", "geometric", "harmonic", "fritsch_carlson", "akima", "makima", "user",
          "periodic")
SLOPE_ALIASES = {"fritsch-carlson": "fritsch_carlson", "pchip": "fritsch_carlson",
                 "mean": "arithmetic"}
SHAPES = ("none", "positive", "above", "below", "between", "monotone")
EXTRAPS = ("error", "clamp", "extend", "linear")
PARAMS = ("centripetal", "chord", "uniform")
TERMS = ("user", "margin", "lower_left", "lower_right", "upper_left", "upper_right",
         "monotone", "certify", "geometric")


def enum_value(table, value, what, aliases=None):
    """Index of value (a name, case-insensitive) in table; ValueError otherwise."""
    if isinstance(value, str):
        key = value.strip().lower()
        if aliases:
            key = aliases.get(key, key)
        if key in table:
            return table.index(key)
    raise ValueError("%s must be one of %s, not %r" % (what, ", ".join(repr(t) for t in table),
                                                       value))


def num(v):
    """Compact number text for messages: 1, 0.31, -2.5e-07, nan."""
    try:
        v = float(v)
    except (TypeError, ValueError):
        return repr(v)
    if math.isnan(v):
        return "nan"
    if math.isinf(v):
        return "inf" if v > 0 else "-inf"
    return "%.15g" % v


def is_scalar(v):
    """A single number (Python, numpy scalar or 0-d array), not a sequence."""
    if isinstance(v, numbers.Real):
        return True
    if np is not None and isinstance(v, np.ndarray) and v.ndim == 0:
        return True
    return False


def to_float(v, what):
    try:
        return float(v)
    except (TypeError, ValueError):
        raise TypeError("%s must be a number, not %r" % (what, v)) from None


def float_list(seq, what):
    """Any sequence/iterable of numbers (also a numpy array, flattened) as a list of floats."""
    if isinstance(seq, (str, bytes)):
        raise TypeError("%s must be a sequence of numbers, not a string" % what)
    if np is not None and isinstance(seq, np.ndarray):
        return [float(v) for v in np.asarray(seq, dtype=np.float64).ravel()]
    try:
        items = list(seq)
    except TypeError:
        raise TypeError("%s must be a sequence of numbers, not %r" % (what, type(seq).__name__)) \
            from None
    return [to_float(v, "%s[%d]" % (what, i)) for i, v in enumerate(items)]


class CArray(object):
    """A C double array for one call, with its owner kept alive.

    ptr: c_double_p, n: length, owner: the object holding the memory."""
    __slots__ = ("ptr", "n", "owner")

    def __init__(self, ptr, n, owner):
        self.ptr, self.n, self.owner = ptr, n, owner


def c_doubles(values):
    """A list of floats as a ctypes array (copied)."""
    n = len(values)
    arr = (ctypes.c_double * n)(*values) if n else (ctypes.c_double * 1)()
    return CArray(ctypes.cast(arr, c_double_p), n, arr)


def input_array(seq, what):
    """Queries for a batch call, without a copy where possible.

    Returns (CArray, kind, shape): kind 'numpy' (shape = the input's shape),
    'array' (array.array('d')) or 'list'."""
    if np is not None and isinstance(seq, np.ndarray):
        a = np.ascontiguousarray(seq, dtype=np.float64)  # no copy if already C-contiguous float64
        return CArray(a.ctypes.data_as(c_double_p), a.size, a), "numpy", a.shape
    if isinstance(seq, array.array) and seq.typecode == "d":
        n = len(seq)
        if n == 0:
            return c_doubles([]), "array", (0,)
        addr, _ = seq.buffer_info()  # the array's own memory; valid while seq lives
        return CArray(ctypes.cast(addr, c_double_p), n, seq), "array", (n,)
    vals = float_list(seq, what)
    return c_doubles(vals), "list", (len(vals),)


def output_array(kind, shape, n):
    """(CArray, result) for n outputs of the same kind as the input."""
    if kind == "numpy":
        out = np.empty(shape, dtype=np.float64)
        return CArray(out.ctypes.data_as(c_double_p), n, out), out
    if kind == "array":
        out = array.array("d", bytes(8 * n))
        if n == 0:
            return c_doubles([]), out
        addr, _ = out.buffer_info()
        return CArray(ctypes.cast(addr, c_double_p), n, out), out
    ca = c_doubles([0.0] * n)
    return ca, ca.owner


def given_output(out, n):
    """(CArray, out) writing straight into the caller's buffer: a writable
    C-contiguous float64 numpy array or an array.array('d') of n elements."""
    if np is not None and isinstance(out, np.ndarray):
        if out.dtype != np.float64 or not out.flags.c_contiguous or not out.flags.writeable:
            raise ValueError("out must be a writable C-contiguous float64 array")
        if out.size != n:
            raise ValueError("out has %d elements, the queries %d" % (out.size, n))
        return CArray(out.ctypes.data_as(c_double_p), n, out), out
    if isinstance(out, array.array) and out.typecode == "d":
        if len(out) != n:
            raise ValueError("out has %d elements, the queries %d" % (len(out), n))
        if n == 0:
            return c_doubles([]), out
        addr, _ = out.buffer_info()
        return CArray(ctypes.cast(addr, c_double_p), n, out), out
    raise TypeError("out must be a numpy float64 array or an array.array('d')")


def finish_output(kind, result, n):
    if kind == "list":
        return [result[i] for i in range(n)]
    return result


class Handle(object):
    """Owner of one C handle: close() frees it (idempotent), also on garbage
    collection and at the end of a with block.  Subclasses set _h, _free
    (the C free function's name in the library) and _kind."""

    _h = None
    _free = None
    _kind = "object"

    def close(self):
        """Free the C object now (later calls raise ValueError).  Idempotent."""
        h, self._h = self._h, None
        if h is not None and h.value:
            from ._ffi import lib
            getattr(lib, self._free)(h)

    def __del__(self):
        try:
            self.close()
        except Exception:  # interpreter shutdown: the library may be gone
            pass

    def __enter__(self):
        return self

    def __exit__(self, *exc):
        self.close()
        return False

    def _handle(self):
        if self._h is None:
            raise ValueError("this %s has been closed" % self._kind)
        return self._h
