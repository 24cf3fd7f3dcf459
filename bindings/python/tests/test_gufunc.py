"""trigspline.interp (the gufunc) against one Spline per series.

The oracle for values is trigspline.Spline, fitted and evaluated one series
at a time (array queries, the batch path): the gufunc makes the same C calls,
so equality is exact; what is tested here is the gufunc's own work (strides,
broadcasting, dtypes, gaps, statuses, float32 rounding).  Shape guarantees
are checked on the outputs directly (>= 0, above the line) by dense sampling.
"""
import threading

import numpy as np
import pytest

from trigspline import Spline, TrigsplineError
from trigspline import _gufunc
from trigspline.interp import interp, pack_options, status_message

TS_ERR_TOO_FEW, TS_ERR_NONFINITE, TS_ERR_NEGATIVE = 4, 5, 14
TS_ERR_OPTION, TS_ERR_SIDE = 11, 15


def rain(rng, shape, n, zeros=0.4):
    """Precipitation-like: exact zeros and heavy-tailed positive values."""
    v = rng.pareto(2.5, size=shape + (n,))
    v[rng.random(shape + (n,)) < zeros] = 0.0
    return v


def knots(rng, n):
    return np.cumsum(rng.uniform(0.2, 2.0, n))


def one_by_one(x, f, xq, **kw):
    """Spline per series; NaN outside the data (interp's extrapolate='nan')."""
    out = np.full(f.shape[:-1] + xq.shape[-1:], np.nan)
    for idx in np.ndindex(f.shape[:-1]):
        xi = x[idx] if x.ndim > 1 else x
        qi = xq[idx] if xq.ndim > 1 else xq
        inside = (qi >= xi[0]) & (qi <= xi[-1])
        out[idx][inside] = Spline(xi, f[idx], **kw)(qi[inside])
    return out


@pytest.mark.parametrize("form", ["paper", "geometric", "c1"])
def test_positive_bit_identical_to_spline(form):
    rng = np.random.default_rng(1)
    x = knots(rng, 60)
    f = rain(rng, (3, 4), 60)
    xq = np.sort(rng.uniform(x[0] - 1, x[-1] + 1, 501))
    y = interp(x, f, xq, shape="positive", form=form, extrapolate="nan")
    ref = one_by_one(x, f, xq, shape="positive", form=form)
    assert y.shape == (3, 4, 501)
    np.testing.assert_array_equal(y, ref)
    assert np.nanmin(y) >= 0.0


@pytest.mark.parametrize("shape,kw", [
    ("none", {}),
    ("monotone", {}),
    ("above", {"lower": (0.01, -0.5)}),
    ("below", {"upper": (0.0, 40.0)}),
    ("between", {"lower": (0.0, -0.5), "upper": (0.0, 40.0)}),
])
def test_other_shapes_bit_identical(shape, kw):
    rng = np.random.default_rng(2)
    x = knots(rng, 40)
    f = rain(rng, (5,), 40, zeros=0.0)
    if shape == "monotone":
        f = np.cumsum(f, axis=-1)
    xq = np.linspace(x[0], x[-1], 333)
    y = interp(x, f, xq, shape=shape, **kw)
    np.testing.assert_array_equal(y, one_by_one(x, f, xq, shape=shape, **kw))
    if shape == "monotone":
        assert (np.diff(y, axis=-1) >= 0).all()
    if "lower" in kw:
        m, c = kw["lower"]
        assert (y > m * xq + c).all()


def test_slopes_alpha_margin_extrapolate_passed_through():
    rng = np.random.default_rng(3)
    x = knots(rng, 30)
    f = rain(rng, (2,), 30)
    xq = np.linspace(x[0] - 3, x[-1] + 3, 200)
    for ex in ("clamp", "extend", "linear"):
        for sl in ("fritsch-carlson", "akima", "harmonic"):
            y = interp(x, f, xq, shape="positive", slopes=sl, alpha=0.4, margin=0.05,
                       extrapolate=ex)
            for i in range(2):
                s = Spline(x, f[i], shape="positive", slopes=sl, alpha=0.4, margin=0.05,
                           extrapolate=ex)
                np.testing.assert_array_equal(y[i], s(xq))


def test_broadcasting_and_axis():
    rng = np.random.default_rng(4)
    n, m = 25, 17
    x = np.sort(rng.uniform(0, 10, (3, 1, n)), axis=-1)        # knots per row
    f = rain(rng, (3, 4), n, zeros=0.0)
    xq = np.sort(rng.uniform(0, 10, (2, 1, 1, m)), axis=-1)    # two query sets
    y = interp(x, f, xq, shape="positive", extrapolate="clamp")
    assert y.shape == (2, 3, 4, m)
    for a in range(2):
        for i in range(3):
            for j in range(4):
                s = Spline(x[i, 0], f[i, j], shape="positive", extrapolate="clamp")
                np.testing.assert_array_equal(y[a, i, j], s(xq[a, 0, 0]))
    # axis: series along axis 0 of a (n, 3) array, non-contiguous views
    f2 = np.asfortranarray(rain(rng, (3,), n).T)
    x2 = np.linspace(0, 1, n)
    q2 = np.linspace(0, 1, 9)
    y2 = interp(x2, f2, q2, shape="positive", axis=0)
    assert y2.shape == (9, 3)
    for j in range(3):
        np.testing.assert_array_equal(y2[:, j], Spline(x2, f2[:, j], shape="positive")(q2))
    # strided data (every other point) give the fit of the strided series
    f3 = rain(rng, (2,), 2 * n)[:, ::2]
    np.testing.assert_array_equal(interp(x2, f3, q2, shape="positive"),
                                  interp(x2, np.ascontiguousarray(f3), q2, shape="positive"))


# The paper's options (docs/method.md §3): the float32 checks below need a curve
# that comes closer to the bound than the data, which the defaults' curve
# (inside each interval's data range, docs/method.md §5.10) never does.
PAPER = {"form": "paper", "slopes": "arithmetic", "alpha": 1.0}


def test_float32_bound_and_exact_knots():
    rng = np.random.default_rng(5)
    x = np.arange(200, dtype=np.float64)
    f = rain(rng, (50,), 200).astype(np.float32)
    f[:, ::7] *= np.float32(1e-30)                 # tiny values: outputs near the subnormals
    xq = np.concatenate([x, np.linspace(0, 199, 4001)])
    with np.errstate(all="raise"):
        y = interp(x, f, xq, shape="positive", **PAPER)
        y64 = interp(x, f.astype(np.float64), xq, shape="positive", **PAPER)
    assert y.dtype == np.float32
    np.testing.assert_array_equal(y[:, :200], f)   # knots come back exactly
    assert (y >= 0).all()
    # positive wherever the float64 curve is (a value below half the least
    # subnormal would round to 0: moved up one step instead)
    assert (y[y64 > 0] > 0).all()
    # otherwise it is the float64 value rounded to nearest
    plain = y64.astype(np.float32)
    moved = y != plain
    assert (plain[moved] == 0).all() and (y[moved] == np.nextafter(np.float32(0), np.float32(1))).all()
    assert moved.any()


def test_float32_keeps_a_line_rounding_would_cross():
    # data one and 64 float32 steps above the line y = 1; the curve dips
    # towards the line between knots, closer than half a float32 step
    e = np.float32(2.0 ** -23)
    f = np.float32(1) + e * np.array([64, 1, 1, 64, 1, 1, 64], dtype=np.float32)
    x = np.arange(7.0)
    xq = np.linspace(0, 6, 20001)
    y = interp(x, f, xq, lower=(0.0, 1.0), shape="above", **PAPER)
    y64 = interp(x, f.astype(np.float64), xq, lower=(0.0, 1.0), shape="above", **PAPER)
    assert (y64 > 1).all()
    crossing = y64.astype(np.float32) <= 1         # plain rounding would touch the line
    assert crossing.any()
    assert (y > 1).all()
    np.testing.assert_array_equal(y[crossing], np.float32(1) + e)
    np.testing.assert_array_equal(y[::1000][::3], y[[0, 3000, 6000, 9000, 12000, 15000, 18000]])


def test_float32_monotone_stays_monotone():
    rng = np.random.default_rng(6)
    f = np.cumsum(rain(rng, (20,), 50), axis=-1).astype(np.float32)
    x = np.arange(50.0)
    y = interp(x, f, np.linspace(0, 49, 3001), shape="monotone")
    assert (np.diff(y, axis=-1) >= 0).all()


def test_nan_series_and_gaps():
    rng = np.random.default_rng(7)
    x = np.arange(30.0)
    f = rain(rng, (4,), 30)
    f[1, 10] = np.nan            # one gap
    f[2, :] = np.nan             # all missing
    f[3, 1:] = np.nan            # too few finite points
    xq = np.linspace(0, 29, 101)
    r = interp(x, f, xq, shape="positive", full=True)
    assert list(r.status) == [0, TS_ERR_NONFINITE, TS_ERR_NONFINITE, TS_ERR_NONFINITE]
    assert list(r.index) == [-1, 10, 0, 1]
    # the gap stays local: NaN exactly in the two intervals touching point 10
    np.testing.assert_array_equal(np.isnan(r.values[1]), (xq > 9) & (xq < 11))
    assert np.isnan(r.values[2:]).all() and not np.isnan(r.values[0]).any()
    assert not r.all_certified
    assert "NaN" in status_message(TS_ERR_NONFINITE) or "finite" in status_message(TS_ERR_NONFINITE)
    g = interp(x, f, xq, shape="positive", skipna=True, full=True)
    assert list(g.status) == [0, 0, TS_ERR_TOO_FEW, TS_ERR_TOO_FEW]
    keep = np.isfinite(f[1])
    np.testing.assert_array_equal(g.values[1], Spline(x[keep], f[1, keep], shape="positive")(xq))
    np.testing.assert_array_equal(g.values[0], r.values[0])
    # a gap at the ends: queries beyond the finite points are NaN
    h = f[0].copy()
    h[:5] = np.nan
    yh = interp(x, h, xq, shape="positive", skipna=True)
    assert np.isnan(yh[xq < 5]).all() and not np.isnan(yh[xq >= 5]).any()
    # NaN queries give NaN, not a failed series
    q = xq.copy()
    q[7] = np.nan
    rq = interp(x, f[0], q, shape="positive", full=True)
    assert rq.status == 0 and np.isnan(rq.values[7]) and not np.isnan(np.delete(rq.values, 7)).any()


def test_bad_series_status_and_errors_raise():
    x = np.arange(6.0)
    f = np.array([[1, 2, 3, 2, 1, 2], [1, 2, -3, 2, 1, 2]], dtype=float)
    r = interp(x, f, [0.5, 2.5], shape="positive", full=True, errors="nan")
    assert list(r.status) == [0, TS_ERR_NEGATIVE] and r.index[1] == 2
    assert np.isnan(r.values[1]).all()
    with pytest.raises(ValueError, match=r"series \(1,\).*point 2"):
        interp(x, f, [0.5], shape="positive")  # errors='raise', the default
    # one series (a 0-d status): the error names the point, no series
    with pytest.raises(TrigsplineError,
                       match=r"^point 2 \(x = 2, f = -3\) is negative.*at x = 2\)$") as e:
        interp(x, f[1], [0.5], shape="positive")
    assert e.value.status == TS_ERR_NEGATIVE and e.value.index == 2 and e.value.series is None
    with pytest.raises(TrigsplineError) as e:
        interp(x, f[0], [0.5], shape="monotone")
    assert e.value.status == 17 and e.value.where == "point"  # TS_ERR_NONMONOTONE
    # point 0 (f = 1) below y = 1.5 (on y = 1 it may touch: docs/method.md §5.8)
    r2 = interp(x, f[:1], [0.5], lower=(0.0, 1.5), shape="above", full=True, errors="nan")
    assert r2.status[0] == TS_ERR_SIDE and r2.index[0] == 0


def test_certificate_summary():
    rng = np.random.default_rng(8)
    x = np.arange(40.0)
    f = rain(rng, (6,), 40, zeros=0.0) + 0.5
    r = interp(x, f, np.linspace(0, 39, 50), shape="positive", full=True, gap=True)
    assert r.all_certified
    # the least gap is the least certified value: no sample may lie below it
    dense = interp(x, f, np.linspace(0, 39, 20001), shape="positive")
    assert (dense.min(axis=-1) >= r.gap * (1 - 1e-12)).all()
    assert r.least_gap == r.gap.min() > 0


def test_no_floating_point_warnings():
    rng = np.random.default_rng(9)
    x = knots(rng, 100)
    f = rain(rng, (30,), 100)
    f[0, 5] = np.nan
    f[1] = 0.0
    f[2, 50:] = 1e-300
    xq = np.concatenate([np.linspace(x[0] - 5, x[-1] + 5, 400), [np.nan, np.inf, -np.inf]])
    with np.errstate(under="ignore"):
        f32 = f.astype(np.float32)
    with np.errstate(all="raise"):
        for form in ("paper", "geometric"):
            for shape in ("positive", "none"):
                interp(x, f, xq, shape=shape, form=form, full=True, gap=True,
                       extrapolate="nan")
                interp(x, f32, xq, shape=shape, form=form, skipna=True, extrapolate="nan")
            interp(x, f, xq, shape="positive", form=form, extrapolate="extend")


def test_bad_options():
    x = np.arange(5.0)
    f = np.ones(5)
    for kw in ({"shape": "round"}, {"form": "cubic"}, {"slopes": "spline"},
               {"extrapolate": "wrap"}, {"alpha": 0}, {"alpha": np.nan}, {"margin": -1},
               {"shape": "above"}, {"shape": "positive", "lower": 1.0},
               {"errors": "ignore"}):
        with pytest.raises(ValueError):
            interp(x, f, x, **kw)
    with pytest.raises(ValueError, match="x has 4 points"):
        interp(x[:4], f, x)
    with pytest.raises(TypeError):
        interp(x, np.array(["a"] * 5), x)
    # a malformed option vector reaches C as a per-series status, not a crash
    opt = pack_options("positive")
    bad = opt.copy()
    bad[0] = 99
    _, st, _, _ = _gufunc.interp(x, f, x, bad)
    assert st == TS_ERR_OPTION
    _, st, _, _ = _gufunc.interp(x, f, x, opt[:5])
    assert st == TS_ERR_OPTION
    assert isinstance(_gufunc.strerror(10 ** 6), str)


def test_gil_released():
    # the main thread keeps running Python while a worker is inside the C loop
    rng = np.random.default_rng(10)
    x = np.arange(2000.0)
    f = rain(rng, (600,), 2000)
    xq = np.linspace(0, 1999, 4000)
    done = threading.Event()

    def work():
        interp(x, f, xq, shape="positive")
        done.set()

    t = threading.Thread(target=work)
    t.start()
    done.wait(0.01)
    count = 0
    while not done.is_set():
        count += 1
    t.join()
    assert count > 100
