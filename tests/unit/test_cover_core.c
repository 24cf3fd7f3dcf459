/* Edge paths of the evaluation core (coverage): slopes computed in
 * construction blocks, the short-piece integral at a power of two, the
 * threaded batch, every run-time kernel (ts__fast_batch_isa 0, 1, 2) on
 * the query patterns of its stage (galloping, cursor behind, unsorted,
 * blocks with a query outside, flat intervals), the geometric solve at
 * subnormal distances, and the out-of-range policies of each entry point.
 *
 * Expected values: the slope formulas of docs/method.md §6 re-derived here;
 * knot values f_i; closed forms of the paper form at a knot
 * (S'(x_i) = d_i / a_i: docs/method.md §2, 3w(B1 − B0) with B1 − B0 = k d,
 * k = 2h/(3π a), w = π/(2h)); the plain path ts_spline_eval_deriv (checked against
 * the mpmath reference in test_core.c) for the kernels, with the tolerances
 * derived in tests/unit/test_fast.c; single-threaded ts_spline_eval_batch for the
 * threaded one (bitwise: each query runs the same instructions wherever
 * it sits, docs/design.md).  Each tolerance is stated where it is used. */
#define _GNU_SOURCE
#include "th.h"
#include "th_options.h"
#include "common/th_rng.h"
#include "trigspline.h"
#include "internal.h"

#include <float.h>
#include <math.h>
#include <pthread.h>
#include <stdio.h>
#include <stdlib.h>
#include <string.h>

#define EPS DBL_EPSILON
/* tests/unit/test_fast.c: |kernel − plain| <= TOL·ε·M·w^k (paper, C¹) and
 * TOLG·ε·(M/h^k + |S^(k)|·[k > 0]) (geometric, a >= 1/2) */
static const double TOL[3] = {80.0, 360.0, 1600.0};
static const double TOLG[3] = {120.0, 800.0, 170000.0};

static th_rng rng = TH_RNG_INIT(0x243F6A8885A308D3u);

static ts_spline *make(const double *x, const double *f, size_t np, ts_form form, ts_slopes sl,
                       ts_extrap ex)
{
    ts_spline_options o;
    th_options_paper(&o);
    o.form = form;
    o.slopes = sl;
    o.extrapolate = ex;
    ts_spline *s = NULL;
    ts_error e;
    ts_status st = ts_spline_new(x, f, np, &o, &s, &e);
    CHECKF(st == TS_OK, "ts_spline_new: %s at %zu", ts_strerror(st), e.index);
    return st == TS_OK ? s : NULL;
}

/* ---- slopes -------------------------------------------------------------- */

/* docs/method.md §6 re-derived: the three-point arithmetic mean (hr Δl + hl Δr)/(hl + hr) */
static double arith3(double hl, double hr, double Dl, double Dr)
{
    return (hr * Dl + hl * Dr) / (hl + hr);
}

/* harmonic: 1/d = w0/Δl + w1/Δr, w0 = hr/(hl + hr), w1 = hl/(hl + hr); 0 unless
 * Δl, Δr have one strict sign */
static double harm3(double hl, double hr, double Dl, double Dr)
{
    if (!((Dl > 0 && Dr > 0) || (Dl < 0 && Dr < 0)))
        return 0.0;
    return 1.0 / ((hr / (hl + hr)) / Dl + (hl / (hl + hr)) / Dr);
}

/* end: Δ0 + (Δ0 − Δ1) h0/(h0 + h1), 0 unless of Δ0's sign */
static double end3(double h0, double h1, double D0, double D1)
{
    double e = D0 + (D0 - D1) * h0 / (h0 + h1);
    return (e > 0 && D0 > 0) || (e < 0 && D0 < 0) ? e : 0.0;
}

static void slopes_blocks(void)
{
    enum { NP = 5000 };
    static double x[NP], f[NP], d[NP];
    for (size_t i = 0; i < NP; i++) {
        x[i] = (double)i + 0.5 * th_rng_unit(&rng);
        f[i] = sin(0.01 * x[i]) + 0.1 * th_rng_unit(&rng);
    }
    /* inputs checked 4096 points at a time: an offender in the second block */
    double keep = x[4500];
    x[4500] = x[4499];
    ts_error e;
    CHECK(ts_slopes_compute(TS_SLOPES_ARITHMETIC, x, f, NP, d, &e) == TS_ERR_UNSORTED);
    CHECK(e.index == 4500 && e.where == TS_WHERE_POINT && isnan(d[0]) && isnan(d[NP - 1]));
    x[4500] = keep;
    /* a width that overflows, not at the first interval */
    double xw[4] = {-1.5e308, -1.4e308, 1.5e308, 1.6e308}, fw[4] = {0, 0, 0, 0}, dw[4];
    CHECK(ts_slopes_compute(TS_SLOPES_ARITHMETIC, xw, fw, 4, dw, &e) == TS_ERR_WIDTH);
    CHECK(e.index == 2 && e.where == TS_WHERE_POINT && isnan(dw[1]));

    /* Construction computes slopes in blocks of 1024 intervals (spline.c):
     * n = 1025 leaves a last block of one interval, n = 2500 a middle block
     * with neither end (periodic: the wrapped end slope is computed only by
     * the first and last block).  Tolerance: each secant carries <= 2u
     * (difference, quotient), the weights <= 2u, the mean's products and
     * sum <= 3u, all terms of one sign for the harmonic mean: 8ε relative;
     * the arithmetic mean and the end formula may cancel, so 8ε of
     * |Δl| + |Δr| (resp. 2|Δ0| + |Δ1|). */
    const size_t ns[2] = {1025, 2500};
    for (int c = 0; c < 2; c++) {
        size_t n = ns[c];
        for (int m = 0; m < 3; m++) {
            ts_slopes sl = m == 0   ? TS_SLOPES_HARMONIC
                           : m == 1 ? TS_SLOPES_FRITSCH_CARLSON
                                    : TS_SLOPES_PERIODIC;
            if (sl == TS_SLOPES_FRITSCH_CARLSON && n != 1025)
                continue;
            double f0 = f[n];
            if (sl == TS_SLOPES_PERIODIC)
                f[n] = f[0];
            ts_spline *s = make(x, f, n + 1, TS_FORM_PAPER, sl, TS_EXTRAP_ERROR);
            if (!s) {
                f[n] = f0;
                continue;
            }
            const double *ds = ts_spline_slopes(s);
            int bad = 0;
            size_t first = 0;
            for (size_t i = 0; i <= n; i++) {
                double want, tol;
                if (sl == TS_SLOPES_PERIODIC) {
                    size_t l = i == 0 ? n - 1 : i - 1, r = i == n ? 0 : i;
                    double hl = x[l + 1] - x[l], hr = x[r + 1] - x[r];
                    double Dl = (f[l + 1] - f[l]) / hl, Dr = (f[r + 1] - f[r]) / hr;
                    want = arith3(hl, hr, Dl, Dr);
                    tol = 8 * EPS * (fabs(Dl) + fabs(Dr));
                } else if (i == 0 || i == n) {
                    size_t j0 = i == 0 ? 0 : n - 1, j1 = i == 0 ? 1 : n - 2;
                    double h0 = x[j0 + 1] - x[j0], h1 = x[j1 + 1] - x[j1];
                    double D0 = (f[j0 + 1] - f[j0]) / h0, D1 = (f[j1 + 1] - f[j1]) / h1;
                    want = end3(h0, h1, D0, D1);
                    if (sl == TS_SLOPES_FRITSCH_CARLSON && D0 * D1 < 0 && fabs(want) > 3 * fabs(D0))
                        want = 3 * D0; /* docs/method.md §6: |d| <= 3|Δ| */
                    tol = 8 * EPS * (2 * fabs(D0) + fabs(D1));
                } else {
                    double hl = x[i] - x[i - 1], hr = x[i + 1] - x[i];
                    double Dl = (f[i] - f[i - 1]) / hl, Dr = (f[i + 1] - f[i]) / hr;
                    if (sl == TS_SLOPES_HARMONIC) {
                        want = harm3(hl, hr, Dl, Dr);
                    } else { /* Brodlie's weights (2hr + hl, hr + 2hl)/3(hl + hr) */
                        double a = 2 * hr + hl, b = hr + 2 * hl;
                        want = (Dl > 0 && Dr > 0) || (Dl < 0 && Dr < 0)
                                   ? 1.0 / ((a / (a + b)) / Dl + (b / (a + b)) / Dr)
                                   : 0.0;
                    }
                    tol = 8 * EPS * fabs(want);
                }
                if (!(fabs(ds[i] - want) <= tol) && !bad++)
                    first = i;
            }
            CHECKF(bad == 0, "n = %zu slopes %d: %d slopes off, first d_%zu = %.17g", n, (int)sl,
                   bad, first, ds[first]);
            ts_spline_free(s);
            f[n] = f0;
        }
    }
}

/* ---- integral of a piece shorter than an ulp's worth of nodes ------------ */

static void integral_short(void)
{
    /* a = 2 (a power of two, a knot), b = next double: the 12-point rule's
     * nodes mid ± 0.98·(b − a)/2 round below a (mid = a by ties-to-even,
     * and the doubles below 2 are twice as dense), so they are clamped.
     * Expected: S(ξ)(b − a) with S(a) = f_1 = 3 (interpolation) and
     * |S(ξ) − S(a)| <= |S'|·(b − a) < 1e-14; the weights sum to 2 within
     * 12 roundings: 16ε relative. */
    const double x[3] = {0.0, 2.0, 4.0}, f[3] = {1.0, 3.0, 2.0};
    for (int form = 0; form < 3; form++) {
        ts_spline *s = make(x, f, 3, (ts_form)form, TS_SLOPES_ARITHMETIC, TS_EXTRAP_ERROR);
        if (!s)
            continue;
        double a = 2.0, b = nextafter(2.0, 4.0), v = 0, w = 0;
        CHECK(ts_spline_integral(s, a, b, &v) == TS_OK);
        CHECK(ts_spline_integral(s, b, a, &w) == TS_OK);
        double want = 3.0 * (b - a);
        CHECKF(fabs(v - want) <= 16 * EPS * want, "form %d: %.17g want %.17g", form, v, want);
        CHECK(w == -v);
        ts_spline_free(s);
    }
}

/* ---- threaded batch -------------------------------------------------------- */

static ts_spline *mt_spline(void)
{
    double x[60], f[60];
    for (int i = 0; i < 60; i++) {
        x[i] = i + 0.3 * th_rng_unit(&rng);
        f[i] = cos(0.2 * x[i]) + th_rng_unit(&rng);
    }
    return make(x, f, 60, TS_FORM_PAPER, TS_SLOPES_ARITHMETIC, TS_EXTRAP_ERROR);
}

#if defined(__GLIBC__) /* pthread_setattr_default_np: the thread-failure check below */
static void *idle(void *arg)
{
    return arg;
}
#endif

static void batch_mt(void)
{
    ts_spline *s = mt_spline();
    if (!s)
        return;
    const double *X = ts_spline_x(s), *F = ts_spline_f(s);
    const size_t n = ts_spline_intervals(s), M = 64 * 8192; /* 64 threads of 8192 (eval.c) */
    double *q = malloc(M * sizeof *q), *y = malloc(M * sizeof *y), *r = malloc(M * sizeof *r);
    if (!q || !y || !r) {
        CHECKF(0, "out of memory in the test");
        goto done;
    }
    for (size_t j = 0; j < M; j++)
        q[j] = j % 101 == 0 ? X[j % (n + 1)] : X[0] + (X[n] - X[0]) * th_rng_unit(&rng);
    const size_t ms[3] = {3 * 8192 + 5, 3 * 8192 + 5, M};
    const unsigned th[3] = {3, 0, 1000}; /* 3; 0: one per processor; 1000: at most 64 */
    for (int c = 0; c < 3; c++) {
        size_t m = ms[c];
        for (int deriv = 0; deriv <= 2; deriv++) {
            ts_error e, e1;
            CHECK(ts_spline_eval_batch(s, deriv, q, m, r, NULL, &e1) == TS_OK);
            CHECK(ts_spline_eval_batch_mt(s, deriv, q, m, y, th[c], &e) == TS_OK && e.status == TS_OK);
            CHECKF(!memcmp(y, r, m * sizeof *y), "%u threads, %zu queries, deriv %d: differs",
                   th[c], m, deriv);
            int knots_ok = 1; /* knot values f_i exactly */
            for (size_t j = 0; deriv == 0 && j < m; j += 101)
                knots_ok &= y[j] == F[j % (n + 1)];
            CHECK(knots_ok);
        }
    }
    /* a query outside in the second thread's part: its global index */
    size_t m = 2 * 8192 + 7, bad = 8192 + 100;
    double keep = q[bad];
    q[bad] = X[n] + 1.0;
    ts_error e;
    CHECK(ts_spline_eval_batch_mt(s, 1, q, m, y, 2, &e) == TS_ERR_DOMAIN);
    CHECKF(e.status == TS_ERR_DOMAIN && e.index == bad && e.where == TS_WHERE_QUERY, "index %zu",
           e.index);
    CHECK(isnan(y[bad]) && !isnan(y[bad - 1]) && !isnan(y[bad + 1]));
    q[bad] = keep;
    /* bad arguments with enough queries for threads */
    CHECK(ts_spline_eval_batch_mt(s, 0, NULL, m, y, 2, &e) == TS_ERR_NULL && e.status == TS_ERR_NULL);
    CHECK(ts_spline_eval_batch_mt(s, 0, q, m, NULL, 2, &e) == TS_ERR_NULL);
    CHECK(ts_spline_eval_batch_mt(s, -1, q, m, y, 2, &e) == TS_ERR_OPTION && isnan(y[0]) &&
          isnan(y[m - 1]));
    CHECK(ts_spline_eval_batch_mt(s, -3, q, m, y, 2, &e) == TS_ERR_OPTION && e.index == TS_NO_INDEX);
#if defined(__GLIBC__)
    /* a thread that cannot be created runs on the caller's thread: make
     * every pthread_create fail (a stack larger than the address space) */
    pthread_attr_t def;
    if (pthread_getattr_default_np(&def) == 0) {
        pthread_attr_t big;
        pthread_attr_init(&big);
        if (pthread_attr_setstacksize(&big, (size_t)1 << 60) == 0 &&
            pthread_setattr_default_np(&big) == 0) {
            pthread_t t;
            int fails = pthread_create(&t, NULL, idle, NULL) != 0; /* the premise */
            if (!fails)
                pthread_join(t, NULL);
            CHECKF(fails, "pthread_create with a 2^60-byte stack succeeded");
            CHECK(ts_spline_eval_batch(s, 2, q, m, r, NULL, NULL) == TS_OK);
            CHECK(ts_spline_eval_batch_mt(s, 2, q, m, y, 2, &e) == TS_OK);
            CHECK(!memcmp(y, r, m * sizeof *y));
            pthread_setattr_default_np(&def);
        }
        pthread_attr_destroy(&big);
        pthread_attr_destroy(&def);
    }
#endif
done:
    free(q);
    free(y);
    free(r);
    ts_spline_free(s);
}

/* ---- batch kernels: every run-time variant, every staging path ------------ */

static size_t interval_of(const double *X, size_t n, double x)
{
    size_t lo = 0, hi = n; /* largest i <= n−1 with X[i] <= x */
    while (hi - lo > 1) {
        size_t mid = lo + (hi - lo) / 2;
        if (X[mid] <= x)
            lo = mid;
        else
            hi = mid;
    }
    return lo;
}

/* 3000 intervals, widths in [0.1, 1.1], plateaus of four equal values
 * every 50 points; harmonic slopes are 0 on a plateau (docs/method.md §6:
 * a zero secant), so its inner intervals are flat (all B_l = f). */
#define KN 3000
static ts_spline *kernel_spline(ts_form form)
{
    static double x[KN + 1], f[KN + 1];
    x[0] = -5.0;
    for (size_t i = 1; i <= KN; i++)
        x[i] = x[i - 1] + 0.1 + th_rng_unit(&rng);
    for (size_t i = 0; i <= KN; i++)
        f[i] = i % 50 < 4 && i >= 4 ? f[i - i % 50] : 10.0 * th_rng_unit(&rng) - 3.0;
    return make(x, f, KN + 1, form, TS_SLOPES_HARMONIC, TS_EXTRAP_ERROR);
}

static int flat_interval(const ts_spline *s, size_t i)
{
    const double *F = ts_spline_f(s), *D = ts_spline_slopes(s);
    return F[i] == F[i + 1] && D[i] == 0.0 && D[i + 1] == 0.0;
}

/* y[0..m) of kernel isa against ts_spline_eval_deriv, tolerances of test_fast.c;
 * on flat intervals the value f exactly and derivatives 0. */
static void against_plain(const ts_spline *s, int isa, int deriv, const double *q, size_t m,
                          const double *y, const char *what)
{
    const double *X = ts_spline_x(s), *F = ts_spline_f(s), *D = ts_spline_slopes(s);
    const double *Al = ts_spline_alpha(s), *Be = ts_spline_beta(s);
    size_t n = ts_spline_intervals(s);
    int geo = ts_spline_form(s) == TS_FORM_GEOMETRIC, bad = 0, flat_bad = 0;
    size_t first = 0;
    for (size_t j = 0; j < m; j++) {
        double o[3];
        CHECK(ts_spline_eval_deriv(s, q[j], NULL, &o[0], &o[1], &o[2]) == TS_OK);
        size_t i = interval_of(X, n, q[j]);
        double h = X[i + 1] - X[i], unit;
        if (geo) {
            double k = 2.0 / (3.0 * TH_PI * (Al[i] + Be[i])) * h;
            double M = fmax(fmax(fabs(F[i]), fabs(F[i + 1])),
                            fmax(fabs(k * D[i]), fabs(k * D[i + 1])));
            unit = TOLG[deriv] * EPS * (M / pow(h, deriv) + (deriv ? fabs(o[deriv]) : 0.0));
        } else {
            double B[4];
            CHECK(ts_spline_control(s, i, B, NULL) == TS_OK);
            double M = fmax(fmax(fabs(B[0]), fabs(B[1])), fmax(fabs(B[2]), fabs(B[3])));
            unit = TOL[deriv] * EPS * M * pow(TH_HALF_PI / h, deriv);
        }
        if (!(fabs(y[j] - o[deriv]) <= unit) && !bad++)
            first = j;
        if (flat_interval(s, i) && !(y[j] == (deriv ? 0.0 : F[i])))
            flat_bad++;
    }
    CHECKF(bad == 0, "%s, form %d, kernel %d, deriv %d: %d off, first x = %.17g: %.17g", what,
           (int)ts_spline_form(s), isa, deriv, bad, q[first], y[first]);
    CHECKF(flat_bad == 0, "%s, form %d, kernel %d, deriv %d: %d flat values not exact", what,
           (int)ts_spline_form(s), isa, deriv, flat_bad);
}

static int cmp_double(const void *a, const void *b)
{
    double u = *(const double *)a, v = *(const double *)b;
    return (u > v) - (u < v);
}

static void kernels(void)
{
    enum { QM = 2048 };
    static double q[QM], y[QM];
    int have[3];
    for (int isa = 0; isa <= 2; isa++) {
        double z = 0.0, yz;
        ts_spline *p = kernel_spline(TS_FORM_PAPER);
        have[isa] = p && ts__fast_batch_isa(p, 0, &z, 0, &yz, NULL, isa, NULL);
        ts_spline_free(p);
    }
    CHECK(have[0]); /* the portable kernel exists everywhere */
    for (int form = 0; form < 3; form++) {
        ts_spline *s = kernel_spline((ts_form)form);
        if (!s)
            continue;
        const double *X = ts_spline_x(s);
        size_t n = ts_spline_intervals(s);
        /* sorted with jumps of 0..1500 intervals (galloping, also past the
         * end of the knots), then the last interval and x_n */
        const size_t jumps[10] = {0, 1, 2, 3, 4, 7, 15, 64, 300, 1500};
        size_t m = 0;
        for (size_t k = 0, t = 0; k < n && m < QM - 2; k += jumps[t++ % 10])
            q[m++] = X[k] + (X[k + 1] - X[k]) * (t % 3 == 0 ? 0.0 : th_rng_unit(&rng));
        q[m++] = X[n - 1] + 0.5 * (X[n] - X[n - 1]);
        q[m++] = X[n];
        size_t m_gallop = m;
        for (int isa = 0; isa <= 2; isa++) {
            if (!have[isa])
                continue;
            for (int deriv = 0; deriv <= 2; deriv++) {
                size_t done = 0;
                ts_cursor c = TS_CURSOR_INIT;
                /* galloping */
                CHECK(ts__fast_batch_isa(s, deriv, q, m_gallop, y, &c, isa, &done) == 1 &&
                      done == m_gallop);
                CHECK(c.interval == n - 1);
                against_plain(s, isa, deriv, q, m_gallop, y, "sorted with gaps");
                /* from the first interval to the last in one step; from
                 * interval n − 2 into the last; within the last (the cursor
                 * starting there) */
                double hl = X[n] - X[n - 1];
                double q2[8] = {X[0],
                                X[n] - 0.25 * hl,
                                X[n],
                                X[n - 1] - 0.5 * (X[n - 1] - X[n - 2]),
                                X[n - 1] + 0.5 * hl,
                                X[n - 1] + 0.25 * hl,
                                X[n - 1] + 0.75 * hl,
                                X[n]};
                double y2[8];
                c.interval = 0;
                CHECK(ts__fast_batch_isa(s, deriv, q2, 3, y2, &c, isa, &done) == 1 && done == 3);
                against_plain(s, isa, deriv, q2, 3, y2, "to the last interval");
                CHECK(ts__fast_batch_isa(s, deriv, q2 + 3, 2, y2, &c, isa, &done) == 1 &&
                      done == 2);
                against_plain(s, isa, deriv, q2 + 3, 2, y2, "into the last interval");
                CHECK(c.interval == n - 1);
                CHECK(ts__fast_batch_isa(s, deriv, q2 + 5, 3, y2, &c, isa, &done) == 1 &&
                      done == 3);
                against_plain(s, isa, deriv, q2 + 5, 3, y2, "within the last interval");
                /* the cursor ahead of the batch (left on the last interval) */
                for (size_t j = 0; j < 300; j++)
                    q[QM - 300 + j] = X[0] + (X[n] - X[0]) * th_rng_unit(&rng);
                qsort(q + QM - 300, 300, sizeof *q, cmp_double);
                CHECK(ts__fast_batch_isa(s, deriv, q + QM - 300, 300, y, &c, isa, &done) == 1 &&
                      done == 300);
                against_plain(s, isa, deriv, q + QM - 300, 300, y, "cursor ahead");
                /* unsorted, three blocks and a short one, queries on flat intervals */
                for (size_t j = 0; j < 400; j++) {
                    size_t i = j % 5 == 0 ? 50 * (1 + j % 59) + 1 : th_rng_below(&rng, n);
                    q[QM - 400 + j] = X[i] + (X[i + 1] - X[i]) * th_rng_unit(&rng);
                }
                CHECK(ts__fast_batch_isa(s, deriv, q + QM - 400, 400, y, &c, isa, &done) == 1 &&
                      done == 400);
                against_plain(s, isa, deriv, q + QM - 400, 400, y, "unsorted");
                /* a block holding a query outside [x0, xn] or NaN: the
                 * kernel stops before it (the prefix of whole blocks) */
                double *r = q + QM - 400;
                const double outs[3] = {X[0] - 1.0, X[n] + 1.0, TH_NAN};
                for (int o = 0; o < 3; o++) {
                    for (int sorted = 0; sorted < 2; sorted++) {
                        for (size_t j = 0; j < 400; j++)
                            r[j] = X[0] + (X[n] - X[0]) * th_rng_unit(&rng);
                        if (sorted)
                            qsort(r, 400, sizeof *r, cmp_double);
                        size_t at = o == 0   ? (sorted ? 128 : 130)
                                    : o == 1 ? (sorted ? 255 : 200)
                                             : 140;
                        if (sorted && o == 0)
                            for (size_t j = 0; j <= at; j++) /* q[128] below x0: still sorted */
                                r[j] = X[0] - 2.0 + (double)j / 1000.0;
                        else
                            r[at] = outs[o];
                        CHECK(ts__fast_batch_isa(s, deriv, r, 400, y, &c, isa, &done) == 1);
                        size_t want = sorted && o == 0 ? 0 : 128 * (at / 128);
                        CHECKF(done == want, "outside %d sorted %d: done %zu, want %zu", o, sorted,
                               done, want);
                    }
                }
            }
        }
        ts_spline_free(s);
    }
}

/* Intervals that are flat in part: control values B = (0, 0, 0, 1) (paper
 * form, user slopes d = (0, 1) with k = 2h/(3π a) = 1: h = 1, a = 2/(3π)),
 * and geometric intervals with f_i = f_{i+1} and one slope 0. */
static void nearly_flat(void)
{
    const double x[2] = {0.0, 1.0};
    const double fs[4][2] = {{0.0, 1.0}, {1.0, 1.0}, {1.0, 1.0}, {1.0, 1.0}};
    const double ds[4][2] = {{0.0, 1.0}, {0.0, 1.0}, {-1.0, 0.0}, {0.0, 0.0}};
    double q[64], y[64];
    for (int j = 0; j < 64; j++)
        q[j] = (j + 0.5) / 64.0;
    for (int c = 0; c < 4; c++) {
        ts_spline_options o;
        th_options_paper(&o);
        o.form = c == 0 ? TS_FORM_PAPER : TS_FORM_GEOMETRIC;
        o.slopes = TS_SLOPES_USER;
        o.user_slopes = ds[c];
        o.n_user_slopes = 2;
        o.alpha = c == 0 ? 2.0 / (3.0 * TH_PI) : 1.0;
        ts_spline *s = NULL;
        CHECK(ts_spline_new(x, fs[c], 2, &o, &s, NULL) == TS_OK);
        if (!s)
            continue;
        double B[4];
        CHECK(ts_spline_control(s, 0, B, NULL) == TS_OK);
        if (c == 0)
            CHECK(B[0] == 0.0 && B[1] == 0.0 && B[2] == 0.0 && B[3] == 1.0);
        for (int isa = 0; isa <= 2; isa++) {
            for (int deriv = 0; deriv <= 2; deriv++) {
                ts_cursor cur = TS_CURSOR_INIT;
                if (!ts__fast_batch_isa(s, deriv, q, 64, y, &cur, isa, NULL))
                    continue;
                against_plain(s, isa, deriv, q, 64, y, "nearly flat");
                /* paper: S = A3(θ) = (1 − cos θ)³, θ = (π/2) x (docs/method.md
                 * §2), in long double; the kernel's bound 80ε·max|B| */
                for (int j = 0; c == 0 && deriv == 0 && j < 64; j++) {
                    long double mc = 1.0L - cosl(1.57079632679489661923L * (long double)q[j]);
                    CHECKF(fabsl((long double)y[j] - mc * mc * mc) <= 80.0L * (long double)EPS,
                           "kernel %d at %g: %.17g", isa, q[j], y[j]);
                }
            }
        }
        ts_spline_free(s);
    }
}

/* ---- the geometric solve at subnormal distances --------------------------- */

static void geometric_tiny(void)
{
    /* u = (x − x_i)/h subnormal: the model start and Halley steps cannot
     * reach a step below 2^-20 φ (subnormal φ has too few bits), so both
     * the scalar solve and the kernel take the iterate at the step cap.
     * Expected: S(x) = f_i + d_i (x − x_i) + O((x − x_i)²) = f_i to
     * rounding (|d_i|·|x − x_i| < 1e-300), S'(x) = d_i + O(|x − x_i|·S'') =
     * d_i with the solve's rounding: X̂'(0) = 3κ and Y'(0) = 3k d_i are
     * computed to a few ulps, so 16ε|d_i|. */
    const double x[4] = {-1.0, 0.0, 1.0, 2.5}, f[4] = {2.0, 1.0, 3.0, 2.5};
    /* a = α: 1, the raised 4/(3π) of the shape schemes, the least allowed */
    const double alphas[3] = {1.0, TS_GEOMETRIC_A_RAISE, TS_GEOMETRIC_A_MIN};
    for (int ia = 0; ia < 3; ia++) {
        ts_spline_options o;
        th_options_paper(&o);
        o.form = TS_FORM_GEOMETRIC;
        o.alpha = alphas[ia];
        ts_spline *s = NULL;
        CHECK(ts_spline_new(x, f, 4, &o, &s, NULL) == TS_OK);
        if (!s)
            return;
        const double *D = ts_spline_slopes(s);
        const double tiny[4] = {4.9406564584124654e-324, 7.1e-322, 2.0e-315, 1.0e-310};
        double q[8], y[3][8];
        for (int j = 0; j < 4; j++) {
            q[2 * j] = tiny[j];      /* from the left end of interval 1 */
            q[2 * j + 1] = -tiny[j]; /* from the right end of interval 0 */
        }
        for (int j = 0; j < 8; j++) {
            double v, dv;
            CHECK(ts_spline_eval_deriv(s, q[j], NULL, &v, &dv, NULL) == TS_OK);
            CHECKF(fabs(v - f[1]) <= EPS * fabs(f[1]), "S(%g) = %.17g", q[j], v);
            CHECKF(fabs(dv - D[1]) <= 16 * EPS * fabs(D[1]), "S'(%g) = %.17g, d_1 = %.17g", q[j],
                   dv, D[1]);
        }
        for (int isa = 0; isa <= 2; isa++) {
            for (int deriv = 0; deriv <= 1; deriv++) {
                ts_cursor c = TS_CURSOR_INIT;
                if (!ts__fast_batch_isa(s, deriv, q, 8, y[deriv], &c, isa, NULL))
                    continue;
                for (int j = 0; j < 8; j++) {
                    double want = deriv ? D[1] : f[1], tol = (deriv ? 16 : 1) * EPS * fabs(want);
                    CHECKF(fabs(y[deriv][j] - want) <= tol, "kernel %d deriv %d at %g: %.17g", isa,
                           deriv, q[j], y[deriv][j]);
                }
            }
        }
        ts_spline_free(s);
    }
}

/* ---- out of range, each entry point ----------------------------------------- */

static void out_of_range(void)
{
    /* paper form, α = 1, β = 0: S'(x_i) = d_i (docs/method.md §2 at a knot,
     * a = 1), so TS_EXTRAP_LINEAR gives f_0 + d_0 (x − x_0); tolerance: two
     * roundings of the tangent line and the slope's (3w(B1 − B0), four
     * roundings of terms of size |d_0|): 8ε(|f_0| + |d_0 (x − x_0)|). */
    const double x[4] = {0.0, 1.0, 2.0, 4.0}, f[4] = {1.0, 2.0, 0.5, 3.0};
    for (int ex = 0; ex < 4; ex++) {
        ts_spline *s = make(x, f, 4, TS_FORM_PAPER, TS_SLOPES_ARITHMETIC, (ts_extrap)ex);
        if (!s)
            continue;
        const double *D = ts_spline_slopes(s);
        const double qs[5] = {-TH_INF, TH_INF, TH_NAN, -0.5, 5.0};
        for (int k = 0; k < 5; k++) {
            double xq = qs[k], v = 0, v2 = 0, dv = 0, yb = 0;
            int left = xq < 0.0;
            ts_status want = isnan(xq) || ex == TS_EXTRAP_ERROR ||
                                     (isinf(xq) && ex != TS_EXTRAP_CLAMP)
                                 ? TS_ERR_DOMAIN
                                 : TS_OK;
            CHECK(ts_spline_eval(s, xq, NULL, &v) == want);
            CHECK(ts_spline_eval_deriv(s, xq, NULL, &v2, &dv, NULL) == want);
            CHECK(ts_spline_eval_batch(s, 0, &xq, 1, &yb, NULL, NULL) == want);
            if (want != TS_OK) {
                CHECK(isnan(v) && isnan(v2) && isnan(dv) && isnan(yb));
                continue;
            }
            CHECK(v == v2 && v == yb);
            if (ex == TS_EXTRAP_CLAMP)
                CHECK(v == f[left ? 0 : 3] && dv == 0.0);
            if (ex == TS_EXTRAP_LINEAR) {
                double xe = left ? 0.0 : 4.0, fe = f[left ? 0 : 3], de = D[left ? 0 : 3];
                double lin = fe + de * (xq - xe);
                CHECKF(fabs(v - lin) <= 8 * EPS * (fabs(fe) + fabs(de * (xq - xe))),
                       "linear at %g: %.17g", xq, v);
                CHECKF(fabs(dv - de) <= 8 * EPS * fabs(de), "linear slope at %g: %.17g", xq, dv);
            }
        }
        /* only the derivative asked for (no value pointer): the same number */
        double dv1 = 0, dv2 = 0, v = 0;
        CHECK(ts_spline_eval_deriv(s, 1.5, NULL, &v, &dv1, NULL) == TS_OK);
        CHECK(ts_spline_eval_deriv(s, 1.5, NULL, NULL, &dv2, NULL) == TS_OK && dv1 == dv2);
        ts_spline_free(s);
    }
}

int main(void)
{
    TH_CASE("slopes_blocks");
    slopes_blocks();
    TH_CASE("integral_short");
    integral_short();
    TH_CASE("batch_mt");
    batch_mt();
    TH_CASE("kernels");
    kernels();
    TH_CASE("nearly_flat");
    nearly_flat();
    TH_CASE("geometric_tiny");
    geometric_tiny();
    TH_CASE("out_of_range");
    out_of_range();
    return th_report("test_cover_core");
}
