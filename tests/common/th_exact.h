/* Exact signs for checks against a region with zero tolerance (tests and
 * fuzz harnesses): the sign of a sum of doubles (Shewchuk's expansion sum:
 * TwoSum keeps every rounding error, the largest nonzero component of the
 * nonoverlapping result has the sum's sign), and the side of a value
 * relative to a line m x + c or a plane p x + q y + c, whose products are
 * split exactly by fma (a x = P + e).  Independent of the library's own
 * version (src/shape.c). */
#ifndef TS_TH_EXACT_H
#define TS_TH_EXACT_H
#include <math.h>

#define TH_EXACT_TERMS 8

/* sign of v[0] + ... + v[n-1] exactly, n <= TH_EXACT_TERMS, every |v| <= 2^1020 */
static inline int th_exact_sign(const double *v, int n)
{
    double e[TH_EXACT_TERMS];
    int k = 0;
    for (int j = 0; j < n; j++) {
        double q = v[j];
        for (int l = 0; l < k; l++) {
            double s = q + e[l], z = s - q;
            e[l] = (q - (s - z)) + (e[l] - z);
            q = s;
        }
        e[k++] = q;
    }
    for (int l = k - 1; l >= 0; l--)
        if (e[l] != 0.0)
            return (e[l] > 0.0) - (e[l] < 0.0);
    return 0;
}

/* a x = t[0] + t[1] exactly; 0 where that cannot be decided (a product
 * beyond 2^1020, or below 2^-960 where the fma error may be inexact) */
static inline int th_exact_split(double a, double x, double *t)
{
    double P = a * x;
    if (!(fabs(P) <= 0x1p1020) || (fabs(P) < 0x1p-960 && a != 0.0 && x != 0.0))
        return 0;
    t[0] = P;
    t[1] = fma(a, x, -P);
    return 1;
}

/* the sign of z − (p x + q y + c), exact; 2 where undecidable (a term out
 * of range: the caller counts it, it is not a check) */
static inline int th_plane_side(double z, double p, double q, double c, double x, double y)
{
    double t[6];
    if (!th_exact_split(p, x, t) || !th_exact_split(q, y, t + 2) || !(fabs(c) <= 0x1p1020) ||
        !(fabs(z) <= 0x1p1020))
        return 2;
    for (int k = 0; k < 4; k++)
        t[k] = -t[k];
    t[4] = -c;
    t[5] = z;
    return th_exact_sign(t, 6);
}
#endif
