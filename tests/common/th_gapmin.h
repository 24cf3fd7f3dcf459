/* The minimum of an interval's gap to a line, re-derived in long double for
 * tests (docs/method.md §2, §5.6): g(θ) = Σ A_l C_l − κ θ on [0, π/2], with
 * C_l the control values minus the line at the interval's left knot (sign
 * applied) and κ = ±m·2h/π.  An n-point grid (n <= 4096), each grid point
 * not above its neighbours (ends included: a dip narrower than a grid step
 * next to a knot is common) refined by golden section on its two grid steps
 * to 1e-15 in θ.  The result is a value g attains, so the true minimum is
 * not above it; that it is not below is what comparing with the library's
 * root isolation (an independent method) checks. */
#ifndef TH_GAPMIN_H
#define TH_GAPMIN_H

#include <math.h>

#define TH_LPI 3.141592653589793238462643383279502884L

static inline long double th_gap_at(const long double C[4], long double kappa, long double th)
{
    long double s = sinl(th), c = cosl(th);
    long double A0 = (1 - s) * (1 - s) * (1 - s), A1 = s * (1 - s) * (3 - s);
    long double A2 = c * (1 - c) * (3 - c), A3 = (1 - c) * (1 - c) * (1 - c);
    return A0 * C[0] + A1 * C[1] + A2 * C[2] + A3 * C[3] - kappa * th;
}

static inline long double th_gap_golden(const long double C[4], long double kappa, long double a,
                                        long double b)
{
    const long double r = 0.6180339887498948482L;
    long double u1 = b - r * (b - a), u2 = a + r * (b - a);
    long double g1 = th_gap_at(C, kappa, u1), g2 = th_gap_at(C, kappa, u2);
    while (b - a > 1e-15L) {
        if (g1 < g2) {
            b = u2, u2 = u1, g2 = g1;
            u1 = b - r * (b - a);
            g1 = th_gap_at(C, kappa, u1);
        } else {
            a = u1, u1 = u2, g1 = g2;
            u2 = a + r * (b - a);
            g2 = th_gap_at(C, kappa, u2);
        }
    }
    return g1 < g2 ? g1 : g2;
}

static inline long double th_gap_min(const long double C[4], long double kappa, int n)
{
    long double w = TH_LPI / 2 / n, g[4097], best = HUGE_VALL;
    for (int k = 0; k <= n; k++) {
        g[k] = th_gap_at(C, kappa, k == n ? TH_LPI / 2 : w * k);
        best = g[k] < best ? g[k] : best;
    }
    for (int k = 0; k <= n; k++)
        if ((k == 0 || g[k] <= g[k - 1]) && (k == n || g[k] <= g[k + 1])) {
            long double v = th_gap_golden(C, kappa, k > 0 ? w * (k - 1) : 0.0L,
                                          k < n ? w * (k + 1) : TH_LPI / 2);
            best = v < best ? v : best;
        }
    return best;
}

#endif
