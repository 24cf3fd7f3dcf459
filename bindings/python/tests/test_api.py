"""The SciPy interpolator API: call conventions, nu, NaN, extrapolate, axis,
accessors.  References: docs/method.md re-derived (conftest.ref_paper), SciPy,
finite differences."""
import math

import numpy as np
import pytest

import trigspline
from trigspline import Spline, TrigsplineError
from conftest import EPS, ref_paper


def smooth_data(n=40, seed=1):
    rng = np.random.default_rng(seed)
    x = np.cumsum(rng.uniform(0.2, 1.0, n))
    return x, np.sin(x) + 2.0 + 0.1 * rng.standard_normal(n)


# Tolerance for values against the numpy re-derivation: both sum four terms
# of size max|B| with O(1) coefficients: 64 ε max|B| covers the roundings.
def tol_of(f):
    return 64 * EPS * np.max(np.abs(f)) * 4


@pytest.mark.parametrize("form", ["paper", "c1"])
def test_values_against_method(form):
    x, f = smooth_data()
    s = Spline(x, f, form=form, shape="positive", alpha=0.5)
    xq = np.linspace(x[0], x[-1], 2001)
    ref = ref_paper(x, f, s.slopes, s.a, xq, c1=(form == "c1"))
    assert np.max(np.abs(s(xq) - ref)) <= tol_of(f)


def test_input_kinds_and_shapes():
    x, f = smooth_data()
    s = Spline(x, f, form="paper")
    xq = np.linspace(x[0], x[-1], 12)
    base = s(xq)
    assert isinstance(base, np.ndarray) and base.shape == (12,)
    assert np.array_equal(s(list(xq)), base)
    assert np.array_equal(s(tuple(xq)), base)
    assert np.array_equal(s(xq.reshape(3, 4)), base.reshape(3, 4))
    assert np.array_equal(s(xq[::-1])[::-1], base)          # non-contiguous / any order
    assert np.array_equal(s(np.asfortranarray(xq.reshape(3, 4))), base.reshape(3, 4))
    f32 = xq.astype(np.float32)
    assert np.array_equal(s(f32), s(f32.astype(np.float64)))
    r = s(float(xq[3]))
    assert isinstance(r, np.ndarray) and r.shape == () and r == base[3]  # 0-d like SciPy
    assert s(np.float32(xq[3])).shape == ()
    assert s([]).shape == (0,)
    # x and f from lists, tuples, float32 and integer arrays
    s2 = Spline(list(x), tuple(f), form="paper")
    assert np.array_equal(s2(xq), base)


def test_pandas_series():
    pd = pytest.importorskip("pandas")
    x, f = smooth_data()
    s = Spline(pd.Series(x), pd.Series(f), form="paper")
    q = pd.Series(np.linspace(x[0], x[-1], 7))
    assert np.array_equal(s(q), Spline(x, f, form="paper")(q.to_numpy()))


def test_nan_queries_give_nan():
    x, f = smooth_data()
    s = Spline(x, f, form="paper")  # derivatives of order 3 need the paper or c1 form
    xq = np.array([x[0], np.nan, x[5], np.nan])
    y = s(xq)
    assert np.isnan(y[1]) and np.isnan(y[3]) and np.isfinite(y[[0, 2]]).all()
    assert np.isnan(s(np.nan))
    for nu in (1, 2, 3):
        assert np.isnan(s(xq, nu)[1])
    assert np.isnan(s(np.nan, extrapolate="error"))  # NaN is not a domain error


def test_derivatives_against_finite_differences():
    x, f = smooth_data()
    s = Spline(x, f, form="paper", alpha=0.7)
    # inside intervals (away from knots, where the paper form's derivatives jump)
    mids = 0.5 * (x[:-1] + x[1:])
    h = 1e-5
    for nu in range(1, 6):
        fd = (s(mids + h, nu - 1) - s(mids - h, nu - 1)) / (2 * h)
        # central difference: error h²/6 max|S^(nu+2)| plus rounding ε|S^(nu-1)|/h;
        # derivatives grow like (π/2h)^nu (h >= 0.2 here) -> a relative 1e-5
        scale = np.max(np.abs(s(mids, nu))) + 1.0
        assert np.max(np.abs(s(mids, nu) - fd)) <= 1e-5 * scale * 10 ** (nu - 1), nu


def test_nu_validation_and_geometric_high_order():
    x, f = smooth_data()
    with pytest.raises(ValueError):
        Spline(x, f)(x[1], -1)
    g = Spline(x, f, form="geometric")
    assert np.isfinite(g(x[1] + 0.01, 2))
    with pytest.raises(ValueError):
        g(x[1], 3)


def test_extrapolate_modes():
    x, f = smooth_data()
    out = np.array([x[0] - 1.0, x[-1] + 2.0])
    for form in ("paper", "geometric"):
        # the library's default ('error', ts_spline_options_init); SciPy's is True
        assert Spline(x, f, form=form).extrapolate == "error"
        s = Spline(x, f, form=form, extrapolate=True)
        assert s.extrapolate == "extend"
        # the library's own policies (handles built with each ts_extrap) as reference
        from trigspline import _core
        for mode, code in (("extend", 2), ("clamp", 1), ("linear", 3)):
            ref = _core.spline_new(x, f, form=["paper", "c1", "geometric"].index(form),
                                   extrapolate=code)
            for nu in (0, 1, 2):
                got = s(out, nu, extrapolate=mode)
                want = np.array([ref.eval(np.array([v]), nu)[0] for v in out])
                assert np.allclose(got, want, rtol=4 * EPS, atol=0), (form, mode, nu)
        assert np.isnan(s(out, extrapolate=False)).all()
        assert np.isnan(s(out, extrapolate="nan")).all()
        with pytest.raises(TrigsplineError) as ei:
            s(np.array([x[1], out[1]]), extrapolate="error")
        assert ei.value.index == 1 and ei.value.where == "query" and ei.value.name == "TS_ERR_DOMAIN"
        assert isinstance(ei.value, ValueError)
        # construction-time default and per-call override
        c = Spline(x, f, extrapolate="clamp", form=form)
        assert np.array_equal(c(out), f[[0, -1]])
        assert np.array_equal(c(out, extrapolate=True), s(out))
        assert np.isnan(Spline(x, f, extrapolate=False)(out)).all()
        # extend: the paper form continues the end interval's formula
    s = Spline(x, f, form="paper", extrapolate=True)
    B = s.c[:, 0]
    th = (math.pi / 2) * (out[0] - x[0]) / (x[1] - x[0])
    from conftest import ref_basis
    assert abs(s(out[0]) - ref_basis(th) @ B) <= tol_of(f) * 10
    with pytest.raises(ValueError):
        s(out, extrapolate="periodic")
    # infinities: clamp gives the end value, linear the signed infinity
    inf = np.array([-np.inf, np.inf])
    assert np.array_equal(s(inf, extrapolate="clamp"), f[[0, -1]])


def test_axis_3d_against_one_by_one():
    rng = np.random.default_rng(5)
    x = np.cumsum(rng.uniform(0.5, 1.5, 12))
    F = rng.uniform(0.1, 3.0, (3, 12, 4))
    s = Spline(x, F, axis=1, shape="positive", form="paper")
    xq = np.linspace(x[0], x[-1], 35).reshape(5, 7)
    y = s(xq)
    assert y.shape == (3, 5, 7, 4)                           # SciPy's layout
    for i in range(3):
        for k in range(4):
            one = Spline(x, F[i, :, k], shape="positive", form="paper")
            assert np.array_equal(y[i, :, :, k], one(xq))
            assert np.array_equal(s.beta[i, :, k], one.beta)
    assert s.certified
    assert s.c.shape == (4, 11, 3, 4)                        # PPoly.c's layout
    assert np.array_equal(s.c[:, :, 1, 2], Spline(x, F[1, :, 2], shape="positive",
                                                  form="paper").c)
    # axis=-1 and axis=0
    G = np.moveaxis(F, 1, -1)
    assert np.array_equal(Spline(x, G, axis=-1, shape="positive", form="paper")(xq),
                          np.moveaxis(y, (1, 2), (2, 3)))
    # integrate and solve per series
    I = s.integrate(x[0], x[-1])
    assert I.shape == (3, 4)
    assert I[1, 2] == Spline(x, F[1, :, 2], shape="positive", form="paper").integrate(x[0], x[-1])
    # an error names the series
    F[2, 5, 1] = -1.0
    with pytest.raises(TrigsplineError) as ei:
        Spline(x, F, axis=1, shape="positive")
    assert ei.value.series == (2, 1) and ei.value.index == 5 and ei.value.name == "TS_ERR_NEGATIVE"
    assert "series (2, 1)" in str(ei.value)


def test_scipy_pchip_agreement_on_cubic_limit():
    """With Fritsch–Carlson slopes the spline interpolates the same data with the same
    slopes as SciPy's PchipInterpolator (docs/method.md §6): values at knots and slopes
    agree; in between both stay inside the data's range on monotone data."""
    scipy_interp = pytest.importorskip("scipy.interpolate")
    x, f = smooth_data()
    f = np.cumsum(np.abs(f))  # monotone
    p = scipy_interp.PchipInterpolator(x, f)
    s = Spline(x, f, slopes="fritsch-carlson", shape="monotone", form="paper")
    assert np.array_equal(s(x), f)
    assert np.allclose(trigspline.estimate_slopes(x, f, "fritsch-carlson"), p(x, 1), rtol=1e-12)
    xq = np.linspace(x[0], x[-1], 5001)
    assert np.all(np.diff(s(xq)) >= 0)


def test_accessors():
    x, f = smooth_data()
    s = Spline(x, f, shape="positive", alpha=0.4, form="paper")
    assert np.array_equal(s.x, x) and np.array_equal(s.values, f)
    assert s.x.flags.writeable is False
    with pytest.raises(ValueError):
        s.x[0] = 1.0
    assert s.c.shape == (4, len(x) - 1)
    K = 2 * np.diff(x) / (3 * math.pi)
    a = s.alpha + s.beta
    assert np.allclose(s.c[1], f[:-1] + K / a * s.slopes[:-1], rtol=1e-14)
    assert np.array_equal(s.a, a) and np.all(s.alpha == 0.4)
    assert s.control_x.shape == (4, len(x) - 1)
    B, X = s.control(3)
    assert B == list(s.c[:, 3])
    rep = s.report()
    assert len(rep) == len(x) - 1 and rep[3]["B"] == B and rep[3]["certified"]
    assert s.intervals == len(x) - 1 and s.domain == (x[0], x[-1])
    assert s.form == "paper" and s.shape == "positive"


def test_report_overshoot_against_dense_sampling():
    """report()'s curve range and excursions (docs/method.md §5.9) against the
    spline sampled at 20001 points per interval: the exact extremum is never
    beaten by a sample, and the best sample comes within the sampling error: the
    extremum lies within half a step dt of a sample, where S' = 0, so the sample
    is at most max|S''| (dt/2)^2 / 2 below it."""
    x = np.array([0.0, 1.0, 2.0, 3.0, 4.0, 5.0])
    f = np.array([0.0, 12.5, 0.0, 3.0, 0.0, 8.0])
    s = Spline(x, f, shape="positive", alpha=0.1, form="paper")
    for i, r in enumerate(s.report()):
        t = np.linspace(x[i], x[i + 1], 20001)
        y = s(t)
        tol = np.abs(s(t, 2)).max() * (t[1] - t[0]) ** 2 / 8 * 1.01 + 1e-12
        assert r["y_min"] <= y.min() + 1e-12 and r["y_max"] >= y.max() - 1e-12
        assert abs(r["y_max"] - y.max()) < tol and abs(r["y_min"] - y.min()) < tol
        assert x[i] <= r["at_y_max"] <= x[i + 1] and x[i] <= r["at_y_min"] <= x[i + 1]
        assert abs(r["excursion_above"] - (y.max() - max(f[i], f[i + 1]))) < tol
        assert abs(r["excursion_below"] - (min(f[i], f[i + 1]) - y.min())) < tol
    assert max(r["excursion_above"] for r in s.report()) > 1.0  # small α overshoots


def test_form_default_follows_library():
    x, f = smooth_data()
    from trigspline import _core
    assert Spline(x, f).form == ["paper", "c1", "geometric"][_core.options_defaults()[0]]


def test_cubic_hermite_and_akima_migration():
    """CubicHermiteSpline(x, y, dydx) -> Spline(x, f, slopes=dydx): with α + β = 1
    the slopes at the knots are dydx (docs/method.md §3: S'(x_i+) = d_i/a_i); Akima's
    slopes are SciPy's Akima1DInterpolator's (docs/method.md §6)."""
    interp = pytest.importorskip("scipy.interpolate")
    x, f = smooth_data()
    d = np.cos(x)
    s = Spline(x, f, slopes=d, form="paper", alpha=1.0)
    assert np.allclose(s(x[:-1], 1), d[:-1], rtol=1e-12, atol=1e-13)
    assert np.array_equal(s(x), f)
    ak = interp.Akima1DInterpolator(x, f)
    assert np.allclose(trigspline.estimate_slopes(x, f, "akima"), ak(x, 1), rtol=1e-12,
                       atol=1e-13)


@pytest.mark.parametrize("form", ["paper", "c1", "geometric"])
def test_probabilities_touch_constant_bounds(form):
    """Data with exact 0 and 1 between y = 0 and y = 1 (docs/method.md §5.8):
    built, certified, every sample inside [0, 1] to the evaluation's rounding
    (16 eps of the values, as the C tests), the knots kept exactly."""
    x = np.arange(10.0)
    p = np.array([0, 0, 0.1, 0.5, 0.9, 1, 1, 0.7, 0.2, 0])
    s = Spline(x, p, shape="between", lower=(0, 0), upper=(0, 1), form=form)
    assert s.certified
    y = s(np.linspace(0, 9, 20001))
    assert y.min() >= 0 and y.max() <= 1 + 16 * EPS
    assert np.array_equal(s(x), p)
    with pytest.raises(TrigsplineError):
        Spline(x, np.where(p == 1, 1 + 2 * EPS, p), shape="between", lower=(0, 0), upper=(0, 1))


def test_core_defaults_are_the_library_inits():
    """_core.defaults(): the ts_*_options_init values by field name, enumerations by
    their canonical names (the header's defaults, include/trigspline.h)."""
    from trigspline import _core
    d = _core.defaults()
    assert set(d) == {"spline", "curve", "surface"}
    sp, cu, su = d["spline"], d["curve"], d["surface"]
    form, slopes, alpha, beta, margin, certify = _core.options_defaults()
    assert ["paper", "c1", "geometric"][form] == sp["form"] == "geometric"
    assert sp["slopes"] == "steffen" and slopes == 8
    assert (sp["alpha"], sp["beta"], sp["margin"]) == (alpha, beta, margin) == (0.85, 0.0, 0.01)
    assert sp["certify"] is bool(certify) is True
    assert (sp["shape"], sp["extrapolate"]) == ("none", "error")
    assert sp["lower"] == sp["upper"] == (0.0, 0.0)
    assert (cu["param"], cu["closed"], cu["slopes"]) == ("centripetal", False, "arithmetic")
    assert (cu["alpha"], cu["beta"], cu["margin"]) == (1.0, 0.0, 0.01)
    assert cu["has_lo"] == cu["has_hi"] == (False, False, False)
    sform, sslopes, twist, salpha, sbeta, smargin = _core.surface_options_defaults()
    assert (su["form"], su["slopes"], su["shape"]) == ("paper", "arithmetic", "none")
    assert (su["zero_twist"], su["alpha"], su["beta"], su["margin"]) == \
        (bool(twist), salpha, sbeta, smargin)
    assert (su["has_lower"], su["has_upper"]) == (False, False)
