"""trigspline.pandas.interpolate.  Oracle: one Spline per column on the
index in seconds since its first timestamp, through the finite values."""
import numpy as np
import pytest

pd = pytest.importorskip("pandas", reason="python3-pandas is installed by make test")

from trigspline import Spline
from trigspline.pandas import interpolate


def hourly(n=48, seed=0):
    rng = np.random.default_rng(seed)
    idx = pd.date_range("2023-05-01", periods=n, freq="H")
    v = rng.pareto(2.5, n)
    v[rng.random(n) < 0.4] = 0.0
    return idx, v


def test_series_with_gaps():
    idx, v = hourly()
    v[[5, 6, 20]] = np.nan
    s = pd.Series(v, index=idx, name="rain")
    s.attrs["units"] = "mm/h"
    new = pd.date_range(idx[0], idx[-1], freq="15min")
    out = interpolate(s, index=new, shape="positive", skipna=True)
    keep = np.isfinite(v)
    secs = (idx - idx[0]) / pd.Timedelta(seconds=1)
    q = (new - idx[0]) / pd.Timedelta(seconds=1)
    ref = Spline(np.asarray(secs)[keep], v[keep], shape="positive")(np.asarray(q))
    np.testing.assert_array_equal(out.values, ref)
    assert (out.values >= 0).all()
    assert out.name == "rain" and out.attrs == {"units": "mm/h"} and out.index.equals(new)
    # without skipna (the default) a NaN blanks only the intervals touching it
    local = interpolate(s, index=new, shape="positive")
    gap = ((new > idx[4]) & (new < idx[7])) | ((new > idx[19]) & (new < idx[21]))
    np.testing.assert_array_equal(np.isnan(local.values), gap)
    np.testing.assert_array_equal(local.values, interpolate(s, index=new, shape="positive",
                                                            skipna=False).values)


def test_dataframe_columns_and_float32():
    idx, v = hourly(seed=1)
    _, w = hourly(seed=2)
    df = pd.DataFrame({"a": v, "b": w.astype(np.float32), "label": ["x"] * len(v)}, index=idx)
    new = idx[:-1] + pd.Timedelta(minutes=30)
    out = interpolate(df, index=new, lower=0)
    assert list(out.columns) == ["a", "b", "label"]
    assert out["b"].dtype == np.float32 and (out[["a", "b"]].values >= 0).all()
    np.testing.assert_array_equal(out["a"].values, interpolate(df["a"], index=new,
                                                               lower=0).values)
    assert out["label"].isna().all()


def test_timezone_and_numeric_index():
    idx, v = hourly(seed=3)
    s = pd.Series(v, index=idx.tz_localize("Europe/Berlin"))
    new_utc = s.index[:10].tz_convert("UTC") + pd.Timedelta(minutes=20)
    a = interpolate(s, index=new_utc, shape="positive")
    b = interpolate(pd.Series(v, index=idx), index=idx[:10] + pd.Timedelta(minutes=20),
                    shape="positive")
    np.testing.assert_array_equal(a.values, b.values)
    num = pd.Series([1.0, 4.0, 2.0], index=[0.0, 1.0, 3.0])
    np.testing.assert_array_equal(interpolate(num, index=[0.5, 2.0]).values,
                                  Spline([0, 1, 3], [1, 4, 2])([0.5, 2.0]))


def test_errors_name_column_and_time():
    idx, v = hourly(seed=4)
    v[9] = -1.0
    df = pd.DataFrame({"ok": np.abs(v), "bad": v}, index=idx)
    with pytest.raises(ValueError, match=r"column 'bad': .*negative.* at 2023-05-01 09:00:00 "
                                         r"\(position 9\)"):
        interpolate(df, index=idx, shape="positive")
    out = interpolate(df, index=idx, shape="positive", errors="nan")
    assert out["bad"].isna().all() and not out["ok"].isna().any()
    unsorted = pd.Series([1.0, 2.0, 3.0], index=pd.to_datetime(["2023-01-02", "2023-01-01",
                                                                "2023-01-03"]))
    with pytest.raises(ValueError, match=r"not strictly increasing: position 1"):
        interpolate(unsorted, index=unsorted.index)
    with pytest.raises(TypeError):
        interpolate(np.ones(3), index=[0.0])
