"""trigspline.disaggregate and da.trigspline.disaggregate (docs/method.md §12):
totals kept, no negative value, C¹ with r'' jumps well below those of
PCHIP on the cumulative sum (SciPy), numpy and dask equal bit for bit."""
import os

import numpy as np
import pytest

import trigspline
from trigspline import TrigsplineError

RAIN = os.path.join(os.path.dirname(__file__), "..", "..", "..", "data", "examples",
                    "rainfall_daily.csv")


def intermittent(rng, n, dry=0.62):
    """Seeded daily series: about 62 % dry days, gamma amounts, spikes x1000."""
    t = np.where(rng.random(n) < dry, 0.0, rng.gamma(0.8, 9.0, n))
    t[rng.random(n) < 0.03] *= 1000.0
    return t


def rainfall():
    with open(RAIN) as f:
        rows = [ln.split(",") for ln in f if ln[:1].isdigit()]
    t = np.array([float(r[1]) for r in rows])
    return np.arange(t.size + 1.0), t


def test_totals_and_signs_many_series():
    rng = np.random.default_rng(29)
    n, sub = 48, 24
    t = np.stack([intermittent(rng, n) for _ in range(2000)])
    assert (t == 0).mean() >= 0.6
    e = np.arange(n + 1.0)
    g = np.linspace(0.0, n, n * sub + 1)
    cells = trigspline.disaggregate(e, t, g)
    assert cells.shape == (2000, n * sub)
    assert (cells >= 0).all()
    back = cells.reshape(2000, n, sub).sum(-1)
    # the cells of a bin add up to its total: sums of 24 rounded values
    np.testing.assert_allclose(back, t, rtol=1e-13, atol=0)
    rate = trigspline.disaggregate(e, t, np.linspace(0.0, n, n * 97 + 1), kind="rate")
    assert (rate >= 0).all()
    # a dry bin is dry throughout
    dry = np.repeat(t == 0, sub, axis=1)
    assert (cells[dry] == 0).all()


def _rpp_jumps(e, t):
    """Largest jump of r'' at the knots: ours by one-sided second-order
    differences of r' (step 1e-4 of a quarter bin: truncation ~1e-8 of r'''
    scale, far below the jumps compared), PCHIP-on-cumulative's exactly
    (its rate's r'' is 6 times the cubic coefficient, constant per bin)."""
    from scipy.interpolate import PchipInterpolator
    P = PchipInterpolator(e, np.concatenate([[0.0], np.cumsum(t)]))
    pchip = np.abs(np.diff(6.0 * P.c[0])).max()
    q = np.diff(e)[:, None] * np.array([0.25, 0.5, 0.75])[None, :]
    knots = np.sort(np.concatenate([e[1:-1], (e[:-1, None] + q).ravel()]))
    d = 1e-4 * 0.25 * np.diff(e).min()

    def rp(x):
        return trigspline.disaggregate(e, t, x, kind="derivative")
    r0, l1, l2, p1, p2 = rp(knots), rp(knots - d), rp(knots - 2 * d), rp(knots + d), rp(knots + 2 * d)
    left = (3 * r0 - 4 * l1 + l2) / (2 * d)
    right = (-3 * r0 + 4 * p1 - p2) / (2 * d)
    return np.abs(right - left).max(), pchip


def test_second_derivative_jumps_against_pchip_on_cumulative():
    rng = np.random.default_rng(60)
    worst = 0.0
    for _ in range(100):
        t = intermittent(rng, 60)
        e = np.arange(61.0)
        ours, pchip = _rpp_jumps(e, t)
        if pchip > 0:
            worst = max(worst, ours / pchip)
    assert worst <= 0.5, worst
    e, t = rainfall()
    ours, pchip = _rpp_jumps(e, t)
    assert ours <= 0.5 * pchip, (ours, pchip)


def test_c1_at_edges():
    e, t = rainfall()
    x = e[1:-1]
    d0 = trigspline.disaggregate(e, t, x, kind="derivative")
    # r' just left of each edge, continued to the edge by the second-order
    # one-sided formula (its truncation is far below 1e-6 of the scale)
    h = 1e-5
    left = 2 * trigspline.disaggregate(e, t, x - h, kind="derivative") - \
        trigspline.disaggregate(e, t, x - 2 * h, kind="derivative")
    scale = max(np.abs(d0).max(), t.max())
    assert np.abs(left - d0).max() <= 1e-6 * scale


def test_errors():
    e = np.arange(4.0)
    g = np.linspace(0, 3, 7)
    with pytest.raises(TrigsplineError) as ex:
        trigspline.disaggregate(e, [1.0, -1.0, 2.0], g)
    assert ex.value.name == "TS_ERR_NEGATIVE" and ex.value.index == 1
    # the library's sentence, naming the bin and its values
    assert "bin 1 [1, 2]: total -1 is negative; totals must be >= 0" in str(ex.value)
    with pytest.raises(TrigsplineError) as ex:
        trigspline.disaggregate(e, [[1.0, 2.0, 3.0], [1.0, 2.0, -3.0]], g)
    assert "bin 2 [2, 3]: total -3 is negative" in str(ex.value)
    assert ex.value.series == (1,)
    with pytest.raises(TrigsplineError) as ex:
        trigspline.disaggregate([0.0, 1.0, 1.0, 3.0], [1.0, 2.0, 3.0], g)
    assert ex.value.name == "TS_ERR_UNSORTED"
    assert "edge 2 (x = 1) is not greater than the previous edge 1" in str(ex.value)
    with pytest.raises(TrigsplineError) as ex:
        trigspline.disaggregate(e, [1.0, 2.0], g)
    assert ex.value.name == "TS_ERR_LENGTH"
    with pytest.raises(TrigsplineError) as ex:
        trigspline.disaggregate(e, [1.0, 2.0, 3.0], [0.0, 4.0])
    assert ex.value.name == "TS_ERR_DOMAIN" and ex.value.where == "query"
    with pytest.raises(TrigsplineError) as ex:
        trigspline.disaggregate(e, [1.0, 5.0, 1.0], g, hi=4.0)
    assert ex.value.name == "TS_ERR_INFEASIBLE"
    assert "bin 1 [1, 2]: total 5 gives the mean 5, outside the rate bounds [0, 4]" in str(ex.value)
    with pytest.raises(TrigsplineError) as ex:
        # means 0 and 1 under hi = 1: no edge value joins them (docs/method.md §12.4)
        trigspline.disaggregate(e, [0.0, 1.0, 1.0], g, hi=1.0)
    assert ("bin 0 [0, 1] and bin 1 [1, 2]: the means 0 and 1 are too far apart"
            in str(ex.value))
    with pytest.raises(ValueError):
        trigspline.disaggregate(e, [1.0, 2.0, 3.0], g, kind="median")
    out = trigspline.disaggregate(e, [[1.0, -1.0, 2.0], [1.0, 2.0, 3.0]], g, errors="nan")
    assert np.isnan(out[0]).all() and np.isfinite(out[1]).all()


def test_bounds():
    e = np.arange(6.0)
    t = np.array([1.0, 2.0, 2.5, 2.0, 1.5])  # neighbours within (hi - lo)/2: §12.4
    r = trigspline.disaggregate(e, t, np.linspace(0, 5, 501), kind="rate", lo=0.5, hi=3.0)
    assert (r >= 0.5).all() and (r <= 3.0).all()
    c = trigspline.disaggregate(e, t, np.linspace(0, 5, 21), lo=0.5, hi=3.0)
    np.testing.assert_allclose(c.reshape(5, 4).sum(-1), t, rtol=1e-14)


def test_xarray_numpy_and_dask():
    xr = pytest.importorskip("xarray")
    pytest.importorskip("dask.array")
    import pandas as pd
    rng = np.random.default_rng(7)
    t = pd.date_range("2021-03-01", periods=30, freq="D")
    v = np.stack([intermittent(rng, 30) for _ in range(6)])
    da = xr.DataArray(v, dims=("station", "time"), coords={"time": t, "station": np.arange(6)})
    h = da.trigspline.disaggregate(time="1h")
    assert h.sizes == {"station": 6, "time": 720}
    assert h.time.values[1] - h.time.values[0] == np.timedelta64(1, "h")
    np.testing.assert_allclose(h.values.reshape(6, 30, 24).sum(-1), v, rtol=1e-13)
    assert (h.values >= 0).all()
    hd = da.chunk({"station": 2, "time": 7}).trigspline.disaggregate(time="1h")
    assert hd.chunks is not None
    assert np.array_equal(hd.values, h.values)  # bit for bit
    r = da.trigspline.disaggregate(time="1h", kind="rate")
    assert (r.values >= 0).all()
    with pytest.raises(ValueError):
        da.trigspline.disaggregate(time="7h")  # 30 days are not whole 7 h steps
    ds = xr.Dataset({"rain": da, "elev": ("station", np.arange(6.0))})
    dh = ds.trigspline.disaggregate(time="1h")
    assert np.array_equal(dh["rain"].values, h.values) and "elev" in dh
    num = xr.DataArray([0.0, 3.0, 0.0], dims="x", coords={"x": [0.0, 2.0, 4.0]})
    cells = num.trigspline.disaggregate(x=0.5)
    assert cells.sizes["x"] == 12 and abs(float(cells.sum()) - 3.0) < 1e-14


def test_per_bin_fast_path():
    rng = np.random.default_rng(11)
    t = np.stack([intermittent(rng, 40) for _ in range(50)])
    e = np.arange(41.0)
    fast = trigspline.disaggregate(e, t, per_bin=24)
    grid = trigspline.disaggregate(e, t, np.arange(40 * 24 + 1) / 24.0)
    assert fast.shape == grid.shape == (50, 960)
    assert (fast >= 0).all()
    # the same cells by two paths: to rounding of the bin totals (the grid's
    # points k/24 are rounded, moving a cell by an ulp of x times the rate)
    scale = np.repeat(np.maximum(t, 1e-300), 24, axis=1)
    assert (np.abs(fast - grid) / scale).max() <= 1e-13
    np.testing.assert_allclose(fast.reshape(50, 40, 24).sum(-1), t, rtol=1e-13)
    with pytest.raises(ValueError):
        trigspline.disaggregate(e, t, per_bin=24, kind="rate")
    with pytest.raises(ValueError):
        trigspline.disaggregate(e, t)
