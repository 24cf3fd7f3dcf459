#!/usr/bin/python3
"""Independent high-precision reference for the geometric form (docs/method.md §4) and
the error constants (docs/method.md §8, docs/accuracy.md).

Written from docs/method.md with mpmath at 40 significant digits; it does not use
the C library.  Its output is checked in and read by tests/api/test_geometric.c
and tests/api/test_accuracy.c; `make test` does NOT run it.  Regenerate
(deterministic, ~1 min) with

    /usr/bin/python3 tests/ref/accuracy_ref.py > tests/ref/accuracy_ref.csv

(needs python3-mpmath from Debian).  What it computes:

  geometric form (§4): on [x_i, x_{i+1}], k = 2h/(3 pi a),
      X(th) = sum A_l(th) [x_i, x_i + k, x_{i+1} - k, x_{i+1}]_l
      Y(th) = sum A_l(th) [f_i, f_i + k d_i, f_{i+1} - k d_{i+1}, f_{i+1}]_l
  A point x is mapped to th by bisection on [0, pi/2] (150 halvings); dy/dx = Y'/X', d2y/dx2 = (Y''X' - Y'X'')/X'^3 with
  Y', X', ... from mpmath.diff of the script's own X and Y (not the basis
  derivative formulas).  Integrals: mpmath.quad of Y(th) X'(th) dth.
  Outside [x0, xn] (TS_EXTRAP_EXTEND): y_e + y'_e t + y''_e t^2 / 2 at the end.

  error constants (docs/accuracy.md §3), h = 1, for a = alpha + beta:
      first   = max_delta  c^2 delta + s^2 (1 - delta) + kappa (A1 + A2)
      line    = max_delta |e[f = t](delta)|    (paper form; the error on f(t) = t)
      second  = max_delta int_0^1 |K(delta, tau)| dtau, where K is obtained
                from the DEFINITION of the spline: K(delta, tau) =
                e[(t - tau)_+](delta) - e[t](delta) 1{tau < delta}
                (paper form; geometric: e[(t - tau)_+], since e[t] = 0), e[g]
                the error of the spline built from g's values and slopes.
      thm1    = max_delta int_0^1 |e[(t - tau)_+^2](delta)| dtau: the paper's
                Theorem 1 constant C (its claimed bound is (1/2) C h^3 |f'''|).
  Maxima over delta (or th): 160-point grid, golden section around every
  local maximum.

CSV records:
  case,NAME,NPOINTS          then x,...  f,...  d,...  alpha,...  beta,...
  pt,X,Y,DY,D2Y,D3Y,XP        inside [x0, xn] (at an inner knot: the interval to its right);
                              D3Y = y''' (chain rule from the th-derivatives), XP = (dX/dth)/h
                              there: the conditioning of x -> th
  ext,X,Y,DY,D2Y,0,XP         outside (XP at the end)
  int,A,B,VALUE               integral of S from A to B
  end
  const,FORM,A,FIRST,LINE,SECOND,THM1      FORM 0 paper, 2 geometric (LINE 0, THM1 nan)
  glnode,XI,W                 12-point Gauss-Legendre rule on [-1, 1] (positive nodes)
"""
import sys

import mpmath
from mpmath import mp, mpf

mp.dps = 40
PI = mp.pi


def basis(th):
    s, c = mpmath.sin(th), mpmath.cos(th)
    return [(1 - s) ** 3, 3 * s - 4 * s ** 2 + s ** 3, 3 * c - 4 * c ** 2 + c ** 3, (1 - c) ** 3]


def seg(th, P):
    A = basis(th)
    return sum(A[l] * P[l] for l in range(4))


class Geo:
    def __init__(self, x, f, d, alpha, beta):
        self.x = [mpf(v) for v in x]
        self.f = [mpf(v) for v in f]
        self.d = [mpf(v) for v in d]
        self.a = [mpf(alpha[i]) + mpf(beta[i]) for i in range(len(alpha))]
        self.n = len(x) - 1

    def ctl(self, i):
        h = self.x[i + 1] - self.x[i]
        k = 2 * h / (3 * PI * self.a[i])
        X = [self.x[i], self.x[i] + k, self.x[i + 1] - k, self.x[i + 1]]
        Y = [self.f[i], self.f[i] + k * self.d[i], self.f[i + 1] - k * self.d[i + 1], self.f[i + 1]]
        return X, Y

    def locate(self, x):
        for i in range(self.n):
            if x < self.x[i + 1]:
                return i
        return self.n - 1

    def theta(self, i, x):
        X, _ = self.ctl(i)
        if x == X[0]:
            return mpf(0)
        if x == X[3]:
            return PI / 2
        lo, hi = mpf(0), PI / 2  # X is increasing: plain bisection to 2^-150
        for _ in range(150):
            m = (lo + hi) / 2
            if seg(m, X) < x:
                lo = m
            else:
                hi = m
        return (lo + hi) / 2

    def derivs(self, i, th):
        X, Y = self.ctl(i)
        x1 = mpmath.diff(lambda t: seg(t, X), th, 1)
        x2 = mpmath.diff(lambda t: seg(t, X), th, 2)
        y0 = seg(th, Y)
        y1 = mpmath.diff(lambda t: seg(t, Y), th, 1)
        y2 = mpmath.diff(lambda t: seg(t, Y), th, 2)
        x3 = mpmath.diff(lambda t: seg(t, X), th, 3)
        y3 = mpmath.diff(lambda t: seg(t, Y), th, 3)
        h = X[3] - X[0]
        num = y2 * x1 - y1 * x2
        d3 = ((y3 * x1 - y1 * x3) * x1 - 3 * x2 * num) / x1 ** 5
        return y0, y1 / x1, num / x1 ** 3, d3, x1 / h

    def at(self, x):
        x = mpf(x)
        if x < self.x[0] or x > self.x[-1]:
            i = 0 if x < self.x[0] else self.n - 1
            e = self.x[0] if x < self.x[0] else self.x[-1]
            y0, y1, y2, y3, xp = self.derivs(i, mpf(0) if x < self.x[0] else PI / 2)
            t = x - e
            return y0 + y1 * t + y2 * t * t / 2, y1 + y2 * t, y2, 0, xp
        i = self.locate(x)
        return self.derivs(i, self.theta(i, x))

    def integral(self, a, b):
        a, b = mpf(a), mpf(b)
        sign = 1
        if a > b:
            a, b, sign = b, a, -1
        tot = mpf(0)
        for i in range(self.n):
            lo, hi = max(a, self.x[i]), min(b, self.x[i + 1])
            if lo >= hi:
                continue
            X, Y = self.ctl(i)
            t0, t1 = self.theta(i, lo), self.theta(i, hi)
            tot += mpmath.quad(lambda t: seg(t, Y) * mpmath.diff(lambda u: seg(u, X), t), [t0, t1])
        return sign * tot


def g(v):
    return repr(float(v))


def emit_case(name, x, f, d, alpha, beta, fracs, ints):
    G = Geo(x, f, d, alpha, beta)
    out = ['case,%s,%d' % (name, len(x))]
    for lab, arr in (('x', x), ('f', f), ('d', d), ('alpha', alpha), ('beta', beta)):
        out.append(lab + ',' + ','.join(repr(float(v)) for v in arr))
    pts = []
    for i in range(len(x) - 1):
        h = x[i + 1] - x[i]
        for fr in fracs:
            pts.append(x[i] + fr * h)
    pts.append(x[-1])
    for p in pts:
        y0, y1, y2, y3, xp = G.at(p)
        out.append('pt,%r,%s,%s,%s,%s,%s' % (float(p), g(y0), g(y1), g(y2), g(y3), g(xp)))
    h0, hn = x[1] - x[0], x[-1] - x[-2]
    for p in (x[0] - 0.3 * h0, x[-1] + 0.5 * hn):
        y0, y1, y2, y3, xp = G.at(p)
        out.append('ext,%r,%s,%s,%s,%s,%s' % (float(p), g(y0), g(y1), g(y2), g(y3), g(xp)))
    for a, b in ints:
        out.append('int,%r,%r,%s' % (float(a), float(b), g(G.integral(a, b))))
    out.append('end')
    return out


# ---- error constants -------------------------------------------------------

def spline_paper(g0, g1, d0, d1, kap, th):
    """Paper-form spline on [0, 1] at th (docs/method.md §3)."""
    return seg(th, [g0, g0 + kap * d0, g1 - kap * d1, g1])


def gmax(F, lo, hi, N=160):
    xs = [lo + (hi - lo) * mpf(j) / N for j in range(N + 1)]
    v = [F(t) for t in xs]
    best = max(v)
    gr = (mpmath.sqrt(5) - 1) / 2
    for j in range(N + 1):
        if (j > 0 and v[j] < v[j - 1]) or (j < N and v[j] < v[j + 1]):
            continue
        a, b = xs[max(j - 1, 0)], xs[min(j + 1, N)]
        for _ in range(30):
            p, q = b - gr * (b - a), a + gr * (b - a)
            if F(p) >= F(q):
                b = q
            else:
                a = p
        best = max(best, F((a + b) / 2))
    return best


def absint(K, dl):
    """int_0^1 |K| for K continuous and polynomial of degree <= 2 in tau between
    its kinks (the data of (t - tau)_+^k are polynomials in tau): split at dl
    and at the sign changes of K (found by sampling 64 cells and bisection),
    then a 4-point Gauss-Legendre rule per piece, exact for such pieces."""
    pts = sorted(set(mpmath.linspace(0, 1, 65) + [dl]))
    cuts = [mpf(0), mpf(1), dl]
    for a, b in zip(pts[:-1], pts[1:]):
        ka, kb = K(a), K(b)
        if ka * kb < 0:
            for _ in range(60):
                m = (a + b) / 2
                km = K(m)
                if km * ka < 0:
                    b = m
                else:
                    a, ka = m, km
            cuts.append((a + b) / 2)
    cuts = sorted(set(cuts))
    q = 2 * mpmath.sqrt(mpf(6) / 5)
    xg = [mpmath.sqrt((3 + q) / 7) * sgn for sgn in (-1, 1)] + [mpmath.sqrt((3 - q) / 7) * sgn for sgn in (-1, 1)]
    wg = [(18 - mpmath.sqrt(30)) / 36] * 2 + [(18 + mpmath.sqrt(30)) / 36] * 2
    tot = mpf(0)
    for a, b in zip(cuts[:-1], cuts[1:]):
        if b <= a:
            continue
        c, r = (a + b) / 2, (b - a) / 2
        tot += r * sum(w * abs(K(c + r * x)) for x, w in zip(xg, wg))
    return tot


def constants(a, geo):
    mp.dps = 20
    a = mpf(a)
    kap = 2 / (3 * PI * a)

    def xhat(th):  # geometric X on [0, 1]
        return seg(th, [0, kap, 1 - kap, 1])

    def pos(th):  # delta of the point with parameter th
        return xhat(th) if geo else th / (PI / 2)

    def err(gfun, gd, th):
        """e[g] at parameter th: g(delta) - spline built from g's data."""
        return gfun(pos(th)) - spline_paper(gfun(0), gfun(1), gd(0), gd(1), kap, th)

    def first(th):
        s, c = mpmath.sin(th), mpmath.cos(th)
        A = basis(th)
        dl = pos(th)
        return c * c * dl + s * s * (1 - dl) + kap * (A[1] + A[2])

    def line(th):
        return abs(err(lambda t: t, lambda t: 1, th))

    def second(th):
        dl = pos(th)
        el = 0 if geo else err(lambda t: t, lambda t: 1, th)

        def K(tau):
            gt = lambda t: max(t - tau, 0)
            gd = lambda t: 1 if t > tau else 0
            return err(gt, gd, th) - (el if tau < dl else 0)
        return absint(K, dl)

    def thm1(th):
        dl = pos(th)

        def K(tau):
            gt = lambda t: max(t - tau, 0) ** 2
            gd = lambda t: 2 * max(t - tau, 0)
            return err(gt, gd, th)
        return absint(K, dl)

    r = [gmax(first, 0, PI / 2), 0 if geo else gmax(line, 0, PI / 2),
         gmax(second, 0, PI / 2, N=48), mpf('nan') if geo else gmax(thm1, 0, PI / 2, N=48)]
    mp.dps = 40
    return r


def gl12():
    def leg(n, x):
        p0, p1 = mpf(1), x
        for k in range(2, n + 1):
            p0, p1 = p1, ((2 * k - 1) * x * p1 - (k - 1) * p0) / k
        return p1, n * (x * p1 - p0) / (x * x - 1)
    out = []
    for k in range(1, 7):
        x = mpmath.cos(PI * (k - mpf(1) / 4) / (12 + mpf(1) / 2))
        for _ in range(60):
            p, dp = leg(12, x)
            x -= p / dp
        p, dp = leg(12, x)
        out.append((x, 2 / ((1 - x * x) * dp * dp)))
    return out


def main():
    w = sys.stdout.write
    w('# generated by tests/ref/accuracy_ref.py -- do not edit\n')
    fr = [0.0, 1e-13, 1e-6, 0.1, 0.3, 0.5 - 1e-9, 0.5, 0.5 + 1e-9, 0.7, 0.9, 1 - 1e-6, 1 - 1e-13]
    cases = [
        ('mixed', [0.0, 1.0, 2.5, 3.0, 4.2, 6.0], [0.3, 1.2, -0.4, 0.1, 2.0, 1.0],
         [1.0, -0.5, 0.7, 2.5, -1.0, 0.3], [0.3472, 0.3, 1.0, 0.5, 3.0], [0.0, 0.0472, 0.0, 0.3, 1000.0]),
        ('tiny', [1.0, 1.0 + 1e-9, 1.0 + 2.5e-9], [2.0, 2.0 + 3e-9, 2.0 - 1e-9], [3.0, -1.0, 0.5],
         [0.3472, 1.0], [0.0, 0.0]),
        ('huge', [-1e250, 0.0, 2e250], [1.0, -2.0, 5.0], [1e-250, 3e-250, -2e-250], [0.5, 0.3472], [0.0, 0.0]),
        ('line', [0.0, 0.7, 1.9, 2.0, 5.0], [3.0 * v - 1.0 for v in [0.0, 0.7, 1.9, 2.0, 5.0]],
         [3.0] * 5, [0.3472, 0.6, 2.0, 50.0], [0.0, 0.0, 0.0, 0.0]),
    ]
    for name, x, f, d, al, be in cases:
        h = [x[i + 1] - x[i] for i in range(len(x) - 1)]
        ints = [(x[0] + 0.1 * h[0], x[2] - 0.3 * h[1]), (x[0], x[-1]),
                (x[1] + 0.6 * h[1], x[1] + 0.9 * h[1]), (x[1] + 0.2 * h[1], x[1] + 0.4 * h[1]),
                (x[1] + 0.45 * h[1], x[1] + 0.55 * h[1]), (x[-1], x[0] + 0.5 * h[0])]
        for line in emit_case(name, x, f, d, al, be, fr, ints):
            w(line + '\n')
    for a in (0.3472, float(4 / (3 * PI)), 0.5, 1.0, 2.0, 5.0):
        for geo in (0, 1):
            c = constants(a, geo)
            w('const,%d,%r,%s,%s,%s,%s\n' % (2 if geo else 0, a, g(c[0]), g(c[1]), g(c[2]), g(c[3])))
    for x, wt in gl12():
        w('glnode,%s,%s\n' % (mpmath.nstr(x, 22), mpmath.nstr(wt, 22)))


if __name__ == '__main__':
    main()
