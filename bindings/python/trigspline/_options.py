"""The package's one option vocabulary (docs/options.md): keyword names, their
values, their defaults, and the deprecated spellings still accepted.

Every entry point (Spline, Curve, Surface, interp, the xarray accessor,
pandas.interpolate, estimate_slopes) takes ``None`` for an option it was not
given and resolves it here:

* options of the library take the library's default, read once from
  ``ts_spline_options_init``, ``ts_curve_options_init`` and
  ``ts_surface_options_init`` through ``_core.defaults()``;
* the options that exist only in Python (``errors``, ``skipna``, the
  ``'nan'`` extrapolation) have their one default in ``PYTHON`` below.

Enum values are the library's canonical names (hyphens: ``'fritsch-carlson'``);
their tables are in the order of the C enums of include/trigspline.h.
"""
import os
import string
import sys
import warnings

from . import _core

# ---- values: index = the C enum value (the library's names, ts_vocab_name) ---
FORMS = _core.vocab(_core.VOCAB_FORM)
SLOPES = _core.vocab(_core.VOCAB_SLOPES)
SHAPES = _core.vocab(_core.VOCAB_SHAPE)
SURFACE_SHAPES = _core.vocab(_core.VOCAB_SURFACE_SHAPE)
EXTRAPS = _core.vocab(_core.VOCAB_EXTRAP)
PARAMS = _core.vocab(_core.VOCAB_PARAM)
TERMS = _core.vocab(_core.VOCAB_TERM)

#: Extrapolation policies of the package: the library's, and 'nan' (NaN
#: outside the data; Python only).
EXTRAPOLATE = EXTRAPS + ("nan",)

# Deprecated spellings of values (accepted with a DeprecationWarning for one
# release); an underscore for a hyphen is deprecated in every vocabulary.
_VALUE_ALIASES = {"slopes": {"pchip": "fritsch-carlson", "mean": "arithmetic"}}

# ---- defaults that exist only in Python -------------------------------------
#: errors: 'raise' as xarray's own errors= keywords (sel, drop_vars, ...);
#: skipna: False as xarray's interp, where a missing value makes NaN only the
#: outputs next to it (and so that dask chunks along the dimension stay
#: independent, see xarray.py); skipping across gaps is asked for.
PYTHON = {"errors": "raise", "skipna": False}
ERRORS = ("raise", "nan")


def _enum_name(table, value):
    if isinstance(value, str) or value is None:
        return value
    return table[value] if 0 <= int(value) < len(table) else value


# The library's option structs after their *_init ("spline", "curve",
# "surface"), enums as canonical names.
LIBRARY = _core.defaults()


def _resolved_defaults():
    lib, cur, srf = LIBRARY["spline"], LIBRARY["curve"], LIBRARY["surface"]
    spline = {"form": _enum_name(FORMS, lib["form"]),
              "slopes": _enum_name(SLOPES, lib["slopes"]),
              "alpha": float(lib["alpha"]), "beta": float(lib["beta"]),
              "margin": float(lib["margin"]), "certify": bool(lib["certify"]),
              "shape": _enum_name(SHAPES, lib["shape"]),
              "extrapolate": _enum_name(EXTRAPS, lib["extrapolate"]),
              "errors": PYTHON["errors"], "skipna": PYTHON["skipna"]}
    curve = {"param": _enum_name(PARAMS, cur["param"]), "closed": bool(cur["closed"]),
             "slopes": _enum_name(SLOPES, cur["slopes"]), "alpha": float(cur["alpha"]),
             "beta": float(cur["beta"]), "margin": float(cur["margin"]),
             # a curve has no extrapolation option in C: the spline's policy
             "extrapolate": spline["extrapolate"]}
    surface = {"form": _enum_name(FORMS, srf["form"]),
               "slopes": _enum_name(SLOPES, srf["slopes"]),
               "zero_twist": bool(srf["zero_twist"]), "alpha": float(srf["alpha"]),
               "beta": float(srf["beta"]), "margin": float(srf["margin"]),
               "shape": _enum_name(SURFACE_SHAPES, srf["shape"]),
               "extrapolate": spline["extrapolate"]}
    return {"spline": spline, "curve": curve, "surface": surface}


_DEFAULTS = _resolved_defaults()


def defaults(kind="spline"):
    """The default of every option keyword, as the entry points resolve
    ``None``: a new dict for ``kind`` 'spline' (Spline, interp, the xarray
    accessor, pandas.interpolate), 'curve' or 'surface'."""
    try:
        return dict(_DEFAULTS[kind])
    except KeyError:
        raise ValueError("kind must be 'spline', 'curve' or 'surface', not %r" % (kind,)) \
            from None


def default(kind, name):
    return _DEFAULTS[kind][name]


# ---- deprecations -----------------------------------------------------------
_PACKAGE_DIR = os.path.dirname(os.path.abspath(__file__))


def deprecated(message):
    """A DeprecationWarning attributed to the first caller outside the package."""
    f, level = sys._getframe(0), 1
    while f is not None and os.path.dirname(os.path.abspath(f.f_code.co_filename)) == \
            _PACKAGE_DIR:
        f, level = f.f_back, level + 1
    warnings.warn(message, DeprecationWarning, stacklevel=level)


def renamed(old, new, old_value, new_value):
    """The value of keyword ``new`` given also under its deprecated name ``old``."""
    if old_value is None:
        return new_value
    deprecated("%s= is deprecated; use %s= (docs/options.md)" % (old, new))
    if new_value is not None:
        raise TypeError("give %s= or the deprecated %s=, not both" % (new, old))
    return old_value


def split_bounds(bounds, lower, upper):
    """(lower, upper) from the deprecated bounds=(lower, upper) or the two."""
    if bounds is None:
        return lower, upper
    deprecated("bounds=(lower, upper) is deprecated; use lower= and upper= "
               "(docs/options.md)")
    if lower is not None or upper is not None:
        raise ValueError("give bounds=(lower, upper) or lower=/upper=, not both")
    try:
        lower, upper = bounds
    except (TypeError, ValueError):
        raise ValueError("bounds must be a pair (lower, upper), not %r" % (bounds,)) from None
    return lower, upper


# ---- values -----------------------------------------------------------------
def name(table, value, what, vocab=None):
    """The canonical name of value (a name, any case) in table; a deprecated
    spelling warns; ValueError otherwise."""
    if isinstance(value, str):
        key = value.strip().lower()
        if key in table:
            return key
        alias = _VALUE_ALIASES.get(vocab or what, {}).get(key)
        if alias is None and "_" in key and key.replace("_", "-") in table:
            alias = key.replace("_", "-")
        if alias is not None and alias in table:
            deprecated("%s=%r is deprecated; use %s=%r (docs/options.md)"
                       % (what, value, what, alias))
            return alias
    raise ValueError("%s must be one of %s, not %r" % (what, ", ".join(repr(t) for t in table),
                                                       value))


def index(table, value, what, vocab=None):
    """The C enum value of a name."""
    return table.index(name(table, value, what, vocab))


def option(kind, key, value):
    """value, or the default of option key when None."""
    return default(kind, key) if value is None else value


def enum(kind, key, value, table, what=None):
    """Canonical name of an enum option (the default when None)."""
    return name(table, option(kind, key, value), what or key, key)


def extrapolate(value, kind="spline", allowed=EXTRAPOLATE, what="extrapolate"):
    """Canonical extrapolation policy: None the default, True 'extend' and
    False 'nan' (SciPy's spellings), or a name of ``allowed``."""
    if value is None:
        value = default(kind, "extrapolate")
    if value is True:
        value = "extend"
    elif value is False:
        value = "nan"
    if isinstance(value, str) and value.strip().lower() in allowed:
        return value.strip().lower()
    spell = ", ".join(repr(v) for v in allowed)
    if "extend" in allowed:
        spell = "True, False, " + spell
    elif "nan" in allowed:
        spell = "False, " + spell
    raise ValueError("%s must be one of %s, not %r" % (what, spell, value))


def errors(value):
    value = option("spline", "errors", value)
    if value not in ERRORS:
        raise ValueError("errors must be 'raise' or 'nan', not %r" % (value,))
    return value


def flag(kind, key, value):
    return bool(option(kind, key, value))


def _zero(b):
    return b is not None and all(v == 0.0 for v in b)


def infer_shape(shape, lower, upper, kind="spline"):
    """The shape when ``shape`` is None, from the bounds given (already as
    tuples (m, c) or (p, q, c), or None): neither gives the default; lower
    = 0 alone 'positive' (zeros allowed); otherwise 'above' / 'below' /
    'between' (spline) or 'bounds' / 'planes' (surface: 'planes' when a
    bound is sloped)."""
    if shape is not None:
        return shape
    if lower is None and upper is None:
        return default(kind, "shape")
    if upper is None and _zero(lower):
        return "positive"
    if kind == "surface":
        flat = all(b is None or all(v == 0.0 for v in b[:-1]) for b in (lower, upper))
        return "bounds" if flat else "planes"
    if upper is None:
        return "above"
    if lower is None:
        return "below"
    return "between"


# ---- docstrings -------------------------------------------------------------
def _text(v):
    if isinstance(v, bool) or isinstance(v, str):
        return repr(v)
    if isinstance(v, float) and v == int(v) and abs(v) < 1e16:
        return str(int(v))
    return repr(v)


def fill(doc, kind="spline"):
    """doc with ``${key}`` replaced by the default of key for kind, and
    ``${spline_key}``, ``${curve_key}``, ``${surface_key}`` by those of the
    other kinds."""
    values = {}
    for other in ("spline", "curve", "surface"):
        values.update({"%s_%s" % (other, k): _text(v) for k, v in _DEFAULTS[other].items()})
    values.update({k: _text(v) for k, v in _DEFAULTS[kind].items()})
    return string.Template(doc).safe_substitute(values)


def document(obj, kind="spline"):
    """obj with its docstring filled (``fill``)."""
    if obj.__doc__:
        obj.__doc__ = fill(obj.__doc__, kind)
    return obj
