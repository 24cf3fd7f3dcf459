"""Certified interpolation of many series at once: ``trigspline.interp``.

One spline per series, fitted and evaluated in C by the numpy generalized
ufunc ``trigspline._gufunc.interp`` (core signature
``(n),(n),(m),(k)->(m),(),(),()``), which broadcasts over every other axis and
runs without the GIL.  Each series gives the values of
``Spline(x, f, ...)(xq)`` with the same options, bit for bit (same C calls).
"""
import numpy as np

from . import _gufunc

__all__ = ["interp", "InterpResult", "status_message", "STATUS_OK", "OPTION_LAYOUT"]

STATUS_OK = 0

SHAPES = {"none": 0, "positive": 1, "above": 2, "below": 3, "between": 4, "monotone": 5}
FORMS = {"paper": 0, "c1": 1, "geometric": 2}
SLOPES = {"arithmetic": 0, "geometric": 1, "harmonic": 2, "fritsch_carlson": 3, "pchip": 3,
          "akima": 4, "makima": 5, "periodic": 7}
EXTRAPS = {"nan": -1, None: -1, False: -1, "clamp": 1, "extend": 2, True: 2, "linear": 3}
OPTION_LAYOUT = ("shape", "form", "slopes", "extrapolate", "alpha", "lower_m", "lower_c",
                 "upper_m", "upper_c", "margin", "skipna", "certify", "want_gap",
                 "gap_first", "gap_end")
DEFAULT_MARGIN = 0.01  # TS_DEFAULT_MARGIN of include/trigspline.h

# The ts_status codes a series gets when its data cannot be fitted at all
# (NaN or too few points): its output is NaN, nothing is raised even with
# errors="raise".
DATA_GAPS = (4, 5)  # TS_ERR_TOO_FEW, TS_ERR_NONFINITE


def status_message(code):
    """The library's fixed message for a per-series status code."""
    return _gufunc.strerror(int(code))


def _line(v, name):
    """A bound: None, a number (constant line) or (m, c) for y = m x + c."""
    if v is None:
        return None
    if np.ndim(v) == 0:
        return (0.0, float(v))
    m, c = v
    return (float(m), float(c))


def resolve_shape(shape, lower, upper):
    """shape name and the (m, c) lines it uses.  shape=None infers it from the
    bounds: none, 'positive' for lower=0 alone (zeros allowed), 'above',
    'below' or 'between' (strict: the data must lie strictly inside)."""
    lo, hi = _line(lower, "lower"), _line(upper, "upper")
    if shape is None:
        if lo is None and hi is None:
            shape = "none"
        elif hi is None:
            shape = "positive" if lo == (0.0, 0.0) else "above"
        elif lo is None:
            shape = "below"
        else:
            shape = "between"
    if shape not in SHAPES:
        raise ValueError("shape must be one of %s, not %r" % (", ".join(map(repr, SHAPES)), shape))
    need = {"above": (1, 0), "below": (0, 1), "between": (1, 1)}.get(shape, (0, 0))
    if shape == "positive" and lo not in (None, (0.0, 0.0)) or shape != "positive" and (
            (lo is not None) != bool(need[0]) or (hi is not None) != bool(need[1])):
        raise ValueError("shape=%r takes %s" % (shape, {
            (0, 0): "no lower or upper bound", (1, 0): "lower only", (0, 1): "upper only",
            (1, 1): "lower and upper"}[need] + (" (or lower=0)" if shape == "positive" else "")))
    return shape, lo, hi


def pack_options(shape="positive", lower=None, upper=None, *, alpha=1.0, form="paper",
                 slopes="arithmetic", extrapolate="nan", margin=None, skipna=False,
                 certify=True, want_gap=False, gap_intervals=(0, -1)):
    """The float64 option vector of the gufunc (layout OPTION_LAYOUT).
    gap_intervals: the least gap is taken over intervals [first, end) of each
    fitted series (end -1: to the last)."""
    shape, lo, hi = resolve_shape(shape, lower, upper)
    for name, table, v in (("form", FORMS, form), ("slopes", SLOPES, slopes),
                           ("extrapolate", EXTRAPS, extrapolate)):
        if not isinstance(v, (str, bool, type(None))) or v not in table:
            raise ValueError("%s must be one of %s, not %r" % (
                name, ", ".join(repr(k) for k in table if k is not None), v))
    alpha = float(alpha)
    if not (alpha > 0 and np.isfinite(alpha)):
        raise ValueError("alpha must be finite and > 0, not %r" % alpha)
    margin = DEFAULT_MARGIN if margin is None else float(margin)
    if not (margin > 0 and np.isfinite(margin)):
        raise ValueError("margin must be finite and > 0, not %r" % margin)
    lo = lo or (0.0, 0.0)
    hi = hi or (0.0, 0.0)
    return np.array([SHAPES[shape], FORMS[form], SLOPES[slopes], EXTRAPS[extrapolate], alpha,
                     lo[0], lo[1], hi[0], hi[1], margin, bool(skipna), bool(certify),
                     bool(want_gap), gap_intervals[0], gap_intervals[1]], dtype=np.float64)


class InterpResult:
    """What ``interp(..., full=True)`` returns.

    values  the interpolated array (NaN for series that failed)
    status  int32 per series, 0 = fitted and certified; else a ts_status code
            (``status_message(code)`` gives its text)
    index   int64 per series: the point (or interval) the status names, in
            the series' own numbering, -1 if none
    gap     float64 per series: the least certified gap over the series
            (S - lower or upper - S; NaN without a boundary or when not fitted)
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


def interp(x, f, xq, *, shape=None, lower=None, upper=None, alpha=1.0, form="paper",
           slopes="arithmetic", extrapolate="nan", margin=None, skipna=False,
           certify=True, axis=-1, full=False, gap=False, errors="nan"):
    """Interpolate every series of ``f`` along ``axis`` at ``xq``, certified.

    Parameters
    ----------
    x : array_like, (..., n)
        Strictly increasing knots along ``axis`` (broadcast with ``f``).
    f : array_like, (..., n, ...)
        Data; float32 data give float32 output (computed in float64, then
        rounded so that the bound still holds and knots come back exactly).
    xq : array_like, (..., m)
        Queries (any order); broadcast against the other axes.
    shape : {'positive', 'monotone', 'above', 'below', 'between', 'none'}, optional
        The scheme of docs/method.md §5.  None infers it from ``lower`` /
        ``upper``: ``lower=0`` alone is 'positive' (zeros allowed).
    lower, upper : float or (m, c), optional
        Bounds: a constant or the line y = m x + c.
    alpha, form, slopes, margin, certify
        As for ``Spline`` (docs/method.md §3-§6).
    extrapolate : {'nan', 'clamp', 'extend', 'linear'}
        Queries outside a series' data: NaN (default, like xarray) or the
        library's policies.
    skipna : bool
        Fit each series through its finite points only (gaps).
    axis : int
        The axis of ``f`` (and ``x``) holding the series.  The output has the
        queries on the same axis.
    full : bool
        Return an :class:`InterpResult` (values, status, index, gap).
    gap : bool
        Compute each series' least certified gap (costs a second pass of
        the certificate).
    errors : {'nan', 'raise'}
        A series that cannot be fitted gives NaN and its status; with
        'raise', a status other than a data gap (NaN, too few points) raises
        ValueError naming the series and point.

    Returns
    -------
    ndarray, or InterpResult when ``full``.
    """
    if errors not in ("nan", "raise"):
        raise ValueError("errors must be 'nan' or 'raise', not %r" % (errors,))
    opt = pack_options(shape, lower, upper, alpha=alpha, form=form, slopes=slopes,
                       extrapolate=extrapolate, margin=margin, skipna=skipna,
                       certify=certify, want_gap=gap)
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
    y, status, index, g = _gufunc.interp(xm, fm, qm, opt)
    if errors == "raise":
        bad = (status != STATUS_OK) & ~np.isin(status, DATA_GAPS)
        if bad.any():
            where = tuple(int(i[0]) for i in np.nonzero(bad))
            code = int(status[where])
            raise ValueError("series %s: %s (point %d)" % (where, status_message(code),
                                                          int(index[where])))
    if axis != f.ndim - 1:
        y = np.moveaxis(y, -1, axis - f.ndim + y.ndim)
    if full:
        return InterpResult(y, status, index, g)
    return y
