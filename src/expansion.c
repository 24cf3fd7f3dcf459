/* Exact arithmetic on expansions (Shewchuk 1997): a value kept as a sum of
 * doubles of increasing magnitude that do not overlap, so that its sign is
 * that of its largest nonzero component.  The exact sides of a line or
 * plane (docs/method.md §5.8, §11.3), of a gridded field (§11.7) and the
 * constraint records' certificates (§13.4).
 *
 * Zero components are kept, not eliminated (Shewchuk's zero elimination
 * only shortens an expansion): a zero component leaves every step below
 * unchanged (TwoSum(Q, 0) = (Q, 0), and a zero factor's product and its
 * rounding error are 0), so the nonzero components, and the sign, are those
 * of the eliminated form, and every step is the same arithmetic whatever
 * the values.  The lengths are then fixed: grow n -> n + 1, scale n -> 2n,
 * product n, m -> 2nm. */
#include "internal.h"

#include <math.h>

int ts__exp_grow(const double *e, int n, double b, double *h)
{
    double Q = b;
    for (int i = 0; i < n; i++) { /* TwoSum(Q, e_i) = Q' + h_i; e_i read before h_i is written */
        double ei = e[i], s = Q + ei, bv = s - Q;
        h[i] = (Q - (s - bv)) + (ei - bv);
        Q = s;
    }
    h[n] = Q;
    return n + 1;
}

int ts__exp_scale(const double *e, int n, double b, double *h)
{
    /* e_i b = p1 + p0 exactly (fma); Q + p0 by TwoSum, then p1 + s by
     * FastTwoSum (|p1| >= |s|: Shewchuk's Scale-Expansion) */
    double Q = e[0] * b;
    h[0] = fma(e[0], b, -Q);
    for (int i = 1; i < n; i++) {
        double p1 = e[i] * b, p0 = fma(e[i], b, -p1);
        double s = Q + p0, bv = s - Q;
        h[2 * i - 1] = (Q - (s - bv)) + (p0 - bv);
        Q = p1 + s;
        h[2 * i] = s - (Q - p1);
    }
    h[2 * n - 1] = Q;
    return 2 * n;
}

int ts__exp_product(const double *e, int n, const double *f, int m, double *h)
{
    double t[2 * TS_EXP_PRODUCT_MAX];
    int k = ts__exp_scale(e, n, f[0], h);
    for (int j = 1; j < m; j++) {
        int nt = ts__exp_scale(e, n, f[j], t);
        for (int l = 0; l < nt; l++)
            k = ts__exp_grow(h, k, t[l], h);
    }
    return k;
}

int ts__exp_sign(const double *e, int n)
{
    for (int l = n - 1; l >= 0; l--)
        if (e[l] != 0.0)
            return (e[l] > 0.0) - (e[l] < 0.0);
    return 0;
}

int ts__exact_sign(const double *v, int n)
{
    double e[TS_EXACT_TERMS];
    int k = 0;
    for (int j = 0; j < n; j++)
        k = ts__exp_grow(e, k, v[j], e);
    return ts__exp_sign(e, k);
}
