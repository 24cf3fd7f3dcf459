"""Every keyword of every public entry point is documented with its actual
default: the numpydoc line ``name : type, default X`` exists, X is not
"None", and X is the value the keyword resolves to (``trigspline.defaults``
for the option vocabulary, the signature's own default otherwise).  The
values are read from the library (``_core.defaults()``) and the signatures,
not copied into this file."""
import inspect
import re

import pytest

import trigspline
from trigspline import Curve, Spline, Surface, estimate_slopes, interp
from trigspline import _options
from trigspline import plot as tsplot

xr = pytest.importorskip("xarray", reason="python3-xarray is installed by make test")
pd = pytest.importorskip("pandas", reason="python3-pandas is installed by make test")
import trigspline.pandas as tspd  # noqa: E402
import trigspline.xarray as tsxr  # noqa: E402

# Keywords whose default depends on the others, documented in words.
INFERRED = {"shape": "inferred", "lower": "none", "upper": "none", "box": "none",
            "epoch": "none", "vmin": None, "vmax": None, "ax": None, "label": None,
            "color": None, "xlabel": None, "ylabel": None, "xscale": None, "yscale": None,
            "cmap": None}
# Deprecated spellings and positional data are not documented with a default.
SKIP = {"bounds", "line", "method", "self", "indexers", "kwargs", "x", "y", "z", "f", "xq", "points",
        "obj", "index", "s", "srf", "slopes_values", "values", "fill_value", "bounds_error"}

ENTRIES = [(Spline, Spline.__init__, "spline"), (interp, interp, "spline"),
           (tspd.interpolate, tspd.interpolate, "spline"),
           (tsxr.TrigsplineAccessor.interp, tsxr.TrigsplineAccessor.interp, "spline"),
           (tsxr.TrigsplineDatasetAccessor.interp, tsxr.TrigsplineDatasetAccessor.interp,
            "spline"),
           (Curve, Curve.__init__, "curve"), (Surface, Surface.__init__, "surface"),
           (estimate_slopes, estimate_slopes, "spline"),
           (tsplot.spline, tsplot.spline, None), (tsplot.surface, tsplot.surface, None)]


def documented_defaults(doc):
    """{name: default text} from the 'name[, name] : type, default X' lines."""
    out = {}
    for m in re.finditer(r"^ {4}([A-Za-z_][\w, ]*?) : .*?, default (.+)$", doc, flags=re.M):
        for name in m.group(1).split(","):
            out[name.strip()] = m.group(2).strip()
    return out


@pytest.mark.parametrize("doc_obj,func,kind", ENTRIES,
                         ids=[getattr(e[0], "__qualname__", str(e[0])) for e in ENTRIES])
def test_every_keyword_states_its_actual_default(doc_obj, func, kind):
    doc = doc_obj.__doc__
    assert "${" not in doc and "library default" not in doc
    documented = documented_defaults(doc)
    defaults = trigspline.defaults(kind) if kind else {}
    for name, p in inspect.signature(func).parameters.items():
        if name in SKIP or p.kind in (p.VAR_KEYWORD, p.VAR_POSITIONAL):
            continue
        assert name in documented, "%s: %s has no 'default' in its docstring" % (doc_obj, name)
        text = documented[name]
        assert not text.startswith("None"), (doc_obj, name, text)
        if name in INFERRED:
            if INFERRED[name] is not None:
                assert text.startswith(INFERRED[name]), (doc_obj, name, text)
        elif name in defaults:
            want = _options._text(defaults[name])
            assert text.split()[0].rstrip(",") == want, (doc_obj, name, text, want)
        elif p.default is not inspect.Parameter.empty and p.default is not None:
            assert text.split()[0] == _options._text(p.default), (doc_obj, name, text)


def test_the_parser_reads_what_it_should():
    doc = "    a, b : float, default 1\n    alpha : float, default 0.85\n"
    assert documented_defaults(doc) == {"a": "1", "b": "1", "alpha": "0.85"}


def test_readme_table_states_the_spline_defaults():
    """bindings/python/README.md's Spline table ends each row with its default."""
    import os
    from conftest import REPO
    text = open(os.path.join(REPO, "bindings", "python", "README.md"), encoding="utf-8").read()
    rows = dict(re.findall(r"^\| `(\w+)`(?:, `\w+`)? \| .* \(([^()]*)\) \|$", text, flags=re.M))
    d = trigspline.defaults()
    assert rows["alpha"] == "%s, %s" % (_options._text(d["alpha"]), _options._text(d["beta"]))
    for k in ("margin", "slopes", "form", "extrapolate", "certify"):
        assert rows[k].strip("`") == _options._text(d[k]), (k, rows[k])
