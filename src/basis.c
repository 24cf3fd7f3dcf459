/* docs/method.md §2: the cubic trigonometric basis, its derivatives and integrals. */
#include "internal.h"

#include <math.h>

/* 1 - s without cancellation near s = 1 (docs/method.md §2: 1 - s = c²/(1 + s)). */
static inline double one_minus(double s, double c)
{
    return ts__pick(s > 0.5, c * c / (1.0 + s), 1.0 - s);
}

void ts__basis(double s, double c, double A[4])
{
    double q[2]; /* one_minus(s, c), one_minus(c, s) with one division */
    ts__div2(c * c, 1.0 + s, s * s, 1.0 + c, q);
    double ms = ts__pick(s > 0.5, q[0], 1.0 - s), mc = ts__pick(c > 0.5, q[1], 1.0 - c);
    A[0] = ms * ms * ms;
    A[1] = s * ms * (3.0 - s);
    A[2] = c * mc * (3.0 - c);
    A[3] = mc * mc * mc;
}

void ts__basis_d1(double s, double c, double A[4])
{
    double ms = one_minus(s, c), mc = one_minus(c, s);
    A[0] = -3.0 * ms * ms * c;
    A[1] = c * (3.0 - 8.0 * s + 3.0 * s * s);
    A[2] = -s * (3.0 - 8.0 * c + 3.0 * c * c);
    A[3] = 3.0 * mc * mc * s;
}

void ts__basis_d2(double s, double c, double A[4])
{
    double ms = one_minus(s, c), mc = one_minus(c, s);
    A[0] = 6.0 * ms * c * c + 3.0 * ms * ms * s;
    A[1] = -s * (3.0 - 8.0 * s + 3.0 * s * s) + c * c * (6.0 * s - 8.0);
    A[2] = -c * (3.0 - 8.0 * c + 3.0 * c * c) + s * s * (6.0 * c - 8.0);
    A[3] = 6.0 * mc * s * s + 3.0 * mc * mc * c;
}

/* ∫_0^θ of s = 1 - c, s² = θ/2 - sc/2, s³ = (1-c)(2 - c - c²)/3,
 * c = s, c² = θ/2 + sc/2, c³ = s - s³/3; θ in [0, π/2]. */
void ts__basis_int(double theta, double s, double c, double I[4])
{
    double u = s * s / (1.0 + c); /* 1 - c */
    double sc = s * c;
    double is2 = 0.5 * (theta - sc), ic2 = 0.5 * (theta + sc);
    double is3 = u * (2.0 - c - c * c) / 3.0;
    double ic3 = s - s * s * s / 3.0;
    I[0] = theta - 3.0 * u + 3.0 * is2 - is3;
    I[1] = 3.0 * u - 4.0 * is2 + is3;
    I[2] = 3.0 * s - 4.0 * ic2 + ic3;
    I[3] = theta - 3.0 * s + 3.0 * ic2 - ic3;
}

void ts__seg_theta(const double B[4], double theta, int want, double out[3])
{
    ts__seg_sc(B, sin(theta), cos(theta), want, out);
}

void ts__seg_sc(const double B[4], double s, double c, int want, double out[3])
{
    ts__seg_scm(B, s, c, one_minus(s, c), one_minus(c, s), want, out);
}

size_t ts__search(const double *xs, size_t n, double x, ts_cursor *cur)
{
    if (cur) {
        size_t i = cur->interval;
        if (i < n && xs[i] <= x) {
            if (x < xs[i + 1] || (i + 1 == n))
                return i;
            /* sorted queries: try the next interval before searching
             * (i + 1 < n here) */
            if (x < xs[i + 2] || i + 2 == n) {
                cur->interval = i + 1;
                return i + 1;
            }
        }
    }
    /* largest i in [0, n-1] with xs[i] <= x */
    size_t lo = 0, hi = n; /* invariant: xs[lo] <= x, answer < hi */
    while (hi - lo > 1) {
        size_t mid = lo + (hi - lo) / 2;
        if (xs[mid] <= x)
            lo = mid;
        else
            hi = mid;
    }
    if (cur)
        cur->interval = lo;
    return lo;
}
