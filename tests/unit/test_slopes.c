/* Tests of the slope estimates (docs/method.md §6): src/slopes.c.
 *
 * Sources of the expected values:
 *  - closed forms: lines (every method exact), quadratics (arithmetic mean and
 *    Akima with three uniform points), the central difference of sin;
 *  - hand computation from the published formulas (comments below);
 *  - tests/ref/slopes_ref.py: exact rational / 60-digit reference written
 *    separately from the C code (Fritsch–Carlson RPN 14 data and three other
 *    sets); its output is checked in as tests/ref/slopes_ref.h.
 */
#include "th.h"
#include "internal.h"
#include "trigspline.h"

#include "ref/slopes_ref.h"

#include <float.h>
#include <math.h>
#include <stdlib.h>
#include <string.h>

#define EPS DBL_EPSILON

static const ts_slopes ALL[] = {TS_SLOPES_ARITHMETIC, TS_SLOPES_GEOMETRIC,
                                TS_SLOPES_HARMONIC,   TS_SLOPES_FRITSCH_CARLSON,
                                TS_SLOPES_AKIMA,      TS_SLOPES_MAKIMA};
#define NALL (sizeof ALL / sizeof ALL[0])

static const char *mname(ts_slopes m)
{
    static const char *names[] = {"arithmetic", "geometric", "harmonic", "fritsch-carlson",
                                  "akima", "makima", "user", "periodic"};
    return ((int)m >= 0 && (int)m < TS_SLOPES_COUNT_) ? names[m] : "?";
}

static double max_abs_secant(const double *x, const double *f, size_t np)
{
    double s = 0.0;
    for (size_t i = 0; i + 1 < np; i++) {
        double D = fabs((f[i + 1] - f[i]) / (x[i + 1] - x[i]));
        if (D > s)
            s = D;
    }
    return s;
}

/* Heap copy of exactly np doubles, so ASan sees any access past the end. */
static double *dup(const double *a, size_t np)
{
    double *p = malloc(np * sizeof *p);
    if (p)
        memcpy(p, a, np * sizeof *p);
    return p;
}

/* ts_slopes_compute on heap copies; d receives np values. */
static ts_status slopes(ts_slopes m, const double *x, const double *f, size_t np, double *d,
                        ts_error *err)
{
    double *xx = dup(x, np), *ff = dup(f, np), *dd = malloc(np * sizeof *dd);
    ts_status st = TS_ERR_NOMEM;
    if (xx && ff && dd) {
        st = ts_slopes_compute(m, xx, ff, np, dd, err);
        memcpy(d, dd, np * sizeof *d);
    }
    free(xx);
    free(ff);
    free(dd);
    return st;
}

/* ---- two points: every method gives Δ0 (docs/method.md §6) ---------------------- */
static void test_two_points(void)
{
    const double x[2] = {1.0, 3.0}, f[2] = {2.0, 7.0}; /* Δ0 = 2.5 exactly */
    double d[2];
    for (size_t k = 0; k < NALL; k++) {
        ts_status st = slopes(ALL[k], x, f, 2, d, NULL);
        CHECKF(st == TS_OK && d[0] == 2.5 && d[1] == 2.5, "%s: %d %g %g", mname(ALL[k]),
               (int)st, d[0], d[1]);
    }
    /* periodic with two points needs f0 == f1, so Δ0 = 0 */
    const double fc[2] = {4.0, 4.0};
    CHECK(slopes(TS_SLOPES_PERIODIC, x, fc, 2, d, NULL) == TS_OK && d[0] == 0.0 && d[1] == 0.0);
}

/* ---- lines: every method reproduces the slope -------------------------- */
static void test_linear(void)
{
    /* dyadic abscissae and slopes: f and every Δ are exact, so every method
     * must return the slope exactly (a weighted mean of equal values). */
    const double x[7] = {-1.0, -0.5, 0.25, 1.0, 2.5, 3.0, 5.125};
    const double ms[3] = {2.5, -0.75, 0.0};
    double f[7], d[7];
    for (int s = 0; s < 3; s++) {
        for (int i = 0; i < 7; i++)
            f[i] = ms[s] * x[i] - 1.0;
        for (size_t k = 0; k < NALL; k++) {
            ts_status st = slopes(ALL[k], x, f, 7, d, NULL);
            CHECK(st == TS_OK);
            for (int i = 0; i < 7; i++)
                CHECKF(d[i] == ms[s], "%s slope %g: d[%d] = %.17g", mname(ALL[k]), ms[s], i, d[i]);
        }
        for (size_t np = 2; np <= 3; np++) { /* shortest cases */
            for (size_t k = 0; k < NALL; k++) {
                ts_status st = slopes(ALL[k], x, f, np, d, NULL);
                CHECK(st == TS_OK);
                for (size_t i = 0; i < np; i++)
                    CHECKF(d[i] == ms[s], "%s np %zu: d[%zu] = %.17g", mname(ALL[k]), np, i, d[i]);
            }
        }
    }
    /* constant data also is periodic data */
    for (int i = 0; i < 7; i++)
        f[i] = -1.0;
    CHECK(slopes(TS_SLOPES_PERIODIC, x, f, 7, d, NULL) == TS_OK);
    for (int i = 0; i < 7; i++)
        CHECK(d[i] == 0.0);

    /* a line sampled at decimal abscissae: f is rounded, so the secants
     * differ by rounding.  |error of Δ| <= 2 eps max|f| / min h (two rounded
     * values over a rounded width, first order), and every estimate is a
     * weighted mean of at most four secants or the end formula, whose
     * coefficients sum in absolute value to <= 3: tolerance 3 * 2 eps max|f|
     * / min h, times 2 for the rounding of the formulas themselves. */
    const double xd[6] = {0.1, 0.3, 0.7, 1.1, 1.3, 1.9};
    double fd[6], maxf = 0.0;
    for (int i = 0; i < 6; i++) {
        fd[i] = 3.7 * xd[i] + 0.2;
        if (fabs(fd[i]) > maxf)
            maxf = fabs(fd[i]);
    }
    double tol = 2.0 * 3.0 * 2.0 * EPS * maxf / 0.2;
    for (size_t k = 0; k < NALL; k++) {
        CHECK(slopes(ALL[k], xd, fd, 6, d, NULL) == TS_OK);
        for (int i = 0; i < 6; i++)
            CHECK_CLOSE(d[i], 3.7, tol);
    }
}

/* ---- quadratics: the arithmetic mean is exact, ends included ----------- */
static void test_quadratic(void)
{
    /* The three-point formulas of docs/method.md §6 are the derivatives of the parabola
     * through three consecutive points, so f = 3x^2 - 2x + 1 gives
     * d_i = 6 x_i - 2 exactly on any grid. */
    const double x[7] = {-1.0, -0.5, 0.25, 1.0, 2.5, 3.0, 5.125};
    double f[7], d[7], maxf = 0.0;
    for (int i = 0; i < 7; i++) {
        f[i] = 3.0 * x[i] * x[i] - 2.0 * x[i] + 1.0; /* exact (dyadic) */
        if (fabs(f[i]) > maxf)
            maxf = fabs(f[i]);
    }
    CHECK(slopes(TS_SLOPES_ARITHMETIC, x, f, 7, d, NULL) == TS_OK);
    /* f exact, each Δ one rounding; coefficients of the formulas sum to <= 3
     * in absolute value: 3 * (2 eps max|f| / min h) is ample; min h = 0.5. */
    double tol = 3.0 * 2.0 * EPS * maxf / 0.5;
    for (int i = 0; i < 7; i++)
        CHECK_CLOSE(d[i], 6.0 * x[i] - 2.0, tol);
    /* three points only: still the parabola */
    CHECK(slopes(TS_SLOPES_ARITHMETIC, x + 2, f + 2, 3, d, NULL) == TS_OK);
    for (int i = 0; i < 3; i++)
        CHECK_CLOSE(d[i], 6.0 * x[i + 2] - 2.0, tol);
    /* the other means are not exact on quadratics: make sure the check above
     * could fail (harmonic at x = 1 differs by far more than tol) */
    CHECK(slopes(TS_SLOPES_HARMONIC, x, f, 7, d, NULL) == TS_OK);
    CHECK(fabs(d[3] - 4.0) > 1e-3);

    /* Akima with three equally spaced points: the ghost secants make all
     * weights equal, so d = averages of neighbouring (ghost) secants, which are
     * the slopes of the parabola: f = x^2 on 0, 1, 2 -> d = 0, 2, 4. */
    const double xq[3] = {0.0, 1.0, 2.0}, fq[3] = {0.0, 1.0, 4.0};
    CHECK(slopes(TS_SLOPES_AKIMA, xq, fq, 3, d, NULL) == TS_OK);
    CHECK(d[0] == 0.0 && d[1] == 2.0 && d[2] == 4.0);
}

/* ---- hand values of the means ------------------------------------------ */
static void test_means_by_hand(void)
{
    double d[5];
    /* uniform x = 0..4, f = 0 2 10 9 5: Δ = 2, 8, -1, -4.
     * arithmetic: d1 = (2+8)/2 = 5, d2 = 3.5, d3 = -2.5,
     *   d0 = 2 + (2-8)/2 = -1, d4 = -4 + (-4+1)/2 = -5.5.
     * geometric: d1 = sqrt(16) = 4, d2 = 0 (sign change), d3 = -sqrt(4) = -2,
     *   ends sign-limited: d0 = -1 has the wrong sign -> 0, d4 = -5.5 kept.
     * harmonic (uniform: 2ab/(a+b)): d1 = 32/10 = 3.2, d2 = 0, d3 = 8/-5 = -1.6,
     *   ends as geometric.
     * pchip: Brodlie weights are equal on a uniform grid, so the interior is
     *   the harmonic one; ends: d0 -> 0 (sign), d4 = -5.5 (Δ3, Δ2 same sign:
     *   no 3Δ limit). */
    const double x[5] = {0, 1, 2, 3, 4}, f[5] = {0, 2, 10, 9, 5};
    const double ea[5] = {-1, 5, 3.5, -2.5, -5.5}, eg[5] = {0, 4, 0, -2, -5.5},
                 eh[5] = {0, 3.2, 0, -1.6, -5.5};
    const double *exp_[4] = {ea, eg, eh, eh};
    for (int k = 0; k < 4; k++) {
        CHECK(slopes(ALL[k], x, f, 5, d, NULL) == TS_OK);
        for (int i = 0; i < 5; i++) /* a few roundings of numbers <= 10 */
            CHECKF(fabs(d[i] - exp_[k][i]) <= 8 * EPS * 10, "%s d[%d] = %.17g, want %g",
                   mname(ALL[k]), i, d[i], exp_[k][i]);
    }

    /* non-uniform: x = 0 1 3, f = 0 1 9 (= x^2): Δ = 1, 4, h = 1, 2.
     * weights at x = 1: three-point w = h1/(h0+h1) = 2/3 on Δ0, 1/3 on Δ1.
     * arithmetic 2/3 + 4/3 = 2 (= 2x), geometric 1^(2/3) 4^(1/3) = cbrt 4,
     * harmonic 1/(2/3 + 1/12) = 4/3, Brodlie w1 = 2h1+h0 = 5, w2 = h1+2h0 = 4:
     * 9/(5/1 + 4/4) = 1.5.  Ends: three-point = parabola = 0 and 6; 0 stays 0,
     * 6 has the sign of Δ1, and Δ0, Δ1 agree (no 3Δ limit). */
    const double xn[3] = {0, 1, 3}, fn[3] = {0, 1, 9};
    const double want[4] = {2.0, cbrt(4.0), 4.0 / 3.0, 1.5};
    for (int k = 0; k < 4; k++) {
        CHECK(slopes(ALL[k], xn, fn, 3, d, NULL) == TS_OK);
        CHECK_CLOSE(d[0], 0.0, 8 * EPS * 9);
        CHECK_CLOSE(d[1], want[k], 8 * EPS * 9);
        CHECK_CLOSE(d[2], 6.0, 8 * EPS * 9);
    }

    /* Fritsch–Carlson 3Δ limit at the ends: x = 0 1 2, f = 0 1 -9: Δ = 1, -10.
     * left: three-point 1 + 11/2 = 6.5, sign of Δ0 but Δ0, Δ1 differ in sign
     * and 6.5 > 3|Δ0| -> 3.  right: -10 + (-10-1)/2 = -15.5, |.| <= 30 kept.
     * interior: sign change -> 0.  Geometric/harmonic only sign-limit: 6.5. */
    const double x3[3] = {0, 1, 2}, f3[3] = {0, 1, -9};
    CHECK(slopes(TS_SLOPES_FRITSCH_CARLSON, x3, f3, 3, d, NULL) == TS_OK);
    CHECK(d[0] == 3.0 && d[1] == 0.0 && d[2] == -15.5);
    CHECK(slopes(TS_SLOPES_GEOMETRIC, x3, f3, 3, d, NULL) == TS_OK);
    CHECK(d[0] == 6.5 && d[1] == 0.0 && d[2] == -15.5);
    /* mirrored: f = -9 1 0: Δ = 10, -1; right end -1 + (-1-10)/2 = -6.5 -> -3 */
    const double f4[3] = {-9, 1, 0};
    CHECK(slopes(TS_SLOPES_FRITSCH_CARLSON, x3, f4, 3, d, NULL) == TS_OK);
    CHECK(d[0] == 15.5 && d[1] == 0.0 && d[2] == -3.0);
    CHECK(slopes(TS_SLOPES_HARMONIC, x3, f4, 3, d, NULL) == TS_OK);
    CHECK(d[0] == 15.5 && d[1] == 0.0 && d[2] == -6.5);

    /* extreme secants: Δ = 1e-300, 1e300 on a uniform grid (ratio overflows).
     * geometric sqrt(1e-300 * 1e300) = 1; the logarithm path has absolute
     * error <= 4 eps * |ln 1e300| ~ 6e-13 in the exponent: tolerance 1e-12.
     * harmonic 2ab/(a+b) = 2e-300 (relative, a few roundings). */
    const double xe[3] = {0, 1, 2}, fe[3] = {0, 1e-300, 1e300};
    CHECK(slopes(TS_SLOPES_GEOMETRIC, xe, fe, 3, d, NULL) == TS_OK);
    CHECK_CLOSE(d[1], 1.0, 1e-12);
    CHECK(slopes(TS_SLOPES_HARMONIC, xe, fe, 3, d, NULL) == TS_OK);
    CHECK_CLOSE(d[1] / 2e-300, 1.0, 8 * EPS);
    /* subnormal secants (4e-320, ~1e-310): no NaN, and the inner value is a
     * mean, so in (0, max Δ] (slack: a few subnormal ulps, 5e-324 each) */
    const double fs[3] = {0, 4e-320, 1e-310};
    for (size_t k = 0; k < NALL; k++) {
        CHECK(slopes(ALL[k], xe, fs, 3, d, NULL) == TS_OK);
        CHECK(isfinite(d[0]) && isfinite(d[1]) && isfinite(d[2]));
        CHECKF(d[1] > 0.0 && d[1] <= 1e-310 + 1e-322, "%s: %g", mname(ALL[k]), d[1]);
    }
}

/* ---- sign structure: zero at extrema, means between the secants -------- */
static void check_sign_structure(const double *x, const double *f, size_t np, const char *what)
{
    double *dm[3];
    double scale = max_abs_secant(x, f, np);
    for (int k = 0; k < 3; k++) {
        dm[k] = malloc(np * sizeof(double));
        if (!dm[k])
            return;
    }
    /* k = 0 geometric, 1 harmonic, 2 pchip */
    for (int k = 0; k < 3; k++) {
        ts_slopes m = ALL[k + 1];
        CHECK(slopes(m, x, f, np, dm[k], NULL) == TS_OK);
        for (size_t i = 1; i + 1 < np; i++) {
            double a = (f[i] - f[i - 1]) / (x[i] - x[i - 1]);
            double b = (f[i + 1] - f[i]) / (x[i + 1] - x[i]);
            double di = dm[k][i];
            if (!((a > 0 && b > 0) || (a < 0 && b < 0))) {
                /* local extremum or flat: exactly 0 */
                CHECKF(di == 0.0, "%s %s: d[%zu] = %g at an extremum", what, mname(m), i, di);
            } else {
                /* a mean lies between its arguments (up to rounding) */
                double lo = fmin(a, b), hi = fmax(a, b), t = 8 * EPS * scale;
                CHECKF(lo - t <= di && di <= hi + t, "%s %s: d[%zu] = %g not in [%g, %g]", what,
                       mname(m), i, di, lo, hi);
            }
        }
    }
    /* same weights: |arithmetic| >= |geometric| >= |harmonic| (AM-GM-HM) */
    double *da = malloc(np * sizeof(double));
    if (da && slopes(TS_SLOPES_ARITHMETIC, x, f, np, da, NULL) == TS_OK) {
        for (size_t i = 1; i + 1 < np; i++) {
            if (dm[0][i] == 0.0)
                continue;
            double t = 8 * EPS * scale;
            CHECKF(fabs(da[i]) + t >= fabs(dm[0][i]) && fabs(dm[0][i]) + t >= fabs(dm[1][i]),
                   "%s AM-GM-HM at %zu: %g %g %g", what, i, da[i], dm[0][i], dm[1][i]);
        }
    }
    free(da);
    for (int k = 0; k < 3; k++)
        free(dm[k]);
}

static void test_sign_structure(void)
{
    for (int s = 0; s < SLOPES_REF_NSETS; s++)
        check_sign_structure(slopes_ref_sets[s].x, slopes_ref_sets[s].f, slopes_ref_sets[s].np,
                             slopes_ref_sets[s].name);
    /* flat runs: no NaN anywhere, zeros where the data are flat */
    const double x[8] = {0, 1, 2, 3, 4, 5, 6, 7}, f[8] = {1, 1, 1, 2, 2, 2, 2, 3};
    double d[8];
    for (size_t k = 0; k < NALL; k++) {
        CHECK(slopes(ALL[k], x, f, 8, d, NULL) == TS_OK);
        for (int i = 0; i < 8; i++)
            CHECKF(isfinite(d[i]), "%s d[%d] = %g", mname(ALL[k]), i, d[i]);
        /* inside a flat run of >= 3 points every local method gives 0
         * (Akima: w1 = |Δ2 - Δ1| = 1, w2 = 0 -> d1 = Δ0 = 0; likewise d4, d5) */
        if (ALL[k] != TS_SLOPES_ARITHMETIC)
            CHECKF(d[1] == 0.0 && d[4] == 0.0 && d[5] == 0.0, "%s: %g %g %g", mname(ALL[k]),
                   d[1], d[4], d[5]);
    }
}

/* ---- against the reference script -------------------------------------- */
static void test_reference(void)
{
    /* Every estimate is a weighted mean of at most four secants (or an end
     * formula with coefficients summing to <= 3 in absolute value).  The
     * secants of the double data carry <= 2 roundings; Akima's weights are
     * differences of secants, so their absolute error is a few eps * max|Δ|,
     * and a convex combination turns that into an absolute error of the same
     * size.  Counting every operation gives < 16 eps max|Δ|; 64 eps max|Δ|
     * leaves a factor 4.  (The geometric mean adds |w ln(b/a)| eps, < 10 eps
     * on these data.) */
    double worst = 0.0;
    for (int s = 0; s < SLOPES_REF_NSETS; s++) {
        const slopes_ref_set *R = &slopes_ref_sets[s];
        double tol = 64 * EPS * max_abs_secant(R->x, R->f, R->np);
        double d[16];
        for (int m = 0; m < (int)(sizeof R->d / sizeof *R->d); m++) {
            if (!R->d[m])
                continue;
            ts_error err = {TS_ERR_NULL, 7, TS_WHERE_QUERY};
            ts_status st = slopes((ts_slopes)m, R->x, R->f, R->np, d, &err);
            CHECKF(st == TS_OK && err.status == TS_OK && err.index == TS_NO_INDEX &&
                       err.where == TS_WHERE_NONE,
                   "%s %s: status %d", R->name, mname((ts_slopes)m), (int)st);
            for (size_t i = 0; i < R->np; i++) {
                double e = fabs(d[i] - R->d[m][i]);
                if (e > worst)
                    worst = e;
                CHECKF(e <= tol, "%s %s d[%zu] = %.17g, ref %.17g", R->name,
                       mname((ts_slopes)m), i, d[i], R->d[m][i]);
            }
        }
    }
    printf("reference: worst absolute difference %.3g\n", worst);
}

/* ---- PCHIP on RPN 14: monotone, and inside the Fritsch–Carlson region -- */
static int fc_region_ok(const double *x, const double *f, const double *d, size_t np)
{
    /* Fritsch & Carlson (1980): a cubic Hermite piece on monotone data is
     * monotone if 0 <= d_i/Δ_i <= 3 and 0 <= d_{i+1}/Δ_i <= 3 (the square
     * inside their region M). */
    for (size_t i = 0; i + 1 < np; i++) {
        double D = (f[i + 1] - f[i]) / (x[i + 1] - x[i]);
        double a = d[i] / D, b = d[i + 1] / D;
        if (!(0.0 <= a && a <= 3.0 && 0.0 <= b && b <= 3.0))
            return 0;
    }
    return 1;
}

static void test_pchip_rpn14(void)
{
    const slopes_ref_set *R = &slopes_ref_sets[0];
    CHECK(strcmp(R->name, "rpn14") == 0 && R->np == 9);
    double d[9];
    CHECK(slopes(TS_SLOPES_FRITSCH_CARLSON, R->x, R->f, 9, d, NULL) == TS_OK);
    for (int i = 0; i < 9; i++)
        CHECKF(d[i] >= 0.0, "d[%d] = %g", i, d[i]);
    CHECK(fc_region_ok(R->x, R->f, d, 9));
    /* the data's first and last slopes: the 3-point end formula goes negative
     * (Δ0 << Δ1), so pchip's sign rule must give exactly 0 there */
    CHECK(d[0] == 0.0 && d[8] == 0.0);
    /* the property check can fail: the arithmetic mean leaves the region on
     * these data (d0 = Δ0 - (Δ1 - Δ0)/2 < 0) */
    CHECK(slopes(TS_SLOPES_ARITHMETIC, R->x, R->f, 9, d, NULL) == TS_OK);
    CHECK(d[0] < 0.0);
    CHECK(!fc_region_ok(R->x, R->f, d, 9));
}

/* ---- Akima and makima by hand ------------------------------------------ */
static void test_akima_by_hand(void)
{
    double d[5];
    /* x = 0 1 3 4 6, f = 0 1 5 5 3: secants m0..m3 = 1, 2, 0, -1.
     * ghosts: m_{-1} = 2*1 - 2 = 0, m_{-2} = 2*0 - 1 = -1,
     *         m_4 = 2*(-1) - 0 = -2, m_5 = 2*(-2) - (-1) = -3.
     * Akima d_i = (|m_{i+1}-m_i| m_{i-1} + |m_{i-1}-m_{i-2}| m_i) / (sum):
     *  d0: m -1 0 1 2:  w1 = 1, w2 = 1 -> (0 + 1)/2 = 1/2
     *  d1: m 0 1 2 0:   w1 = 2, w2 = 1 -> (2*1 + 1*2)/3 = 4/3
     *  d2: m 1 2 0 -1:  w1 = 1, w2 = 1 -> (2 + 0)/2 = 1
     *  d3: m 2 0 -1 -2: w1 = 1, w2 = 2 -> (0 - 2)/3 = -2/3
     *  d4: m 0 -1 -2 -3: w1 = 1, w2 = 1 -> (-1 - 2)/2 = -3/2
     * makima weights w1 = |m_{i+1}-m_i| + |m_{i+1}+m_i|/2, w2 likewise:
     *  d0: w1 = 1 + 3/2 = 5/2, w2 = 1 + 1/2 = 3/2 -> (0 + 3/2)/4 = 3/8
     *  d1: w1 = 2 + 1 = 3, w2 = 1 + 1/2 = 3/2 -> (3 + 3)/(9/2) = 4/3
     *  d2: w1 = 1 + 1/2 = 3/2, w2 = 1 + 3/2 = 5/2 -> (3 + 0)/4 = 3/4
     *  d3: w1 = 1 + 3/2 = 5/2, w2 = 2 + 1 = 3 -> (0 - 3)/(11/2) = -6/11
     *  d4: w1 = 1 + 5/2 = 7/2, w2 = 1 + 1/2 = 3/2 -> (-7/2 - 3)/5 = -13/10 */
    const double x[5] = {0, 1, 3, 4, 6}, f[5] = {0, 1, 5, 5, 3};
    const double ak[5] = {0.5, 4.0 / 3.0, 1.0, -2.0 / 3.0, -1.5};
    const double mk[5] = {3.0 / 8.0, 4.0 / 3.0, 0.75, -6.0 / 11.0, -1.3};
    /* secants exact, a handful of roundings on numbers <= 5 */
    CHECK(slopes(TS_SLOPES_AKIMA, x, f, 5, d, NULL) == TS_OK);
    for (int i = 0; i < 5; i++)
        CHECK_CLOSE(d[i], ak[i], 8 * EPS * 5);
    CHECK(slopes(TS_SLOPES_MAKIMA, x, f, 5, d, NULL) == TS_OK);
    for (int i = 0; i < 5; i++)
        CHECK_CLOSE(d[i], mk[i], 8 * EPS * 5);

    /* flat run, Akima's 0/0: x = 0..4, f = 0 0 0 1 2: m = 0 0 1 1, ghosts
     * 0 0 | 1 1.  Akima: d0: all 0 -> 0/0 -> average 0; d1: m 0 0 0 1,
     * w1 = 1, w2 = 0 -> m0 = 0; d2: m 0 0 1 1, w1 = w2 = 0 -> (0 + 1)/2 = 1/2;
     * d3: m 0 1 1 1, w1 = 0, w2 = 1 -> m3 = 1; d4: all 1 -> 1.
     * makima d2: w1 = 0 + 1 = 1, w2 = 0 + 0 = 0 -> m1 = 0 (flat stays flat);
     * d1: w1 = 1 + 1/2, w2 = 0 -> 0; d3: w1 = 0 + 1, w2 = 1 + 1/2 -> 1. */
    const double xf[5] = {0, 1, 2, 3, 4}, ff[5] = {0, 0, 0, 1, 2};
    const double akf[5] = {0, 0, 0.5, 1, 1}, mkf[5] = {0, 0, 0, 1, 1};
    CHECK(slopes(TS_SLOPES_AKIMA, xf, ff, 5, d, NULL) == TS_OK);
    for (int i = 0; i < 5; i++)
        CHECKF(d[i] == akf[i], "akima flat d[%d] = %.17g", i, d[i]);
    CHECK(slopes(TS_SLOPES_MAKIMA, xf, ff, 5, d, NULL) == TS_OK);
    for (int i = 0; i < 5; i++)
        CHECKF(d[i] == mkf[i], "makima flat d[%d] = %.17g", i, d[i]);

    /* three points (n = 2): x = 0 1 3, f = 0 1 9: m0 = 1, m1 = 4; the ghosts
     * make one arithmetic progression -5 -2 1 4 7 10.
     * Akima: equal weights -> (3m0 - m1)/2 = -1/2, (m0+m1)/2 = 5/2, (3m1 - m0)/2 = 11/2.
     * makima: d0: w1 = 3 + 5/2, w2 = 3 + 7/2 -> (-11 + 6.5)/12 = -3/8;
     *         d1: w1 = 3 + 11/2, w2 = 3 + 1/2 -> (8.5 + 14)/12 = 15/8;
     *         d2: w1 = 3 + 17/2, w2 = 3 + 5/2 -> (46 + 38.5)/17 = 169/34. */
    const double x3[3] = {0, 1, 3}, f3[3] = {0, 1, 9};
    CHECK(slopes(TS_SLOPES_AKIMA, x3, f3, 3, d, NULL) == TS_OK);
    CHECK_CLOSE(d[0], -0.5, 8 * EPS * 10);
    CHECK_CLOSE(d[1], 2.5, 8 * EPS * 10);
    CHECK_CLOSE(d[2], 5.5, 8 * EPS * 10);
    CHECK(slopes(TS_SLOPES_MAKIMA, x3, f3, 3, d, NULL) == TS_OK);
    CHECK_CLOSE(d[0], -0.375, 8 * EPS * 10);
    CHECK_CLOSE(d[1], 1.875, 8 * EPS * 10);
    CHECK_CLOSE(d[2], 169.0 / 34.0, 8 * EPS * 10);
}

/* ---- periodic ---------------------------------------------------------- */
static void test_periodic(void)
{
    enum { N = 16 };
    double x[N + 1], f[N + 1], d[N + 1];
    const double twopi = 2.0 * TS_PI;
    /* uniform: the three-point mean is the central difference, and for sin
     * (sin(x+h) - sin(x-h))/(2h) = cos(x) sin(h)/h exactly.  The grid is
     * uniform up to rounding of x (|δh| <= 2 eps * 2pi) and f carries one
     * rounding: error <= (2 eps + 2 eps*2pi/h) / h-ish, < 1e-14 for h = 0.39. */
    for (int i = 0; i <= N; i++) {
        x[i] = twopi * i / N;
        f[i] = sin(x[i]);
    }
    f[N] = f[0]; /* sin(2pi) is -2.4e-16 in doubles: the data must close exactly */
    CHECK(slopes(TS_SLOPES_PERIODIC, x, f, N + 1, d, NULL) == TS_OK);
    double h = twopi / N, damp = sin(h) / h;
    for (int i = 0; i <= N; i++) {
        CHECK_CLOSE(d[i], cos(x[i]) * damp, 1e-14);
        /* and close to cos: 1 - sin(h)/h <= h^2/6 */
        CHECK(fabs(d[i] - cos(x[i])) <= h * h / 6.0 + 1e-14);
    }
    CHECK(d[0] == d[N]);
    CHECK(fabs(d[0] - 1.0) < h * h / 6.0 + 1e-14);

    /* non-uniform, asymmetric closed grid x = t + 0.2 sin t + 0.1 (1 - cos t)
     * (dx/dt >= 1 - sqrt(0.05) > 0; x(2pi) = 2pi): the three-point derivative
     * error is |f'''(ξ)| h_{i-1} h_i / 6 <= h_{i-1} h_i / 6 for sin,
     * including point 0 where the left neighbour is the last interval. */
    for (int i = 0; i <= N; i++) {
        double t = twopi * i / N;
        x[i] = t + 0.2 * sin(t) + 0.1 * (1.0 - cos(t));
        f[i] = sin(x[i]);
    }
    x[N] = twopi;
    f[N] = f[0];
    CHECK(slopes(TS_SLOPES_PERIODIC, x, f, N + 1, d, NULL) == TS_OK);
    for (int i = 0; i <= N; i++) {
        double hl = i > 0 ? x[i] - x[i - 1] : x[N] - x[N - 1];
        double hr = i < N ? x[i + 1] - x[i] : x[1] - x[0];
        CHECKF(fabs(d[i] - cos(x[i])) <= hl * hr / 6.0 + 1e-14, "d[%d] = %g, cos = %g", i, d[i],
               cos(x[i]));
    }
    CHECK(d[0] == d[N]);
    /* d0 == dn is not automatic: the one-sided ends of the plain arithmetic
     * mean differ on these data, and they differ from the periodic value */
    double da[N + 1];
    CHECK(slopes(TS_SLOPES_ARITHMETIC, x, f, N + 1, da, NULL) == TS_OK);
    CHECKF(fabs(da[0] - da[N]) > 1e-3 && fabs(da[0] - d[0]) > 1e-3, "%g %g %g", da[0], da[N],
           d[0]);

    /* three points: x = 0 1 3, f = 0 2 0: Δ = 2, -1; point 1: (2*2 + 1*(-1))/3 = 1;
     * point 0 (left = interval 1, h 2, Δ -1; right = interval 0, h 1, Δ 2):
     * (1*(-1) + 2*2)/3 = 1 = d2. */
    const double x3[3] = {0, 1, 3}, f3[3] = {0, 2, 0};
    CHECK(slopes(TS_SLOPES_PERIODIC, x3, f3, 3, d, NULL) == TS_OK);
    CHECK_CLOSE(d[0], 1.0, 4 * EPS);
    CHECK_CLOSE(d[1], 1.0, 4 * EPS);
    CHECK(d[2] == d[0]);
}

/* ---- every error path --------------------------------------------------- */
static int all_nan(const double *d, size_t np)
{
    for (size_t i = 0; i < np; i++)
        if (!isnan(d[i]))
            return 0;
    return 1;
}

#define EXPECT_ERR(call, st_, idx_, where_)                                                  \
    do {                                                                                     \
        ts_error e_ = {TS_OK, 12345, TS_WHERE_QUERY};                                         \
        ts_status s_ = (call);                                                               \
        CHECKF(s_ == (st_) && e_.status == (st_) && e_.index == (size_t)(idx_) &&            \
                   e_.where == (where_),                                                     \
               "status %d/%d index %zu where %d", (int)s_, (int)e_.status, e_.index,         \
               (int)e_.where);                                                               \
    } while (0)

static void test_errors(void)
{
    double x[6] = {0, 1, 2, 3, 4, 5}, f[6] = {1, 3, 2, 5, 4, 6}, d[6];
    ts_error e;

    /* NULL arguments */
    EXPECT_ERR(ts_slopes_compute(TS_SLOPES_ARITHMETIC, NULL, f, 6, d, &e_), TS_ERR_NULL,
               TS_NO_INDEX, TS_WHERE_NONE);
    EXPECT_ERR(ts_slopes_compute(TS_SLOPES_ARITHMETIC, x, NULL, 6, d, &e_), TS_ERR_NULL,
               TS_NO_INDEX, TS_WHERE_NONE);
    EXPECT_ERR(ts_slopes_compute(TS_SLOPES_ARITHMETIC, x, f, 6, NULL, &e_), TS_ERR_NULL,
               TS_NO_INDEX, TS_WHERE_NONE);
    CHECK(ts_slopes_compute(TS_SLOPES_ARITHMETIC, x, f, 6, NULL, NULL) == TS_ERR_NULL);

    /* too few */
    for (size_t np = 0; np < 2; np++) {
        d[0] = 42.0;
        EXPECT_ERR(ts_slopes_compute(TS_SLOPES_ARITHMETIC, x, f, np, d, &e_), TS_ERR_TOO_FEW,
                   TS_NO_INDEX, TS_WHERE_NONE);
        CHECK(np == 0 ? d[0] == 42.0 : isnan(d[0])); /* only the np given entries are touched */
    }

    /* non-finite x or f: index of the first offending point */
    const double bad[3] = {TH_NAN, TH_INF, -TH_INF};
    for (int b = 0; b < 3; b++) {
        double xx[6], ff[6];
        memcpy(xx, x, sizeof xx);
        memcpy(ff, f, sizeof ff);
        xx[3] = bad[b];
        EXPECT_ERR(ts_slopes_compute(TS_SLOPES_AKIMA, xx, ff, 6, d, &e_), TS_ERR_NONFINITE, 3,
                   TS_WHERE_POINT);
        CHECK(all_nan(d, 6));
        ff[2] = bad[b];
        EXPECT_ERR(ts_slopes_compute(TS_SLOPES_AKIMA, xx, ff, 6, d, &e_), TS_ERR_NONFINITE, 2,
                   TS_WHERE_POINT);
        memcpy(xx, x, sizeof xx);
        memcpy(ff, f, sizeof ff);
        ff[0] = bad[b];
        EXPECT_ERR(ts_slopes_compute(TS_SLOPES_ARITHMETIC, xx, ff, 6, d, &e_), TS_ERR_NONFINITE,
                   0, TS_WHERE_POINT);
        ff[0] = f[0];
        xx[5] = bad[b];
        EXPECT_ERR(ts_slopes_compute(TS_SLOPES_ARITHMETIC, xx, ff, 6, d, &e_), TS_ERR_NONFINITE,
                   5, TS_WHERE_POINT);
    }

    /* unsorted / duplicate: index i with x[i] <= x[i-1], the first one */
    {
        double xx[6];
        memcpy(xx, x, sizeof xx);
        xx[2] = xx[1]; /* duplicate */
        EXPECT_ERR(ts_slopes_compute(TS_SLOPES_ARITHMETIC, xx, f, 6, d, &e_), TS_ERR_UNSORTED,
                   2, TS_WHERE_POINT);
        CHECK(all_nan(d, 6));
        xx[4] = 2.5; /* also decreasing at 4; 2 still first */
        EXPECT_ERR(ts_slopes_compute(TS_SLOPES_ARITHMETIC, xx, f, 6, d, &e_), TS_ERR_UNSORTED,
                   2, TS_WHERE_POINT);
        memcpy(xx, x, sizeof xx);
        xx[5] = 3.5; /* below x[4] = 4 */
        EXPECT_ERR(ts_slopes_compute(TS_SLOPES_MAKIMA, xx, f, 6, d, &e_), TS_ERR_UNSORTED, 5,
                   TS_WHERE_POINT);
        memcpy(xx, x, sizeof xx);
        xx[1] = -0.0; /* -0 == 0: a duplicate too */
        EXPECT_ERR(ts_slopes_compute(TS_SLOPES_MAKIMA, xx, f, 6, d, &e_), TS_ERR_UNSORTED, 1,
                   TS_WHERE_POINT);
    }

    /* method: user slopes cannot be estimated; out-of-range values */
    EXPECT_ERR(ts_slopes_compute(TS_SLOPES_USER, x, f, 6, d, &e_), TS_ERR_OPTION, TS_NO_INDEX,
               TS_WHERE_NONE);
    CHECK(all_nan(d, 6));
    EXPECT_ERR(ts_slopes_compute((ts_slopes)TS_SLOPES_COUNT_, x, f, 6, d, &e_), TS_ERR_OPTION,
               TS_NO_INDEX, TS_WHERE_NONE);
    EXPECT_ERR(ts_slopes_compute((ts_slopes)-1, x, f, 6, d, &e_), TS_ERR_OPTION, TS_NO_INDEX,
               TS_WHERE_NONE);
    EXPECT_ERR(ts_slopes_compute((ts_slopes)1000, x, f, 2, d, &e_), TS_ERR_OPTION, TS_NO_INDEX,
               TS_WHERE_NONE);

    /* periodic needs f[0] == f[n] exactly; index = n */
    EXPECT_ERR(ts_slopes_compute(TS_SLOPES_PERIODIC, x, f, 6, d, &e_), TS_ERR_PERIODIC, 5,
               TS_WHERE_POINT);
    CHECK(all_nan(d, 6));
    {
        double ff[6];
        memcpy(ff, f, sizeof ff);
        ff[5] = nextafter(ff[0], 2.0); /* one ulp off still fails */
        EXPECT_ERR(ts_slopes_compute(TS_SLOPES_PERIODIC, x, ff, 6, d, &e_), TS_ERR_PERIODIC, 5,
                   TS_WHERE_POINT);
        EXPECT_ERR(ts_slopes_compute(TS_SLOPES_PERIODIC, x, ff, 2, d, &e_), TS_ERR_PERIODIC, 1,
                   TS_WHERE_POINT);
        ff[5] = ff[0];
        EXPECT_ERR(ts_slopes_compute(TS_SLOPES_PERIODIC, x, ff, 6, d, &e_), TS_OK, TS_NO_INDEX,
                   TS_WHERE_NONE);
    }

    /* finite data whose secant overflows: first point with a non-finite slope */
    {
        const double xo[3] = {0, 1e-300, 1}, fo[3] = {0, 1e300, 0};
        for (size_t k = 0; k < NALL; k++) {
            EXPECT_ERR(ts_slopes_compute(ALL[k], xo, fo, 3, d, &e_), TS_ERR_SLOPE_OVERFLOW, 0,
                       TS_WHERE_POINT);
            CHECK(all_nan(d, 3));
        }
        const double xo2[4] = {0, 1, 1 + 1e-15, 2}, fo2[4] = {0, 0, 1e300, 1e300};
        EXPECT_ERR(ts_slopes_compute(TS_SLOPES_AKIMA, xo2, fo2, 4, d, &e_), TS_ERR_SLOPE_OVERFLOW, 0,
                   TS_WHERE_POINT);
        /* Δ = 0, inf, 0: the end formula gives 0 + (0 - inf) h0/(h0+h1) = -inf
         * at point 0 already */
        EXPECT_ERR(ts_slopes_compute(TS_SLOPES_ARITHMETIC, xo2, fo2, 4, d, &e_),
                   TS_ERR_SLOPE_OVERFLOW, 0, TS_WHERE_POINT);
    }

    /* success resets err; err may be NULL */
    e.status = TS_ERR_NOMEM;
    e.index = 3;
    e.where = TS_WHERE_INTERVAL;
    CHECK(ts_slopes_compute(TS_SLOPES_HARMONIC, x, f, 6, d, &e) == TS_OK);
    CHECK(e.status == TS_OK && e.index == TS_NO_INDEX && e.where == TS_WHERE_NONE);
    CHECK(ts_slopes_compute(TS_SLOPES_HARMONIC, x, f, 6, d, NULL) == TS_OK);

    /* the internal entry point: unchecked data and method (its callers
     * check their options), but the periodic condition is still refused */
    EXPECT_ERR(ts__slopes(TS_SLOPES_PERIODIC, x, f, 6, d, &e_), TS_ERR_PERIODIC, 5,
               TS_WHERE_POINT);
    CHECK(ts__slopes(TS_SLOPES_MAKIMA, x, f, 6, d, NULL) == TS_OK);
}

int main(void)
{
    TH_CASE("two_points");
    test_two_points();
    TH_CASE("linear");
    test_linear();
    TH_CASE("quadratic");
    test_quadratic();
    TH_CASE("means_by_hand");
    test_means_by_hand();
    TH_CASE("sign_structure");
    test_sign_structure();
    TH_CASE("reference");
    test_reference();
    TH_CASE("pchip_rpn14");
    test_pchip_rpn14();
    TH_CASE("akima_by_hand");
    test_akima_by_hand();
    TH_CASE("periodic");
    test_periodic();
    TH_CASE("errors");
    test_errors();
    return th_report("test_slopes");
}
