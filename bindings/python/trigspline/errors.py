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
    where : {"point", "interval", "query", "node", "patch", "x", "y", None}
        What ``index`` counts (``"node"``, ``"patch"``, ``"x"``, ``"y"``:
        surfaces).
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


def _line_text(line):
    m, c = line
    if m == 0:
        return "y = %s" % num(c)
    if c == 0:
        return "y = %s*x" % num(m)
    sign = "+" if c > 0 else "-"
    return "y = %s*x %s %s" % (num(m), sign, num(abs(c)))


def _line_at(line, x):
    return line[0] * x + line[1]


def spline_error(err, ctx):
    """TrigsplineError from a _core.LibraryError of spline construction.

    ctx: dict with x, f (arrays), shape (name), lower, upper ((m, c) or None),
    slopes_values (array or None)."""
    st, index, w = err.args
    where = WHERE_NAMES[w] if 0 <= w < len(WHERE_NAMES) else None
    x = ctx.get("x")
    f = ctx.get("f")
    x = [] if x is None else x
    f = [] if f is None else f
    base = strerror(st)
    msg = base
    if where == "point" and index is not None and index < len(x):
        xi, fi = x[index], f[index]
        loc = "point %d (x = %s)" % (index, num(xi))
        lower, upper = ctx.get("lower"), ctx.get("upper")
        if st == _S.SIDE:
            # which line (the scheme's own: above -> lower, below -> upper)
            if lower is not None and not (fi > _line_at(lower, xi)):
                line = lower
            elif upper is not None:
                line = upper
            else:
                line = lower
            if line is not None:
                msg = "%s lies on or across the line %s (f = %s, line value %s)" % (
                    loc, _line_text(line), num(fi), num(_line_at(line, xi)))
            else:
                msg = "%s lies on or across the line" % loc
        elif st == _S.NEGATIVE:
            msg = "%s has f = %s < 0: the positive scheme needs f >= 0" % (loc, num(fi))
        elif st == _S.UNSORTED and index > 0:
            msg = "%s is not greater than point %d (x = %s): x must be strictly increasing" % (
                loc, index - 1, num(x[index - 1]))
        elif st == _S.NONMONOTONE:
            msg = "%s (f = %s) changes the direction of the data: the monotone scheme needs " \
                  "monotone data" % (loc, num(fi))
        elif st == _S.LINES and lower is not None and upper is not None:
            msg = "%s: the lower line %s (%s) is not strictly below the upper line %s (%s)" % (
                loc, _line_text(lower), num(_line_at(lower, xi)), _line_text(upper),
                num(_line_at(upper, xi)))
        elif st == _S.PERIODIC:
            msg = "%s: periodic slopes need f[0] == f[%d], got %s and %s" % (
                loc, index, num(f[0]), num(fi))
        elif st == _S.ZERO_SLOPE:
            sv = ctx.get("slopes_values")
            d = " %s" % num(sv[index]) if sv is not None and index < len(sv) else ""
            msg = "%s touches the boundary (f = %s) and the user slope%s has the wrong sign" % (
                loc, num(fi), d)
        elif st == _S.NONFINITE:
            sv = ctx.get("slopes_values")
            if sv is not None and index < len(sv) and all(map(_finite, (xi, fi))) \
                    and not _finite(sv[index]):
                msg = "%s: user slope %s is not finite" % (loc, num(sv[index]))
            else:
                msg = "point %d (x = %s, f = %s): %s" % (index, num(xi), num(fi), base)
        else:
            msg = "%s: %s" % (loc, base)
    elif where == "interval" and index is not None and index + 1 < len(x):
        msg = "interval %d [%s, %s]: %s" % (index, num(x[index]), num(x[index + 1]), base)
    elif where is not None and index is not None:
        msg = "%s %d: %s" % (where, index, base)
    return TrigsplineError(st, msg, index, where)


def _finite(v):
    return v == v and v not in (float("inf"), float("-inf"))


class _S(object):
    """Status codes used by name."""
    NULL, NOMEM, OVERFLOW, TOO_FEW, NONFINITE, UNSORTED = 1, 2, 3, 4, 5, 6
    ALPHA, BETA, MARGIN, LENGTH, OPTION, PERIODIC, DOMAIN = 7, 8, 9, 10, 11, 12, 13
    NEGATIVE, SIDE, LINES, NONMONOTONE, INFEASIBLE, VIOLATED = 14, 15, 16, 17, 18, 19
    GEOMETRIC, DIMENSION, INDEX, ZERO_SLOPE = 20, 21, 22, 23
    SLOPE_OVERFLOW, TOO_LARGE, CONTROL_OVERFLOW, WIDTH, PRECISION, UNPROVEN = 24, 25, 26, 27, 28, 29


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
