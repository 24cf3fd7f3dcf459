#!/usr/bin/env python3
"""Reference arc length for tests/api/test_curve.c, independent of the C code.

The closed curve through N points on a circle of radius r, built from docs/method.md §3, §6, §7
re-derived here: knots (all steps equal, so every parameterisation gives the same
curve up to a scale of t), periodic three-point-mean slopes per coordinate, control
points P_i, P_i + k d_i, P_{i+1} - k d_{i+1}, k = 2h/(3 pi a).  Length of each segment
= integral over theta in [0, pi/2] of |dP/dtheta| with dP/dtheta from docs/method.md (2.1), by
mpmath.quad (tanh-sinh) at 40 digits.  Prints one line per a value.

Usage: /usr/bin/python3 tests/ref/curve_circle_length.py   (needs python3-mpmath)
"""
import mpmath as mp

mp.mp.dps = 40


def curve_length(pts, a):
    n = len(pts)  # closed: n segments
    dim = len(pts[0])
    h = [mp.mpf(1)] * n  # equal steps (scale of t cancels in the length)
    # periodic three-point mean (docs/method.md §6), per coordinate
    d = []
    for i in range(n):
        hm, hp = h[i - 1], h[i]
        dm = [(pts[i][k] - pts[i - 1][k]) / hm for k in range(dim)]
        dp = [(pts[(i + 1) % n][k] - pts[i][k]) / hp for k in range(dim)]
        d.append([(hp * dm[k] + hm * dp[k]) / (hm + hp) for k in range(dim)])
    total = mp.mpf(0)
    for i in range(n):
        j = (i + 1) % n
        kk = 2 * h[i] / (3 * mp.pi * a)
        B = [[pts[i][k], pts[i][k] + kk * d[i][k], pts[j][k] - kk * d[j][k], pts[j][k]]
             for k in range(dim)]

        def speed(th):
            s, c = mp.sin(th), mp.cos(th)
            v = [3 * (1 - s) ** 2 * c * (b[1] - b[0]) + 2 * s * c * (b[2] - b[1])
                 + 3 * (1 - c) ** 2 * s * (b[3] - b[2]) for b in B]
            return mp.sqrt(sum(x * x for x in v))

        total += mp.quad(speed, [0, mp.pi / 4, mp.pi / 2])
    return total


if __name__ == "__main__":
    N, r, cx, cy = 64, mp.mpf(2), mp.mpf("0.5"), mp.mpf("-0.25")
    pts = [[cx + r * mp.cos(2 * mp.pi * i / N), cy + r * mp.sin(2 * mp.pi * i / N)]
           for i in range(N)]
    print("circumference 2*pi*r =", mp.nstr(2 * mp.pi * r, 25))
    for a in ["1", "0.5", "0.37", "2"]:
        L = curve_length(pts, mp.mpf(a))
        print("a =", a, "length =", mp.nstr(L, 25), " rel. to 2 pi r:",
              mp.nstr(L / (2 * mp.pi * r) - 1, 6))
