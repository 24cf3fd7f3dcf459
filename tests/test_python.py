#!/usr/bin/env python3
"""Tests of the Python binding (python/trigspline) against BUILD_DIR/libtrigspline.so.

    python3 tests/test_python.py BUILD_DIR

Standard library only; the numpy checks run only when numpy is importable.
Expected values come from outside the binding and the library:
  - struct layouts: sizeof/offsetof printed by a C program compiled here with
    cc against include/ (skipped without a C compiler);
  - values, derivatives, integrals: docs/method.md §2/§3/§6 re-derived below in pure
    Python (math module), written from docs/method.md, not from the C code;
  - shape schemes: the paper's tables (data/paper), checked on
    dense samples and against the reported exact minima;
  - curves: knots recomputed from docs/method.md §7, the polygon/polyline length bounds.
Last line: "test_python: N passed, M failed".
"""
import array
import ctypes
import math
import os
import random
import shutil
import subprocess
import sys
import tempfile

HERE = os.path.dirname(os.path.abspath(__file__))
REPO = os.path.dirname(HERE)
PAPER = os.path.join(REPO, "data", "paper")
EPS = 2.0 ** -52

passed = 0
failed = 0


def check(cond, msg):
    global passed, failed
    if cond:
        passed += 1
    else:
        failed += 1
        print("FAIL: " + msg, file=sys.stderr)
    return cond


def close(a, b, tol, msg):
    ok = abs(a - b) <= tol  # NaN fails
    return check(ok, "%s: %r vs %r (tol %.3g)" % (msg, a, b, tol))


def raises(fn, exc, msg):
    try:
        fn()
    except exc as e:
        check(True, msg)
        return e
    except Exception as e:  # wrong kind
        check(False, "%s: raised %r instead of %s" % (msg, e, exc.__name__))
        return None
    check(False, "%s: did not raise %s" % (msg, exc.__name__))
    return None


def read_csv(name):
    rows = []
    with open(os.path.join(PAPER, name)) as fh:
        next(fh)
        for line in fh:
            if line.strip():
                rows.append([float(v) for v in line.split(",")])
    return rows


# ---------------------------------------------------------------------------
# docs/method.md §2, §3, §6 re-derived (pure Python)

def ref_basis(th):
    s, c = math.sin(th), math.cos(th)
    A = [(1 - s) ** 3, 3 * s - 4 * s * s + s ** 3, 3 * c - 4 * c * c + c ** 3, (1 - c) ** 3]
    # first derivatives in theta: docs/method.md §2
    A1 = [-3 * (1 - s) ** 2 * c, c * (3 - 8 * s + 3 * s * s),
          -s * (3 - 8 * c + 3 * c * c), 3 * (1 - c) ** 2 * s]
    # second derivatives: the derivatives of the lines above, by hand
    A2 = [6 * (1 - s) * c * c + 3 * (1 - s) ** 2 * s,
          -s * (3 - 8 * s + 3 * s * s) + c * c * (6 * s - 8),
          -c * (3 - 8 * c + 3 * c * c) + s * s * (6 * c - 8),
          6 * (1 - c) * s * s + 3 * (1 - c) ** 2 * c]
    return A, A1, A2


def ref_slopes(x, f):
    """docs/method.md §6 three-point arithmetic mean with its end formulas."""
    n = len(x) - 1
    h = [x[i + 1] - x[i] for i in range(n)]
    D = [(f[i + 1] - f[i]) / h[i] for i in range(n)]
    if n == 1:
        return [D[0], D[0]]
    d = [0.0] * (n + 1)
    for i in range(1, n):
        d[i] = (h[i] * D[i - 1] + h[i - 1] * D[i]) / (h[i - 1] + h[i])
    d[0] = D[0] + (D[0] - D[1]) * h[0] / (h[0] + h[1])
    d[n] = D[n - 1] + (D[n - 1] - D[n - 2]) * h[n - 1] / (h[n - 1] + h[n - 2])
    return d


class RefSpline(object):
    """docs/method.md §3 paper form (c1=False) or the C¹ option (c1=True)."""

    def __init__(self, x, f, alpha, beta, c1=False, d=None):
        self.x, self.f = x, f
        n = len(x) - 1
        self.n = n
        self.d = d if d is not None else ref_slopes(x, f)
        self.a = [alpha[i] + beta[i] for i in range(n)]
        self.B = []
        for i in range(n):
            h = x[i + 1] - x[i]
            K = 2 * h / (3 * math.pi)
            if c1:
                aL = max(self.a[i - 1], self.a[i]) if i > 0 else self.a[i]
                aR = max(self.a[i], self.a[i + 1]) if i + 1 < n else self.a[i]
                b1, b2 = f[i] + K * self.d[i] / aL, f[i + 1] - K * self.d[i + 1] / aR
            else:
                k = K / self.a[i]
                b1, b2 = f[i] + k * self.d[i], f[i + 1] - k * self.d[i + 1]
            self.B.append([f[i], b1, b2, f[i + 1]])

    def interval(self, xv):
        for i in range(self.n - 1, -1, -1):  # right-hand interval at inner knots
            if xv >= self.x[i]:
                return i
        return 0

    def eval(self, xv, i=None):
        i = self.interval(xv) if i is None else i
        h = self.x[i + 1] - self.x[i]
        w = (math.pi / 2) / h
        th = (xv - self.x[i]) * w
        A, A1, A2 = ref_basis(th)
        B = self.B[i]
        return (sum(A[l] * B[l] for l in range(4)), w * sum(A1[l] * B[l] for l in range(4)),
                w * w * sum(A2[l] * B[l] for l in range(4)))

    def integral_whole(self, i):
        # ∫_0^{π/2} A_l dθ by hand: A0, A3 -> 5π/4 - 11/3; A1, A2 -> 11/3 - π
        e, m = 1.25 * math.pi - 11.0 / 3.0, 11.0 / 3.0 - math.pi
        h = self.x[i + 1] - self.x[i]
        B = self.B[i]
        return 2 * h / math.pi * (e * (B[0] + B[3]) + m * (B[1] + B[2]))

    def integral_simpson(self, a, b, per=2000):
        """Composite Simpson split at the knots, per subintervals per piece."""
        pts = [a] + [t for t in self.x if a < t < b] + [b]
        tot = 0.0
        for p, q in zip(pts[:-1], pts[1:]):
            i = self.interval(p)
            hh = (q - p) / per
            s = self.eval(p, i)[0] + self.eval(q, i)[0]
            for j in range(1, per):
                s += (4 if j % 2 else 2) * self.eval(p + j * hh, i)[0]
            tot += s * hh / 3
        return tot


# ---------------------------------------------------------------------------

def test_layout(ffi):
    """ctypes mirrors vs the C compiler's sizeof/offsetof."""
    cc = shutil.which("cc") or shutil.which("gcc") or shutil.which("clang")
    if not cc:
        print("test_python: no C compiler, struct layout check skipped")
        return
    lines = []
    for cname, cls in sorted(ffi.STRUCTS.items()):
        lines.append('    printf("%s sizeof %%zu\\n", sizeof(%s));' % (cname, cname))
        for fname, _ in cls._fields_:
            lines.append('    printf("%s %s %%zu %%zu\\n", offsetof(%s, %s), sizeof(((%s *)0)->%s));'
                         % (cname, fname, cname, fname, cname, fname))
    for e in ("ts_status", "ts_where", "ts_form", "ts_slopes", "ts_shape", "ts_extrap",
              "ts_term", "ts_param"):
        lines.append('    printf("%s sizeof %%zu\\n", sizeof(%s));' % (e, e))
    src = ("#include <stddef.h>\n#include <stdio.h>\n#include \"trigspline.h\"\n"
           "int main(void)\n{\n" + "\n".join(lines) + "\n    return 0;\n}\n")
    with tempfile.TemporaryDirectory() as tmp:
        cpath, exe = os.path.join(tmp, "layout.c"), os.path.join(tmp, "layout")
        with open(cpath, "w") as fh:
            fh.write(src)
        r = subprocess.run([cc, "-std=c11", "-I", os.path.join(REPO, "include"), cpath, "-o", exe],
                           stdout=subprocess.PIPE, stderr=subprocess.STDOUT)
        if not check(r.returncode == 0, "layout helper compiles: " + r.stdout.decode()[-500:]):
            return
        out = subprocess.run([exe], stdout=subprocess.PIPE).stdout.decode().split("\n")
    got = {}
    for line in out:
        p = line.split()
        if len(p) == 3:
            got[(p[0], p[1])] = int(p[2])
        elif len(p) == 4:
            got[(p[0], p[1])] = int(p[2])
            got[(p[0], p[1], "size")] = int(p[3])
    n = 0
    for cname, cls in ffi.STRUCTS.items():
        close(ctypes.sizeof(cls), got.get((cname, "sizeof"), -1), 0, "sizeof(%s)" % cname)
        for fname, _ in cls._fields_:
            close(getattr(cls, fname).offset, got.get((cname, fname), -1), 0,
                  "offsetof(%s, %s)" % (cname, fname))
            close(getattr(cls, fname).size, got.get((cname, fname, "size"), -1), 0,
                  "sizeof(%s.%s)" % (cname, fname))
            n += 1
    for e in ("ts_status", "ts_where", "ts_form", "ts_slopes", "ts_shape", "ts_extrap",
              "ts_term", "ts_param"):
        close(got.get((e, "sizeof"), -1), ctypes.sizeof(ctypes.c_int), 0,
              "sizeof(%s) == sizeof(int)" % e)
    check(n >= 50, "layout: all fields compared (%d)" % n)


def test_values(ts):
    """Values, derivatives and integrals vs the docs/method.md §3 re-derivation."""
    x = [0.0, 0.7, 1.5, 3.1, 4.0, 6.2]
    f = [1.0, 2.2, 1.7, 3.5, 0.4, 2.0]
    al = [1.0, 0.5, 2.0, 0.8, 1.3]
    be = [0.0, 0.3, 0.1, 0.0, 0.7]
    for form in ("paper", "c1"):
        ref = RefSpline(x, f, al, be, c1=(form == "c1"))
        s = ts.Spline(x, f, alpha=al, beta=be, form=form)
        M = max(abs(b) for B in ref.B for b in B)
        w = max((math.pi / 2) / (x[i + 1] - x[i]) for i in range(len(x) - 1))
        # < 40 roundings on numbers of size <= M per value (basis, sum); 1e-12 M is
        # ~4500 eps M: far above rounding, far below any formula error (a wrong
        # sign of B2 moves values by k d ~ 0.1 here)
        tol0, tol1, tol2 = 1e-12 * M, 1e-12 * M * w, 1e-12 * M * w * w
        for j, d in enumerate(ref.d):
            close(s.slopes[j], d, 1e-13 * max(1.0, abs(d)), "%s slope d_%d" % (form, j))
        for i in range(len(x) - 1):
            Bl, Xl = s.control(i)
            for l in range(4):
                close(Bl[l], ref.B[i][l], 1e-13 * M, "%s B%d of interval %d" % (form, l, i))
        pts = [0.0, 0.05, 0.35, 0.7, 1.1, 1.5, 2.0, 2.95, 3.1, 3.3, 4.0, 5.0, 6.1, 6.2]
        for xv in pts:
            r = ref.eval(xv)
            close(s(xv), r[0], tol0, "%s S(%g)" % (form, xv))
            close(s(xv, derivative=1), r[1], tol1, "%s S'(%g)" % (form, xv))
            close(s(xv, derivative=2), r[2], tol2, "%s S''(%g)" % (form, xv))
        for i, xv in enumerate(x):
            close(s(xv), f[i], tol0, "%s interpolates point %d" % (form, i))
        if form == "paper":
            # docs/method.md §3: S'(x_i+) = d_i/a_i and S'(x_{i+1}-) = d_{i+1}/a_i
            for i in range(len(x) - 1):
                a = al[i] + be[i]
                close(s(x[i], 1), ref.d[i] / a, tol1, "S'(x_%d+) = d/a" % i)
                close(ref.eval(x[i + 1], i)[1], ref.d[i + 1] / a, tol1,
                      "reference S'(x_%d-) = d/a" % (i + 1))
            close(s(x[-1], 1), ref.d[-1] / (al[-1] + be[-1]), tol1, "S'(x_n-) = d_n/a_{n-1}")
        # the reference's own derivative formulas vs central differences
        # (truncation h^2/6 |S'''| with h = 1e-4, |S'''| <= M w^3 * 60)
        for xv in (0.3, 2.2, 5.5):
            hd = 1e-4
            r = [ref.eval(xv + k * hd) for k in (-1, 0, 1)]
            close((r[2][0] - r[0][0]) / (2 * hd), r[1][1], 1e-8 * M * w ** 3 * 10 + 1e-9,
                  "reference S' vs differences at %g" % xv)
            close((r[2][1] - r[0][1]) / (2 * hd), r[1][2], 1e-8 * M * w ** 4 * 10 + 1e-9,
                  "reference S'' vs differences at %g" % xv)
        # integrals: whole intervals in closed form (rounding only), partial by
        # Simpson (error <= L step^4 max|S''''|/180 ~ 1e-11 here; tolerance 1e-9)
        for i in range(len(x) - 1):
            close(s.integral(x[i], x[i + 1]), ref.integral_whole(i), 1e-12 * M,
                  "%s integral over interval %d" % (form, i))
        for a, b in ((0.0, 6.2), (0.3, 0.6), (0.2, 5.9), (5.9, 0.2), (1.5, 4.0)):
            sign = 1.0 if a <= b else -1.0
            lo, hi = min(a, b), max(a, b)
            close(s.integral(a, b), sign * ref.integral_simpson(lo, hi), 1e-9 * M,
                  "%s integral %g..%g" % (form, a, b))
        check(s.integral(2.0, 2.0) == 0.0, "empty integral")
        s.close()
    # user slopes and the accessors
    d = [0.5, -1.0, 2.0, 0.0, 1.0, -0.5]
    s = ts.Spline(x, f, slopes_values=d, alpha=0.7)
    ref = RefSpline(x, f, [0.7] * 5, [0.0] * 5, d=d)
    check(s.slopes == tuple(d), "user slopes kept")
    check(s.alpha == (0.7,) * 5 and s.beta == (0.0,) * 5, "alpha/beta accessors")
    check(s.knots == tuple(x) and s.values == tuple(f), "knots/values accessors")
    check(s.intervals == 5 and s.domain == (0.0, 6.2), "intervals/domain")
    check(s.form == "paper" and s.shape == "none" and s.extrapolate == "error", "enum accessors")
    close(s(2.4), ref.eval(2.4)[0], 1e-12 * 10, "user slopes value")
    check(s.certified is False, "shape none is never certified")
    # other slope methods: the library's estimate equals estimate_slopes()
    for m in ("geometric", "harmonic", "fritsch_carlson", "pchip", "akima", "makima"):
        sm = ts.Spline(x, f, slopes=m)
        check(sm.slopes == tuple(ts.estimate_slopes(x, f, m)), "slopes=%s via estimate_slopes" % m)
    close(ts.estimate_slopes(x, f)[2], ref_slopes(x, f)[2], 1e-14, "estimate_slopes arithmetic")
    # extrapolation policies (definitions from the header, not from docs/method.md)
    sc = ts.Spline(x, f, extrapolate="clamp")
    check(sc(-3.0) == f[0] and sc(9.0) == f[-1] and sc(-3.0, 1) == 0.0, "clamp")
    check(sc(float("inf")) == f[-1], "clamp accepts +inf")
    sl = ts.Spline(x, f, extrapolate="linear")
    close(sl(-1.0), f[0] - sl(0.0, 1), 1e-12, "linear extrapolation")
    se = ts.Spline(x, f, extrapolate="extend")
    ref = RefSpline(x, f, [1.0] * 5, [0.0] * 5)
    close(se(-0.2), ref.eval(-0.2, 0)[0], 1e-12 * 10, "extend continues the end formula")
    # error_bound: a positive number, per interval list of n values
    b, per = s.error_bound(3.0, per_interval=True)
    check(b > 0 and len(per) == 5 and abs(max(per) - b) <= 1e-15 * b, "error_bound")


def dense(s, m=20001):
    x0, xn = s.domain
    xs = [x0 + (xn - x0) * j / (m - 1) for j in range(m)]
    return xs, s(xs)


def test_positive(ts):
    """Table 1, positive scheme: certified and >= 0 on dense samples."""
    rows = read_csv("table1_positive.csv")
    x, f = [r[0] for r in rows], [r[1] for r in rows]
    for alpha in (1.0, 0.15, 0.01, 0.0001):  # 0.15: Figure 4c, 0.0001: Figure 4d
        s = ts.Spline(x, f, shape="positive", alpha=alpha)
        check(s.certified, "Table 1 positive alpha=%g certified" % alpha)
        rep = s.report()
        check(len(rep) == len(x) - 1, "report has n entries")
        check(all(r["certified"] and r["has_lower"] and not r["has_upper"] for r in rep),
              "every interval certified (alpha=%g)" % alpha)
        check(all(r["gap_lower"] > 0 for r in rep), "exact gaps > 0 (alpha=%g)" % alpha)
        check(all(abs(r["a"] - (r["alpha"] + r["beta"])) <= 1e-15 * r["a"] for r in rep),
              "report a = alpha + beta")
        check(all(r["beta"] >= 0.01 * (1 - 1e-15) for r in rep),
              "beta >= margin t = 0.01 (docs/method.md §5)")
        xs, ys = dense(s)
        check(min(ys) >= 0.0, "Table 1 alpha=%g: min of 20001 samples %r >= 0" % (alpha, min(ys)))
        # the exact minimum is attained where reported and no sample lies below it
        # (tolerance: rounding of one evaluation, 1e-12 * max|f| ~ 2e-12)
        for i, r in enumerate(rep):
            close(s(r["at_lower"]), r["gap_lower"], 1e-12 * 2, "S(at_lower) = gap, interval %d" % i)
            inside = [y for xv, y in zip(xs, ys) if r["x0"] <= xv <= r["x1"]]
            check(min(inside) >= r["gap_lower"] - 1e-12 * 2,
                  "no sample below the exact minimum (interval %d)" % i)
        check(s.certify() is True, "certify() against the scheme's own line")
        ok, reps = s.certify(lower=(0.0, 0.0), report=True)
        check(ok and len(reps) == len(rep), "certify(lower=0, report=True)")
        s.close()
    # without the scheme the same data go negative at small alpha (docs/method.md §9.6:
    # one a for all intervals: minimum -6.2 at a = 0.01)
    u = ts.Spline(x, f, alpha=0.01)
    xs, ys = dense(u)
    check(min(ys) < -1.0, "unconstrained alpha=0.01 dips below zero (min %r)" % min(ys))
    ok, reps = u.certify(lower=(0.0, 0.0), report=True)
    check(ok is False, "certify finds the negative part")
    worst = min(r["gap_lower"] for r in reps)
    check(worst <= min(ys) + 1e-9 and worst > min(ys) - 0.5,
          "exact minimum %r <= sampled minimum %r" % (worst, min(ys)))
    close(worst, -6.2, 0.05, "docs/method.md §9.6: minimum about -6.2 at a = 0.01")
    check(not all(r["certified"] for r in reps), "report marks violated intervals")
    u.close()


def test_lines(ts):
    """Tables 3, 4: below and between lines, certified, on dense samples."""
    rows = read_csv("table3_below_line.csv")
    x, f = [r[0] for r in rows], [r[1] for r in rows]
    s = ts.Spline(x, f, shape="below", line=(1.0, 2.5), alpha=0.001, margin=0.01)
    check(s.certified, "Table 3 below y = x + 2.5 certified")
    xs, ys = dense(s)
    check(max(y - (xv + 2.5) for xv, y in zip(xs, ys)) < 0, "Table 3 below the line on samples")
    gaps = [r["gap_upper"] for r in s.report()]
    check(min(gaps) > 0 and all(r["has_upper"] for r in s.report()), "Table 3 exact gaps > 0")
    rows = read_csv("table4_between_lines.csv")
    x, f = [r[0] for r in rows], [r[1] for r in rows]
    for alpha in (0.1, 0.4):  # Figures 7d, 7c
        s = ts.Spline(x, f, shape="between", lower=(1.0, 0.1), upper=(8.0, 6.0), alpha=alpha)
        check(s.certified, "Table 4 between lines certified (alpha=%g)" % alpha)
        xs, ys = dense(s)
        check(all(xv + 0.1 < y < 8 * xv + 6 for xv, y in zip(xs, ys)),
              "Table 4 between the lines on samples (alpha=%g)" % alpha)
    m = ts.Spline([0, 1, 2, 4, 5], [0, 0.1, 3, 3.2, 9], shape="monotone")
    xs, ys = dense(m, 5001)
    check(all(b >= a for a, b in zip(ys, ys[1:])), "monotone scheme: samples non-decreasing")
    check(m.certified, "monotone certified")


def test_errors(ts):
    E = ts.TrigsplineError
    check(issubclass(E, ValueError), "TrigsplineError is a ValueError")
    rows = read_csv("table2_above_line.csv")
    x, f = [r[0] for r in rows], [r[1] for r in rows]
    # docs/method.md §9.5: Table 2 is not above y = 0.31x + 1; the first offender is x = 1
    e = raises(lambda: ts.Spline(x, f, shape="above", line=(0.31, 1.0)), E, "Table 2 refused")
    if e:
        check(e.status == 15 and e.name == "TS_ERR_SIDE", "TS_ERR_SIDE (%r)" % e)
        check(e.index == 0 and e.where == "point", "index 0, point")
        check("point 0 (x = 1) lies on or across the line" in str(e), "message: " + str(e))
    e = raises(lambda: ts.Spline([0, 1, 2, 3], [1, 2, -0.5, 1], shape="positive"), E, "negative")
    if e:
        check(e.name == "TS_ERR_NEGATIVE" and e.index == 2 and "point 2 (x = 2)" in str(e),
              "negative: %r" % e)
    e = raises(lambda: ts.Spline([0, 1, 1, 2], [1, 2, 3, 4]), E, "duplicate x")
    if e:
        check(e.name == "TS_ERR_UNSORTED" and e.index == 2 and e.where == "point", repr(e))
    e = raises(lambda: ts.Spline([0, 1, 2], [1, float("nan"), 3]), E, "NaN")
    if e:
        check(e.name == "TS_ERR_NONFINITE" and e.index == 1, repr(e))
    e = raises(lambda: ts.Spline([0, 1, 2, 3], [0, 2, 1, 3], shape="monotone"), E, "nonmonotone")
    if e:
        check(e.name == "TS_ERR_NONMONOTONE" and e.where == "point" and e.index is not None,
              repr(e))
    e = raises(lambda: ts.Spline([0, 1, 2, 3], [1, 2, 3, 4], alpha=[1, -1, 1]), E, "alpha < 0")
    if e:
        check(e.name == "TS_ERR_ALPHA" and e.index == 1 and e.where == "interval"
              and str(e).startswith("interval 1 [1, 2]"), repr(e))
    e = raises(lambda: ts.Spline([0, 1, 2, 3], [1, 2, 3, 4], beta=[0, 0, -1]), E, "beta < 0")
    if e:
        check(e.name == "TS_ERR_BETA" and e.index == 2, repr(e))
    e = raises(lambda: ts.Spline([0, 1, 2, 3], [1, 2, 3, 4], alpha=[1, 1]), E, "alpha length")
    if e:
        check(e.name == "TS_ERR_LENGTH", repr(e))
    e = raises(lambda: ts.Spline([0, 1, 2], [1, 2]), E, "x/f length")
    e = raises(lambda: ts.Spline([0], [1]), E, "too few")
    if e:
        check(e.name == "TS_ERR_TOO_FEW", repr(e))
    e = raises(lambda: ts.Spline([0, 1, 2], [1, 2, 3], slopes="periodic"), E, "periodic")
    if e:
        check(e.name == "TS_ERR_PERIODIC" and e.index == 2, repr(e))
    e = raises(lambda: ts.Spline([0, 1, 2], [1, 2, 1], shape="positive", margin=0), E, "margin")
    if e:
        check(e.name == "TS_ERR_MARGIN", repr(e))
    e = raises(lambda: ts.Spline([0, 1, 2], [1, 2, 1], shape="between", lower=(0, 1.5),
                                 upper=(0, 3)), E, "point below the lower line")
    if e:
        check(e.name == "TS_ERR_SIDE" and e.index == 0 and "y = 1.5" in str(e), repr(e))
    e = raises(lambda: ts.Spline([0, 1, 2], [1, 2, 1], form="geometric", alpha=0.2), E,
               "geometric bound")
    if e:
        check(e.name == "TS_ERR_GEOMETRIC" and e.index == 0, repr(e))
    # Python-side argument errors
    raises(lambda: ts.Spline([0, 1], [1, 2], shape="sideways"), ValueError, "bad shape name")
    raises(lambda: ts.Spline([0, 1], [1, 2], form="fancy"), ValueError, "bad form name")
    raises(lambda: ts.Spline([0, 1], [1, 2], shape="above"), ValueError, "above without line")
    raises(lambda: ts.Spline([0, 1], [1, 2], shape="positive", beta=0.5), ValueError,
           "beta with a scheme")
    raises(lambda: ts.Spline([0, 1], [1, 2], line=(1, 0)), ValueError, "line without scheme")
    raises(lambda: ts.Spline([0, 1], [1, 2], slopes="user"), ValueError, "user without values")
    raises(lambda: ts.Spline("ab", [1, 2]), TypeError, "string data")
    raises(lambda: ts.Spline([0, "a"], [1, 2]), TypeError, "non-number")
    s = ts.Spline([0, 1, 2, 3], [1, 2, 0.5, 3])
    e = raises(lambda: s(5.0), E, "scalar outside")
    if e:
        check(e.name == "TS_ERR_DOMAIN" and "x = 5" in str(e), repr(e))
    e = raises(lambda: s([0.5, 1.5, -1.0, 9.0]), E, "batch outside")
    if e:
        check(e.index == 2 and e.where == "query" and "query 2 (x = -1)" in str(e), repr(e))
    e = raises(lambda: s([0.5, float("nan")]), E, "batch NaN")
    if e:
        check(e.index == 1 and "NaN" in str(e), repr(e))
    e = raises(lambda: s.integral(-1, 2), E, "integral outside")
    if e:
        check(e.name == "TS_ERR_DOMAIN", repr(e))
    raises(lambda: s(1.0, derivative=3), ValueError, "derivative 3")
    raises(lambda: s.certify(), ValueError, "certify without lines on shape none")
    e = raises(lambda: s.certify(lower=(float("inf"), 0)), E, "certify non-finite line")
    if e:
        check(e.name == "TS_ERR_NONFINITE", repr(e))
    raises(lambda: s.control(7), E, "control index")
    # life time
    with ts.Spline([0, 1, 2], [1, 2, 1]) as s2:
        check(s2(0.5) > 0, "context manager")
    raises(lambda: s2(0.5), ValueError, "use after close")
    s2.close()  # idempotent
    check(True, "close twice")
    check("closed" in repr(s2), "repr of a closed spline")
    # the error pickles with its fields (multiprocessing)
    import pickle
    e2 = pickle.loads(pickle.dumps(E(15, "m", 3, "point")))
    check(e2.status == 15 and e2.index == 3 and e2.where == "point" and str(e2) == "m", "pickle")


def test_batch(ts):
    rows = read_csv("table1_positive.csv")
    x, f = [r[0] for r in rows], [r[1] for r in rows]
    s = ts.Spline(x, f, shape="positive", alpha=0.15)
    rng = random.Random(7)
    q = [rng.uniform(0, 30) for _ in range(1000)] + list(x)
    M = max(abs(b) for i in range(s.intervals) for b in s.control(i)[0])
    w = max((math.pi / 2) / (x[i + 1] - x[i]) for i in range(len(x) - 1))
    # fast.c: |batch - scalar| <= 8 eps M (value), 8 eps M w (S'), 16 eps M w^2 (S'')
    tols = (8 * EPS * M, 8 * EPS * M * w, 16 * EPS * M * w * w)
    for d in (0, 1, 2):
        b = s(q, derivative=d)
        check(isinstance(b, list) and len(b) == len(q), "list in, list out (d=%d)" % d)
        worst = max(abs(b[j] - s(q[j], d)) for j in range(len(q)))
        check(worst <= tols[d], "batch vs scalar d=%d: %.3g <= %.3g" % (d, worst, tols[d]))
        mt = s(q, derivative=d, threads=2)
        check(max(abs(a - c) for a, c in zip(mt, b)) <= tols[d], "threads=2 agrees (d=%d)" % d)
    check(s(tuple(q[:5])) == s(q[:5]), "tuple input")
    check(s([]) == [], "empty batch")
    check(s(iter([1.0, 2.0])) == s([1.0, 2.0]), "iterator input")
    aa = array.array("d", q[:50])
    ra = s(aa)
    check(isinstance(ra, array.array) and list(ra) == s(q[:50]), "array.array in and out")
    buf = array.array("d", [0.0] * 50)
    r = s(q[:50], out=buf)
    check(r is buf and list(buf) == s(q[:50]), "out= array.array filled in place")
    raises(lambda: s(q[:50], out=array.array("d", [0.0] * 3)), ValueError, "out of wrong size")
    raises(lambda: s(q[:50], out=[0.0] * 50), TypeError, "out must be a buffer")
    check(s(q[3]) == s([q[3]])[0] or abs(s(q[3]) - s([q[3]])[0]) <= tols[0], "scalar vs 1-batch")
    sorted_q = sorted(q)
    bs = s(sorted_q)
    check(max(abs(bs[j] - s(sorted_q[j])) for j in range(len(q))) <= tols[0], "sorted batch")


def test_numpy(ts):
    try:
        import numpy as np
    except ImportError:
        print("test_python: numpy not importable, numpy checks skipped")
        return
    from trigspline import _util
    rows = read_csv("table1_positive.csv")
    x, f = np.array([r[0] for r in rows]), np.array([r[1] for r in rows])
    s = ts.Spline(x, f, shape="positive", alpha=0.15)
    check(s.knots == tuple(x.tolist()), "numpy data accepted")
    q = np.linspace(0, 30, 1001)
    y = s(q)
    check(isinstance(y, np.ndarray) and y.shape == q.shape and y.dtype == np.float64, "ndarray out")
    check(y.tolist() == s(q.tolist()), "ndarray = list path, bit for bit")
    o = np.empty(1001)
    r = s(q, out=o)
    check(r is o and o.tolist() == y.tolist(), "out= ndarray filled in place")
    raises(lambda: s(q[:10], out=np.empty(20)[::2]), ValueError, "non-contiguous out refused")
    raises(lambda: s(q[:10], out=np.empty(10, dtype=np.float32)), ValueError, "float32 out")
    q2 = q[:1000].reshape(20, 50)
    y2 = s(q2, derivative=1)
    check(y2.shape == (20, 50) and y2.ravel().tolist() == s(q2.ravel().tolist(), 1), "2-D shape")
    qs = q[::3]  # strided view: copied once into a contiguous array
    check(s(qs).tolist() == s(qs.tolist()), "strided input")
    qi = np.arange(0, 31)
    check(s(qi).tolist() == s([float(v) for v in qi]), "integer array input")
    # no copy for C-contiguous float64: the C call reads the caller's buffer
    ca, kind, shape = _util.input_array(q, "x")
    check(kind == "numpy" and ca.owner is q, "contiguous float64 passed without a copy")
    check(isinstance(s(np.float64(3.5)), float), "numpy scalar gives a float")
    check(isinstance(s(np.array(3.5)), float), "0-d array gives a float")
    e = None
    try:
        s(np.array([1.0, 50.0]))
    except ts.TrigsplineError as ex:
        e = ex
    check(e is not None and e.index == 1, "ndarray domain error index")
    c = ts.Curve(np.array([[0, 1], [1, 4], [2, 1], [3, 4]], dtype=float))
    t = np.linspace(0, c.knots[-1], 7)
    p = c(t)
    check(p.shape == (7, 2) and p[0].tolist() == [0.0, 1.0], "curve ndarray eval")
    smp = c.sample(5, array=True)
    check(smp.shape == (3 * 4 + 1, 3), "curve sample array")


def test_curve(ts):
    E = ts.TrigsplineError
    for name in ("fig2_closed.csv", "fig3_closed.csv"):
        pts = [tuple(r) for r in read_csv(name)]
        for beta in (0.001, 0.01, 0.05):  # docs/method.md §7 / Figures 2-3
            c = ts.Curve(pts, closed=True, alpha=0.37, beta=beta)
            m = len(pts) - 1  # first point repeated at the end
            check(c.closed and c.segments == m and c.dim == 2, "%s closed, %d segments" % (name, m))
            # docs/method.md §7 centripetal knots recomputed
            t = [0.0]
            for i in range(m):
                dx = pts[i + 1][0] - pts[i][0]
                dy = pts[i + 1][1] - pts[i][1]
                t.append(t[-1] + math.hypot(dx, dy) ** 0.5)
            kn = c.knots
            check(all(abs(a - b) <= 1e-14 * t[-1] for a, b in zip(kn, t)), "centripetal knots")
            for i in range(m + 1):
                p = c(kn[i])
                check(all(abs(p[k] - pts[i][k]) <= 1e-13 * 4 for k in range(2)),
                      "%s passes through point %d" % (name, i))
            T = kn[-1]
            for tv in (0.3, 1.7, T - 0.1):
                a, b = c(tv), c(tv + T)
                check(all(abs(a[k] - b[k]) <= 1e-12 * 4 for k in range(2)), "periodic wrap")
            # seam: same a everywhere -> C¹ in t; the derivative at t_0 from
            # segment 0 is d_0/a with d_0 the periodic three-point mean (docs/method.md §6)
            a_ = 0.37 + beta
            h0, hl = kn[1] - kn[0], kn[m] - kn[m - 1]
            for k in range(2):
                D0 = (pts[1][k] - pts[0][k]) / h0
                Dl = (pts[m][k] - pts[m - 1][k]) / hl
                d0 = (h0 * Dl + hl * D0) / (hl + h0)
                close(c(0.0, 1)[k], d0 / a_, 1e-12 * 10, "seam slope right, coord %d" % k)
                # left side: 1e-9 before the end; |d2| <= ~1e3 here -> error ~1e-6
                close(c(T - 1e-9, 1)[k], d0 / a_, 1e-5, "seam slope left, coord %d" % k)
            # length: >= polygon, >= inscribed polyline, and close to it
            poly = sum(math.hypot(pts[i + 1][0] - pts[i][0], pts[i + 1][1] - pts[i][1])
                       for i in range(m))
            L = c.length()
            smp = c.sample(400)
            check(len(smp) == m * 399 + 1 and smp[0][0] == 0.0, "sample rows")
            check(abs(smp[-1][1] - pts[0][0]) <= 1e-12 and abs(smp[-1][2] - pts[0][1]) <= 1e-12,
                  "sample closes")
            inscribed = sum(math.hypot(smp[j + 1][1] - smp[j][1], smp[j + 1][2] - smp[j][2])
                            for j in range(len(smp) - 1))
            check(L >= poly * (1 - 1e-12), "length %r >= polygon %r" % (L, poly))
            # inscribed polyline of N chords: L - P = O(L/N^2) on a smooth curve;
            # 1e-3 relative allows the tight turns at beta = 0.001
            check(L >= inscribed * (1 - 1e-12) and L - inscribed <= 1e-3 * L,
                  "length %r vs inscribed polyline %r" % (L, inscribed))
            c.close()
    # same curve without the repeated point
    pts = [tuple(r) for r in read_csv("fig2_closed.csv")]
    c1 = ts.Curve(pts, closed=True, alpha=0.37, beta=0.01)
    c2 = ts.Curve(pts[:-1], closed=True, alpha=0.37, beta=0.01)
    check(c1(1.234) == c2(1.234) and c1.knots == c2.knots, "implied closing point")
    check(c1.alpha == (0.37,) * 4 and c1.beta == (0.01,) * 4, "curve alpha/beta")
    check(len(c1.control(0)) == 4 and c1.control(0)[0] == pts[0], "control points")
    lst = c1([0.5, 1.0])
    check(lst == [c1(0.5), c1(1.0)], "curve list eval")
    # open curve: domain error; box certificate
    o = ts.Curve(pts[:-1], alpha=0.37, beta=0.001)
    e = raises(lambda: o(-1.0), E, "open curve outside")
    if e:
        check(e.name == "TS_ERR_DOMAIN", repr(e))
    e = raises(lambda: o([0.1, 100.0]), E, "open curve batch outside")
    if e:
        check(e.index == 1 and "query 1" in str(e), repr(e))
    box = ((-0.05, 3.05), (0.95, 4.05))
    b = ts.Curve(pts, closed=True, alpha=0.37, beta=0.001, box=box)
    check(b.certify() is True, "box curve certified")
    smp = b.sample(200)
    check(all(-0.05 < r[1] < 3.05 and 0.95 < r[2] < 4.05 for r in smp), "box curve inside")
    loose = ts.Curve(pts, closed=True, alpha=0.37, beta=0.001)
    smp = loose.sample(200)
    outside = any(not (-0.05 < r[1] < 3.05 and 0.95 < r[2] < 4.05) for r in smp)
    ok, reps = loose.certify(box=box, report=True)
    check(outside and not ok, "unconstrained curve leaves the box and certify says so")
    check(len(reps) == loose.segments * 2, "curve report entries")
    check(loose.certify() is True, "no box of its own: nothing to violate")
    # 3-D
    c3 = ts.Curve([(0, 0, 0), (1, 0, 1), (1, 1, 2), (0, 1, 3)], param="chord")
    check(c3.dim == 3 and len(c3(0.5)) == 3 and c3(0.0) == (0.0, 0.0, 0.0), "3-D curve")
    d1 = c3(0.5, derivative=1)
    check(len(d1) == 3 and any(v != 0 for v in d1), "3-D derivative")
    # errors
    e = raises(lambda: ts.Curve([(0, 0), (1, 1), (1, 1), (2, 0)]), E, "repeated point")
    if e:
        check(e.name == "TS_ERR_UNSORTED" and e.index == 2 and "point 2 (1, 1)" in str(e), repr(e))
    e = raises(lambda: ts.Curve([(0, 0, 0, 0), (1, 1, 1, 1)]), E, "4-D")
    if e:
        check(e.name == "TS_ERR_DIMENSION", repr(e))
    e = raises(lambda: ts.Curve([(0, 0), (1, 1, 1)]), E, "ragged")
    e = raises(lambda: ts.Curve([(0, 0), (1, 1)], closed=True), E, "closed too few")
    if e:
        check(e.name == "TS_ERR_TOO_FEW", repr(e))
    e = raises(lambda: ts.Curve([(0, 1), (1, 4), (2, 1), (3, 4)], box=((0.5, 4), None)), E,
               "point outside box")
    if e:
        check(e.name == "TS_ERR_SIDE" and e.index == 0, repr(e))
    e = raises(lambda: ts.Curve([(0, 0), (1, float("inf"))]), E, "inf coordinate")
    if e:
        check(e.name == "TS_ERR_NONFINITE" and e.index == 1, repr(e))
    raises(lambda: ts.Curve(pts, param="random"), ValueError, "bad param")
    raises(lambda: o.sample(1), E, "sample m < 2")
    with ts.Curve(pts) as cc:
        check(cc.length() > 0, "curve context manager")
    raises(lambda: cc.length(), ValueError, "curve use after close")


def main():
    if len(sys.argv) < 2:
        print("usage: test_python.py BUILD_DIR", file=sys.stderr)
        print("test_python: 0 passed, 1 failed")
        return 1
    build = os.path.abspath(sys.argv[1])
    libpath = os.path.join(build, "libtrigspline.so")
    os.environ["TRIGSPLINE_LIB"] = libpath
    sys.path.insert(0, os.path.join(REPO, "python"))
    try:
        import trigspline as ts
        from trigspline import _ffi
    except ImportError as e:
        print("FAIL: import trigspline: %s" % e, file=sys.stderr)
        print("test_python: 0 passed, 1 failed")
        return 1
    check(os.path.samefile(ts.lib_path, libpath), "loaded the library of BUILD_DIR")
    check(ts.library_version() == "0.1.0", "version")
    for t in (test_layout, test_values, test_positive, test_lines, test_errors, test_batch,
              test_numpy, test_curve):
        try:
            if t is test_layout:
                t(_ffi)
            else:
                t(ts)
        except Exception as e:  # a crash in one group is a failure, not the end
            import traceback
            traceback.print_exc()
            check(False, "%s raised %r" % (t.__name__, e))
    print("test_python: %d passed, %d failed" % (passed, failed))
    return 1 if failed else 0


if __name__ == "__main__":
    sys.exit(main())
