#!/usr/bin/env python3
"""Measurements behind the default form, slopes and alpha (docs/defaults-study.md).

Run with the Python package built from this tree and Debian's numpy/scipy:

    python3 -m venv --system-site-packages /tmp/study-venv
    /tmp/study-venv/bin/pip install --no-build-isolation ./bindings/python
    /tmp/study-venv/bin/python scripts/defaults_study.py [--out docs/defaults-study.md] [--quick]

For every candidate (form x slopes x alpha rule) it measures
  (a) the largest excursion beyond an interval's data range, by the exact
      extrema of Spline.report() (docs/method.md §5.9); SciPy's PPoly
      interpolators by the exact roots of each piece's derivative;
  (b) the error on the line y = 3x - 2 at random abscissae;
  (c) knot exactness on every data set;
  (d) the max error on smooth functions at n = 10 ... 10000 intervals and the
      observed order;
  (e) SciPy's TestPCHIP tests that apply, run against the candidate;
and prints markdown tables (also written to --out).
"""
import argparse
import glob
import io
import math
import os
import sys
import time
import warnings

import numpy as np
import scipy
from scipy.interpolate import (Akima1DInterpolator, CubicHermiteSpline, CubicSpline,
                               PchipInterpolator)

import trigspline
from trigspline import Spline, estimate_slopes

ROOT = os.path.dirname(os.path.dirname(os.path.abspath(__file__)))
EPS = np.finfo(float).eps
A_X = 4 / (3 * math.pi)          # X increasing with margin (docs/method.md §4)
A_FC = 4 / math.pi               # monotone polygon for d/Δ <= 3 at both ends
A_ST = 8 / (3 * math.pi)         # monotone polygon for d/Δ <= 2 at both ends


# ---------------------------------------------------------------- data
def read_csv(path):
    """(x, y, title) from a data file: '#' comment lines, one header line, x,y rows."""
    comments, rows, header = [], [], None
    with open(path) as fh:
        for line in fh:
            line = line.strip()
            if not line:
                continue
            if line.startswith("#"):
                comments.append(line[1:].strip())
            elif header is None:
                header = line
            else:
                rows.append([float(v) for v in line.split(",")[:2]])
    a = np.array(rows)
    return a[:, 0], a[:, 1], " ".join(comments)


def datasets():
    """name -> (x, y): the example data, the paper's function data and the corpus."""
    out = {}
    for pat in ("data/examples/*.csv", "data/paper/table*.csv", "data/realworld/*.csv"):
        for p in sorted(glob.glob(os.path.join(ROOT, pat))):
            x, y, _ = read_csv(p)
            if not np.all(np.diff(x) > 0):
                continue  # closed outlines (curves) are not function data
            name = os.path.relpath(p, os.path.join(ROOT, "data"))[:-4]
            out[name] = (x, y)
    return out


# ---------------------------------------------------------------- slopes
def steffen_slopes(x, y, ends="steffen"):
    """Steffen (1990) slopes: |d| <= 2 min(|Δ_left|, |Δ_right|), 0 at extrema;
    ends by his eq. (26): the three-point value, 0 if its sign differs from
    Δ_0's, 2Δ_0 if it exceeds that (mirrored at the right end)."""
    x, y = np.asarray(x, float), np.asarray(y, float)
    h = np.diff(x)
    D = np.diff(y) / h
    n = len(h)
    d = np.empty(n + 1)
    if n == 1:
        d[:] = D[0]
        return d
    p = (D[:-1] * h[1:] + D[1:] * h[:-1]) / (h[:-1] + h[1:])
    d[1:-1] = (np.sign(D[:-1]) + np.sign(D[1:])) * np.minimum(
        np.minimum(np.abs(D[:-1]), np.abs(D[1:])), 0.5 * np.abs(p))

    def end(D0, D1, h0, h1):
        p0 = D0 * (1 + h0 / (h0 + h1)) - D1 * h0 / (h0 + h1)
        if p0 * D0 <= 0:
            return 0.0
        if abs(p0) > 2 * abs(D0):
            return 2 * D0
        return p0
    if ends == "gsl":   # GSL's gsl_interp_steffen: the end secants themselves
        d[0], d[-1] = D[0], D[-1]
    else:
        d[0] = end(D[0], D[1], h[0], h[1])
        d[-1] = end(D[-1], D[-2], h[-1], h[-2])
    return d


def slopes_of(method, x, y):
    if method == "steffen":
        return steffen_slopes(x, y)
    if method == "steffen-gsl":
        return steffen_slopes(x, y, "gsl")
    return estimate_slopes(x, y, method)


def monotone_a(x, y, d, floor):
    """The per-interval rule: the smallest a_i >= floor with a monotone control
    polygon where the slopes have the secant's sign, a_i = max(floor,
    2(d_i + d_{i+1})/(3π Δ_i)) with d measured along sign(Δ_i) (docs/method.md §5.5)."""
    h = np.diff(x)
    df = np.diff(y)
    s = np.sign(df)
    dl = np.maximum(d[:-1] * s, 0.0)
    dr = np.maximum(d[1:] * s, 0.0)
    with np.errstate(divide="ignore", invalid="ignore"):
        need = np.where(df != 0, 2 * (dl + dr) * h / (3 * math.pi * np.abs(df)), 0.0)
    return np.maximum(floor, need)


# ---------------------------------------------------------------- candidates
class Cand:
    """A trigspline configuration: form, slopes, alpha rule ('fixed' a or
    'mono' floor), shape scheme."""

    def __init__(self, label, form, slopes, rule, a, shape="none"):
        self.label, self.form, self.slopes, self.rule, self.a, self.shape = (
            label, form, slopes, rule, a, shape)

    def build(self, x, y):
        kw = {"form": self.form, "shape": self.shape}
        if self.slopes in ("steffen", "steffen-gsl"):
            d = steffen_slopes(x, y, "gsl" if self.slopes == "steffen-gsl" else "steffen")
            kw["slopes_values"] = d
        else:
            kw["slopes"] = self.slopes
            d = None
        if self.rule == "mono":
            if d is None:
                d = slopes_of(self.slopes, x, y)
            kw["alpha"] = monotone_a(x, y, d, self.a)
        else:
            kw["alpha"] = self.a
        return Spline(x, y, **kw)


def G(label, slopes, rule, a, shape="none", form="geometric"):
    return Cand(label, form, slopes, rule, a, shape)


A_REC = 0.85                     # recommended: 8/(3π) = 0.84883 rounded up
A_Q = 0.815                      # the quadratic sweet spot (section (d))
CANDS = [
    G("geo Steffen a=0.85", "steffen", "fixed", A_REC),
    G("geo Steffen (GSL ends) a=0.85", "steffen-gsl", "fixed", A_REC),
    G("geo Steffen a=0.8", "steffen", "fixed", 0.8),
    G("geo Steffen a=0.7", "steffen", "fixed", 0.7),
    G("geo Steffen a=0.65", "steffen", "fixed", 0.65),
    G("geo Steffen mono≥0.815", "steffen", "mono", A_Q),
    G("geo Steffen a=1", "steffen", "fixed", 1.0),
    G("geo FC a=4/π", "fritsch-carlson", "fixed", A_FC),
    G("geo FC mono≥0.815", "fritsch-carlson", "mono", A_Q),
    G("geo FC mono≥4/(3π)", "fritsch-carlson", "mono", A_X),
    G("geo FC a=1.05", "fritsch-carlson", "fixed", 1.05),
    G("geo FC a=1", "fritsch-carlson", "fixed", 1.0),
    G("geo FC a=0.85", "fritsch-carlson", "fixed", A_REC),
    G("geo makima a=1", "makima", "fixed", 1.0),
    G("geo makima a=4/π", "makima", "fixed", A_FC),
    G("geo makima mono≥1", "makima", "mono", 1.0),
    G("geo Akima a=1", "akima", "fixed", 1.0),
    G("geo Akima mono≥1", "akima", "mono", 1.0),
    G("geo arithmetic a=1", "arithmetic", "fixed", 1.0),
    G("geo arithmetic mono≥1", "arithmetic", "mono", 1.0),
    G("paper Steffen a=0.85", "steffen", "fixed", A_REC, form="paper"),
    G("c1 Steffen a=0.85", "steffen", "fixed", A_REC, form="c1"),
    G("paper FC a=4/π", "fritsch-carlson", "fixed", A_FC, form="paper"),
    Cand("old default (paper arith a=1)", "paper", "arithmetic", "fixed", 1.0),
]
POSITIVE = [
    G("geo Steffen a=0.85 +positive", "steffen", "fixed", A_REC, shape="positive"),
    G("geo FC a=4/π +positive", "fritsch-carlson", "fixed", A_FC, shape="positive"),
    Cand("old default +positive", "paper", "arithmetic", "fixed", 1.0, shape="positive"),
]


def makima_scipy(x, y):
    """SciPy 1.10 has no Akima1DInterpolator(method='makima'): the same cubic
    Hermite interpolant from the library's makima slopes (Moler's formula)."""
    return CubicHermiteSpline(x, y, estimate_slopes(x, y, "makima"))


REFS = [("SciPy PCHIP", PchipInterpolator), ("SciPy CubicSpline", CubicSpline),
        ("SciPy Akima", Akima1DInterpolator), ("makima (cubic)", makima_scipy)]


# ---------------------------------------------------------------- (a) excursions
def ppoly_excursion(pp, x, y):
    """Largest excursion of a cubic PPoly beyond [min, max] of each interval's
    data: exact extrema (roots of each piece's derivative)."""
    c = pp.c
    h = np.diff(x)
    worst = 0.0
    for i in range(len(h)):
        c3, c2, c1, c0 = c[:, i]
        cands = [0.0, h[i]]
        A, B, C = 3 * c3, 2 * c2, c1
        if A != 0:
            disc = B * B - 4 * A * C
            if disc >= 0:
                r = math.sqrt(disc)
                q = -0.5 * (B + math.copysign(r, B))
                roots = [q / A] + ([C / q] if q != 0 else [])
                cands += [t for t in roots if 0 < t < h[i]]
        elif B != 0:
            t = -C / B
            if 0 < t < h[i]:
                cands.append(t)
        v = [((c3 * t + c2) * t + c1) * t + c0 for t in cands]
        lo, hi = min(y[i], y[i + 1]), max(y[i], y[i + 1])
        worst = max(worst, max(v) - hi, lo - min(v))
    return worst


def spline_excursion(s):
    rep = s.report()
    return max(max(r["excursion_above"], r["excursion_below"]) for r in rep)


_TH = np.linspace(0, math.pi / 2, 4001)
_S, _C = np.sin(_TH), np.cos(_TH)
_A = np.stack([(1 - _S) ** 3, _S * (1 - _S) * (3 - _S), _C * (1 - _C) * (3 - _C), (1 - _C) ** 3])


def spline_nonmonotone(s, y):
    """Intervals whose curve is not monotone in the direction of its data, by
    4001 samples of Y(θ) = Σ A_l(θ) B_l (X is increasing for every a used here,
    docs/method.md §4); a flat interval must be constant.  Tolerance 8 ulps of max|f|."""
    B = np.array([r["B"] for r in s.report()])            # (n, 4)
    Y = (B[:, 1:] - B[:, :1]) @ _A[1:]                      # Y − B0, as evaluation forms it
    dY = np.diff(Y, axis=1)
    sg = np.sign(np.diff(y))[:, None]
    tol = tol_of(y)
    bad = np.where(sg[:, 0] != 0, (dY * sg < -tol).any(axis=1), (np.abs(dY) > tol).any(axis=1))
    return int(bad.sum())


def tol_of(y):
    """'0 to rounding': a few ulps of the data's magnitude."""
    return 8 * EPS * max(1.0, float(np.max(np.abs(y))))



# ---------------------------------------------------------------- (a') random stress
def random_sets(count, seed=2026):
    """Random data meant to reach the slope bounds: spacings exp(N(0, 1.5)) (ratios
    of neighbouring widths up to ~100), values random, random-walk or with flat runs."""
    rng = np.random.default_rng(seed)
    for k in range(count):
        n = int(rng.integers(3, 25))
        x = np.concatenate([[0.0], np.cumsum(np.exp(rng.normal(0, 1.5, n - 1)))])
        kind = k % 4
        if kind == 0:
            y = rng.random(n)
        elif kind == 1:
            y = np.cumsum(rng.normal(0, 1, n))
        elif kind == 2:
            y = np.round(rng.random(n) * 3)     # flat runs and plateaus
        else:
            # a staircase: short steep steps between long gentle ones, which puts
            # both end slopes of a gentle interval at the slope bound (d/Δ -> 3 or 2)
            w = np.where(np.arange(n - 1) % 2 == 0, 10 ** rng.uniform(-3, -1, n - 1), 1.0)
            x = np.concatenate([[0.0], np.cumsum(w)])
            rise = np.where(np.arange(n - 1) % 2 == 0, 1.0, 10 ** rng.uniform(-3, -1, n - 1))
            y = np.concatenate([[0.0], np.cumsum(rise)]) * rng.choice([-1.0, 1.0])
        yield x, y


def slope_ratio(method, x, y):
    """Largest d/Δ at either end of an interval with Δ != 0 (d measured along Δ);
    and the least (negative: a slope against its secant)."""
    d = slopes_of(method, x, y)
    D = np.diff(y) / np.diff(x)
    m = D != 0
    r = np.concatenate([(d[:-1] / np.where(m, D, 1))[m], (d[1:] / np.where(m, D, 1))[m]])
    return (float(np.max(r)), float(np.min(r))) if r.size else (0.0, 0.0)


# ---------------------------------------------------------------- alpha: the quadratic constant
def quad_constant(a, m=20001):
    """max over θ of |X̂² − Ŷ| for f = x² on [0, 1] with exact slopes (0, 2) in the
    geometric form: the h² f''-term of the error (docs/method.md §4, §8)."""
    th = np.linspace(0, math.pi / 2, m)
    s, c = np.sin(th), np.cos(th)
    A1, A2 = s * (1 - s) * (3 - s), c * (1 - c) * (3 - c)
    k = 2 / (3 * math.pi * a)
    X = s * s + k * (A1 - A2)
    Y = s * s - 2 * k * A2
    return float(np.max(np.abs(X * X - Y)))


def jittered(fn, a, b, n, rng):
    """n intervals, knots moved by up to 40 % of the uniform width (seeded)."""
    x = np.linspace(a, b, n + 1)
    x[1:-1] += (rng.random(n - 1) - 0.5) * 0.8 * (b - a) / n
    return x

# ---------------------------------------------------------------- (d) smooth functions
def bump(x):
    out = np.zeros_like(x)
    m = np.abs(x) < 1
    out[m] = np.exp(1 - 1 / (1 - x[m] ** 2))
    return out


SMOOTH = [("sin on [0, 2π]", np.sin, 0.0, 2 * math.pi),
          ("exp on [0, 1]", np.exp, 0.0, 1.0),
          ("Runge 1/(1+25x²) on [-1, 1]", lambda t: 1 / (1 + 25 * t * t), -1.0, 1.0),
          ("bump exp(1-1/(1-x²)) on [-1.5, 1.5]", bump, -1.5, 1.5)]
NS = [10, 30, 100, 300, 1000, 3000, 10000]


def smooth_error(make, fn, a, b, n, rng, x=None):
    if x is None:
        x = np.linspace(a, b, n + 1)
    y = fn(x)
    s = make(x, y)
    # 16 points per interval at fixed relative places plus random ones, capped
    per = max(4, min(16, 160000 // n))
    t = np.concatenate([np.linspace(0, 1, per + 2)[1:-1], rng.random(per)])
    xq = (x[:-1, None] + np.outer(np.diff(x), t)).ravel()
    xq = xq[(xq >= a) & (xq <= b)]
    return float(np.max(np.abs(s(xq) - fn(xq))))


def order(errs):
    """Least-squares slope of -log(err) against log(n) over n = 1000 ... 10000."""
    ns = np.array(NS[-3:], float)
    e = np.array(errs[-3:])
    if np.any(e <= 0):
        return float("nan")
    return -np.polyfit(np.log(ns), np.log(e), 1)[0]


# ---------------------------------------------------------------- (e) SciPy's PCHIP tests
def scipy_pchip_tests(make):
    """TestPCHIP (scipy/interpolate/tests/test_polyint.py) that apply to any
    shape-preserving interpolant; a dict test -> True/False/message."""
    res = {}
    np.random.seed(1234)
    xi = np.sort(np.random.random(20))
    yi = np.random.random(20)
    p = make(xi, yi)
    ok = True
    for i in range(len(xi) - 1):
        y1, y2 = sorted((yi[i], yi[i + 1]))
        yp = p(np.linspace(xi[i], xi[i + 1], 10))
        ok &= bool(((y1 <= yp + 1e-15) & (yp <= y2 + 1e-15)).all())
    res["overshoot"] = ok
    ok_lit, ok_strict = True, True
    for i in range(len(xi) - 1):
        yp = p(np.linspace(xi[i], xi[i + 1], 10))
        dy = yi[i + 1] - yi[i]
        ok_lit &= bool((dy * (yp[1:] - yp[:1]) > 0).all())       # SciPy's text
        ok_strict &= bool((dy * np.diff(yp) > 0).all())          # consecutive samples
    res["monotone"] = ok_lit and ok_strict
    x = np.array([0.0, 0.1, 0.25, 0.35])
    ok = True
    for yy in (np.array([279.35, 0.5e3, 1.0e3, 2.5e3]), np.array([279.35, 2.5e3, 1.50e3, 1.0e3])):
        pp = make(x, yy)
        for t in (x[0], x[-1]):
            ok &= bool(pp(np.array([t]), 1)[0] != 0)
    res["endslopes"] = ok
    with warnings.catch_warnings():
        warnings.filterwarnings("error")
        try:
            pz = make(np.arange(10.0), np.zeros(10))
            res["all_zeros"] = bool(np.all(pz(np.linspace(0, 9, 101)) == 0.0))
        except Exception as e:  # noqa: BLE001 - report any failure
            res["all_zeros"] = "raised %s" % type(e).__name__
    xx = np.linspace(0, 1, 11)
    p2 = make(np.array([0.0, 1.0]), np.array([0.0, 2.0]))
    res["two_points"] = bool(np.max(np.abs(p2(xx) - 2 * xx)) <= 1e-15)
    data = np.array([[0, 4, 12, 27, 47, 60, 79, 87, 99, 100],
                     [-33, -33, -19, -2, 12, 26, 38, 45, 53, 55]])
    xx = np.arange(100)
    try:
        c1 = make(data[0], data[1])(xx)
        res["cast"] = bool(np.allclose(c1, make(data[0] * 1.0, data[1] * 1.0)(xx * 1.0),
                                       atol=1e-14, rtol=1e-14))
    except trigspline.TrigsplineError as e:
        res["cast"] = "refused (%s)" % e.name
    nag = np.loadtxt(io.StringIO("""7.99 0.0\n8.09 0.27643E-4\n8.19 0.43750E-1\n8.70 0.16918
        9.20 0.46943\n10.00 0.94374\n12.00 0.99864\n15.00 0.99992\n20.00 0.99999"""))
    pn = make(nag[:, 0], nag[:, 1])
    q = np.linspace(7.99, 20, 4001)
    res["nag monotone"] = bool(np.all(np.diff(pn(q)) >= 0))
    return res


# ---------------------------------------------------------------- output
class Out:
    def __init__(self):
        self.buf = io.StringIO()

    def __call__(self, *lines):
        for line in lines:
            print(line)
            self.buf.write(line + "\n")
        sys.stdout.flush()

    def table(self, head, rows):
        self("| " + " | ".join(head) + " |", "|" + "---|" * len(head))
        for r in rows:
            self("| " + " | ".join(str(c) for c in r) + " |")
        self("")


def fmt(v, pct=False):
    if isinstance(v, str):
        return v
    if v != v:
        return "–"
    if pct:
        return "0" if v == 0 else "%.3g %%" % v
    return "0" if v == 0 else "%.2e" % v


MARKER = "<!-- the tables below are written by scripts/defaults_study.py -->"


def main():
    ap = argparse.ArgumentParser(description=__doc__.split("\n")[0])
    ap.add_argument("--out", help="also write the tables (markdown) to this file")
    ap.add_argument("--quick", action="store_true", help="n up to 1000 only")
    args = ap.parse_args()
    global NS
    if args.quick:
        NS = NS[:5]
    o = Out()
    t0 = time.time()
    data = datasets()
    cands = CANDS
    o("## (a) Largest excursion beyond an interval's data range", "",
      "Per data set: max over intervals of the distance by which the curve leaves "
      "[min(f_i, f_{i+1}), max(f_i, f_{i+1})], in %% of the set's range max f − min f. "
      "trigspline: exact extrema (Spline.report, docs/method.md §5.9); SciPy: exact "
      "roots of each cubic piece's derivative. 'worse than PCHIP' counts sets where the "
      "excursion exceeds PCHIP's by more than 8 ulps of max|f|. %d data sets "
      "(data/examples, data/paper tables, data/realworld)." % len(data), "")
    exc = {}   # (label, name) -> relative excursion (%)
    worse, nonmono = {}, {}
    for name, (x, y) in data.items():
        rng_ = float(np.max(y) - np.min(y)) or 1.0
        ref_abs = {}
        for lab, mk in REFS:
            e = ppoly_excursion(mk(x, y), x, y)
            ref_abs[lab] = e
            exc[(lab, name)] = 100 * e / rng_
        for c in cands + (POSITIVE if np.all(y >= 0) else []):
            try:
                sp = c.build(x, y)
                e = spline_excursion(sp)
            except trigspline.TrigsplineError as err:
                exc[(c.label, name)] = "refused (%s)" % err.name
                continue
            exc[(c.label, name)] = 100 * e / rng_
            if spline_nonmonotone(sp, y):
                nonmono.setdefault(c.label, []).append(name)
            if e > ref_abs["SciPy PCHIP"] + tol_of(y):
                worse.setdefault(c.label, []).append(name)
    labels = [lab for lab, _ in REFS] + [c.label for c in cands] + [c.label for c in POSITIVE]
    rows = []
    for lab in labels:
        vals = [exc[(lab, n)] for n in data if (lab, n) in exc and not isinstance(exc[(lab, n)], str)]
        nz = sum(1 for v in vals if v > 1e-10)
        w = worse.get(lab, [])
        rows.append([lab, fmt(max(vals), True), "%d / %d" % (nz, len(vals)),
                     "–" if lab in dict(REFS) else "%d%s" % (len(w), (": " + ", ".join(w[:3]) + (" …" if len(w) > 3 else "")) if w else ""),
                     "0 (proof)" if lab == "SciPy PCHIP" else ("–" if lab in dict(REFS) else str(len(nonmono.get(lab, []))))])
    o("### Summary over all data sets", "")
    o.table(["candidate", "largest excursion", "sets with excursion > 1e-10 %",
             "sets worse than PCHIP", "sets with a non-monotone interval"], rows)
    main_labels = ["SciPy PCHIP", "SciPy CubicSpline", "SciPy Akima", "makima (cubic)",
                   "geo Steffen a=0.85", "geo Steffen a=0.85 +positive", "geo FC a=4/π",
                   "geo makima a=1", "old default (paper arith a=1)", "old default +positive"]
    o("### Per data set (% of the set's range)", "")
    rows = []
    for name in data:
        rows.append([name, str(len(data[name][0]))] +
                    [fmt(exc.get((lab, name), "n/a"), True) for lab in main_labels])
    o.table(["data set", "points"] + main_labels, rows)

    # ---- (a') random stress
    R = 3000
    o("### Random data at the slope bounds (%d sets)" % R, "",
      "Random sets of 3–24 points, spacings exp(N(0, 1.5)) (neighbouring widths differ by "
      "factors up to ~100, which drives Fritsch–Carlson's d/Δ towards 3 and Steffen's to 2), "
      "values uniform, random walk, rounded to {0, 1, 2, 3} (flat runs), or a staircase of "
      "short steep and long gentle steps (both slopes of a gentle interval at the bound). "
      "Sets with an "
      "excursion above 8 ulps of max|f|, the largest in % of the set's range, and sets "
      "where some interval's curve is not monotone in its data's direction (4001 samples "
      "of Y(θ) per interval; PCHIP is monotone on every interval by Fritsch–Carlson).", "")
    sets = list(random_sets(R))
    rows = []
    for lab, mk in REFS[:1]:
        bad, big = 0, 0.0
        for x, y in sets:
            e = ppoly_excursion(mk(x, y), x, y)
            bad += e > tol_of(y)
            big = max(big, 100 * e / (float(np.ptp(y)) or 1.0))
        rows.append([lab, "%d" % bad, fmt(big, True)])
    rows[0] += ["0 (proof)"]
    for c in cands:
        bad, big, nm = 0, 0.0, 0
        for x, y in sets:
            sp = c.build(x, y)
            e = spline_excursion(sp)
            bad += e > tol_of(y)
            big = max(big, 100 * e / (float(np.ptp(y)) or 1.0))
            nm += spline_nonmonotone(sp, y) > 0
        rows.append([c.label, "%d" % bad, fmt(big, True), "%d" % nm])
    o.table(["candidate", "sets with excursion", "largest excursion",
             "sets with a non-monotone interval (sampled)"], rows)
    rows = []
    for meth in ("fritsch-carlson", "steffen", "makima", "akima", "arithmetic"):
        hi, lo = -np.inf, np.inf
        for x, y in list(sets) + list(data.values()):
            a_, b_ = slope_ratio(meth, x, y)
            hi, lo = max(hi, a_), min(lo, b_)
        rows.append([meth, "%.4f" % hi, "%.4f" % lo])
    o("Slope ratios d/Δ at the ends of intervals with Δ ≠ 0, over the random sets and every "
      "data set (the bound the proof needs: FC ≤ 3, Steffen ≤ 2, both ≥ 0):", "")
    o.table(["slopes", "largest d/Δ", "least d/Δ"], rows)

    # ---- (b) lines and (c) knots
    o("## (b) Straight lines and (c) knots", "",
      "(b) y = 3x − 2 at 200 sorted uniform random x in [0, 10] (seed 7), max |S − y| at "
      "20000 random points, relative to max |y| = 28. (c) number of knots over all data "
      "sets where S(x_i) ≠ f_i (bit comparison).", "")
    rng = np.random.default_rng(7)
    xl = np.sort(rng.uniform(0, 10, 200))
    yl = 3 * xl - 2
    ql = rng.uniform(xl[0], xl[-1], 20000)
    rows = []
    for c in cands:
        s = c.build(xl, yl)
        el = float(np.max(np.abs(s(ql) - (3 * ql - 2)))) / 28
        bad = 0
        for name, (x, y) in data.items():
            bad += int(np.sum(c.build(x, y)(x) != y))
        rows.append([c.label, fmt(el), str(bad)])
    for lab, mk in REFS:
        el = float(np.max(np.abs(mk(xl, yl)(ql) - (3 * ql - 2)))) / 28
        bad = sum(int(np.sum(mk(x, y)(x) != y)) for x, y in data.values())
        rows.append([lab, fmt(el), str(bad)])
    o.table(["candidate", "line: max rel. error", "knots not exact"], rows)

    # ---- alpha scan
    o("## (d′) Choosing α: the accuracy cost of a larger α", "",
      "Geometric form with exact slopes: the h²·f'' term of the error is max|X̂² − Ŷ| for "
      "f = x² on [0, 1] (slopes 0 and 2); it nearly vanishes at a ≈ %.3f:" % A_Q, "")
    avals = [0.6, 0.6944, 0.75, 0.8, A_Q, A_ST, A_REC, 0.9, 1.0, 1.0415, A_FC, 1.5, 2.0]
    o.table(["a"] + ["%.4g" % a for a in avals], [["max abs(X̂²−Ŷ)"] + ["%.4f" % quad_constant(a) for a in avals]])
    o("Max error at n = 1000 intervals for fixed a (uniform grid; 'jit.': knots moved by up "
      "to ±40 % of the width):", "")
    rng = np.random.default_rng(5)
    rows = []
    for meth in ("steffen", "fritsch-carlson"):
        for a in avals:
            c = G("", meth, "fixed", a)
            row = ["%s a=%.4g" % (meth, a)]
            for fname, fn, lo, hi in SMOOTH:
                row.append(fmt(smooth_error(c.build, fn, lo, hi, 1000, rng)))
            for fname, fn, lo, hi in SMOOTH[::2]:
                xj = jittered(fn, lo, hi, 1000, np.random.default_rng(11))
                row.append(fmt(smooth_error(c.build, fn, lo, hi, 1000, rng, xj)))
            rows.append(row)
    for lab, mk in REFS[:1]:
        row = [lab]
        for fname, fn, lo, hi in SMOOTH:
            row.append(fmt(smooth_error(mk, fn, lo, hi, 1000, rng)))
        for fname, fn, lo, hi in SMOOTH[::2]:
            xj = jittered(fn, lo, hi, 1000, np.random.default_rng(11))
            row.append(fmt(smooth_error(mk, fn, lo, hi, 1000, rng, xj)))
        rows.append(row)
    o.table(["slopes, a"] + [f[0].split(" on")[0] for f in SMOOTH] +
            [f[0].split(" on")[0] + " jit." for f in SMOOTH[::2]], rows)

    # ---- (d) smooth functions
    o("## (d) Smooth functions: max error, uniform grid, n intervals", "",
      "Max |S − f| at 16 fixed and 16 random points per interval (fewer for large n, "
      "at least 4); order = least-squares slope over n = %s." % ", ".join(map(str, NS[-3:])), "")
    acc_cands = [c for c in cands if c.label in (
        "geo Steffen a=0.85", "geo Steffen (GSL ends) a=0.85", "geo Steffen a=0.8",
        "geo Steffen mono≥0.815", "geo Steffen a=1",
        "geo FC a=4/π", "geo FC mono≥0.815", "geo FC a=1", "geo makima a=1",
        "geo Akima a=1", "geo arithmetic a=1", "old default (paper arith a=1)")]
    makers = [(c.label, c.build) for c in acc_cands] + list(REFS)
    rng = np.random.default_rng(3)
    summary = {}
    for fname, fn, a, b in SMOOTH:
        rows = []
        for lab, mk in makers:
            errs = [smooth_error(mk, fn, a, b, n, rng) for n in NS]
            summary[(lab, fname)] = errs
            rows.append([lab] + [fmt(e) for e in errs] + ["%.2f" % order(errs)])
        o("### %s" % fname, "")
        o.table(["method"] + ["n=%d" % n for n in NS] + ["order"], rows)

    # ---- (e) SciPy's PCHIP tests
    o("## (e) SciPy's TestPCHIP against each candidate", "",
      "overshoot, monotone (SciPy's text and consecutive samples), endslopes, all_zeros "
      "(no warning, exactly 0), two_points (atol 1e-15), cast (integer input), and "
      "monotonicity on test_nag's data (4001 samples; its values are NAG's PCHIP and do "
      "not apply).", "")
    tests = None
    rows = []
    for c in cands + POSITIVE:
        r = scipy_pchip_tests(c.build)
        tests = list(r)
        rows.append([c.label] + [("pass" if v is True else ("FAIL" if v is False else v))
                                 for v in r.values()])
    o.table(["candidate"] + tests, rows)
    o("trigspline %s, NumPy %s, SciPy %s; %.0f s." % (
        getattr(trigspline, "__version__", "?"), np.__version__, scipy.__version__,
        time.time() - t0))
    if args.out:
        # keep the hand-written part of the document above the marker
        head = ""
        if os.path.exists(args.out):
            with open(args.out) as fh:
                text = fh.read()
            if MARKER in text:
                head = text[:text.index(MARKER)]
        with open(args.out, "w") as fh:
            fh.write(head + MARKER + "\n\n" + o.buf.getvalue())


if __name__ == "__main__":
    main()
