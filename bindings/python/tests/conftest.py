"""Shared data and independent references for the tests of the Python package.

Expected values never come from the package itself:
  - ref_paper: docs/method.md §2/§3 re-derived with numpy (basis, control
    values, θ = (π/2)(x − x_i)/h), from the slopes and a the spline reports;
  - the C library built by CMake (libtrigspline.so, through ctypes) for
    bit-identity (TS_BUILD_DIR, default <repo>/build);
  - SciPy (PchipInterpolator, quad, brentq), finite differences, dense
    sampling with bisection.
The package under test is the installed one: run pytest from outside the
source tree (tests/run.sh does).
"""
import math
import os

import numpy as np
import pytest

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.normpath(os.path.join(HERE, "..", "..", ".."))
PAPER = os.path.join(REPO, "data", "paper")
EPS = np.finfo(float).eps


def read_csv(name):
    a = np.loadtxt(os.path.join(PAPER, name), delimiter=",", skiprows=1)
    return a[:, 0].copy(), a[:, 1].copy()


@pytest.fixture
def table1():
    return read_csv("table1_positive.csv")


def ref_basis(th):
    """A_l(θ) of docs/method.md §2, shape (4, ...)."""
    s, c = np.sin(th), np.cos(th)
    return np.array([(1 - s) ** 3, 3 * s - 4 * s * s + s ** 3, 3 * c - 4 * c * c + c ** 3,
                     (1 - c) ** 3])


def ref_paper(x, f, d, a, xq, c1=False):
    """S(xq) of docs/method.md §3 (paper form; C¹ option with c1=True)."""
    x, f, d, a = map(np.asarray, (x, f, d, a))
    n = len(x) - 1
    i = np.clip(np.searchsorted(x, xq, side="right") - 1, 0, n - 1)
    h = x[i + 1] - x[i]
    K = 2 * h / (3 * math.pi)
    if c1:
        am = np.maximum(a[:-1], a[1:])
        aknot = np.concatenate([[a[0]], am, [a[-1]]])
        b1 = f[i] + K * d[i] / aknot[i]
        b2 = f[i + 1] - K * d[i + 1] / aknot[i + 1]
    else:
        b1 = f[i] + K / a[i] * d[i]
        b2 = f[i + 1] - K / a[i] * d[i + 1]
    A = ref_basis((math.pi / 2) * (xq - x[i]) / h)
    return A[0] * f[i] + A[1] * b1 + A[2] * b2 + A[3] * f[i + 1]


def bisect_roots(fn, lo, hi, m=200001, y=0.0):
    """Roots of fn - y on [lo, hi] by dense sign changes + bisection."""
    xs = np.linspace(lo, hi, m)
    v = fn(xs) - y
    out = []
    for j in np.flatnonzero(v == 0):
        out.append(xs[j])
    for j in np.flatnonzero(np.sign(v[:-1]) * np.sign(v[1:]) < 0):
        a, b = xs[j], xs[j + 1]
        fa = fn(np.array([a]))[0] - y
        for _ in range(100):
            mid = 0.5 * (a + b)
            fm = fn(np.array([mid]))[0] - y
            if fm == 0:
                a = b = mid
                break
            if (fm < 0) == (fa < 0):
                a, fa = mid, fm
            else:
                b = mid
        out.append(0.5 * (a + b))
    return np.sort(np.array(out))
