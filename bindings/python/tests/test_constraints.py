"""Constraint records from Python (docs/method.md §13): Spline(constraints=[...]).

A Black-Scholes call chain (closed form here, S0 = 100, sigma = 0.2, T = 1,
r = 0) certified convex, decreasing, with S' >= -1 and S >= 0: its implied
density S'' is >= 0 everywhere, where SciPy's CubicSpline through the same
prices is not convex (its second derivative, exact per piece, dips below
0), nor is PCHIP's; the report's exact minima against dense sampling of the spline's own
derivatives; SPEC strings and dicts give the same spline; refusals name the
record.
"""
import math
import pickle

import numpy as np
import pytest

import trigspline
from trigspline import Spline, TrigsplineError

K = np.array([60, 70, 80, 90, 100, 105, 110, 120, 140], dtype=float)


def _calls():
    from math import erfc, log, sqrt
    out = []
    for k in K:
        d1 = (log(100.0 / k) + 0.02) / 0.2
        out.append(100.0 * 0.5 * erfc(-d1 / sqrt(2)) - k * 0.5 * erfc(-(d1 - 0.2) / sqrt(2)))
    return np.array(out)


C = _calls()
SPECS = ["convex", "decreasing", "slope>=-1", "lower=0"]


def test_option_chain_certified_convex():
    s = Spline(K, C, constraints=SPECS)
    assert s.certified
    rep = s.constraint_report()
    assert len(rep) == 4 and all(len(r) == len(K) - 1 for r in rep)
    for k, spec in enumerate(SPECS):
        for i in range(len(K) - 1):
            r = rep[k][i]
            # the exact minimum in floating point: >= 0 up to its rounding
            assert r is not None and r["certified"] and r["gap"] >= -1e-12
            xs = np.linspace(K[i], np.nextafter(K[i + 1], -np.inf), 2001)  # interval i only
            d0, d1, d2 = s(xs), s(xs, 1), s(xs, 2)
            q = {"convex": d2, "decreasing": -d1, "slope>=-1": d1 + 1.0, "lower=0": d0}[spec]
            # the exact minimum is below every sample (1e-9 relative: the
            # samples' rounding) and near the smallest (grid resolution)
            assert r["gap"] <= q.min() + 1e-9 * (1 + abs(q.min()))
            assert q.min() - r["gap"] <= 1e-4 * (1 + abs(q.min()))
    xs = np.linspace(K[0], K[-1], 20001)
    assert (s(xs, 2) >= -1e-12).all()


def test_scipy_cubic_spline_is_not_convex_there():
    scipy_interp = pytest.importorskip("scipy.interpolate")
    cs = scipy_interp.CubicSpline(K, C)
    # S'' of a cubic is linear per piece: its minimum is at a knot
    assert min(cs(K, 2)) < 0.0
    # PCHIP's second derivative (piecewise linear too) dips below 0 as well
    pc = scipy_interp.PchipInterpolator(K, C)
    assert min(pc(np.linspace(K[0], K[-1], 100001), 2)) < 0.0


def test_spec_strings_and_dicts_agree():
    a = Spline(K, C, constraints=SPECS + ["abs-slope<=1.5@2-4", "lower=poly:50,30;100,3;140,0.2"])
    b = Spline(K, C, constraints=[{"kind": "convex"}, {"kind": "decreasing"},
                                  {"kind": "slope-min", "value": -1}, {"kind": "lower"},
                                  {"kind": "slope-abs", "value": 1.5, "first": 2, "count": 3},
                                  {"kind": "lower", "points": [(50, 30), (100, 3), (140, 0.2)]}])
    xs = np.linspace(60, 140, 777)
    assert np.array_equal(a(xs), b(xs))
    rep = a.constraint_report()
    assert [r is None for r in rep[4]] == [True, True, False, False, False, True, True, True]
    c = pickle.loads(pickle.dumps(a))
    assert np.array_equal(c(xs), a(xs))


def test_refusals_name_the_record():
    with pytest.raises(TrigsplineError, match=r"not concave here.*constraint 0, concave"):
        Spline(K, C, constraints=["concave"])
    with pytest.raises(TrigsplineError, match=r"beyond the slope-max bound"):
        Spline(K, C, constraints=["slope<=-0.99"])
    with pytest.raises(ValueError, match="unknown constraint"):
        Spline(K, C, constraints=["wiggly"])
    with pytest.raises(ValueError, match="constraint kind"):
        Spline(K, C, constraints=[{"kind": "bumpy"}])


def test_hagan_west_forwards_positive_where_cubic_spline_goes_negative():
    """Hagan & West's test curve: zero rates 8.1, 7, 4.4, 7, 4, 3 % at
    t = 0.1, 1, 4, 9, 20, 30.  Fitting y = t r (with y(0) = 0) increasing
    with y' >= 0.005 certifies the forward y' >= 0.005; SciPy's CubicSpline
    through the same y has negative forwards."""
    t = np.array([0.0, 0.1, 1.0, 4.0, 9.0, 20.0, 30.0])
    r = np.array([0.081, 0.081, 0.07, 0.044, 0.07, 0.04, 0.03])
    y = t * r
    s = Spline(t, y, constraints=["increasing", "slope>=0.005"])
    assert s.certified
    assert all(c["certified"] and c["gap"] >= -1e-12 for row in s.constraint_report() for c in row)
    xs = np.linspace(0, 30, 30001)
    fwd = s(xs, 1)
    assert np.isfinite(fwd).all() and fwd.min() >= 0.005 - 1e-12
    assert np.allclose(s(t[1:]) / t[1:], r[1:], rtol=1e-15, atol=0)
    scipy_interp = pytest.importorskip("scipy.interpolate")
    assert scipy_interp.CubicSpline(t, y)(xs, 1).min() < 0.0



def test_bound_given_by_another_spline():
    """docs/method.md §13.7: the calls above their intrinsic value 100 - K,
    given as a Spline through points of that line on [40, 99] (default
    geometric form: collinear points give the line itself, §4), and below
    a paper-form spline 5 above the calls; every report certified, its
    minimum against dense samples of S - B; the bound may be dropped after
    the fit (the fitted spline keeps its own copy) and the fit pickles."""
    kb = np.array([40.0, 55.0, 70.0, 85.0, 99.0])
    floor = Spline(kb, 100.0 - kb)
    ceil = Spline(K, C + 5.0, form="paper")
    s = Spline(K, C, constraints=["convex", {"kind": "lower", "spline": floor},
                                  {"kind": "upper", "spline": ceil}])
    assert s.certified
    rep = s.constraint_report()
    for k, (b, sg) in ((1, (floor, 1.0)), (2, (ceil, -1.0))):
        for i in range(len(K) - 1):
            r = rep[k][i]
            if k == 1 and K[i] >= 99.0:
                assert r is None  # beyond the bound curve's last knot
                continue
            assert r is not None and r["certified"] and r["gap"] > 0.0
            hi = min(K[i + 1], 99.0) if k == 1 else K[i + 1]
            xs = np.linspace(K[i], hi, 2001)
            q = sg * (s(xs) - b(xs))
            # below every sample (both evaluations' rounding, 1e-9 relative)
            # and near the smallest (grid resolution)
            assert r["gap"] <= q.min() + 1e-9 * (1 + abs(q.min()))
            assert q.min() - r["gap"] <= 1e-4 * (1 + abs(q.min()))
    xs = np.linspace(K[0], K[-1], 777)
    del floor, ceil
    c = pickle.loads(pickle.dumps(s))
    assert np.array_equal(c(xs), s(xs))
    assert c.constraint_report()[1][0]["gap"] == rep[1][0]["gap"]


def test_bound_spline_refusals():
    kb = np.array([40.0, 55.0, 70.0, 85.0, 99.0])
    floor = Spline(kb, 100.0 - kb)
    # the calls are above their intrinsic value: as an upper bound, point 0 is across
    with pytest.raises(TrigsplineError, match=r"point 0 .*not below the upper bound"):
        Spline(K, C, constraints=[{"kind": "upper", "spline": floor}])
    with pytest.raises(ValueError, match="is a bound"):
        Spline(K, C, constraints=[{"kind": "convex", "spline": floor}])
    with pytest.raises(ValueError, match="is a bound"):
        Spline(K, C, constraints=[{"kind": "lower", "spline": floor, "points": [(0, 0), (1, 1)]}])
    with pytest.raises(TypeError, match="must be a trigspline Spline"):
        Spline(K, C, constraints=[{"kind": "lower", "spline": [1, 2, 3]}])
    two = Spline(kb, np.stack([100.0 - kb, 90.0 - kb]), axis=-1)
    with pytest.raises(TypeError, match="one series"):
        Spline(K, C, constraints=[{"kind": "lower", "spline": two}])
