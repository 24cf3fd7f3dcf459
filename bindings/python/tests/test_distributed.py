"""The accessor on a dask.distributed LocalCluster: worker processes on
127.0.0.1 only, started and stopped inside the test.  The oracle is the
same computation on numpy data in this process (bit for bit)."""
import os

import numpy as np
import pytest

xr = pytest.importorskip("xarray", reason="python3-xarray is installed by make test")
distributed = pytest.importorskip("distributed", reason="python3-distributed is installed by make test")

import trigspline
import trigspline.xarray  # noqa: F401


def test_local_cluster_chunked_equals_unchunked(monkeypatch):
    # worker processes import trigspline from where this process found it
    pkg_root = os.path.dirname(os.path.dirname(os.path.abspath(trigspline.__file__)))
    monkeypatch.setenv("PYTHONPATH", os.pathsep.join(
        [pkg_root] + [p for p in os.environ.get("PYTHONPATH", "").split(os.pathsep) if p]))
    rng = np.random.default_rng(11)
    n = 400
    v = rng.pareto(2.5, (2, 3, n)).astype(np.float32)
    v[rng.random(v.shape) < 0.4] = 0
    t = np.datetime64("2022-01-01T00", "ns") + np.arange(n) * np.timedelta64(1, "h")
    da = xr.DataArray(v, dims=("lat", "lon", "time"),
                      coords={"time": t, "lat": [1.0, 2.0], "lon": [0.0, 1.0, 2.0]},
                      attrs={"units": "mm/h"})
    new = t[0] + np.arange(2 * n - 1) * np.timedelta64(30, "m")
    ref = da.trigspline.interp(time=new, lower=0, form="paper")

    cluster = distributed.LocalCluster(n_workers=2, threads_per_worker=1, processes=True,
                                       host="127.0.0.1", dashboard_address="127.0.0.1:0",
                                       silence_logs=40)
    try:
        with distributed.Client(cluster) as client:
            assert all(a.startswith("tcp://127.0.0.1:") for a in client.scheduler_info()["workers"])
            lazy = da.chunk({"time": 100}).trigspline.interp(time=new, lower=0,
                                                             form="paper")
            out = client.compute(lazy).result()
            who = client.run(lambda: os.getpid())
    finally:
        cluster.close()
    assert len(set(who.values())) == 2 and os.getpid() not in who.values()
    np.testing.assert_array_equal(out.values, ref.values)
    assert out.dtype == np.float32 and (out.values >= 0).all()
    assert out.attrs == da.attrs
