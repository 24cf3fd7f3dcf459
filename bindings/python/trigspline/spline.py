"""Spline: the GC¹ cubic trigonometric spline of a function (docs/method.md §3–§6),
with the interface of SciPy's interpolators (PchipInterpolator, PPoly)."""
import math
from typing import Any, Optional, Tuple, Union

import numpy as np

from . import _constraints, _core, _options
from ._options import FORMS, SHAPES, SLOPES, TERMS
from ._util import float_array, is_scalar, num, to_float
from .errors import (_S, TrigsplineError, domain_error, library_error, simple_error,
                     spline_error, strerror)

ArrayLike = Any
Extrapolate = Union[bool, str, None]

_MODES = {"extend": _core.MODE_EXTEND, "clamp": _core.MODE_CLAMP,
          "linear": _core.MODE_LINEAR, "nan": _core.MODE_NAN, "error": _core.MODE_ERROR}
_MODE_NAMES = {v: k for k, v in _MODES.items()}


def _mode(extrapolate, default=None):
    """The per-call policy: None the default (the spline's), True = 'extend',
    False = 'nan' (SciPy), or a name (docs/options.md)."""
    if extrapolate is None and default is not None:
        return default
    return _MODES[_options.extrapolate(extrapolate)]


def _line(value, what):
    """(m, c) from a number c (the line y = c) or a pair (m, c)."""
    if value is None:
        return None
    if is_scalar(value):
        return (0.0, to_float(value, what))
    try:
        items = list(value)
    except TypeError:
        raise TypeError("%s must be a number or a pair (m, c) for the line y = m*x + c"
                        % what) from None
    if len(items) != 2:
        raise ValueError("%s must be a number or a pair (m, c) for the line y = m*x + c, got "
                         "%d values" % (what, len(items)))
    return (to_float(items[0], what + "[0]"), to_float(items[1], what + "[1]"))


def _per_interval(value, name, n):
    """(scalar or None, array or None) for a scalar-or-per-interval parameter."""
    if value is None:
        return None, None
    if is_scalar(value):
        return to_float(value, name), None
    what = "%s must be a number or an array of numbers (one per interval)" % name
    if isinstance(value, (str, bytes)):
        raise TypeError("%s, got a string %r" % (what, value))
    try:
        vals = np.array(value, dtype=np.float64).ravel()  # a copy: kept for pickling
    except (TypeError, ValueError):
        raise TypeError("%s, got %r" % (what, value)) from None
    if len(vals) != n:
        raise TrigsplineError(_S.LENGTH, "%s has %d values; a per-interval %s needs exactly "
                              "n = %d (one per interval)" % (name, len(vals), name, n))
    return None, vals


def _report_dict(r):
    term = int(r[6])
    return {"x0": r[0], "x1": r[1], "alpha": r[2], "beta": r[3], "a": r[4], "B": list(r[5]),
            "term": TERMS[term] if 0 <= term < len(TERMS) else term,
            "has_lower": bool(r[7]), "has_upper": bool(r[8]),
            "gap_lower": r[9], "at_lower": r[10], "gap_upper": r[11], "at_upper": r[12],
            "certified": bool(r[13]),
            "y_min": r[14], "at_y_min": r[15], "y_max": r[16], "at_y_max": r[17],
            "excursion_above": r[18], "excursion_below": r[19]}


def estimate_slopes(x: ArrayLike, f: ArrayLike, slopes: Optional[str] = None, *,
                    method: Optional[str] = None) -> np.ndarray:
    """Slopes d_i of docs/method.md §6 at every point (``ts_slopes_compute``).

    Parameters
    ----------
    x, f : array_like, shape (n,)
        Points, x strictly increasing.
    slopes : str, default ${slopes}
        ``'arithmetic'``, ``'geometric'``, ``'harmonic'``, ``'fritsch-carlson'``,
        ``'akima'``, ``'makima'``, ``'periodic'`` or ``'steffen'`` (the ``slopes`` of
        :class:`Spline`).
    method : str
        Deprecated name of ``slopes``.

    Returns
    -------
    ndarray, shape (n,)
    """
    slopes = _options.renamed("method", "slopes", method, slopes)
    m = SLOPES.index(_options.enum("spline", "slopes", slopes, SLOPES))
    if SLOPES[m] == "user":
        raise ValueError("slopes 'user' has nothing to estimate")
    xa, fa = float_array(x, "x", 1), float_array(f, "f", 1)
    try:
        return _core.slopes_compute(m, xa, fa)
    except _core.LibraryError as e:
        if e.args[0] == _S.LENGTH:
            raise TrigsplineError(_S.LENGTH, "x has %d values but f has %d"
                                  % (len(xa), len(fa))) from None
        raise spline_error(e) from None


_options.document(estimate_slopes)


def _rebuild(state):
    """Unpickling: a Spline from its inputs (see Spline.__reduce__)."""
    return Spline(state["x"], state["f"], **state["kwargs"])


class Spline:
    """The shape-preserving trigonometric spline through (x[i], f[i]).

    SciPy's interpolator interface (:class:`scipy.interpolate.PchipInterpolator`:
    the same call signature, evaluation, derivatives, integrals, roots and
    ``axis``); it can also keep the curve positive, above or below a line,
    between two lines, or monotone, certified exactly on every interval.
    Unlike SciPy, a query outside the data raises by default (the library's
    ``extrapolate='error'``): ``extrapolate=True`` gives SciPy's behaviour.

    With no options the curve keeps PCHIP's promise: on every interval it is
    monotone and stays between the interval's two data values (no new
    extrema), it is exact on straight lines and C¹ (geometric form, Steffen's
    slopes, ``alpha=0.85``; docs/method.md §5.10).  Complex ``f`` is
    interpolated as two real splines (real and imaginary parts, the same
    options; no shape scheme); complex ``x`` is refused; zero-size ``f``
    gives empty results.

    The keywords and their defaults are the package's one vocabulary
    (docs/options.md), shared with :func:`trigspline.interp`, the xarray
    accessor, :func:`trigspline.pandas.interpolate`, :class:`Surface` and
    :class:`Curve`; the defaults are the library's (``ts_spline_options_init``).

    Parameters
    ----------
    x : array_like, shape (n,)
        Strictly increasing knots.
    f : array_like, shape (..., n, ...)
        Values; ``f`` is interpolated along ``axis``.  Several series (the
        other axes) are fitted independently, each with its own β and
        certificate.
    axis : int, default 0
        The axis of ``f`` along the knots (as SciPy's interpolators).
    extrapolate : {'error', 'clamp', 'extend', 'linear', 'nan', True, False}, default ${extrapolate}
        Policy outside ``[x[0], x[-1]]``: ``'error'`` raises naming the
        query; ``'extend'`` (``True``, SciPy's default) continues the end
        interval's own formula; ``'nan'`` (``False``) gives NaN; ``'clamp'``
        the end value (derivatives 0); ``'linear'`` the tangent line at the
        end.  Shape guarantees hold on ``[x[0], x[-1]]`` only; ``'clamp'``
        keeps positivity and constant bounds outside too.
    shape : {'none', 'positive', 'above', 'below', 'between', 'monotone'}, default inferred
        The region the spline must stay in (docs/method.md §5); ``'none'``
        uses ``beta`` as given.  Left out, it follows from the bounds:
        ``lower=0`` alone ``'positive'`` (zeros allowed), another ``lower``
        alone ``'above'``, ``upper`` alone ``'below'``, both ``'between'``,
        neither ${shape}.
    lower, upper : float or (m, c), default none
        The lines y = m x + c (a number c: y = c) of ``'above'`` (``lower``),
        ``'below'`` (``upper``) and ``'between'`` (both).
    alpha : float or array_like of n-1 floats, default ${alpha}
        Tension parameter α (docs/method.md §3), > 0.
    beta : float or array_like of n-1 floats, default ${beta}
        β, only with ``shape='none'`` (the schemes compute β).
    margin : float or array_like of n-1 floats, default ${margin}
        The margin t of docs/method.md §5.
    slopes : str or array_like, default ${slopes}
        Slope estimate (docs/method.md §6): ``'arithmetic'``,
        ``'geometric'``, ``'harmonic'``, ``'fritsch-carlson'``, ``'akima'``,
        ``'makima'``, ``'periodic'``, ``'steffen'`` (Steffen 1990, the default:
        with the default alpha it keeps PCHIP's promise, docs/method.md §5.10);
        or your own slopes d_i, an array the
        shape of ``f`` (as ``dydx`` of SciPy's ``CubicHermiteSpline``).
    form : {'paper', 'c1', 'geometric'}, default ${form}
        docs/method.md §3/§4.
    certify : bool, default ${certify}
        ``False`` skips the exact certificate where the scheme is a proof by
        itself.
    constraints : list, default none
        Constraint records certified per interval (docs/method.md §13;
        geometric form, no ``shape``): SPEC strings as the command line's
        ``--constraint`` (``'convex'``, ``'concave'``, ``'increasing'``,
        ``'decreasing'``, ``'lower=C'``, ``'upper=C'``,
        ``'lower=poly:X,Y;X,Y;...'``, ``'slope>=V'``, ``'slope<=V'``,
        ``'abs-slope<=V'``, with an optional scope ``'@I0-I1'``) or dicts
        ``{"kind", "value", "points", "first", "count"}``; a bound given by
        another one-dimensional Spline B: ``{"kind": "lower", "spline": B}``
        (docs/method.md §13.7; data strictly on their side of B).  See
        ``constraint_report``.
    line, slopes_values
        Deprecated: ``line`` is ``lower`` (``'above'``) or ``upper``
        (``'below'``); ``slopes_values`` is ``slopes`` given an array.

    Raises
    ------
    TrigsplineError
        A ``ValueError`` naming the offending point or interval (``.name``,
        ``.index``, ``.where``).

    Notes
    -----
    A Spline is immutable and can be shared between threads; the GIL is
    released while it is built and evaluated.  ``copy``, ``deepcopy`` and
    ``pickle`` rebuild it from its inputs (bit-identical values).
    """

    def __init__(self, x: ArrayLike, f: ArrayLike, axis: int = 0,
                 extrapolate: Extrapolate = None, *, shape: Optional[str] = None,
                 lower: Any = None, upper: Any = None, alpha: Any = None, beta: Any = None,
                 margin: Any = None, slopes: Any = None, form: Optional[str] = None,
                 certify: Optional[bool] = None, line: Optional[Tuple[float, float]] = None,
                 slopes_values: ArrayLike = None, constraints: Any = None) -> None:
        if np.iscomplexobj(x):
            raise TrigsplineError(_S.OPTION, "x is complex; the abscissae must be real")
        # complex f (as SciPy): the real and imaginary parts are two real
        # splines with the same options, a trailing axis of 2 inside
        self._complex = np.iscomplexobj(f)
        if self._complex:
            fc = np.asarray(f)
            shp_name = _options.infer_shape(shape, lower, upper) if line is None else shape
            if (shp_name is not None and shp_name != "none") or line is not None:
                raise TrigsplineError(_S.OPTION, "f is complex: the shape schemes keep real "
                                      "data inside bounds; use shape='none' or split the "
                                      "real and imaginary parts yourself")
            f = np.stack([fc.real, fc.imag], axis=-1)
        xa = float_array(x, "x", 1)
        fa = float_array(f, "f")
        if fa.ndim == 0 or (self._complex and fa.ndim == 1):
            raise ValueError("f must have at least one dimension")
        ax = int(axis)
        if self._complex and ax < 0:
            ax -= 1  # counted on f without the inner axis of 2
        if not -fa.ndim <= ax < fa.ndim:
            raise ValueError("axis %d is out of range for f of shape %r" % (ax, fa.shape))
        ax %= fa.ndim
        if fa.shape[ax] != xa.size:
            raise TrigsplineError(_S.LENGTH, "x has %d values but f has %d along axis %d"
                                  % (xa.size, fa.shape[ax], ax))
        n = max(xa.size - 1, 0)
        self._mode = _mode(extrapolate)
        slopes = _options.renamed("slopes_values", "slopes", slopes_values, slopes)
        certify = _options.flag("spline", "certify", certify)
        form = _options.enum("spline", "form", form, FORMS)
        # bounds and shape
        lower, upper = _line(lower, "lower"), _line(upper, "upper")
        if line is not None:
            _options.deprecated("line= is deprecated; use lower= (shape='above') or upper= "
                                "(shape='below') (docs/options.md)")
            line = _line(line, "line")
            side = {"above": "lower", "below": "upper"}.get(
                shape.strip().lower() if isinstance(shape, str) else shape)
            if side is None:
                raise ValueError("line= goes with shape='above' or 'below' (use lower= and "
                                 "upper= for 'between')")
            given = lower if side == "lower" else upper
            if given is not None and given != line:
                raise ValueError("shape=%r: give line or %s, not both" % (shape, side))
            if side == "lower":
                lower = line
            else:
                upper = line
        shp = _options.name(SHAPES, _options.infer_shape(shape, lower, upper), "shape")
        if shp == "positive" and lower == (0.0, 0.0) and upper is None:
            lower = None  # lower=0: the positive scheme's own bound (as interp)
        if shp == "above":
            if lower is None or upper is not None:
                raise ValueError("shape='above' needs the line lower=(m, c) alone")
        elif shp == "below":
            if upper is None or lower is not None:
                raise ValueError("shape='below' needs the line upper=(m, c) alone")
        elif shp == "between":
            if lower is None or upper is None:
                raise ValueError("shape='between' needs lower=(m, c) and upper=(m, c)")
        elif lower is not None or upper is not None:
            raise ValueError("lower and upper go with shape='above', 'below' or 'between', "
                             "not %r" % shp)
        kwargs = {"axis": ax, "extrapolate": _MODE_NAMES[self._mode], "shape": shp,
                  "certify": certify, "form": form}
        opts = {"shape": SHAPES.index(shp), "certify": 1 if certify else 0,
                "form": FORMS.index(form), "lower": lower, "upper": upper}
        if lower is not None:
            kwargs["lower"] = lower
        if upper is not None:
            kwargs["upper"] = upper
        self._lines = ((0.0, 0.0) if shp == "positive" else lower, upper)
        # alpha, beta, margin
        for name, value in (("alpha", alpha), ("beta", beta), ("margin", margin)):
            if name == "beta" and shp != "none":
                if value is None or (is_scalar(value) and float(value) == 0.0):
                    continue
                raise ValueError("beta is chosen by the shape scheme (shape=%r); leave it "
                                 "out and set alpha and margin instead" % shp)
            sc, arr = _per_interval(_options.option("spline", name, value), name, n)
            if sc is not None:
                opts[name] = sc
                kwargs[name] = sc
            elif arr is not None:
                opts[name + "s"] = arr
                kwargs[name] = arr
        # slopes: a name, or the slopes themselves
        sv = None
        if slopes is not None and not isinstance(slopes, str):
            sv = np.array(slopes, dtype=np.float64)  # a copy: kept for pickling
            if sv.shape != fa.shape:
                raise TrigsplineError(_S.LENGTH, "slopes has shape %r; your own slopes need "
                                      "one per value of f, shape %r" % (sv.shape, fa.shape))
            opts["slopes"] = SLOPES.index("user")
            kwargs["slopes"] = sv
        else:
            sname = _options.enum("spline", "slopes", slopes, SLOPES)
            if sname == "user":
                raise ValueError("slopes='user': give the slopes themselves, slopes=array "
                                 "(one per point)")
            opts["slopes"] = SLOPES.index(sname)
            kwargs["slopes"] = sname
        if constraints is not None:
            # docs/method.md §13: records certified per interval (geometric form)
            opts["constraints"] = _constraints.records(constraints)
            kwargs["constraints"] = constraints
        self._kwargs = kwargs
        self._axis = ax
        self._shape = shp
        # series: f with the axis last, flattened to (series, n)
        if fa.ndim == 1:
            self._trail = ()
            self._pre = ()
            series = [fa]
            svs = [sv]
        else:
            self._pre = fa.shape[:ax]
            self._trail = fa.shape[ax + 1:]
            fm = np.ascontiguousarray(np.moveaxis(fa, ax, -1)).reshape(-1, xa.size)
            series = list(fm)
            svs = (list(np.ascontiguousarray(np.moveaxis(sv, ax, -1)).reshape(-1, xa.size))
                   if sv is not None else [None] * len(series))
        if not series or fa.size == 0:  # zero-size f: nothing to fit, empty results
            self._h = []
            self._x = xa
            self._n = n
            return
        handles = []
        for k, (fk, sk) in enumerate(zip(series, svs)):
            o = dict(opts)
            if sk is not None:
                o["user_slopes"] = sk
            try:
                handles.append(_core.spline_new(xa, fk, **o))
            except _core.LibraryError as e:
                raise self._build_error(e, k, len(series)) from None
        self._h = handles
        h0 = handles[0]
        self._x = h0.x
        self._n = h0.intervals

    def _build_error(self, e, k, count):
        err = spline_error(e)
        if count > 1:
            idx = tuple(int(i) for i in np.unravel_index(k, self._pre + self._trail))
            err = TrigsplineError(err.status, "series %r: %s" % (idx, err.message), err.index,
                                  err.where, idx)
        return err

    # ---- pickling and copies: rebuilt from the inputs -------------------
    def __reduce__(self):
        if len(self._h) == 1 and not self._pre and not self._trail:
            f = np.array(self._h[0].f)
        else:
            fm = np.stack([h.f for h in self._h]).reshape(self._pre + self._trail + (-1,))
            f = np.moveaxis(fm, -1, self._axis).copy()
        return (_rebuild, ({"x": np.array(self._x), "f": f, "kwargs": dict(self._kwargs)},))

    def __repr__(self):
        return "<trigspline.Spline %d intervals on [%s, %s], shape=%r, form=%r%s>" % (
            self._n, num(self._x[0]), num(self._x[-1]), self._shape, self.form,
            ", %d series" % len(self._h) if len(self._h) > 1 else "")

    # ---- accessors --------------------------------------------------------
    def _stacked(self, get):
        if len(self._h) == 1 and not self._pre and not self._trail:
            return get(self._h[0])
        a = np.stack([get(h) for h in self._h])
        return np.moveaxis(a.reshape(self._pre + self._trail + a.shape[1:]), len(self._pre) +
                           len(self._trail), len(self._pre))

    @property
    def x(self) -> np.ndarray:
        """The knots, shape (n+1,) (read-only)."""
        return self._x

    @property
    def knots(self) -> np.ndarray:
        """Alias of ``x``."""
        return self._x

    @property
    def values(self) -> np.ndarray:
        """The data values f, shape of ``f`` (read-only for one series)."""
        return self._stacked(lambda h: h.f)

    @property
    def slopes(self) -> np.ndarray:
        """The slopes d_i actually used (after any shape adjustment), shape of ``f``."""
        return self._stacked(lambda h: h.slopes)

    @property
    def alpha(self) -> np.ndarray:
        """α per interval (the interval axis replaces the data axis)."""
        return self._stacked(lambda h: h.alpha)

    @property
    def beta(self) -> np.ndarray:
        """β per interval (computed by the shape scheme)."""
        return self._stacked(lambda h: h.beta)

    @property
    def a(self) -> np.ndarray:
        """a_i = α_i + β_i per interval."""
        return self.alpha + self.beta

    @property
    def c(self) -> np.ndarray:
        """Control values B0..B3 per interval, shape (4, n, ...) like ``PPoly.c``
        (the coefficients of the basis A0..A3 of docs/method.md §2, not of a
        power series)."""
        b = np.stack([h.control()[0] for h in self._h])  # (series, n, 4)
        return b.transpose(2, 1, 0).reshape((4, self._n) + self._pre + self._trail)

    @property
    def control_x(self) -> np.ndarray:
        """Abscissae X0..X3 of the control polygon per interval, shape (4, n)."""
        return self._h[0].control()[1].T.copy()

    @property
    def axis(self) -> int:
        return self._axis

    @property
    def intervals(self) -> int:
        """Number of intervals n (points - 1)."""
        return self._n

    @property
    def form(self) -> str:
        return FORMS[self._h[0].form]

    @property
    def shape(self) -> str:
        return self._shape

    @property
    def extrapolate(self) -> str:
        """The spline's extrapolation policy ('error', 'clamp', 'extend', 'linear', 'nan')."""
        return _MODE_NAMES[self._mode]

    @property
    def domain(self) -> Tuple[float, float]:
        return (float(self._x[0]), float(self._x[-1]))

    def control(self, i: int):
        """(B, X): control values B0..B3 of interval i and their abscissae (one series)."""
        i = int(i)
        if not 0 <= i < self._n:
            raise simple_error(_S.INDEX, "interval %d does not exist (n = %d)" % (i, self._n),
                               i, "interval")
        B, X = self._h[0].control()
        return list(B[i]), list(X[i])

    # ---- evaluation ---------------------------------------------------------
    def __call__(self, x: ArrayLike, nu: int = 0, extrapolate: Extrapolate = None, *,
                 threads: int = 1, out: Optional[np.ndarray] = None) -> np.ndarray:
        """Values or derivatives at x.

        Parameters
        ----------
        x : array_like
            Queries of any shape (a scalar gives a 0-d array).  NaN gives NaN.
        nu : int, optional
            Derivative order >= 0 (closed form; orders above 2 in the paper
            and c1 forms only).
        extrapolate : optional
            Policy for this call (the values of the class); default: the
            spline's own (``self.extrapolate``).
        threads : int, optional
            Split a large batch over threads (0: all cores).
        out : ndarray, optional
            A writable C-contiguous float64 array with one element per query
            (one series only), filled in place.

        Returns
        -------
        ndarray
            Shape ``f.shape[:axis] + x.shape + f.shape[axis+1:]``.

        Raises
        ------
        TrigsplineError
            Under ``extrapolate='error'``, naming the first query outside.
        """
        mode = _mode(extrapolate, self._mode)
        if nu < 0 or int(nu) != nu:
            raise ValueError("nu must be an integer >= 0, not %r" % (nu,))
        nu = int(nu)
        if self._complex:
            self._complex = False
            try:
                r = self(x, nu, extrapolate, threads=threads)
            finally:
                self._complex = True
            return r[..., 0] + 1j * r[..., 1]
        if not self._h:
            xq = np.asarray(x, dtype=np.float64)
            return np.empty(self._pre + xq.shape + self._trail)
        try:
            if len(self._h) == 1 and not self._pre and not self._trail:
                return self._h[0].eval(x, nu, mode, out, threads)
            if out is not None:
                raise ValueError("out= is for one series; this spline has %d" % len(self._h))
            xq = np.asarray(x, dtype=np.float64)
            res = np.empty((len(self._h), xq.size))
            xf = np.ascontiguousarray(xq.reshape(-1))
            for k, h in enumerate(self._h):
                h.eval(xf, nu, mode, res[k], threads)
        except _core.LibraryError as e:
            raise self._query_error(e, x) from None
        a, b, q = len(self._pre), len(self._trail), xq.ndim
        r = res.reshape(self._pre + self._trail + xq.shape)
        order = list(range(a)) + list(range(a + b, a + b + q)) + list(range(a, a + b))
        return r.transpose(order)

    def _query_error(self, e, x):
        st, index, _ = e.args
        if st == _S.DOMAIN:
            xq = np.asarray(x, dtype=np.float64).reshape(-1)
            v = xq[index] if index is not None else xq[0]
            return domain_error(v, index, self._x[0], self._x[-1], "error")
        return library_error(e)

    def derivative(self, nu: int = 1) -> "Derivative":
        """The derivative of order nu as a callable object (``PPoly.derivative``)."""
        if nu < 0:
            return self.antiderivative(-nu)
        return Derivative(self, int(nu)) if nu else self

    def antiderivative(self, nu: int = 1) -> "Antiderivative":
        """The antiderivative F(x) = ∫_{x0}^x S as a callable object (nu = 1 only)."""
        if nu == 0:
            return self
        if nu != 1:
            raise NotImplementedError("antiderivative of order %r: only nu = 1 is available "
                                      "(the trigonometric pieces do not close under repeated "
                                      "integration in the geometric form)" % (nu,))
        return Antiderivative(self)

    # ---- integrals --------------------------------------------------------
    def _ends(self, h):
        x0, xn = float(self._x[0]), float(self._x[-1])
        e = h.eval(np.array([x0, xn]), 0), h.eval(np.array([x0, xn]), 1), \
            h.eval(np.array([x0, xn]), 2)
        return (x0, e[0][0], e[1][0], e[2][0]), (xn, e[0][1], e[1][1], e[2][1])

    def _outside_integral(self, h, side, a, b, mode):
        """∫_a^b of the extrapolation on one side (a, b arrays on that side, a <= b)."""
        ends = self._ends(h)
        xe, y, d, c2 = ends[side]
        if mode == _core.MODE_NAN:
            return np.where(a == b, 0.0, np.nan)
        if mode == _core.MODE_ERROR:
            bad = np.flatnonzero(a != b)
            if bad.size:
                raise TrigsplineError(_S.DOMAIN, "integration bound outside [%s, %s] with "
                                      "extrapolate='error'" % (num(self._x[0]),
                                                               num(self._x[-1])), None, "query")
            return np.zeros_like(a)
        if mode == _core.MODE_CLAMP:
            return y * (b - a)
        ua, ub = a - xe, b - xe
        if mode == _core.MODE_LINEAR:
            return y * (b - a) + 0.5 * d * (ub * ub - ua * ua)
        if self.form == "geometric":  # the osculating parabola (include/trigspline.h)
            return y * (b - a) + 0.5 * d * (ub * ub - ua * ua) + c2 / 6.0 * (ub ** 3 - ua ** 3)
        # paper / c1: the end interval's trigonometric polynomial continued
        i = 0 if side == 0 else self._n - 1
        B = h.control()[0][i]
        x0, h_ = float(self._x[i]), float(self._x[i + 1] - self._x[i])
        a0 = 2.5 * B[0] - 2.0 * B[1] - 2.0 * B[2] + 2.5 * B[3]
        p, q = 3.75 * (B[1] - B[0]), 3.75 * (B[2] - B[3])
        r = 1.5 * (B[3] - B[0]) + 2.0 * (B[1] - B[2])
        u, w = 0.25 * (B[0] - B[1]), 0.25 * (B[2] - B[3])

        def G(xv):
            th = (math.pi / 2) * (xv - x0) / h_
            return (a0 * th - p * np.cos(th) + q * np.sin(th) + r * np.sin(2 * th) / 2
                    - u * np.cos(3 * th) / 3 + w * np.sin(3 * th) / 3)
        return (2.0 * h_ / math.pi) * (G(b) - G(a))

    def _integral_from_x0(self, h, xq, mode):
        """∫_{x0}^{xq} S for an array xq, with extrapolation."""
        x0, xn = float(self._x[0]), float(self._x[-1])
        xc = np.clip(xq, x0, xn)
        r = h.antiderivative(xc)
        lo = xq < x0
        if lo.any():
            r[lo] = -self._outside_integral(h, 0, xq[lo], np.full(lo.sum(), x0), mode)
        hi = xq > xn
        if hi.any():
            r[hi] = r[hi] + self._outside_integral(h, 1, np.full(hi.sum(), xn), xq[hi], mode)
        r[np.isnan(xq)] = np.nan
        return r

    def integrate(self, a: float, b: float, extrapolate: Extrapolate = None):
        """Definite integral of S over [a, b] (``PPoly.integrate``).

        Closed form inside the data (``ts_spline_integral``); outside by the
        extrapolation policy (``False``: NaN, as SciPy).  A float for one
        series, else an array of the series' shape.
        """
        mode = _mode(extrapolate, self._mode)
        a, b = to_float(a, "a"), to_float(b, "b")
        sign = 1.0
        if b < a:
            a, b, sign = b, a, -1.0
        res = []
        x0, xn = float(self._x[0]), float(self._x[-1])
        for h in self._h:
            if a != a or b != b:
                res.append(math.nan)
                continue
            v = 0.0
            ia, ib = max(a, x0), min(b, xn)
            if ia < ib:
                v += h.integral(ia, ib)
            if a < x0:
                v += float(self._outside_integral(h, 0, np.array([a]), np.array([min(b, x0)]),
                                                  mode)[0])
            if b > xn:
                v += float(self._outside_integral(h, 1, np.array([max(a, xn)]), np.array([b]),
                                                  mode)[0])
            res.append(sign * v)
        if len(self._h) == 1 and not self._pre and not self._trail:
            return res[0]
        return np.array(res).reshape(self._pre + self._trail)

    def integral(self, a: float, b: float) -> float:
        """Exact integral over [a, b] inside the data (``ts_spline_integral``); raises outside."""
        av, bv = to_float(a, "a"), to_float(b, "b")
        try:
            return self._h[0].integral(av, bv)
        except _core.LibraryError as e:
            if e.args[0] == _S.DOMAIN:
                raise TrigsplineError(_S.DOMAIN, "integral bounds a = %s, b = %s must lie in "
                                      "[%s, %s]" % (num(av), num(bv), num(self._x[0]),
                                                    num(self._x[-1]))) from None
            raise library_error(e) from None

    # ---- roots ------------------------------------------------------------
    def solve(self, y: float = 0.0, discontinuity: bool = True,
              extrapolate: Extrapolate = None) -> np.ndarray:
        """All x in [x0, xn] with S(x) = y, sorted (``PPoly.solve``).

        Exact per interval: the roots of the interval's trigonometric
        polynomial (a degree-6 polynomial in tan(θ/2)), isolated in Bernstein
        form and refined to rounding.  An interval on which S == y gives its
        left end followed by NaN, as SciPy.  Roots outside the data are not
        searched (``extrapolate`` is accepted for compatibility);
        ``discontinuity`` has no effect (S is continuous).  One series: an
        array; several: an object array of arrays of the series' shape.
        """
        yv = to_float(y, "y")
        if len(self._h) == 1 and not self._pre and not self._trail:
            return self._h[0].solve(yv)
        out = np.empty(len(self._h), dtype=object)
        for k, h in enumerate(self._h):
            out[k] = h.solve(yv)
        return out.reshape(self._pre + self._trail)

    def roots(self, discontinuity: bool = True, extrapolate: Extrapolate = None) -> np.ndarray:
        """The zeros of S (``solve(0)``)."""
        return self.solve(0.0, discontinuity, extrapolate)

    # ---- certificates -----------------------------------------------------
    @property
    def certified(self) -> bool:
        """True when every interval (of every series) of a shape-constrained
        spline is certified (False for shape='none': nothing was promised)."""
        return all(h.certified for h in self._h)

    def report(self):
        """One dict per interval (``ts_spline_report``, first series): x0, x1,
        alpha, beta, a, B, term (which rule chose β), has_lower/has_upper,
        gap_lower, at_lower, gap_upper, at_upper (exact minimum distance to
        each boundary and where), certified, and the overshoot: y_min,
        at_y_min, y_max, at_y_max (the curve's exact range on the interval and
        where), excursion_above, excursion_below (how far it leaves the range
        of the interval's two data values; docs/method.md §5.9)."""
        h = self._h[0]
        return [_report_dict(h.report(i)) for i in range(self._n)]

    def constraint_report(self):
        """Per constraint record (in the order of ``constraints=``), per
        interval (first series): ``None`` outside the record's scope, else a
        dict with ``active`` (it set α + β or changed a slope there), ``gap``
        (the exact minimum over the interval of S'' for 'convex', −S''
        'concave', S' 'increasing', S − bound 'lower', bound − S 'upper',
        S' − V 'slope-min', V − S' 'slope-max', V − |S'| 'slope-abs'), ``at``
        (where) and ``certified``; docs/method.md §13."""
        h = self._h[0] if self._h else None
        out = []
        for k in range(h.n_constraints if h is not None else 0):
            row = []
            for i in range(self._n):
                scope, active, gap, at, cert = h.constraint_report(k, i)
                row.append({"active": bool(active), "gap": gap, "at": at,
                            "certified": bool(cert)} if scope else None)
            out.append(row)
        return out

    def certify(self, lower=None, upper=None, *, report: bool = False):
        """Exact check that lower < S < upper on every interval (``ts_spline_certify``).

        lower/upper: (m, c) lines; with neither, the spline's own scheme lines
        (positive: y = 0).  Returns True/False, or (ok, list of report dicts)
        with ``report=True`` (first series)."""
        lo, up = _line(lower, "lower"), _line(upper, "upper")
        if lo is None and up is None:
            lo, up = self._lines
            if lo is None and up is None:
                raise ValueError("certify needs lower=(m, c) and/or upper=(m, c) (this spline "
                                 "has no boundary of its own: shape=%r)" % self._shape)
        ok_all, reps = True, None
        for h in self._h:
            try:
                ok, _, r = h.certify(lo, up)
            except _core.LibraryError as e:
                raise library_error(e, "certify: %s (lower = %r, upper = %r)"
                                    % (strerror(e.args[0]), lo, up)) from None
            ok_all = ok_all and ok
            if reps is None:
                reps = r
        if report:
            return ok_all, [_report_dict(r) for r in reps]
        return ok_all

    def error_bound(self, fprime_max: float, fsecond_max: float = math.inf,
                    exact_slopes: bool = False, per_interval: bool = False):
        """Bound on max|f - S| for any f through the data with max|f'| <=
        fprime_max (``ts_spline_error_bound``, first series); with
        ``per_interval=True`` also the array per interval."""
        try:
            b, per = self._h[0].error_bound(to_float(fprime_max, "fprime_max"),
                                            to_float(fsecond_max, "fsecond_max"),
                                            bool(exact_slopes))
        except _core.LibraryError as e:
            raise library_error(e) from None
        return (b, per) if per_interval else b


_options.document(Spline)


class Derivative:
    """The derivative of order ``nu`` of a Spline, a callable like SciPy's."""

    def __init__(self, spline: Spline, nu: int):
        self.spline, self.nu = spline, nu

    def __call__(self, x, nu: int = 0, extrapolate: Extrapolate = None, **kw):
        return self.spline(x, self.nu + nu, extrapolate, **kw)

    def derivative(self, nu: int = 1):
        return self.spline.derivative(self.nu + nu)

    def antiderivative(self, nu: int = 1):
        if nu > self.nu:
            return self.spline.antiderivative(nu - self.nu)
        raise NotImplementedError("the antiderivative of a derivative (it differs from the "
                                  "lower derivative by a constant): use "
                                  "spline.derivative(%d)" % (self.nu - nu))

    @property
    def x(self):
        return self.spline.x

    def __repr__(self):
        return "<trigspline.Derivative nu=%d of %r>" % (self.nu, self.spline)


class Antiderivative:
    """F(x) = ∫_{x0}^x S(t) dt of a Spline, a callable like SciPy's."""

    def __init__(self, spline: Spline):
        self.spline = spline

    def __call__(self, x, nu: int = 0, extrapolate: Extrapolate = None):
        if nu >= 1:
            return self.spline(x, nu - 1, extrapolate)
        sp = self.spline
        mode = _mode(extrapolate, sp._mode)
        xq = np.asarray(x, dtype=np.float64)
        xf = np.ascontiguousarray(xq.reshape(-1))
        res = np.stack([sp._integral_from_x0(h, xf, mode) for h in sp._h])
        if len(sp._h) == 1 and not sp._pre and not sp._trail:
            return res[0].reshape(xq.shape)
        a, b, q = len(sp._pre), len(sp._trail), xq.ndim
        r = res.reshape(sp._pre + sp._trail + xq.shape)
        order = list(range(a)) + list(range(a + b, a + b + q)) + list(range(a, a + b))
        return r.transpose(order)

    def derivative(self, nu: int = 1):
        return self.spline.derivative(nu - 1)

    @property
    def x(self):
        return self.spline.x

    def __repr__(self):
        return "<trigspline.Antiderivative of %r>" % (self.spline,)
