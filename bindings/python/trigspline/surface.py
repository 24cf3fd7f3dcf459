"""Surface: certified shape-preserving interpolation of gridded 2-D data
(docs/method.md §11), callable like SciPy's RegularGridInterpolator and
RectBivariateSpline."""
from typing import Any, Optional, Tuple

import numpy as np

from . import _core, _options
from ._options import FORMS, SLOPES, SURFACE_SHAPES
from ._util import WHERE_NAMES, float_array, is_scalar, num, to_float
from .errors import _S, TrigsplineError, library_error, strerror

ArrayLike = Any
Plane = Tuple[float, float, float]

_F8 = np.float64
REPORT_DTYPE = np.dtype([
    ("i", np.intp), ("j", np.intp), ("x0", _F8), ("x1", _F8), ("y0", _F8), ("y1", _F8),
    ("ax", _F8), ("ay", _F8), ("B", _F8, (4, 4)), ("has_lower", np.bool_),
    ("has_upper", np.bool_), ("proven_lower", _F8), ("sampled_lower", _F8),
    ("at_lower", _F8, (2,)), ("proven_upper", _F8), ("sampled_upper", _F8),
    ("at_upper", _F8, (2,)), ("certified", np.bool_)])


def _report_array(raw, nx, ny):
    """The rows of _core's report (patch (i, j) at j*nx + i) as a structured
    array indexed [i, j]."""
    out = np.empty(nx * ny, dtype=REPORT_DTYPE)
    for k, name in enumerate(("i", "j", "x0", "x1", "y0", "y1", "ax", "ay")):
        out[name] = raw[:, k]
    out["B"] = raw[:, 8:24].reshape(-1, 4, 4)
    out["has_lower"], out["has_upper"] = raw[:, 24] != 0, raw[:, 25] != 0
    out["proven_lower"], out["sampled_lower"] = raw[:, 26], raw[:, 27]
    out["at_lower"] = raw[:, 28:30]
    out["proven_upper"], out["sampled_upper"] = raw[:, 30], raw[:, 31]
    out["at_upper"] = raw[:, 32:34]
    out["certified"] = raw[:, 34] != 0
    return out.reshape(ny, nx).T


def _plane(value, what):
    """(p, q, c) from a number c or three numbers; None stays None."""
    if value is None:
        return None
    if is_scalar(value):
        return (0.0, 0.0, to_float(value, what))
    try:
        items = list(value)
    except TypeError:
        raise TypeError("%s must be a number or a plane (p, q, c) for z = p*x + q*y + c"
                        % what) from None
    if len(items) != 3:
        raise ValueError("%s must be a number or a plane (p, q, c) for z = p*x + q*y + c, "
                         "got %d values" % (what, len(items)))
    return tuple(to_float(v, "%s[%d]" % (what, k)) for k, v in enumerate(items))


def _grid(value, what):
    """(x, y, z) of a gridded field (docs/method.md §11.7), z[i, j] at
    (x[i], y[j]) as Surface's own z: an xarray DataArray with two coordinate
    dimensions (named x and y in any order, else the first is x), or a tuple
    (x, y, z) with z 2-D.  None when value is not grid-like (a number or a
    plane)."""
    if value is None or is_scalar(value):
        return None
    if hasattr(value, "dims") and hasattr(value, "coords"):
        if len(value.dims) != 2:
            raise ValueError("%s: a gridded field needs 2 dimensions, got %d %r"
                             % (what, len(value.dims), tuple(value.dims)))
        dims = tuple(value.dims)
        dx, dy = ("x", "y") if set(dims) == {"x", "y"} else dims
        for d in (dx, dy):
            if d not in value.coords:
                raise ValueError("%s: the dimension %r has no coordinate" % (what, d))
        x, y, z = value.coords[dx].values, value.coords[dy].values, value.transpose(dx, dy).values
    elif isinstance(value, (tuple, list)) and len(value) == 3 and np.ndim(value[2]) == 2:
        x, y, z = value
    else:
        return None
    xa, ya = float_array(x, what + " x", 1), float_array(y, what + " y", 1)
    za = float_array(z, what + " z")
    if za.shape != (xa.size, ya.size):
        raise TrigsplineError(_S.LENGTH, "%s: z has shape %r; a field on %d x values and %d y "
                              "values needs shape (%d, %d) (z[i, j] at (x[i], y[j]))" % (
                                  what, za.shape, xa.size, ya.size, xa.size, ya.size))
    return xa, ya, za


def _plane_text(pl):
    p, q, c = pl
    if p == 0 and q == 0:
        return "z = %s" % num(c)
    terms = []
    for coef, var in ((p, "x"), (q, "y")):
        if coef:
            terms.append("%s*%s" % (num(coef), var))
    if c:
        terms.append(num(c))
    return "z = " + " + ".join(terms).replace("+ -", "- ")


def _plane_at(pl, x, y):
    return pl[0] * x + pl[1] * y + pl[2]


def _field_at(g, x, y):
    """The bilinear value of field g = (x, y, z) at (x, y) (rounded; for
    messages)."""
    gx, gy, gz = g
    i = min(max(int(np.searchsorted(gx, x, side="right")) - 1, 0), gx.size - 2)
    j = min(max(int(np.searchsorted(gy, y, side="right")) - 1, 0), gy.size - 2)
    tx = (x - gx[i]) / (gx[i + 1] - gx[i])
    ty = (y - gy[j]) / (gy[j + 1] - gy[j])
    return ((1 - ty) * ((1 - tx) * gz[i, j] + tx * gz[i + 1, j]) +
            ty * ((1 - tx) * gz[i, j + 1] + tx * gz[i + 1, j + 1]))


def _axis_fault(t):
    """First index of t that is not finite or not above its predecessor
    (the order of the library's check), or None."""
    for i, v in enumerate(t):
        if not np.isfinite(v) or (i > 0 and not v > t[i - 1]):
            return i
    return None


def _points(xi):
    """Query points as an array (..., 2), with RegularGridInterpolator's
    conventions: a tuple of coordinate arrays is broadcast; a 1-D array is
    read as consecutive (x, y) pairs."""
    if isinstance(xi, tuple) and len(xi) == 1:
        xi = xi[0]
    if isinstance(xi, tuple):
        if len(xi) != 2:
            raise ValueError("the requested sample points have dimension %d but this Surface "
                             "has dimension 2" % len(xi))
        try:
            xs, ys = np.broadcast_arrays(float_array(xi[0], "xi[0]"),
                                         float_array(xi[1], "xi[1]"))
        except ValueError:
            raise ValueError("the coordinate arrays xi[0], xi[1] cannot be broadcast "
                             "together") from None
        return np.stack([xs, ys], axis=-1)
    pts = float_array(xi, "points")
    if pts.ndim == 0:
        raise ValueError("points must have shape (..., 2), got a scalar")
    if pts.ndim == 1:
        if pts.size % 2:
            raise ValueError("a 1-D points array is read as (x, y) pairs; got %d values"
                             % pts.size)
        pts = pts.reshape(-1, 2)
    if pts.shape[-1] != 2:
        raise ValueError("the requested sample points have dimension %d but this Surface has "
                         "dimension 2 (points must have shape (..., 2))" % pts.shape[-1])
    return pts


def _rebuild(state):
    """Unpickling: a Surface from its inputs (see Surface.__reduce__)."""
    return Surface(state["x"], state["y"], state["z"], **state["kwargs"])


class Surface:
    """The certified trigonometric surface through z[i, j] at (x[i], y[j]).

    The tensor product of the 1-D spline (docs/method.md §11): 16 control
    values per patch, one shape parameter per column and per row of patches,
    chosen by the shape scheme so that every patch is proven inside its
    region (never below zero, inside constant bounds, between two planes, or
    inside the data's own range).  Called like SciPy's
    :class:`~scipy.interpolate.RegularGridInterpolator` (``s(points)``) and
    :class:`~scipy.interpolate.RectBivariateSpline` (``s(x, y, grid=True)``).

    Parameters
    ----------
    x : array_like, shape (nx,)
        Strictly increasing grid coordinates (non-uniform allowed), nx >= 2.
        ``Surface((x, y), z)`` (RegularGridInterpolator's order) works too.
    y : array_like, shape (ny,)
        Strictly increasing, ny >= 2.
    z : array_like, shape (nx, ny)
        ``z[i, j]`` is the value at ``(x[i], y[j])``, as RegularGridInterpolator's
        ``values``.  A Fortran-ordered float64 array goes to C without a copy.
    The keywords and their defaults are the package's one vocabulary
    (docs/options.md); the defaults are the library's
    (``ts_surface_options_init``).

    shape : {'none', 'positive', 'bounds', 'planes', 'range', 'grids'}, default inferred
        The region (docs/method.md §11.3): ``'positive'`` S >= 0 (zeros in
        the data allowed); ``'bounds'`` constant ``lower <= S <= upper`` (either
        side; the data may touch them, e.g. 0 and 100 for percentages);
        ``'planes'`` ``lower < S < upper`` for planes (sloped planes need
        ``form='geometric'``, where they are exact); ``'range'``
        ``min(z) <= S <= max(z)`` (no overshoot); ``'grids'``
        ``lower(x, y) < S < upper(x, y)`` for gridded fields (docs/method.md
        §11.7); ``'none'``: no promise.
        Left out, it follows from the bounds: ``lower=0`` alone
        ``'positive'``, other constants ``'bounds'``, a sloped plane
        ``'planes'``, neither ${shape}.
    lower, upper : float, (p, q, c) or a gridded field, default none
        The bounds of ``'bounds'`` (numbers) and ``'planes'`` (a number c or
        the plane z = p x + q y + c); for ``'grids'`` (inferred) a field on
        a grid of its own, bilinear between its nodes: ``(xf, yf, zf)`` with
        ``zf[i, j]`` at ``(xf[i], yf[j])``, or an xarray ``DataArray`` with
        two coordinate dimensions (named ``x`` and ``y``, else the first is
        x).  Its grid must cover the surface's (it is not extended); every
        node must be strictly between the fields (decided exactly).
    form : {'paper', 'c1', 'geometric'}, default ${form}
        docs/method.md §11.2: the paper form is continuous; ``'c1'`` and
        ``'geometric'`` are C¹, the geometric form reproduces planes (and
        bilinear data) exactly.
    slopes : str, default ${slopes}
        The 1-D slope method applied along every grid line (docs/method.md
        §6): ``'arithmetic'``, ``'geometric'``, ``'harmonic'``,
        ``'fritsch-carlson'``, ``'akima'``, ``'makima'``, ``'steffen'``
        (much less overshoot on the data/surface fields: 0.1–0.3 % of the
        range with ``alpha=0.85`` against 7–16 % at the defaults, but not
        PCHIP's 1-D promise; CHANGELOG).
    alpha : float, default ${alpha}
        Lower bound on every shape parameter a; with ``shape='none'`` a =
        alpha + beta.
    beta : float, default ${beta}
        ``shape='none'`` only.
    margin : float, default ${margin}
        The margin t of docs/method.md §5.
    zero_twist : bool, default ${zero_twist}
        Cross slopes r = 0 instead of the estimate (docs/method.md §11.1).
    extrapolate : {'error', 'nan', False}, default ${extrapolate}
        A query outside the grid raises (``'error'``) or gets ``fill_value``
        (``'nan'``).  NaN queries give NaN either way.
    bounds_error : bool, default True
        RegularGridInterpolator's spelling of ``extrapolate``: ``True`` is
        ``'error'``, ``False`` ``'nan'``.
    fill_value : float, default nan
        The value outside the grid under ``extrapolate='nan'``.  ``None``
        (SciPy's extrapolation) is not offered: the surface and its
        certificate live on the grid.

    Raises
    ------
    TrigsplineError
        A ``ValueError`` naming the node (``.node = (i, j)``), the patch
        (``.patch = (i, j)``) or the grid coordinate (``.where = 'x'`` or
        ``'y'``, ``.index``) at fault.

    Notes
    -----
    A Surface is immutable and can be shared between threads; the GIL is
    released while it is built, evaluated, integrated and certified.
    ``copy``, ``deepcopy`` and ``pickle`` rebuild it from its inputs
    (bit-identical values).
    """

    def __init__(self, x: ArrayLike, y: ArrayLike, z: ArrayLike = None, *,
                 shape: Optional[str] = None, lower: Any = None, upper: Any = None,
                 form: Optional[str] = None, slopes: Optional[str] = None,
                 alpha: Optional[float] = None, beta: Optional[float] = None,
                 margin: Optional[float] = None, zero_twist: Optional[bool] = None,
                 extrapolate: Any = None, bounds_error: Optional[bool] = None,
                 fill_value: Optional[float] = np.nan) -> None:
        if z is None:
            if isinstance(x, (tuple, list)) and len(x) == 2 and np.ndim(x[0]) == 1:
                x, y, z = x[0], x[1], y  # RegularGridInterpolator((x, y), z)
            else:
                raise TypeError("Surface(x, y, z) or Surface((x, y), z): z is missing")
        xa, ya, za = float_array(x, "x", 1), float_array(y, "y", 1), float_array(z, "z")
        if za.shape != (xa.size, ya.size):
            hint = ""
            if za.ndim == 2 and za.shape == (ya.size, xa.size):
                hint = "; z[i, j] is the value at (x[i], y[j]): pass z.T"
            elif za.ndim > 2:
                hint = "; one value per node (build one Surface per component)"
            raise TrigsplineError(_S.LENGTH, "z has shape %r; a grid of %d x values and %d y "
                                  "values needs shape (%d, %d)%s" % (
                                      za.shape, xa.size, ya.size, xa.size, ya.size, hint))
        ext = _options.extrapolate(extrapolate, "surface", ("error", "nan"))
        if bounds_error is not None:
            if extrapolate is not None and (ext == "error") != bool(bounds_error):
                raise ValueError("bounds_error=%r contradicts extrapolate=%r"
                                 % (bounds_error, extrapolate))
            ext = "error" if bounds_error else "nan"
        zero_twist = _options.flag("surface", "zero_twist", zero_twist)
        form = _options.enum("surface", "form", form, FORMS)
        glo, gup = _grid(lower, "lower"), _grid(upper, "upper")
        if glo is not None or gup is not None:
            for what, g, v in (("lower", glo, lower), ("upper", gup, upper)):
                if g is None and v is not None:
                    raise ValueError("%s: with a gridded field on the other side, give a field "
                                     "here too (or None)" % what)
            if shape is None:
                shape = "grids"
            lo = up = None
        else:
            lo, up = _plane(lower, "lower"), _plane(upper, "upper")
        shp = _options.name(SURFACE_SHAPES, _options.infer_shape(shape, lo, up, "surface"),
                            "shape")
        if shape is None and shp == "positive":
            lo = None  # lower=0 alone: the positive scheme's own bound
        opts = {"shape": SURFACE_SHAPES.index(shp), "zero_twist": zero_twist,
                "form": FORMS.index(form)}
        kwargs = {"shape": shp, "zero_twist": zero_twist, "extrapolate": ext, "form": form}
        form_index = opts["form"]
        sl = _options.enum("surface", "slopes", slopes, SLOPES)
        if sl in ("user", "periodic"):
            raise ValueError("slopes=%r is not offered for surfaces (the slopes are "
                             "estimated along every grid line)" % slopes)
        opts["slopes"] = SLOPES.index(sl)
        kwargs["slopes"] = sl
        for name, value in (("alpha", alpha), ("beta", beta), ("margin", margin)):
            if name == "beta" and shp != "none":
                if value is None or to_float(value, name) == 0.0:
                    continue
                raise ValueError("beta is chosen by the shape scheme (shape=%r); leave it out "
                                 "and set alpha and margin instead" % shp)
            v = to_float(_options.option("surface", name, value), name)
            opts[name] = kwargs[name] = v
        if shp == "grids":
            if glo is None and gup is None:
                raise ValueError("shape='grids' needs lower= and/or upper= as gridded fields: "
                                 "(x, y, z) or an xarray DataArray")
            for key, g in (("lower", glo), ("upper", gup)):
                if g is not None:
                    zt = g[2].T if g[2].T.flags.c_contiguous else np.ascontiguousarray(g[2].T)
                    opts[key + "_grid"] = (g[0], g[1], zt)
                    kwargs[key] = (g[0], g[1], g[2])
        elif glo is not None or gup is not None:
            raise ValueError("gridded fields go with shape='grids', not %r" % shp)
        elif shp in ("bounds", "planes"):
            if lo is None and up is None:
                raise ValueError("shape=%r needs lower= and/or upper=" % shp)
            for what, pl in (("lower", lo), ("upper", up)):
                if pl is None or (pl[0] == 0.0 and pl[1] == 0.0):
                    continue
                if shp == "bounds":
                    raise ValueError("shape='bounds' takes constants; %s = %s is a sloped "
                                     "plane: use shape='planes' with form='geometric'"
                                     % (what, _plane_text(pl)))
                if FORMS[form_index] != "geometric":
                    raise ValueError("the sloped plane %s = %s needs form='geometric' (where "
                                     "planes are exact, docs/method.md §11.2); the %s form "
                                     "takes constant bounds only" % (what, _plane_text(pl),
                                                                     FORMS[form_index]))
            opts["lower"], opts["upper"] = lo, up
            if lo is not None:
                kwargs["lower"] = lo if shp == "planes" else lo[2]
            if up is not None:
                kwargs["upper"] = up if shp == "planes" else up[2]
        elif lo is not None or up is not None:
            raise ValueError("lower and upper go with shape='bounds' or 'planes', not %r" % shp)
        if fill_value is None:
            raise ValueError("fill_value=None (extrapolation outside the grid) is not offered: "
                             "the surface and its certificate are defined on the grid; give a "
                             "number")
        self._fill = to_float(fill_value, "fill_value")
        kwargs["fill_value"] = self._fill
        self._mode = _core.SURF_ERROR if ext == "error" else _core.SURF_FILL
        self._kwargs = kwargs
        self._shape = shp
        self._fields = (glo, gup)
        if shp == "positive":
            self._bounds = ((0.0, 0.0, 0.0), None)
        elif shp == "range":
            self._bounds = ((0.0, 0.0, float(np.min(za))), (0.0, 0.0, float(np.max(za))))
        elif shp == "grids":
            self._bounds = (glo, gup)
        else:
            self._bounds = (lo, up)
        zt = za.T if za.T.flags.c_contiguous else np.ascontiguousarray(za.T)
        try:
            self._h = _core.surface_new(xa, ya, zt, **opts)
        except _core.LibraryError as e:
            raise self._build_error(e, xa, ya, za, opts) from None
        self._nx, self._ny = self._h.patches
        self._x, self._y = self._h.x, self._h.y

    # ---- errors -----------------------------------------------------------
    def _build_error(self, e, x, y, z, opts):
        st, index, w = e.args
        where = WHERE_NAMES[w] if 0 <= w < len(WHERE_NAMES) else None
        base = strerror(st)
        lo, up = self._bounds if self._shape != "grids" else (None, None)
        if st == _S.TOO_FEW:
            return TrigsplineError(st, "too few grid values: %d x values and %d y values; a "
                                   "surface needs at least 2 of each" % (x.size, y.size))
        if where == "point" and st in (_S.NONFINITE, _S.UNSORTED):
            for name, t in (("x", x), ("y", y)):
                k = _axis_fault(t)
                if k is None:
                    continue
                if not np.isfinite(t[k]):
                    msg = "%s[%d] = %s: grid coordinates must be finite" % (name, k, num(t[k]))
                else:
                    msg = ("%s[%d] = %s is not greater than %s[%d] = %s: %s must be strictly "
                           "increasing" % (name, k, num(t[k]), name, k - 1, num(t[k - 1]),
                                           name))
                return TrigsplineError(st, msg, k, name)
        if where == "point" and index is not None:
            i, j = index % x.size, index // x.size
            xi, yj, v = x[i], y[j], z[i, j]
            loc = "node (%d, %d) at (x = %s, y = %s)" % (i, j, num(xi), num(yj))
            if st == _S.NONFINITE:
                if not np.isfinite(v):
                    msg = "%s has z = %s: every value must be finite" % (loc, num(v))
                else:
                    msg = "%s (z = %s): a slope or twist there overflows (values too large " \
                          "for the spacing)" % (loc, num(v))
            elif st == _S.NEGATIVE:
                msg = "%s has z = %s < 0: the positive scheme needs z >= 0" % (loc, num(v))
            elif st == _S.SIDE and self._shape == "grids":
                glo, gup = self._fields
                side = "lower" if glo is not None and (gup is None or v <= _field_at(glo, xi, yj)) \
                    else "upper"
                msg = "%s (z = %s) is not strictly %s the %s field, whose value there is %s" % (
                    loc, num(v), "above" if side == "lower" else "below", side,
                    num(_field_at(glo if side == "lower" else gup, xi, yj)))
            elif st == _S.SIDE:
                if lo is not None and (v < _plane_at(lo, xi, yj) or
                                       (self._shape == "planes" and
                                        not v > _plane_at(lo, xi, yj))):
                    side, pl = "lower", lo
                else:
                    side, pl = "upper", up
                if self._shape == "bounds":
                    rel = "below" if side == "lower" else "above"
                    msg = "%s has z = %s %s the %s bound %s" % (loc, num(v), rel, side,
                                                                 num(pl[2]))
                else:
                    msg = "%s lies on or across the %s plane %s (z = %s, plane value %s)" % (
                        loc, side, _plane_text(pl), num(v), num(_plane_at(pl, xi, yj)))
            elif st == _S.LINES and lo is not None and up is not None:
                msg = "%s: the lower plane %s (%s) is not strictly below the upper plane %s " \
                      "(%s)" % (loc, _plane_text(lo), num(_plane_at(lo, xi, yj)),
                                _plane_text(up), num(_plane_at(up, xi, yj)))
            else:
                msg = "%s: %s" % (loc, base)
            return TrigsplineError(st, msg, (i, j), "node", node=(i, j))
        if where == "interval" and index is not None:
            nx = x.size - 1
            i, j = index % nx, index // nx
            loc = "patch (%d, %d) [%s, %s] x [%s, %s]" % (i, j, num(x[i]), num(x[i + 1]),
                                                           num(y[j]), num(y[j + 1]))
            if st == _S.NONFINITE:
                msg = "%s: a control value overflows (values too large for the shape " \
                      "parameter)" % loc
            elif st == _S.UNPROVEN and self._shape == "grids":
                msg = "%s: not proven strictly between the gridded fields, even with the " \
                      "shape parameters raised tenfold 12 times (a field may bulge past the " \
                      "data between their nodes)" % loc
            else:
                msg = "%s: %s" % (loc, base)
            return TrigsplineError(st, msg, (i, j), "patch", patch=(i, j))
        if st == _S.BOUND_GRID:
            side = "upper" if index == 1 else "lower"
            g = self._fields[1 if index == 1 else 0]
            if g is not None:
                gx, gy, _ = g
                msg = "the %s field on [%s, %s] x [%s, %s]" % (
                    side, num(gx[0]), num(gx[-1]), num(gy[0]), num(gy[-1])) \
                    if gx.size and gy.size else "the %s field" % side
                if gx.size >= 2 and gy.size >= 2 and _axis_fault(gx) is None and \
                        _axis_fault(gy) is None and not (gx[0] <= x[0] and x[-1] <= gx[-1] and
                                                         gy[0] <= y[0] and y[-1] <= gy[-1]):
                    msg += " does not cover the surface's grid [%s, %s] x [%s, %s] (a field " \
                           "is not extended)" % (num(x[0]), num(x[-1]), num(y[0]), num(y[-1]))
                else:
                    msg += ": at least 2 x 2 nodes, finite strictly increasing coordinates and " \
                           "finite values of at most 2**1022 in magnitude are needed"
                return TrigsplineError(st, "%s: %s" % (msg, base), index, side)
        if st == _S.LINES and self._shape == "grids":
            return TrigsplineError(st, "the upper field is not above the lower field everywhere "
                                   "on the surface's grid (by more than their rounding): %s"
                                   % base)
        detail = {_S.ALPHA: "alpha = %s must be > 0" % num(opts.get("alpha")),
                  _S.BETA: "beta = %s must be >= 0" % num(opts.get("beta")),
                  _S.MARGIN: "margin = %s must be > 0" % num(opts.get("margin")),
                  _S.LINES: "the lower bound %s is not below the upper bound %s" % (
                      num(lo[2]) if lo else "-", num(up[2]) if up else "-"),
                  _S.NONFINITE: "the bounds must be finite (lower = %r, upper = %r)" % (lo, up)}
        msg = detail.get(st)
        return TrigsplineError(st, "%s: %s" % (msg, base) if msg else base)

    def _outside(self, what, k, v, lim):
        return TrigsplineError(_S.DOMAIN, "%s = %s lies outside [%s, %s] (extrapolate='error'; "
                               "extrapolate='nan' gives fill_value)" % (
                                   what, v, num(lim[0]), num(lim[1])), k, "query")

    # ---- pickling and copies: rebuilt from the inputs -----------------------
    def __reduce__(self):
        return (_rebuild, ({"x": np.array(self._x), "y": np.array(self._y),
                            "z": np.array(self.values), "kwargs": dict(self._kwargs)},))

    def __repr__(self):
        return "<trigspline.Surface %d x %d patches on [%s, %s] x [%s, %s], shape=%r, " \
               "form=%r>" % (self._nx, self._ny, num(self._x[0]), num(self._x[-1]),
                             num(self._y[0]), num(self._y[-1]), self._shape, self.form)

    # ---- evaluation ---------------------------------------------------------
    @staticmethod
    def _nu(nu):
        try:
            d = tuple(int(v) for v in nu)
        except TypeError:
            raise TypeError("nu must be a pair of derivative orders (in x, in y)") from None
        if d not in ((0, 0), (1, 0), (0, 1)):
            raise ValueError("nu = %r: the surface offers the value and the first partials, "
                             "nu = (0, 0), (1, 0) or (0, 1)" % (nu,))
        return 0 if d == (0, 0) else (1 if d == (1, 0) else 2)

    def _batch(self, xs, ys, partials, labels=None):
        """ts_surface_eval_batch at the pairs (xs[k], ys[k]) (1-D arrays)."""
        try:
            return self._h.eval(xs, ys, partials, self._mode, self._fill)
        except _core.LibraryError as e:
            st, k, _ = e.args
            if st == _S.DOMAIN and k is not None:
                msg = "%s (x = %s, y = %s)" % (labels(k) if labels else "point %d" % k,
                                               num(xs[k]), num(ys[k]))
                raise TrigsplineError(_S.DOMAIN, "%s lies outside the grid [%s, %s] x [%s, %s] "
                                      "(extrapolate='error'; extrapolate='nan' gives "
                                      "fill_value)" % (msg, num(self._x[0]), num(self._x[-1]),
                                                       num(self._y[0]), num(self._y[-1])),
                                      k, "query") from None
            raise library_error(e) from None

    def _evaluate(self, xi, yi, grid, d):
        """(results tuple, shape): the value (d = 0) or all three (d > 0)."""
        if yi is None:
            pts = _points(xi)
            flat = pts.reshape(-1, 2)
            shape = pts.shape[:-1]

            def label(k):  # one point (shape ()) has no index
                if not shape:
                    return "point"
                return "point %r" % (tuple(int(v) for v in np.unravel_index(k, shape)),)
            return self._batch(flat[:, 0], flat[:, 1], d > 0, label), shape
        xq, yq = float_array(xi, "x"), float_array(yi, "y")
        if grid:
            if xq.ndim > 1 or yq.ndim > 1:
                raise ValueError("grid=True takes 1-D x and y (got shapes %r and %r); use "
                                 "grid=False for pointwise pairs" % (xq.shape, yq.shape))
            xq, yq = np.atleast_1d(xq), np.atleast_1d(yq)
            shape = (xq.size, yq.size)
            if d == 0:
                try:
                    return self._h.eval_grid(xq, yq, self._mode, self._fill).T, shape
                except _core.LibraryError as e:
                    st, k, _ = e.args
                    if st == _S.DOMAIN and k is not None:
                        if k < xq.size:
                            raise self._outside("x[%d]" % k, k, num(xq[k]),
                                                (self._x[0], self._x[-1])) from None
                        b = k - xq.size
                        raise self._outside("y[%d]" % b, b, num(yq[b]),
                                            (self._y[0], self._y[-1])) from None
                    raise library_error(e) from None
            X, Y = np.meshgrid(xq, yq, indexing="ij")
        else:
            try:
                X, Y = np.broadcast_arrays(xq, yq)
            except ValueError:
                raise ValueError("x of shape %r and y of shape %r cannot be broadcast together"
                                 % (xq.shape, yq.shape)) from None
            shape = X.shape
        return self._batch(X.reshape(-1), Y.reshape(-1), d > 0), shape

    def __call__(self, xi: ArrayLike, yi: ArrayLike = None, *, grid: bool = True,
                 nu: Tuple[int, int] = (0, 0)) -> np.ndarray:
        """Values (or a first partial) of the surface.

        Parameters
        ----------
        xi : array_like
            With ``yi`` left out, the points as RegularGridInterpolator takes
            them: an array of shape ``(..., 2)`` (a 1-D array is read as
            consecutive (x, y) pairs), or a tuple ``(X, Y)`` of coordinate
            arrays broadcast together (e.g. from ``np.meshgrid``).  With
            ``yi``: the x coordinates, as RectBivariateSpline.
        yi : array_like, optional
            The y coordinates (RectBivariateSpline's ``s(x, y, grid=True)``).
        grid : bool
            With ``yi``: ``True`` (default, as RectBivariateSpline) evaluates
            on the grid ``x × y`` (1-D arrays, any order; ``ts_surface_eval_grid``),
            ``False`` at the pairs of the broadcast ``x`` and ``y``.
        nu : (int, int)
            ``(0, 0)`` values; ``(1, 0)`` ∂S/∂x; ``(0, 1)`` ∂S/∂y.

        Returns
        -------
        ndarray
            Shape ``points.shape[:-1]`` (RegularGridInterpolator), ``(len(x),
            len(y))`` on a grid, or the broadcast shape of ``x`` and ``y``.
            NaN coordinates give NaN; outside the grid see ``extrapolate``.

        Raises
        ------
        TrigsplineError
            ``extrapolate='error'`` and a query outside the grid (named).
        """
        d = self._nu(nu)
        res, shape = self._evaluate(xi, yi, grid, d)
        return (res if d == 0 else res[d]).reshape(shape)

    def partials(self, xi: ArrayLike, yi: ArrayLike = None, *, grid: bool = True):
        """(z, ∂z/∂x, ∂z/∂y) at the queries (the conventions of ``__call__``),
        from one ``ts_surface_eval_batch`` call."""
        res, shape = self._evaluate(xi, yi, grid, 1)
        return tuple(r.reshape(shape) for r in res)

    def integral(self, xa: float, xb: float, ya: float, yb: float) -> float:
        """∫∫ S over [xa, xb] × [ya, yb] (``ts_surface_integral``: closed form
        per patch in the paper and c1 forms, Gauss–Legendre exact to rounding
        in the geometric form, docs/method.md §11.5).  The limits must lie on
        the grid; reversed limits give the sign."""
        lim = [to_float(v, n) for v, n in ((xa, "xa"), (xb, "xb"), (ya, "ya"), (yb, "yb"))]
        try:
            return self._h.integral(*lim)
        except _core.LibraryError as e:
            if e.args[0] == _S.DOMAIN:
                raise TrigsplineError(_S.DOMAIN, "integral limits x in [%s, %s], y in [%s, %s] "
                                      "must lie on the grid [%s, %s] x [%s, %s]" % (
                                          num(lim[0]), num(lim[1]), num(lim[2]), num(lim[3]),
                                          num(self._x[0]), num(self._x[-1]), num(self._y[0]),
                                          num(self._y[-1]))) from None
            raise library_error(e) from None

    # ---- certificates -------------------------------------------------------
    @property
    def certified(self) -> bool:
        """True when a shape scheme was applied and every patch is proven
        inside its region (False for shape='none': nothing was promised)."""
        return bool(self._h.certified)

    def report(self) -> np.ndarray:
        """The certificate of every patch against the scheme's own bounds
        (``ts_surface_report``, docs/method.md §11.4).

        Returns
        -------
        ndarray, shape (nx, ny), dtype REPORT_DTYPE
            ``r[i, j]`` for the patch ``[x[i], x[i+1]] × [y[j], y[j+1]]``, with
            fields ``i``, ``j``, ``x0``, ``x1``, ``y0``, ``y1``, ``ax``, ``ay``,
            ``B`` (the 16 control values, ``B[k, l]`` with k along x),
            ``has_lower``, ``has_upper``, ``proven_lower`` (a proven lower
            bound on S − lower over the patch), ``sampled_lower`` (the least
            sampled gap, a true value) and ``at_lower`` (its (x, y)), the same
            for ``upper`` (upper − S), and ``certified``.  Absent bounds are
            NaN.  E.g. ``r["proven_lower"].min()``.
        """
        return _report_array(self._h.report(), self._nx, self._ny)

    def certify(self, lower: Any = None, upper: Any = None, *, report: bool = False):
        """Prove ``lower <= S <= upper`` patch by patch (``ts_surface_certify``).

        Parameters
        ----------
        lower, upper : float or (p, q, c), optional
            Constants or planes z = p x + q y + c, any form; with neither, the
            surface's own bounds (positive: 0; range: the data's min and max).
        report : bool
            Also return the per-patch reports (as ``report()``).

        Returns
        -------
        bool, or (bool, ndarray)
        """
        lo, up = _plane(lower, "lower"), _plane(upper, "upper")
        if lo is None and up is None and self._shape == "grids":
            rep = self.report()  # against the surface's own fields (§11.7)
            ok = bool(rep["certified"].all())
            return (ok, rep) if report else ok
        if lo is None and up is None:
            lo, up = self._bounds
            if lo is None and up is None:
                raise ValueError("certify needs lower= and/or upper= (this surface has no "
                                 "bound of its own: shape='none')")
        try:
            ok, _, raw = self._h.certify(lo, up)
        except _core.LibraryError as e:
            raise library_error(e, "certify: %s (lower = %r, upper = %r)"
                                % (strerror(e.args[0]), lo, up)) from None
        if report:
            return bool(ok), _report_array(raw, self._nx, self._ny)
        return bool(ok)

    # ---- accessors ----------------------------------------------------------
    def _nodes(self, flat):
        return flat.reshape(self._ny + 1, self._nx + 1).T

    @property
    def x(self) -> np.ndarray:
        """Grid x, shape (nx+1,) (read-only)."""
        return self._x

    @property
    def y(self) -> np.ndarray:
        """Grid y, shape (ny+1,) (read-only)."""
        return self._y

    @property
    def grid(self) -> Tuple[np.ndarray, np.ndarray]:
        """``(x, y)``, as RegularGridInterpolator's ``grid``."""
        return (self._x, self._y)

    @property
    def values(self) -> np.ndarray:
        """The data z, shape (len(x), len(y)) (a read-only view)."""
        return self._nodes(self._h.z)

    @property
    def dzdx(self) -> np.ndarray:
        """The partial slopes ∂z/∂x used at the nodes (after the scheme), shape
        of ``values`` (read-only)."""
        return self._nodes(self._h.dzdx)

    @property
    def dzdy(self) -> np.ndarray:
        """The partial slopes ∂z/∂y used at the nodes, shape of ``values``."""
        return self._nodes(self._h.dzdy)

    @property
    def twist(self) -> np.ndarray:
        """The twists (cross slopes) r used at the nodes, shape of ``values``."""
        return self._nodes(self._h.twist)

    @property
    def ax(self) -> np.ndarray:
        """a^x per column of patches, shape (len(x) - 1,) (read-only)."""
        return self._h.ax

    @property
    def ay(self) -> np.ndarray:
        """a^y per row of patches, shape (len(y) - 1,) (read-only)."""
        return self._h.ay

    @property
    def patches(self) -> Tuple[int, int]:
        """(len(x) - 1, len(y) - 1)."""
        return (self._nx, self._ny)

    @property
    def form(self) -> str:
        return FORMS[self._h.form]

    @property
    def shape(self) -> str:
        return self._shape

    @property
    def bounds(self):
        """(lower, upper) of the scheme as planes (p, q, c), or None; for
        ``shape='grids'`` the fields as arrays (x, y, z), z[i, j] at
        (x[i], y[j])."""
        return self._bounds

    @property
    def extrapolate(self) -> str:
        """'error' or 'nan' (fill_value) outside the grid."""
        return "error" if self._mode == _core.SURF_ERROR else "nan"

    @property
    def bounds_error(self) -> bool:
        return self._mode == _core.SURF_ERROR

    @property
    def fill_value(self) -> float:
        return self._fill

    def control(self, i: int, j: int):
        """(B, X, Y) of patch (i, j): the 16 control values ``B[k, l]`` (k
        along x) and the control abscissae in x and y (``ts_surface_control``)."""
        i, j = int(i), int(j)
        if not (0 <= i < self._nx and 0 <= j < self._ny):
            raise TrigsplineError(_S.INDEX, "patch (%d, %d) does not exist (%d x %d patches)"
                                  % (i, j, self._nx, self._ny), (i, j), "patch", patch=(i, j))
        return self._h.control(i, j)


_options.document(Surface, "surface")
