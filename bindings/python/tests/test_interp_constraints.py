"""constraints= in the batch entry points (docs/method.md §13): interp (the
numpy gufunc), the xarray accessors (numpy and dask) and pandas.interpolate.

Each series' values must be those of Spline(x, f, constraints=...) bit for
bit (the same C calls: ts_spline_new, ts_spline_eval_batch); dask chunked
along the dimension equal to unchunked bit for bit; a refusal gives the
series the library's status (TS_ERR_CONDITION 31 for data that break a
necessary condition) and errors='raise' the library's sentence naming the
record and the condition.
"""
import math

import numpy as np
import pytest

import trigspline
from trigspline import Spline, TrigsplineError, interp
from trigspline.interp import constraint_message

CONDITION, OPTION, NONFINITE = 31, 11, 5

# Black-Scholes calls in strike (S0 = 100, sigma = 0.2, T = 1, r = 0):
# convex and decreasing in K, with slope >= -1 and values >= 0 (closed form).
K = np.array([60, 70, 80, 90, 100, 105, 110, 120, 140], dtype=float)


def _call(k):
    d1 = (math.log(100.0 / k) + 0.02) / 0.2
    return 100.0 * 0.5 * math.erfc(-d1 / math.sqrt(2)) - k * 0.5 * math.erfc(
        -(d1 - 0.2) / math.sqrt(2))


C = np.array([_call(k) for k in K])
SPECS = ["convex", "decreasing", "slope>=-1", "lower=0"]
XQ = np.linspace(60.0, 140.0, 161)


def _chains():
    """Three chains: a multiple in (0, 1] and an added constant keep the
    prices convex, decreasing, with slope >= -1 and >= 0."""
    return np.stack([C, 0.5 * C, C + 1.0])


def test_each_series_is_its_spline_bit_for_bit():
    F = _chains()
    y = interp(K, F, XQ, constraints=SPECS, extrapolate="extend")
    for j in range(F.shape[0]):
        s = Spline(K, F[j], constraints=SPECS)
        assert np.array_equal(y[j], s(XQ)), j
    # float32 data: computed in float64, rounded (no bound among the records
    # of the lines' kind, so rounding to nearest)
    y32 = interp(K, F.astype(np.float32), XQ, constraints=SPECS, extrapolate="extend")
    assert y32.dtype == np.float32


def test_refusal_status_index_and_sentence():
    F = np.stack([C, C[::-1].copy(), C])  # the middle one is increasing: not decreasing
    r = interp(K, F, XQ, constraints=["decreasing"], errors="nan", full=True)
    assert list(r.status) == [0, CONDITION, 0]
    # the first point where the reversed data turn upwards: point 1
    assert r.index[1] == 1
    assert np.isnan(r.values[1]).all() and np.isfinite(r.values[0][1:-1]).all()
    with pytest.raises(TrigsplineError) as e:
        interp(K, F, XQ, constraints=["decreasing"])
    msg = str(e.value)
    # the library's sentence: the series, the point, the record and the condition
    assert msg.startswith("series (1,): ") and "change direction" in msg
    assert "(constraint 0, decreasing)" in msg
    assert e.value.status == CONDITION
    # the same sentence on demand from the full=True result
    m = constraint_message(K, F[1], r.status[1], r.index[1], constraints=["decreasing"])
    assert m in msg


def test_scopes_count_the_series_intervals_and_runs_keep_them():
    # convex only on intervals 0-3 (the data on 4-7 are a bump: not convex)
    f = np.concatenate([C[:5], [C[4] + 1.0, C[6] + 2.0, C[7], C[8]]])
    s = Spline(K, f, constraints=["convex@0-3"])
    assert np.array_equal(interp(K, f, XQ, constraints=["convex@0-3"], extrapolate="extend"),
                          s(XQ))
    with pytest.raises(TrigsplineError):
        interp(K, f, XQ, constraints=["convex"])
    # a missing point at 6: runs 0-5 and 7-8; the scope 0-3 lies in the first
    # run, which is that of Spline(K[:6], f[:6]) with the same scope
    g = f.copy()
    g[6] = np.nan
    y = interp(K, g, XQ, constraints=["convex@0-3"], extrapolate="extend", full=True)
    assert y.status == NONFINITE and y.index == 6
    s6 = Spline(K[:6], g[:6], constraints=["convex@0-3"])
    inside = (XQ >= K[0]) & (XQ <= K[5])
    assert np.array_equal(y.values[inside], s6(XQ[inside]))
    # a scope beyond the series is refused with or without gaps
    for data in (f, g):
        r = interp(K, data, XQ, constraints=["convex@9-10"], errors="nan", full=True)
        assert r.status == OPTION


def test_gap_is_the_least_exact_gap_of_the_bound_records():
    r = interp(K, C, XQ, constraints=SPECS, full=True, gap=True, extrapolate="extend")
    s = Spline(K, C, constraints=SPECS)
    rep = s.constraint_report()[3]  # lower=0
    assert r.gap == min(q["gap"] for q in rep)
    assert r.gap > 0  # every price > 0: the least value, at the last strike
    # no bound record: NaN, as a scheme without a boundary
    r = interp(K, C, XQ, constraints=["convex"], full=True, gap=True, extrapolate="extend")
    assert np.isnan(r.gap)


def test_polyline_record_and_options_checked_by_the_library():
    floor = "lower=poly:50,30;100,3;150,-1"
    y = interp(K, C, XQ, constraints=["convex", floor], extrapolate="extend")
    assert np.array_equal(y, Spline(K, C, constraints=["convex", floor])(XQ))
    # the records need the geometric form and shape 'none': the library's TS_ERR_OPTION
    r = interp(K, C, XQ, constraints=["convex"], form="paper", errors="nan", full=True)
    assert r.status == OPTION
    with pytest.raises(ValueError):
        interp(K, C, XQ, constraints=["convex@x"])


def test_xarray_numpy_and_dask_chunked_equal_bit_for_bit():
    xr = pytest.importorskip("xarray")
    dask = pytest.importorskip("dask.array")
    F = _chains()
    da = xr.DataArray(F, dims=("chain", "strike"), coords={"strike": K, "chain": [0, 1, 2]})
    ref = interp(K, F, XQ, constraints=SPECS, extrapolate="extend")
    out = da.trigspline.interp(strike=XQ, constraints=SPECS, extrapolate="extend")
    assert np.array_equal(out.values, ref)
    lazy = da.chunk({"strike": 3, "chain": 1})
    with pytest.warns(RuntimeWarning, match="constraints"):
        got = lazy.trigspline.interp(strike=XQ, constraints=SPECS, extrapolate="extend")
    assert isinstance(got.data, dask.Array)
    assert np.array_equal(got.values, ref)
    # per-series certificate, lazily
    with pytest.warns(RuntimeWarning):
        _, cert = lazy.trigspline.interp(strike=XQ, constraints=SPECS, extrapolate="extend",
                                         certificate=True)
    assert list(cert["status"].values) == [0, 0, 0]
    # a refusal raises the library's sentence naming the series
    bad = da.copy(data=np.stack([C, C[::-1].copy(), C]))
    with pytest.raises(ValueError, match=r"chain=1: .*\(constraint 0, decreasing\)"):
        bad.trigspline.interp(strike=XQ, constraints=["decreasing"])
    with pytest.raises(ValueError, match=r"chain=1: .*\(constraint 0, decreasing\)"):
        with pytest.warns(RuntimeWarning):
            bad.chunk({"strike": 4}).trigspline.interp(
                strike=XQ, constraints=["decreasing"]).compute()
    ds = xr.Dataset({"calls": da})
    assert np.array_equal(ds.trigspline.interp(strike=XQ, constraints=SPECS,
                                               extrapolate="extend")["calls"].values, ref)


def test_pandas_columns():
    pd = pytest.importorskip("pandas")
    import trigspline.pandas
    df = pd.DataFrame({"a": C, "b": 0.5 * C}, index=K)
    out = trigspline.pandas.interpolate(df, XQ, constraints=SPECS, extrapolate="extend")
    assert np.array_equal(out["a"].values, Spline(K, C, constraints=SPECS)(XQ))
    df["b"] = C[::-1]
    with pytest.raises(ValueError, match=r"column 'b': .*\(constraint 0, convex\)"):
        trigspline.pandas.interpolate(df, XQ, constraints=SPECS, extrapolate="extend")
