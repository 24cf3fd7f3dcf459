/* docs/method.md §2: the cubic trigonometric basis, through the internal functions of
 * src/internal.h.  Expected values come from the definitions of docs/method.md,
 * re-typed here (A0 = (1-s)^3, A1 = 3s - 4s^2 + s^3, ...), from finite
 * differences and from Gauss–Legendre quadrature -- never from basis.c.
 *
 * Bounds used for tolerances (rigorous, from writing each A_l as a trig
 * polynomial, valid for every real θ):
 *   A0 = 5/2 - (15/4) s - (3/2) cos2θ + (1/4) sin3θ,
 *   A1 = -2 + (15/4) s + 2 cos2θ - (1/4) sin3θ,   A2, A3: s <-> c mirror images.
 * The k-th θ-derivative is bounded by the sum of |coef|·freq^k:
 *   k=0: 8, k=1: 8.5, k=2: 16.75, k=3: 26.5, k=4: 56  (call them M0..M4).
 * Central difference (f(θ+h) - f(θ-h))/(2h) has truncation error <= h²/6·M3 and
 * rounding error <= 4ε·M0/h when each f is computed to within 4 ulp of M0.
 */
#include "th.h"
#include "common/th_basis.h"
#include "common/th_rng.h"
#include "internal.h"

#include <float.h>
#include <math.h>

#define EPS DBL_EPSILON
static const double M0 = 8.0, M1 = 8.5, M3 = 26.5, M4 = 56.0;

/* The reference basis and its derivatives: common/th_basis.h (the closed
 * form typed from the text, no cancellation guards: reference only). */

static void lib_basis(double t, double A[4]) { ts__basis(sin(t), cos(t), A); }
static void lib_basis_d1(double t, double A[4]) { ts__basis_d1(sin(t), cos(t), A); }
static void lib_basis_d2(double t, double A[4]) { ts__basis_d2(sin(t), cos(t), A); }

/* Gauss–Legendre nodes/weights of order GLN on [-1, 1] by Newton on P_GLN. */
#define GLN 10
static double gl_x[GLN], gl_w[GLN];
static void gl_init(void)
{
    for (int i = 0; i < GLN; i++) {
        double z = cos(3.14159265358979323846 * (i + 0.75) / (GLN + 0.5)), dp = 0;
        for (int it = 0; it < 100; it++) {
            double p0 = 1, p1 = z;
            for (int k = 2; k <= GLN; k++) {
                double p2 = ((2 * k - 1) * z * p1 - (k - 1) * p0) / k;
                p0 = p1;
                p1 = p2;
            }
            dp = GLN * (z * p1 - p0) / (z * z - 1);
            double dz = p1 / dp;
            z -= dz;
            if (fabs(dz) < 1e-17)
                break;
        }
        gl_x[i] = z;
        gl_w[i] = 2 / ((1 - z * z) * dp * dp);
    }
}
/* ∫_0^θ A_l by GLN-point Gauss–Legendre on 4 panels.  Error of an n-point rule
 * on a panel of width w: w^(2n+1) (n!)^4 / ((2n+1)((2n)!)^3) · max|f^(2n)|; with
 * n = 10, w <= π/8, |A_l^(20)| <= 15/4 + 2·2^20 + 3^20/4 < 1e9 this is < 1e-29
 * per panel, so only rounding (~1e-16·θ per node sum) remains. */
static void gl_int(double theta, double I[4])
{
    for (int l = 0; l < 4; l++)
        I[l] = 0;
    const int P = 4;
    double w = theta / P;
    for (int p = 0; p < P; p++) {
        double mid = (p + 0.5) * w;
        for (int k = 0; k < GLN; k++) {
            double A[4];
            th_basis(mid + 0.5 * w * gl_x[k], A);
            for (int l = 0; l < 4; l++)
                I[l] += 0.5 * w * gl_w[k] * A[l];
        }
    }
}

int main(void)
{
    const double HP = TH_HALF_PI;
    const int N = 2000;
    gl_init();
    TH_CASE("quadrature");
    /* sanity of the quadrature itself: ∫_0^π/2 cos² = π/4 */
    {
        double sum = 0;
        for (int k = 0; k < GLN; k++) {
            double t = HP / 2 * (1 + gl_x[k]);
            sum += HP / 2 * gl_w[k] * cos(t) * cos(t);
        }
        CHECK_CLOSE(sum, TH_PI / 4, 1e-15);
    }

    TH_CASE("identities");
    /* Identities on a dense grid of [0, π/2], plus slightly outside (the
     * extension uses the same formulas).  Rounding: each A_l is a product of
     * three factors <= 3, so its error is a few ulp of M0 -> tolerance 8ε·M0 for
     * sums of four of them outside [0, π/2], 8ε inside (|A_l| <= 1 there). */
    int nonneg = 1, pou = 1, pair01 = 1, pair23 = 1, vs_ref = 1;
    for (int k = 0; k <= N; k++) {
        double t = HP * k / N, s = sin(t), c = cos(t), A[4], R[4];
        ts__basis(s, c, A);
        th_basis(t, R);
        for (int l = 0; l < 4; l++) {
            if (!(A[l] >= 0))
                nonneg = 0;
            if (!(fabs(A[l] - R[l]) <= 8 * EPS))
                vs_ref = 0;
        }
        if (!(fabs(A[0] + A[1] + A[2] + A[3] - 1) <= 8 * EPS))
            pou = 0;
        if (!(fabs(A[0] + A[1] - c * c) <= 8 * EPS))
            pair01 = 0;
        if (!(fabs(A[2] + A[3] - s * s) <= 8 * EPS))
            pair23 = 0;
    }
    CHECKF(nonneg, "every A_l >= 0 on [0, pi/2]");
    CHECKF(pou, "sum A_l = 1 on [0, pi/2]");
    CHECKF(pair01, "A0 + A1 = c^2");
    CHECKF(pair23, "A2 + A3 = s^2");
    CHECKF(vs_ref, "basis = docs/method.md §2 definitions");
    for (int k = -200; k <= 200; k++) { /* θ in [-2π, 2π]: extension */
        double t = 0.01 * TH_PI * k, A[4], R[4];
        lib_basis(t, A);
        th_basis(t, R);
        for (int l = 0; l < 4; l++)
            CHECK_CLOSE(A[l], R[l], 8 * EPS * M0);
        CHECK_CLOSE(A[0] + A[1] + A[2] + A[3], 1.0, 8 * EPS * M0);
    }

    TH_CASE("end values");
    /* End values: A0(0) = A3(π/2) = 1, all other ends 0 (exact s, c). */
    {
        double A[4];
        ts__basis(0.0, 1.0, A);
        CHECK(A[0] == 1.0 && A[1] == 0.0 && A[2] == 0.0 && A[3] == 0.0);
        ts__basis(1.0, 0.0, A);
        CHECK(A[0] == 0.0 && A[1] == 0.0 && A[2] == 0.0 && A[3] == 1.0);
        /* derivatives at the ends (docs/method.md §2 formulas): A'(0) = (-3, 3, 0, 0),
         * A'(π/2) = (0, 0, -3, 3) */
        ts__basis_d1(0.0, 1.0, A);
        CHECK(A[0] == -3.0 && A[1] == 3.0 && A[2] == 0.0 && A[3] == 0.0);
        ts__basis_d1(1.0, 0.0, A);
        CHECK(A[0] == 0.0 && A[1] == 0.0 && A[2] == -3.0 && A[3] == 3.0);
    }

    TH_CASE("derivatives");
    /* First derivatives: vs the docs/method.md formulas and vs central differences
     * (h = 1e-5: h²/6·M3 + 4ε·M0/h = 4.4e-10 + 7.1e-10 -> 1.2e-9).  Second
     * derivatives: vs the hand-derived formulas and vs central differences of
     * the library's first derivative (h²/6·M4 + 4ε·M1/h = 9.3e-10 + 7.6e-10). */
    {
        const double h = 1e-5;
        const double tol1 = h * h / 6 * M3 + 4 * EPS * M0 / h;
        const double tol2 = h * h / 6 * M4 + 4 * EPS * M1 / h;
        int ok_f1 = 1, ok_fd1 = 1, ok_f2 = 1, ok_fd2 = 1;
        double worst1 = 0, worst2 = 0;
        for (int k = -100; k <= 600; k++) { /* θ from -π/2·0.2 to π/2·1.2 */
            double t = HP * k / 500.0, D1[4], D2[4], R1[4], R2[4], P[4], Q[4], P1[4], Q1[4];
            lib_basis_d1(t, D1);
            lib_basis_d2(t, D2);
            th_basis_d1(t, R1);
            th_basis_d2(t, R2);
            lib_basis(t + h, P);
            lib_basis(t - h, Q);
            lib_basis_d1(t + h, P1);
            lib_basis_d1(t - h, Q1);
            for (int l = 0; l < 4; l++) {
                double fd1 = (P[l] - Q[l]) / (2 * h), fd2 = (P1[l] - Q1[l]) / (2 * h);
                if (!(fabs(D1[l] - R1[l]) <= 16 * EPS * M1))
                    ok_f1 = 0;
                if (!(fabs(D2[l] - R2[l]) <= 32 * EPS * 16.75))
                    ok_f2 = 0;
                if (!(fabs(D1[l] - fd1) <= tol1))
                    ok_fd1 = 0;
                if (!(fabs(D2[l] - fd2) <= tol2))
                    ok_fd2 = 0;
                if (fabs(D1[l] - fd1) > worst1)
                    worst1 = fabs(D1[l] - fd1);
                if (fabs(D2[l] - fd2) > worst2)
                    worst2 = fabs(D2[l] - fd2);
            }
        }
        CHECKF(ok_f1, "A' = docs/method.md §2 formulas");
        CHECKF(ok_fd1, "A' vs finite differences: worst %.3g, tol %.3g", worst1, tol1);
        CHECKF(ok_f2, "A'' = hand-derived formulas");
        CHECKF(ok_fd2, "A'' vs finite differences: worst %.3g, tol %.3g", worst2, tol2);
        /* Sum of derivatives is 0 (partition of unity). */
        double D[4];
        lib_basis_d1(0.7, D);
        CHECK_CLOSE(D[0] + D[1] + D[2] + D[3], 0.0, 16 * EPS * M1);
        lib_basis_d2(0.7, D);
        CHECK_CLOSE(D[0] + D[1] + D[2] + D[3], 0.0, 32 * EPS * 16.75);
    }

    TH_CASE("integrals");
    /* Integrals ∫_0^θ A_l vs Gauss–Legendre (error < 1e-29 + rounding;
     * tolerance 1e-14 covers the closed form's cancellation, which is a few
     * ulp of θ·M0), and the exact values on [0, π/2] derived by hand:
     * ∫A0 = ∫A3 = 5π/4 - 11/3, ∫A1 = ∫A2 = 11/3 - π. */
    {
        int ok = 1;
        double worst = 0;
        for (int k = 0; k <= 400; k++) {
            double t = HP * k / 400.0, I[4], G[4];
            if (k == 1)
                t = 1e-7; /* tiny θ: cancellation territory */
            ts__basis_int(t, sin(t), cos(t), I);
            gl_int(t, G);
            for (int l = 0; l < 4; l++) {
                double e = fabs(I[l] - G[l]);
                if (!(e <= 1e-14))
                    ok = 0;
                if (e > worst)
                    worst = e;
            }
        }
        CHECKF(ok, "basis integrals vs Gauss-Legendre: worst %.3g", worst);
        double I[4];
        ts__basis_int(HP, 1.0, 0.0, I);
        CHECK_CLOSE(I[0], 5 * TH_PI / 4 - 11.0 / 3, 4e-16 * 8);
        CHECK_CLOSE(I[1], 11.0 / 3 - TH_PI, 4e-16 * 8);
        CHECK_CLOSE(I[2], 11.0 / 3 - TH_PI, 4e-16 * 8);
        CHECK_CLOSE(I[3], 5 * TH_PI / 4 - 11.0 / 3, 4e-16 * 8);
        ts__basis_int(0.0, 0.0, 1.0, I);
        CHECK(I[0] == 0 && I[1] == 0 && I[2] == 0 && I[3] == 0);
        /* ∫ (A0 + A1) = ∫ c² = θ/2 + sin2θ/4 */
        double t = 0.9;
        ts__basis_int(t, sin(t), cos(t), I);
        CHECK_CLOSE(I[0] + I[1], t / 2 + sin(2 * t) / 4, 1e-15);
        CHECK_CLOSE(I[2] + I[3], t / 2 - sin(2 * t) / 4, 1e-15);
    }

    TH_CASE("seg_theta");
    /* ts__seg_theta: S = Σ A_l B_l, dS/dθ = (2.1), d²S/dθ² vs finite
     * differences of dS/dθ, for random control values and θ in and outside
     * [0, π/2].  Rounding tolerance: 16ε·(Σ|A_l|)·max|B| with Σ|A_l| <= 4·M0
     * (any θ).  FD of S' (h = 1e-5): h²/6·max|S''''| + 4ε·max|S'|/h with
     * max|S''''| <= 4·M4·max|B|, max|S'| <= 4·M1·max|B|. */
    {
        th_rng gen = TH_RNG_INIT(12345u);
        int ok0 = 1, ok1 = 1, ok2 = 1, okw = 1;
        double w0 = 0, w1 = 0, w2 = 0;
        for (int trial = 0; trial < 300; trial++) {
            double B[4], mb = 0;
            for (int l = 0; l < 4; l++) {
                B[l] = th_rng_range(&gen, -10.0, 10.0);
                if (fabs(B[l]) > mb)
                    mb = fabs(B[l]);
            }
            double t = -0.6 + 2.8 * trial / 299.0; /* [-0.6, 2.2] */
            double s = sin(t), c = cos(t), R[4], out[3];
            th_basis(t, R);
            double S = R[0] * B[0] + R[1] * B[1] + R[2] * B[2] + R[3] * B[3];
            /* docs/method.md (2.1) typed from the text */
            double dS = th_seg_d1(B, t);
            double R1[4];
            th_basis_d1(t, R1);
            double dS2 = R1[0] * B[0] + R1[1] * B[1] + R1[2] * B[2] + R1[3] * B[3];
            const double h = 1e-5;
            double op[3], om[3];
            ts__seg_theta(B, t, 2, out);
            ts__seg_theta(B, t + h, 1, op);
            ts__seg_theta(B, t - h, 1, om);
            double fd2 = (op[1] - om[1]) / (2 * h);
            double tr = 16 * EPS * 4 * M0 * mb;
            double tfd = h * h / 6 * 4 * M4 * mb + 4 * EPS * 4 * M1 * mb / h;
            if (!(fabs(out[0] - S) <= tr))
                ok0 = 0;
            if (!(fabs(out[1] - dS) <= tr))
                ok1 = 0;
            if (!(fabs(dS - dS2) <= tr)) /* (2.1) = Σ A_l' B_l: checks the text of docs/method.md too */
                okw = 0;
            if (!(fabs(out[2] - fd2) <= tfd))
                ok2 = 0;
            if (fabs(out[0] - S) / mb > w0)
                w0 = fabs(out[0] - S) / mb;
            if (fabs(out[1] - dS) / mb > w1)
                w1 = fabs(out[1] - dS) / mb;
            if (fabs(out[2] - fd2) / mb > w2)
                w2 = fabs(out[2] - fd2) / mb;
            /* (2.1) weights are >= 0 on [0, π/2] */
            if (t >= 0 && t <= HP)
                CHECK(3 * (1 - s) * (1 - s) * c >= 0 && 2 * s * c >= 0 && 3 * (1 - c) * (1 - c) * s >= 0);
        }
        CHECKF(ok0, "seg_theta value = sum A_l B_l (worst %.3g rel)", w0);
        CHECKF(ok1, "seg_theta dS/dtheta = (2.1) (worst %.3g rel)", w1);
        CHECKF(okw, "(2.1) = sum A_l' B_l");
        CHECKF(ok2, "seg_theta d2S/dtheta2 vs FD (worst %.3g rel)", w2);
        /* want = 0 and 1 must not need out[1], out[2]; values match want = 2 */
        double B[4] = {1.5, -2.0, 3.25, 0.5}, o0[3] = {0, 0, 0}, o2[3];
        ts__seg_theta(B, 0.3, 0, o0);
        ts__seg_theta(B, 0.3, 2, o2);
        CHECK(o0[0] == o2[0]);
        /* end values: S(0) = B0, S(π/2) = B3 up to rounding of cos(π/2) */
        ts__seg_theta(B, 0.0, 2, o2);
        CHECK_CLOSE(o2[0], B[0], 4 * EPS * 4);
        CHECK_CLOSE(o2[1], 3 * (B[1] - B[0]), 4 * EPS * 30);
        ts__seg_theta(B, HP, 2, o2);
        CHECK_CLOSE(o2[0], B[3], 4 * EPS * 4);
        CHECK_CLOSE(o2[1], 3 * (B[3] - B[2]), 4 * EPS * 30);
    }
    return th_report("test_basis");
}
