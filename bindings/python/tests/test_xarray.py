"""DataArray.trigspline / Dataset.trigspline: numpy-backed, dask-backed,
chunked along the interpolated dimension.

Oracles: one Spline per series on the coordinate in seconds since its first
value (the conversion the accessor documents) for the values; the unchunked
result for every chunking (bit for bit: the schemes are local, docs/method.md
§3, §5, §6); the outputs themselves for the bound.
"""

import numpy as np
import pytest

xr = pytest.importorskip("xarray", reason="python3-xarray is installed by make test")
dask = pytest.importorskip("dask")

import trigspline
import trigspline.xarray  # noqa: F401  (registers the accessor)
from trigspline import Spline, TrigsplineError
from trigspline.xarray import halo_knots, summary

HOUR = np.timedelta64(1, "h")


def cube(n=240, nlat=3, nlon=4, seed=0, dtype=np.float64):
    rng = np.random.default_rng(seed)
    v = rng.pareto(2.5, (nlat, nlon, n))
    v[rng.random(v.shape) < 0.4] = 0.0        # dry hours: exact zeros
    t = np.datetime64("2021-03-01T00", "ns") + np.arange(n) * HOUR
    return xr.DataArray(v.astype(dtype), dims=("lat", "lon", "time"),
                        coords={"time": t, "lat": [10.0, 20.0, 30.0][:nlat],
                                "lon": np.arange(nlon) * 1.5, "station": ("lat", ["a", "b", "c"][:nlat])},
                        name="precip", attrs={"units": "mm/h", "source": "synthetic"})


def half_hours(da):
    t = da.time.values
    return t[0] + np.arange(2 * len(t) - 1) * np.timedelta64(30, "m")


def test_numpy_backed_equals_one_spline_per_series():
    da = cube()
    new = half_hours(da)
    out = da.trigspline.interp(time=new, lower=0)
    secs = (da.time.values - da.time.values[0]) / np.timedelta64(1, "s")
    q = (new - da.time.values[0]) / np.timedelta64(1, "s")
    for i, j in [(0, 0), (1, 3), (2, 2)]:
        ref = Spline(secs, da.values[i, j], shape="positive")(q)
        np.testing.assert_array_equal(out.values[i, j], ref)
    assert (out.values >= 0).all()
    # coordinates, attrs and name kept; the time coordinate is the new one
    assert out.dims == da.dims and out.name == "precip" and out.attrs == da.attrs
    np.testing.assert_array_equal(out.time.values, new)
    assert out.time.dtype == da.time.dtype
    np.testing.assert_array_equal(out.lat.values, da.lat.values)
    np.testing.assert_array_equal(out.station.values, da.station.values)
    # knots come back
    np.testing.assert_array_equal(out.sel(time=da.time.values).values, da.values)


def test_dims_in_any_order_and_numeric_coordinate():
    da = cube().transpose("time", "lon", "lat")
    new = half_hours(da)
    a = da.trigspline.interp(time=new, lower=0, form="paper")
    b = cube().trigspline.interp(time=new, lower=0, form="paper")
    assert a.dims == ("time", "lon", "lat")
    np.testing.assert_array_equal(a.transpose(*b.dims).values, b.values)
    num = xr.DataArray(np.array([1.0, 3.0, 2.0, 5.0]), dims="x", coords={"x": [0.0, 1.0, 2.5, 4.0]})
    r = num.trigspline.interp(x=[0.5, 2.0, 4.0, 9.0], lower=0, extrapolate="nan")
    np.testing.assert_array_equal(r.values[:3], Spline([0, 1, 2.5, 4], [1, 3, 2, 5],
                                                       shape="positive")([0.5, 2.0, 4.0]))
    assert np.isnan(r.values[3])          # outside: NaN, as xarray's interp
    with pytest.raises(TrigsplineError, match=r"new value 9.0 \(position 3\) lies outside"):
        num.trigspline.interp(x=[0.5, 2.0, 4.0, 9.0], lower=0)   # extrapolate='error'



@pytest.mark.parametrize("chunk", [1, 2, 3, 7, 100])
def test_chunked_along_time_bit_identical(chunk):
    da = cube(n=60 if chunk < 5 else 240)
    new = half_hours(da)
    ref = da.trigspline.interp(time=new, lower=0, form="paper")
    lazy = da.chunk({"time": chunk, "lat": 2}).trigspline.interp(time=new, lower=0,
                                                                 form="paper")
    assert lazy.chunks is not None          # still lazy
    out = lazy.compute(scheduler="sync")
    np.testing.assert_array_equal(out.values, ref.values)
    assert (out.values >= 0).all()
    assert out.attrs == da.attrs


@pytest.mark.parametrize("opts", [
    dict(form="geometric", slopes="akima", lower=0, extrapolate="nan"),
    dict(form="paper", slopes="fritsch-carlson", lower=(0.0, -0.25), shape="above",
         extrapolate=False),
    dict(form="geometric", slopes="makima", lower=-0.5, upper=60.0, extrapolate="linear"),
])
def test_chunked_other_options(opts):
    da = cube(n=50, seed=3)
    t = da.time.values
    # unsorted queries, some outside the data
    new = np.concatenate([t[::-1][:40] + 17 * np.timedelta64(1, "m"), t[:3] - HOUR])
    ref = da.trigspline.interp(time=new, **opts)
    for chunk in (1, 3, 25):
        out = da.chunk({"time": chunk}).trigspline.interp(time=new, **opts).compute(
            scheduler="sync")
        np.testing.assert_array_equal(out.values, ref.values)
        np.testing.assert_array_equal(out.time.values, new)


def test_halo_is_needed():
    # the halo is not decoration: one knot less changes the values
    import dask.array as dsa
    from trigspline.interp import pack_options
    from trigspline.xarray import _interp_chunked
    da = cube(n=60, seed=4)
    x = np.arange(60.0)
    q = np.linspace(0, 59, 200)
    f = da.values
    for slopes in ("arithmetic", "akima"):
        opt = pack_options("positive", slopes=slopes)
        h = halo_knots(slopes)
        good, _ = _interp_chunked(dsa.from_array(f, chunks=(3, 4, 5)), x, q, opt, h,
                                  "nan", [], {}, "time", x)
        short, _ = _interp_chunked(dsa.from_array(f, chunks=(3, 4, 5)), x, q, opt, h - 1,
                                   "nan", [], {}, "time", x)
        ref = trigspline.interp(x, f, q, shape="positive", slopes=slopes)
        np.testing.assert_array_equal(good.compute(scheduler="sync"), ref)
        assert not np.array_equal(short.compute(scheduler="sync"), ref)


def test_non_local_options_fall_back_with_a_warning():
    da = cube(n=80, seed=5)
    new = half_hours(da)
    ref = da.trigspline.interp(time=new, lower=0, form="c1")
    with pytest.warns(RuntimeWarning, match="not local"):
        lazy = da.chunk({"time": 10}).trigspline.interp(time=new, lower=0, form="c1")
    np.testing.assert_array_equal(lazy.compute(scheduler="sync").values, ref.values)


def test_dask_one_chunk_along_time_and_float32():
    da = cube(dtype=np.float32)
    new = half_hours(da)
    ref = da.trigspline.interp(time=new, lower=0)
    assert ref.dtype == np.float32
    out = da.chunk({"lat": 1, "lon": 2}).trigspline.interp(time=new, lower=0)
    np.testing.assert_array_equal(out.compute(scheduler="sync").values, ref.values)
    assert (ref.values >= 0).all()
    np.testing.assert_array_equal(ref.sel(time=da.time.values).values, da.values)


def test_nan_stays_local_when_chunked():
    da = cube(n=90, seed=6)
    da.values[1, 2, 40] = np.nan
    new = half_hours(da)
    ref = da.trigspline.interp(time=new, lower=0)
    # the half hours on either side of hour 40 and hour 40 itself
    assert np.flatnonzero(np.isnan(ref.values[1, 2])).tolist() == [79, 80, 81]
    assert not np.isnan(ref.values[0]).any()
    out = da.chunk({"time": 7}).trigspline.interp(time=new, lower=0)
    np.testing.assert_array_equal(out.compute(scheduler="sync").values, ref.values)
    # gaps skipped: the series through its finite points
    g = da.trigspline.interp(time=new, lower=0, skipna=True)
    assert not np.isnan(g.values).any()


def test_bad_input_names_coordinate_and_position():
    da = cube(n=30)
    t = da.time.values.copy()
    t[7], t[8] = t[8], t[7]
    with pytest.raises(ValueError, match=r"coordinate 'time' is not strictly increasing: "
                                         r"position 8 \(2021-03-01T07"):
        da.assign_coords(time=t).trigspline.interp(time=t[:3], lower=0)
    neg = da.copy()
    neg.values[2, 1, 12] = -0.5
    msg = r"series lat=30.0, lon=1.5: .*negative.* at time=2021-03-01T12:00:00.* \(position 12\)"
    with pytest.raises(ValueError, match=msg):
        neg.trigspline.interp(time=half_hours(da), lower=0)
    with pytest.raises(ValueError, match=msg):
        neg.chunk({"time": 5, "lat": 2}).trigspline.interp(
            time=half_hours(da), lower=0).compute(scheduler="sync")
    # errors='nan': that series is NaN, chunked or not
    a = neg.trigspline.interp(time=half_hours(da), lower=0, errors="nan")
    b = neg.chunk({"time": 5}).trigspline.interp(time=half_hours(da), lower=0,
                                                 errors="nan").compute(scheduler="sync")
    assert np.isnan(a.values[2, 1]).all() and not np.isnan(a.values[2, 0]).any()
    np.testing.assert_array_equal(a.values, b.values)
    with pytest.raises(ValueError, match="not a dimension"):
        da.trigspline.interp(depth=[1.0])
    with pytest.raises(ValueError, match="exactly one dimension"):
        da.trigspline.interp(time=t[:2], lat=[15.0])
    with pytest.raises(TypeError, match="datetime64"):
        da.trigspline.interp(time=[1.0, 2.0])


def test_certificate_summary_and_companion_arrays():
    da = cube(n=100, seed=7) + 0.1                 # strictly positive: every gap > 0
    new = half_hours(da)
    out, cert = da.trigspline.interp(time=new, lower=0, certificate=True)
    assert cert.attrs["all_certified"] == 1 and cert.attrs["least_gap"] > 0
    assert cert.status.dims == ("lat", "lon") and (cert.status.values == 0).all()
    # no sample of any series below its certified least gap
    dense = da.trigspline.interp(time=da.time.values[0] + np.arange(99 * 60) * np.timedelta64(1, "m"),
                                 lower=0)
    assert (dense.min("time").values >= cert.gap.values * (1 - 1e-12)).all()
    lazy_out, lazy_cert = da.chunk({"time": 9}).trigspline.interp(
        time=new, lower=0, certificate=True)
    s = summary(lazy_cert)
    assert s["all_certified"] and s["least_gap"] == cert.attrs["least_gap"]
    np.testing.assert_array_equal(lazy_cert.gap.values, cert.gap.values)


def test_dataset():
    da = cube(n=50)
    ds = xr.Dataset({"precip": da, "count": da.astype(np.int64),
                     "elevation": (("lat", "lon"), np.ones((3, 4)))}, attrs={"title": "t"})
    new = half_hours(da)
    out = ds.trigspline.interp(time=new, lower=0)
    np.testing.assert_array_equal(out.precip.values,
                                  da.trigspline.interp(time=new, lower=0).values)
    assert out["count"].dtype == np.float64 and out.elevation.dims == ("lat", "lon")
    assert out.attrs == {"title": "t"}
    lazy = ds.chunk({"time": 6}).trigspline.interp(time=new, lower=0)
    xr.testing.assert_identical(lazy.compute(scheduler="sync"), out)

