#!/usr/bin/python3
"""Independent high-precision reference for the core spline (docs/method.md §2, §3, §6).

Computes the GC¹ cubic trigonometric spline from scratch with mpmath at 40
significant digits -- it does not use the C library -- and writes a CSV that
tests/api/test_core.c reads at run time.  The output is checked in; this script is
NOT run by `make test`.  Regenerate (deterministic: fixed seeds, no clocks; ~6 s) from the repository root with

    /usr/bin/python3 tests/ref/reference.py > tests/ref/core_ref.csv

(needs python3-mpmath from Debian; reads the paper's Table 1 from data/paper/ at the
repository root).  Every data value is written exactly (repr of the
double), so the C test rebuilds exactly the spline the script computed.  Everything below is docs/method.md §2/§3/§6 restated:

  basis (§2)   A0 = (1-s)^3, A1 = 3s - 4s^2 + s^3, A2 = 3c - 4c^2 + c^3, A3 = (1-c)^3
  paper (§3)   k_i = 2 h_i / (3 pi a_i), a_i = alpha_i + beta_i,
               B = [f_i, f_i + k_i d_i, f_{i+1} - k_i d_{i+1}, f_{i+1}]
  C¹ (§3)      dh_i = d_i / max(a_{i-1}, a_i) (one-sided at the ends),
               B = [f_i, f_i + K_i dh_i, f_{i+1} - K_i dh_{i+1}, f_{i+1}], K_i = 2 h_i/(3 pi)
  slopes (§6)  three-point arithmetic mean with the one-sided end formulas;
               n = 1: d_0 = d_1 = Delta_0.

Derivatives come from mpmath.diff of the script's own S (not from the basis
derivative formulas); integrals from mpmath.quad of S split at the knots (not
from a closed form).

CSV records (one per line, '#' lines are comments):
  case,NAME,FORM,SLOPES,NPOINTS,NALPHA,NBETA   FORM 0 paper / 1 C¹; SLOPES 0 arithmetic / 6 user;
                                               NALPHA (NBETA) = 1: scalar option, else per-interval array
  x,...  f,...                                  data (exact doubles, repr)
  d,...                                         SLOPES 6: the user slopes (exact doubles);
                                                SLOPES 0: the reference arithmetic-mean slopes
  alpha,...  beta,...                           exact doubles
  scale,M                                       max(1, max |B_l| over all intervals)
  ctl,i,B0,B1,B2,B3                             reference control values of interval i
  knot,i,LEFT,RIGHT                             one-sided S' at knot i (LEFT from interval i-1,
                                                RIGHT from interval i; "nan" where absent)
  pt,X,S,S1,S2                                  value, S', S'' at a non-knot X inside the data
  ext,X,S,S1,S2                                 the end segment's formula continued outside [x0, xn]
  int,A,B,VALUE                                 integral of S from A to B (A > B gives the negative)
  end
"""
import math
import os
import random
import sys

import mpmath
from mpmath import mp, mpf

mp.dps = 40
PI = mp.pi


def basis(theta):
    s, c = mpmath.sin(theta), mpmath.cos(theta)
    return [(1 - s) ** 3, 3 * s - 4 * s ** 2 + s ** 3, 3 * c - 4 * c ** 2 + c ** 3, (1 - c) ** 3]


def arith_slopes(x, f):
    """docs/method.md §6, three-point arithmetic mean, in mpmath from the exact doubles."""
    n = len(x) - 1
    X = [mpf(v) for v in x]
    F = [mpf(v) for v in f]
    h = [X[i + 1] - X[i] for i in range(n)]
    D = [(F[i + 1] - F[i]) / h[i] for i in range(n)]
    if n == 1:
        return [D[0], D[0]]
    d = [mpf(0)] * (n + 1)
    for i in range(1, n):
        d[i] = (h[i] * D[i - 1] + h[i - 1] * D[i]) / (h[i - 1] + h[i])
    d[0] = D[0] + (D[0] - D[1]) * h[0] / (h[0] + h[1])
    d[n] = D[n - 1] + (D[n - 1] - D[n - 2]) * h[n - 1] / (h[n - 1] + h[n - 2])
    return d


class Spline:
    def __init__(self, x, f, d, alpha, beta, form):
        self.n = n = len(x) - 1
        self.X = [mpf(v) for v in x]
        self.F = [mpf(v) for v in f]
        self.d = [mpf(v) for v in d]
        self.h = [self.X[i + 1] - self.X[i] for i in range(n)]
        self.a = [mpf(alpha[i]) + mpf(beta[i]) for i in range(n)]
        self.form = form
        self.B = []
        for i in range(n):
            if form == 0:
                k = 2 * self.h[i] / (3 * PI * self.a[i])
                b1 = self.F[i] + k * self.d[i]
                b2 = self.F[i + 1] - k * self.d[i + 1]
            else:
                K = 2 * self.h[i] / (3 * PI)
                b1 = self.F[i] + K * self.dhat(i)
                b2 = self.F[i + 1] - K * self.dhat(i + 1)
            self.B.append([self.F[i], b1, b2, self.F[i + 1]])

    def dhat(self, j):
        """docs/method.md §3 C¹ option: d_j / max(a_{j-1}, a_j), one-sided at the ends."""
        if j == 0:
            return self.d[0] / self.a[0]
        if j == self.n:
            return self.d[self.n] / self.a[self.n - 1]
        return self.d[j] / max(self.a[j - 1], self.a[j])

    def seg(self, i, x):
        """S_i(x): interval i's formula, for any x (theta outside [0, pi/2] = extension)."""
        theta = (PI / 2) * (x - self.X[i]) / self.h[i]
        A = basis(theta)
        return sum(A[l] * self.B[i][l] for l in range(4))

    def locate(self, x):
        # right-hand interval at an inner knot (docs/method.md §3 / header); ends -> end intervals
        for i in range(self.n):
            if x < self.X[i + 1]:
                return max(i, 0)
        return self.n - 1

    def S(self, x):
        return self.seg(self.locate(x), x)

    def seg_derivs(self, i, x):
        g = lambda t: self.seg(i, t)
        return g(x), mpmath.diff(g, x, 1), mpmath.diff(g, x, 2)

    def integral(self, a, b):
        lo, hi, sign = (a, b, 1) if a <= b else (b, a, -1)
        if lo == hi:
            return mpf(0)
        total = mpf(0)
        for i in range(self.n):
            u, v = max(lo, self.X[i]), min(hi, self.X[i + 1])
            if u < v:
                total += mpmath.quad(lambda t: self.seg(i, t), [u, v])
        return sign * total

    def scale(self):
        return max([mpf(1)] + [abs(b) for B in self.B for b in B])


def fmt(v):
    """Reference value: 20 significant digits (strtod rounds it correctly)."""
    if v is None:
        return "nan"
    return mpmath.nstr(mpf(v), 20)


def exact(v):
    return repr(float(v))


def check(cond, msg):
    if not cond:
        sys.stderr.write("reference self-check failed: %s\n" % msg)
        sys.exit(1)


def emit(out, name, x, f, form, slopes_mode, alpha, beta, user_d=None):
    n = len(x) - 1
    al = alpha if len(alpha) == n else alpha * n
    be = beta if len(beta) == n else beta * n
    d = user_d if slopes_mode == 6 else arith_slopes(x, f)
    sp = Spline(x, f, d, al, be, form)
    out.append("case,%s,%d,%d,%d,%d,%d" % (name, form, slopes_mode, n + 1, len(alpha), len(beta)))
    out.append("x," + ",".join(exact(v) for v in x))
    out.append("f," + ",".join(exact(v) for v in f))
    out.append("d," + ",".join(exact(v) if slopes_mode == 6 else fmt(v) for v in d))
    out.append("alpha," + ",".join(exact(v) for v in alpha))
    out.append("beta," + ",".join(exact(v) for v in beta))
    out.append("scale," + fmt(sp.scale()))
    tiny = mpf(10) ** -25
    for i in range(n):
        out.append("ctl,%d,%s" % (i, ",".join(fmt(b) for b in sp.B[i])))
        # self-checks of the docs/method.md §3 claims (these fail with the paper's printed "+" in B2)
        check(abs(sp.seg(i, sp.X[i]) - sp.F[i]) < tiny, "%s: S_%d(x_i)" % (name, i))
        check(abs(sp.seg(i, sp.X[i + 1]) - sp.F[i + 1]) < tiny, "%s: S_%d(x_i+1)" % (name, i))
        dl = mpmath.diff(lambda t: sp.seg(i, t), sp.X[i])
        dr = mpmath.diff(lambda t: sp.seg(i, t), sp.X[i + 1])
        want_l = sp.d[i] / sp.a[i] if form == 0 else sp.dhat(i)
        want_r = sp.d[i + 1] / sp.a[i] if form == 0 else sp.dhat(i + 1)
        sc = 1 + abs(want_l) + abs(want_r)
        check(abs(dl - want_l) < tiny * sc and abs(dr - want_r) < tiny * sc, "%s: end slopes of %d" % (name, i))
    for j in range(n + 1):
        left = mpmath.diff(lambda t: sp.seg(j - 1, t), sp.X[j]) if j > 0 else None
        right = mpmath.diff(lambda t: sp.seg(j, t), sp.X[j]) if j < n else None
        out.append("knot,%d,%s,%s" % (j, fmt(left), fmt(right)))
    # points inside every interval, including some within 1e-13 h of a knot
    fracs = [1e-13, 1e-9, 0.1, 0.37, 0.5, 0.81, 1 - 1e-9, 1 - 1e-12]
    for i in range(n):
        xi, h = float(x[i]), float(x[i + 1]) - float(x[i])
        for t in fracs:
            xq = xi + t * h
            # keep within the interval at a few ulps from the knot when t*h is below the ulp
            if t < 0.5 and xq <= x[i]:
                xq = math.nextafter(math.nextafter(float(x[i]), math.inf), math.inf)
            if t > 0.5 and xq >= x[i + 1]:
                xq = math.nextafter(math.nextafter(float(x[i + 1]), -math.inf), -math.inf)
            check(x[i] < xq < x[i + 1], "%s: point %r not inside interval %d" % (name, xq, i))
            v, d1, d2 = sp.seg_derivs(i, mpf(xq))
            out.append("pt,%s,%s,%s,%s" % (exact(xq), fmt(v), fmt(d1), fmt(d2)))
    # extension (TS_EXTRAP_EXTEND): the end segments' formulas continued
    h0, hn = float(x[1]) - float(x[0]), float(x[n]) - float(x[n - 1])
    for xq, i in ((float(x[0]) - 1e-9 * h0, 0), (float(x[0]) - 0.3 * h0, 0), (float(x[0]) - 1.7 * h0, 0),
                  (float(x[n]) + 1e-9 * hn, n - 1), (float(x[n]) + 0.25 * hn, n - 1),
                  (float(x[n]) + 2.2 * hn, n - 1)):
        check(xq < x[0] or xq > x[n], "%s: extension point inside" % name)
        v, d1, d2 = sp.seg_derivs(i, mpf(xq))
        out.append("ext,%s,%s,%s,%s" % (exact(xq), fmt(v), fmt(d1), fmt(d2)))
    # integrals over sub-ranges (quadrature of S, split at the knots)
    x0, xn = float(x[0]), float(x[n])
    ranges = [(x0, xn), (xn, x0), (x0 + 0.3 * h0, xn - 0.2 * hn),
              (x0 + 0.1 * h0, x0 + 0.7 * h0), (x0 + 0.7 * h0, x0 + 0.1 * h0),
              (float(x[n - 1]) + 0.5 * hn, xn), (x0, x0), (x0 + 0.5 * h0, x0 + 0.5 * h0 + 1e-9 * h0)]
    if n >= 3:
        ranges += [(float(x[1]), float(x[3])), (float(x[1]) + 0.25 * (float(x[2]) - float(x[1])), float(x[n - 1])),
                   (float(x[n - 1]) - 0.4 * (float(x[n - 1]) - float(x[n - 2])), float(x[1]) + 1e-3)]
    for a, b in ranges:
        out.append("int,%s,%s,%s" % (exact(a), exact(b), fmt(sp.integral(mpf(a), mpf(b)))))
    out.append("end")


def main():
    out = ["# generated by tests/ref/reference.py (mpmath %s, %d digits) -- do not edit;" % (mpmath.__version__, mp.dps),
           "# regenerate: /usr/bin/python3 tests/ref/reference.py > tests/ref/core_ref.csv"]
    # The paper's Table 1 (positive data), from data/paper/ at the repository root.
    here = os.path.dirname(os.path.abspath(__file__))
    t1 = os.path.join(here, "..", "..", "data", "paper", "table1_positive.csv")
    tx, tf = [], []
    with open(t1) as fh:
        for line in fh:
            p = line.strip().split(",")
            if len(p) != 2 or p[0] == "x":
                continue
            tx.append(float(p[0]))
            tf.append(float(p[1]))
    n1 = len(tx) - 1
    rng = random.Random(20240517)
    t1_al = [round(rng.uniform(0.2, 2.0), 3) for _ in range(n1)]
    t1_be = [round(rng.uniform(0.0, 1.5), 3) for _ in range(n1)]
    t1_be[2] = 0.0

    # non-uniform random set (fixed seed), widths over 1.5 decades
    rx = [-2.5]
    for _ in range(11):
        rx.append(rx[-1] + 10 ** rng.uniform(-1.3, 0.5))
    rf = [rng.uniform(0.5, 4.0) for _ in rx]
    nr = len(rx) - 1
    r_al = [rng.uniform(0.05, 3.0) for _ in range(nr)]
    r_be = [rng.uniform(0.0, 2.0) for _ in range(nr)]
    r_ud = [rng.uniform(-3.0, 3.0) for _ in rx]

    # negative values (and a sign change), non-uniform
    nx = [0.0, 0.4, 1.5, 1.9, 3.0, 4.75, 5.0, 7.5]
    nf = [-1.0, -3.25, -0.5, 0.75, -2.0, -6.5, -6.25, -0.125]
    nn = len(nx) - 1
    n_al = [0.3, 1.0, 2.5, 0.7, 0.15, 1.2, 0.9]
    n_be = [0.0, 0.5, 0.1, 0.0, 1.0, 0.25, 3.0]
    n_ud = [0.5, -4.0, 2.0, 1.0, -3.0, 0.0, 1.5, 2.5]

    # large abscissae and values: relative accuracy near knots
    bx = [1000.0, 1000.5, 1002.0, 1002.25, 1005.0]
    bf = [12345.0, 12001.5, 13999.0, 14000.0, 11000.0]

    emit(out, "t1_a1", tx, tf, 0, 0, [1.0], [0.0])
    emit(out, "t1_fig4b", tx, tf, 0, 0, [1.4], [1.9])
    emit(out, "t1_per", tx, tf, 0, 0, t1_al, t1_be)
    emit(out, "t1_per_c1", tx, tf, 1, 0, t1_al, t1_be)
    emit(out, "rnd_per", rx, rf, 0, 0, r_al, r_be)
    emit(out, "rnd_per_c1", rx, rf, 1, 0, r_al, r_be)
    emit(out, "rnd_user", rx, rf, 0, 6, [0.7], [0.3], r_ud)
    emit(out, "rnd_user_c1", rx, rf, 1, 6, r_al, r_be, r_ud)
    emit(out, "rnd_mix", rx, rf, 0, 0, [0.45], r_be)
    emit(out, "rnd_mix_c1", rx, rf, 1, 0, r_al, [0.125])
    emit(out, "neg_per", nx, nf, 0, 0, n_al, n_be)
    emit(out, "neg_user_c1", nx, nf, 1, 6, n_al, n_be, n_ud)
    emit(out, "two", [1.0, 3.5], [2.0, -1.25], 0, 0, [0.5], [0.25])
    emit(out, "two_user_c1", [-1.0, 0.25], [0.5, 0.75], 1, 6, [0.8], [0.0], [3.0, -2.0])
    emit(out, "three", [0.0, 0.3, 2.0], [1.0, 2.0, -0.5], 0, 0, [0.6, 1.7], [0.2, 0.0])
    emit(out, "big_c1", bx, bf, 1, 0, [0.9, 0.4, 1.3, 2.0], [0.05, 0.0, 0.7, 0.0])
    sys.stdout.write("\n".join(out) + "\n")


if __name__ == "__main__":
    main()
