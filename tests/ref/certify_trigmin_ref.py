#!/usr/bin/python3
"""Independent high-precision reference for ts__trig_min (docs/method.md §2, §5).

For control values C0..C3 and kappa, the exact minimum over theta in [0, pi/2] of

    g(theta) = sum_l A_l(theta) C_l - kappa * theta,
    A0 = (1-s)^3, A1 = 3s - 4s^2 + s^3, A2 = 3c - 4c^2 + c^3, A3 = (1-c)^3  (docs/method.md §2)

computed with mpmath at 60 digits WITHOUT the C library's method: g'(theta) is
written as a trigonometric polynomial and its zeros are found from the
companion-matrix roots (mpmath.polyroots) of the polynomial in z = exp(i theta)
obtained from sin and cos directly -- not from the tan(theta/2) substitution and
Bernstein isolation of certify.c -- and are then polished with mpmath.findroot on
g'(theta); a 4001-point scan of g' adds a candidate at every sign change, so a
root the companion matrix misplaces is still seen.  g is evaluated with mpmath's
own sin and cos at 0, pi/2 and every candidate.

Output (checked in; NOT run by `make test`; deterministic, fixed seed):

    /usr/bin/python3 tests/ref/certify_trigmin_ref.py > tests/ref/certify_trigmin_ref.csv

Each line:  C0,C1,C2,C3,kappa,min,theta_min   (inputs as exact double reprs,
min and theta rounded to 20 significant digits).  '#' lines are comments.
Needs python3-mpmath from Debian.
"""
import random

import mpmath
from mpmath import mp, mpf

mp.dps = 60
HALF_PI = mp.pi / 2


def g(C, k, th):
    s, c = mpmath.sin(th), mpmath.cos(th)
    A = [(1 - s) ** 3, 3 * s - 4 * s ** 2 + s ** 3, 3 * c - 4 * c ** 2 + c ** 3, (1 - c) ** 3]
    return sum(a * cl for a, cl in zip(A, C)) - k * th


def gp(C, k, th):
    s, c = mpmath.sin(th), mpmath.cos(th)
    return (3 * (1 - s) ** 2 * c * (C[1] - C[0]) + 2 * s * c * (C[2] - C[1])
            + 3 * (1 - c) ** 2 * s * (C[3] - C[2]) - k)


def gp_poly_roots(C, k):
    """Zeros of g' on [0, pi/2] via z = e^{i theta}: s = (z - 1/z)/(2i),
    c = (z + 1/z)/2; z^3 g'(theta) is a polynomial of degree 6 in z."""
    D0, D1, D2 = C[1] - C[0], C[2] - C[1], C[3] - C[2]
    # polynomial arithmetic on coefficient lists indexed by power offset +3
    def P(coeffs):  # dict power->coef
        return coeffs

    def mul(a, b):
        r = {}
        for pa, ca in a.items():
            for pb, cb in b.items():
                r[pa + pb] = r.get(pa + pb, 0) + ca * cb
        return r

    def add(*xs):
        r = {}
        for x in xs:
            for p, v in x.items():
                r[p] = r.get(p, 0) + v
        return r

    def scal(a, v):
        return {p: c * v for p, c in a.items()}

    I = mpmath.mpc(0, 1)
    s = {1: 1 / (2 * I), -1: -1 / (2 * I)}
    c = {1: mpf(1) / 2, -1: mpf(1) / 2}
    one = {0: mpf(1)}
    oms = add(one, scal(s, -1))
    omc = add(one, scal(c, -1))
    t0 = scal(mul(mul(oms, oms), c), 3 * D0)
    t1 = scal(mul(s, c), 2 * D1)
    t2 = scal(mul(mul(omc, omc), s), 3 * D2)
    poly = add(t0, t1, t2, {0: -k})
    coeffs = [poly.get(p, 0) for p in range(3, -4, -1)]  # z^3 .. z^-3 -> times z^3
    while coeffs and abs(coeffs[0]) == 0:
        coeffs.pop(0)
    if len(coeffs) < 2:
        return []
    try:
        roots = mpmath.polyroots(coeffs, maxsteps=400, extraprec=400)
    except mpmath.libmp.libhyper.NoConvergence:
        return []
    out = []
    for z in roots:
        if abs(abs(z) - 1) < mpf('1e-20'):
            th = mpmath.arg(z)
            if mpf('-1e-30') <= th <= HALF_PI + mpf('1e-30'):
                out.append(min(max(th, mpf(0)), HALF_PI))
    return out


def exact_min(C, k):
    C = [mpf(v) for v in C]
    k = mpf(k)
    cands = [mpf(0), HALF_PI]
    for th in gp_poly_roots(C, k):
        cands.append(th)
    N = 4000
    prev = gp(C, k, mpf(0))
    for j in range(1, N + 1):
        th = HALF_PI * j / N
        cur = gp(C, k, th)
        if prev == 0 or (prev < 0) != (cur < 0):
            a, b = HALF_PI * (j - 1) / N, th
            try:
                r = mpmath.findroot(lambda t: gp(C, k, t), (a, b), solver='anderson')
                if a <= r <= b:
                    cands.append(r)
            except (ValueError, ZeroDivisionError):
                pass
            cands.append(a)
            cands.append(b)
        prev = cur
    best = None
    for th in cands:
        v = g(C, k, th)
        if best is None or v < best[0]:
            best = (v, th)
    return best


def dbl(v):
    return float(v)


def main():
    rnd = random.Random(20261123)
    cases = []
    # degenerate
    cases.append(([0.0, 0.0, 0.0, 0.0], 0.0))
    cases.append(([3.5, 3.5, 3.5, 3.5], 0.0))
    cases.append(([-2.0, -2.0, -2.0, -2.0], 0.0))
    cases.append(([1.0, 1.0, 1.0, 1.0], 1.0))
    cases.append(([1.0, 1.0, 1.0, 1.0], -1.0))
    cases.append(([0.0, 0.0, 1.0, 1.0], 0.0))
    cases.append(([1.0, 1.0, 0.0, 0.0], 0.0))
    cases.append(([1.0, 0.0, 0.0, 1.0], 0.0))
    cases.append(([0.0, 1.0, 1.0, 0.0], 0.0))
    cases.append(([1e300, -1e300, 1e300, -1e300], 0.0))
    cases.append(([1e-300, 2e-300, -3e-300, 1e-300], 1e-300))
    cases.append(([1e200, 1e200 + 1e185, 1e200 - 1e185, 1e200], 1e184))
    cases.append(([5.0, 5.0 + 1e-15, 5.0 - 1e-15, 5.0], 0.0))
    # random, several scales
    for _ in range(160):
        sc = 10.0 ** rnd.uniform(-8, 8)
        C = [rnd.uniform(-1, 1) * sc for _ in range(4)]
        k = rnd.choice([0.0, rnd.uniform(-3, 3) * sc, rnd.uniform(-0.1, 0.1) * sc])
        cases.append((C, k))
    # spline-like: positive offset, small slope terms (near-boundary gaps)
    for _ in range(60):
        base = 10.0 ** rnd.uniform(-3, 3)
        f0, f1 = base * rnd.uniform(0.01, 1), base * rnd.uniform(0.01, 1)
        kd0, kd1 = base * rnd.uniform(-2, 2), base * rnd.uniform(-2, 2)
        k = rnd.choice([0.0, base * rnd.uniform(-2, 2)])
        cases.append(([f0, f0 + kd0, f1 - kd1, f1], k))
    # near-double and near-triple roots of g': choose (D0, D1, D2, kappa) in the
    # null space of the conditions g'(th0) = g''(th0) (= g'''(th0)) = 0
    for order in (2, 3):
        for _ in range(40):
            th0 = mpf(rnd.uniform(0.05, 1.52))
            s, c = mpmath.sin(th0), mpmath.cos(th0)

            def w(th):
                s, c = mpmath.sin(th), mpmath.cos(th)
                return [3 * (1 - s) ** 2 * c, 2 * s * c, 3 * (1 - c) ** 2 * s, mpf(-1)]

            rows = [w(th0)]
            rows.append([mpmath.diff(lambda t, j=j: w(t)[j], th0) for j in range(4)])
            if order == 3:
                rows.append([mpmath.diff(lambda t, j=j: w(t)[j], th0, 2) for j in range(4)])
            # null space: random combination orthogonal to rows
            M = mpmath.matrix(rows)
            v = mpmath.matrix([rnd.uniform(-1, 1) for _ in range(4)])
            # project v onto null space of M: v - M^T (M M^T)^-1 M v
            MT = M.T
            v = v - MT * (mpmath.inverse(M * MT) * (M * v))
            D0, D1, D2, k = [v[j] for j in range(4)]
            sc = 10.0 ** rnd.uniform(-4, 4)
            C0 = mpf(rnd.uniform(-1, 1))
            C = [C0, C0 + D0, C0 + D0 + D1, C0 + D0 + D1 + D2]
            cases.append(([dbl(x * sc) for x in C], dbl(k * sc)))
    print("# C0,C1,C2,C3,kappa,min,theta_min  (tests/ref/certify_trigmin_ref.py, mp.dps=60)")
    for C, k in cases:
        C = [float(x) for x in C]
        k = float(k)
        v, th = exact_min(C, k)
        print(",".join([repr(x) for x in C] + [repr(k), mpmath.nstr(v, 20, strip_zeros=False),
                                                mpmath.nstr(th, 20, strip_zeros=False)]))


if __name__ == "__main__":
    main()
