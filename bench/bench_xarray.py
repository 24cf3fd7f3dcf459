#!/usr/bin/python3
"""Benchmark: certified interpolation of a precipitation-like cube with the
xarray accessor, against xarray's own interp (cubic, linear), measured side by
side in one run; and the gufunc against one Spline per series in a Python
loop and SciPy's PchipInterpolator(axis=...).

    bench_xarray.py                 # 8760 x 18 x 36 cube (make bench)
    bench_xarray.py --size full     # 8760 x 180 x 360 float32 (~2.3 GB)
    bench_xarray.py --size 10gb     # 8760 x 360 x 720 float32 (~9.1 GB)

Every method runs in its own process (so its peak RSS is its own); the cube
is generated lazily, chunk by chunk, by dask (the same values for every
method: each chunk is seeded by its position), upsampled x2 in time, and the
result reduced (negatives, minimum) chunk by chunk, as a pipeline writing to
disk would stream it.  Throughput: output points per second per core.
"""
import argparse
import json
import os
import resource
import subprocess
import sys
import time

import numpy as np

SIZES = {"small": (8760, 18, 36), "full": (8760, 180, 360), "10gb": (8760, 360, 720)}
CHUNK = {"lat": 10, "lon": 40}


def rain_block(block_info=None):
    """One chunk of the synthetic cube: ~40 % exact zeros (dry hours), wet
    hours Pareto(2.5)-distributed (heavy tail), float32."""
    info = block_info[None]
    shape = info["chunk-shape"]
    seed = [int(a) for a, _ in info["array-location"]]
    rng = np.random.default_rng(seed)
    v = rng.pareto(2.5, size=shape).astype(np.float32)
    v[rng.random(shape, dtype=np.float32) < 0.4] = 0
    return v


def make_cube(size, time_chunk=-1):
    import dask.array as dsa
    import xarray as xr
    nt, nlat, nlon = SIZES[size]
    chunks = (nt if time_chunk == -1 else time_chunk, CHUNK["lat"], CHUNK["lon"])
    data = dsa.map_blocks(rain_block, dtype=np.float32, chunks=dsa.core.normalize_chunks(
        chunks, (nt, nlat, nlon)))
    t = np.datetime64("2021-01-01T00", "ns") + np.arange(nt) * np.timedelta64(1, "h")
    da = xr.DataArray(data, dims=("time", "lat", "lon"),
                      coords={"time": t, "lat": np.linspace(-89.5, 89.5, nlat),
                              "lon": np.linspace(0.5, 359.5, nlon)},
                      name="precip", attrs={"units": "mm/h"})
    new = t[0] + np.arange(2 * nt - 1) * np.timedelta64(30, "m")
    return da, new


def run_method(method, size, cores):
    import dask
    da, new = make_cube(size, time_chunk=1000 if method == "trigspline-time-chunked" else -1)
    if method.startswith("trigspline"):
        import trigspline.xarray  # noqa: F401
        out = da.trigspline.interp(time=new, lower=0, form="paper")
    elif method == "xarray-cubic":
        out = da.interp(time=new, method="cubic")
    elif method == "xarray-linear":
        out = da.interp(time=new, method="linear")
    else:
        raise SystemExit("unknown method %r" % method)
    y = out.data
    t0, c0 = time.perf_counter(), time.process_time()
    neg, low, nan = dask.compute((y < 0).sum(), y.min(), dask.array.isnan(y).sum(),
                                 scheduler="threads", num_workers=cores)
    dt, cpu = time.perf_counter() - t0, time.process_time() - c0
    rss = resource.getrusage(resource.RUSAGE_SELF).ru_maxrss * 1024
    print(json.dumps({"method": method, "seconds": dt, "cpu": cpu, "points": int(y.size),
                      "negatives": int(neg), "min": float(low), "nan": int(nan),
                      "peak_rss": rss, "cores": cores}))


def bench_series(n_series=10000, n=1000, repeat=3):
    """gufunc vs a Python loop of Spline vs SciPy Pchip, 1e4 series x 1e3 points."""
    from trigspline import Spline
    from trigspline.interp import interp
    rng = np.random.default_rng(0)
    x = np.arange(n, dtype=np.float64)
    f = rng.pareto(2.5, (n_series, n))
    f[rng.random(f.shape) < 0.4] = 0
    xq = np.linspace(0, n - 1, 2 * n - 1)
    rows = []

    def best(fn):
        ts = []
        for _ in range(repeat):
            t0 = time.perf_counter()
            r = fn()
            ts.append(time.perf_counter() - t0)
        return min(ts), r

    t_g, yg = best(lambda: interp(x, f, xq, shape="positive", form="paper"))
    rows.append(("trigspline.interp (gufunc)", t_g, int((yg < 0).sum())))
    k = max(1, n_series // 10)   # the loop is timed on a tenth and scaled
    t_l, yl = best(lambda: np.stack([Spline(x, f[i], shape="positive", form="paper")(xq)
                                          for i in range(k)]))
    assert np.array_equal(yl, yg[:k])
    rows.append(("Spline per series, Python loop (x%d)" % (n_series // k), t_l * n_series / k,
                 int((yl < 0).sum())))
    try:
        from scipy.interpolate import PchipInterpolator
        t_p, yp = best(lambda: PchipInterpolator(x, f, axis=-1)(xq))
        rows.append(("SciPy PchipInterpolator(axis=-1)", t_p, int((yp < 0).sum())))
    except ImportError:
        rows.append(("SciPy PchipInterpolator (not installed)", float("nan"), -1))
    print("\n%d series x %d points, evaluated at %d points each (one core)" % (
        n_series, n, len(xq)))
    print("%-42s %10s %12s %10s %10s" % ("method", "seconds", "Mpoints/s", "vs gufunc", "negatives"))
    for name, t, neg in rows:
        print("%-42s %10.3f %12.1f %10.2f %10d" % (name, t, n_series * len(xq) / t / 1e6,
                                                   t / t_g, neg))


def main():
    ap = argparse.ArgumentParser(description=__doc__, formatter_class=argparse.RawDescriptionHelpFormatter)
    ap.add_argument("--size", choices=sorted(SIZES), default="small")
    ap.add_argument("--cores", type=int, default=min(2, os.cpu_count() or 1))
    ap.add_argument("--part", choices=("cube", "series", "all"), default="all")
    ap.add_argument("--skip-xarray", action="store_true",
                    help="only the trigspline rows (xarray cubic is slow on the big cubes)")
    ap.add_argument("--run", help=argparse.SUPPRESS)
    a = ap.parse_args()
    if a.run:
        run_method(a.run, a.size, a.cores)
        return
    if a.part in ("cube", "all"):
        nt, nlat, nlon = SIZES[a.size]
        print("cube %d x %d x %d float32 (%.2f GB), upsampled x2 in time, chunks time x %d x %d, "
              "%d cores" % (nt, nlat, nlon, nt * nlat * nlon * 4 / 1e9, CHUNK["lat"],
                            CHUNK["lon"], a.cores))
        methods = ["trigspline", "trigspline-time-chunked"]
        if not a.skip_xarray:
            methods += ["xarray-cubic", "xarray-linear"]
        res = []
        for m in methods:
            p = subprocess.run([sys.executable, os.path.abspath(__file__), "--run", m, "--size",
                                a.size, "--cores", str(a.cores)], capture_output=True, text=True)
            if p.returncode != 0:
                print(p.stderr[-2000:], file=sys.stderr)
                raise SystemExit("%s failed" % m)
            res.append(json.loads(p.stdout.strip().splitlines()[-1]))
        base = res[0]["seconds"]
        # Mpts/s/core: output points per wall second per core used; per CPU
        # second: the same on the CPU time the process got (a shared machine)
        print("%-24s %9s %7s %12s %12s %9s %10s %10s" % (
            "method", "seconds", "vs ts", "Mpts/s/core", "Mpts/cpu-s", "peak RSS", "negatives",
            "min"))
        for r in res:
            print("%-24s %9.2f %7.2f %12.1f %12.1f %8.2fG %10d %10.3g" % (
                r["method"], r["seconds"], r["seconds"] / base,
                r["points"] / r["seconds"] / r["cores"] / 1e6, r["points"] / r["cpu"] / 1e6,
                r["peak_rss"] / 2 ** 30, r["negatives"], r["min"]))
        for r in res:
            if r["method"].startswith("trigspline"):
                assert r["negatives"] == 0 and r["min"] >= 0, r
                assert r["peak_rss"] < 4 * 2 ** 30, r
    if a.part in ("series", "all"):
        bench_series()


if __name__ == "__main__":
    main()
