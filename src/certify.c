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
 * 0 sign changes = no root, 1 = exactly one, bracketed and refined by the
 * Illinois method on the factored P), then g is evaluated at 0, 1 and every
 * root; the least value is the minimum.
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
#include "ts_internal.h"

#include <float.h>
#include <math.h>

#define TM_EPS DBL_EPSILON
#define TM_MAXC 48   /* candidate slots: ≤ 2 ends + 6 roots + 6 deep leaves (+ split points) */
#define TM_DEPTH 46  /* subdivision depth limit: width 2^-46 in t */

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

/* One root of P in (lo, hi); sign of P just right of lo is s. */
static void refine(tm_ctx *z, double lo, double hi, int s)
{
    double flo = p_eval(z, lo), fhi = p_eval(z, hi);
    int illinois = sgn(flo) == s && sgn(fhi) == -s;
    int side = 0;
    for (int it = 0; it < 200 && hi - lo > 4.0 * TM_EPS; it++) {
        double m = 0.5 * (lo + hi);
        if (illinois && (it & 7) != 7) {
            double r = (lo * fhi - hi * flo) / (fhi - flo);
            if (r > lo && r < hi)
                m = r;
        }
        double fm = p_eval(z, m);
        int sm = sgn(fm);
        if (sm == 0) {
            lo = hi = m;
            break;
        }
        if (sm == s) {
            lo = m;
            flo = fm;
            if (side == -1)
                fhi *= 0.5;
            side = -1;
        } else {
            hi = m;
            fhi = fm;
            if (side == 1)
                flo *= 0.5;
            side = 1;
        }
    }
    add_cand(z, 0.5 * (lo + hi));
}

static void isolate(tm_ctx *z, const double b[7], double lo, double hi, int depth)
{
    int var = 0, first = 0, last = 0;
    for (int j = 0; j < 7; j++) {
        int s = sgn(b[j]);
        if (!s)
            continue;
        if (last && s != last)
            var++;
        if (!first)
            first = s;
        last = s;
    }
    if (var == 0)
        return;
    if (depth > z->depth)
        z->depth = depth;
    if (var == 1) {
        refine(z, lo, hi, first);
        return;
    }
    double mid = 0.5 * (lo + hi);
    if (depth >= TM_DEPTH) {
        add_cand(z, mid);
        return;
    }
    /* de Casteljau at 1/2 */
    double w[7], l[7], r[7];
    for (int j = 0; j < 7; j++)
        w[j] = b[j];
    l[0] = w[0];
    r[6] = w[6];
    for (int k = 1; k < 7; k++) {
        for (int j = 0; j < 7 - k; j++)
            w[j] = 0.5 * (w[j] + w[j + 1]);
        l[k] = w[0];
        r[6 - k] = w[6 - k];
    }
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
    return t >= 1.0 ? TS_HALF_PI : 2.0 * atan(t);
}

/* Exact min of g; *tbest its t, *errb the rounding guard (unscaled). */
static double tmin_core(const double C[4], double kappa, double *theta, double *tbest,
                        double *errb)
{
    double M = fabs(kappa);
    int finite = isfinite(kappa);
    for (int l = 0; l < 4; l++) {
        finite = finite && isfinite(C[l]);
        if (fabs(C[l]) > M)
            M = fabs(C[l]);
    }
    if (!finite) {
        *theta = *tbest = *errb = NAN;
        return NAN;
    }
    if (M == 0.0) {
        *theta = *tbest = *errb = 0.0;
        return 0.0;
    }
    int e;
    (void)frexp(M, &e);
    double Cs[4], ks = ldexp(kappa, -e);
    for (int l = 0; l < 4; l++)
        Cs[l] = ldexp(C[l], -e);
    tm_ctx z;
    z.D0 = Cs[1] - Cs[0];
    z.D1 = Cs[2] - Cs[1];
    z.D2 = Cs[3] - Cs[2];
    z.k = ks;
    z.nc = 0;
    z.depth = 0;
    double D0 = z.D0, D1 = z.D1, D2 = z.D2;
    double b[7] = {3.0 * D0 - ks,
                   D0 + (2.0 / 3.0) * D1 - ks,
                   (4.0 / 3.0) * D1 - 1.2 * ks,
                   2.0 * D1 - 1.6 * ks,
                   (8.0 / 3.0) * D1 - 2.4 * ks,
                   (8.0 / 3.0) * D1 + 4.0 * D2 - 4.0 * ks,
                   24.0 * D2 - 8.0 * ks};
    double ak = fabs(ks), a0 = fabs(D0), a1 = fabs(D1), a2 = fabs(D2);
    double babs = 3.0 * a0 + 3.0 * a1 + 24.0 * a2 + 8.0 * ak;
    add_cand(&z, 0.0);
    add_cand(&z, 1.0);
    isolate(&z, b, 0.0, 1.0, 0);

    double best = INFINITY, bt = 0.0;
    for (int j = 0; j < z.nc; j++) {
        double t = z.t[j], A[4];
        basis_t(t, A);
        double g = A[0] * Cs[0] + A[1] * Cs[1] + A[2] * Cs[2] + A[3] * Cs[3];
        if (ks != 0.0)
            g -= ks * theta_of(t);
        if (g < best) {
            best = g;
            bt = t;
        }
    }
    double Ms = ldexp(M, -e);
    double eta = (6.0 * z.depth + 6.0) * TM_EPS * babs;
    double gd = 2.0 * (16.0 * TM_EPS * (Ms + TS_HALF_PI * ak) + 2.0 * eta);
    *tbest = bt;
    *theta = theta_of(bt);
    *errb = ldexp(gd, e);
    return ldexp(best, e);
}

double ts__trig_min(const double C[4], double kappa, double *theta_min)
{
    double t, eb, th;
    double v = tmin_core(C, kappa, &th, &t, &eb);
    if (theta_min)
        *theta_min = th;
    return v;
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
        if (fabs(B[l]) > bmax)
            bmax = fabs(B[l]);
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
        /* SPEC §5: S − L = Σ A_l (B_l − L(x_i)) − (2mh/π) θ since Σ A_l = 1 */
        double L0 = m * xi + c;
        for (int l = 0; l < 4; l++)
            C[l] = sg * (B[l] - L0);
        kappa = sg * m * (2.0 * h / TS_PI);
    }
    double g = tmin_core(C, kappa, &theta, &t, &eb);
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

static void controls_of(const ts_spline *sp, size_t i, double B[4], double X[4], int *geo)
{
    ts__B(sp, i, B);
    *geo = sp->form == TS_FORM_GEOMETRIC;
    X[0] = sp->x[i];
    X[1] = sp->xc1[i];
    X[2] = sp->xc2[i];
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
 * of sp's scheme?  exact: compute the trig-min certificates (into *cr);
 * otherwise only the control-value test, which is a proof by itself
 * (S = Σ A_l B_l, A_l >= 0, Σ A_l = 1, SPEC §2):
 *  positive, f_i, f_{i+1} > 0: B0, B3 > 0 and B1, B2 >= 0 give S > 0;
 *  positive with a zero end (promise S >= 0): all B_l >= 0;
 *  monotone: B monotone in the data's direction gives S' of that sign by
 *    (2.1) (and X' > 0 in the geometric form); no gaps (NaN);
 *  lines, geometric form only: every Y_l − m X_l − c above its rounding
 *    (hull_inside); with exact, also a trig-min gap above its guard will do. */
static int check_ctl(const ts_spline *sp, size_t i, const double B[4], const double *X,
                     int exact, cert *cr)
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
        cr->glo = gap_ctl(sp, i, B, X, &sp->lower, 1, &cr->alo, &guard);
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
            *g = gap_ctl(sp, i, B, X, ln, sign, a, &guard);
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
    int ok = check_ctl(sp, i, B, geo ? X : NULL, exact, &cr);
    sp->gap_lo[i] = cr.glo;
    sp->at_lo[i] = cr.alo;
    sp->gap_up[i] = cr.gup;
    sp->at_up[i] = cr.aup;
    return ok;
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
    if (check_ctl(sp, i, B, geo ? X : NULL, exact, &cr)) {
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

ts_status ts__certify_build(ts_spline *sp, const ts_options *opt, ts_error *err)
{
    if (!sp || !opt)
        return TS_ERR_NULL;
    size_t n = sp->n;
    sp->certified = 0;
    sp->have_certs = 0;
    if (sp->shape == TS_SHAPE_NONE)
        return TS_OK;
    int lines = sp->shape == TS_SHAPE_ABOVE || sp->shape == TS_SHAPE_BELOW ||
                sp->shape == TS_SHAPE_BETWEEN;
    /* opt->certify == 0 skips the trig-min certificates only where the
     * control-value test is a proof (positive, monotone, geometric form) */
    int exact = opt->certify != 0 || (lines && sp->form != TS_FORM_GEOMETRIC);
    size_t budget = 16 * n + 64;
    size_t i = 0;
    while (i < n) {
        if (check_interval(sp, i, exact)) {
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
    sp->have_certs = exact;
    sp->certified = 1;
    return TS_OK;
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
    rep->certified = s->certified && check_ctl(s, i, B, geo ? X : NULL, s->have_certs, &cr);
    if (s->have_certs) {
        rep->gap_lower = s->gap_lo[i];
        rep->at_lower = s->at_lo[i];
        rep->gap_upper = s->gap_up[i];
        rep->at_upper = s->at_up[i];
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
