"""Certified interpolation of many series at once: ``trigspline.interp``.

One spline per series, fitted and evaluated in C by the numpy generalized
ufunc ``trigspline._gufunc.interp`` (core signature
``(n),(n),(m),(k)->(m),(),(),()``), which broadcasts over every other axis and
runs without the GIL.  Each series gives the values of
``Spline(x, f, ...)(xq)`` with the same options, bit for bit (same C calls).
"""
import numpy as np

from . import _constraints, _gufunc, _options
from ._options import FORMS, SHAPES, SLOPES
from ._util import num
from .errors import _S, TrigsplineError

__all__ = ["interp", "InterpResult", "status_message", "constraint_message", "STATUS_OK",
           "OPTION_LAYOUT"]

STATUS_OK = 0

# The gufunc's extrapolation codes: the ts_extrap values, -1 NaN outside
# ('error' is checked before the call, see check_queries).
_EXTRAP_CODES = {"error": -1, "nan": -1, "clamp": 1, "extend": 2, "linear": 3}
OPTION_LAYOUT = ("shape", "form", "slopes", "extrapolate", "alpha", "lower_m", "lower_c",
                 "upper_m", "upper_c", "margin", "skipna", "certify", "want_gap",
                 "gap_first", "gap_end")

# The ts_status codes of a series with data gaps: TS_ERR_NONFINITE (missing
# values: the runs between them are fitted, the outputs next to them NaN) and
# TS_ERR_TOO_FEW (fewer than two points: all NaN); nothing is raised even
# with errors="raise".
DATA_GAPS = (4, 5)  # TS_ERR_TOO_FEW, TS_ERR_NONFINITE
# The codes whose index is an interval (include/trigspline.h); the others name a point.
_INTERVAL_STATUSES = (_S.ALPHA, _S.BETA, _S.MARGIN, _S.INFEASIBLE, _S.VIOLATED, _S.GEOMETRIC,
                      _S.CONTROL_OVERFLOW, _S.PRECISION, _S.UNPROVEN)


def where_of(code, o):
    """'interval' or 'point': what a series' index names for status code
    (with constraint records, TS_ERR_INFEASIBLE names the knot of a slope
    conflict)."""
    if code == _S.INFEASIBLE and o.get("constraints") is not None:
        return "point"
    return "interval" if code in _INTERVAL_STATUSES else "point"


def sentence(code, index, x, f, opt):
    """The library's sentence of one series' failure under the option
    vector opt (``pack``), x and f that series' data."""
    cons = len(opt) > _gufunc.OPT_LEN
    where = where_of(code, {"constraints": [] if cons else None})
    return _gufunc.message(int(code), int(index), 2 if where == "interval" else 1,
                           np.asarray(x, dtype=np.float64), np.asarray(f, dtype=np.float64),
                           opt)


def constraint_message(x, f, status, index, **options):
    """The library's sentence for one series' status and index (as
    ``interp(..., full=True)`` gives them) under the options of that call:
    for a constraint refusal it names the record and the necessary
    condition the data break (docs/method.md §13.1)."""
    o = resolve(options.pop("shape", None), options.pop("lower", None),
                options.pop("upper", None), **options)
    return sentence(status, index, x, f, pack(o))


def status_message(code):
    """The library's fixed message for a per-series status code."""
    return _gufunc.strerror(int(code))


def _line(v, name):
    """A bound: None, a number (constant line) or (m, c) for y = m x + c."""
    if v is None:
        return None
    if np.ndim(v) == 0:
        return (0.0, float(v))
    try:
        m, c = v
    except (TypeError, ValueError):
        raise ValueError("%s must be a number or a pair (m, c) for the line y = m*x + c, not %r"
                         % (name, v)) from None
    return (float(m), float(c))


def resolve_shape(shape, lower, upper):
    """shape name and the (m, c) lines it uses.  shape=None infers it from the
    bounds (docs/options.md): none, 'positive' for lower=0 alone (zeros
    allowed), 'above', 'below' or 'between' (strict: the data must lie
    strictly inside)."""
    lo, hi = _line(lower, "lower"), _line(upper, "upper")
    shape = _options.name(SHAPES, _options.infer_shape(shape, lo, hi), "shape")
    need = {"above": (1, 0), "below": (0, 1), "between": (1, 1)}.get(shape, (0, 0))
    if shape == "positive" and lo not in (None, (0.0, 0.0)) or shape != "positive" and (
            (lo is not None) != bool(need[0]) or (hi is not None) != bool(need[1])):
        raise ValueError("shape=%r takes %s" % (shape, {
            (0, 0): "no lower or upper bound", (1, 0): "lower only", (0, 1): "upper only",
            (1, 1): "lower and upper"}[need] + (" (or lower=0)" if shape == "positive" else "")))
    return shape, lo, hi


def resolve(shape=None, lower=None, upper=None, *, alpha=None, form=None, slopes=None,
            extrapolate=None, margin=None, skipna=None, certify=None, errors=None,
            constraints=None):
    """The options of the batch entry points (interp, the xarray accessor,
    pandas.interpolate) with every None replaced by its default: a dict of
    canonical values (docs/options.md); constraints: the records
    (``_constraints.records``) or None."""
    shape, lo, hi = resolve_shape(shape, lower, upper)
    sl = _options.enum("spline", "slopes", slopes, SLOPES)
    if sl == "user":
        raise ValueError("slopes must be one of %s, not 'user' (your own slopes: Spline)"
                         % ", ".join(repr(t) for t in SLOPES if t != "user"))
    alpha = float(_options.option("spline", "alpha", alpha))
    if not (alpha > 0 and np.isfinite(alpha)):
        raise ValueError("alpha must be finite and > 0, not %r" % alpha)
    margin = float(_options.option("spline", "margin", margin))
    if not (margin > 0 and np.isfinite(margin)):
        raise ValueError("margin must be finite and > 0, not %r" % margin)
    return {"shape": shape, "lower": lo, "upper": hi, "alpha": alpha,
            "form": _options.enum("spline", "form", form, FORMS), "slopes": sl,
            "extrapolate": _options.extrapolate(extrapolate), "margin": margin,
            "skipna": _options.flag("spline", "skipna", skipna),
            "certify": _options.flag("spline", "certify", certify),
            "errors": _options.errors(errors),
            "constraints": _constraints.records(constraints)}


def pack(o, want_gap=False, gap_intervals=(0, -1)):
    """The float64 option vector of the gufunc (layout OPTION_LAYOUT) from
    resolved options (``resolve``)."""
    lo = o["lower"] or (0.0, 0.0)
    hi = o["upper"] or (0.0, 0.0)
    head = [SHAPES.index(o["shape"]), FORMS.index(o["form"]), SLOPES.index(o["slopes"]),
            _EXTRAP_CODES[o["extrapolate"]], o["alpha"], lo[0], lo[1], hi[0], hi[1],
            o["margin"], bool(o["skipna"]), bool(o["certify"]), bool(want_gap),
            gap_intervals[0], gap_intervals[1]]
    if o.get("constraints") is not None:
        # docs/method.md §13: the records after the options (an empty list
        # too: the scheme of records, with none to meet)
        head += _constraints.pack(o["constraints"])
    return np.array(head, dtype=np.float64)


def pack_options(shape=None, lower=None, upper=None, *, alpha=None, form=None, slopes=None,
                 extrapolate=None, margin=None, skipna=None, certify=None, want_gap=False,
                 gap_intervals=(0, -1), constraints=None):
    """The float64 option vector of the gufunc (layout OPTION_LAYOUT); the
    options as for ``interp``.  gap_intervals: the least gap is taken over
    intervals [first, end) of each fitted series (end -1: to the last).
    extrapolate='error' travels as NaN outside: the caller checks the
    queries (``check_queries``)."""
    o = resolve(shape, lower, upper, alpha=alpha, form=form, slopes=slopes,
                extrapolate=extrapolate, margin=margin, skipna=skipna, certify=certify,
                constraints=constraints)
    return pack(o, want_gap, gap_intervals)


def check_queries(x, xq):
    """extrapolate='error': TrigsplineError (TS_ERR_DOMAIN) naming the first
    query outside its series' [x[0], x[-1]] (x (..., n) and xq (..., m)
    broadcast over the leading axes).  NaN queries are not outside."""
    if x.shape[-1] == 0 or xq.size == 0:
        return
    lo, hi = x[..., :1], x[..., -1:]
    with np.errstate(invalid="ignore"):
        out = (xq < lo) | (xq > hi)
    if not out.any():
        return
    pos = tuple(int(i[0]) for i in np.nonzero(out))
    q = np.broadcast_to(xq, out.shape)[pos]
    series = pos[:-1]
    s0 = np.broadcast_to(lo, out.shape[:-1] + (1,))[series + (0,)]
    s1 = np.broadcast_to(hi, out.shape[:-1] + (1,))[series + (0,)]
    raise TrigsplineError(_S.DOMAIN, "%squery %d (x = %s) lies outside [%s, %s] "
                          "(extrapolate='error'; 'nan' gives NaN outside, 'extend', 'clamp' "
                          "or 'linear' evaluate there)"
                          % ("series %s: " % (series,) if series else "", pos[-1], num(q),
                             num(s0), num(s1)), pos[-1], "query")


class InterpResult:
    """What ``interp(..., full=True)`` returns.

    values  the interpolated array (NaN for series that failed, and next to
            missing values)
    status  int32 per series, 0 = fitted and certified; 5 (TS_ERR_NONFINITE)
            = missing values, the runs between them fitted and certified;
            else a ts_status code (``status_message(code)`` gives its text)
    index   int64 per series: the point (or interval) the status names, in
            the series' own numbering, -1 if none
    gap     float64 per series: the least certified gap over the series
            (S - lower or upper - S; with constraints=, the least exact gap
            of its lower= and upper= records; NaN without a boundary or
            when not fitted)
    """

    __slots__ = ("values", "status", "index", "gap")

    def __init__(self, values, status, index, gap):
        self.values, self.status, self.index, self.gap = values, status, index, gap

    @property
    def all_certified(self):
        return bool(np.all(self.status == STATUS_OK))

    @property
    def least_gap(self):
        g = np.asarray(self.gap)
        g = g[np.isfinite(g)]
        return float(g.min()) if g.size else float("nan")

    def messages(self):
        """{code: message} for every status code that occurs."""
        return {int(c): status_message(c) for c in np.unique(self.status)}

    def __iter__(self):
        return iter((self.values, self.status, self.index, self.gap))


def _coerce(a, name):
    a = np.asarray(a)
    if a.dtype.kind not in "fiub":
        raise TypeError("%s must be a real numeric array, not dtype %s" % (name, a.dtype))
    if a.dtype.kind != "f" or a.dtype.itemsize > 8 or a.dtype.itemsize < 4:
        a = a.astype(np.float64)
    return a


def interp(x, f, xq, *, shape=None, lower=None, upper=None, alpha=None, form=None,
           slopes=None, extrapolate=None, margin=None, skipna=None, certify=None,
           errors=None, constraints=None, axis=-1, full=False, gap=False):
    """Interpolate every series of ``f`` along ``axis`` at ``xq``, certified.

    The option keywords and their defaults are the package's one vocabulary
    (docs/options.md), shared with :class:`Spline`, the xarray accessor and
    :func:`trigspline.pandas.interpolate`.

    Parameters
    ----------
    x : array_like, (..., n)
        Strictly increasing knots along ``axis`` (broadcast with ``f``).
    f : array_like, (..., n, ...)
        Data; float32 data give float32 output (computed in float64, then
        rounded so that the bound still holds and knots come back exactly).
    xq : array_like, (..., m)
        Queries (any order); broadcast against the other axes.
    shape : {'none', 'positive', 'above', 'below', 'between', 'monotone'}, default inferred
        The scheme of docs/method.md §5.  Left out, it follows from the
        bounds: ``lower=0`` alone ``'positive'`` (zeros allowed), another
        ``lower`` alone ``'above'``, ``upper`` alone ``'below'``, both
        ``'between'``, neither ${shape}.
    lower, upper : float or (m, c), default none
        Bounds: a constant or the line y = m x + c.
    alpha : float, default ${alpha}
    form : {'paper', 'c1', 'geometric'}, default ${form}
    slopes : str, default ${slopes}
    margin : float, default ${margin}
    certify : bool, default ${certify}
        As for ``Spline`` (docs/method.md §3-§6).
    extrapolate : {'error', 'nan', 'clamp', 'extend', 'linear', True, False}, default ${extrapolate}
        Queries outside a series' data: ``'error'`` raises a
        ``TrigsplineError`` naming the first (before anything is fitted),
        ``'nan'`` (``False``) gives NaN (as xarray's interp), or the
        library's policies.  With ``skipna``, a series is fitted on its
        finite points: queries beyond them but inside ``x`` give NaN.
    skipna : bool, default ${skipna}
        ``False``: a missing point (NaN or ±Inf in ``f`` or ``x``) stays
        local, as in xarray's interp.  The series is split at its missing
        points into runs of consecutive finite points; each run of two or
        more points is fitted on its own (its own end slopes); a query in
        a run's ``[first, last]`` knot gets that run's value, a query in an
        interval touching a missing point (or at it, or at a lone finite
        point between two missing ones) gets NaN.  Outside ``x`` only a run
        reaching that end extrapolates.  The series' status is
        TS_ERR_NONFINITE (5) with the index of its first missing point
        (``full=True``).  ``True``: fit through the finite points only,
        across the gaps.  No warning is given in either case.
    errors : {'raise', 'nan'}, default ${errors}
        A series that cannot be fitted (one of its runs): ``'raise'``
        raises ValueError naming the series and point, ``'nan'`` gives NaN
        for the whole series and its status.  A series with fewer than two
        finite points gives NaN either way.
    constraints : list, default none
        Constraint records certified on every interval of every series
        (docs/method.md §13), as for :class:`Spline`: SPEC strings
        (``'convex'``, ``'decreasing'``, ``'lower=0'``,
        ``'upper=poly:X,Y;X,Y'``, ``'slope<=5@2-4'``, ...) or dicts; the
        geometric form with ``shape='none'``.  A series the records refuse
        has the library's status (TS_ERR_CONDITION 31: the data break a
        necessary condition; TS_ERR_INFEASIBLE, TS_ERR_UNPROVEN), and
        ``errors='raise'`` raises the library's sentence naming the record
        and the condition (``constraint_message``).  A scope ``@I0-I1``
        counts the series' intervals (with ``skipna=True``, those between
        the points kept); a run between missing points meets the records
        on its own intervals.
    axis : int, default -1
        The axis of ``f`` (and ``x``) holding the series (numpy's gufunc
        convention).  The output has the queries on the same axis.
    full : bool, default False
        Return an :class:`InterpResult` (values, status, index, gap).
    gap : bool, default False
        Compute each series' least certified gap (costs a second pass of
        the certificate).

    Returns
    -------
    ndarray, or InterpResult when ``full``.
    """
    o = resolve(shape, lower, upper, alpha=alpha, form=form, slopes=slopes,
                extrapolate=extrapolate, margin=margin, skipna=skipna, certify=certify,
                errors=errors, constraints=constraints)
    if np.iscomplexobj(x) or np.iscomplexobj(xq):
        raise TrigsplineError(_S.OPTION, "x and xq must be real, not complex")
    if np.iscomplexobj(f):
        # as SciPy: the real and imaginary parts are two real splines with the
        # same options; the shape schemes bound real data only
        if o["shape"] != "none" or o["constraints"] is not None:
            raise TrigsplineError(_S.OPTION, "f is complex: the shape schemes and constraints "
                                  "keep real data inside bounds; use shape='none' and no "
                                  "constraints")
        if full or gap:
            raise ValueError("full= and gap= take real f; interpolate f.real and f.imag")
        kw = dict(shape=shape, lower=lower, upper=upper, alpha=alpha, form=form, slopes=slopes,
                  extrapolate=extrapolate, margin=margin, skipna=skipna, certify=certify,
                  errors=errors, axis=axis)
        fc = np.asarray(f)
        return interp(x, fc.real, xq, **kw) + 1j * interp(x, fc.imag, xq, **kw)
    opt = pack(o, want_gap=gap)
    f = _coerce(f, "f")
    x = _coerce(x, "x")
    xq = _coerce(xq, "xq")
    if f.ndim == 0:
        raise ValueError("f must have at least one dimension")
    axis = np.core.multiarray.normalize_axis_index(axis, f.ndim)
    fm = np.moveaxis(f, axis, -1)
    xm = np.moveaxis(x, axis - f.ndim + x.ndim, -1) if x.ndim > 1 else x
    qm = np.moveaxis(xq, axis - f.ndim + xq.ndim, -1) if xq.ndim > 1 else xq
    if xm.shape[-1] != fm.shape[-1]:
        raise ValueError("x has %d points along the axis, f has %d" % (xm.shape[-1], fm.shape[-1]))
    if o["extrapolate"] == "error":
        check_queries(xm, qm)
    y, status, index, g = _gufunc.interp(xm, fm, qm, opt)
    if o["errors"] == "raise":
        status, index = np.asarray(status), np.asarray(index)
        bad = (status != STATUS_OK) & ~np.isin(status, DATA_GAPS)
        if bad.any():
            # the first failing series; () for a single series (0-d status)
            where = tuple(int(i) for i in np.unravel_index(int(np.argmax(bad)), bad.shape))
            code, at = int(status[where]), int(index[where])
            what = where_of(code, o)
            lead = bad.shape + xm.shape[-1:]
            msg = _gufunc.message(code, at, 2 if what == "interval" else 1,
                                  np.broadcast_to(xm, lead)[where],
                                  np.broadcast_to(fm, lead)[where], opt)
            raise TrigsplineError(code, "%s%s" % ("series %s: " % (where,) if where else "", msg),
                                  at, what, series=where or None)
    if axis != f.ndim - 1:
        y = np.moveaxis(y, -1, axis - f.ndim + y.ndim)
    if full:
        return InterpResult(y, status, index, g)
    return y


_options.document(interp)
