/* SPEC §2, §5: exact certificates (minimum of a degree-3 trigonometric
 * polynomial minus a linear function), the build-time repair of beta, and
 * the per-interval report.
 *
 * Minimum of g(θ) = Σ A_l(θ) C_l − κθ on [0, π/2].  With t = tan(θ/2) in
 * [0, 1]: s = 2t/q, c = (1−t²)/q, 1−s = (1−t)²/q, 1−c = 2t²/q (q = 1+t²),
 * so every A_l is a product of non-negative factors computed without
 * cancellation, and (SPEC (2.1))
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
 * of no − before + among the coefficients) is also written out for a block
 * of intervals at once (mono_certify), with the same operations.
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
 * certificate adds the rounding of C_l = ±(B_l − L(x_i)) and of
 * κ = ±2mh/π: 8ε (max|B| + |m|(|x_i| + h) + |c|).
 */
#include "internal.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#define TM_EPS DBL_EPSILON
#define TM_MAXC 48   /* candidate slots: ≤ 2 ends + 6 roots + 6 deep leaves (+ split points) */
#define TM_DEPTH 46  /* subdivision depth limit: width 2^-46 in t */
#define TS_CERT_BLOCK 256 /* intervals per mono_certify call */

typedef struct tm_ctx {
    double D0, D1, D2, k; /* scaled differences and κ */
    double t[TM_MAXC];
    int nc;
    int depth;            /* deepest subdivision level reached */
} tm_ctx;

static void add_cand(tm_ctx *z, double t)
{
    if (z->nc < TM_MAXC)
        z->t[z->nc++] = t;
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
    const double w = 4.0 * TM_EPS;
    /* start where the Bernstein polygon b (on [lo, hi]) crosses zero */
    double t = 0.5 * (lo + hi), step = hi - lo, step_old = hi - lo;
    for (int j = 0; j < 6; j++) {
        if ((b[j] < 0.0 && b[j + 1] > 0.0) || (b[j] > 0.0 && b[j + 1] < 0.0)) {
            double u = (j + b[j] / (b[j] - b[j + 1])) / 6.0, c = lo + (hi - lo) * u;
            if (c > lo && c < hi)
                t = c;
            break;
        }
    }
    for (int it = 0; it < 200 && hi - lo > w; it++) {
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
    if (depth >= TM_DEPTH) {
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

/* Basis at t = tan(θ/2) (SPEC §2), cancellation-free. */
static void basis_t(double t, double A[4])
{
    double t2 = t * t, q = 1.0 + t2;
    double s = 2.0 * t / q, c = (1.0 - t) * (1.0 + t) / q;
    double u = (1.0 - t) * (1.0 - t) / q, v = 2.0 * t2 / q;
    A[0] = u * u * u;
    A[1] = s * u * (2.0 + u);
    A[2] = c * v * (2.0 + v);
    A[3] = v * v * v;
}

static double theta_of(double t)
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
static double tmin_core(double C0, double C1, double C2, double C3, double kappa, double *theta,
                        double *tbest, double *errb)
{
    /* scalars, not an array: a vector load of two separately stored
     * elements stalls store forwarding */
    double m0 = fabs(C0), m1 = fabs(C1), m2 = fabs(C2), m3 = fabs(C3), M = fabs(kappa);
    if (!((m0 <= DBL_MAX) & (m1 <= DBL_MAX) & (m2 <= DBL_MAX) & (m3 <= DBL_MAX) & (M <= DBL_MAX))) {
        if (theta)
            *theta = NAN;
        *tbest = *errb = NAN;
        return NAN;
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
    z.nc = 0;
    z.depth = 0;
    double D0 = z.D0, D1 = z.D1, D2 = z.D2;
    double ak = fabs(ks), a0 = fabs(D0), a1 = fabs(D1), a2 = fabs(D2);
    double babs = 3.0 * a0 + 3.0 * a1 + 24.0 * a2 + 8.0 * ak;
    add_cand(&z, 0.0);
    add_cand(&z, 1.0);
    /* (2.1): a monotone control polygon with κ of the other sign makes g
     * monotone; then every Bernstein coefficient below has one sign (also
     * as computed: sums of rounded terms of one sign), no root, and the
     * minimum is at an end.  Most intervals of real data are so. */
    int mono = ((D0 >= 0.0) & (D1 >= 0.0) & (D2 >= 0.0) & (ks <= 0.0)) |
               ((D0 <= 0.0) & (D1 <= 0.0) & (D2 <= 0.0) & (ks >= 0.0));
    if (!mono) {
        double b[7] = {3.0 * D0 - ks,
                       D0 + (2.0 / 3.0) * D1 - ks,
                       (4.0 / 3.0) * D1 - 1.2 * ks,
                       2.0 * D1 - 1.6 * ks,
                       (8.0 / 3.0) * D1 - 2.4 * ks,
                       (8.0 / 3.0) * D1 + 4.0 * D2 - 4.0 * ks,
                       24.0 * D2 - 8.0 * ks};
        isolate(&z, b, 0.0, 1.0, 0);
    }

    /* the ends (candidates 0, 1) with basis_t's exact values there, A = e_0
     * at t = 0, θ = 0, and A = e_3 at t = 1, θ = π/2; then the roots */
    double g0 = 1.0 * c0 + 0.0 * c1 + 0.0 * c2 + 0.0 * c3;
    double g1 = 0.0 * c0 + 0.0 * c1 + 0.0 * c2 + 1.0 * c3;
    if (ks != 0.0) {
        g0 -= ks * 0.0;
        g1 -= ks * TS_HALF_PI;
    }
    double best = g1 < g0 ? g1 : g0, bt = g1 < g0 ? 1.0 : 0.0;
    for (int j = 2; j < z.nc; j++) {
        double t = z.t[j], A[4];
        if (t == 0.0 || t == 1.0) { /* as above */
            A[0] = t == 0.0 ? 1.0 : 0.0;
            A[1] = A[2] = 0.0;
            A[3] = 1.0 - A[0];
        } else {
            basis_t(t, A);
        }
        double g = A[0] * c0 + A[1] * c1 + A[2] * c2 + A[3] * c3;
        if (ks != 0.0)
            g -= ks * theta_of(t);
        if (g < best) {
            best = g;
            bt = t;
        }
    }
    double eta = (6.0 * z.depth + 6.0) * TM_EPS * babs;
    double gd = 2.0 * (16.0 * TM_EPS * (Ms + TS_HALF_PI * ak) + 2.0 * eta);
    *tbest = bt;
    if (theta)
        *theta = theta_of(bt);
    *errb = scale2(gd, e);
    return scale2(best, e);
}

double ts__trig_min(const double C[4], double kappa, double *theta_min)
{
    double t, eb;
    return tmin_core(C[0], C[1], C[2], C[3], kappa, theta_min, &t, &eb);
}

/* ------------------------------------------------------------------ */
/* Interval gaps                                                        */
/* ------------------------------------------------------------------ */

/* SPEC §4: one control gap sg·(Y − m X − c) of the geometric form, to the
 * rounding of the gap itself (not of the line's size: a knot may lie 1e-14
 * of |c| above the line).  m X = p + e exactly (fma), Y − p = s1 + e1 and
 * s1 − c = s2 + e2 exactly (TwoSum), so the gap is s2 + e1 + e2 − e; the two
 * roundings summing the small terms and the last one add
 * ≤ u(1+u)(2(|e1| + |e2| + |e|) + |v|) < ε(...) (u = ε/2); *err is twice
 * that, plus 4·2^-1074 for a subnormal e.  Overflow gives NaN/Inf: never
 * above *err. */
static double ctl_gap(double Y, double X, double m, double c, double sg, double *err)
{
    double p = m * X, e = fma(m, X, -p);
    double s1 = Y - p, z1 = s1 - Y, e1 = (Y - (s1 - z1)) + (-p - z1);
    double s2 = s1 - c, z2 = s2 - s1, e2 = (s1 - (s2 - z2)) + (-c - z2);
    double v = s2 + ((e1 + e2) - e);
    *err = 2.0 * TM_EPS * (fabs(e1) + fabs(e2) + fabs(e) + fabs(v)) + 4.0 * DBL_TRUE_MIN;
    return sg * v;
}

/* SPEC §4, convex hull (S = Σ A_l Y_l, X = Σ A_l X_l, A_l >= 0, Σ A_l = 1):
 * every control gap above its rounding proves the whole segment inside. */
static int hull_inside(const double B[4], const double X[4], const ts_line *ln, int sign)
{
    int ok = 1;
    for (int l = 0; l < 4; l++) {
        double el, Cl = ctl_gap(B[l], X[l], ln->m, ln->c, sign > 0 ? 1.0 : -1.0, &el);
        ok = ok && Cl > el;
    }
    return ok;
}

/* Gap of interval i with control values B (and abscissae X in the geometric
 * form, else NULL) to a line: sign +1 min of S − L, −1 min of L − S.
 * *guard receives the rounding guard of that value. */
static double gap_ctl(const ts_spline *sp, size_t i, const double B[4], const double *X,
                      const ts_line *ln, int sign, double *at, double *guard)
{
    double C[4], kappa, theta, t, eb, m = ln->m, c = ln->c, sg = sign > 0 ? 1.0 : -1.0;
    double xi = sp->x[i], h = sp->h[i], bmax = 0.0, xmax = fabs(xi) + h;
    for (int l = 0; l < 4; l++)
        bmax = fabs(B[l]) > bmax ? fabs(B[l]) : bmax;
    double cerr = -1.0; /* geometric form: max rounding of the C_l */
    if (X) {
        /* SPEC §4: Y − L(X) = Σ A_l (Y_l − m X_l − c), exact */
        for (int l = 0; l < 4; l++) {
            double el;
            C[l] = ctl_gap(B[l], X[l], m, c, sg, &el);
            cerr = el > cerr ? el : cerr;
        }
        kappa = 0.0;
    } else {
        /* SPEC §5: S − L = Σ A_l (B_l − L(x_i)) − (2mh/π) θ since Σ A_l = 1
         * (m = 0: κ = ±0, the same as 0 below) */
        double L0 = m * xi + c;
        for (int l = 0; l < 4; l++)
            C[l] = sg * (B[l] - L0);
        kappa = m != 0.0 ? sg * m * (2.0 * h / TS_PI) : 0.0;
    }
    double g = tmin_core(C[0], C[1], C[2], C[3], kappa, at && !X ? &theta : NULL, &t, &eb);
    if (at) {
        if (isnan(g)) {
            *at = NAN;
        } else if (X) {
            double A[4];
            basis_t(t, A);
            *at = A[0] * X[0] + A[1] * X[1] + A[2] * X[2] + A[3] * X[3];
        } else {
            *at = t >= 1.0 ? sp->x[i + 1] : xi + h * (theta / TS_HALF_PI);
        }
    }
    if (guard)
        *guard = eb + (X ? cerr : 8.0 * TM_EPS * (bmax + fabs(m) * xmax + fabs(c)));
    return g;
}

/* B of interval i; X (SPEC §4) only in the geometric form, the one that uses it. */
static void controls_of(const ts_spline *sp, size_t i, double B[4], double X[4], int *geo)
{
    ts__B(sp, i, B);
    *geo = sp->form == TS_FORM_GEOMETRIC;
    X[0] = sp->x[i];
    X[1] = *geo ? sp->xc1[i] : (double)NAN;
    X[2] = *geo ? sp->xc2[i] : (double)NAN;
    X[3] = sp->x[i + 1];
}

double ts__interval_gap(const ts_spline *sp, size_t i, const ts_line *line, int sign, double *at)
{
    double B[4], X[4];
    int geo;
    controls_of(sp, i, B, X, &geo);
    return gap_ctl(sp, i, B, geo ? X : NULL, line, sign, at, NULL);
}

/* ------------------------------------------------------------------ */
/* Per-interval certificate of a shape spline                          */
/* ------------------------------------------------------------------ */

typedef struct cert {
    double glo, alo, gup, aup; /* NaN where absent or not computed */
} cert;

/* Is interval i with controls B (X in the geometric form) inside the region
 * of sp's scheme?  exact: compute the trig-min certificates (into *cr, with
 * the places of the minima if want_at: the report's, not the build's);
 * otherwise only the control-value test, which is a proof by itself
 * (S = Σ A_l B_l, A_l >= 0, Σ A_l = 1, SPEC §2):
 *  positive, f_i, f_{i+1} > 0: B0, B3 > 0 and B1, B2 >= 0 give S > 0;
 *  positive with a zero end (promise S >= 0): all B_l >= 0;
 *  monotone: B monotone in the data's direction gives S' of that sign by
 *    (2.1) (and X' > 0 in the geometric form); no gaps (NaN);
 *  lines, geometric form only: every Y_l − m X_l − c above its rounding
 *    (hull_inside); with exact, also a trig-min gap above its guard will do. */
static int check_ctl(const ts_spline *sp, size_t i, const double B[4], const double *X,
                     int exact, cert *cr, int want_at)
{
    cr->glo = cr->alo = cr->gup = cr->aup = NAN;
    double f0 = sp->f[i], f1 = sp->f[i + 1], guard;
    /* an overflowed control value (tiny a_i) proves nothing: S would be NaN */
    for (int l = 0; l < 4; l++)
        if (!isfinite(B[l]) || (X && !isfinite(X[l])))
            return 0;
    if (sp->shape == TS_SHAPE_MONOTONE) {
        int ok;
        if (f1 > f0)
            ok = B[0] <= B[1] && B[1] <= B[2] && B[2] <= B[3];
        else if (f1 < f0)
            ok = B[0] >= B[1] && B[1] >= B[2] && B[2] >= B[3];
        else
            ok = B[0] == B[1] && B[1] == B[2] && B[2] == B[3];
        if (X) {
            /* X' > 0 by (2.1) when D0, D2 > 0 and D1 >= -min(D0, D2)/4: at
             * a_i = 4/(3π) (TS_TERM_GEOMETRIC) D1 = h - 2k is 0 up to rounding.
             * min over θ of [(1-s)²c + (1-c)²s]/(sc) is 0.2426 (θ = π/4),
             * so X' >= sc·min(D0, D2)(3·0.2426 - 2/4) > 0 inside. */
            double D0 = X[1] - X[0], D1 = X[2] - X[1], D2 = X[3] - X[2];
            double dm = D0 < D2 ? D0 : D2;
            ok = ok && ((D0 >= 0.0 && D1 >= 0.0 && D2 >= 0.0) || (dm > 0.0 && D1 >= -0.25 * dm));
        }
        return ok;
    }
    if (sp->shape == TS_SHAPE_POSITIVE) {
        int zero_end = !(f0 > 0.0 && f1 > 0.0);
        int structural = zero_end ? (B[0] >= 0.0 && B[1] >= 0.0 && B[2] >= 0.0 && B[3] >= 0.0)
                                  : (B[0] > 0.0 && B[3] > 0.0 && B[1] >= 0.0 && B[2] >= 0.0);
        if (!exact)
            return structural;
        cr->glo = gap_ctl(sp, i, B, X, &sp->lower, 1, want_at ? &cr->alo : NULL, &guard);
        return structural || (!zero_end && cr->glo > guard);
    }
    int ok = 1;
    for (int side = 0; side < 2; side++) {
        if (!(side == 0 ? sp->has_lower : sp->has_upper))
            continue;
        const ts_line *ln = side == 0 ? &sp->lower : &sp->upper;
        int sign = side == 0 ? 1 : -1;
        /* geometric form: the control gaps are a proof by themselves */
        int hull = X && hull_inside(B, X, ln, sign);
        if (exact) {
            double *g = side == 0 ? &cr->glo : &cr->gup, *a = side == 0 ? &cr->alo : &cr->aup;
            *g = gap_ctl(sp, i, B, X, ln, sign, want_at ? a : NULL, &guard);
            ok = ok && (hull || *g > guard);
        } else {
            ok = ok && hull; /* only the geometric form gets here */
        }
    }
    return ok;
}

static int check_interval(ts_spline *sp, size_t i, int exact)
{
    double B[4], X[4];
    int geo;
    cert cr;
    controls_of(sp, i, B, X, &geo);
    return check_ctl(sp, i, B, geo ? X : NULL, exact, &cr, 0);
}

/* Set a_i (through beta_i) and recompute the controls it touches. */
static void set_a(ts_spline *sp, size_t i, double a)
{
    size_t n = sp->n, i0 = i, i1 = i + 1;
    sp->beta[i] = a - sp->alpha[i];
    if (sp->form == TS_FORM_C1) {
        /* d̂ of both knots changes (SPEC §3) */
        i0 = i > 0 ? i - 1 : 0;
        i1 = i + 2 < n ? i + 2 : n;
    }
    ts__controls(sp, i0, i1);
}

static int ok_at(ts_spline *sp, size_t i, double a, int exact)
{
    set_a(sp, i, a);
    return check_interval(sp, i, exact);
}

/* Certification margin of interval i at a (lines only): min over the
 * active boundaries of gap − guard. */
static double margin_at(ts_spline *sp, size_t i, double a)
{
    double B[4], X[4], r = INFINITY, guard, at;
    int geo;
    set_a(sp, i, a);
    controls_of(sp, i, B, X, &geo);
    if (sp->has_lower) {
        double g = gap_ctl(sp, i, B, geo ? X : NULL, &sp->lower, 1, &at, &guard) - guard;
        if (!(g >= r))
            r = g;
    }
    if (sp->has_upper) {
        double g = gap_ctl(sp, i, B, geo ? X : NULL, &sp->upper, -1, &at, &guard) - guard;
        if (!(g >= r))
            r = g;
    }
    return r;
}

#define TS_A_MAX 1e307

static ts_status infeasible(ts_spline *sp, size_t i, double a0, ts_error *err)
{
    set_a(sp, i, a0);
    (void)check_interval(sp, i, 1);
    ts__error_set(err, TS_ERR_INFEASIBLE, i, TS_WHERE_INTERVAL);
    return TS_ERR_INFEASIBLE;
}

/* SPEC §5: change beta_i until interval i is certified.
 *  - If the limit a -> ∞ (S -> f_i c² + f_{i+1} s², geometric form: the
 *    chord) is certified, beta_i is raised: doubling, then bisection to the
 *    smallest certified a above the rule's, plus the margin t.
 *  - Otherwise (a sloped line in the paper or C¹ form) the gap is concave in
 *    u = 1/a in the paper form (a minimum of functions affine in u), so its
 *    maximum over beta >= 0 (u in (0, 1/alpha]) is found by golden section;
 *    if it is not certified no beta >= 0 is (TS_ERR_INFEASIBLE); else the
 *    smallest certified a >= alpha is taken, plus t towards the maximum.
 *    In the C¹ form the gap also depends on the neighbours' a (fixed here),
 *    so there the search is a heuristic, and an error means no beta_i with
 *    the neighbours as they are. */
static ts_status repair(ts_spline *sp, size_t i, double t, int exact, ts_error *err)
{
    double a0 = sp->alpha[i] + sp->beta[i], al = sp->alpha[i];
    double B[4], X[4];
    int geo = sp->form == TS_FORM_GEOMETRIC;
    cert cr;
    B[0] = B[1] = sp->f[i];
    B[2] = B[3] = sp->f[i + 1];
    X[0] = X[1] = sp->x[i];
    X[2] = X[3] = sp->x[i + 1];
    double lo, hi, amax;
    if (check_ctl(sp, i, B, geo ? X : NULL, exact, &cr, 0)) {
        lo = a0;
        hi = 2.0 * a0;
        for (;;) { /* a_i stays <= TS_A_MAX: never an infinite a (k_i = 0) */
            if (!(hi <= TS_A_MAX))
                return infeasible(sp, i, a0, err);
            if (ok_at(sp, i, hi, exact))
                break;
            lo = hi;
            hi *= 2.0;
        }
        amax = INFINITY;
    } else {
        if (geo)
            return infeasible(sp, i, a0, err);
        const double r = 0.6180339887498949;
        /* u = 1/a in (0, 1/alpha]; a subnormal alpha would give ub = inf */
        double ua = 0.0, ub = 1.0 / al;
        if (!(ub <= DBL_MAX))
            ub = DBL_MAX;
        double u1 = ub - r * (ub - ua), u2 = ua + r * (ub - ua);
        double m1 = margin_at(sp, i, 1.0 / u1), m2 = margin_at(sp, i, 1.0 / u2);
        for (int it = 0; it < 90 && ub - ua > 1e-13 * ub; it++) {
            if (m1 < m2) {
                ua = u1;
                u1 = u2;
                m1 = m2;
                u2 = ua + r * (ub - ua);
                m2 = margin_at(sp, i, 1.0 / u2);
            } else {
                ub = u2;
                u2 = u1;
                m2 = m1;
                u1 = ub - r * (ub - ua);
                m1 = margin_at(sp, i, 1.0 / u1);
            }
        }
        amax = 1.0 / (m1 >= m2 ? u1 : u2);
        if (!(amax <= TS_A_MAX)) {
            if (!(al <= TS_A_MAX)) /* header: the a needed exceeds 1e307 */
                return infeasible(sp, i, a0, err);
            amax = TS_A_MAX;
        }
        if (!ok_at(sp, i, amax, exact))
            return infeasible(sp, i, a0, err);
        if (ok_at(sp, i, al, exact)) {
            lo = hi = al;
        } else {
            lo = al;
            hi = amax;
        }
    }
    /* bisection: lo fails, hi is certified */
    for (int it = 0; it < 200 && lo != hi && fabs(hi - lo) > 1e-12 * hi; it++) {
        double mid = lo + 0.5 * (hi - lo);
        if (mid == lo || mid == hi)
            break;
        if (ok_at(sp, i, mid, exact))
            hi = mid;
        else
            lo = mid;
    }
    /* the margin t, towards the best a, never past it */
    double cand = hi + t;
    if (cand > amax)
        cand = 0.5 * (hi + amax);
    if (!(cand <= TS_A_MAX)) /* a huge margin t */
        cand = hi > TS_A_MAX ? hi : TS_A_MAX;
    if (!ok_at(sp, i, cand, exact) && !ok_at(sp, i, hi, exact))
        return infeasible(sp, i, a0, err);
    sp->term[i] = (unsigned char)TS_TERM_CERTIFY;
    return TS_OK;
}

/* C¹ form: interval i could not be certified with its neighbours' a.  A
 * neighbour j with a_j > a_i caps d̂ at the shared knot; lower a_j to the
 * smallest value (>= alpha_j) that keeps j and its other neighbour
 * certified.  Returns 1 if some a_j was lowered. */
static int relax_neighbours(ts_spline *sp, size_t i, int exact)
{
    size_t n = sp->n;
    double ai = sp->alpha[i] + sp->beta[i];
    int changed = 0;
    for (int side = 0; side < 2; side++) {
        if ((side == 0 && i == 0) || (side == 1 && i + 1 >= n))
            continue;
        size_t j = side == 0 ? i - 1 : i + 1;
        double aj = sp->alpha[j] + sp->beta[j];
        if (!(aj > ai))
            continue;
        int has_o = side == 0 ? j > 0 : j + 1 < n;
        size_t o = side == 0 ? j - 1 : j + 1;
        double lo = sp->alpha[j], hi = aj;
#define TS_J_OK(a) (ok_at(sp, j, (a), exact) && (!has_o || check_interval(sp, o, exact)))
        if (TS_J_OK(lo)) {
            hi = lo;
        } else {
            for (int it = 0; it < 100 && hi - lo > 1e-12 * hi; it++) {
                double mid = lo + 0.5 * (hi - lo);
                if (TS_J_OK(mid))
                    hi = mid;
                else
                    lo = mid;
            }
        }
#undef TS_J_OK
        set_a(sp, j, hi);
        (void)check_interval(sp, j, exact);
        if (has_o)
            (void)check_interval(sp, o, exact);
        if (hi < aj) {
            sp->term[j] = (unsigned char)TS_TERM_CERTIFY;
            changed = 1;
        }
    }
    return changed;
}

/* opt->certify == 0 skips the trig-min certificates only where the
 * control-value test is a proof (positive, monotone, geometric form) */
int ts__certify_exact(const ts_options *opt)
{
    int lines = opt->shape == TS_SHAPE_ABOVE || opt->shape == TS_SHAPE_BELOW ||
                opt->shape == TS_SHAPE_BETWEEN;
    return opt->certify != 0 || (lines && opt->form != TS_FORM_GEOMETRIC);
}

/* First interval in [i, i1) that check_ctl with exact == 0 would not pass,
 * for the schemes whose control-value test is a bare sign test (paper and C¹
 * forms; else i): the same decisions as check_ctl, in a loop that touches
 * only the control values (issue 6).
 *  positive: f_i >= 0 (ts__shape_apply checked the data) and finite, so
 *    check_ctl's test is 0 <= B1, B2 <= DBL_MAX;
 *  monotone: every B_l finite and B monotone in the interval's direction. */
TS_VECTOR_LOOP static int ctl_nonnegative(const double *restrict b1, const double *restrict b2,
                                          size_t i0, size_t i1)
{
    int ok = 1;
    for (size_t i = i0; i < i1; i++)
        ok &= (b1[i] >= 0.0) & (b1[i] <= DBL_MAX) & (b2[i] >= 0.0) & (b2[i] <= DBL_MAX);
    return ok;
}

static size_t skip_proven(const ts_spline *sp, size_t i, size_t i1)
{
    if (sp->form == TS_FORM_GEOMETRIC)
        return i;
    const double *b1 = sp->b1, *b2 = sp->b2, *f = sp->f;
    if (sp->shape == TS_SHAPE_POSITIVE) {
        if (i < i1 && ctl_nonnegative(b1, b2, i, i1))
            return i1; /* the whole range at once (a flag, so that it vectorises) */
        while (i < i1 && b1[i] >= 0.0 && b1[i] <= DBL_MAX && b2[i] >= 0.0 && b2[i] <= DBL_MAX)
            i++;
    } else if (sp->shape == TS_SHAPE_MONOTONE) {
        for (; i < i1; i++) {
            double B0 = f[i], B1 = b1[i], B2 = b2[i], B3 = f[i + 1];
            if (!(fabs(B1) <= DBL_MAX && fabs(B2) <= DBL_MAX))
                break;
            if (B3 > B0 ? !(B0 <= B1 && B1 <= B2 && B2 <= B3)
                        : B3 < B0 ? !(B0 >= B1 && B1 >= B2 && B2 >= B3)
                                  : !(B0 == B1 && B1 == B2 && B2 == B3))
                break;
        }
    }
    return i;
}

/* A block of exact certificates at once (issue 6): for each interval i in
 * [i0, i1), ok[i] = 1 when check_ctl (exact, paper form, one boundary m x + c
 * with sign sg; positive: the scheme's structural test too) would pass it
 * through the path of tmin_core where the minimum is at an end (g monotone
 * by (2.1), or no minimum inside: most intervals of real data), else 0 (not
 * decided here: the general path then).  That path is written out operation
 * by operation as gap_ctl and tmin_core do it (the same values), restricted
 * to where it stays exact: finite controls, a normal M with 2^-e normal;
 * branch-free, so that it vectorises. */
TS_VECTOR_LOOP static void mono_certify(const double *restrict f, const double *restrict b1,
                                        const double *restrict b2, const double *restrict x,
                                        const double *restrict h, size_t i0, size_t i1,
                                        double m, double c, double sg, int positive,
                                        unsigned char *restrict ok)
{
    const double gm = 8.0 * TM_EPS, am = fabs(m), ac = fabs(c);
    for (size_t i = i0; i < i1; i++) {
        double B0 = f[i], B1 = b1[i], B2 = b2[i], B3 = f[i + 1];
        double xi = x[i], hi = h[i], xmax = fabs(xi) + hi, bmax = 0.0;
        bmax = fabs(B0) > bmax ? fabs(B0) : bmax;
        bmax = fabs(B1) > bmax ? fabs(B1) : bmax;
        bmax = fabs(B2) > bmax ? fabs(B2) : bmax;
        bmax = fabs(B3) > bmax ? fabs(B3) : bmax;
        int good = (fabs(B0) <= DBL_MAX) & (fabs(B1) <= DBL_MAX) & (fabs(B2) <= DBL_MAX) &
                   (fabs(B3) <= DBL_MAX);
        double L0 = m * xi + c;
        double C0 = sg * (B0 - L0), C1 = sg * (B1 - L0), C2 = sg * (B2 - L0), C3 = sg * (B3 - L0);
        /* gap_ctl has 0 for m = 0: ±0 here, the same from here on (|κ|, the
         * signs of κ·2^-e, κ != 0 do not see the sign of a zero) */
        double kappa = sg * m * (2.0 * hi / TS_PI);
        /* tmin_core */
        double m0 = fabs(C0), m1 = fabs(C1), m2 = fabs(C2), m3 = fabs(C3), M = fabs(kappa);
        good &= (m0 <= DBL_MAX) & (m1 <= DBL_MAX) & (m2 <= DBL_MAX) & (m3 <= DBL_MAX) &
                (M <= DBL_MAX);
        M = m0 > M ? m0 : M;
        M = m1 > M ? m1 : M;
        M = m2 > M ? m2 : M;
        M = m3 > M ? m3 : M;
        uint64_t u;
        memcpy(&u, &M, sizeof u);
        int field = (int)((u >> 52) & 0x7ff), e = field - 1022; /* exponent_of, M normal */
        good &= (field != 0) & (e >= -1021) & (e <= 1022);
        int ec = good ? e : 0; /* keeps the factors below finite where not good */
        uint64_t up = (uint64_t)(1023 - ec) << 52, ue = (uint64_t)(ec + 1023) << 52;
        double p, q;
        memcpy(&p, &up, sizeof p);
        memcpy(&q, &ue, sizeof q);
        double c0 = C0 * p, c1 = C1 * p, c2 = C2 * p, c3 = C3 * p, ks = kappa * p, Ms = M * p;
        double D0 = c1 - c0, D1 = c2 - c1, D2 = c3 - c2;
        double ak = fabs(ks), a0 = fabs(D0), a1 = fabs(D1), a2 = fabs(D2);
        double babs = 3.0 * a0 + 3.0 * a1 + 24.0 * a2 + 8.0 * ak;
        int mono = ((D0 >= 0.0) & (D1 >= 0.0) & (D2 >= 0.0) & (ks <= 0.0)) |
                   ((D0 <= 0.0) & (D1 <= 0.0) & (D2 <= 0.0) & (ks >= 0.0));
        /* isolate adds no candidate (and depth stays 0) unless a Bernstein
         * coefficient < 0 comes before one > 0 (a sign change from - to +,
         * where g has a minimum): then only the ends count */
        double bb0 = 3.0 * D0 - ks, bb1 = D0 + (2.0 / 3.0) * D1 - ks,
               bb2 = (4.0 / 3.0) * D1 - 1.2 * ks, bb3 = 2.0 * D1 - 1.6 * ks,
               bb4 = (8.0 / 3.0) * D1 - 2.4 * ks, bb5 = (8.0 / 3.0) * D1 + 4.0 * D2 - 4.0 * ks,
               bb6 = 24.0 * D2 - 8.0 * ks;
        int neg = bb0 < 0.0, rise = 0;
        rise |= neg & (bb1 > 0.0), neg |= bb1 < 0.0;
        rise |= neg & (bb2 > 0.0), neg |= bb2 < 0.0;
        rise |= neg & (bb3 > 0.0), neg |= bb3 < 0.0;
        rise |= neg & (bb4 > 0.0), neg |= bb4 < 0.0;
        rise |= neg & (bb5 > 0.0), neg |= bb5 < 0.0;
        rise |= neg & (bb6 > 0.0);
        good &= mono | !rise;
        double g0 = 1.0 * c0 + 0.0 * c1 + 0.0 * c2 + 0.0 * c3;
        double g1 = 0.0 * c0 + 0.0 * c1 + 0.0 * c2 + 1.0 * c3;
        g0 = ks != 0.0 ? g0 - ks * 0.0 : g0;
        g1 = ks != 0.0 ? g1 - ks * TS_HALF_PI : g1;
        double best = g1 < g0 ? g1 : g0;
        double eta = (6.0 * 0 + 6.0) * TM_EPS * babs; /* depth 0 */
        double gd = 2.0 * (16.0 * TM_EPS * (Ms + TS_HALF_PI * ak) + 2.0 * eta);
        double g = best * q, guard = gd * q + gm * (bmax + am * xmax + ac);
        int pass = g > guard;
        if (positive) {
            double f0 = B0, f1 = B3;
            int zero_end = !((f0 > 0.0) & (f1 > 0.0));
            int structural = zero_end ? (B0 >= 0.0) & (B1 >= 0.0) & (B2 >= 0.0) & (B3 >= 0.0)
                                      : (B0 > 0.0) & (B3 > 0.0) & (B1 >= 0.0) & (B2 >= 0.0);
            pass = structural | ((!zero_end) & pass);
        }
        ok[i - i0] = (unsigned char)(good & pass & (M != 0.0));
    }
}

/* The certification loop over [i0, i1).  In the paper and geometric forms
 * every interval is checked (and repaired) on its own; the C¹ form steps back
 * after a repair, so it runs once over [0, n). */
static ts_status certify_loop(ts_spline *sp, const ts_options *opt, size_t i0, size_t i1,
                              ts_error *err)
{
    int exact = ts__certify_exact(opt);
    /* every repair moves on (paper, geometric) or may step back once (C¹) */
    size_t budget = 16 * sp->n + 64;
    size_t i = i0;
    /* exact, paper form: mono_certify decides most intervals a block at a
     * time (a repair there changes only its own interval) */
    int batch = exact && sp->form == TS_FORM_PAPER && !(sp->has_lower && sp->has_upper) &&
                (sp->has_lower || sp->has_upper);
    unsigned char ok[TS_CERT_BLOCK];
    size_t k0 = i, k1 = i; /* ok[] covers [k0, k1) */
    while (i < i1) {
        if (!exact) {
            i = skip_proven(sp, i, i1);
            if (i >= i1)
                break;
        }
        if (batch && i >= k1) {
            const ts_line *ln = sp->has_lower ? &sp->lower : &sp->upper;
            k0 = i;
            k1 = i1 - i > TS_CERT_BLOCK ? i + TS_CERT_BLOCK : i1;
            mono_certify(sp->f, sp->b1, sp->b2, sp->x, sp->h, k0, k1, ln->m, ln->c,
                         sp->has_lower ? 1.0 : -1.0, sp->shape == TS_SHAPE_POSITIVE, ok);
        }
        if ((batch && ok[i - k0]) || check_interval(sp, i, exact)) {
            i++;
            continue;
        }
        if (budget-- == 0) {
            ts__error_set(err, TS_ERR_INFEASIBLE, i, TS_WHERE_INTERVAL);
            return TS_ERR_INFEASIBLE;
        }
        double t = opt->margins ? opt->margins[i] : opt->margin;
        ts_status st = repair(sp, i, t, exact, err);
        if (st != TS_OK && sp->form == TS_FORM_C1 && relax_neighbours(sp, i, exact)) {
            ts__error_set(err, TS_OK, TS_NO_INDEX, TS_WHERE_NONE);
            st = repair(sp, i, t, exact, err);
        }
        if (st != TS_OK)
            return st;
        /* C¹: the repair changed d̂_i, so re-check the left neighbour */
        if (sp->form == TS_FORM_C1 && i > 0)
            i--;
        else
            i++;
    }
    return TS_OK;
}

ts_status ts__certify_range(ts_spline *sp, const ts_options *opt, size_t i0, size_t i1,
                            ts_error *err)
{
    if (!sp || !opt || sp->form == TS_FORM_C1)
        return TS_ERR_OPTION;
    sp->certified = 0;
    sp->have_certs = 0;
    if (sp->shape == TS_SHAPE_NONE)
        return TS_OK;
    return certify_loop(sp, opt, i0, i1 < sp->n ? i1 : sp->n, err);
}

void ts__certify_done(ts_spline *sp, const ts_options *opt)
{
    if (sp->shape == TS_SHAPE_NONE)
        return;
    sp->have_certs = ts__certify_exact(opt);
    sp->certified = 1;
}

ts_status ts__certify_build(ts_spline *sp, const ts_options *opt, ts_error *err)
{
    if (!sp || !opt)
        return TS_ERR_NULL;
    sp->certified = 0;
    sp->have_certs = 0;
    if (sp->shape == TS_SHAPE_NONE)
        return TS_OK;
    ts_status st = certify_loop(sp, opt, 0, sp->n, err);
    if (st == TS_OK)
        ts__certify_done(sp, opt);
    return st;
}

/* ------------------------------------------------------------------ */
/* Public                                                              */
/* ------------------------------------------------------------------ */

static void report_base(const ts_spline *s, size_t i, ts_interval_report *rep)
{
    double X[4];
    int geo;
    rep->x0 = s->x[i];
    rep->x1 = s->x[i + 1];
    rep->alpha = s->alpha[i];
    rep->beta = s->beta[i];
    rep->a = s->alpha[i] + s->beta[i];
    controls_of(s, i, rep->B, X, &geo);
    rep->term = (ts_term)s->term[i];
    rep->has_lower = rep->has_upper = 0;
    rep->gap_lower = rep->at_lower = rep->gap_upper = rep->at_upper = NAN;
    rep->certified = 0;
}

static void report_clear(ts_interval_report *rep)
{
    rep->x0 = rep->x1 = rep->alpha = rep->beta = rep->a = NAN;
    rep->B[0] = rep->B[1] = rep->B[2] = rep->B[3] = NAN;
    rep->term = TS_TERM_USER;
    rep->has_lower = rep->has_upper = 0;
    rep->gap_lower = rep->at_lower = rep->gap_upper = rep->at_upper = NAN;
    rep->certified = 0;
}

ts_status ts_spline_report(const ts_spline *s, size_t i, ts_interval_report *rep)
{
    if (rep)
        report_clear(rep);
    if (!s || !rep)
        return TS_ERR_NULL;
    if (i >= s->n)
        return TS_ERR_INDEX;
    report_base(s, i, rep);
    if (s->shape == TS_SHAPE_NONE)
        return TS_OK;
    double B[4], X[4];
    int geo;
    cert cr;
    controls_of(s, i, B, X, &geo);
    rep->has_lower = s->has_lower;
    rep->has_upper = s->has_upper;
    int ok = check_ctl(s, i, B, geo ? X : NULL, s->have_certs, &cr, 1); /* fills cr */
    rep->certified = s->certified && ok;
    if (s->have_certs) {
        /* the build's certificates, computed again (not stored: issue 6) */
        rep->gap_lower = cr.glo;
        rep->at_lower = cr.alo;
        rep->gap_upper = cr.gup;
        rep->at_upper = cr.aup;
    } else {
        /* certificates skipped at build (opt.certify = 0): compute them now */
        if (s->has_lower)
            rep->gap_lower = gap_ctl(s, i, B, geo ? X : NULL, &s->lower, 1, &rep->at_lower, NULL);
        if (s->has_upper)
            rep->gap_upper = gap_ctl(s, i, B, geo ? X : NULL, &s->upper, -1, &rep->at_upper, NULL);
    }
    return TS_OK;
}

int ts_spline_certified(const ts_spline *s)
{
    return s && s->shape != TS_SHAPE_NONE && s->certified ? 1 : 0;
}

ts_status ts_certify(const ts_spline *s, const ts_line *lower, const ts_line *upper,
                     ts_interval_report *reports, ts_error *err)
{
    ts__error_set(err, TS_OK, TS_NO_INDEX, TS_WHERE_NONE);
    for (size_t i = 0; s && reports && i < s->n; i++) /* out-params reset first */
        report_clear(&reports[i]);
    if (!s || (!lower && !upper)) {
        ts__error_set(err, TS_ERR_NULL, TS_NO_INDEX, TS_WHERE_NONE);
        return TS_ERR_NULL;
    }
    if ((lower && !(isfinite(lower->m) && isfinite(lower->c))) ||
        (upper && !(isfinite(upper->m) && isfinite(upper->c)))) {
        ts__error_set(err, TS_ERR_NONFINITE, TS_NO_INDEX, TS_WHERE_NONE);
        return TS_ERR_NONFINITE;
    }
    size_t first = TS_NO_INDEX;
    for (size_t i = 0; i < s->n; i++) {
        double B[4], X[4], guard;
        int geo, ok = 1;
        ts_interval_report r;
        report_base(s, i, &r);
        controls_of(s, i, B, X, &geo);
        /* geometric form: the convex hull proof (hull_inside) also counts */
        if (lower) {
            r.has_lower = 1;
            r.gap_lower = gap_ctl(s, i, B, geo ? X : NULL, lower, 1, &r.at_lower, &guard);
            ok = ok && (r.gap_lower > guard || (geo && hull_inside(B, X, lower, 1)));
        }
        if (upper) {
            r.has_upper = 1;
            r.gap_upper = gap_ctl(s, i, B, geo ? X : NULL, upper, -1, &r.at_upper, &guard);
            ok = ok && (r.gap_upper > guard || (geo && hull_inside(B, X, upper, -1)));
        }
        r.certified = ok;
        if (!ok && first == TS_NO_INDEX)
            first = i;
        if (reports)
            reports[i] = r;
    }
    if (first != TS_NO_INDEX) {
        ts__error_set(err, TS_ERR_VIOLATED, first, TS_WHERE_INTERVAL);
        return TS_ERR_VIOLATED;
    }
    return TS_OK;
}
