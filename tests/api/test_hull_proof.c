/* The line bound of docs/method.md §5.6 item 8 (paper and C¹ forms): an
 * interval is proved when min_l B_l − max(L(x_i), L(x_{i+1})) (lower line;
 * min(U) − max B upper) exceeds its rounding guard, before any minimum.
 *  - proved: random intervals with that difference 1e-3 .. 1e-12 of the
 *    values' size (above the guard, 16ε·3 = 1.1e-14 of it): ts_spline_certify
 *    certifies, the exact minimum re-derived here in long double (grid and
 *    golden section, docs/method.md §2, §5.6) is positive and equals the
 *    reported gap, and dense samples of ts_spline_eval stay on the line's side;
 *  - the bound fails, the minimum certifies: B = [0, 0, 1, 1] on [0, 1] and
 *    L = x − 0.15 (L(1) = 0.85 > min B = 0; the true minimum is 0.045 by
 *    hand and here): certified (the bound must not refuse);
 *  - near tie: flat B = 1 and a line whose right end is 2^-52 below it: the
 *    true gap is positive but below the guard, so it must go to the minimum,
 *    whose guard (8ε·2 at least) refuses it: not certified (a guard of 0 in
 *    the bound would certify it);
 *  - construction: line schemes in both forms, intervals all proved, the
 *    last one not proved, one not proved in a later block of 256; every
 *    result checked by ts_spline_certify and dense samples in long double. */
#include "th.h"
#include "th_options.h"
#include "common/th_gapmin.h"
#include "common/th_rng.h"
#include "trigspline.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>


static long double exact_min(const double B[4], double x0, double x1, double m, double c, int sign)
{
    long double Li = (long double)m * (long double)x0 + (long double)c;
    long double h = (long double)x1 - (long double)x0;
    long double C[4], kappa = sign * (long double)m * (2.0L * h / TH_LPI);
    for (int l = 0; l < 4; l++)
        C[l] = sign * ((long double)B[l] - Li);
    return th_gap_min(C, kappa, 2048);
}

/* A spline without shape through (x, f) with slopes d. */
static ts_spline *plain(const double *x, const double *f, const double *d, size_t np)
{
    ts_spline_options o;
    th_options_paper(&o);
    o.slopes = TS_SLOPES_USER;
    o.user_slopes = d;
    o.n_user_slopes = np;
    ts_spline *s = NULL;
    CHECK(ts_spline_new(x, f, np, &o, &s, NULL) == TS_OK);
    return s;
}

/* Dense samples: sign·(S(x) − m x − c) > 0 in long double (S as evaluated,
 * the line exact to 2^-63 relative, far below the margins used here). */
static long samples_outside(const ts_spline *s, double x0, double x1, double m, double c, int sign)
{
    long bad = 0;
    for (int k = 0; k <= 1000; k++) {
        double x = k == 1000 ? x1 : x0 + (x1 - x0) * (k / 1000.0), y;
        if (!(x <= x1))
            x = x1;
        CHECK(ts_spline_eval(s, x, NULL, &y) == TS_OK);
        long double gap = sign *
                          ((long double)y - ((long double)m * (long double)x + (long double)c));
        bad += !(gap > 0.0L);
    }
    return bad;
}

static void proved(void)
{
    TH_CASE("proved");
    th_rng r = TH_RNG_INIT(15);
    long n = 0, outside = 0;
    for (int it = 0; it < 300; it++) {
        double x[2] = {th_rng_range(&r, -10.0, 10.0), 0.0};
        x[1] = x[0] + th_rng_range(&r, 0.01, 5.0);
        double f[2] = {th_rng_range(&r, -3.0, 3.0), th_rng_range(&r, -3.0, 3.0)};
        double d[2] = {th_rng_range(&r, -2.0, 2.0), th_rng_range(&r, -2.0, 2.0)};
        ts_spline *s = plain(x, f, d, 2);
        ts_interval_report rep = TS_INTERVAL_REPORT_INIT;
        CHECK(ts_spline_report(s, 0, &rep) == TS_OK);
        int sign = it % 2 ? 1 : -1;
        double bmin = rep.B[0], bmax = rep.B[0], size = 0.0;
        for (int l = 0; l < 4; l++) {
            bmin = rep.B[l] < bmin ? rep.B[l] : bmin;
            bmax = rep.B[l] > bmax ? rep.B[l] : bmax;
            size = fabs(rep.B[l]) > size ? fabs(rep.B[l]) : size;
        }
        /* the line: slope m, its nearer end (lower: larger end value) rel·size beyond B */
        double m = th_rng_range(&r, -2.0, 2.0), rel = pow(10.0, -3.0 - 9.0 * (it % 10) / 9.0);
        double edge = sign > 0 ? bmin - rel * (size + 1.0) : bmax + rel * (size + 1.0);
        int right = (sign > 0) == (m > 0); /* the end where the line is nearest */
        double c = edge - m * (right ? x[1] : x[0]);
        /* the bound's difference in long double: above 64ε of the size */
        long double L0 = (long double)m * (long double)x[0] + (long double)c;
        long double L1 = (long double)m * (long double)x[1] + (long double)c;
        long double dd = sign > 0 ? (long double)bmin - (L0 > L1 ? L0 : L1)
                                  : (L0 < L1 ? L0 : L1) - (long double)bmax;
        CHECKF(dd > 64.0L * (long double)DBL_EPSILON *
                        ((long double)size + fabsl(L0) + fabsl(L1 - L0) + 1.0L),
               "it %d: setup d %Lg", it, dd);
        ts_line ln = {m, c};
        ts_interval_report cr = TS_INTERVAL_REPORT_INIT;
        ts_status st = ts_spline_certify(s, sign > 0 ? &ln : NULL, sign > 0 ? NULL : &ln, &cr, NULL);
        CHECKF(st == TS_OK && cr.certified, "it %d: not certified (d %Lg)", it, dd);
        long double g = exact_min(rep.B, x[0], x[1], m, c, sign);
        CHECKF(g > 0.0L, "it %d: exact min %Lg", it, g);
        /* the reported gap is the exact minimum: tolerance the certificate's
         * guard scale (docs/method.md §5.6, ≤ 1e3 ε of size) plus the grid's */
        double gap = sign > 0 ? cr.gap_lower : cr.gap_upper;
        CHECKF(fabsl((long double)gap - g) <=
                   1e3L * (long double)DBL_EPSILON *
                       ((long double)size + fabsl(L0) + fabsl(L1 - L0) + 1.0L),
               "it %d: gap %g against %Lg", it, gap, g);
        outside += samples_outside(s, x[0], x[1], m, c, sign);
        n++;
        ts_spline_free(s);
    }
    CHECK(n == 300);
    CHECKF(outside == 0, "%ld samples outside", outside);
}

static void bound_fails(void)
{
    TH_CASE("bound_fails_minimum_certifies");
    const double x[2] = {0.0, 1.0}, f[2] = {0.0, 1.0}, d[2] = {0.0, 0.0};
    ts_spline *s = plain(x, f, d, 2);
    ts_interval_report rep = TS_INTERVAL_REPORT_INIT;
    CHECK(ts_spline_report(s, 0, &rep) == TS_OK);
    CHECK(rep.B[0] == 0.0 && rep.B[1] == 0.0 && rep.B[2] == 1.0 && rep.B[3] == 1.0);
    ts_line ln = {1.0, -0.15};
    long double g = exact_min(rep.B, 0.0, 1.0, 1.0, -0.15, 1);
    /* by hand: s² + 0.15 − (2/π)θ, least at sin 2θ = 2/π: 0.0447 */
    CHECKF(g > 0.0447L && g < 0.0448L, "exact min %Lg", g);
    CHECK(1.0 * 1.0 - 0.15 > 0.0); /* L(1) = 0.85 > min B = 0: the bound fails */
    ts_interval_report cr = TS_INTERVAL_REPORT_INIT;
    CHECK(ts_spline_certify(s, &ln, NULL, &cr, NULL) == TS_OK && cr.certified == 1);
    CHECKF(fabsl((long double)cr.gap_lower - g) < 1e-12L, "gap %g", cr.gap_lower);
    CHECK(samples_outside(s, 0.0, 1.0, 1.0, -0.15, 1) == 0);
    ts_spline_free(s);
}

static void near_tie(void)
{
    TH_CASE("near_tie");
    const double x[2] = {0.0, 1.0}, f[2] = {1.0, 1.0}, d[2] = {0.0, 0.0};
    ts_spline *s = plain(x, f, d, 2);
    /* L(x) = 1e-3 x + c, c = 1 − 1e-3 − 2^-52 rounded; L(1) in long double */
    double m = 0x1p-10, c = 1.0 - 0x1p-10 - 0x1p-52; /* both exact */
    long double L1 = (long double)m + (long double)c, tie = 1.0L - L1;
    CHECKF(tie > 0.0L && tie < 16.0L * (long double)DBL_EPSILON * 2.0L, "tie %Lg", tie);
    long double g = exact_min((const double[4]){1.0, 1.0, 1.0, 1.0}, 0.0, 1.0, m, c, 1);
    CHECKF(g > 0.0L && g <= tie, "exact min %Lg", g);
    ts_line ln = {m, c};
    ts_interval_report cr = TS_INTERVAL_REPORT_INIT;
    CHECK(ts_spline_certify(s, &ln, NULL, &cr, NULL) == TS_ERR_VIOLATED && cr.certified == 0);
    /* the upper side, mirrored */
    ts_line up = {-m, -c + 2.0};
    CHECK(ts_spline_certify(s, NULL, &up, &cr, NULL) == TS_ERR_VIOLATED && cr.certified == 0);
    ts_spline_free(s);
}

/* Line schemes built: every interval checked by ts_spline_certify and samples. */
static void built(const double *x, const double *f, size_t np, ts_shape shape, ts_form form,
                  ts_line lo, ts_line up, const char *what)
{
    ts_spline_options o;
    th_options_paper(&o);
    o.shape = shape;
    o.form = form;
    o.lower = lo;
    o.upper = up;
    ts_spline *s = NULL;
    ts_status st = ts_spline_new(x, f, np, &o, &s, NULL);
    CHECKF(st == TS_OK, "%s form %d: %s", what, (int)form, ts_strerror(st));
    if (st != TS_OK)
        return;
    int hl = shape != TS_SHAPE_BELOW, hu = shape != TS_SHAPE_ABOVE;
    ts_interval_report *rep = malloc((np - 1) * sizeof *rep);
    ts_interval_report_init(rep, np - 1);
    CHECK(rep && ts_spline_certify(s, hl ? &lo : NULL, hu ? &up : NULL, rep, NULL) == TS_OK);
    long out = 0;
    for (size_t i = 0; i + 1 < np; i += (np > 40 ? 37 : 1)) {
        if (hl)
            out += samples_outside(s, x[i], x[i + 1], lo.m, lo.c, 1);
        if (hu)
            out += samples_outside(s, x[i], x[i + 1], up.m, up.c, -1);
        if (hl)
            CHECK(exact_min(rep[i].B, x[i], x[i + 1], lo.m, lo.c, 1) > 0.0L);
    }
    CHECKF(out == 0, "%s: %ld samples outside", what, out);
    free(rep);
    ts_spline_free(s);
}

static void construction(void)
{
    TH_CASE("construction");
    enum { NP = 700 };
    static double x[NP], f[NP];
    for (size_t k = 0; k < NP; k++) {
        x[k] = (double)k;
        f[k] = 3.5 + sin(0.3 * (double)k);
    }
    const ts_form forms[2] = {TS_FORM_PAPER, TS_FORM_C1};
    for (int fi = 0; fi < 2; fi++) {
        ts_line lo = {1e-4, 1.0}, up = {-1e-4, 5.0};
        built(x, f, NP, TS_SHAPE_ABOVE, forms[fi], lo, up, "above, all proved");
        built(x, f, NP, TS_SHAPE_BELOW, forms[fi], lo, up, "below, all proved");
        built(x, f, NP, TS_SHAPE_BETWEEN, forms[fi], lo, up, "between, all proved");
        /* a steep fall at the last interval, the line falling through it
         * (L(3) = 0.8 > f_4 = 0.5): the bound fails there only */
        const double xl[5] = {0, 1, 2, 3, 4}, fl[5] = {3.0, 3.0, 3.0, 3.0, 0.5};
        built(xl, fl, 5, TS_SHAPE_ABOVE, forms[fi], (ts_line){-0.4, 2.0}, up,
              "above, last not proved");
        /* a dip to 0.005 above a rising line at knot 600 (third block of
         * 256): L(601) > f_600, the bound fails on [600, 601] */
        static double f2[NP];
        memcpy(f2, f, sizeof f2);
        f2[600] = 1.0;
        built(x, f2, NP, TS_SHAPE_ABOVE, forms[fi], (ts_line){0.01, -5.005}, up,
              "above, one in a later block");
    }
}

int main(void)
{
    proved();
    bound_fails();
    near_tie();
    construction();
    return th_report("test_hull_proof");
}
