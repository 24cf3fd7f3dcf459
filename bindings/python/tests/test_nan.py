"""Missing values (NaN) stay local, as in xarray's own interp; skipping them
is asked for with skipna=True.  The same rule in every batch entry point:
trigspline.interp, pandas.interpolate, the xarray accessor on numpy- and
dask-backed data (chunked along the dimension bit for bit as unchunked).

What xarray 2023.01 (Debian) itself does, run in test_xarray_own_interp_keeps_nan_local:
DataArray.interp(method="linear") on [0, 1, 4, NaN, 3, 2, 5, 6] at x = 0, 0.5,
..., 7 gives NaN at 2.5, 3, 3.5 only (the two intervals touching the NaN
point; the knots 2 and 4 keep their values), and no warning;
method="cubic" (a global spline) makes every output NaN.  Our schemes are
local, so we follow the linear pattern: the series is split at its NaN
points into runs, each run of two or more points is a spline of its own.

Oracle for the values: trigspline.Spline fitted on each run separately (an
independent construction of the rule; the gufunc takes another code path,
fit_runs in src/_gufunc.c).
"""
import warnings

import numpy as np
import pytest

from trigspline import Spline, TrigsplineError, interp

xr = pytest.importorskip("xarray", reason="python3-xarray is installed by make test")
pd = pytest.importorskip("pandas", reason="python3-pandas is installed by make test")
pytest.importorskip("dask")

TS_ERR_TOO_FEW, TS_ERR_NONFINITE, TS_ERR_UNSORTED, TS_ERR_NEGATIVE = 4, 5, 6, 14


def runs_oracle(x, f, xq, extrapolate="nan", **kw):
    """The documented rule, built from one Spline per run."""
    ok = np.isfinite(x) & np.isfinite(f)
    out = np.full(len(xq), np.nan)
    i, n = 0, len(x)
    while i < n:
        if not ok[i]:
            i += 1
            continue
        j = i
        while j + 1 < n and ok[j + 1]:
            j += 1
        if j > i:
            s = Spline(x[i:j + 1], f[i:j + 1], extrapolate=extrapolate, **kw)
            lo = -np.inf if i == 0 else x[i]
            hi = np.inf if j == n - 1 else x[j]
            sel = (xq >= lo) & (xq <= hi)
            out[sel] = s(xq[sel])
        i = j + 1
    return out


def test_xarray_own_interp_keeps_nan_local():
    x = np.arange(8.0)
    f = np.array([0, 1, 4, np.nan, 3, 2, 5, 6.0])
    q = np.arange(0, 7.01, 0.5)
    da = xr.DataArray(f, dims="t", coords={"t": x})
    with warnings.catch_warnings():
        warnings.simplefilter("error")             # xarray gives no warning
        lin = da.interp(t=q, method="linear").values
        ours = da.trigspline.interp(t=q, lower=0).values
    assert np.flatnonzero(np.isnan(lin)).tolist() == [5, 6, 7]     # q = 2.5, 3, 3.5
    np.testing.assert_array_equal(np.isnan(ours), np.isnan(lin))
    assert ours[4] == 4.0 and ours[8] == 3.0                        # knots next to the gap
    np.testing.assert_array_equal(ours, runs_oracle(x, f, q, shape="positive"))


@pytest.mark.parametrize("missing", [[3], [0], [7], [3, 4], [2, 4], [0, 2], [1, 6],
                                     [0, 1, 2, 3, 4, 5, 6, 7]])
@pytest.mark.parametrize("extrapolate", ["nan", "extend", "clamp", "linear"])
def test_numpy_entry_point_follows_the_rule(missing, extrapolate):
    x = np.array([0, 1, 2.5, 3, 4.5, 6, 7, 9.0])
    f = np.array([0, 1, 4, 2, 3, 2, 5, 6.0])
    f[missing] = np.nan
    q = np.concatenate([np.linspace(-2, 11, 131), x, [np.nan]])
    r = interp(x, f, q, lower=0, extrapolate=extrapolate, full=True)
    want = runs_oracle(x, f, q, extrapolate=extrapolate, shape="positive")
    np.testing.assert_array_equal(r.values, want)
    assert r.status == TS_ERR_NONFINITE and r.index == missing[0]
    # a lone finite point between two missing ones gives no value, not even at itself
    if missing == [0, 2]:
        assert np.isnan(interp(x, f, [1.0], lower=0))[0]
    # skipna=True: through the finite points, across the gap
    keep = np.isfinite(f)
    if keep.sum() >= 2:
        inside = (q >= x[keep][0]) & (q <= x[keep][-1])
        g = interp(x, f, q[inside], lower=0, skipna=True)
        np.testing.assert_array_equal(g, Spline(x[keep], f[keep], shape="positive")(q[inside]))


def test_nan_in_x_is_a_missing_point_and_runs_must_stay_in_order():
    x = np.array([0, 1, np.nan, 3, 4.0])
    f = np.array([1, 2, 3, 2, 1.0])
    q = np.linspace(0, 4, 41)
    np.testing.assert_array_equal(interp(x, f, q), runs_oracle(x, f, q))
    bad = np.array([0, 1, 2, 0.5, 4.0])
    f2 = f.copy()
    f2[2] = np.nan
    with pytest.raises(TrigsplineError) as e:
        interp(bad, f2, q)
    assert e.value.status == TS_ERR_UNSORTED and e.value.index == 3


def test_a_run_the_scheme_refuses_fails_the_series():
    x = np.arange(10.0)
    f = np.array([1, 2, 1, np.nan, 2, 3, -1, 2, 1, 1.0])
    with pytest.raises(TrigsplineError, match="point 6") as e:
        interp(x, f, [0.5], lower=0)               # errors='raise': the series' numbering
    assert e.value.status == TS_ERR_NEGATIVE and e.value.index == 6
    r = interp(x, f, [0.5, 8.5], lower=0, errors="nan", full=True)
    assert r.status == TS_ERR_NEGATIVE and r.index == 6 and np.isnan(r.values).all()
    # NaN alone never raises: it is a gap, not a fault
    assert interp(x, np.where(f < 0, np.nan, f), [0.5], lower=0, full=True).status == 5


def test_least_gap_over_the_runs():
    x = np.arange(12.0)
    f = np.array([1, 2, 1.5, 3, np.nan, 2, 0.5, 1, np.nan, np.nan, 2, 3.0]) + 0.25
    r = interp(x, f, [0.5], lower=0, full=True, gap=True)
    want = min(interp(x[a:b], f[a:b], [x[a]], lower=0, full=True, gap=True).gap
               for a, b in [(0, 4), (5, 8), (10, 12)])
    assert r.gap == want > 0


def test_float32_follows_the_same_rule():
    x = np.arange(20.0)
    f = np.abs(np.sin(x)).astype(np.float32)
    f[[4, 11, 12]] = np.nan
    q = np.linspace(0, 19, 97)
    y = interp(x, f, q, lower=0)
    assert y.dtype == np.float32
    np.testing.assert_array_equal(np.isnan(y), np.isnan(runs_oracle(x, f.astype(float), q)))
    assert (y[~np.isnan(y)] >= 0).all()


def cube(n=96, seed=11):
    rng = np.random.default_rng(seed)
    v = rng.pareto(2.5, (3, 4, n))
    v[rng.random(v.shape) < 0.4] = 0.0
    v[0, 1, 30] = np.nan                       # one missing hour
    v[1, 2, [0, 1, 50, 51, 52, 95]] = np.nan   # at both ends and a three-hour hole
    v[2, 3, ::2] = np.nan                      # every other hour: no run of two
    v[2, 0, :] = np.nan                        # a dead cell (land mask)
    t = np.datetime64("2021-03-01T00", "ns") + np.arange(n) * np.timedelta64(1, "h")
    return xr.DataArray(v, dims=("lat", "lon", "time"),
                        coords={"time": t, "lat": [1.0, 2.0, 3.0], "lon": np.arange(4.0)})


def test_every_entry_point_gives_the_same_values():
    da = cube()
    t = da.time.values
    new = np.concatenate([t[0] + np.arange(2 * len(t) - 1) * np.timedelta64(30, "m"),
                          t[[0, -1]] + np.array([-1, 1]) * np.timedelta64(20, "m")])
    secs = (t - t[0]) / np.timedelta64(1, "s")
    q = (new - t[0]) / np.timedelta64(1, "s")
    ref = interp(secs, da.values, q, lower=0, extrapolate="extend")
    for idx in np.ndindex(3, 4):
        np.testing.assert_array_equal(ref[idx], runs_oracle(secs, da.values[idx], q,
                                                            extrapolate="extend",
                                                            shape="positive"))
    out, cert = da.trigspline.interp(time=new, lower=0, extrapolate="extend", certificate=True)
    np.testing.assert_array_equal(out.values, ref)
    df = pd.DataFrame(da.values.reshape(12, -1).T, index=pd.DatetimeIndex(t))
    np.testing.assert_array_equal(
        interp_pd(df, new).T.reshape(3, 4, -1), ref)
    for chunks in ({"time": 1}, {"time": 7, "lat": 2}, {"time": 25}, {"lon": 1}):
        lazy, lcert = da.chunk(chunks).trigspline.interp(time=new, lower=0,
                                                         extrapolate="extend",
                                                         certificate=True)
        np.testing.assert_array_equal(lazy.compute(scheduler="sync").values, ref)
        lc = lcert.compute(scheduler="sync")
        np.testing.assert_array_equal(lc.status.values, cert.status.values)
        np.testing.assert_array_equal(lc.index.values, cert.index.values)
    st = cert.status.values
    assert st[0, 0] == 0 and st[0, 1] == st[1, 2] == st[2, 3] == st[2, 0] == TS_ERR_NONFINITE
    assert cert.index.values[0, 1] == 30 and cert.index.values[1, 2] == 0
    # one missing hour blanks the three outputs around it, nothing else
    assert np.flatnonzero(np.isnan(out.values[0, 1])).tolist() == [59, 60, 61]
    assert np.isnan(out.values[2, 3]).all() and np.isnan(out.values[2, 0]).all()


def interp_pd(df, new):
    from trigspline.pandas import interpolate
    return interpolate(df, index=new, lower=0, extrapolate="extend").values


def test_netcdf_fill_value_hour(tmp_path):
    """The case of a netCDF cube with _FillValue: one missing hour."""
    pytest.importorskip("netCDF4")
    da = cube().isel(lat=[0], lon=[1]).fillna(0.0)
    da.values[..., 30] = np.nan
    path = tmp_path / "rain.nc"
    da.to_dataset(name="rain").to_netcdf(path, encoding={"rain": {"_FillValue": -9999.0}})
    back = xr.open_dataset(path)["rain"].load()
    assert np.isnan(back.values[..., 30]) and np.isfinite(np.delete(back.values, 30, -1)).all()
    t = back.time.values
    new = t[0] + np.arange(427) * np.timedelta64(13, "m")
    out = back.trigspline.interp(time=new, lower=0, extrapolate="nan")
    near = (new > t[29]) & (new < t[31])
    np.testing.assert_array_equal(np.isnan(out.values[0, 0]), near | (new > t[-1]))
    assert near.sum() == 10 and out.values.size == 427   # was 427 NaN before


def test_chunked_failure_beats_an_earlier_gap():
    # a NaN in the first chunk and a negative value (a fault) in a later one:
    # the series fails as unchunked, with the fault's status and position
    da = cube(seed=12).fillna(0.0)
    da.values[0, 0, 10] = np.nan
    da.values[0, 0, 60] = -1.0
    new = da.time.values[:-1] + np.timedelta64(30, "m")
    ref, cert = da.trigspline.interp(time=new, lower=0, errors="nan", certificate=True)
    assert cert.status.values[0, 0] == TS_ERR_NEGATIVE and cert.index.values[0, 0] == 60
    assert np.isnan(ref.values[0, 0]).all() and not np.isnan(ref.values[0, 1]).any()
    for chunk in (5, 13):
        out, c = da.chunk({"time": chunk}).trigspline.interp(time=new, lower=0, errors="nan",
                                                             certificate=True)
        np.testing.assert_array_equal(out.compute(scheduler="sync").values, ref.values)
        c = c.compute(scheduler="sync")
        np.testing.assert_array_equal(c.status.values, cert.status.values)
        np.testing.assert_array_equal(c.index.values, cert.index.values)
    with pytest.raises(ValueError, match=r"series lat=1.0, lon=0.0: .*\(position 60\)"):
        da.trigspline.interp(time=new, lower=0)
