"""Status and where tables (the order of the C enums in include/trigspline.h) and number
text.  The option vocabulary is in _options.py."""
import math
import numbers

import numpy as np

STATUS_NAMES = ("TS_OK", "TS_ERR_NULL", "TS_ERR_NOMEM", "TS_ERR_OVERFLOW", "TS_ERR_TOO_FEW",
                "TS_ERR_NONFINITE", "TS_ERR_UNSORTED", "TS_ERR_ALPHA", "TS_ERR_BETA",
                "TS_ERR_MARGIN", "TS_ERR_LENGTH", "TS_ERR_OPTION", "TS_ERR_PERIODIC",
                "TS_ERR_DOMAIN", "TS_ERR_NEGATIVE", "TS_ERR_SIDE", "TS_ERR_LINES",
                "TS_ERR_NONMONOTONE", "TS_ERR_INFEASIBLE", "TS_ERR_VIOLATED",
                "TS_ERR_GEOMETRIC", "TS_ERR_DIMENSION", "TS_ERR_INDEX", "TS_ERR_ZERO_SLOPE",
                "TS_ERR_SLOPE_OVERFLOW", "TS_ERR_TOO_LARGE", "TS_ERR_CONTROL_OVERFLOW",
                "TS_ERR_WIDTH", "TS_ERR_PRECISION", "TS_ERR_UNPROVEN")
WHERE_NAMES = (None, "point", "interval", "query")


def num(v):
    """Compact number text for messages: 1, 0.31, -2.5e-07, nan (shortest round trip)."""
    try:
        v = float(v)
    except (TypeError, ValueError):
        return repr(v)
    if math.isnan(v):
        return "nan"
    if math.isinf(v):
        return "inf" if v > 0 else "-inf"
    if v == int(v) and abs(v) < 1e16:
        return str(int(v))
    return repr(v)


def is_scalar(v):
    """A single number (Python, numpy scalar or 0-d array), not a sequence."""
    return isinstance(v, numbers.Real) or (isinstance(v, np.ndarray) and v.ndim == 0)


def to_float(v, what):
    try:
        return float(v)
    except (TypeError, ValueError):
        raise TypeError("%s must be a number, not %r" % (what, v)) from None


def float_array(v, what, ndim=None):
    """v as a float64 array (no copy when it already is one)."""
    if isinstance(v, (str, bytes)):
        raise TypeError("%s must be numbers, not a string" % what)
    try:
        a = np.asarray(v, dtype=np.float64)
    except (TypeError, ValueError):
        raise TypeError("%s must be an array of numbers, not %r" % (what, type(v).__name__)) \
            from None
    if ndim is not None and a.ndim != ndim:
        raise ValueError("%s must be %d-dimensional, got shape %r" % (what, ndim, a.shape))
    return a
