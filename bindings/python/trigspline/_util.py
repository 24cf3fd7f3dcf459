"""Status and where tables (the library's names, ts_vocab_name) and number
text.  The option vocabulary is in _options.py."""
import math
import numbers

import numpy as np

from . import _core

# The library's names (ts_vocab_name): statuses "TS_OK", ...; where an index
# points (None for "none").
STATUS_NAMES = _core.vocab(_core.VOCAB_STATUS)
WHERE_NAMES = (None,) + _core.vocab(_core.VOCAB_WHERE)[1:]


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
