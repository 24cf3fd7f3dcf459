"""The defaults keep PCHIP's promise (docs/method.md §5.10): SciPy's TestPCHIP
checks that apply, the example, paper and real-world data against SciPy's
PchipInterpolator, lines, knots; complex and zero-size data as SciPy does.

Expected values come from SciPy (PchipInterpolator's cubic pieces, their
exact extrema) and closed forms, never from this library's output."""
import glob
import math
import os
import warnings

import numpy as np
import pytest

import trigspline
from trigspline import Spline, TrigsplineError, interp
from conftest import REPO

interpolate = pytest.importorskip("scipy.interpolate")


def read_csv(path):
    rows, header = [], None
    with open(path) as fh:
        for line in fh:
            line = line.strip()
            if not line or line.startswith("#"):
                continue
            if header is None:
                header = line
                continue
            rows.append([float(v) for v in line.split(",")[:2]])
    a = np.array(rows)
    return a[:, 0], a[:, 1]


def datasets():
    out = {}
    for pat in ("data/examples/*.csv", "data/paper/table*.csv", "data/realworld/*.csv"):
        for p in sorted(glob.glob(os.path.join(REPO, pat))):
            x, y = read_csv(p)
            if len(x) >= 2 and np.all(np.diff(x) > 0):
                out[os.path.relpath(p, REPO)] = (x, y)
    return out


def excursion(s):
    """The library's exact excursion beyond each interval's data (§5.9)."""
    return max(max(r["excursion_above"], r["excursion_below"]) for r in s.report())


def pchip_excursion(x, y):
    """SciPy's PCHIP: exact extrema of each cubic piece (roots of its derivative)."""
    pp = interpolate.PchipInterpolator(x, y)
    worst = 0.0
    for i in range(len(x) - 1):
        c3, c2, c1, c0 = pp.c[:, i]
        h = x[i + 1] - x[i]
        cands = [0.0, h]
        A, B, C = 3 * c3, 2 * c2, c1
        if A != 0:
            disc = B * B - 4 * A * C
            if disc >= 0:
                r = math.sqrt(disc)
                q = -0.5 * (B + math.copysign(r, B))
                cands += [t for t in [q / A] + ([C / q] if q != 0 else []) if 0 < t < h]
        elif B != 0 and 0 < -C / B < h:
            cands.append(-C / B)
        v = [((c3 * t + c2) * t + c1) * t + c0 for t in cands]
        lo, hi = min(y[i], y[i + 1]), max(y[i], y[i + 1])
        worst = max(worst, max(v) - hi, lo - min(v))
    return worst


# rounding of a convex combination of the data: a few ulps of the data's size
def tol(y):
    return 8 * np.finfo(float).eps * float(np.max(np.abs(y)))


@pytest.mark.parametrize("kw", [{}, {"shape": "positive"}])
def test_scipy_pchip_overshoot_and_monotone(kw):
    # TestPCHIP.test_overshoot / test_monotone (scipy/interpolate/tests/test_polyint.py)
    np.random.seed(1234)
    xi = np.sort(np.random.random(20))
    yi = np.random.random(20)
    p = Spline(xi, yi, **kw)
    assert excursion(p) <= tol(yi)
    for i in range(len(xi) - 1):
        y1, y2 = sorted((yi[i], yi[i + 1]))
        yp = p(np.linspace(xi[i], xi[i + 1], 10))
        assert ((y1 <= yp + 1e-15) & (yp <= y2 + 1e-15)).all()
        dy = yi[i + 1] - yi[i]
        assert (dy * (yp[1:] - yp[:1]) > 0).all()
        assert (dy * np.diff(yp) > 0).all()


@pytest.mark.parametrize("kw", [{}, {"shape": "positive"}])
def test_scipy_pchip_endslopes_two_points_zeros(kw):
    # TestPCHIP.test_endslopes: the end slopes are not 0 on these data
    x = np.array([0.0, 0.1, 0.25, 0.35])
    for yy in (np.array([279.35, 0.5e3, 1.0e3, 2.5e3]), np.array([279.35, 2.5e3, 1.50e3, 1.0e3])):
        pp = Spline(x, yy, **kw)
        for t in (x[0], x[-1]):
            assert pp(t, 1) != 0
    # test_two_points: the straight line (exact in the geometric form, §4)
    xx = np.linspace(0, 1, 11)
    p2 = Spline(np.array([0.0, 1.0]), np.array([0.0, 2.0]), **kw)
    assert np.max(np.abs(p2(xx) - 2 * xx)) <= 2 * np.finfo(float).eps * 2
    # test_all_zeros: zeros, no warning
    with warnings.catch_warnings():
        warnings.simplefilter("error")
        pz = Spline(np.arange(10.0), np.zeros(10), **kw)
        assert np.all(pz(np.linspace(0, 9, 101)) == 0.0)


def test_monotone_data_never_leave_their_interval():
    # random monotone data, uneven spacing: excursion 0 to rounding
    rng = np.random.default_rng(26)
    for _ in range(200):
        n = rng.integers(2, 40)
        x = np.cumsum(rng.uniform(0.01, 3, n))
        y = np.cumsum(rng.exponential(1, n)) * rng.choice([-1, 1])
        for kw in ({}, {"shape": "positive"} if (y > 0).all() else {}):
            assert excursion(Spline(x, y, **kw)) <= tol(y)


def test_corpus_never_worse_than_pchip():
    data = datasets()
    real = [k for k in data if k.startswith("data/realworld")]
    assert len(real) >= 10
    rows = []
    for name, (x, y) in data.items():
        s = Spline(x, y)
        ours, theirs = excursion(s), pchip_excursion(x, y)
        rows.append((name, ours, theirs))
        # PCHIP's own excursion is rounding (<= 5e-14 of the range measured):
        # ours must not exceed max(PCHIP's, our rounding)
        assert ours <= max(theirs, tol(y)), (name, ours, theirs)
        assert np.array_equal(s(x), y), name                     # knots exact
        # a straight line through the same abscissae: reproduced to rounding
        # (the geometric form is exact on lines, §4; evaluation rounds a few ulps)
        line = 3.0 * (x - x[0]) / (x[-1] - x[0]) - 2.0
        xq = np.linspace(x[0], x[-1], 2001)
        want = 3.0 * (xq - x[0]) / (x[-1] - x[0]) - 2.0
        assert np.max(np.abs(Spline(x, line)(xq) - want)) <= 64 * np.finfo(float).eps, name
    print("\nexcursion (ours, PCHIP):")
    for r in rows:
        print("  %-45s %.3g %.3g" % r)


def test_defaults_are_the_library_s():
    d = trigspline.defaults("spline")
    assert (d["form"], d["slopes"], d["alpha"]) == ("geometric", "steffen", 0.85)
    assert d["alpha"] >= 8 / (3 * math.pi)


# ---- complex and zero-size data, as SciPy's interpolators

def test_complex_f_is_two_real_splines():
    x = np.array([1.0, 2, 3, 4])
    f = np.array([1, 2, 1j, 3])
    with warnings.catch_warnings():
        warnings.simplefilter("error")  # no ComplexWarning: nothing is cut
        s = Spline(x, f)
        y = s(x)
    assert np.array_equal(y, f)
    xq = np.linspace(1, 4, 31)
    want = Spline(x, f.real)(xq) + 1j * Spline(x, f.imag)(xq)
    assert np.array_equal(s(xq), want)
    assert np.array_equal(s(xq, 1), Spline(x, f.real)(xq, 1) + 1j * Spline(x, f.imag)(xq, 1))
    f2 = np.stack([f, 2 * f], axis=1)   # (4, 2) complex: series along the second axis
    assert s(xq).shape == (31,) and Spline(x, f2)(xq).shape == (31, 2)
    assert np.array_equal(interp(x, f, xq), want)


def test_complex_refused_where_it_cannot_mean_anything():
    x = np.array([1.0, 2, 3, 4])
    f = np.array([1, 2, 1j, 3])
    for kw in ({"shape": "positive"}, {"lower": (0, 0)}, {"shape": "monotone"}):
        with pytest.raises(TrigsplineError, match="complex"):
            Spline(x, f, **kw)
    with pytest.raises(TrigsplineError, match="complex"):
        interp(x, f, [1.5], shape="positive")
    with pytest.raises(TrigsplineError, match="complex"):
        Spline(x + 0j, [1, 2, 3, 4])
    with pytest.raises(TrigsplineError, match="complex"):
        interp(x + 0j, np.array([1.0, 2, 3, 4]), [1.5])


def test_zero_size_f_gives_empty_results():
    x = np.arange(6.0)
    xq = np.linspace(0, 5, 3)
    assert Spline(x, np.zeros((6, 0)))(xq).shape == (3, 0)
    assert interp(x, np.zeros((6, 0)), xq, axis=0).shape == (3, 0)
    assert interp(x, np.zeros((0, 6)), xq).shape == (0, 3)
