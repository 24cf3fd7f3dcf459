/* docs/method.md §4, §5: per-interval certificates of a shape spline: exact gaps to a
 * line, the convex-hull and control-value proofs, their rounding guards.
 * Read-only: nothing here changes a spline.  Gaps are taken in the local
 * coordinates evaluation uses (docs/method.md §5.6): the paper and C¹ forms'
 * C_l = ±(B_l − L_i) with L_i = fma(m, x_i, c) rounded once, so the guard
 * added to the trigonometric minimum's (trigmin.c) is
 * 8ε (max|B| + |L_i| + |m| h) + |m| times the rounding of h, never |m x_i|. */
#include "internal.h"

#include <float.h>
#include <math.h>
#include <stdint.h>
#include <string.h>

#define TM_EPS DBL_EPSILON

/* docs/method.md §5.1 control-value proof (S = Σ A_l B_l, A_l >= 0,
 * Σ A_l = 1): f_i, f_{i+1} > 0 with B1, B2 >= 0 give S > 0, and with a zero
 * end (promise S >= 0) all B_l >= 0 give S >= 0; both read: every B_l >= 0.
 * Branch-free (used in vector loops). */
TS_INLINE int positive_proof(double B0, double B1, double B2, double B3)
{
    return (B0 >= 0.0) & (B1 >= 0.0) & (B2 >= 0.0) & (B3 >= 0.0);
}

/* docs/method.md §5.5: B monotone (either way) gives S' of one sign by
 * (2.1); it is the data's direction, as B0 = f_i, B3 = f_{i+1}, and equal
 * ends need equal control values (both directions at once).  Branch-free. */
TS_INLINE int monotone_proof(double B0, double B1, double B2, double B3)
{
    return ((B0 <= B1) & (B1 <= B2) & (B2 <= B3)) | ((B0 >= B1) & (B1 >= B2) & (B2 >= B3));
}

/* ------------------------------------------------------------------ */
/* Interval gaps                                                        */
/* ------------------------------------------------------------------ */

/* The guard of docs/method.md §5.6 (paper and C¹ forms) beyond the
 * trigonometric minimum's eb: the rounding of L_i = fma(m, x_i, c), of
 * C_l = ±(B_l − L_i) and of κ, and where evaluation places x, all in
 * 8ε (max|B| + |L_i| + |m| h), plus 4·2^-1074 for underflow. */
TS_INLINE double local_guard(double eb, double bmax, double Li, double am, double h)
{
    return eb + 8.0 * TM_EPS * (bmax + fabs(Li) + am * h) + 4.0 * DBL_TRUE_MIN;
}

/* docs/method.md §4: one control gap sg·(Y − m X − c) of the geometric form, to the
 * rounding of the gap itself (not of the line's size: a knot may lie 1e-14
 * of |c| above the line).  m X = p + e exactly (fma), Y − p = s1 + e1 and
 * s1 − c = s2 + e2 exactly (TwoSum), so the gap is s2 + e1 + e2 − e; the two
 * roundings summing the small terms and the last one add
 * ≤ u(1+u)(2(|e1| + |e2| + |e|) + |v|) < ε(...) (u = ε/2); *err is twice
 * that, plus 4·2^-1074 for a subnormal e.  Overflow gives NaN/Inf: never
 * above *err. */
TS_INLINE double ctl_gap(double Y, double X, double m, double c, double sg, double *err)
{
    double p = m * X, e = fma(m, X, -p);
    double s1 = Y - p, z1 = s1 - Y, e1 = (Y - (s1 - z1)) + (-p - z1);
    double s2 = s1 - c, z2 = s2 - s1, e2 = (s1 - (s2 - z2)) + (-c - z2);
    double v = s2 + ((e1 + e2) - e);
    *err = 2.0 * TM_EPS * (fabs(e1) + fabs(e2) + fabs(e) + fabs(v)) + 4.0 * DBL_TRUE_MIN;
    return sg * v;
}

/* docs/method.md §4 in the coordinates evaluation uses: x = x_i + h X̂(θ),
 * X̂ = Σ A_l X̂_l with X[] = X̂_l (ts__controls_of: [0, κ, 1 − κ, 1]), so
 * Y − L(x) = Σ A_l G_l with G_l = ±(Y_l − L(x_i) − m h X̂_l), L(x_i) taken
 * exactly (ctl_gap); err[l] bounds the rounding of G_l.  Independent of
 * |x_i|: the stored abscissae x_i + k, rounded to the grid of x, are not
 * used.  How far the evaluated curve (geometric.c) may be from this exact
 * one:
 *  - its position: u = (x − x_end)/h from the nearer end, the solve
 *    X̂(φ) = u, both to a few ε relative, so x is off by at most
 *    8ε h min(u, 1 − u); the line then by |m| times that.  Since
 *    A1 + A2 >= 1.6 min(u, 1 − u) for κ <= 0.62 (a >= a*; checked on a fine
 *    grid), subtracting S = 12ε |m| h from G_1, G_2 covers it and keeps the
 *    knots' gaps as they are (evaluation is exact there); and |m| times the
 *    rounding of h = fl(x_{i+1} − x_i) from all G_l;
 *  - Y's own rounding (a few ulps of |Y|) is not covered: as before, knot
 *    gaps of a few ulps are certified. */
TS_INLINE void geo_gaps_core(const double B[4], const double X[4], double x0, double x1, double m,
                             double c, double sg, double G[4], double err[4])
{
    double h = x1 - x0, mh = m * h;
    for (int l = 0; l < 4; l++) {
        double e0, g0 = ctl_gap(B[l], x0, m, c, sg, &e0);
        double t = mh * X[l];
        G[l] = g0 - sg * t;
        err[l] = e0 + 4.0 * TM_EPS * fabs(mh) + TM_EPS * fabs(G[l]);
    }
    /* h = fl(x_{i+1} − x_i) may differ from the true width (rarely: the
     * difference is exact when the knots are within a factor 2): measured
     * from the right end the curve sits that much aside */
    double eh = ts__width_error(x0, x1, h);
    for (int l = 0; l < 4; l++)
        G[l] -= fabs(m) * eh * (1.0 + 2.0 * TM_EPS);
    G[1] -= 12.0 * TM_EPS * fabs(mh);
    G[2] -= 12.0 * TM_EPS * fabs(mh);
}

static void geo_local_gaps(const ts_spline *sp, size_t i, const double B[4], const double X[4],
                           const ts_line *ln, int sign, double G[4], double err[4])
{
    geo_gaps_core(B, X, sp->x[i], sp->x[i + 1], ln->m, ln->c, sign > 0 ? 1.0 : -1.0, G, err);
}

/* The geometric form's hull proof against one line (m, c; sg = +1 lower,
 * −1 upper): every control gap above its rounding, or >= 0 where an end
 * touches a constant line (docs/method.md §5.8).  Branch-free. */
TS_INLINE int geo_hull(const double B[4], const double X[4], double x0, double x1, double m,
                       double c, double sg)
{
    int touch = (m == 0.0) & ((B[0] == c) | (B[3] == c));
    double G[4], err[4];
    geo_gaps_core(B, X, x0, x1, m, c, sg, G, err);
    int ok = 1;
    for (int l = 0; l < 4; l++) /* m = 0: G_l = ±fl(B_l − c), its sign exact */
        ok &= (G[l] > err[l]) | (touch & (G[l] >= 0.0));
    return ok;
}

/* docs/method.md §5.6 item 8, paper and C¹ forms: S >= min B_l (§2) and the
 * line's largest value on [x_i, x_{i+1}] is at an end, so
 * min_l sg·B_l − max(sg·L_i, sg·L_{i+1}) > guard proves the interval.
 * L_i = fma(m, x_i, c), L_{i+1} = L_i + m h (local coordinates); the guard
 * bounds their rounding, the subtraction's and |m| times the rounding of h.
 * Finite control values only.  Branch-free (used in vector loops). */
TS_INLINE int line_bound(double B0, double B1, double B2, double B3, double xi, double xi1,
                         double h, double m, double c, double sg)
{
    double Li = fma(m, xi, c), mh = m * h, Lr = Li + mh;
    double b0 = sg * B0, b1 = sg * B1, b2 = sg * B2, b3 = sg * B3;
    double lo = b0 < b1 ? b0 : b1, lo2 = b2 < b3 ? b2 : b3;
    lo = lo < lo2 ? lo : lo2;
    double l0 = sg * Li, l1 = sg * Lr, lmax = l0 > l1 ? l0 : l1;
    double a0 = fabs(B0), a1 = fabs(B1), a2 = fabs(B2), a3 = fabs(B3);
    double bmax = a0 > a1 ? a0 : a1, bmax2 = a2 > a3 ? a2 : a3;
    bmax = bmax > bmax2 ? bmax : bmax2;
    double guard = 16.0 * TM_EPS * (bmax + fabs(Li) + fabs(mh)) +
                   fabs(m) * ts__width_error(xi, xi1, h) * (1.0 + 2.0 * TM_EPS) + 4.0 * DBL_TRUE_MIN;
    int finite = (a0 <= TS_VALUE_MAX) & (a1 <= TS_VALUE_MAX) & (a2 <= TS_VALUE_MAX) &
                 (a3 <= TS_VALUE_MAX); /* NaN too: min and max above skip it */
    return finite & (lo - lmax > guard);
}

/* docs/method.md §5.6, §5.8: the control gaps C_l = ±(B_l − c) to a
 * constant line (signs exact: fl(B − c) has the sign of B − c), S − c =
 * Σ A_l C_l: all > 0 prove S > c; none < 0 with an end on the line (touched,
 * §5.8) prove S >= c.  Branch-free. */
TS_INLINE int const_line_proof(const double C[4])
{
    int pos = (C[0] > 0.0) & (C[1] > 0.0) & (C[2] > 0.0) & (C[3] > 0.0);
    int nonneg = (C[0] >= 0.0) & (C[1] >= 0.0) & (C[2] >= 0.0) & (C[3] >= 0.0);
    return pos | (nonneg & ((C[0] == 0.0) | (C[3] == 0.0)));
}

int ts__hull_inside(const ts_spline *sp, size_t i, const double B[4], const double *X,
                    const ts_line *ln, int sign)
{
    if (!X) {
        /* paper and C¹ forms: a constant line by its control gaps, or any
         * line by the bound */
        double C[4];
        for (int l = 0; l < 4; l++)
            C[l] = sign > 0 ? B[l] - ln->c : ln->c - B[l];
        return ((ln->m == 0.0) & const_line_proof(C)) |
               line_bound(B[0], B[1], B[2], B[3], sp->x[i], sp->x[i + 1], ts__h(sp, i), ln->m, ln->c,
                          sign > 0 ? 1.0 : -1.0);
    }
    return geo_hull(B, X, sp->x[i], sp->x[i + 1], ln->m, ln->c, sign > 0 ? 1.0 : -1.0);
}

double ts__gap_segment(const double B[4], double xi, double h, const ts_line *ln, int sign,
                       double *theta, double *tpar, double *guard, int *proven)
{
    double C[4], t, eb, m = ln->m, sg = sign > 0 ? 1.0 : -1.0, th, bmax = 0.0;
    for (int l = 0; l < 4; l++)
        bmax = fabs(B[l]) > bmax ? fabs(B[l]) : bmax;
    /* docs/method.md §5.6 in local coordinates, x = x_i + (2h/π)θ:
     * S − L = Σ A_l (B_l − L_i) − (2mh/π) θ since Σ A_l = 1, with
     * L_i = m x_i + c rounded once (m = 0: L_i = c exactly, κ = 0) */
    double Li = fma(m, xi, ln->c);
    for (int l = 0; l < 4; l++)
        C[l] = sg * (B[l] - Li);
    double kappa = m != 0.0 ? sg * m * (2.0 * h / TS_PI) : 0.0;
    double g = ts__trig_min_core(C[0], C[1], C[2], C[3], kappa, &th, &t, &eb);
    *theta = th;
    if (tpar)
        *tpar = t;
    if (guard)
        *guard = local_guard(eb, bmax, Li, fabs(m), h);
    /* a constant line (κ = 0, L_i = c exactly): the control gaps' proof */
    if (proven)
        *proven = (m == 0.0) & const_line_proof(C);
    return g;
}

/* Gap of interval i with control values B (and abscissae X in the geometric
 * form, else NULL) to a line: sign +1 min of S − L, −1 min of L − S.
 * *guard receives the rounding guard of that value. */
double ts__gap_ctl(const ts_spline *sp, size_t i, const double B[4], const double *X,
                   const ts_line *ln, int sign, double *at, double *guard)
{
    double xi = sp->x[i], h = ts__h(sp, i);
    if (!X) {
        double theta, t;
        double g = ts__gap_segment(B, xi, h, ln, sign, &theta, &t, guard, NULL);
        if (guard) /* the curve of width h measured from x_{i+1} (docs/method.md §5.6) */
            *guard += fabs(ln->m) * ts__width_error(xi, sp->x[i + 1], h) * (1.0 + 2.0 * TM_EPS);
        if (at)
            *at = isnan(g) ? (double)NAN : t >= 1.0 ? sp->x[i + 1] : xi + h * (theta / TS_HALF_PI);
        return g;
    }
    double G[4], err[4], t, eb, cerr = 0.0;
    geo_local_gaps(sp, i, B, X, ln, sign, G, err);
    for (int l = 0; l < 4; l++)
        cerr = err[l] > cerr ? err[l] : cerr;
    double g = ts__trig_min_core(G[0], G[1], G[2], G[3], 0.0, NULL, &t, &eb);
    if (at) {
        if (isnan(g)) {
            *at = (double)NAN;
        } else {
            double A[4];
            ts__basis_t(t, A);
            double u = A[0] * X[0] + A[1] * X[1] + A[2] * X[2] + A[3] * X[3];
            double xa = xi + h * u;
            *at = xa > sp->x[i + 1] ? sp->x[i + 1] : xa; /* u >= 0: xa >= xi */
        }
    }
    if (guard)
        *guard = eb + cerr;
    return g;
}

/* docs/method.md §5.9: the excursions beyond the end values B0 = S(x0), B3 = S(x1). */
static void set_excursions(const double B[4], ts_interval_report *rep)
{
    double hi = B[0] > B[3] ? B[0] : B[3], lo = B[0] < B[3] ? B[0] : B[3];
    double ea = rep->y_max - hi, eb = lo - rep->y_min;
    rep->excursion_above = ea <= 0.0 ? 0.0 : ea; /* +0 also for -0; NaN stays NaN */
    rep->excursion_below = eb <= 0.0 ? 0.0 : eb;
}

void ts__range_ctl(const ts_spline *sp, size_t i, const double B[4], const double *X,
                   ts_interval_report *rep)
{
    const ts_line zero = {0.0, 0.0};
    rep->y_min = ts__gap_ctl(sp, i, B, X, &zero, 1, &rep->at_y_min, NULL);
    rep->y_max = -ts__gap_ctl(sp, i, B, X, &zero, -1, &rep->at_y_max, NULL);
    set_excursions(B, rep);
}

void ts__range_segment(const double B[4], double ti, double h, ts_interval_report *rep)
{
    const ts_line zero = {0.0, 0.0};
    double th;
    rep->y_min = ts__gap_segment(B, ti, h, &zero, 1, &th, NULL, NULL, NULL);
    rep->at_y_min = ti + h * th / TS_HALF_PI;
    rep->y_max = -ts__gap_segment(B, ti, h, &zero, -1, &th, NULL, NULL, NULL);
    rep->at_y_max = ti + h * th / TS_HALF_PI;
    set_excursions(B, rep);
}

/* B of interval i; X (docs/method.md §4) only in the geometric form, the one that uses it. */
void ts__controls_of(const ts_spline *sp, size_t i, double B[4], double X[4], int *geo)
{
    ts__B(sp, i, B);
    *geo = sp->form == TS_FORM_GEOMETRIC;
    /* the local abscissae X̂_l of geometric.c (docs/method.md §4) */
    double kappa = *geo ? sp->kappa[i] : (double)NAN;
    X[0] = 0.0;
    X[1] = kappa;
    X[2] = 1.0 - kappa;
    X[3] = 1.0;
}

double ts__interval_gap(const ts_spline *sp, size_t i, const ts_line *line, int sign, double *at)
{
    double B[4], X[4];
    int geo;
    ts__controls_of(sp, i, B, X, &geo);
    return ts__gap_ctl(sp, i, B, geo ? X : NULL, line, sign, at, NULL);
}

/* ------------------------------------------------------------------ */
/* Per-interval certificate of a shape spline                          */
/* ------------------------------------------------------------------ */


/* Is interval i with controls B (X in the geometric form) inside the region
 * of sp's scheme?  exact: compute the trig-min certificates (into *cr, with
 * the places of the minima if want_at: the report's, not the build's);
 * otherwise only the control-value test, which is a proof by itself
 * (S = Σ A_l B_l, A_l >= 0, Σ A_l = 1, docs/method.md §2):
 *  positive, f_i, f_{i+1} > 0: B0, B3 > 0 and B1, B2 >= 0 give S > 0;
 *  positive with a zero end (promise S >= 0): all B_l >= 0;
 *  monotone: B monotone in the data's direction gives S' of that sign by
 *    (2.1) (and X' > 0 in the geometric form); no gaps (NaN);
 *  lines: in the geometric form every Y_l − m X_l − c above its rounding,
 *    in the others a constant line strictly beyond every B_l or the line
 *    bound (hull_inside, docs/method.md §5.6 item 8);
 *    with exact, also a trig-min gap above its guard will do.
 * Without want_at (the build, which keeps no gaps: ts_spline_report
 * recomputes them) a control-value proof that holds decides alone, and the
 * gaps it makes unnecessary are not computed (the same decision). */
int ts__check_ctl(const ts_spline *sp, size_t i, const double B[4], const double *X,
                  int exact, ts__cert *cr, int want_at)
{
    cr->glo = cr->alo = cr->gup = cr->aup = (double)NAN;
    double f0 = sp->f[i], f1 = sp->f[i + 1], guard;
    /* a control value beyond TS_VALUE_MAX (tiny a_i) proves nothing: S could
     * overflow (NaN where B overflowed); the repair raises a_i instead */
    for (int l = 0; l < 4; l++)
        if (!(fabs(B[l]) <= TS_VALUE_MAX))
            return 0;
    if (sp->shape == TS_SHAPE_MONOTONE) {
        int ok = monotone_proof(B[0], B[1], B[2], B[3]);
        if (X) {
            /* X' > 0 by (2.1) when D0, D2 > 0 and D1 >= -min(D0, D2)/4: at
             * a_i = 4/(3π) (TS_TERM_GEOMETRIC) D1 = h - 2k is 0 up to rounding.
             * min over θ of [(1-s)²c + (1-c)²s]/(sc) is 0.2426 (θ = π/4),
             * so X' >= sc·min(D0, D2)(3·0.2426 - 2/4) > 0 inside.  Here
             * D0 = κ > 0 and D2 = 1 − fl(1 − κ) >= 0 (X̂ of ts__controls_of,
             * or [0, 0, 1, 1] in the limit), so D1 >= 0 (a monotone polygon)
             * or D1 >= -min(D0, D2)/4 (then min > 0) is the whole test. */
            double D0 = X[1] - X[0], D1 = X[2] - X[1], D2 = X[3] - X[2];
            double dm = D0 < D2 ? D0 : D2;
            ok = ok & (D1 >= -0.25 * dm);
        }
        return ok;
    }
    if (sp->shape == TS_SHAPE_POSITIVE) {
        int zero_end = !(f0 > 0.0 && f1 > 0.0);
        int structural = positive_proof(B[0], B[1], B[2], B[3]);
        if (!exact || (structural && !want_at)) /* the build: the proof decides */
            return structural;
        cr->glo = ts__gap_ctl(sp, i, B, X, &sp->lower, 1, want_at ? &cr->alo : NULL, &guard);
        return structural || (!zero_end && cr->glo > guard);
    }
    int ok = 1;
    for (int side = 0; side < 2; side++) {
        if (!(side == 0 ? sp->has_lower : sp->has_upper))
            continue;
        const ts_line *ln = side == 0 ? &sp->lower : &sp->upper;
        int sign = side == 0 ? 1 : -1;
        /* the control gaps are a proof by themselves (geometric form; a
         * constant line in the others) */
        int hull = ts__hull_inside(sp, i, B, X, ln, sign);
        if (exact && !(hull && !want_at)) {
            double *g = side == 0 ? &cr->glo : &cr->gup, *a = side == 0 ? &cr->alo : &cr->aup;
            *g = ts__gap_ctl(sp, i, B, X, ln, sign, want_at ? a : NULL, &guard);
            ok = ok && (hull || *g > guard);
        } else {
            ok = ok && hull; /* the build's proof, or not exact (geometric form) */
        }
    }
    return ok;
}

int ts__check_interval(const ts_spline *sp, size_t i, int exact)
{
    double B[4], X[4];
    int geo;
    ts__cert cr;
    ts__controls_of(sp, i, B, X, &geo);
    return ts__check_ctl(sp, i, B, geo ? X : NULL, exact, &cr, 0);
}

/* opt->certify == 0 skips the trig-min certificates only where the
 * control-value test is a proof (positive, monotone, geometric form) */
int ts__certify_exact(const ts_spline_options *opt)
{
    int lines = opt->shape == TS_SHAPE_ABOVE || opt->shape == TS_SHAPE_BELOW ||
                opt->shape == TS_SHAPE_BETWEEN;
    return opt->certify != 0 || (lines && opt->form != TS_FORM_GEOMETRIC);
}

/* The control-value proof of interval i, not exact (check_ctl with
 * exact == 0): positive or monotone, paper and C¹ forms, finite controls. */
TS_INLINE int proven(const double *restrict f, const double *restrict b1,
                         const double *restrict b2, size_t i, int positive)
{
    double B0 = f[i], B1 = b1[i], B2 = b2[i], B3 = f[i + 1];
    int finite = (fabs(B1) <= TS_VALUE_MAX) & (fabs(B2) <= TS_VALUE_MAX);
    return finite & ((positive & positive_proof(B0, B1, B2, B3)) |
                     ((positive == 0) & monotone_proof(B0, B1, B2, B3)));
}

/* 1 if every interval of [i0, i1) is positive_proof'ed (a flag, so that it
 * vectorises). */
TS_VECTOR_LOOP static int all_proven_positive(const double *restrict f,
                                              const double *restrict b1,
                                              const double *restrict b2, size_t i0, size_t i1)
{
    int ok = 1;
    for (size_t i = i0; i < i1; i++)
        ok &= proven(f, b1, b2, i, 1);
    return ok;
}

/* The line bound (line_bound) of interval i for each line sp has (hl, hu;
 * paper and C¹ forms): ts__check_ctl's hull proof of every line, which
 * passes the interval without a gap. */
TS_INLINE int lines_bound(const double *restrict f, const double *restrict b1,
                          const double *restrict b2, const double *restrict x, size_t i,
                          const double lc[4], int hl, int hu)
{
    double B0 = f[i], B1 = b1[i], B2 = b2[i], B3 = f[i + 1], h = x[i + 1] - x[i];
    return ((1 - hl) | line_bound(B0, B1, B2, B3, x[i], x[i + 1], h, lc[0], lc[1], 1.0)) &
           ((1 - hu) | line_bound(B0, B1, B2, B3, x[i], x[i + 1], h, lc[2], lc[3], -1.0));
}

/* 1 if lines_bound passes every interval of [i0, i1) (a flag, so that it
 * vectorises). */
TS_VECTOR_LOOP static int all_bound(const double *restrict f, const double *restrict b1,
                                    const double *restrict b2, const double *restrict x,
                                    size_t i0, size_t i1, const double *restrict lc, int hl,
                                    int hu)
{
    int ok = 1;
    for (size_t i = i0; i < i1; i++)
        ok &= lines_bound(f, b1, b2, x, i, lc, hl, hu);
    return ok;
}

/* First interval of [i, i1) that lines_bound does not pass: blocks of
 * TS_BOUND_BLOCK at once (a failing interval costs one block, not the rest). */
#define TS_BOUND_BLOCK 256
static size_t skip_lines(const ts_spline *sp, size_t i, size_t i1)
{
    const double lc[4] = {sp->lower.m, sp->lower.c, sp->upper.m, sp->upper.c};
    int hl = sp->has_lower != 0, hu = sp->has_upper != 0;
    while (i < i1) {
        size_t k1 = i1 - i > TS_BOUND_BLOCK ? i + TS_BOUND_BLOCK : i1;
        if (!all_bound(sp->f, sp->b1, sp->b2, sp->x, i, k1, lc, hl, hu)) {
            /* the same operations fail one of [i, k1); the last is left to
             * the caller's check in any case */
            while (i + 1 < k1 && lines_bound(sp->f, sp->b1, sp->b2, sp->x, i, lc, hl, hu))
                i++;
            return i;
        }
        i = k1;
    }
    return i;
}

/* The geometric form's control-value proof of interval i as ts__check_ctl
 * (not exact) makes it, B from the knots (ts__B) and X̂ = (0, κ, 1 − κ, 1)
 * (ts__controls_of): finite B and, kind 0, positive_proof; 1, a monotone
 * polygon with X' > 0; 2, the hull proof of each line sp has (lc: lower m,
 * c, upper m, c; hl, hu).  Branch-free (used in vector loops). */
TS_INLINE int geo_proven(const double *restrict x, const double *restrict f,
                         const double *restrict d, const double *restrict al,
                         const double *restrict be, const double *restrict kappa, size_t i,
                         int kind, const double *restrict lc, int hl, int hu)
{
    double x0 = x[i], x1 = x[i + 1], a = al[i] + be[i], k = kappa[i];
    double B[4] = {f[i], 0.0, 0.0, f[i + 1]};
    B[1] = ts__geo_b1(x0, x1, B[0], d[i], a);
    B[2] = ts__geo_b2(x0, x1, B[3], d[i + 1], a);
    int finite = (fabs(B[0]) <= TS_VALUE_MAX) & (fabs(B[1]) <= TS_VALUE_MAX) &
                 (fabs(B[2]) <= TS_VALUE_MAX) & (fabs(B[3]) <= TS_VALUE_MAX);
    if (kind == 0)
        return finite & positive_proof(B[0], B[1], B[2], B[3]);
    double X[4] = {0.0, k, 1.0 - k, 1.0};
    if (kind == 1) {
        double D0 = X[1] - X[0], D1 = X[2] - X[1], D2 = X[3] - X[2];
        double dm = D0 < D2 ? D0 : D2;
        return finite & monotone_proof(B[0], B[1], B[2], B[3]) & (D1 >= -0.25 * dm);
    }
    return finite & ((1 - hl) | geo_hull(B, X, x0, x1, lc[0], lc[1], 1.0)) &
           ((1 - hu) | geo_hull(B, X, x0, x1, lc[2], lc[3], -1.0));
}

/* 1 if test (an expression of interval i) passes every interval of
 * [i0, i1) (a flag, so that it vectorises; one loop per test, constants in
 * each). */
#define TS_GEO_ALL(name, test)                                                                   \
    TS_VECTOR_LOOP static int name(const double *restrict x, const double *restrict f,          \
                                   const double *restrict d, const double *restrict al,         \
                                   const double *restrict be, const double *restrict kappa,     \
                                   size_t i0, size_t i1, const double *restrict lc)             \
    {                                                                                            \
        int ok = 1;                                                                              \
        for (size_t i = i0; i < i1; i++)                                                         \
            ok &= test;                                                                          \
        return ok;                                                                               \
    }
/* geo_proven of each kind and set of lines */
#define TS_GEO_ALL_PROVEN(name, kind, hl, hu)                                                    \
    TS_GEO_ALL(name, geo_proven(x, f, d, al, be, kappa, i, kind, lc, hl, hu))
TS_GEO_ALL_PROVEN(geo_all_positive, 0, 0, 0)
TS_GEO_ALL_PROVEN(geo_all_monotone, 1, 0, 0)
TS_GEO_ALL_PROVEN(geo_all_lower, 2, 1, 0)
TS_GEO_ALL_PROVEN(geo_all_upper, 2, 0, 1)
TS_GEO_ALL_PROVEN(geo_all_lines, 2, 1, 1)

/* docs/method.md §5.6 item 9: sg·(Y_l − L̂_0 − fl(m h) X̂_l) in plain
 * arithmetic above 32ε(max|B| + |L̂_0| + |m h|) + 16ε²(|m x_0| + |c|) +
 * 16·2^-1074 implies geo_hull's test of every control gap (it bounds the
 * rounding of both); κ <= 1 and no magnitude above 2^1019 (no overflow
 * there either).  Branch-free. */
TS_INLINE int geo_quick(const double B[4], double bmax, double k, double k2, double x0, double h,
                        double m, double c, double sg)
{
    double L0 = fma(m, x0, c), mh = m * h, px = fabs(m * x0);
    double w0 = sg * (B[0] - L0), w1 = sg * ((B[1] - L0) - mh * k);
    double w2 = sg * ((B[2] - L0) - mh * k2), w3 = sg * ((B[3] - L0) - mh);
    double lo = w0 < w1 ? w0 : w1, lo2 = w2 < w3 ? w2 : w3;
    lo = lo < lo2 ? lo : lo2;
    double S = bmax + fabs(L0) + fabs(mh), S2 = px + fabs(c);
    double guard = 32.0 * TM_EPS * S + 16.0 * TM_EPS * TM_EPS * S2 + 16.0 * DBL_TRUE_MIN;
    return (lo > guard) & (S + S2 <= 0x1p1019) & (k <= 1.0);
}

/* geo_quick of interval i for each line sp has (hl, hu; lc as geo_proven):
 * 1 only where geo_proven (kind 2) passes it.  Branch-free. */
TS_INLINE int geo_quick_proven(const double *restrict x, const double *restrict f,
                               const double *restrict d, const double *restrict al,
                               const double *restrict be, const double *restrict kappa, size_t i,
                               const double *restrict lc, int hl, int hu)
{
    double x0 = x[i], x1 = x[i + 1], a = al[i] + be[i], k = kappa[i], h = x1 - x0;
    double B[4] = {f[i], 0.0, 0.0, f[i + 1]};
    B[1] = ts__geo_b1(x0, x1, B[0], d[i], a);
    B[2] = ts__geo_b2(x0, x1, B[3], d[i + 1], a);
    double a0 = fabs(B[0]), a1 = fabs(B[1]), a2 = fabs(B[2]), a3 = fabs(B[3]);
    double bmax = a0 > a1 ? a0 : a1, bmax2 = a2 > a3 ? a2 : a3;
    bmax = bmax > bmax2 ? bmax : bmax2;
    double k2 = 1.0 - k;
    return ((1 - hl) | geo_quick(B, bmax, k, k2, x0, h, lc[0], lc[1], 1.0)) &
           ((1 - hu) | geo_quick(B, bmax, k, k2, x0, h, lc[2], lc[3], -1.0));
}

/* geo_quick_proven of each set of lines */
#define TS_GEO_ALL_QUICK(name, hl, hu)                                                           \
    TS_GEO_ALL(name, geo_quick_proven(x, f, d, al, be, kappa, i, lc, hl, hu))
TS_GEO_ALL_QUICK(geo_quick_lower, 1, 0)
TS_GEO_ALL_QUICK(geo_quick_upper, 0, 1)
TS_GEO_ALL_QUICK(geo_quick_lines, 1, 1)

/* ts__skip_proven in the geometric form (kind as geo_proven): blocks of
 * TS_BOUND_BLOCK at once, as skip_lines; lines: a block geo_quick passes
 * needs no error-free gaps (the same decision). */
static size_t skip_geo(const ts_spline *sp, size_t i, size_t i1, int kind)
{
    const double lc[4] = {sp->lower.m, sp->lower.c, sp->upper.m, sp->upper.c};
    int hl = sp->has_lower != 0, hu = sp->has_upper != 0;
    int (*all)(const double *restrict, const double *restrict, const double *restrict,
               const double *restrict, const double *restrict, const double *restrict, size_t,
               size_t, const double *restrict) =
        kind == 0 ? geo_all_positive
        : kind == 1 ? geo_all_monotone
        : hl && hu  ? geo_all_lines
        : hl        ? geo_all_lower
                    : geo_all_upper;
    int (*quick)(const double *restrict, const double *restrict, const double *restrict,
                 const double *restrict, const double *restrict, const double *restrict, size_t,
                 size_t, const double *restrict) =
        kind != 2  ? NULL
        : hl && hu ? geo_quick_lines
        : hl       ? geo_quick_lower
                   : geo_quick_upper;
    while (i < i1) {
        size_t k1 = i1 - i > TS_BOUND_BLOCK ? i + TS_BOUND_BLOCK : i1;
        if (quick && quick(sp->x, sp->f, sp->d, sp->alpha, sp->beta, sp->kappa, i, k1, lc)) {
            i = k1;
            continue;
        }
        if (!all(sp->x, sp->f, sp->d, sp->alpha, sp->beta, sp->kappa, i, k1, lc)) {
            while (i + 1 < k1 &&
                   geo_proven(sp->x, sp->f, sp->d, sp->alpha, sp->beta, sp->kappa, i, kind, lc, hl, hu))
                i++;
            return i;
        }
        i = k1;
    }
    return i;
}

/* First interval in [i, i1) that ts__check_ctl would not pass by its
 * control-value proof alone (which passes it also when exact): positive
 * and monotone, every form (the geometric form's X̂ are finite as
 * a_i >= 4/(3π)); lines, the bound in the paper and C¹ forms, the control
 * gaps in the geometric form; else i. */
size_t ts__skip_proven(const ts_spline *sp, size_t i, size_t i1)
{
    int positive = sp->shape == TS_SHAPE_POSITIVE;
    if (sp->form == TS_FORM_GEOMETRIC) {
        if (!(positive || sp->shape == TS_SHAPE_MONOTONE || sp->has_lower || sp->has_upper))
            return i;
        return skip_geo(sp, i, i1, positive ? 0 : sp->shape == TS_SHAPE_MONOTONE ? 1 : 2);
    }
    /* the paper and C¹ forms from here (the geometric form returned above) */
    if ((sp->has_lower | sp->has_upper) && !positive)
        return skip_lines(sp, i, i1);
    if (!(positive || sp->shape == TS_SHAPE_MONOTONE))
        return i;
    if (positive && all_proven_positive(sp->f, sp->b1, sp->b2, i, i1)) /* i < i1 */
        return i1;
    while (i < i1 && proven(sp->f, sp->b1, sp->b2, i, positive))
        i++;
    return i;
}

/* A block of exact certificates at once: for each interval i in
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
                                        size_t i0, size_t i1,
                                        double m, double c, double sg, int positive,
                                        unsigned char *restrict ok)
{
    const double am = fabs(m);
    for (size_t i = i0; i < i1; i++) {
        double B0 = f[i], B1 = b1[i], B2 = b2[i], B3 = f[i + 1];
        double xi = x[i], hi = x[i + 1] - x[i], bmax = 0.0;
        bmax = fabs(B0) > bmax ? fabs(B0) : bmax;
        bmax = fabs(B1) > bmax ? fabs(B1) : bmax;
        bmax = fabs(B2) > bmax ? fabs(B2) : bmax;
        bmax = fabs(B3) > bmax ? fabs(B3) : bmax;
        int good = (fabs(B0) <= TS_VALUE_MAX) & (fabs(B1) <= TS_VALUE_MAX) &
                   (fabs(B2) <= TS_VALUE_MAX) & (fabs(B3) <= TS_VALUE_MAX);
        double L0 = fma(m, xi, c);
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
        double b[7], best, babs;
        double at1;
        good &= ts__trig_min_ends(c0, c1, c2, c3, ks, b, &best, &at1, &babs);
        double gd = ts__trig_min_guard(0, babs, Ms, fabs(ks));
        double g = best * q, guard = local_guard(gd * q, bmax, L0, am, hi);
        guard += am * ts__width_error(xi, x[i + 1], hi) * (1.0 + 2.0 * TM_EPS); /* as gap_ctl */
        int pass = g > guard;
        /* positive: the control-value proof, or (both ends > 0) the gap */
        int ends_pos = (B0 > 0.0) & (B3 > 0.0);
        pass = (positive & positive_proof(B0, B1, B2, B3)) | (((positive == 0) | ends_pos) & pass);
        ok[i - i0] = (unsigned char)(good & pass & (M != 0.0));
    }
}

/* The external entry is a plain function: the ifunc resolver of a
 * TS_VECTOR_LOOP function with external linkage would be exported. */
void ts__mono_certify(const double *restrict f, const double *restrict b1,
                      const double *restrict b2, const double *restrict x, size_t i0, size_t i1,
                      double m, double c, double sg, int positive, unsigned char *restrict ok)
{
    mono_certify(f, b1, b2, x, i0, i1, m, c, sg, positive, ok);
}
