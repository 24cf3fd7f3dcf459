/* Certificates in local coordinates (issue 18, finding 9; docs/method.md
 * §5.6, §5.8), paper and C¹ forms, line schemes:
 *  - translation invariance: data at x0 = 1e6, 1e9, 1e12 with slope 1e9
 *    and with realistic slopes, and the same data shifted to x0 = 0 with the
 *    line translated exactly (c' = c + m x0, every shift and product exact:
 *    checked below).  Both copies must give the same status, the same a_i
 *    and gaps and the same values at every sample (the certificate and
 *    evaluation see only x − x_i, h, f and the line at x_i rounded once:
 *    bit for bit the same numbers).  Formerly the guard carried
 *    8ε(|m x_i| + |c|), 3.5 at x = 1e6 with slope 1e9: the offset copy was
 *    refused (TS_ERR_PRECISION) where the shifted one certified;
 *  - every certified interval is checked independently: dense samples of
 *    ts_spline_eval against the line in long double, and the exact minimum of
 *    g(θ) = Σ A_l(θ)(B_l − L(x_i)) − m (2h/π) θ (docs/method.md §2, §5.6)
 *    re-derived here in long double (grid and golden section), which must be
 *    positive and agree with the reported gap;
 *  - the 1e-14 example of the issue: data 1e-14 above y = 1 at every other
 *    knot (certified: a proof, see constant_line) and above a sloped line at
 *    x ≈ 1e6 (TS_ERR_PRECISION: see sloped_line);
 *  - negative controls: true gaps negative for every beta (TS_ERR_INFEASIBLE
 *    in both copies), a point on the line and one just across it at x ≈ 1e12
 *    (TS_ERR_SIDE, decided exactly);
 *  - the side of a line where a point equals the line's rounded value, and
 *    two lines whose doubles coincide (decided exactly, docs/method.md §5.8). */
#include "th.h"
#include "common/th_gapmin.h"
#include "common/th_rng.h"
#include "trigspline.h"

#include <float.h>
#include <math.h>
#include <string.h>

#define NP 9
#define PER 512

/* A line in the test's local form L(x) = m (x − x0) + c0 (c0 = its value at
 * x0), and the library's global form m x + c, c = c0 − m x0. */
typedef struct lline {
    double m, c0;
} lline;

static double fl_ulp(double v)
{
    return nextafter(fabs(v), TH_INF) - fabs(v);
}

/* c = c0 − m x0, checked exact: m x0 by fma, the sum by TwoSum. */
static double global_c(const lline *L, double x0)
{
    double p = L->m * x0, e = fma(L->m, x0, -p), c = L->c0 - p, z = c - L->c0;
    double es = (L->c0 - (c - z)) + (-p - z);
    CHECKF(e == 0.0 && es == 0.0, "line m = %g at x0 = %g: c not exact", L->m, x0);
    return c;
}

/* L(q) − y in long double for q = x0 + dq (dq exact): m·dq has ≤ 21 + 53
 * bits, so it and the sums round by ≤ 2^-63 of the largest term each;
 * *eb bounds that. */
static long double line_minus(const lline *L, double dq, double y, long double *eb)
{
    long double p = (long double)L->m * (long double)dq;
    long double v = p + (long double)L->c0 - (long double)y;
    *eb = 0x1p-61L * (fabsl(p) + fabsl((long double)L->c0) + fabsl((long double)y));
    return v;
}

/* The minimum of g(θ) = Σ A_l (B_l − L_i) − κ θ, κ = m (2h/π), over
 * [0, π/2] (sign +1; −1 for L − S), in long double on a 2048-point grid
 * refined by golden section (tests/common/th_gapmin.h). */
static long double exact_min(const double B[4], long double Li, double m, double h, int sign)
{
    long double C[4], kappa = sign * (long double)m * (2.0L * (long double)h / TH_LPI);
    for (int l = 0; l < 4; l++)
        C[l] = sign * ((long double)B[l] - Li);
    return th_gap_min(C, kappa, 2048);
}

typedef struct tally {
    long pairs, certified, refused, samples, outside;
} tally;

/* Build the data twice (x0 as given, and shifted to 0) and compare.
 * s[]: the abscissae minus x0 (exact), f[]: the values. */
static void compare(const double *s, const double *f, size_t np, double x0, const lline *lo,
                    const lline *up, ts_shape shape, ts_form form, ts_slopes slopes,
                    double alpha, tally *t, const char *what)
{
    double xa[NP], xb[NP];
    for (size_t k = 0; k < np; k++) {
        xa[k] = x0 + s[k];
        xb[k] = s[k];
        CHECKF(xa[k] - x0 == s[k], "%s: shift of point %zu not exact", what, k);
    }
    ts_spline_options oa, ob;
    ts_spline_options_init(&oa);
    oa.form = form;
    oa.shape = shape;
    oa.slopes = slopes;
    oa.alpha = alpha;
    ob = oa;
    if (lo) {
        oa.lower.m = ob.lower.m = lo->m;
        oa.lower.c = global_c(lo, x0);
        ob.lower.c = lo->c0;
    }
    if (up) {
        oa.upper.m = ob.upper.m = up->m;
        oa.upper.c = global_c(up, x0);
        ob.upper.c = up->c0;
    }
    ts_spline *A = NULL, *B = NULL;
    ts_error ea, eb;
    ts_status sa = ts_spline_new(xa, f, np, &oa, &A, &ea);
    ts_status sb = ts_spline_new(xb, f, np, &ob, &B, &eb);
    t->pairs++;
    CHECKF(sa == sb && ea.index == eb.index, "%s: at x0 %s (index %zu), shifted %s (index %zu)",
           what, ts_strerror(sa), ea.index, ts_strerror(sb), eb.index);
    if (sa != TS_OK || sb != TS_OK) {
        t->refused++;
        /* a refusal is one of the schemes' documented ones */
        CHECKF(sa == TS_ERR_INFEASIBLE || sa == TS_ERR_PRECISION || sa == TS_ERR_UNPROVEN ||
                   sa == TS_OK,
               "%s: %s", what, ts_strerror(sa));
        ts_spline_free(A);
        ts_spline_free(B);
        return;
    }
    t->certified++;
    CHECK(ts_spline_certified(A) && ts_spline_certified(B));
    for (size_t i = 0; i + 1 < np; i++) {
        ts_interval_report ra, rb;
        ts_spline_report(A, i, &ra);
        ts_spline_report(B, i, &rb);
        /* the same numbers on both sides (see the head comment): bit for bit */
        CHECKF(ra.a == rb.a && ra.certified && rb.certified &&
                   (!lo || ra.gap_lower == rb.gap_lower) && (!up || ra.gap_upper == rb.gap_upper),
               "%s interval %zu: a %.17g / %.17g, gaps %.17g / %.17g, %.17g / %.17g", what, i,
               ra.a, rb.a, ra.gap_lower, rb.gap_lower, ra.gap_upper, rb.gap_upper);
        double Bc[4];
        ts_spline_control(A, i, Bc, NULL);
        double h = xa[i + 1] - xa[i], bm = 0.0;
        for (int l = 0; l < 4; l++)
            bm = fabs(Bc[l]) > bm ? fabs(Bc[l]) : bm;
        for (int side = 0; side < 2; side++) {
            const lline *L = side == 0 ? lo : up;
            if (!L)
                continue;
            int sg = side == 0 ? 1 : -1;
            long double Li = (long double)L->m * (long double)s[i] + (long double)L->c0;
            long double gmin = exact_min(Bc, Li, L->m, h, sg);
            long double rep = (long double)(side == 0 ? ra.gap_lower : ra.gap_upper);
            /* the library's gap is within its guard of the exact one; the
             * guard is at most ~4e4 ε of the scale max|B| + |L_i| + |m| h
             * (trigmin.c at the deepest subdivision): 1e-11 of it */
            long double tol = 1e-11L * ((long double)bm + fabsl(Li) + fabsl((long double)L->m * (long double)h));
            CHECKF(gmin > 0 && fabsl(rep - gmin) <= tol,
                   "%s interval %zu side %d: exact min %.17Lg, reported %.17Lg", what, i, side,
                   gmin, rep);
        }
        long differ = 0;
        for (int k = 0; k <= PER; k++) {
            double q = xa[i] + h * (k / (double)PER), ya, yb;
            q = q > xa[i + 1] ? xa[i + 1] : q;
            double dq = q - x0; /* exact: x0 <= q <= 2 x0, or x0 = 0 */
            ts_spline_eval(A, q, NULL, &ya);
            ts_spline_eval(B, dq, NULL, &yb);
            differ += ya != yb;
            t->samples++;
            long double e, v;
            if (lo) {
                v = -line_minus(lo, dq, ya, &e); /* S − L */
                t->outside += !(v > e);
            }
            if (up) {
                v = line_minus(up, dq, ya, &e);
                t->outside += !(v > e);
            }
        }
        CHECKF(differ == 0, "%s interval %zu: %ld of %d samples differ from the shifted copy's",
               what, i, differ, PER + 1);
    }
    ts_spline_free(A);
    ts_spline_free(B);
}

/* Random sets: x0 = 1e6, 1e9, 1e12; slope 1e9 (spacings of 8 to 64 ulps of
 * x0: m h of 1 to 1e6) and realistic slopes 2.75 / 3 and −0.3125 / −0.25
 * (spacings 1 to 8); gaps a fraction of m h (steep) or of order one. */
static void translation(void)
{
    static const double offs[3] = {1e6, 1e9, 1e12};
    static const double slopes[3][2] = {{1e9, 1e9}, {2.75, 3.0}, {-0.3125, -0.25}};
    th_rng r = TH_RNG_INIT(1809);
    for (int oi = 0; oi < 3; oi++)
        for (int si = 0; si < 3; si++) {
            tally t = {0, 0, 0, 0, 0};
            double x0 = offs[oi];
            double h0 = si == 0 ? 8.0 * fl_ulp(x0) : 1.0;
            double G = fabs(slopes[si][0]) * h0; /* the rise over one unit spacing */
            G = G > 1.0 ? G : 1.0;
            /* parallel steep lines W apart (W a power of two >= 4G, so that
             * c0 − m x0 is exact); realistic ones diverge from 4G at x0 */
            double W = ldexp(1.0, (int)ceil(log2(4.0 * G)));
            lline lo = {slopes[si][0], 0.0}, up = {slopes[si][1], W};
            for (int shape = TS_SHAPE_ABOVE; shape <= TS_SHAPE_BETWEEN; shape++)
                for (int form = TS_FORM_PAPER; form <= TS_FORM_C1; form++)
                    for (int rep = 0; rep < 6; rep++) {
                        double s[NP], f[NP];
                        s[0] = 0.0;
                        for (int k = 1; k < NP; k++)
                            s[k] = s[k - 1] + h0 * (double)(1 + th_rng_below(&r, 8));
                        for (int k = 0; k < NP; k++) {
                            long double Llo = (long double)lo.m * (long double)s[k] + (long double)lo.c0;
                            long double Lup = (long double)up.m * (long double)s[k] + (long double)up.c0;
                            double u = th_rng_range(&r, 0.05, 1.0);
                            if (shape == TS_SHAPE_ABOVE)
                                f[k] = (double)(Llo + (long double)(G * u));
                            else if (shape == TS_SHAPE_BELOW)
                                f[k] = (double)(Lup - (long double)(G * u));
                            else
                                f[k] = (double)(Llo + (Lup - Llo) * (long double)(0.05 + 0.9 * u));
                        }
                        char what[96];
                        snprintf(what, sizeof what, "x0 %g slope %g shape %d form %d set %d", x0,
                                 lo.m, shape, form, rep);
                        compare(s, f, NP, x0, shape == TS_SHAPE_BELOW ? NULL : &lo,
                                shape == TS_SHAPE_ABOVE ? NULL : &up, (ts_shape)shape,
                                (ts_form)form, (ts_slopes)th_rng_below(&r, 6),
                                th_rng_logu(&r, 0.5, 2.0), &t, what);
                    }
            printf("x0 %-6g slope %-8g: %ld pairs, %ld certified, %ld refused (the same at x0 and "
                   "at 0); %ld samples, %ld outside\n",
                   x0, lo.m, t.pairs, t.certified, t.refused, t.samples, t.outside);
            CHECKF(t.outside == 0, "x0 %g slope %g: %ld samples outside", x0, lo.m, t.outside);
            /* not vacuous: most sets certify */
            CHECKF(t.certified * 2 >= t.pairs, "x0 %g slope %g: only %ld of %ld certified", x0,
                   lo.m, t.certified, t.pairs);
        }
}

/* The issue's example: x = 1e6 + k 2^-30 (m h = 0.93), y = 1e9 x − 1e15, gaps
 * about 1: formerly refused at x0 = 1e6 (guard 3.5), certified at 0. */
static void issue_example(void)
{
    static const double g[6] = {1.0, 1.3, 0.9, 1.2, 1.1, 1.0};
    double s[6], f[6];
    for (int k = 0; k < 6; k++) {
        s[k] = k * 0x1p-30;
        f[k] = 1e9 * s[k] + g[k]; /* 1e9 s exact; the sum rounds once */
    }
    lline lo = {1e9, 0.0};
    tally t = {0, 0, 0, 0, 0};
    compare(s, f, 6, 1e6, &lo, NULL, TS_SHAPE_ABOVE, TS_FORM_PAPER, TS_SLOPES_ARITHMETIC, 1.0, &t,
            "issue example, paper");
    compare(s, f, 6, 1e6, &lo, NULL, TS_SHAPE_ABOVE, TS_FORM_C1, TS_SLOPES_ARITHMETIC, 1.0, &t,
            "issue example, C1");
    CHECKF(t.certified == 2, "issue example: %ld of 2 certified", t.certified);
}

/* Data 1e-14 above y = 1 at every other knot, 2 between, harmonic slopes (0
 * at these inner extrema), at x = 0..6 and at 1e6 + 0..6.  Mathematically
 * certified: at the inner knots d = 0, so the control values there are f;
 * at the two end knots (f = 2) the rule of docs/method.md §5 keeps B1, B2
 * above 1 + δ by far (δ = fl(1 + 1e-14) − 1 > 0).  So every B_l >= 1 + δ
 * and S − 1 = Σ A_l (B_l − 1) >= δ (A_l >= 0, Σ A_l = 1), with equality at
 * the near knots: the exact minimum is δ.  In double the comparisons
 * B_l > 1 are exact, so the proof holds as computed, and evaluation (S = f
 * exactly at the knots, within a few ulps of |S| <= 2, i.e. 1e-15,
 * elsewhere) keeps every sample above 1.  Formerly refused with
 * TS_ERR_PRECISION (gap δ below the guard, about 1.2e-14). */
static void constant_line(void)
{
    for (int off = 0; off < 2; off++)
        for (int form = TS_FORM_PAPER; form <= TS_FORM_C1; form++) {
            double x[7], f[7];
            for (int k = 0; k < 7; k++) {
                x[k] = (off ? 1e6 : 0.0) + k;
                f[k] = k % 2 ? 1 + 1e-14 : 2;
            }
            double delta = (1 + 1e-14) - 1.0;
            ts_spline_options o;
            ts_spline_options_init(&o);
            o.form = (ts_form)form;
            o.shape = TS_SHAPE_ABOVE;
            o.slopes = TS_SLOPES_HARMONIC;
            o.lower.m = 0;
            o.lower.c = 1;
            ts_spline *s = NULL;
            ts_error e;
            ts_status st = ts_spline_new(x, f, 7, &o, &s, &e);
            CHECKF(st == TS_OK && ts_spline_certified(s), "1e-14, y = 1, form %d: %s at %zu", form,
                   ts_strerror(st), e.index);
            for (size_t i = 0; s && i < 6; i++) {
                ts_interval_report r;
                ts_spline_report(s, i, &r);
                /* the minimum is at the near knot, g(0) = f − 1 exactly */
                CHECKF(r.certified && r.gap_lower > 0 && fabs(r.gap_lower - delta) <= 1e-3 * delta,
                       "interval %zu: certified %d gap %.17g (exact %.17g)", i, r.certified,
                       r.gap_lower, delta);
                long bad = 0;
                for (int k = 0; k <= 4096; k++) {
                    double q = x[i] + k / 4096.0, y;
                    ts_spline_eval(s, q, NULL, &y);
                    bad += !(y > 1.0);
                }
                CHECKF(bad == 0, "interval %zu: %ld samples not above y = 1", i, bad);
            }
            ts_spline_free(s);
        }
}

/* The same with a sloped line at x ≈ 1e6: y = 0.5 (x − 1e6), every other
 * knot δ = 1e-14 above it, the others 1 above, user slopes 0.5 (the line's):
 * by (3.1) S − L = δ c² + s² + (h/2) ε_a(θ) on an interval from a near knot
 * (mirrored on the others), ε_a = s² + (2/(3πa))(A1 − A2) − 2θ/π, whose
 * derivative at the near knot is (1/a − 1)(2/π) (times h/2): the gap can
 * be no more than δ (the knot), and with a = 1 it is δ, attained at the
 * knots (its minimum, computed below for a = 1 on a grid refined near the
 * knots: positive, not
 * infeasible).  The certificate's
 * rounding bound there is above δ: 2·16ε (max|C_l| + |κ| π/2) >= 32ε·1 =
 * 7e-15 from the minimum's evaluation alone, plus 8ε (max|B| + |L_i| +
 * |m| h) >= 8ε·2.5 = 4.4e-15, i.e. > 1.1e-14 > δ: TS_ERR_PRECISION is the
 * correct answer (the message says "double precision").  Unchanged by the
 * fix (the old guard, 8ε·5e5, was larger still); here so that the status
 * and message stay right. */
static void sloped_line(void)
{
    double x[7], f[7], d[7];
    for (int k = 0; k < 7; k++) {
        x[k] = 1e6 + k;
        f[k] = 0.5 * k + (k % 2 ? 1e-14 : 1.0);
        d[k] = 0.5;
    }
    /* a = 1 (beta = 0, alpha = 1): the best gap, positive */
    for (int i = 0; i < 6; i++) {
        double K = 2.0 / (3.0 * TH_PI), B[4] = {f[i], f[i] + K * d[i], f[i + 1] - K * d[i + 1], f[i + 1]};
        long double g = exact_min(B, 0.5L * i, 0.5, 1.0, 1);
        long double knot = (long double)f[i % 2 ? i : i + 1] - 0.5L * (i % 2 ? i : i + 1);
        CHECKF(g > 0 && g >= knot * (1 - 1e-3L), "a = 1, interval %d: exact min %.6Lg, knot gap %.6Lg",
               i, g, knot);
    }
    for (int form = TS_FORM_PAPER; form <= TS_FORM_C1; form++) {
        ts_spline_options o;
        ts_spline_options_init(&o);
        o.form = (ts_form)form;
        o.shape = TS_SHAPE_ABOVE;
        o.slopes = TS_SLOPES_USER;
        o.user_slopes = d;
        o.n_user_slopes = 7;
        o.lower.m = 0.5;
        o.lower.c = -5e5;
        ts_spline *s = NULL;
        ts_error e;
        ts_status st = ts_spline_new(x, f, 7, &o, &s, &e);
        CHECKF(st == TS_ERR_PRECISION && e.where == TS_WHERE_INTERVAL && e.index < 6,
               "sloped 1e-14, form %d: %s at %zu", form, ts_strerror(st), e.index);
        ts_spline_free(s);
    }
    CHECK(strstr(ts_strerror(TS_ERR_PRECISION),
                 "cannot be certified in double precision: gap below the rounding bound") != NULL);
}

/* Negative controls.  (1) Gaps δ = 1e-3 m h at every knot of a steep line,
 * user slopes −m (against the line), alpha 1: on interval i,
 * S − L = δ + m h b(θ), b = (2/(3π))(uR A2 − uL A1) + s² − 2θ/π with
 * uL, uR in (0, 1] (the slope factors 1/a or 1/max a, paper and C¹ forms,
 * beta >= 0), so b <= b*(θ) = (2/(3π)) A2 + s² − 2θ/π; b*(0.4) is computed
 * below (≈ −0.086): every gap is below δ + m h b*(0.4) < 0 for every beta,
 * TS_ERR_INFEASIBLE at interval 0, at x0 and shifted (formerly TS_ERR_PRECISION
 * at x0 = 1e6: its guard 3.5 exceeded the gap).  (2) A point on the line and
 * one 1e-3 m h below it at x ≈ 1e12 (there m x rounds by 6.6e4 in double):
 * TS_ERR_SIDE at that point. */
static void negative(void)
{
    long double th = 0.4L, sn = sinl(th), cs = cosl(th);
    long double bstar = (2.0L / (3.0L * TH_LPI)) * cs * (1 - cs) * (3 - cs) + sn * sn - 2.0L * th / TH_LPI;
    CHECKF(bstar < -0.05L, "b*(0.4) = %.6Lg", bstar);
    static const double offs[2] = {1e6, 1e12};
    for (int oi = 0; oi < 2; oi++)
        for (int form = TS_FORM_PAPER; form <= TS_FORM_C1; form++) {
            double x0 = offs[oi], h0 = 8.0 * fl_ulp(x0), m = 1e9, s[6], f[6], d[6];
            for (int k = 0; k < 6; k++) {
                s[k] = k * h0;
                f[k] = m * s[k] + 1e-3 * m * h0; /* m s exact; one rounding */
                d[k] = -m;
            }
            for (int shift = 0; shift < 2; shift++) {
                double x[6];
                for (int k = 0; k < 6; k++)
                    x[k] = (shift ? 0.0 : x0) + s[k];
                ts_spline_options o;
                ts_spline_options_init(&o);
                o.form = (ts_form)form;
                o.shape = TS_SHAPE_ABOVE;
                o.slopes = TS_SLOPES_USER;
                o.user_slopes = d;
                o.n_user_slopes = 6;
                lline L = {m, 0.0};
                o.lower.m = m;
                o.lower.c = shift ? 0.0 : global_c(&L, x0);
                ts_spline *sp = NULL;
                ts_error e;
                ts_status st = ts_spline_new(x, f, 6, &o, &sp, &e);
                CHECKF(st == TS_ERR_INFEASIBLE && e.index == 0 && sp == NULL,
                       "negative x0 %g form %d shift %d: %s at %zu", x0, form, shift,
                       ts_strerror(st), e.index);
                ts_spline_free(sp);
            }
        }
    /* (2) on the line at point 2, across it at point 3 */
    double x0 = 1e12, h0 = 8.0 * fl_ulp(x0), m = 1e9, x[5], f[5];
    lline L = {m, 0.0};
    for (int k = 0; k < 5; k++) {
        x[k] = x0 + k * h0;
        f[k] = m * (k * h0) + (k == 2 ? 0.0 : k == 3 ? -1e-3 * m * h0 : m * h0);
    }
    ts_spline_options o;
    ts_spline_options_init(&o);
    o.shape = TS_SHAPE_ABOVE;
    o.lower.m = m;
    o.lower.c = global_c(&L, x0);
    ts_spline *sp = NULL;
    ts_error e;
    ts_status st = ts_spline_new(x, f, 5, &o, &sp, &e);
    CHECKF(st == TS_ERR_SIDE && e.index == 2 && e.where == TS_WHERE_POINT, "on the line: %s at %zu",
           ts_strerror(st), e.index);
    f[2] = m * (2 * h0) + 1e-3 * m * h0;
    st = ts_spline_new(x, f, 5, &o, &sp, &e);
    CHECKF(st == TS_ERR_SIDE && e.index == 3, "across: %s at %zu", ts_strerror(st), e.index);
    /* below: the mirror image (point 3 above the upper line) */
    for (int k = 0; k < 5; k++)
        f[k] = -f[k];
    o.shape = TS_SHAPE_BELOW;
    o.upper.m = -m;
    o.upper.c = -o.lower.c;
    st = ts_spline_new(x, f, 5, &o, &sp, &e);
    CHECKF(st == TS_ERR_SIDE && e.index == 3, "below, across: %s at %zu", ts_strerror(st), e.index);
    ts_spline_free(sp);
}

/* The data check decides the side exactly (docs/method.md §5.8) where the
 * point equals the line's rounded value: on y = 0.1 x (c = 0), fl(0.1·3)
 * lies 2.8e-17 above 0.1·3 and fl(0.1·5) 2.8e-17 below 0.1·5 (0.1 the
 * double; 0.1 x is exact in long double: 55 bits, so the test checks the
 * sides itself).  Formerly f − (m x + c) = 0 made both "on the line". */
static void exact_side(void)
{
    double x[7], f[7];
    for (int k = 0; k < 7; k++) {
        x[k] = k;
        f[k] = 0.1 * k + 1.0;
    }
    double f3 = 0.1 * 3, f5 = 0.1 * 5;
    CHECK((long double)f3 > (long double)0.1 * 3 && (long double)f5 < (long double)0.1 * 5);
    for (int form = TS_FORM_PAPER; form <= TS_FORM_C1; form++) {
        ts_spline_options o;
        ts_spline_options_init(&o);
        o.form = (ts_form)form;
        o.shape = TS_SHAPE_ABOVE;
        o.lower.m = 0.1;
        o.lower.c = 0.0;
        ts_spline *s = NULL;
        ts_error e;
        /* point 3 above by 2.8e-17, point 5 below: refused at 5 */
        f[3] = f3, f[5] = f5;
        ts_status st = ts_spline_new(x, f, 7, &o, &s, &e);
        CHECKF(st == TS_ERR_SIDE && e.index == 5, "above, form %d: %s at %zu", form, ts_strerror(st),
               e.index);
        /* point 3 alone: above, by far less than the rounding bound; the
         * arithmetic mean slope there is 0.1 (secants -0.9, 1.1), the
         * line's, so no beta lifts the curve: not certifiable in double */
        f[5] = 0.1 * 5 + 1.0;
        st = ts_spline_new(x, f, 7, &o, &s, &e);
        CHECKF(st == TS_ERR_PRECISION && (e.index == 2 || e.index == 3),
               "above, form %d: %s at %zu", form, ts_strerror(st), e.index);
        ts_spline_free(s);
    }
    /* below the same line: point 3 is across it */
    for (int k = 0; k < 7; k++)
        f[k] = 0.1 * k - 1.0;
    f[3] = f3;
    ts_spline_options o;
    ts_spline_options_init(&o);
    o.shape = TS_SHAPE_BELOW;
    o.upper.m = 0.1;
    o.upper.c = 0.0;
    ts_spline *s = NULL;
    ts_error e;
    ts_status st = ts_spline_new(x, f, 7, &o, &s, &e);
    CHECKF(st == TS_ERR_SIDE && e.index == 3, "below: %s at %zu", ts_strerror(st), e.index);
    /* between y = 0.1 x and y = 0.1 x + 1e-300: the lines are ordered at
     * every point (exactly; their doubles coincide from x = 1 on), but no
     * double lies strictly between them there: TS_ERR_SIDE at 1, not
     * TS_ERR_LINES */
    o.shape = TS_SHAPE_BETWEEN;
    o.lower.m = 0.1;
    o.lower.c = 0.0;
    o.upper.c = 1e-300;
    f[0] = 5e-301;
    for (int k = 1; k < 7; k++)
        f[k] = 0.1 * k;
    st = ts_spline_new(x, f, 7, &o, &s, &e);
    CHECKF(st == TS_ERR_SIDE && e.index == 1, "between: %s at %zu", ts_strerror(st), e.index);
    ts_spline_free(s);
}

int main(void)
{
    TH_CASE("issue example");
    issue_example();
    TH_CASE("translation invariance");
    translation();
    TH_CASE("1e-14 above a constant line");
    constant_line();
    TH_CASE("1e-14 above a sloped line");
    sloped_line();
    TH_CASE("negative controls");
    negative();
    TH_CASE("exact side of a line");
    exact_side();
    return th_report("test_local_certify");
}
