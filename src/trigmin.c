/* docs/method.md §2, §5: the exact minimum of a degree-3 trigonometric polynomial
 * minus a linear function, with its rounding guard.
 *
 * Minimum of g(θ) = Σ A_l(θ) C_l − κθ on [0, π/2].  With t = tan(θ/2) in
 * [0, 1]: s = 2t/q, c = (1−t²)/q, 1−s = (1−t)²/q, 1−c = 2t²/q (q = 1+t²),
 * so every A_l is a product of non-negative factors computed without
 * cancellation, and (docs/method.md (2.1))
 *   P(t) = q³ g'(θ) = 3D0 (1−t)⁵(1+t) + 4D1 t(1−t⁴) + 24D2 t⁵ − κ q³,
 * D_l = C_{l+1} − C_l, a polynomial of degree ≤ 6.  Its Bernstein
 * coefficients on [0, 1] are (exact rationals, derived by hand and checked
 * with Python fractions):
 *   3D0 − κ, D0 + 2D1/3 − κ, 4D1/3 − 6κ/5, 2D1 − 8κ/5, 8D1/3 − 12κ/5,
 *   8D1/3 + 4D2 − 4κ, 24D2 − 8κ.
 * Roots are isolated by Bernstein subdivision (Descartes' rule of signs:
 * 0 sign changes = no root, 1 = exactly one, bracketed and refined by
 * safeguarded Newton on the factored P), then g is evaluated at 0, 1 and
 * every root; the least value is the minimum.  Only roots where P goes from
 * − to + (minima of g) are refined: a maximum is never the least candidate.
 * When the control polygon is monotone and κ has the other sign, g is
 * monotone ((2.1)): no root, the minimum is at an end; that path (and that
 * of no − before + among the coefficients) is also taken for a block of
 * intervals at once by certificate.c, with the same operations.
 *
 * Rounding guard (ε = DBL_EPSILON, i.e. twice the unit roundoff).  Inputs
 * are scaled by a power of two (exact).  Three error sources:
 *  (1) g at a candidate: each A_l comes from ≤ 8 roundings of non-negative
 *      quantities (≤ 10ε relative), the 4 products and 3 sums add ≤ 4ε,
 *      θ = 2 atan t ≤ 2ε: |ĝ − g| ≤ 16ε (max|C| + |κ| π/2).
 *  (2) a sign of P decided wrongly where |P̂ − P| ≤ η: there |g'| ≤ η/q³
 *      and dθ = 2dt/q, so an undetected dip of g is at most 2η.  The
 *      coefficients carry ≤ 6ε Σ|terms| =: 6ε·babs, each subdivision level
 *      ≤ 6 more roundings of magnitude ≤ babs: η ≤ (6L + 6) ε babs at depth L.
 *  (3) root location: brackets end below 4ε in t; the value error is
 *      ≤ ½ max|g''| (8ε)² (negligible against (1), since |g''| ≤ 40 max|C|).
 * guard = 2 × [(1) + 2η] (factor 2 for second-order terms).  The interval
 * certificate (certificate.c, docs/method.md §5.6 items 4–7) adds the
 * rounding of C_l = ±(B_l − L_i), L_i = fma(m, x_i, c), of κ = ±2mh/π and
 * of where evaluation places x: 8ε (max|B| + |L_i| + |m| h) + |m| err(h).
 */
#include "internal.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>


typedef struct tm_ctx {
    double D0, D1, D2, k; /* scaled differences and κ */
    double c[4];          /* scaled C_l */
    double best, bt;      /* least g so far and its t */
    int depth;            /* deepest subdivision level reached */
} tm_ctx;

/* A candidate t (a root of P, a deep leaf's or a split point): g there,
 * kept if below the least so far (ts__basis_t is exact at t = 0 and 1). */
static void add_cand(tm_ctx *z, double t)
{
    double A[4];
    ts__basis_t(t, A);
    double g = A[0] * z->c[0] + A[1] * z->c[1] + A[2] * z->c[2] + A[3] * z->c[3];
    if (z->k != 0.0)
        g -= z->k * ts__theta_of(t);
    if (g < z->best) {
        z->best = g;
        z->bt = t;
    }
}

/* P(t) = q³ g'(θ) in factored form (each term has small relative error). */
static double p_eval(const tm_ctx *z, double t)
{
    double omt = 1.0 - t, opt = 1.0 + t, q = 1.0 + t * t;
    double o2 = omt * omt, t2 = t * t;
    return 3.0 * z->D0 * (o2 * o2 * omt) * opt + 4.0 * z->D1 * t * omt * opt * q +
           24.0 * z->D2 * (t2 * t2 * t) - z->k * (q * q * q);
}

static int sgn(double v)
{
    return (v > 0.0) - (v < 0.0);
}

/* de Casteljau at 1/2: b on [lo, hi] into l on [lo, mid], r on [mid, hi];
 * written out (level k, entry j: wkj; no array shuffling through memory). */
static void casteljau(const double b[7], double l[7], double r[7])
{
#define TM_AV(p, q) (0.5 * ((p) + (q)))
    double w10 = TM_AV(b[0], b[1]), w11 = TM_AV(b[1], b[2]), w12 = TM_AV(b[2], b[3]),
           w13 = TM_AV(b[3], b[4]), w14 = TM_AV(b[4], b[5]), w15 = TM_AV(b[5], b[6]);
    double w20 = TM_AV(w10, w11), w21 = TM_AV(w11, w12), w22 = TM_AV(w12, w13),
           w23 = TM_AV(w13, w14), w24 = TM_AV(w14, w15);
    double w30 = TM_AV(w20, w21), w31 = TM_AV(w21, w22), w32 = TM_AV(w22, w23),
           w33 = TM_AV(w23, w24);
    double w40 = TM_AV(w30, w31), w41 = TM_AV(w31, w32), w42 = TM_AV(w32, w33);
    double w50 = TM_AV(w40, w41), w51 = TM_AV(w41, w42);
    double w60 = TM_AV(w50, w51);
#undef TM_AV
    l[0] = b[0], l[1] = w10, l[2] = w20, l[3] = w30, l[4] = w40, l[5] = w50, l[6] = w60;
    r[0] = w60, r[1] = w51, r[2] = w42, r[3] = w33, r[4] = w24, r[5] = w15, r[6] = b[6];
}

/* P (exactly as p_eval) and P' = −6D0(1−t)⁴(2+3t) + 4D1(1−5t⁴) + 120D2 t⁴
 * − 6κt q² (derived by hand, checked with sympy) at t. */
static double p_eval_d(const tm_ctx *z, double t, double *dp)
{
    double omt = 1.0 - t, opt = 1.0 + t, q = 1.0 + t * t;
    double o2 = omt * omt, t2 = t * t, t4 = t2 * t2;
    *dp = -6.0 * z->D0 * (o2 * o2) * (2.0 + 3.0 * t) + 4.0 * z->D1 * (1.0 - 5.0 * t4) +
          120.0 * z->D2 * t4 - 6.0 * z->k * t * (q * q);
    return 3.0 * z->D0 * (o2 * o2 * omt) * opt + 4.0 * z->D1 * t * omt * opt * q +
           24.0 * z->D2 * (t2 * t2 * t) - z->k * (q * q * q);
}

/* One root of P in (lo, hi); sign of P just right of lo is s.  Newton's
 * method inside the bracket, which every evaluation narrows; bisection when a
 * step would leave the bracket or is not below half the step before the last
 * (Numerical Recipes' rtsafe).  It ends, as plain bisection would, with a
 * bracket below 4ε: once a step is below 2^-30 the next iterate is within
 * ~step² (far below ε) of the root unless P'' is huge, and the points 2ε
 * either side of it close the bracket (if not, the search goes on). */
static void refine(tm_ctx *z, const double b[7], double lo, double hi, int s)
{
    const double w = 4.0 * DBL_EPSILON;
    /* start where the Bernstein polygon b (on [lo, hi]) crosses zero */
    double t = 0.5 * (lo + hi), step = hi - lo, step_old = hi - lo;
    for (int j = 0; j < 6; j++) {
        if (b[j] < 0.0 && b[j + 1] > 0.0) { /* the only sign change: from − (s) to + */
            double u = (j + b[j] / (b[j] - b[j + 1])) / 6.0, c = lo + (hi - lo) * u;
            if (c > lo && c < hi)
                t = c;
            break;
        }
    }
    for (int it = 0; it < TS_LIMIT(trigmin_steps) && hi - lo > w; it++) {
        double dp, f = p_eval_d(z, t, &dp);
        int sf = sgn(f);
        if (sf == 0) {
            lo = hi = t;
            break;
        }
        if (sf == s)
            lo = t;
        else
            hi = t;
        double nt = t - f / dp, dn = fabs(nt - t);
        if (dn <= 0x1p-30 && nt >= lo && nt <= hi) {
            double pa = nt - 0.5 * w, pb = nt + 0.5 * w;
            if (pa > lo) {
                int sa = sgn(p_eval(z, pa));
                if (sa == 0) {
                    lo = hi = pa;
                    break;
                }
                if (sa == s)
                    lo = pa;
                else
                    hi = pa;
            }
            if (pb < hi) {
                int sb = sgn(p_eval(z, pb));
                if (sb == 0) {
                    lo = hi = pb;
                    break;
                }
                if (sb == s)
                    lo = pb;
                else
                    hi = pb;
            }
            nt = 0.5 * (lo + hi);
            step = step_old = hi - lo;
        } else if (!(nt > lo && nt < hi && dn <= 0.5 * step_old)) { /* NaN: bisect too */
            nt = 0.5 * (lo + hi);
            step_old = step;
            step = 0.5 * (hi - lo);
        } else {
            step_old = step;
            step = dn;
        }
        t = nt;
    }
    add_cand(z, 0.5 * (lo + hi));
}

static void isolate(tm_ctx *z, const double b[7], double lo, double hi, int depth)
{
    int var = 0, first = 0, last = 0;
    for (int j = 0; j < 7; j++) { /* sign changes, zeros skipped (branch-free) */
        int s = sgn(b[j]);
        var += (s != 0) & (last != 0) & (s != last);
        first = first != 0 ? first : s;
        last = s != 0 ? s : last;
    }
    if (var == 0)
        return;
    if (depth > z->depth)
        z->depth = depth;
    if (var == 1) {
        /* one simple root: a minimum of g only where P goes from - to +; a
         * maximum (P from + to -) is never below both its neighbouring
         * candidates (ends, minima), so it is not refined */
        if (first < 0)
            refine(z, b, lo, hi, first);
        return;
    }
    double mid = 0.5 * (lo + hi);
    if (depth >= TS_LIMIT(trigmin_depth)) {
        add_cand(z, mid);
        return;
    }
    double l[7], r[7];
    casteljau(b, l, r);
    if (l[6] == 0.0)
        add_cand(z, mid);
    isolate(z, l, lo, mid, depth + 1);
    isolate(z, r, mid, hi, depth + 1);
}

/* Basis at t = tan(θ/2) (docs/method.md §2), cancellation-free. */
void ts__basis_t(double t, double A[4])
{
    double t2 = t * t, q = 1.0 + t2;
    double s = 2.0 * t / q, c = (1.0 - t) * (1.0 + t) / q;
    double u = (1.0 - t) * (1.0 - t) / q, v = 2.0 * t2 / q;
    A[0] = u * u * u;
    A[1] = s * u * (2.0 + u);
    A[2] = c * v * (2.0 + v);
    A[3] = v * v * v;
}

double ts__theta_of(double t)
{
    return t >= 1.0 ? TS_HALF_PI : t == 0.0 ? 0.0 : 2.0 * atan(t); /* 2 atan 0 = 0 */
}

/* frexp's exponent of a finite M > 0 (the call only for a subnormal M). */
static int exponent_of(double M)
{
    uint64_t u;
    memcpy(&u, &M, sizeof u);
    int field = (int)((u >> 52) & 0x7ff);
    if (field == 0) {
        int e;
        (void)frexp(M, &e);
        return e;
    }
    return field - 1022;
}

/* ldexp(x, k): one correctly rounded product by 2^k where 2^k is normal. */
static double scale2(double x, int k)
{
    if (k >= -1022 && k <= 1023) {
        uint64_t u = (uint64_t)(k + 1023) << 52;
        double p;
        memcpy(&p, &u, sizeof p);
        return x * p;
    }
    return ldexp(x, k);
}

/* Exact min of g; *tbest its t, *theta (if not NULL) its θ, *errb the
 * rounding guard (unscaled). */
double ts__trig_min_core(double C0, double C1, double C2, double C3, double kappa, double *theta,
                        double *tbest, double *errb)
{
    /* scalars, not an array: a vector load of two separately stored
     * elements stalls store forwarding */
    double m0 = fabs(C0), m1 = fabs(C1), m2 = fabs(C2), m3 = fabs(C3), M = fabs(kappa);
    if (!((m0 <= DBL_MAX) & (m1 <= DBL_MAX) & (m2 <= DBL_MAX) & (m3 <= DBL_MAX) & (M <= DBL_MAX))) {
        if (theta)
            *theta = (double)NAN;
        *tbest = *errb = (double)NAN;
        return (double)NAN;
    }
    M = m0 > M ? m0 : M;
    M = m1 > M ? m1 : M;
    M = m2 > M ? m2 : M;
    M = m3 > M ? m3 : M;
    if (M == 0.0) {
        if (theta)
            *theta = 0.0;
        *tbest = *errb = 0.0;
        return 0.0;
    }
    int e = exponent_of(M);
    double c0, c1, c2, c3, ks, Ms;
    if (e >= -1021 && e <= 1022) { /* 2^-e normal: one factor for all (as ldexp) */
        double p = scale2(1.0, -e);
        c0 = C0 * p, c1 = C1 * p, c2 = C2 * p, c3 = C3 * p, ks = kappa * p, Ms = M * p;
    } else {
        c0 = scale2(C0, -e), c1 = scale2(C1, -e), c2 = scale2(C2, -e), c3 = scale2(C3, -e);
        ks = scale2(kappa, -e), Ms = scale2(M, -e);
    }
    tm_ctx z;
    z.D0 = c1 - c0;
    z.D1 = c2 - c1;
    z.D2 = c3 - c2;
    z.k = ks;
    z.c[0] = c0, z.c[1] = c1, z.c[2] = c2, z.c[3] = c3;
    z.depth = 0;
    double b[7], babs, at1;
    int ends = ts__trig_min_ends(c0, c1, c2, c3, ks, b, &z.best, &at1, &babs);
    z.bt = at1;
    if (!ends) /* the roots: candidates after the two ends */
        isolate(&z, b, 0.0, 1.0, 0);
    double gd = ts__trig_min_guard(z.depth, babs, Ms, fabs(ks));
    *tbest = z.bt;
    if (theta)
        *theta = ts__theta_of(z.bt);
    *errb = scale2(gd, e);
    return scale2(z.best, e);
}

double ts__trig_min(const double C[4], double kappa, double *theta_min)
{
    double t, eb;
    return ts__trig_min_core(C[0], C[1], C[2], C[3], kappa, theta_min, &t, &eb);
}

