/* ts_spline_solve and ts_spline_find_interval.  Expected roots from closed
 * forms: the geometric form reproduces a line exactly (docs/method.md §4),
 * so S(x) = y at x = (y − c)/m; a paper-form interval with control values
 * symmetric about their mean (B0 + B3 = B1 + B2) takes that mean at its
 * midpoint (A0 = A3 and A1 = A2 at θ = π/4, docs/method.md §2); knots with
 * f_i = y are roots exactly.  Where no closed form exists, S(root) is
 * re-evaluated in long double from the basis of docs/method.md §2 (an
 * evaluation independent of the library's). */
#include "th.h"
#include "th_options.h"
#include "trigspline.h"

#include <float.h>
#include <math.h>
#include <stddef.h>

static ts_spline *fit(const double *x, const double *f, size_t n, ts_form form)
{
    ts_spline_options o;
    th_options_paper(&o);
    o.form = form;
    ts_spline *s = NULL;
    ts_status st = ts_spline_new(x, f, n, &o, &s, NULL);
    CHECKF(st == TS_OK, "fit: %s", ts_strerror(st));
    return s;
}

/* S(x) on interval i in long double, paper and C¹ forms (θ linear in x). */
static long double S_ref(const ts_spline *s, size_t i, double x)
{
    double B[4];
    (void)ts_spline_control(s, i, B, NULL);
    const double *k = ts_spline_x(s);
    long double th = 1.57079632679489661923132169163975144L * ((long double)x - (long double)k[i]) /
                     ((long double)k[i + 1] - (long double)k[i]);
    long double sn = sinl(th), c = cosl(th);
    long double A0 = (1 - sn) * (1 - sn) * (1 - sn), A1 = sn * (1 - sn) * (3 - sn);
    long double A2 = c * (1 - c) * (3 - c), A3 = (1 - c) * (1 - c) * (1 - c);
    return A0 * (long double)B[0] + A1 * (long double)B[1] + A2 * (long double)B[2] +
           A3 * (long double)B[3];
}

static void find_interval(void)
{
    TH_CASE("find_interval");
    static const double x[5] = {0, 1, 3, 4, 7}, f[5] = {1, 2, 0, 3, 1};
    ts_spline *s = fit(x, f, 5, TS_FORM_PAPER);
    if (!s)
        return;
    static const double q[8] = {0, 0.5, 1, 2.9, 3, 4, 6.99, 7};
    static const size_t want[8] = {0, 0, 1, 1, 2, 3, 3, 3}; /* right-hand at inner knots */
    size_t i;
    for (int j = 0; j < 8; j++) {
        CHECK(ts_spline_find_interval(s, q[j], NULL, &i) == TS_OK && i == want[j]);
    }
    ts_cursor cur = TS_CURSOR_INIT;
    for (int j = 0; j < 8; j++) /* sorted walk with a cursor: the same intervals */
        CHECK(ts_spline_find_interval(s, q[j], &cur, &i) == TS_OK && i == want[j] &&
              cur.interval == want[j]);
    cur.interval = 99; /* a stale cursor is only a hint */
    CHECK(ts_spline_find_interval(s, 3.5, &cur, &i) == TS_OK && i == 2 && cur.interval == 2);
    i = 5;
    CHECK(ts_spline_find_interval(s, -0.1, NULL, &i) == TS_ERR_DOMAIN && i == TS_NO_INDEX);
    i = 5;
    CHECK(ts_spline_find_interval(s, 7.5, NULL, &i) == TS_ERR_DOMAIN && i == TS_NO_INDEX);
    CHECK(ts_spline_find_interval(s, TH_NAN, NULL, &i) == TS_ERR_DOMAIN && i == TS_NO_INDEX);
    CHECK(ts_spline_find_interval(s, TH_INF, NULL, &i) == TS_ERR_DOMAIN);
    i = 5;
    CHECK(ts_spline_find_interval(NULL, 1.0, NULL, &i) == TS_ERR_NULL && i == TS_NO_INDEX);
    CHECK(ts_spline_find_interval(s, 1.0, NULL, NULL) == TS_ERR_NULL);
    ts_spline_free(s);
}

static void lines(void)
{
    TH_CASE("geometric form: a line, roots in closed form");
    /* f = 3x − 2 on uneven integer knots: every secant is exactly 3, every
     * slope method returns 3, and S is the line itself (docs/method.md §4) */
    static const double x[7] = {-4, -1, 0, 2, 3, 7, 8};
    double f[7];
    for (int i = 0; i < 7; i++)
        f[i] = 3.0 * x[i] - 2.0;
    ts_spline *s = fit(x, f, 7, TS_FORM_GEOMETRIC);
    if (!s)
        return;
    for (int k = 0; k <= 400; k++) {
        double y = f[0] + (f[6] - f[0]) * k / 400.0, r[4];
        size_t cnt = 99;
        ts_status st = ts_spline_solve(s, y, r, 4, &cnt);
        /* t is bisected to 4ε and X(t) is a convex combination of the
         * abscissae: an error of a few ε times the interval's width (<= 4)
         * and |x| (<= 8), plus the line's own reproduction (a few ε of |f|
         * <= 22 over the slope 3); 1e-13 covers them with a margin of ~10 */
        CHECKF(st == TS_OK && cnt == 1, "y %g: %s, %zu roots", y, ts_strerror(st), cnt);
        if (st == TS_OK && cnt == 1)
            CHECKF(fabs(r[0] - (y + 2.0) / 3.0) <= 1e-13, "y %.17g: %.17g, want %.17g", y, r[0],
                   (y + 2.0) / 3.0);
    }
    /* at the knots: the knot itself, exactly, once */
    for (int i = 0; i < 7; i++) {
        double r[4];
        size_t cnt = 0;
        CHECK(ts_spline_solve(s, f[i], r, 4, &cnt) == TS_OK && cnt == 1 && r[0] == x[i]);
    }
    /* beyond the data's range: none */
    size_t cnt = 9;
    CHECK(ts_spline_solve(s, f[6] + 1e-9, NULL, 0, &cnt) == TS_OK && cnt == 0);
    CHECK(ts_spline_solve(s, f[0] - 1e-9, NULL, 0, &cnt) == TS_OK && cnt == 0);
    ts_spline_free(s);
}

static void symmetric(void)
{
    TH_CASE("paper form: symmetric intervals, root at the midpoint");
    /* f = x on 0..4: every slope is 1, B = (i, i + K, i + 1 − K, i + 1):
     * symmetric, so S = i + 1/2 at the midpoint of interval i, and S is
     * strictly increasing (a monotone control polygon, (2.1)): one root */
    static const double x[5] = {0, 1, 2, 3, 4}, f[5] = {0, 1, 2, 3, 4};
    ts_spline *s = fit(x, f, 5, TS_FORM_PAPER);
    if (!s)
        return;
    for (int i = 0; i < 4; i++) {
        double r[2];
        size_t cnt = 0;
        CHECK(ts_spline_solve(s, i + 0.5, r, 2, &cnt) == TS_OK && cnt == 1);
        /* bisection in t to 4ε (t = tan(π/8) here), mapped by 2 atan t/(π/2):
         * a few ε of the width 1; 1e-15 */
        CHECKF(fabs(r[0] - (i + 0.5)) <= 1e-15, "interval %d: %.17g", i, r[0]);
    }
    /* monotone: exactly one root for every y strictly inside, and S there
     * equals y to the bisection's resolution times the slope (<= 2 here) */
    for (int k = 1; k < 1000; k++) {
        double y = 4.0 * k / 1000.0, r[2];
        size_t cnt = 0;
        CHECK(ts_spline_solve(s, y, r, 2, &cnt) == TS_OK && cnt == 1);
        size_t i;
        if (cnt == 1 && ts_spline_find_interval(s, r[0], NULL, &i) == TS_OK)
            CHECKF(fabsl(S_ref(s, i, r[0]) - (long double)y) <= 1e-14L, "y %g: S(%.17g) = %.17Lg",
                   y, r[0], S_ref(s, i, r[0]));
    }
    ts_spline_free(s);
}

static void near_knots(void)
{
    TH_CASE("roots within an ulp of a knot stay strictly inside the interval");
    /* f = x − 1e6 on x = 1e6, 1e6 + 1, 1e6 + 2 (a line: S = f exactly in the
     * geometric form, docs/method.md §4): y one ulp of 1 below 1 has its
     * root at x = 1e6 + 1 − 2^-53, which rounds to the knot 1e6 + 1; y one
     * ulp above 0 at 1e6 + 2^-1074, which rounds to the knot 1e6.  Expected:
     * the root reported strictly inside its interval, one ulp of x from the
     * knot (ts_spline_solve: the knots themselves are reported only where
     * f = y) */
    static const double x[3] = {1e6, 1e6 + 1, 1e6 + 2}, f[3] = {0, 1, 2};
    ts_spline *s = fit(x, f, 3, TS_FORM_GEOMETRIC);
    if (!s)
        return;
    double r[4];
    size_t cnt = 0;
    CHECK(ts_spline_solve(s, nextafter(1.0, 0.0), r, 4, &cnt) == TS_OK && cnt == 1);
    CHECKF(cnt == 1 && r[0] == nextafter(x[1], x[0]), "root %.17g", r[0]);
    CHECK(ts_spline_solve(s, 4.9406564584124654e-324, r, 4, &cnt) == TS_OK && cnt == 1);
    CHECKF(cnt == 1 && r[0] == nextafter(x[0], x[1]), "root %.17g", r[0]);
    ts_spline_free(s);
}

static void oscillating(void)
{
    TH_CASE("oscillating data: every crossing, touching, flat pieces");
    /* f = 0 1 0 1 0: inner slopes 0 (arithmetic mean of ±1), so intervals 1
     * and 2 have B = (1, 1, 0, 0) and (0, 0, 1, 1): symmetric, S = 1/2 at
     * 1.5 and 2.5; intervals 0 and 3 cross once each (monotone polygons) */
    static const double x[5] = {0, 1, 2, 3, 4}, f[5] = {0, 1, 0, 1, 0};
    ts_spline *s = fit(x, f, 5, TS_FORM_PAPER);
    if (!s)
        return;
    double r[8];
    size_t cnt = 0;
    CHECK(ts_spline_solve(s, 0.5, r, 8, &cnt) == TS_OK && cnt == 4);
    if (cnt == 4) {
        CHECK(0 < r[0] && r[0] < 1 && fabs(r[1] - 1.5) <= 1e-15 && fabs(r[2] - 2.5) <= 1e-15 &&
              3 < r[3] && r[3] < 4);
        CHECK(fabsl(S_ref(s, 0, r[0]) - 0.5L) <= 1e-15L &&
              fabsl(S_ref(s, 3, r[3]) - 0.5L) <= 1e-15L);
    }
    /* y = 1: S touches 1 at the knots 1 and 3 (maxima: S <= 1 by the hull
     * of (1, 1, 0, 0) and of the end intervals, whose polygons stay <= 1) */
    CHECK(ts_spline_solve(s, 1.0, r, 8, &cnt) == TS_OK && cnt == 2 && r[0] == 1.0 && r[1] == 3.0);
    /* y = 0: the knots 0, 2, 4, the last one too */
    CHECK(ts_spline_solve(s, 0.0, r, 8, &cnt) == TS_OK && cnt == 3 && r[0] == 0.0 && r[1] == 2.0 &&
          r[2] == 4.0);
    /* the size query and a short buffer */
    CHECK(ts_spline_solve(s, 0.5, NULL, 0, &cnt) == TS_ERR_LENGTH && cnt == 4);
    double part[2] = {TH_NAN, TH_NAN}, full[4];
    CHECK(ts_spline_solve(s, 0.5, full, 4, &cnt) == TS_OK && cnt == 4);
    CHECK(ts_spline_solve(s, 0.5, part, 2, &cnt) == TS_ERR_LENGTH && cnt == 4 &&
          part[0] == full[0] && part[1] == full[1]);
    ts_spline_free(s);

    /* flat pieces: f = 1 1 1 1 2 has slopes 0 0 0 0.5 1.5 (arithmetic), so
     * S == 1 on [0, 1] and [1, 2]; on [2, 3] S <= 1 (B2 = 1 − K/2) touching
     * 1 at both ends; on [3, 4] S > 1 after the knot.  As
     * scipy.interpolate.PPoly.solve: [x_i, NaN] per flat interval, then the
     * knots 2 and 3 (each once) */
    static const double xf[5] = {0, 1, 2, 3, 4}, ff[5] = {1, 1, 1, 1, 2};
    s = fit(xf, ff, 5, TS_FORM_PAPER);
    if (!s)
        return;
    CHECK(ts_spline_solve(s, 1.0, r, 8, &cnt) == TS_OK && cnt == 6);
    if (cnt == 6)
        CHECK(r[0] == 0.0 && isnan(r[1]) && r[2] == 1.0 && isnan(r[3]) && r[4] == 2.0 &&
              r[5] == 3.0);
    ts_spline_free(s);
}

static void errors(void)
{
    TH_CASE("solve: every status");
    static const double x[3] = {0, 1, 2}, f[3] = {0, 1, 0};
    ts_spline *s = fit(x, f, 3, TS_FORM_C1);
    if (!s)
        return;
    double r[4];
    size_t cnt = 7;
    CHECK(ts_spline_solve(NULL, 0.5, r, 4, &cnt) == TS_ERR_NULL && cnt == 0);
    CHECK(ts_spline_solve(s, 0.5, r, 4, NULL) == TS_ERR_NULL);
    cnt = 7;
    CHECK(ts_spline_solve(s, 0.5, NULL, 4, &cnt) == TS_ERR_NULL && cnt == 0);
    CHECK(ts_spline_solve(s, 0.5, r, 1, &cnt) == TS_ERR_LENGTH && cnt == 2);
    CHECK(ts_spline_solve(s, 0.5, r, 2, &cnt) == TS_OK && cnt == 2 && r[0] < 1.0 && r[1] > 1.0);
    /* no root for y beyond the range of S, NaN or ±Inf (|S| <= max |B|) */
    const double none[5] = {TH_NAN, TH_INF, -TH_INF, DBL_MAX, -0x1p1023};
    for (int k = 0; k < 5; k++) {
        cnt = 7;
        CHECK(ts_spline_solve(s, none[k], r, 4, &cnt) == TS_OK && cnt == 0);
    }
    ts_spline_free(s);
}

int main(void)
{
    find_interval();
    lines();
    symmetric();
    near_knots();
    oscillating();
    errors();
    return th_report("test_solve");
}
