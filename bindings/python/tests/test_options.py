"""One option vocabulary (docs/options.md): every entry point takes the same
keywords with the same defaults, the library's; deprecated spellings warn and
mean the same.

References: the defaults of the C library itself (ts_spline_options_init through
ctypes on the CMake build, the extension's own defaults tuples), the table of
docs/options.md, and each entry point called with every default spelled out.
"""
import inspect
import os
import re
import warnings

import numpy as np
import pytest

import trigspline
from trigspline import Curve, Spline, Surface, estimate_slopes, interp
from trigspline import _core, _options
from conftest import REPO

xr = pytest.importorskip("xarray")
pd = pytest.importorskip("pandas")
import trigspline.pandas as tspd  # noqa: E402
import trigspline.xarray as tsxr  # noqa: E402

ENTRY_POINTS = {
    "Spline": (Spline.__init__, "spline"),
    "interp": (interp, "spline"),
    "DataArray.trigspline.interp": (tsxr.TrigsplineAccessor.interp, "spline"),
    "Dataset.trigspline.interp": (tsxr.TrigsplineDatasetAccessor.interp, "spline"),
    "pandas.interpolate": (tspd.interpolate, "spline"),
    "estimate_slopes": (estimate_slopes, "spline"),
    "Surface": (Surface.__init__, "surface"),
    "Curve": (Curve.__init__, "curve"),
}
BATCH = ("interp", "DataArray.trigspline.interp", "Dataset.trigspline.interp",
         "pandas.interpolate")
DEPRECATED = {"line", "bounds", "slopes_values", "method"}


def table():
    """docs/options.md's table: (C structs, Python keyword, default text) per row."""
    rows = []
    with open(os.path.join(REPO, "docs", "options.md"), encoding="utf-8") as fh:
        lines = fh.read().splitlines()
    start = lines.index("| C field | CLI option | Python keyword | JS name | default | meaning |")
    for line in lines[start + 2:]:
        if not line.startswith("|"):
            break
        cells = [c.strip() for c in line.strip("|").split("|")]
        kinds = sorted({{"options": "spline", "curve_options": "curve",
                         "surface_options": "surface"}[k]
                        for k in re.findall(r"ts_(options|curve_options|surface_options)\.",
                                            cells[0])}) or ["spline"]
        kw = re.fullmatch(r"`(\w+)`", cells[2]).group(1)
        m = re.fullmatch(r"`(.+)`", cells[4])
        rows.append((kinds, kw, m.group(1) if m else None))
    return rows


def keywords(fn):
    return {n: p.default for n, p in inspect.signature(fn).parameters.items()
            if p.kind == p.KEYWORD_ONLY or p.default is not p.empty}


def test_docs_table_is_the_package_vocabulary():
    rows = table()
    vocab = {kw for _, kw, _ in rows}
    assert len(rows) >= 15
    for kinds, kw, dflt in rows:
        for kind in kinds:
            d = trigspline.defaults(kind)
            if dflt is None:   # no default: the option is off
                assert kw not in d, kw
            else:
                assert _options._text(d[kw]) == dflt, (kind, kw, d[kw], dflt)
        # every keyword of the table is taken by some entry point
        assert any(kw in keywords(fn) for fn, _ in ENTRY_POINTS.values()), kw
    # and every default the package resolves is in the table
    for kind in ("spline", "curve", "surface"):
        assert set(trigspline.defaults(kind)) <= vocab


def test_same_keywords_same_defaults_in_every_entry_point():
    vocab = {kw for _, kw, _ in table()}
    sets = {}
    for name, (fn, kind) in ENTRY_POINTS.items():
        kws = keywords(fn)
        sets[name] = {k for k in kws if k in vocab}
        for k in sets[name] | (DEPRECATED & set(kws)):
            # None everywhere: the value is resolved in _options, one place
            assert kws[k] is None, (name, k, kws[k])
        for k in sets[name]:
            if k in trigspline.defaults(kind):
                assert _options.option(kind, k, None) == trigspline.defaults(kind)[k]
    # the batch entry points speak exactly the same vocabulary
    for name in BATCH:
        assert sets[name] == sets["interp"], name
    assert sets["interp"] == {"shape", "lower", "upper", "alpha", "form", "slopes", "margin",
                              "certify", "extrapolate", "skipna", "errors", "constraints"}
    # Spline: the same but for the batch-only ones, plus beta
    assert sets["Spline"] == sets["interp"] - {"skipna", "errors"} | {"beta"}
    assert sets["Surface"] == {"shape", "lower", "upper", "alpha", "beta", "form", "slopes",
                               "margin", "zero_twist", "extrapolate"}
    assert sets["Curve"] == {"closed", "param", "alpha", "beta", "box", "slopes", "margin",
                             "extrapolate"}
    # the same options resolve to the same values in every kind that has them
    sp, cu, su = (trigspline.defaults(k) for k in ("spline", "curve", "surface"))
    # except the 1-D spline's form, slopes and alpha (geometric, Steffen, 0.85:
    # PCHIP's promise, docs/method.md §5.10), which curves and surfaces do not
    # take over (docs/options.md, "Defaults")
    own = {"form", "slopes", "alpha"}
    for k in set(sp) & set(cu) - own:
        assert sp[k] == cu[k], k
    for k in set(sp) & set(su) - own:
        assert sp[k] == su[k], k


def test_defaults_are_the_library_s():
    d = trigspline.defaults()
    assert d["extrapolate"] == "error" and d["errors"] == "raise" and d["skipna"] is False
    # the extension's tuples, read from ts_spline_options_init / ts_surface_options_init
    form, slopes, alpha, beta, margin, certify = _core.options_defaults()
    assert (d["form"], d["slopes"], d["alpha"], d["beta"], d["margin"], d["certify"]) == (
        _options.FORMS[form], _options.SLOPES[slopes], alpha, beta, margin, bool(certify))
    s = trigspline.defaults("surface")
    form, slopes, zt, alpha, beta, margin = _core.surface_options_defaults()
    assert (s["form"], s["slopes"], s["zero_twist"], s["alpha"], s["beta"], s["margin"]) == (
        _options.FORMS[form], _options.SLOPES[slopes], bool(zt), alpha, beta, margin)
    # _core.defaults(): the option structs' fields
    lib = _core.defaults()
    assert {"form", "slopes", "alpha", "beta", "margin", "certify", "extrapolate",
            "shape"} <= set(lib["spline"])
    assert {"param", "closed", "slopes", "alpha", "beta", "margin"} <= set(lib["curve"])
    assert {"form", "slopes", "zero_twist", "alpha", "beta", "margin", "shape"} <= set(
        lib["surface"])
    # and the shared library's own ts_spline_options_init, through ctypes
    import ctypes
    import test_clib
    if not os.path.exists(test_clib.LIB):
        pytest.skip("no CMake build at " + test_clib.LIB)
    L = ctypes.CDLL(test_clib.LIB)
    o = test_clib.Options()
    L.ts_spline_options_init(ctypes.byref(o))
    assert (d["form"], d["slopes"], d["alpha"], d["beta"], d["margin"], d["shape"],
            d["certify"], d["extrapolate"]) == (
        _options.FORMS[o.form], _options.SLOPES[o.slopes], o.alpha, o.beta, o.margin,
        _options.SHAPES[o.shape], bool(o.certify), _options.EXTRAPS[o.extrapolate])


def data():
    rng = np.random.default_rng(21)
    x = np.cumsum(rng.uniform(0.2, 1.5, 30))
    f = rng.pareto(2.5, (3, 30))
    f[:, ::4] = 0.0
    return x, f


def explicit(kind, names, **extra):
    d = trigspline.defaults(kind)
    out = {k: d[k] for k in names if k in d}
    if "lower" in extra or "upper" in extra:
        del out["shape"]  # inferred from the bounds
    out.update(extra)
    return out


def test_left_out_equals_the_defaults_spelled_out():
    x, f = data()
    xq = np.linspace(x[0], x[-1], 97)
    same = np.testing.assert_array_equal
    names = keywords(Spline.__init__)
    for kw in ({}, {"lower": 0}, {"shape": "monotone"}):
        ff = np.cumsum(f, axis=-1) if kw.get("shape") == "monotone" else f
        s = Spline(x, ff[0], **kw)
        t = Spline(x, ff[0], **explicit("spline", names, **kw))
        same(s(xq), t(xq))
        same(s.beta, t.beta)
        assert s.extrapolate == t.extrapolate == "error"
        same(interp(x, ff, xq, **kw), interp(x, ff, xq, **explicit(
            "spline", keywords(interp), **kw)))
        same(interp(x, ff, xq, **kw)[0], s(xq))
    da = xr.DataArray(f, dims=("s", "t"), coords={"t": x})
    ds = xr.Dataset({"v": da})
    a = da.trigspline.interp(t=xq, lower=0)
    same(a.values, da.trigspline.interp(t=xq, **explicit(
        "spline", keywords(tsxr.TrigsplineAccessor.interp), lower=0)).values)
    same(a.values, interp(x, f, xq, lower=0))
    same(ds.trigspline.interp(t=xq, lower=0)["v"].values, a.values)
    ser = pd.Series(f[1], index=x)
    p = tspd.interpolate(ser, xq, lower=0)
    same(p.values, tspd.interpolate(ser, xq, **explicit(
        "spline", keywords(tspd.interpolate), lower=0)).values)
    same(p.values, a.values[1])
    z = np.add.outer(np.sin(x[:8]), np.cos(x[:6])) + 2.0
    g = Surface(x[:8], x[:6], z, lower=0)
    h = Surface(x[:8], x[:6], z, **explicit("surface", keywords(Surface.__init__), lower=0))
    assert g.shape == h.shape == "positive"
    same(g(xq[:5], xq[:5] * 0.3 + x[0]), h(xq[:5], xq[:5] * 0.3 + x[0]))
    pts = np.stack([x[:7], f[0, :7]], axis=1)
    c, e = Curve(pts), Curve(pts, **explicit("curve", keywords(Curve.__init__)))
    same(c(np.linspace(0, c.knots[-1], 50)), e(np.linspace(0, c.knots[-1], 50)))
    same(estimate_slopes(x, f[0]), estimate_slopes(x, f[0], trigspline.defaults()["slopes"]))


def test_extrapolate_default_error_everywhere():
    x, f = data()
    out = [x[0] - 1.0]
    with pytest.raises(trigspline.TrigsplineError) as e1:
        Spline(x, f[0])(out)
    with pytest.raises(trigspline.TrigsplineError) as e2:
        interp(x, f, out)
    with pytest.raises(trigspline.TrigsplineError) as e3:
        xr.DataArray(f, dims=("s", "t"), coords={"t": x}).trigspline.interp(t=out)
    with pytest.raises(trigspline.TrigsplineError) as e4:
        tspd.interpolate(pd.Series(f[0], index=x), out)
    for e in (e1, e2, e3, e4):
        assert e.value.name == "TS_ERR_DOMAIN" and e.value.where == "query"
        assert "extrapolate='error'" in str(e.value)
    with pytest.raises(trigspline.TrigsplineError, match=r"series \(1,\): query 0"):
        interp(np.stack([x, x + 2.0]), f[:2], [x[0] + 1.0, x[-1]])  # per-series knots
    # 'nan' (and SciPy's False) give NaN outside, True extends as SciPy
    assert np.isnan(interp(x, f, out, extrapolate="nan")).all()
    assert np.isnan(interp(x, f, out, extrapolate=False)).all()
    np.testing.assert_array_equal(interp(x, f[0], out, extrapolate=True),
                                  Spline(x, f[0], extrapolate="extend")(out))
    # NaN queries are no error
    assert np.isnan(interp(x, f, [np.nan])).all()
    pts = [[0, 0], [1, 1], [2, 0]]
    with pytest.raises(trigspline.TrigsplineError):
        Curve(pts)(9.0)
    assert Surface(x[:3], x[:3], np.ones((3, 3))).extrapolate == "error"
    with pytest.raises(ValueError, match="contradicts"):
        Surface(x[:3], x[:3], np.ones((3, 3)), extrapolate="error", bounds_error=False)
    s = Surface(x[:3], x[:3], np.ones((3, 3)), extrapolate="nan")
    assert s.bounds_error is False and np.isnan(s([[x[0] - 1, x[0]]]))
    for bad in ("extend", True, "clamp"):
        with pytest.raises(ValueError):
            Curve(pts, extrapolate=bad)
        with pytest.raises(ValueError):
            Surface(x[:3], x[:3], np.ones((3, 3)), extrapolate=bad)


def test_errors_and_skipna_defaults_in_every_batch_entry_point():
    x = np.arange(6.0)
    f = np.array([[1, 2, 3, 2, 1, 2], [1, 2, -3, 2, 1, 2], [1, np.nan, 3, 2, 1, 2]])
    q = np.array([0.5, 4.5])
    da = xr.DataArray(f, dims=("s", "t"), coords={"t": x})
    df = pd.DataFrame(f.T, index=x)
    for call in (lambda **k: interp(x, f, q, lower=0, **k),
                 lambda **k: da.trigspline.interp(t=q, lower=0, **k).values,
                 lambda **k: tspd.interpolate(df, q, lower=0, **k).values.T):
        with pytest.raises(ValueError, match="negative"):
            call()                                   # errors='raise'
        y = call(errors="nan")
        assert not np.isnan(y[0]).any() and np.isnan(y[1]).all()
        # skipna=False: the NaN at x = 1 blanks the interval [0, 1] only
        assert np.isnan(y[2, 0]) and not np.isnan(y[2, 1])
        assert not np.isnan(call(errors="nan", skipna=True)[2]).any()
        with pytest.raises(ValueError, match="errors must be"):
            call(errors="ignore")


def test_inferred_shape_is_the_same_everywhere():
    x, f = data()
    xq = np.linspace(x[0], x[-1], 41)
    g = f[0] + 1.0
    for kw, shape in (({}, "none"), ({"lower": 0}, "positive"), ({"lower": (0, 0)}, "positive"),
                      ({"lower": 0.5}, "above"), ({"upper": 100}, "below"),
                      ({"lower": (0.01, 0.5), "upper": 100}, "between")):
        s = Spline(x, g, **kw)
        assert s.shape == shape, kw
        np.testing.assert_array_equal(s(xq), Spline(x, g, shape=shape, **kw)(xq))
        np.testing.assert_array_equal(interp(x, g, xq, **kw), s(xq))
    z = np.ones((3, 3)) + np.eye(3)
    for kw, shape in (({}, "none"), ({"lower": 0}, "positive"), ({"lower": 0.5}, "bounds"),
                      ({"upper": 9.0}, "bounds"),
                      ({"lower": (0.01, 0.0, 0.5), "form": "geometric"}, "planes")):
        assert Surface(x[:3], x[:3], z, **kw).shape == shape, kw


@pytest.mark.parametrize("make", [
    lambda v: Spline(np.arange(6.0), [1, 2, 4, 3, 5, 6], slopes=v),
    lambda v: interp(np.arange(6.0), [1, 2, 4, 3, 5, 6], [0.5, 2.5], slopes=v),
    lambda v: Surface(np.arange(4.0), np.arange(3.0), np.arange(12.0).reshape(4, 3), slopes=v),
    lambda v: Curve([[0, 0], [1, 2], [3, 1], [4, 4]], slopes=v),
    lambda v: estimate_slopes(np.arange(6.0), [1, 2, 4, 3, 5, 6], v),
])
def test_value_spellings_deprecated(make):
    def value(r):
        if isinstance(r, (Spline, Curve)):
            return r(r.x[0] + 0.37)
        if isinstance(r, Surface):
            return r([[0.5, 0.5]])
        return r
    new = value(make("fritsch-carlson"))
    for old, canonical in (("fritsch_carlson", "fritsch-carlson"), ("pchip", "fritsch-carlson"),
                           ("FRITSCH_CARLSON", "fritsch-carlson")):
        with pytest.warns(DeprecationWarning, match="use slopes='fritsch-carlson'") as w:
            got = value(make(old))
        assert w[0].filename == __file__        # attributed to the caller
        np.testing.assert_array_equal(got, new)
    with pytest.warns(DeprecationWarning, match="use slopes='arithmetic'"):
        np.testing.assert_array_equal(value(make("mean")), value(make("arithmetic")))
    # the canonical spellings do not warn
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        value(make("fritsch-carlson"))


def test_renamed_keywords_deprecated():
    x = np.arange(7.0)
    f = np.array([2.0, 2.5, 3.5, 3.0, 4.0, 5.0, 4.5])
    xq = np.linspace(0, 6, 29)
    same = np.testing.assert_array_equal
    with pytest.warns(DeprecationWarning, match="line= is deprecated") as w:
        s = Spline(x, f, shape="above", line=(0.1, 1.0))
    assert w[0].filename == __file__
    same(s(xq), Spline(x, f, shape="above", lower=(0.1, 1.0))(xq))
    with pytest.warns(DeprecationWarning, match="line= is deprecated"):
        same(Spline(x, f, shape="below", line=(0, 9))(xq), Spline(x, f, upper=9)(xq))
    for bad in ({}, {"shape": "between"}, {"shape": "above", "lower": (0, 0.5)}):
        with pytest.warns(DeprecationWarning), pytest.raises(ValueError):
            Spline(x, f, line=(0, 1), **bad)
    d = np.cos(x)
    with pytest.warns(DeprecationWarning, match="slopes_values= is deprecated; use slopes="):
        same(Spline(x, f, slopes_values=d)(xq), Spline(x, f, slopes=d)(xq))
    with pytest.warns(DeprecationWarning), pytest.raises(TypeError, match="not both"):
        Spline(x, f, slopes_values=d, slopes="akima")
    with pytest.warns(DeprecationWarning, match="method= is deprecated; use slopes="):
        same(estimate_slopes(x, f, method="akima"), estimate_slopes(x, f, "akima"))
    da = xr.DataArray(f, dims="t", coords={"t": x})
    with pytest.warns(DeprecationWarning, match=r"bounds=\(lower, upper\) is deprecated") as w:
        a = da.trigspline.interp(t=xq, bounds=(0, None))
    assert w[0].filename == __file__
    same(a.values, da.trigspline.interp(t=xq, lower=0).values)
    with pytest.warns(DeprecationWarning):
        b = da.to_dataset(name="v").trigspline.interp(t=xq, bounds=(1, 6))
    same(b["v"].values, da.trigspline.interp(t=xq, lower=1, upper=6).values)
    with pytest.warns(DeprecationWarning):
        p = tspd.interpolate(pd.Series(f, index=x), xq, bounds=(0, None))
    same(p.values, a.values)
    with pytest.warns(DeprecationWarning), pytest.raises(ValueError, match="not both"):
        da.trigspline.interp(t=xq, bounds=(0, None), lower=0)


def test_docstrings_state_the_default_values():
    d = trigspline.defaults()
    for obj in (Spline, interp, tsxr.TrigsplineAccessor.interp,
                tsxr.TrigsplineDatasetAccessor.interp, tspd.interpolate, estimate_slopes,
                Surface, Curve):
        doc = obj.__doc__
        assert "${" not in doc and "library default" not in doc, obj
        kind = {Surface: "surface", Curve: "curve"}.get(obj, "spline")
        assert "default %s" % _options._text(trigspline.defaults(kind)["slopes"]) in doc, obj
    for obj in (Spline, interp, tsxr.TrigsplineAccessor.interp, tspd.interpolate):
        for k in ("alpha", "form", "margin", "certify", "extrapolate"):
            assert "default %s" % _options._text(d[k]) in obj.__doc__, (obj, k)
    for obj in (interp, tsxr.TrigsplineAccessor.interp, tspd.interpolate):
        assert "default 'raise'" in obj.__doc__ and "default False" in obj.__doc__
    assert "default 'centripetal'" in Curve.__doc__
    assert "default 0.01" in Surface.__doc__


def test_report_terms_use_the_canonical_names():
    x = np.array([0.0, 1.0, 2.0, 3.0, 4.0])
    s = Spline(x, [1.0, 0.01, 0.01, 1.0, 2.0], shape="positive", alpha=0.2)
    terms = {r["term"] for r in s.report()}
    assert terms <= set(_options.TERMS) and not any("_" in t for t in terms)
