/* Exact signs for checks against a region with zero tolerance (tests and
 * fuzz harnesses): the sign of a sum of doubles, and the side of a value
 * relative to a line m x + c or a plane p x + q y + c, whose products are
 * split exactly by fma (a x = P + e).  The sum is accumulated as one big
 * integer in units of 2^-1074 (every double is an integer multiple of it),
 * not by the library's expansion sum (src/shape.c, ts__exact_sign): a
 * different method, so the two cannot share a mistake. */
#ifndef TS_TH_EXACT_H
#define TS_TH_EXACT_H
#include <math.h>

#define TH_EXACT_TERMS 8
/* limbs of 32 bits from 2^-1074 up: |v| <= 2^1020 needs 1074 + 1021 bits,
 * plus carries of at most TH_EXACT_TERMS terms */
#define TH_EXACT_LIMBS 68

/* sign of v[0] + ... + v[n-1] exactly, every |v| <= 2^1020; n <= 2^20 (the
 * limbs' headroom: each term adds below 2^33 to a limb) */
static inline int th_exact_sign(const double *v, int n)
{
    long long L[TH_EXACT_LIMBS] = {0};
    for (int j = 0; j < n; j++) {
        if (v[j] == 0.0)
            continue;
        int e;
        double fr = frexp(v[j], &e);                    /* v = fr 2^e, 1/2 <= |fr| < 1 */
        long long m = (long long)ldexp(fabs(fr), 53);   /* exact, < 2^53 */
        int at = e - 53 + 1074;                         /* v = ±m 2^(at - 1074) */
        if (at < 0) {                                   /* subnormal: m has that many low zeros */
            m /= 1LL << -at;
            at = 0;
        }
        long long sg = v[j] < 0.0 ? -1 : 1;
        unsigned long long lo = ((unsigned long long)m & 0xffffffffULL) << (at % 32);
        unsigned long long hi = ((unsigned long long)m >> 32) << (at % 32);
        int k = at / 32;
        L[k] += sg * (long long)(lo & 0xffffffffULL);
        L[k + 1] += sg * (long long)((lo >> 32) + (hi & 0xffffffffULL));
        L[k + 2] += sg * (long long)(hi >> 32);
    }
    /* carries: every limb but the top one into [0, 2^32) */
    for (int k = 0; k + 1 < TH_EXACT_LIMBS; k++) {
        long long q = L[k] / 4294967296LL, r = L[k] - q * 4294967296LL;
        if (r < 0) {
            r += 4294967296LL;
            q -= 1;
        }
        L[k] = r;
        L[k + 1] += q;
    }
    if (L[TH_EXACT_LIMBS - 1] != 0)
        return L[TH_EXACT_LIMBS - 1] > 0 ? 1 : -1;
    for (int k = TH_EXACT_LIMBS - 2; k >= 0; k--)
        if (L[k] != 0)
            return 1;
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
/* zero, or 2^-300 <= |v| <= 2^300: products of three such values and of
 * their rounding errors neither overflow nor underflow */
static inline int th_exact_tame(double v)
{
    double a = fabs(v);
    return a == 0.0 || (0x1p-300 <= a && a <= 0x1p300);
}

/* the sign of v − F(x, y), F bilinear on the cell [X0, X1] × [Y0, Y1] with
 * corner values z00 (X0, Y0), z10, z01, z11, exact: hx hy (v − F) =
 * Σ_c (v − z_c) wx_c wy_c with wx the distances to the opposite lines, each
 * factor an exact sum of two doubles (TwoSum), each triple product split
 * into four doubles (fma), summed by th_exact_sign; 2 where undecidable (an
 * input outside th_exact_tame) */
static inline int th_bilinear_side(double v, double x, double y, double X0, double X1, double Y0,
                                   double Y1, double z00, double z10, double z01, double z11)
{
    double in[11] = {v, x, y, X0, X1, Y0, Y1, z00, z10, z01, z11};
    for (int k = 0; k < 11; k++)
        if (!th_exact_tame(in[k]))
            return 2;
    double w[2][2][2], d[2]; /* w[axis][side] = two terms */
    double ax[2][2] = {{X1, x}, {x, X0}}, ay[2][2] = {{Y1, y}, {y, Y0}};
    for (int s = 0; s < 2; s++) {
        double a = ax[s][0], b = -ax[s][1], t = a + b, z = t - a;
        w[0][s][0] = t;
        w[0][s][1] = (a - (t - z)) + (b - z);
        a = ay[s][0], b = -ay[s][1], t = a + b, z = t - a;
        w[1][s][0] = t;
        w[1][s][1] = (a - (t - z)) + (b - z);
    }
    double zc[2][2] = {{z00, z01}, {z10, z11}}; /* [cx][cy] */
    double terms[128];
    int n = 0;
    for (int cx = 0; cx < 2; cx++)
        for (int cy = 0; cy < 2; cy++) {
            double a = v, b = -zc[cx][cy], t = a + b, z = t - a;
            d[0] = t;
            d[1] = (a - (t - z)) + (b - z);
            for (int i = 0; i < 2; i++)
                for (int j = 0; j < 2; j++)
                    for (int k = 0; k < 2; k++) {
                        double p = d[i], q = w[0][cx][j], r = w[1][cy][k];
                        double P = p * q, e = fma(p, q, -P);
                        double P1 = P * r, e1 = fma(P, r, -P1), P2 = e * r, e2 = fma(e, r, -P2);
                        terms[n++] = P1;
                        terms[n++] = e1;
                        terms[n++] = P2;
                        terms[n++] = e2;
                    }
        }
    return th_exact_sign(terms, n);
}
#endif
