"""derivative(), antiderivative(), integrate(), roots(), solve().  References:
finite differences, scipy.integrate.quad, dense sampling + bisection
(conftest.bisect_roots), closed forms."""
import numpy as np
import pytest

from trigspline import Spline, TrigsplineError
from conftest import bisect_roots

quad = pytest.importorskip("scipy.integrate").quad


def wavy(n=25, seed=3):
    rng = np.random.default_rng(seed)
    x = np.cumsum(rng.uniform(0.3, 1.2, n))
    return x, np.cos(1.3 * x) + 0.2 * rng.standard_normal(n)


@pytest.mark.parametrize("form", ["paper", "c1", "geometric"])
def test_derivative_objects(form):
    x, f = wavy()
    s = Spline(x, f, form=form)
    d1, d2 = s.derivative(), s.derivative(2)
    mids = 0.5 * (x[:-1] + x[1:])
    assert np.array_equal(d1(mids), s(mids, 1)) and np.array_equal(d2(mids), s(mids, 2))
    assert np.array_equal(d1.derivative()(mids), d2(mids))
    assert np.array_equal(d1(mids, 1), d2(mids))
    h = 1e-6
    fd = (s(mids + h) - s(mids - h)) / (2 * h)
    assert np.max(np.abs(d1(mids) - fd)) < 1e-6   # h² max|S'''| + ε max|S|/h
    assert s.derivative(0) is s


@pytest.mark.parametrize("form", ["paper", "c1", "geometric"])
def test_antiderivative_and_integrate(form):
    x, f = wavy()
    s = Spline(x, f, form=form)
    F = s.antiderivative()
    xq = np.linspace(x[0], x[-1], 37)
    # F against quad of S on each piece (quad's own estimate is < 1e-12 here)
    for v in xq[::6]:
        ref = sum(quad(lambda t: float(s(t)), a, b, epsabs=1e-13, epsrel=1e-13)[0]
                  for a, b in zip(np.r_[x[0], x[(x > x[0]) & (x < v)]],
                                  np.r_[x[(x > x[0]) & (x < v)], v]))
        assert abs(F(v) - ref) < 1e-10
    # derivative of F is S (finite differences), F(x0) = 0, integrate = F(b) - F(a)
    assert F(x[0]) == 0.0
    mids = 0.5 * (x[:-1] + x[1:])
    h = 1e-5
    assert np.max(np.abs((F(mids + h) - F(mids - h)) / (2 * h) - s(mids))) < 1e-7
    assert np.array_equal(F(mids, 1), s(mids))
    assert abs(s.integrate(x[2], x[7]) - (F(x[7]) - F(x[2]))) < 1e-12
    assert s.integrate(x[7], x[2]) == -s.integrate(x[2], x[7])
    assert F.derivative()(mids[0]) == s(mids[0])
    with pytest.raises(NotImplementedError):
        s.antiderivative(2)


@pytest.mark.parametrize("form", ["paper", "geometric"])
@pytest.mark.parametrize("mode", [True, "clamp", "linear"])
def test_integrate_outside(form, mode):
    x, f = wavy()
    s = Spline(x, f, form=form)
    a, b = x[0] - 0.7, x[-1] + 0.4
    ref = quad(lambda t: float(s(t, extrapolate=mode)), a, x[0], epsabs=1e-13)[0] + \
        s.integrate(x[0], x[-1]) + \
        quad(lambda t: float(s(t, extrapolate=mode)), x[-1], b, epsabs=1e-13)[0]
    assert abs(s.integrate(a, b, extrapolate=mode) - ref) < 1e-9
    F = s.antiderivative()
    assert abs(F(b, extrapolate=mode) - F(a, extrapolate=mode) - ref) < 1e-9
    assert np.isnan(s.integrate(a, b, extrapolate=False))       # SciPy: NaN
    with pytest.raises(TrigsplineError):
        s.integrate(a, b, extrapolate="error")
    with pytest.raises(TrigsplineError) as ei:
        s.integral(a, b)                                         # the library's own: inside only
    assert ei.value.name == "TS_ERR_DOMAIN"


@pytest.mark.parametrize("form", ["paper", "c1", "geometric"])
def test_roots_and_solve_against_bisection(form):
    x, f = wavy(40, seed=7)
    s = Spline(x, f, form=form)
    for y in (0.0, 0.3, -0.5):
        got = s.solve(y)
        ref = bisect_roots(lambda v: s(v), x[0], x[-1], y=y)
        assert len(got) == len(ref) and len(ref) > 0
        assert np.max(np.abs(got - ref)) < 1e-9
        assert np.max(np.abs(s(got) - y)) < 1e-12
    assert np.array_equal(s.roots(), s.solve(0.0))


def test_roots_at_knots_and_flat():
    # a root exactly at a knot is reported once; a flat interval at y gives (x_i, nan)
    x = np.array([0.0, 1.0, 2.0, 3.0, 4.0])
    f = np.array([1.0, 0.0, -1.0, -1.0, 2.0])
    s = Spline(x, f, slopes="fritsch-carlson", form="paper")
    r = s.roots()
    assert r[0] == 1.0 and np.sum(r == 1.0) == 1
    assert len(r) == 2 and 3.0 < r[1] < 4.0
    fl = s.solve(-1.0)
    assert fl[0] == 2.0 and np.isnan(fl[1])       # as scipy.interpolate.PPoly.roots
    # a positive spline with zero data touches 0 only at the zero knot
    p = Spline(x, np.array([1.0, 0.0, 2.0, 3.0, 1.0]), shape="positive")
    assert np.array_equal(p.roots(), [1.0])
