"""Curve: open and closed parametric curves in 2-D and 3-D (docs/method.md §7)."""
from typing import Any, Optional

import numpy as np

from . import _core, _options
from ._options import PARAMS, SLOPES
from ._util import WHERE_NAMES, num, to_float
from .errors import _S, TrigsplineError, library_error, simple_error, strerror
from .spline import _per_interval, _report_dict

_MODES = {"error": _core.MODE_ERROR, "nan": _core.MODE_NAN}
_MODE_NAMES = {v: k for k, v in _MODES.items()}


def _box(box, dim):
    """Box -> (lo, hi) arrays of dim values, NaN for an open side."""
    lo, hi = np.full(dim, np.nan), np.full(dim, np.nan)
    items = list(box)
    if len(items) != dim:
        raise ValueError("box needs one (lo, hi) pair per coordinate (%d), got %d"
                         % (dim, len(items)))
    for k, pair in enumerate(items):
        if pair is None:
            continue
        pair = list(pair)
        if len(pair) != 2:
            raise ValueError("box[%d] must be a pair (lo, hi); use None for an open side" % k)
        if pair[0] is not None:
            lo[k] = to_float(pair[0], "box[%d][0]" % k)
            if lo[k] != lo[k]:
                raise simple_error(_S.NONFINITE, "box[%d][0] is NaN" % k)
        if pair[1] is not None:
            hi[k] = to_float(pair[1], "box[%d][1]" % k)
            if hi[k] != hi[k]:
                raise simple_error(_S.NONFINITE, "box[%d][1] is NaN" % k)
    return lo, hi


def _rebuild(state):
    return Curve(state["points"], **state["kwargs"])


class Curve:
    """The trigonometric spline curve through points (rows of 2 or 3 coordinates).

    The keywords and their defaults are the package's one vocabulary
    (docs/options.md); the defaults are the library's
    (``ts_curve_options_init``).

    Parameters
    ----------
    points : array_like, shape (m, 2) or (m, 3)
    closed : bool, default ${closed}
        A closed curve (the first point may be repeated at the end or not).
    param : {'centripetal', 'chord', 'uniform'}, default ${param}
        Parameter knots (t_0 = 0).
    alpha : float or array_like (one per segment), default ${alpha}
    beta : float or array_like (one per segment), default ${beta}
    box : sequence of (lo, hi) pairs, default none
        One pair per coordinate, ``None`` for an open side: each coordinate
        kept inside (β raised where needed, certified); a point may lie on a
        side, where the curve then touches it.
    slopes : str, default ${slopes}
        Slope method per coordinate (docs/method.md §6).
    margin : float, default ${margin}
        The margin t of the box rule (docs/method.md §5).
    extrapolate : {'error', 'nan', False}, default ${extrapolate}
        Parameters outside an open curve's [t0, tn]: ``'error'`` raises,
        ``'nan'`` (``False``) gives NaN.  Closed curves wrap.

    Notes
    -----
    Same conventions as :class:`Spline`: array in, array out (shape
    ``t.shape + (dim,)``), NaN in, NaN out; immutable, thread-safe, and
    ``copy``/``pickle`` rebuild it from its inputs.
    """

    def __init__(self, points: Any, *, closed: Optional[bool] = None,
                 param: Optional[str] = None, alpha: Any = None, beta: Any = None,
                 box: Any = None, slopes: Optional[str] = None, margin: Optional[float] = None,
                 extrapolate: Any = None) -> None:
        pts = np.array(points, dtype=np.float64)  # a copy: kept for pickling
        if pts.ndim != 2:
            raise TrigsplineError(_S.DIMENSION, "points must be a 2-D array (rows of 2 or 3 "
                                  "coordinates), got shape %r" % (pts.shape,))
        dim = pts.shape[1]
        if dim not in (2, 3):
            raise TrigsplineError(_S.DIMENSION, "points need 2 or 3 coordinates, not %d" % dim)
        npts = pts.shape[0]
        closed = _options.flag("curve", "closed", closed)
        if closed:
            segs = npts - 1 if npts >= 2 and (pts[0] == pts[-1]).all() else npts
        else:
            segs = max(npts - 1, 0)
        self._mode = self._mode_of(extrapolate)
        param = _options.enum("curve", "param", param, PARAMS)
        slopes = _options.enum("curve", "slopes", slopes, SLOPES)
        kwargs = {"closed": closed, "extrapolate": _MODE_NAMES[self._mode], "param": param,
                  "slopes": slopes}
        opts = {"closed": 1 if closed else 0, "param": PARAMS.index(param),
                "slopes": SLOPES.index(slopes)}
        for name, value in (("alpha", alpha), ("beta", beta)):
            sc, arr = _per_interval(_options.option("curve", name, value), name, segs)
            if sc is not None:
                opts[name] = kwargs[name] = sc
            elif arr is not None:
                opts[name + "s"] = kwargs[name] = arr
        if box is not None:
            opts["lo"], opts["hi"] = _box(box, dim)
            kwargs["box"] = box
        opts["margin"] = kwargs["margin"] = to_float(_options.option("curve", "margin", margin),
                                                     "margin")
        self._points = pts
        self._kwargs = kwargs
        try:
            self._h = _core.curve_new(pts, **opts)
        except _core.LibraryError as e:
            raise self._error(e, pts) from None

    @staticmethod
    def _mode_of(extrapolate):
        return _MODES[_options.extrapolate(extrapolate, "curve", ("error", "nan"),
                                           "Curve: extrapolate")]

    @staticmethod
    def _error(e, rows):
        st, idx, w = e.args
        where = WHERE_NAMES[w] if 0 <= w < len(WHERE_NAMES) else None
        if st == _S.TOO_FEW:
            msg = "too few points: %d given; an open curve needs 2, a closed one 3 distinct" \
                  % len(rows)
        else:  # the library's sentence, written in C with the points and options
            msg = getattr(e, "message", None) or strerror(st)
        return TrigsplineError(st, msg, idx, where)

    def __reduce__(self):
        return (_rebuild, ({"points": self._points, "kwargs": dict(self._kwargs)},))

    def __repr__(self):
        return "<trigspline.Curve %s, %d segments in %d-D>" % (
            "closed" if self.closed else "open", self.segments, self.dim)

    # ---- accessors ------------------------------------------------------
    @property
    def segments(self) -> int:
        return self._h.segments

    @property
    def dim(self) -> int:
        return self._h.dim

    @property
    def closed(self) -> bool:
        return self._h.closed

    @property
    def knots(self) -> np.ndarray:
        """Parameter knots t_0 = 0 < ... < t_segments (read-only)."""
        return self._h.knots

    x = knots

    @property
    def alpha(self) -> np.ndarray:
        return self._h.params()[0]

    @property
    def beta(self) -> np.ndarray:
        """β per segment (with a box: the computed ones)."""
        return self._h.params()[1]

    @property
    def c(self) -> np.ndarray:
        """Control points, shape (4, segments, dim)."""
        return np.moveaxis(self._h.control(), 1, 0)

    def control(self, i: int):
        """The 4 control points of segment i, shape (4, dim)."""
        i = int(i)
        if not 0 <= i < self.segments:
            raise simple_error(_S.INDEX, "segment %d does not exist (%d segments)"
                               % (i, self.segments), i, "interval")
        return self._h.control()[i]

    # ---- evaluation -----------------------------------------------------
    def __call__(self, t, nu: int = 0, extrapolate: Any = None) -> np.ndarray:
        """Point (nu = 0) or its first/second derivative in t.

        Returns an array of shape ``t.shape + (dim,)`` (``(dim,)`` for a
        scalar).  Closed curves wrap t periodically."""
        mode = self._mode if extrapolate is None else self._mode_of(extrapolate)
        if nu not in (0, 1, 2):
            raise ValueError("nu must be 0, 1 or 2 for a curve, not %r" % (nu,))
        try:
            return self._h.eval(t, int(nu), mode)
        except _core.LibraryError as e:
            st, j, _ = e.args
            if st == _S.DOMAIN:
                tv = np.asarray(t, dtype=np.float64).reshape(-1)[j or 0]
                kn = self.knots
                what = "query %d (t = %s)" % (j, num(tv)) if j is not None else \
                    "t = %s" % num(tv)
                why = ("is infinite" if tv == tv else "is NaN") if not np.isfinite(tv) else \
                    "lies outside [%s, %s] (open curve)" % (num(kn[0]), num(kn[-1]))
                raise TrigsplineError(st, "%s %s" % (what, why), j, "query") from None
            raise library_error(e) from None

    def derivative(self, nu: int = 1):
        """The derivative of order nu (<= 2) as a callable."""
        c = self

        def d(t, n=0, extrapolate=None):
            return c(t, nu + n, extrapolate)
        return d

    def length(self, tol: float = 0.0) -> float:
        """Arc length (``ts_curve_length``; tol <= 0 means 1e-12 relative)."""
        try:
            return self._h.length(to_float(tol, "tol"))
        except _core.LibraryError as e:
            raise library_error(e) from None

    def sample(self, m: int = 32) -> np.ndarray:
        """m samples per segment, knots included: rows (t, x, y[, z])."""
        m = int(m)
        if m < 2:
            raise simple_error(_S.OPTION, "sample needs m >= 2 samples per segment, not %d" % m)
        try:
            return self._h.sample(m)
        except _core.LibraryError as e:
            raise library_error(e) from None

    def certify(self, box=None, *, report: bool = False):
        """Exact check that every coordinate stays inside the box (by default
        the curve's own; True when it has none).  True/False, or (ok, list of
        report dicts, entry i*dim + k for segment i, coordinate k) with
        ``report=True``."""
        if box is None:
            lo = hi = None
        else:
            lo, hi = _box(box, self.dim)
        try:
            ok, _, reps = self._h.certify(lo, hi)
        except _core.LibraryError as e:
            raise library_error(e) from None
        if report:
            return ok, [_report_dict(r) for r in reps]
        return ok


_options.document(Curve, "curve")
