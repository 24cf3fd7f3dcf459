/* The tests' reference trigonometric basis, written from the closed form of
 * the method (docs/method.md §2), independently of src/basis.c: no
 * cancellation guards, no shared code, plain libm sin/cos of θ.
 *
 * With s = sin θ, c = cos θ:
 *   A0 = (1 - s)^3,   A1 = 3s - 4s^2 + s^3,   A2 = 3c - 4c^2 + c^3,   A3 = (1 - c)^3;
 * first derivatives in θ (chain rule, s' = c, c' = -s):
 *   A0' = -3(1 - s)^2 c,   A1' = c(3 - 8s + 3s^2),
 *   A2' = -s(3 - 8c + 3c^2),   A3' = 3(1 - c)^2 s;
 * second derivatives (product rule on the above):
 *   A0'' = 6(1 - s)c^2 + 3(1 - s)^2 s,   A1'' = -s(3 - 8s + 3s^2) + c^2(6s - 8),
 *   A2'' = -c(3 - 8c + 3c^2) + s^2(6c - 8),   A3'' = 6(1 - c)s^2 + 3(1 - c)^2 c.
 * On [0, π/2]: A_l >= 0, Σ A_l = 1, A0 + A1 = c^2, A2 + A3 = s^2.  The formulas
 * hold for every real θ (the extension outside an interval uses them too).
 *
 * A segment with control values B0..B3 is S(θ) = Σ A_l B_l (th_seg) and
 * dS/dθ = 3(1 - s)^2 c (B1 - B0) + 2sc (B2 - B1) + 3(1 - c)^2 s (B3 - B2),
 * docs/method.md (2.1) (th_seg_d1).
 *
 * Rounding: each A_l is a sum of at most three products of factors <= 4 in
 * magnitude, so on [0, π/2] it is within a few ulp of 1 (tests state their
 * own tolerances from this).
 */
#ifndef TS_TH_BASIS_H
#define TS_TH_BASIS_H

#include <math.h>

static inline void th_basis(double theta, double A[4])
{
    double s = sin(theta), c = cos(theta);
    A[0] = (1 - s) * (1 - s) * (1 - s);
    A[1] = 3 * s - 4 * s * s + s * s * s;
    A[2] = 3 * c - 4 * c * c + c * c * c;
    A[3] = (1 - c) * (1 - c) * (1 - c);
}

static inline void th_basis_d1(double theta, double A[4])
{
    double s = sin(theta), c = cos(theta);
    A[0] = -3 * (1 - s) * (1 - s) * c;
    A[1] = c * (3 - 8 * s + 3 * s * s);
    A[2] = -s * (3 - 8 * c + 3 * c * c);
    A[3] = 3 * (1 - c) * (1 - c) * s;
}

static inline void th_basis_d2(double theta, double A[4])
{
    double s = sin(theta), c = cos(theta);
    A[0] = 6 * (1 - s) * c * c + 3 * (1 - s) * (1 - s) * s;
    A[1] = -s * (3 - 8 * s + 3 * s * s) + c * c * (6 * s - 8);
    A[2] = -c * (3 - 8 * c + 3 * c * c) + s * s * (6 * c - 8);
    A[3] = 6 * (1 - c) * s * s + 3 * (1 - c) * (1 - c) * c;
}

/* Σ A_l B_l for basis values A (of th_basis, th_basis_d1 or th_basis_d2). */
static inline double th_dot4(const double A[4], const double B[4])
{
    return A[0] * B[0] + A[1] * B[1] + A[2] * B[2] + A[3] * B[3];
}

/* S(θ) = Σ A_l(θ) B_l. */
static inline double th_seg(const double B[4], double theta)
{
    double A[4];
    th_basis(theta, A);
    return th_dot4(A, B);
}

/* dS/dθ by (2.1), the form with differences of control values. */
static inline double th_seg_d1(const double B[4], double theta)
{
    double s = sin(theta), c = cos(theta);
    return 3 * (1 - s) * (1 - s) * c * (B[1] - B[0]) + 2 * s * c * (B[2] - B[1]) +
           3 * (1 - c) * (1 - c) * s * (B[3] - B[2]);
}

#endif
