"""TrigsplineError and the messages that name the offending point or interval."""
from . import _core
from ._util import STATUS_NAMES, WHERE_NAMES, num


def strerror(status):
    """The library's fixed English text for a status code (``ts_strerror``).

    Parameters
    ----------
    status : int
        A ``ts_status`` code.

    Returns
    -------
    str
    """
    return _core.strerror(int(status))


class TrigsplineError(ValueError):
    """A failure reported by libtrigspline.

    Attributes
    ----------
    status : int
        The ``ts_status`` code; ``name`` gives its name, e.g. ``"TS_ERR_SIDE"``.
    message : str
        The text (also ``str(err)``), naming the point, interval or query.
    index : int or None
        The point, interval or query it concerns.
    where : {"point", "interval", "query", "node", "patch", "x", "y", "lower", "upper", None}
        What ``index`` counts (``"node"``, ``"patch"``, ``"x"``, ``"y"``:
        surfaces; ``"lower"``, ``"upper"``: a surface's gridded field, index
        0 or 1).
    series : tuple of int or None
        For vector-valued data: the index of the series (``f`` without the
        interpolation axis) that failed.
    node, patch : tuple of int or None
        Surfaces: the node ``(i, j)`` at ``(x[i], y[j])`` or the patch
        ``(i, j)`` = ``[x[i], x[i+1]] × [y[j], y[j+1]]`` the error names.
    """

    def __init__(self, status, message, index=None, where=None, series=None, node=None,
                 patch=None):
        super().__init__(message)
        self.status = int(status)
        self.message = message
        self.index = index
        self.where = where
        self.series = series
        self.node = node
        self.patch = patch

    @property
    def name(self):
        s = self.status
        return STATUS_NAMES[s] if 0 <= s < len(STATUS_NAMES) else "TS_STATUS_%d" % s

    def __repr__(self):
        return "TrigsplineError(%s, %r, index=%r, where=%r)" % (self.name, self.message,
                                                               self.index, self.where)

    def __reduce__(self):
        return (TrigsplineError, (self.status, self.message, self.index, self.where,
                                  self.series, self.node, self.patch))


def spline_error(err):
    """TrigsplineError from a _core.LibraryError of spline construction: the
    library's sentence (``ts_error_message``, computed in C with the data and
    options of the call)."""
    st, index, w = err.args
    where = WHERE_NAMES[w] if 0 <= w < len(WHERE_NAMES) else None
    return TrigsplineError(st, getattr(err, "message", None) or strerror(st), index, where)


class _S(object):
    """Status codes used by name: _S.SIDE is TS_ERR_SIDE's value (from the
    library's names, ts_status_name)."""


for _code, _name in enumerate(STATUS_NAMES):
    if _name.startswith("TS_ERR_"):
        setattr(_S, _name[len("TS_ERR_"):], _code)


def domain_error(value, index, lo, hi, extrapolate="error"):
    """TS_ERR_DOMAIN for query index (None: a scalar query)."""
    v = float(value)
    if v != v:
        detail = "is NaN"
    elif v in (float("inf"), float("-inf")):
        detail = "is infinite (only extrapolate='clamp' accepts it)"
    else:
        detail = "lies outside [%s, %s] (extrapolate=%r; 'extend', 'clamp', 'linear' or " \
                 "'nan' evaluate there)" % (num(lo), num(hi), extrapolate)
    if index is None:
        return TrigsplineError(_S.DOMAIN, "query x = %s %s" % (num(v), detail), None, "query")
    return TrigsplineError(_S.DOMAIN, "query %d (x = %s) %s" % (index, num(v), detail), index,
                           "query")


def simple_error(status, message=None, index=None, where=None):
    return TrigsplineError(status, message or strerror(status), index, where)


def library_error(err, message=None):
    """TrigsplineError from a _core.LibraryError without context."""
    st, index, w = err.args
    where = WHERE_NAMES[w] if 0 <= w < len(WHERE_NAMES) else None
    return TrigsplineError(st, message or strerror(st), index, where)
