#!/usr/bin/env python3
"""The geometric form's start for X̂(φ) = u (src/internal.h, ts__geo_start):
its accuracy, the Halley steps it leaves, and why no cheap start reaches one
step (bench/HISTORY.md, "Third round").

X̂(φ) = s² + κ(A1 − A2), s = sin φ, c = cos φ, A1 = s(1 − s)(3 − s),
A2 = c(1 − c)(3 − c) (docs/method.md §4), solved for φ in [0, π/4],
u in [0, 1/2].  The root is found here by bisection and Newton in double
(to about 1e-15 relative, far below the errors measured).

1. ts__geo_start as written in C (one Newton step on the quartic model from
   the root of 3κφ + bφ², b = max(1 − 5κ, chord)): the maximum relative
   error over u for κ up to 2/(3π), 0.4, 1/2, and the most Halley steps
   (ts__geo_halley's step, stopping at the first step below 2^-20 φ) any u
   needs from it.
2. One Halley step needs a start within about 2^-21.  A fit of the
   correction φ/φ_q in the two bounded variables (φ_q, σ), φ_q the root of
   3κφ + φ² (b = 1) and σ = 3κ/(3κ + 2φ_q) (they stay bounded at the cone
   u, κ -> 0 where φ turns from u/(3κ) into √u): least squares in
   relative error, total degree d, for κ <= 0.1 and κ <= 1/2.

Needs python3-numpy (Debian).  Run: /usr/bin/python3 bench/geo_start.py
"""
import numpy as np

Q = np.pi / 4
G1 = 8 - 9 / np.sqrt(2)
V0, V1 = 0.5 - Q * Q, 5 * Q * Q - 3 * Q
W0, W1 = 1 - 2 * Q, 10 * Q - G1 - 3
Q3 = Q ** 3
C40, C41 = (W0 - 3 * V0 / Q) / Q3, (W1 - 3 * V1 / Q) / Q3
C30, C31 = V0 / Q3 - C40 * Q, V1 / Q3 - C41 * Q
B0, B1 = 0.5 / (Q * Q), 3 / Q


def xhat(phi, k):
    s, c = np.sin(phi), np.cos(phi)
    return s * s + k * (s * (1 - s) * (3 - s) - c * (1 - c) * (3 - c))


def xhatp(phi, k):
    s, c = np.sin(phi), np.cos(phi)
    return 2 * s * c + k * (c * (3 - 8 * s + 3 * s * s) + s * (3 - 8 * c + 3 * c * c))


def root(u, k):
    lo, hi = np.zeros_like(u), np.full_like(u, Q)
    for _ in range(60):
        m = 0.5 * (lo + hi)
        f = xhat(m, k) - u
        lo, hi = np.where(f < 0, m, lo), np.where(f < 0, hi, m)
    phi = 0.5 * (lo + hi)
    for _ in range(3):
        phi = phi - (xhat(phi, k) - u) / xhatp(phi, k)
    return phi


def start(u, k):
    b = 1 - 5 * k
    bq = np.maximum(B0 - B1 * k, b)
    d = 9 * k * k + 4 * bq * u
    phi = np.minimum(2 * u / (3 * k + np.sqrt(np.maximum(d, 0))), Q)
    c3, c4 = C30 + C31 * k, C40 + C41 * k
    M = phi * (3 * k + phi * (b + phi * (c3 + phi * c4))) - u
    Mp = 3 * k + phi * (2 * b + phi * (3 * c3 + 4 * c4 * phi))
    return np.minimum(np.maximum(phi - M / np.maximum(Mp, 1e-300), 0), Q)


def halley(phi, k, u):
    s, c = np.sin(phi), np.cos(phi)
    ms, mc = 1 - s, 1 - c
    p1, p2 = 3 - 8 * s + 3 * s * s, 3 - 8 * c + 3 * c * c
    F = s * s + k * (s * ms * (3 - s) - c * mc * (3 - c)) - u
    X1 = 2 * s * c + k * (c * p1 + s * p2)
    X2 = 2 * (c * c - s * s) + k * ((c * c) * (6 * s - 8) - s * p1 + c * p2 - (s * s) * (6 * c - 8))
    nx = phi - 2 * F * X1 / np.maximum(2 * X1 * X1 - F * X2, 1e-300)
    return np.minimum(np.maximum(nx, 0), Q)


def steps(phi, k, u):
    n, done = np.zeros_like(phi), np.zeros(phi.shape, bool)
    for p in range(8):
        nx = halley(phi, k, u)
        conv = np.abs(nx - phi) <= 2.0 ** -20 * nx
        n = np.where(done, n, p + 1)
        done |= conv
        phi = np.where(conv, phi, nx)
    return n


def main():
    us = np.concatenate([np.geomspace(1e-12, 0.5, 300), np.linspace(1e-4, 0.5, 1500)])
    print("1. ts__geo_start: max relative error, most Halley steps")
    for kmax in (2 / (3 * np.pi), 0.4, 0.5):
        worst, most = 0.0, 0
        for k in np.linspace(1e-4, kmax, 120):
            K = np.full_like(us, k)
            P, S = root(us, K), start(us, K)
            worst = max(worst, float(np.max(np.abs(S - P) / P)))
            most = max(most, int(steps(S, K, us).max()))
        print("   kappa <= %.4f: %.3g, %d steps" % (kmax, worst, most))
    print("2. phi/phi_q as a polynomial in (phi_q, sigma): max relative error")
    for kmax in (0.1, 0.5):
        ks = np.concatenate([np.geomspace(1e-6, kmax, 100), np.linspace(1e-3, kmax, 100)])
        uu = np.concatenate([np.geomspace(1e-12, 0.5, 150), np.linspace(1e-4, 0.5, 150)])
        K, U = np.meshgrid(ks, uu)
        K, U = K.ravel(), U.ravel()
        P = root(U, K)
        sq = np.sqrt(9 * K * K + 4 * U)
        pq, sig = 2 * U / (3 * K + sq), 3 * K / sq
        G = P / pq
        for deg in (4, 6, 8):
            A = np.array([pq ** i * sig ** j for i in range(deg + 1) for j in range(deg + 1 - i)]).T
            c, *_ = np.linalg.lstsq(A / G[:, None], np.ones_like(G), rcond=None)
            err = np.max(np.abs(A @ c - G) / G)
            print("   kappa <= %.1f, degree %d (%d terms): %.3g (2^%.1f)"
                  % (kmax, deg, A.shape[1], err, np.log2(err)))


if __name__ == "__main__":
    main()
