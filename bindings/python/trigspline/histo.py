"""Rates from bin totals: ``trigspline.disaggregate`` (docs/method.md §12).

Daily totals to hourly ones, grouped counts to single years: from bins
(edges) and their totals, a rate ``r(x)`` whose integral over every bin is
its total, ``lo <= r <= hi`` everywhere (default ``r >= 0``) and C¹.  The
work is one numpy generalized ufunc in C (``trigspline._histo``), one rate
per series, without the GIL.
"""
import numpy as np

from . import _histo
from ._util import STATUS_NAMES
from .errors import TrigsplineError, strerror

__all__ = ["disaggregate"]

_KINDS = {"totals": 0, "rate": 1, "derivative": 2}


def _options(kind, lo, hi, alpha):
    if kind not in _KINDS:
        raise ValueError("kind must be 'totals', 'rate' or 'derivative', not %r" % (kind,))
    alpha = _histo.DEFAULT_ALPHA if alpha is None else float(alpha)
    lo = _histo.DEFAULT_LO if lo is None else float(lo)
    hi = _histo.DEFAULT_HI if hi is None else float(hi)
    return np.array([_KINDS[kind], alpha, lo, hi], dtype=np.float64)


def _raise_first(status, index, edges, totals, opt):
    """TrigsplineError for the first series whose status is not TS_OK; the
    message is the library's sentence naming the bin or edge with its values
    where the bins themselves are refused."""
    flat = np.asarray(status).ravel()
    bad = np.flatnonzero(flat)
    if bad.size == 0:
        return
    k = int(bad[0])
    st, ix = int(flat[k]), int(np.asarray(index).ravel()[k])
    name = STATUS_NAMES[st] if 0 <= st < len(STATUS_NAMES) else ""
    where = "query" if name == "TS_ERR_DOMAIN" else None
    series = tuple(int(i) for i in np.unravel_index(k, np.shape(status)))
    msg = None
    if not where and ix >= 0:
        shape = np.shape(status)
        e = np.broadcast_to(edges, shape + edges.shape[-1:])[series]
        t = np.broadcast_to(totals, shape + totals.shape[-1:])[series]
        msg = _histo.message(e, t, float(opt[1]), float(opt[2]), float(opt[3]))
    if msg is None:
        msg = strerror(st)
        if ix >= 0:
            msg += " (%s %d)" % ("grid point" if where else "bin or edge", ix)
    if series:
        msg += " in series %s" % (series,)
    raise TrigsplineError(st, msg, ix if ix >= 0 else None, where, series or None)


def disaggregate(edges, totals, grid=None, *, per_bin=None, kind="totals", lo=None, hi=None,
                 alpha=None, axis=-1, errors="raise"):
    """Totals over a finer grid, or the rate, from bin totals.

    Parameters
    ----------
    edges : array_like, shape (..., n + 1)
        Bin edges, strictly increasing (broadcast against ``totals``).
    totals : array_like, shape (..., n)
        The total of each bin, within ``[lo, hi]`` times its width.
    grid : array_like, shape (..., m)
        Points inside ``[edges[0], edges[-1]]``, non-decreasing.
    per_bin : int, optional
        Instead of ``grid``: cut every bin into this many equal cells and
        return their totals (shape ``(..., n * per_bin)``), the fast path
        (``ts_histo_subdivide``: the cells' weights computed once for all bins).
    kind : {"totals", "rate", "derivative"}
        ``"totals"``: the m - 1 totals over ``[grid[k], grid[k+1]]`` (they add up
        to the bins' totals); ``"rate"``: r at the m points; ``"derivative"``: r'.
    lo, hi : float, optional
        Bounds of the rate (default 0 and +inf: r >= 0).
    alpha : float, optional
        Tension (default: the library's, as for splines); larger is flatter.
    axis : int
        The axis of ``totals`` along the bins (moved last and back).
    errors : {"raise", "nan"}
        A series that cannot be built raises ``TrigsplineError`` or is NaN.

    Returns
    -------
    numpy.ndarray
        float64; the bins axis replaced by the grid's cells (or points).
    """
    if errors not in ("raise", "nan"):
        raise ValueError("errors must be 'raise' or 'nan', not %r" % (errors,))
    opt = _options(kind, lo, hi, alpha)
    t = np.moveaxis(np.asarray(totals, dtype=np.float64), axis, -1)
    e = np.asarray(edges, dtype=np.float64)
    if (grid is None) == (per_bin is None):
        raise ValueError("give either grid or per_bin")
    if per_bin is not None:
        per_bin = int(per_bin)
        if kind != "totals" or per_bin < 1:
            raise ValueError("per_bin (>= 1) gives cell totals only (kind='totals')")
        opt[0] = 3.0
        # the grid argument only carries the output length (zero strides)
        g = np.broadcast_to(np.float64(0.0), (t.shape[-1] * per_bin,))
    else:
        g = np.asarray(grid, dtype=np.float64)
    if e.shape[-1:] != (t.shape[-1] + 1,):
        raise TrigsplineError(STATUS_NAMES.index("TS_ERR_LENGTH"),
                              "edges must have one more value than totals along the bins "
                              "(%d edges, %d totals)" % (e.shape[-1] if e.ndim else 0,
                                                         t.shape[-1]))
    out, status, index = _histo.disaggregate(e, t, g, opt)
    if errors == "raise":
        _raise_first(status, index, e, t, opt)
    if kind == "totals" and per_bin is None:
        out = out[..., 1:]
    return np.moveaxis(out, -1, axis)
