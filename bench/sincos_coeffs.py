#!/usr/bin/env python3
"""Coefficients of the sin/cos polynomials of src/kernels.c (make bench).

fast.c evaluates, for u = theta/2 in [0, pi/4] (z = u*u),
    sin u ~ u + u*z*(S1 + z*S2 + ... + z^5*S6)
    cos u ~ 1 - z/2 + z^2*(C1 + z*C2 + ... + z^5*C6)
The coefficients are a weighted least-squares fit at 600 Chebyshev nodes
(near-minimax), computed with mpmath at 50 digits and rounded to double.
The script prints them as C literals and the max absolute error of the
polynomials with the rounded coefficients (evaluated exactly, no rounding of
the evaluation itself) over a dense grid: this is the truncation part of the
error budget stated in fast.c.  Needs python3-mpmath (Debian).
Run: python3 bench/sincos_coeffs.py
"""
import mpmath as mp

mp.mp.dps = 50
B = mp.pi / 4
N = 600
K = 6


def fit(target, weight, powers):
    nodes = [(B / 2) * (1 - mp.cos(mp.pi * (k + mp.mpf(1) / 2) / N)) for k in range(N)]
    A = mp.matrix(N, len(powers))
    y = mp.matrix(N, 1)
    for i, u in enumerate(nodes):
        w = weight(u)
        for j, p in enumerate(powers):
            A[i, j] = w * (u * u) ** p
        y[i] = w * target(u)
    c = mp.lu_solve(A.T * A, A.T * y)
    return [float(c[j]) for j in range(len(powers))]


def main():
    # sin u - u = u*z*P(z): fit P to (sin u - u)/(u z) weighted by u^3 (absolute error)
    sin_t = lambda u: (mp.sin(u) - u) / u**3 if u != 0 else mp.mpf(-1) / 6
    S = fit(sin_t, lambda u: u**3, list(range(K)))
    cos_t = lambda u: (mp.cos(u) - 1 + u * u / 2) / u**4 if u != 0 else mp.mpf(1) / 24
    C = fit(cos_t, lambda u: u**4, list(range(K)))
    es = ec = mp.mpf(0)
    for k in range(20001):
        u = B * k / 20000
        z = u * u
        ps = u + u * z * sum(mp.mpf(S[j]) * z**j for j in range(K))
        pc = 1 - z / 2 + z * z * sum(mp.mpf(C[j]) * z**j for j in range(K))
        es = max(es, abs(ps - mp.sin(u)))
        ec = max(ec, abs(pc - mp.cos(u)))
    for j in range(K):
        print("#define TS_S%d %r" % (j + 1, S[j]))
    for j in range(K):
        print("#define TS_C%d %r" % (j + 1, C[j]))
    print("/* max |poly - sin| = %.3g, max |poly - cos| = %.3g on [0, pi/4] */" % (es, ec))


if __name__ == "__main__":
    main()
