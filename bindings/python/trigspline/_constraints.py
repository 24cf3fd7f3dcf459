"""Constraint records (docs/method.md §13): ``constraints=[...]`` of Spline,
``interp``, the xarray accessors and ``pandas.interpolate``.

Each item is a SPEC string, the command line's ``--constraint`` syntax
(docs/cli.md): ``'convex'``, ``'concave'``, ``'increasing'``, ``'decreasing'``,
``'lower=C'``, ``'upper=C'``, ``'lower=poly:X,Y;X,Y;...'``, ``'slope>=V'``,
``'slope<=V'``, ``'abs-slope<=V'`` (also ``'slope-min=V'``, ``'slope-max=V'``,
``'slope-abs=V'``), optionally followed by ``'@I0-I1'`` (intervals); or a dict
``{"kind": K, "value": V, "points": [(x, y), ...], "first": I, "count": N}``
with K a name of the library's vocabulary ``constraint``; a lower or upper
bound given by another spline (docs/method.md §13.7) is the dict
``{"kind": "lower", "spline": B}`` with B a one-dimensional ``Spline`` (any
form, its own knots; the fitted spline keeps its own copy of B).
"""
import numpy as np

from . import _core

KINDS = _core.vocab(_core.VOCAB_CONSTRAINT)

_OPS = (("slope>=", "slope-min"), ("slope<=", "slope-max"), ("abs-slope<=", "slope-abs"),
        ("|slope|<=", "slope-abs"), ("slope-min=", "slope-min"), ("slope-max=", "slope-max"),
        ("slope-abs=", "slope-abs"), ("lower=", "lower"), ("upper=", "upper"))


def _scope(text):
    a, dash, b = text.partition("-")
    try:
        first = int(a)
        if not dash:
            return first, 1
        if b == "":
            return first, 0
        last = int(b)
    except ValueError:
        raise ValueError("constraint scope @%s is not I0-I1 (interval indices)" % text) from None
    if last < first or first < 0:
        raise ValueError("constraint scope @%s is not I0-I1 (interval indices)" % text)
    return first, last - first + 1


def _points(pts, what):
    arr = np.asarray(pts, dtype=np.float64)
    if arr.ndim != 2 or arr.shape[1] != 2:
        raise ValueError("%s: points must be pairs (x, y)" % what)
    return np.ascontiguousarray(arr[:, 0]), np.ascontiguousarray(arr[:, 1])


def _bound_handle(b, kind):
    """The library spline of a bound Spline B (one series, one dimension)."""
    hs = getattr(b, "_h", None)
    if not isinstance(hs, list) or len(hs) != 1 or getattr(b, "_pre", None) != () or \
            getattr(b, "_trail", None) != ():
        raise TypeError("constraint %r: \"spline\" must be a trigspline Spline of one series "
                        "(1-D f), not %r" % (kind, type(b).__name__))
    return hs[0]


def record(item):
    """One item as the tuple _core.spline_new takes: (kind, value, px, py, first, count)."""
    if isinstance(item, dict):
        unknown = set(item) - {"kind", "value", "points", "spline", "first", "count"}
        if unknown:
            raise ValueError("unknown constraint keys %s" % sorted(unknown))
        kind = item.get("kind")
        if kind not in KINDS:
            raise ValueError("constraint kind %r is not one of %s" % (kind, ", ".join(KINDS)))
        px = py = None
        if item.get("points") is not None:
            px, py = _points(item["points"], "constraint %r" % kind)
        if item.get("spline") is not None:
            if kind not in ("lower", "upper") or px is not None:
                raise ValueError("constraint %r: \"spline\" is a bound (lower or upper), "
                                 "without \"points\"" % kind)
            px = _bound_handle(item["spline"], kind)
        return (KINDS.index(kind), float(item.get("value", 0.0)), px, py,
                int(item.get("first", 0)), int(item.get("count", 0)))
    if not isinstance(item, str):
        raise TypeError("a constraint is a SPEC string or a dict, not %r" % (item,))
    spec, at, scope = item.strip().partition("@")
    first, count = _scope(scope) if at else (0, 0)
    if spec in KINDS[:4]:
        return (KINDS.index(spec), 0.0, None, None, first, count)
    for pre, kind in _OPS:
        if spec.startswith(pre):
            val = spec[len(pre):]
            if kind in ("lower", "upper") and val.startswith("poly:"):
                try:
                    pts = [tuple(float(v) for v in p.split(",")) for p in val[5:].split(";")]
                except ValueError:
                    raise ValueError("constraint %r: not a polyline X,Y;X,Y;..." % item) from None
                px, py = _points(pts, "constraint %r" % item)
                return (KINDS.index(kind), 0.0, px, py, first, count)
            try:
                return (KINDS.index(kind), float(val), None, None, first, count)
            except ValueError:
                raise ValueError("constraint %r: %r is not a number" % (item, val)) from None
    raise ValueError("unknown constraint %r (convex, concave, increasing, decreasing, lower=C, "
                     "upper=C, lower=poly:X,Y;..., slope>=V, slope<=V, abs-slope<=V)" % item)


def records(items):
    """The list of records of constraints=[...] (None: None)."""
    if items is None:
        return None
    if isinstance(items, (str, dict)):
        items = [items]
    return [record(it) for it in items]


def pack(recs):
    """The records (``records``) as the float64 tail of the gufunc's option
    vector: n, then per record kind, value, first, count, n_poly, px, py
    (bindings/python/src/_gufunc.c)."""
    out = [float(len(recs))]
    for kind, value, px, py, first, count in recs:
        if first < 0 or count < 0:
            raise ValueError("constraint scope: first and count must be >= 0")
        npts = 0 if px is None else min(len(px), len(py))
        out += [float(kind), float(value), float(first), float(count), float(npts)]
        if npts:
            out += [float(v) for v in px[:npts]] + [float(v) for v in py[:npts]]
    return out
