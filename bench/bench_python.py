#!/usr/bin/env python3
"""Python rows of `make bench` (`make bench-python` runs only these).

The installed trigspline package against SciPy's PchipInterpolator (Debian's
python3-scipy), measured in the same run, and construction against the C
library's own ts_spline_new (the shared library of the CMake build, called
through ctypes: one call, so the call overhead is negligible against 1e6 knots).

    python3 bench/bench_python.py [--quick]

Times: the minimum over repetitions (wall clock; the machine may be shared),
printed with the ratio and its goal:
  construction at 1e6 knots <= 0.5x SciPy Pchip and <= 1.5x the C library;
  evaluation at 1e7 points <= 0.4x SciPy.
"""
import ctypes
import os
import sys
import time

import numpy as np
import scipy
from scipy.interpolate import PchipInterpolator

import trigspline

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
QUICK = "--quick" in sys.argv
N_KNOTS = 10 ** 5 if QUICK else 10 ** 6
N_EVAL = 10 ** 6 if QUICK else 10 ** 7
N_SCALAR = 10 ** 4 if QUICK else 10 ** 5


def best(fn, reps):
    t = float("inf")
    for _ in range(reps):
        t0 = time.perf_counter()
        fn()
        t = min(t, time.perf_counter() - t0)
    return t


def c_library():
    for d in ("build-bench", "build"):
        p = os.path.join(REPO, d, "libtrigspline.so")
        if os.path.exists(p):
            lib = ctypes.CDLL(p)
            dp = ctypes.POINTER(ctypes.c_double)
            lib.ts_spline_new.argtypes = [dp, dp, ctypes.c_size_t, ctypes.c_void_p,
                                          ctypes.POINTER(ctypes.c_void_p), ctypes.c_void_p]
            lib.ts_spline_free.argtypes = [ctypes.c_void_p]
            return lib, p
    return None, None


def c_construct(lib, x, f):
    dp = ctypes.POINTER(ctypes.c_double)
    h = ctypes.c_void_p()
    st = lib.ts_spline_new(x.ctypes.data_as(dp), f.ctypes.data_as(dp), len(x), None,
                           ctypes.byref(h), None)
    assert st == 0
    lib.ts_spline_free(h)


def row(name, t, ref=None, goal=None, unit_count=1, ref_name="SciPy"):
    per = t / unit_count * 1e9
    s = "| %-46s | %9.4f | %8.1f |" % (name, t, per)
    if ref is not None:
        ratio = t / ref
        s += " %6.2f x %s" % (ratio, ref_name)
        if goal is not None:
            s += " (goal <= %.1f: %s)" % (goal, "met" if ratio <= goal else "NOT met")
    print(s + " |")


def main():
    rng = np.random.default_rng(2026)
    x = np.cumsum(rng.uniform(0.1, 1.0, N_KNOTS))
    f = np.abs(np.sin(x / 50.0)) * 10.0 + rng.uniform(0.0, 1.0, N_KNOTS)
    lib, libpath = c_library()
    print("# trigspline Python package vs SciPy %s (numpy %s), trigspline %s" % (
        scipy.__version__, np.__version__, trigspline.__version__))
    print("load average at the start: %.2f; %d knots, %d queries; times: min over repetitions"
          % (os.getloadavg()[0], N_KNOTS, N_EVAL))
    if libpath:
        print("C library: %s" % os.path.relpath(libpath, REPO))
    print()
    print("| case | seconds | ns/item | ratio |")
    print("|---|---:|---:|---|")
    reps = 7
    t_pchip = best(lambda: PchipInterpolator(x, f), reps)
    row("construct: SciPy PchipInterpolator(x, f)", t_pchip, unit_count=N_KNOTS)
    t_c = best(lambda: c_construct(lib, x, f), reps) if lib else None
    if t_c:
        row("construct: C ts_spline_new (defaults)", t_c, unit_count=N_KNOTS)
    t_py = best(lambda: trigspline.Spline(x, f), reps)
    row("construct: trigspline.Spline(x, f)", t_py, t_pchip, 0.5, N_KNOTS)
    if t_c:
        row("  same, against the C library", t_py, t_c, 1.5, N_KNOTS, "C")
    t_pos = best(lambda: trigspline.Spline(x, f, shape="positive"), reps)
    row("construct: Spline(x, f, shape='positive')", t_pos, t_pchip, None, N_KNOTS)
    t_mono = best(lambda: PchipInterpolator(x, np.cumsum(f)), 3)
    t_pm = best(lambda: trigspline.Spline(x, np.cumsum(f), shape="monotone"), 3)
    row("construct: Spline(shape='monotone') (monotone data)", t_pm, t_mono, None, N_KNOTS)

    s = trigspline.Spline(x, f)
    p = PchipInterpolator(x, f)
    xs = np.sort(rng.uniform(x[0], x[-1], N_EVAL))
    xr = rng.uniform(x[0], x[-1], N_EVAL)
    for label, q in (("sorted", xs), ("random", xr)):
        tp = best(lambda: p(q), 3)
        row("evaluate %s: SciPy Pchip p(xq)" % label, tp, unit_count=N_EVAL)
        ts = best(lambda: s(q), 3)
        row("evaluate %s: trigspline s(xq)" % label, ts, tp, 0.4, N_EVAL)
        out = np.empty_like(q)
        to = best(lambda: s(q, out=out), 3)
        row("  same, into out= (no allocation)", to, tp, None, N_EVAL)
        td = best(lambda: s(q, 1), 3)
        tpd = best(lambda: p(q, 1), 3)
        row("evaluate %s: s(xq, 1) vs p(xq, 1)" % label, td, tpd, None, N_EVAL)

    pts = [float(v) for v in rng.uniform(x[0], x[-1], N_SCALAR)]

    def scalar_loop(fn):
        for v in pts:
            fn(v)
    tp = best(lambda: scalar_loop(p), 3)
    row("scalar calls: SciPy p(v)", tp, unit_count=N_SCALAR)
    ts = best(lambda: scalar_loop(s), 3)
    row("scalar calls: trigspline s(v)", ts, tp, None, N_SCALAR)


if __name__ == "__main__":
    main()
